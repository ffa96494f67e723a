"""The browser page (build/web, `make web`) against dhsym as a native process, in the same run.

- Cold start: a fresh browser profile (empty cache) opens `index.html?robot=puma560&show=fk` and waits
  for ⁰T₆ typeset in #result, against a native `dhsym fk puma560` process (Python's start, imports and
  the work). Target (issue 28): within 3x.
- One `fk puma560` once the page has loaded: a robot file the page has not read yet (the PUMA's file
  with a comment added) in, the typeset ⁰T₆ out, against the same request answered by
  `dhsym.web.app.handle` in a native process that has dhsym imported (the work and the LaTeX
  layout; the page adds MathJax's typesetting).
- Bytes: what the page loads from the server for its first result, against the prototype's 25.9 MB.

Wall-clock seconds (a browser is several processes), the median of RUNS runs, page and native runs
interleaved so that a busy machine slows both alike. The page is served by a local http.server, and
Chromium (Debian's, driven by Playwright) refuses every other address.
Run with `make bench`, or `python benchmarks/web_speed.py [RUNS]`.
"""
from __future__ import annotations

import functools
import http.server
import shutil
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "build" / "web"
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
RUNS = 5
COLD_TARGET = 3.0
PROTOTYPE_BYTES = 25.9e6
READY = "#result[data-state=ready]"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(folder: Path) -> tuple[http.server.ThreadingHTTPServer, str]:
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=str(folder)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


def offline_page(browser, base: str):
    """A page in a fresh context (empty cache) that may load from `base` only; (page, bytes loaded)."""
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    loaded = []
    page.route("**/*", lambda route: route.continue_() if route.request.url.startswith(base) else route.abort())
    page.on("requestfinished", lambda request: loaded.append(request.sizes()["responseBodySize"]))
    return context, page, loaded


def page_cold(browser, base: str) -> tuple[float, int, dict]:
    """Seconds from opening the page to the typeset ⁰T₆, the bytes loaded, the worker's own timings."""
    context, page, loaded = offline_page(browser, base)
    started = time.perf_counter()
    page.goto(base + "index.html?robot=puma560&show=fk")
    page.wait_for_selector(READY, state="attached", timeout=300_000)
    seconds = time.perf_counter() - started
    timings = page.evaluate("window.dhsymTimings || {}")
    warm = page_warm(page)
    context.close()
    return seconds, sum(loaded), {**timings, "warm": warm}


def page_warm(page) -> float:
    """One fk puma560 of a robot file the loaded page has not read yet: request to typeset."""
    text = (ROOT / "dhsym" / "robots" / "puma560.yaml").read_text() + f"# {time.time()}\n"
    page.fill("#yaml", text)
    page.wait_for_selector("#result[data-state=working]", state="attached")
    page.wait_for_selector(READY, state="attached", timeout=300_000)
    return float(page.get_attribute("#result", "data-seconds"))  # the page's own clock: request to typeset


def native_cold() -> float:
    started = time.perf_counter()
    subprocess.run([sys.executable, "-m", "dhsym.cli", "fk", "puma560"], stdout=subprocess.DEVNULL, check=True,
                   cwd=ROOT)
    return time.perf_counter() - started


NATIVE_WARM = """
import json, sys, time
from dhsym.web.app import handle
text = open(sys.argv[1]).read() + "# fresh\\n"
started = time.perf_counter()
answer = json.loads(handle(json.dumps({"kind": "show", "show": "fk", "yaml": text, "width": 700})))
assert answer["state"] == "ready", answer
print(time.perf_counter() - started)
"""


def native_warm() -> float:
    result = subprocess.run([sys.executable, "-c", NATIVE_WARM, str(ROOT / "dhsym" / "robots" / "puma560.yaml")],
                            capture_output=True, text=True, check=True, cwd=ROOT)
    return float(result.stdout)


def main(runs: int = RUNS) -> int:
    if not (PAGE / "index.html").exists():
        print("web: build/web is missing; run `make web` first")
        return 1
    if not Path(CHROMIUM).exists():
        print("web: skipped, no Chromium (scripts/ensure-browser.sh installs it)")
        return 0
    from playwright.sync_api import sync_playwright

    server, base = serve(PAGE)
    rows = {"page": [], "native": [], "page warm": [], "native warm": [], "bytes": [], "load": [], "imports": []}
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        native_cold()  # the file cache and Python's bytecode, as a student's second command has them
        for _ in range(runs):
            seconds, loaded, timings = page_cold(browser, base)
            rows["page"].append(seconds)
            rows["bytes"].append(loaded)
            rows["page warm"].append(timings["warm"])
            rows["load"].append(timings.get("load", float("nan")))
            rows["imports"].append(timings.get("imports", float("nan")))
            rows["native"].append(native_cold())
            rows["native warm"].append(native_warm())
        browser.close()
    server.shutdown()
    report({key: statistics.median(values) for key, values in rows.items()}, runs)
    return 0


def report(m: dict, runs: int) -> None:
    cold = m["page"] / m["native"]
    print(f"web page (build/web, Chromium, wall-clock medians of {runs} interleaved runs)")
    verdict = "no more)" if m["bytes"] <= PROTOTYPE_BYTES else "more)"
    print(f"  bytes loaded for the first result   {m['bytes'] / 1e6:6.1f} MB   "
          f"(prototype {PROTOTYPE_BYTES / 1e6:.1f} MB: {verdict}")
    print(f"  page cold start to typeset 0T6     {m['page']:6.2f} s   (Python and the wheels {m['load']:.2f} s, "
          f"imports {m['imports']:.2f} s)")
    print(f"  native `dhsym fk puma560` process  {m['native']:6.2f} s")
    print(f"  cold start ratio                   {cold:6.1f}x  (target {COLD_TARGET:.0f}x: "
          + ("met)" if cold <= COLD_TARGET else "missed)"))
    print(f"  one fk puma560 in the loaded page  {m['page warm']:6.2f} s   (request to typeset)")
    print(f"  the same request, native           {m['native warm']:6.2f} s   "
          f"ratio {m['page warm'] / m['native warm']:.1f}x")


if __name__ == "__main__":
    if shutil.which("node") is None and not PAGE.exists():
        sys.exit("web: node is needed to build the page (make web)")
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else RUNS))
