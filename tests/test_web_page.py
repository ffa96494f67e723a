"""The browser page, built (scripts/build_web.py, as `make web` does) and driven in Debian's Chromium
with Playwright, every request to an address other than the page's own server refused: what a
student sees who opens the lecture's link.

The page is built once per run into build/web-test/ (the downloads and the byte-compiled SymPy and
standard library are kept in build/web-cache/ between runs), and screenshots of each step are
kept there for a person to look at.
"""
from __future__ import annotations

import functools
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import urllib.parse
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # the web page in a browser: seconds to minutes per test

ROOT = Path(__file__).resolve().parent.parent
BUILT = ROOT / "build" / "web-test"
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
VIEWPORT = {"width": 1400, "height": 1000}
WAIT_MS = 300_000  # far off: a page that never answers fails instead of hanging
READY = "#result[data-state=ready]"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def site():
    """The page, built and served on this machine: its base URL."""
    if not Path(CHROMIUM).exists() or shutil.which("node") is None:
        if os.environ.get("CI"):
            pytest.fail("CI must have chromium and node: `make test` runs scripts/ensure-browser.sh")
        pytest.skip("chromium or node missing: run `make test` (scripts/ensure-browser.sh) to install them")
    pytest.importorskip("playwright.sync_api")
    build = subprocess.run([sys.executable, str(ROOT / "scripts" / "build_web.py"), str(BUILT)], capture_output=True,
                           text=True, cwd=ROOT)
    assert build.returncode == 0, build.stdout[-2000:] + build.stderr[-3000:]
    assert "built from its sdist without the libyaml C extension" in build.stdout  # the build says so
    (BUILT / "screenshots").mkdir(exist_ok=True)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=str(BUILT)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    yield f"http://127.0.0.1:{server.server_address[1]}/"
    server.shutdown()


@pytest.fixture(scope="module")
def browser(site):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield chromium
        chromium.close()


@pytest.fixture
def open_page(browser, site):
    """open_page(path) opens the page in a fresh profile; `page.refused` lists every outside request."""
    contexts = []

    def open_page(path: str):
        context = browser.new_context(viewport=VIEWPORT, accept_downloads=True)
        context.grant_permissions(["clipboard-read", "clipboard-write"], origin=site.rstrip("/"))
        contexts.append(context)
        page = context.new_page()
        page.refused, page.failures = [], []

        def offline(route):
            if route.request.url.startswith(site):
                route.continue_()
            else:
                page.refused.append(route.request.url)
                route.abort()

        page.route("**/*", offline)
        page.on("pageerror", lambda error: page.failures.append(str(error)))
        page.goto(site + path)
        return page

    yield open_page
    for context in contexts:
        context.close()


def settled(page, name: str) -> str:
    """Waits for the result (ready or error), keeps a screenshot, and gives the result's state."""
    page.wait_for_selector("#result[data-state=ready], #result[data-state=error]", state="attached", timeout=WAIT_MS)
    page.wait_for_selector("#arm svg, #arm .message", state="attached", timeout=WAIT_MS)
    page.screenshot(path=str(BUILT / "screenshots" / f"{name}.png"), full_page=True)
    return page.get_attribute("#result", "data-state")


def typeset_text(page) -> str:
    """The result as a screen reader gets it, without spaces: words, and the MathML MathJax adds to each formula."""
    return re.sub(r"\s+", "", page.text_content("#result"))


def math_problems(page) -> list[str]:
    unread = "#result [data-mjx-error], #result mjx-container merror, #result mjx-container [mathcolor='red']"
    return page.eval_on_selector_all(unread, "found => found.map(e => e.textContent)")


