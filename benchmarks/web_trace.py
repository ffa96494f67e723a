"""Where the browser page's cold start goes, from Chromium's own trace (a profile, not a benchmark).

    python benchmarks/web_trace.py [PAGE_DIR] [--keep TRACE.json]

Opens `index.html?robot=puma560&show=fk` of PAGE_DIR (default build/web) once in a fresh browser
(empty cache; given time to finish its own start-up first, as benchmarks/web_speed.py does) while
Chromium records its trace, and prints, in seconds since the page's request was sent:
- each file's request, first byte and end (is the large state fetched early, does the server lag?);
- for the page's thread and each worker's thread, the tasks longer than MIN_TASK_S, with what ran
  inside them (MathJax's script, DecompressionStream inflating, the runtime instantiated, Python's work);
- the busy seconds of every thread by kind of work, background WebAssembly compilation included:
  on a machine with few cores, work on any thread slows the others.
One run of a busy machine is noisy: compare the shape, and measure with web_speed.py.
"""
from __future__ import annotations

import argparse
import collections
import json
import tempfile
import time
from pathlib import Path

from web_speed import CHROMIUM, CHROMIUM_ARGS, LINK, PAGE, READY, serve

CATEGORIES = ["devtools.timeline", "disabled-by-default-devtools.timeline", "v8", "v8.wasm", "loading",
              "blink.user_timing"]
MIN_TASK_S = 0.02
SETTLE_S = 2.0


def record(folder: Path, trace: Path) -> dict:
    from playwright.sync_api import sync_playwright

    server, base = serve(folder)
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        page.goto("about:blank")
        time.sleep(SETTLE_S)
        browser.start_tracing(page=page, path=str(trace), categories=CATEGORIES)
        started = time.perf_counter()
        page.goto(base + LINK)
        page.wait_for_selector(READY, state="attached", timeout=300_000)
        seconds = time.perf_counter() - started
        marks = page.evaluate("window.dhsymMarks || {}")
        browser.stop_tracing()
        browser.close()
    server.shutdown()
    return {"seconds": seconds, "marks": marks, "base": base}


def events_of(trace: Path) -> tuple[list, dict]:
    data = json.loads(trace.read_text())
    events = data["traceEvents"] if isinstance(data, dict) else data
    threads = {(e["pid"], e["tid"]): f"{e['args']['name']} {e['tid']}" for e in events
               if e.get("ph") == "M" and e.get("name") == "thread_name"}
    return events, threads


def requests(events: list, base: str) -> tuple[float, list]:
    """The page's own requests: (the time its first was sent, [(path, sent, first byte, end)])."""
    kinds = {"ResourceSendRequest": 0, "ResourceReceiveResponse": 1, "ResourceFinish": 2}
    found = collections.defaultdict(lambda: [None, None, None, None])
    for event in events:
        data = (event.get("args") or {}).get("data")
        if event.get("name") in kinds and isinstance(data, dict) and data.get("requestId"):
            row = found[data["requestId"]]
            row[0] = row[0] or data.get("url")
            row[1 + kinds[event["name"]]] = event["ts"] / 1e6
    rows = [row for row in found.values() if row[0] and row[0].startswith(base) and row[1]]
    start = min(row[1] for row in rows)
    return start, sorted(([row[0][len(base):].split("?")[0] or "index.html"] + row[1:] for row in rows),
                         key=lambda row: row[1])


def tasks(events: list, threads: dict, start: float) -> dict:
    """{thread: [(start, seconds, name, [(inner name, seconds)])]} of the page's and workers' threads."""
    spans = collections.defaultdict(list)
    for event in events:
        name = threads.get((event.get("pid"), event.get("tid")), "")
        if event.get("ph") == "X" and event.get("dur") and ("CrRendererMain" in name or "Worker thread" in name):
            spans[name].append((event["ts"] / 1e6 - start, event["dur"] / 1e6, event["name"]))
    shown = {}
    for name, found in spans.items():
        found.sort(key=lambda span: (span[0], -span[1]))
        tops, end = [], -1.0
        for at, seconds, what in found:
            if at >= end:
                tops.append((at, seconds, what, collections.Counter()))
                end = at + seconds
            elif tops and what != tops[-1][2]:
                tops[-1][3][what] = max(tops[-1][3][what], seconds)  # outermost of each kind, roughly
        shown[name] = [top for top in tops if top[1] >= MIN_TASK_S and top[0] >= 0]
    return shown


def busy(events: list, threads: dict) -> dict:
    """{thread: Counter(kind of work: seconds)} of the work that threads do by themselves."""
    kinds = ("wasm.", "V8.", "v8.", "DecompressionStream", "EvaluateScript", "Layout", "TimerFire",
             "HandlePostMessage")
    totals = collections.defaultdict(collections.Counter)
    for event in events:
        if event.get("ph") == "X" and event.get("dur") and event["name"].startswith(kinds):
            totals[threads.get((event["pid"], event["tid"]), "?")][event["name"]] += event["dur"] / 1e6
    return totals


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("page", nargs="?", type=Path, default=PAGE)
    parser.add_argument("--keep", type=Path, help="keep the trace here (open it in chrome://tracing or Perfetto)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        trace = args.keep or Path(scratch) / "trace.json"
        visit = record(args.page, trace)
        events, threads = events_of(trace)
    start, files = requests(events, visit["base"])
    print(f"cold start {visit['seconds']:.2f} s (wall clock, tracing on); the page's marks: "
          + "  ".join(f"{mark} {value:.2f}" for mark, value in visit["marks"].items()))
    print("files (s): sent, first byte, end")
    for path, sent, first, end in files:
        print(f"  {path:34} {sent - start:6.3f} {(first or sent) - start:6.3f} {(end or sent) - start:6.3f}")
    for thread, found in tasks(events, threads, start).items():
        print(f"{thread}: tasks of {MIN_TASK_S} s or more (start, seconds, what ran inside)")
        for at, seconds, what, inside in found:
            parts = ", ".join(f"{name} {inner:.3f}" for name, inner in inside.most_common(3))
            print(f"  {at:6.3f} {seconds:6.3f} {what}: {parts}")
    print("busy seconds by thread and kind of work")
    for thread, kinds in sorted(busy(events, threads).items(), key=lambda item: -sum(item[1].values())):
        top = ", ".join(f"{name} {seconds:.2f}" for name, seconds in kinds.most_common(4) if seconds >= 0.01)
        if top:
            print(f"  {thread}: {top}")


if __name__ == "__main__":
    main()
