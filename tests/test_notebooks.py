"""Notebooks are tests: none is committed with outputs. That each one executes without error is
checked in test_notebook_pages.py, in the same file as its page, so that under xdist's --dist
loadfile one worker runs each notebook once (a second file would run them all again elsewhere)."""
import json

import pytest
from notebook_runs import NOTEBOOKS

pytestmark = pytest.mark.slow  # every notebook run: seconds to minutes per test


def test_there_are_notebooks():
    assert len(NOTEBOOKS) >= 6


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_committed_without_outputs(path):
    notebook = json.loads(path.read_text(encoding="utf-8"))
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            assert cell.get("outputs") == [] and cell.get("execution_count") is None, path.name
