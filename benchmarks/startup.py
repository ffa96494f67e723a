"""Start-up: what a student waits for each time a command runs, against the bare SymPy import.

Each command runs as a whole process (`python -m dhsym.cli ...`), and so does `python -c
"import sympy"`; the runs are interleaved so that a busy machine slows both alike, and the cost
of a run is its CPU time (user + system, from `resource.getrusage(RUSAGE_CHILDREN)`), which
moves less than wall time on a shared machine. The processes run with compiled bytecode, as an
installed dhsym does (kept in a temporary folder: PYTHONPYCACHEPREFIX), also where the
environment says PYTHONDONTWRITEBYTECODE; the warm-up round writes it. Reported: the median of RUNS runs of each, and
the ratio to the SymPy import. Target: `fk` and `table` within 1.2x (issue 17).
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
BASELINE = ("import sympy", [sys.executable, "-c", "import sympy"])
COMMANDS = [
    ("fk puma560", [sys.executable, "-m", "dhsym.cli", "fk", "puma560"]),
    ("table puma560", [sys.executable, "-m", "dhsym.cli", "table", "puma560"]),
    ("jacobian puma560", [sys.executable, "-m", "dhsym.cli", "jacobian", "puma560"]),
    # the same work without the process's garbage-collector housekeeping (cli/__main__.py): what the
    # lazy imports alone give, so that a module imported too early shows here
    ("fk puma560, no gc setup", [sys.executable, "-c", "import sys; from dhsym.cli.app import main; "
                                 "sys.exit(main(['fk', 'puma560']))"]),
]
TARGETS = {"fk puma560": 1.2, "table puma560": 1.2}  # the goal; jacobian has none
RUNS = 7


def cpu_seconds(argv: list[str], env: dict) -> float:
    """User plus system CPU time of one whole process running argv (its output discarded)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, env=env, cwd=ROOT)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def medians(runs: int) -> dict[str, float]:
    """The median CPU time of each process, the runs interleaved (baseline, commands, baseline, ...)."""
    times: dict[str, list[float]] = {name: [] for name, _ in [BASELINE, *COMMANDS]}
    with tempfile.TemporaryDirectory(prefix="dhsym-bytecode-") as bytecode:
        env = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
        env.update(PYTHONPYCACHEPREFIX=bytecode,
                   PYTHONPATH=os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")])))
        for _, argv in [BASELINE, *COMMANDS]:  # one warm-up round: the file cache, the bytecode
            cpu_seconds(argv, env)
        for _ in range(runs):
            for name, argv in [BASELINE, *COMMANDS]:
                times[name].append(cpu_seconds(argv, env))
    return {name: statistics.median(values) for name, values in times.items()}


def main(runs: int = RUNS) -> int:
    result = medians(runs)
    base = result[BASELINE[0]]
    print(f"start-up, median CPU time of {runs} whole processes (interleaved)")
    label = 'python -c "import sympy"'
    print(f"  {label:28} {base:6.3f} s   1.00x")
    for name, _ in COMMANDS:
        ratio = result[name] / base
        target = TARGETS.get(name)
        verdict = "" if target is None else (f"  (target {target:.1f}x: " + ("met)" if ratio <= target else "missed)"))
        print(f"  {'dhsym ' + name:28} {result[name]:6.3f} s   {ratio:4.2f}x{verdict}")
    return 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else RUNS))
