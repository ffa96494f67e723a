"""The browser page (build/web, `make web`) against dhsym as a native process, in the same run.

- Cold start: a new browser profile (empty cache) opens `index.html?robot=puma560&show=fk` and waits
  for ⁰T₆ typeset in #result (`data-state="ready"`), against a native `dhsym fk puma560` process run
  as an installed dhsym runs (its bytecode compiled and cached; Python's start, the imports, the
  work and the printing). Both are wall-clock seconds from the start to the result; the browser is
  running already, as a student's is: each new profile's browser is given BROWSER_SETTLE_S to finish
  its own start-up work (Chromium prepares its built-in pages then) before the page is opened.
  Target (issue 28): within 3x.
- Where the page's cold start goes: the page's own marks (web/page.js, web/worker.js), in seconds
  since it was opened.
- A second visit: the same profile opens the page again (the files in its cache on disk).
- One `fk puma560` once the page has loaded: a robot file the page has not read yet (the PUMA's file
  with a comment added) in, the typeset ⁰T₆ out, against the same request answered by
  `dhsym.web.app.handle` in a native process that has dhsym imported (the work and the LaTeX
  layout; the page adds MathJax's typesetting).
- Bytes: what the page loads from the server for its first result, against the prototype's 25.9 MB.

The median of RUNS runs, page and native runs interleaved so that a busy machine slows both alike.
The page is served by a local http.server to Chromium (Debian's, driven by Playwright); a request
for any other address stops the benchmark (watched, not blocked: blocking turns the cache off).
`--against DIR` measures another build of the page (an older one, say) in the same runs.
Run with `make bench`, or `python benchmarks/web_speed.py [RUNS] [--against DIR]`.
"""
from __future__ import annotations

import argparse
import functools
import http.server
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "build" / "web"
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
RUNS = 5
BROWSER_SETTLE_S = 2.0  # a just-launched Chromium works on its own pages for about a second
COLD_TARGET = 3.0
PROTOTYPE_BYTES = 25.9e6
LINK = "index.html?robot=puma560&show=fk"
READY = "#result[data-state=ready]"
# The page's marks (web/page.js), in the order they come, and the worker's (web/worker.js).
PAGE_MARKS = ["worker started", "python ready", "first answer", "first result typeset"]


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(folder: Path) -> tuple[http.server.ThreadingHTTPServer, str]:
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=str(folder)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


def visit(page, base: str) -> dict:
    """Opens the page's link: seconds to the typeset ⁰T₆ (wall clock), bytes over the network, marks."""
    loaded = []
    listener = lambda request: loaded.append(request.sizes()["responseBodySize"])  # noqa: E731
    page.on("requestfinished", listener)
    started = time.perf_counter()
    page.goto(base + LINK)
    page.wait_for_selector(READY, state="attached", timeout=300_000)
    seconds = time.perf_counter() - started
    page.remove_listener("requestfinished", listener)
    marks = page.evaluate("window.dhsymMarks || {}")
    timings = page.evaluate("window.dhsymTimings || {}")
    return {"seconds": seconds, "bytes": sum(max(0, size) for size in loaded), "marks": marks, "worker": timings}


def page_runs(playwright, base: str) -> dict:
    """A cold visit (a new browser profile: empty cache), one fk of a new file in the loaded page, and
    a second visit (the profile's cache on disk, as a student's browser keeps it)."""
    with tempfile.TemporaryDirectory(prefix="dhsym-browser-") as profile:
        context = playwright.chromium.launch_persistent_context(profile, executable_path=CHROMIUM, args=CHROMIUM_ARGS,
                                                                viewport={"width": 1280, "height": 900})
        page = context.new_page()
        page.goto("about:blank")
        time.sleep(BROWSER_SETTLE_S)
        outside = []  # watched, not routed: routing requests turns the browser's cache off
        page.on("request", lambda request: None if request.url.removeprefix("blob:").startswith(base)
                else outside.append(request.url))
        cold = visit(page, base)
        cold["warm"] = page_warm(page)
        cold["second"] = visit(page, base)
        context.close()
    if outside:
        raise SystemExit(f"web: the page asked for addresses outside its folder: {outside[:3]}")
    return cold


def page_warm(page) -> float:
    """One fk puma560 of a robot file the loaded page has not read yet: request to typeset."""
    text = (ROOT / "dhsym" / "robots" / "puma560.yaml").read_text() + f"# {time.time()}\n"
    page.fill("#yaml", text)
    page.wait_for_selector("#result[data-state=working]", state="attached")
    page.wait_for_selector(READY, state="attached", timeout=300_000)
    return float(page.get_attribute("#result", "data-seconds"))  # the page's own clock: request to typeset


