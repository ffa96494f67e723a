"""Each notebook executed once per test session, shared by the tests that need its outputs
(test_notebook_pages.py checks that it runs and renders its page)."""
from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


def _load_exporter():
    spec = importlib.util.spec_from_file_location("export_notebooks", ROOT / "scripts" / "export_notebooks.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


exporter = _load_exporter()


@functools.cache
def executed(path: Path):
    """The notebook at `path` after running every cell (a failing cell raises; failures are not cached)."""
    return exporter.execute(path)
