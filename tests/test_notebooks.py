"""Notebooks are tests: each one executes without error, and none is committed with outputs."""
import json

import pytest
from notebook_runs import NOTEBOOKS, executed


def test_there_are_notebooks():
    assert len(NOTEBOOKS) >= 6


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_committed_without_outputs(path):
    notebook = json.loads(path.read_text(encoding="utf-8"))
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            assert cell.get("outputs") == [] and cell.get("execution_count") is None, path.name


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_executes(path):
    pytest.importorskip("nbclient")
    notebook = executed(path)  # a cell that raises fails here with its traceback
    assert any(cell.get("outputs") for cell in notebook.cells), f"{path.name} printed nothing"
