"""Notebooks as self-contained HTML pages: executed, converted, and their math typeset at export time.

    python scripts/export_notebooks.py OUT_DIR NOTEBOOK.ipynb...

A page loads nothing from the network: nbconvert's JupyterLab template without its CDN scripts
(scripts/notebook-page.html.j2) and MathJax 3 run by node over the page (scripts/typeset-pages.js),
so every formula is already SVG in the file. tests/test_notebook_pages.py opens the pages in
Chromium with the network refused.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

SCRIPTS = Path(__file__).resolve().parent
TEMPLATE = SCRIPTS / "notebook-page.html.j2"
TYPESETTER = SCRIPTS / "typeset-pages.js"
EXECUTION_TIMEOUT = 300  # seconds a cell may take


def execute(path: Path):
    """The notebook at `path`, run top to bottom in its own folder (as `make test` runs it)."""
    import nbclient
    import nbformat

    notebook = nbformat.read(path, as_version=4)
    nbclient.NotebookClient(notebook, timeout=EXECUTION_TIMEOUT, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}}).execute()
    return notebook


def write_page(notebook, page: Path) -> Path:
    """Write an executed notebook as HTML at `page`, math still as TeX (see `typeset`)."""
    from nbconvert import HTMLExporter

    exporter = HTMLExporter(template_name="lab", template_file=str(TEMPLATE))
    html, _ = exporter.from_notebook_node(notebook, resources={"metadata": {"name": page.stem}})
    page.parent.mkdir(parents=True, exist_ok=True)
    page.write_text(html, encoding="utf-8")
    return page


def typeset(pages: list[Path]) -> str:
    """Typeset the TeX of `pages` in place; a TeX error raises with node's message."""
    result = subprocess.run(["node", str(TYPESETTER), *map(str, pages)], cwd=SCRIPTS.parent,
                            capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"typesetting failed:\n{result.stderr or result.stdout}")
    return result.stdout


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    out_dir, notebooks = Path(argv[0]), [Path(a) for a in argv[1:]]
    pages = []
    for path in notebooks:
        print(f"export: executing {path}", flush=True)
        pages.append(write_page(execute(path), out_dir / f"{path.stem}.html"))
    print(typeset(pages), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
