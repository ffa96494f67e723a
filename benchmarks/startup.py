"""Start-up: what a student waits for each time a command runs, against the bare SymPy import.

Each command runs as a whole process (`python -m dhsym.cli ...`), and so does `python -c
"import sympy"`; the runs are interleaved so that a busy machine slows both alike, and the cost
of a run is its CPU time (user + system, from `resource.getrusage(RUSAGE_CHILDREN)`), which
moves less than wall time on a shared machine. The processes run with compiled bytecode, as an
installed dhsym does (kept in a temporary folder: PYTHONPYCACHEPREFIX), also where the
environment says PYTHONDONTWRITEBYTECODE; the warm-up round writes it.

Two baselines: the import as Python runs it, and the import with the garbage collector off while
it runs and what it made frozen afterwards, which is what the `dhsym` process does
(dhsym/cli/__main__.py). The ratios against the second are the fair ones: the collector's work is
not dhsym's to save. One more row runs `fk` with bytecode not written and no cache folder, as an
editable install under PYTHONDONTWRITEBYTECODE does: it reads the bytecode `make install` compiled
(`compileall`), else it compiles dhsym's modules anew each time. Reported: the median of RUNS runs
of each. Target: `fk` and `table` within 1.2x of the import (issue 17).
Run with `make bench`, or `python benchmarks/startup.py [RUNS]`.
"""
from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PLAIN = "python -c \"import sympy\""
COLLECTOR_OFF = "the same, collector off"
BASELINES = [
    (PLAIN, [sys.executable, "-c", "import sympy"]),
    # what dhsym/cli/__main__.py does around its imports and before it exits
    (COLLECTOR_OFF, [sys.executable, "-c", "import gc, sys; gc.disable(); import sympy; gc.freeze(); gc.enable(); "
                     "gc.freeze(); sys.exit(0)"]),
]
COMMANDS = [
    ("fk puma560", [sys.executable, "-m", "dhsym.cli", "fk", "puma560"]),
    ("table puma560", [sys.executable, "-m", "dhsym.cli", "table", "puma560"]),
    ("jacobian puma560", [sys.executable, "-m", "dhsym.cli", "jacobian", "puma560"]),
    # the same work without the process's garbage-collector housekeeping (cli/__main__.py): what the
    # lazy imports alone give, so that a module imported too early shows here
    ("fk puma560, no gc setup", [sys.executable, "-c", "import sys; from dhsym.cli.app import main; "
                                 "sys.exit(main(['fk', 'puma560']))"]),
]
UNCACHED = "fk puma560, no bytecode written"  # runs in the environment of an editable install, see the docstring
TARGETS = {"fk puma560": 1.2, "table puma560": 1.2}  # the goal, against the fair baseline
RUNS = 7


def cpu_seconds(argv: list[str], env: dict) -> float:
    """User plus system CPU time of one whole process running argv (its output discarded)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, env=env, cwd=ROOT)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def medians(runs: int) -> dict[str, float]:
    """The median CPU time of each process, the runs interleaved (baselines, commands, baselines, ...)."""
    processes = [*BASELINES, *COMMANDS]
    times: dict[str, list[float]] = {name: [] for name, _ in processes + [(UNCACHED, None)]}
    path = os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))
    uncached = {key: value for key, value in os.environ.items() if key != "PYTHONPYCACHEPREFIX"}
    uncached.update(PYTHONDONTWRITEBYTECODE="1", PYTHONPATH=path)
    with tempfile.TemporaryDirectory(prefix="dhsym-bytecode-") as bytecode:
        env = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
        env.update(PYTHONPYCACHEPREFIX=bytecode, PYTHONPATH=path)
        for _, argv in processes:  # one warm-up round: the file cache, the bytecode
            cpu_seconds(argv, env)
        for _ in range(runs):
            for name, argv in processes:
                times[name].append(cpu_seconds(argv, env))
            times[UNCACHED].append(cpu_seconds(COMMANDS[0][1], uncached))
    return {name: statistics.median(values) for name, values in times.items()}


def main(runs: int = RUNS) -> int:
    result = medians(runs)
    plain, fair = result[PLAIN], result[COLLECTOR_OFF]
    print(f"start-up, median CPU time of {runs} whole processes (interleaved); ratios to the import as Python runs "
          "it, and to the import with the collector off as dhsym's process has it")
    print(f"  {PLAIN:38} {plain:6.3f} s   1.00x")
    print(f"  {COLLECTOR_OFF:38} {fair:6.3f} s   {fair / plain:4.2f}x   1.00x")
    for name in [name for name, _ in COMMANDS] + [UNCACHED]:
        ratio = result[name] / fair
        target = TARGETS.get(name)
        verdict = "" if target is None else (f"  (target {target:.1f}x: " + ("met)" if ratio <= target else "missed)"))
        print(f"  {'dhsym ' + name:38} {result[name]:6.3f} s   {result[name] / plain:4.2f}x   {ratio:4.2f}x{verdict}")
    return 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else RUNS))