def native_command() -> list[str]:
    script = Path(sys.executable).parent / "dhsym"  # the console script of an installed dhsym
    return [str(script)] if script.exists() else [sys.executable, "-m", "dhsym.cli"]


def native_cold(env: dict) -> float:
    started = time.perf_counter()
    subprocess.run(native_command() + ["fk", "puma560"], stdout=subprocess.DEVNULL, check=True, cwd=ROOT, env=env)
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


def native_warm(env: dict) -> float:
    result = subprocess.run([sys.executable, "-c", NATIVE_WARM, str(ROOT / "dhsym" / "robots" / "puma560.yaml")],
                            capture_output=True, text=True, check=True, cwd=ROOT, env=env)
    return float(result.stdout)


def measure(pages: dict[str, Path], runs: int) -> tuple[dict, dict]:
    """{page name: [page runs]}, {"cold": [...], "warm": [...]} of the native process, interleaved."""
    from playwright.sync_api import sync_playwright

    servers = {name: serve(folder) for name, folder in pages.items()}
    measured = {name: [] for name in pages}
    native = {"cold": [], "warm": []}
    with tempfile.TemporaryDirectory(prefix="dhsym-bytecode-") as bytecode, sync_playwright() as playwright:
        # an installed dhsym has its bytecode compiled: kept here, written by the first run
        env = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = bytecode
        native_cold(env)  # the file cache and the bytecode, as a student's second command has them
        for _ in range(runs):
            for name, (_, base) in servers.items():
                measured[name].append(page_runs(playwright, base))
                native["cold"].append(native_cold(env))
            native["warm"].append(native_warm(env))
    for server, _ in servers.values():
        server.shutdown()
    return measured, native


def median_of(runs: list[dict], *keys) -> float:
    """The median of run[key1][key2]... over the runs that have it (NaN if none has)."""
    values = []
    for run in runs:
        for key in keys:
            run = run.get(key) if isinstance(run, dict) else None
        if isinstance(run, (int, float)):
            values.append(run)
    return statistics.median(values) if values else float("nan")


def report(name: str, runs: list[dict], native: dict) -> None:
    cold, native_cold_s = median_of(runs, "seconds"), statistics.median(native["cold"])
    ratio = cold / native_cold_s
    loaded = median_of(runs, "bytes")
    print(f"{name}: Chromium, wall-clock medians of {len(runs)} runs interleaved with the native process")
    print(f"  bytes loaded for the first result   {loaded / 1e6:6.1f} MB   (prototype {PROTOTYPE_BYTES / 1e6:.1f} MB: "
          + ("no more)" if loaded <= PROTOTYPE_BYTES else "more)"))
    print(f"  page cold start to typeset 0T6     {cold:6.2f} s   (best {min(run['seconds'] for run in runs):.2f} s)")
    steps = "  ".join(f"{mark} {median_of(runs, 'marks', mark):.2f}" for mark in PAGE_MARKS)
    print(f"    the page's own clock (s): {steps}")
    worker = sorted({key for run in runs for key in run["worker"]}, key=lambda key: median_of(runs, "worker", key))
    print("    in the worker (s since it started): "
          + "  ".join(f"{key} {median_of(runs, 'worker', key):.2f}" for key in worker))
    print(f"  native `dhsym fk puma560` process  {native_cold_s:6.2f} s   (best {min(native['cold']):.2f} s)")
    print(f"  cold start ratio                   {ratio:6.1f}x  (target {COLD_TARGET:.0f}x: "
          + ("met)" if ratio <= COLD_TARGET else "missed)"))
    print(f"  second visit (browser's cache)     {median_of(runs, 'second', 'seconds'):6.2f} s   "
          f"{median_of(runs, 'second', 'bytes') / 1e6:.1f} MB over the network")
    warm, native_warm_s = median_of(runs, "warm"), statistics.median(native["warm"])
    print(f"  one fk puma560 in the loaded page  {warm:6.2f} s   (request to typeset)")
    print(f"  the same request, native           {native_warm_s:6.2f} s   ratio {warm / native_warm_s:.1f}x")


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="?", type=int, default=RUNS)
    parser.add_argument("--against", type=Path, help="another build of the page, measured in the same runs")
    args = parser.parse_args(argv)
    pages = {"web page (build/web)": PAGE}
    if args.against:
        pages[f"web page ({args.against})"] = args.against
    for folder in pages.values():
        if not (folder / "index.html").exists():
            print(f"web: {folder} has no page; run `make web` first")
            return 1
    if not Path(CHROMIUM).exists():
        print("web: skipped, no Chromium (scripts/ensure-browser.sh installs it)")
        return 0
    measured, native = measure(pages, args.runs)
    for name, runs in measured.items():
        report(name, runs, native)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