def test_the_puma_forward_kinematics_with_an_edited_length_and_a_broken_file(open_page):
    page = open_page("index.html?robot=planar2r&show=table")
    assert settled(page, "1-planar2r-table") == "ready"
    assert page.get_attribute("#status", "data-state") == "ready"
    page.select_option("#robot", "puma560")
    page.click("#tabs button[data-show=fk]")
    assert settled(page, "2-puma560-fk") == "ready"
    shown = typeset_text(page)
    assert "PUMA560:0T6(modifiedDH)" in shown and "px=c1(a2c2+a3c23−d4s23)−d3s1" in shown
    assert math_problems(page) == []
    assert "robot=puma560" in page.url and "show=fk" in page.url

    puma = page.input_value("#yaml")
    page.fill("#yaml", puma.replace("a: a_2, d: d_3", "a: L_2, d: d_3").replace("a_2: 0.4318", "L_2: 0.4318"))
    page.wait_for_selector("#result[data-state=working]", state="attached")
    assert settled(page, "3-puma560-edited") == "ready"
    shown = typeset_text(page)
    assert "px=c1(L2c2+a3c23−d4s23)−d3s1" in shown and "a2" not in shown
    assert page.input_value("#robot") == "" and "#yaml=" in page.url  # the user's own robot now, in the link

    broken = page.input_value("#yaml").replace("alpha: pi/2,  a: 0", "alpha: pi/,  a: 0")
    line = next(n for n, text in enumerate(broken.splitlines(), 1) if "pi/," in text)
    page.fill("#yaml", broken)
    assert settled(page, "4-broken-file") == "error"
    message = page.inner_text("#problem .error")
    assert re.match(rf"error: robot\.yaml:{line}:\d+: ", message), message
    assert page.inner_text("#gutter .error-line").strip() == str(line)
    assert page.refused == [] and page.failures == []


def test_the_inverse_kinematics_of_the_planar_2r_and_its_drawing(open_page):
    page = open_page("index.html?robot=planar2r&show=ik")
    assert settled(page, "5-planar2r-ik") == "ready"
    headings = page.eval_on_selector_all("#result h3", "found => found.map(e => e.textContent)")
    assert "Branch 1: elbow down" in headings and "Branch 2: elbow up" in headings
    shown = typeset_text(page)
    assert "θ2=atan2(1−D2,D)" in shown and "θ2=atan2(−1−D2,D)" in shown
    assert math_problems(page) == []

    assert page.locator("#arm svg .joint").count() == 2 and page.locator("#sliders input").count() == 2
    before = page.get_attribute("#arm svg polyline.link", "points")
    page.locator("#sliders input[name=theta_2]").fill("90")
    page.wait_for_function(f"document.querySelector('#arm svg polyline.link').getAttribute('points') !== {before!r}",
                           timeout=WAIT_MS)
    tip = page.get_attribute("#arm svg polyline.link", "points").split()[-1]
    assert [round(float(x), 3) for x in tip.split(",")] == [0.5, -0.4]  # (a1, a2) seen from +z0, y up
    page.screenshot(path=str(BUILT / "screenshots" / "6-planar2r-theta2-90.png"), full_page=True)

    page.click("#copy")
    copied = page.evaluate("navigator.clipboard.readText()")
    assert copied.startswith("\\medskip\\noindent\\textbf{Inverse kinematics: the problem}")
    assert "\\textbf{Branch 1: elbow down}" in copied
    with page.expect_download() as download:
        page.click("#slides")
    tex = Path(download.value.path()).read_text(encoding="utf-8")
    assert download.value.suggested_filename == "planar2r.tex"
    assert "\\documentclass[11pt,aspectratio=169]{beamer}" in tex and "1 & $+$ & elbow down" in tex  # the sign table

    page.click("#tabs button[data-show=jacobian]")
    assert settled(page, "8-planar2r-jacobian") == "ready"
    shown = typeset_text(page)
    assert "0J=[−a1s1−a2s12" in shown and "detJblock=a1a2s2" in shown and "s2=0" in shown
    assert math_problems(page) == [] and "show=jacobian" in page.url
    assert page.refused == [] and page.failures == []


