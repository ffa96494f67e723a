"""The exported notebook pages, opened in a real browser with the network refused, as in a
lecture hall without internet: every formula typeset, no TeX source left in the text, and no
formula wider than the page's content column at a 1280 px window.

The pages and a screenshot of each are kept in build/notebook-pages/ for a person to look at.
Chromium is Debian's (scripts/ensure-browser.sh), driven by Playwright; MathJax comes from
node_modules (scripts/ensure-node-packages.sh). Each notebook is executed once per session
(notebook_runs.executed): the test that it executes is here too, so that xdist's --dist loadfile
gives both to one worker and no notebook runs twice.
"""
from __future__ import annotations

import functools
import os
import re
import shutil
from pathlib import Path

import pytest
from notebook_runs import NOTEBOOKS, ROOT, executed, exporter

pytestmark = pytest.mark.slow  # the notebook pages in a browser: seconds to minutes per test

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
VIEWPORT = {"width": 1280, "height": 900}
PAGES = ROOT / "build" / "notebook-pages"
MATH_IN_SOURCE = re.compile(r"\$|\\\(|\\\[|\\begin\{")
# TeX that a reader would see if typesetting had failed: environments, display delimiters, control words.
RAW_TEX = re.compile(r"\\begin\{|\$\$|\\(?:frac|left|right|theta|alpha|cos|sin|mathrm|operatorname)\b")

# Runs in the page: what a reader sees of the math, measured against the column each formula sits in.
MEASURE = """() => {
  const cells = [...document.querySelectorAll('.jp-Cell')];
  const typesetCells = cells.filter(c => c.querySelector('mjx-container')).map(c => c.id.replace('cell-id=', ''));
  const latexOutputs = [...document.querySelectorAll('.jp-RenderedLatex')];
  const rendered = [...document.querySelectorAll('.jp-RenderedHTMLCommon, .jp-RenderedLatex')];
  const texts = rendered.map(area => {
    const copy = area.cloneNode(true);
    copy.querySelectorAll('pre, code, mjx-container, script, style').forEach(e => e.remove());
    return copy.textContent;
  });
  const wide = [];
  for (const math of document.querySelectorAll('mjx-container')) {
    const column = math.closest('.jp-RenderedHTMLCommon, .jp-RenderedLatex, .jp-OutputArea-output, .jp-Cell');
    const style = getComputedStyle(column);
    const box = column.getBoundingClientRect();
    const left = box.left + parseFloat(style.borderLeftWidth) + parseFloat(style.paddingLeft);
    const right = box.right - parseFloat(style.borderRightWidth) - parseFloat(style.paddingRight);
    const picture = (math.querySelector(':scope > svg') || math).getBoundingClientRect();
    if (picture.left < left - 1 || picture.right > right + 1) {
      const cell = math.closest('.jp-Cell');
      wide.push({cell: cell ? cell.id.replace('cell-id=', '') : '?', tex: math.getAttribute('data-tex') || '',
                 width: Math.round(picture.width), column: Math.round(right - left)});
    }
  }
  // what MathJax could not read: an unknown macro is set in red (mathcolor) or as an merror
  const errors = [...document.querySelectorAll('mjx-container [mathcolor="red"], mjx-container merror, '
                                               + 'mjx-container [data-mjx-error]')].map(e => e.textContent);
  return {formulas: document.querySelectorAll('mjx-container').length, typesetCells, errors,
          latexOutputs: latexOutputs.length,
          untypesetLatex: latexOutputs.filter(o => !o.querySelector('mjx-container')).length,
          texts, wide};
}"""


@pytest.fixture(scope="module")
def browser():
    if not Path(CHROMIUM).exists() or shutil.which("node") is None:
        if os.environ.get("CI"):
            pytest.fail("CI must have chromium and node: `make test` runs scripts/ensure-browser.sh")
        pytest.skip("chromium or node missing: run `make test` (scripts/ensure-browser.sh) to install them")
    sync_api = pytest.importorskip("playwright.sync_api")
    with sync_api.sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield chromium
        chromium.close()


@pytest.fixture(scope="module")
def render(browser):
    """render(path) exports, typesets, opens and measures a notebook's page, once per module."""
    @functools.cache
    def render(path: Path) -> dict:
        notebook = executed(path)
        page_file = exporter.write_page(notebook, PAGES / f"{path.stem}.html")
        exporter.typeset([page_file])
        page = browser.new_page(viewport=VIEWPORT)
        refused = []

        def offline(route):
            if route.request.url.startswith("file://"):
                route.continue_()
            else:
                refused.append(route.request.url)
                route.abort()

        page.route("**/*", offline)
        page.goto(page_file.as_uri(), wait_until="load")
        page.wait_for_function("document.fonts.status === 'loaded'")
        report = page.evaluate(MEASURE)
        page.screenshot(path=str(PAGES / f"{path.stem}.png"), full_page=True)
        page.close()
        math_cells = {cell.get("id") for cell in notebook.cells if _shows_math(cell)}
        return dict(report, refused=refused, math_cells=math_cells)
    return render


def _shows_math(cell) -> bool:
    if cell.cell_type == "markdown":
        return bool(MATH_IN_SOURCE.search(cell.source))
    return any("text/latex" in output.get("data", {}) for output in cell.get("outputs", []))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_executes(path):
    pytest.importorskip("nbclient")
    notebook = executed(path)  # a cell that raises fails here with its traceback
    assert any(cell.get("outputs") for cell in notebook.cells), f"{path.name} printed nothing"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_page_loads_nothing_from_the_network(path, render):
    assert render(path)["refused"] == []


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_every_formula_is_typeset(path, render):
    report = render(path)
    assert report["math_cells"], f"{path.name} shows no math: the test would check nothing"
    assert report["formulas"] >= len(report["math_cells"])
    assert report["untypesetLatex"] == 0, f"{report['untypesetLatex']} of {report['latexOutputs']} LaTeX outputs"
    missing = report["math_cells"] - set(report["typesetCells"])
    assert not missing, f"cells whose math was not typeset: {sorted(missing)}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_no_tex_source_visible(path, render):
    raw = [m.group(0) + " in «" + text[max(0, m.start() - 40):m.end() + 40].strip() + "»"
           for text in render(path)["texts"] for m in RAW_TEX.finditer(text)]
    assert not raw, f"{len(raw)} pieces of TeX source are visible, e.g. " + "; ".join(raw[:5])


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_no_formula_shows_a_typesetting_error(path, render):
    errors = render(path)["errors"]
    assert not errors, f"{len(errors)} pieces MathJax could not read (set in red), e.g. {errors[:5]}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_no_formula_wider_than_the_column(path, render):
    wide = render(path)["wide"]
    described = [f"cell {w['cell']}: {w['width']} px in a {w['column']} px column: " + " ".join(w["tex"].split())[:100]
                 for w in wide]
    assert not wide, f"{len(wide)} formulas overflow at {VIEWPORT['width']} px:\n" + "\n".join(described)