def test_a_link_with_a_robot_file_opens_that_arm(open_page):
    arm = ("name: Two-link arm from a slide\nconvention: modified\njoints:\n"
           "  - {joint: R, alpha: 0, a: 0, d: 0, theta: theta_1}\n"
           "  - {joint: R, alpha: 0, a: l_1, d: 0, theta: theta_2}\n")
    page = open_page("index.html?show=links#yaml=" + urllib.parse.quote(arm))
    assert settled(page, "7-own-arm-links") == "ready"
    shown = typeset_text(page)
    assert "Two-linkarmfromaslide:linkmatrices" in shown and "1T2=" in shown
    assert page.input_value("#robot") == "" and page.input_value("#yaml") == arm
    assert "give a number for l_1" in page.inner_text("#arm")  # no sample: no drawing, and why
    assert page.refused == [] and page.failures == []


def test_a_page_opened_as_a_file_says_how_to_serve_it(browser):
    page = browser.new_page()
    page.goto((BUILT / "index.html").as_uri())
    page.wait_for_selector("#result[data-state=error]", state="attached", timeout=30_000)
    assert "python3 -m http.server" in page.inner_text("#result")
    page.close()


# The page's Python as web/worker.js starts it, here in node with the same runtime: the saved state
# restored (its non-zero stretches put in place), the zips written where it expects them.
RESTORE = r"""
const fs = require("fs"), zlib = require("zlib"), path = require("path");
const { loadPyodide } = require("pyodide");
const built = path.join(process.argv[1], "pyodide");
async function main() {
  const packed = zlib.gunzipSync(fs.readFileSync(path.join(built, "python.snapshot.gzip")));
  const word = (index) => packed.readUInt32LE(4 * index); // [bytes, stretches, (start, length)...]
  const state = new Uint8Array(word(0));
  for (let i = 0, at = 8 + 8 * word(1); i < word(1); at += word(3 + 2 * i), i++) {
    state.set(packed.subarray(at, at + word(3 + 2 * i)), word(2 + 2 * i));
  }
  const memory = state.length - new Uint32Array(state.buffer, state.byteOffset, 4)[1];
  const runtime = path.dirname(require.resolve("pyodide/package.json"));
  const create = (await import(path.join(runtime, "pyodide.asm.mjs"))).default;
  const site = fs.readFileSync(path.join(built, "site-packages.zip"));
  const python = await loadPyodide({
    indexURL: runtime + path.sep, stdLibURL: path.join(built, "python_stdlib.zip"),
    _loadSnapshot: new Uint8Array(state),
    createPyodideModule: async (settings) => {
      const module = await create(settings);
      module.growMemory(memory);
      return module;
    },
    fsInit: async (FS) => FS.writeFile("/lib/site-packages.zip", site),
  });
  console.log(python.runPython(process.argv[2]));
}
main().catch((error) => { console.error(error); process.exit(1); });
"""

IN_THE_STATE = """
import json, sys, traceback
imported = all(name in sys.modules for name in ("sympy", "dhsym.web.app", "yaml"))
robot = "name: arm\\nconvention: standard\\njoints:\\n  - {joint: R, theta: theta_1, d: 0, a: a_1, alpha: 0}\\n"
answer = json.loads(handle(json.dumps({"kind": "show", "show": "fk", "yaml": robot, "file": "arm.yaml"})))
import email.mime.text, sympy.physics.units  # left in the zips: imported from them on first use
try:
    sympy.Matrix([[1, 2]]).inv()
except Exception:
    shown = traceback.format_exc()
json.dumps([imported, answer["state"], "sympy.physics.units" in sys.modules, shown.splitlines()[-1],
            any("sympy/matrices" in line and ", line " in line for line in shown.splitlines())])
"""


def test_the_saved_python_state_restores_and_imports_what_the_zips_hold(site):
    """The modules imported at build time are in the state; the others come from the zips; a
    traceback still names the file and line of each step."""
    result = subprocess.run(["node", "-e", RESTORE, str(BUILT), IN_THE_STATE], capture_output=True, text=True,
                            cwd=ROOT)
    assert result.returncode == 0, result.stderr[-3000:]
    imported, state, from_zip, error, lines = json.loads(result.stdout.splitlines()[-1])
    assert imported and state == "ready" and from_zip
    assert error.startswith("sympy.matrices.exceptions.NonSquareMatrixError") and lines
