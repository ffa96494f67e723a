"""Time to the simplified 0Tn: dhsym against sympy.trigsimp on each element of the raw product.

Both are measured in the same run, so the printed ratio is meaningful on a noisy machine.
Run with `make bench`. Targets (2-core machine): PUMA 560 < 0.3 s, 7-axis < 1 s,
`dhsym fk puma560` as a process < 2.5 s, general 6-link chain < 10 s with count_ops no
larger than the unexpanded product A1·(A2·(…·A6)). Last, printing: the `fk` command of a general
8-link chain in process, in each format, against reading the file and working out the transform
(text and JSON within 2.5x, LaTeX 5x).
"""
from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
import tempfile
import time

import sympy
from sympy.core.cache import clear_cache

from dhsym import Chain, DHRow
from dhsym.cli.app import main as run_command
from dhsym.core.budget import BudgetExceeded, time_budget
from dhsym.io.library import load

TRIGSIMP_BUDGET = 60.0  # seconds; past it the baseline is reported as "> budget"
TARGETS = {"puma560": 0.3, "iiwa7": 1.0, "general-6": 10.0}


def general_chain(n: int) -> Chain:
    """Every link with its own symbolic a, α and d: nothing to contract."""
    sym = lambda name: sympy.Symbol(name, real=True)  # noqa: E731
    rows = [DHRow.revolute(sym(f"theta_{i}"), sym(f"d_{i}"), sym(f"a_{i}"), sym(f"alpha_{i}")) for i in range(1, n + 1)]
    return Chain(rows, "standard")


def fresh(name: str) -> Chain:
    if name.startswith("general-"):
        return general_chain(int(name.split("-")[1]))
    return load(name)


def time_dhsym(name: str) -> tuple[float, sympy.Matrix]:
    """One cold run: a new chain and an empty SymPy cache, as a user's first call sees it."""
    chain = fresh(name)
    clear_cache()
    start = time.perf_counter()
    result = chain.fk()
    return time.perf_counter() - start, result


def time_trigsimp(name: str) -> float | None:
    raw = fresh(name).fk(raw=True)
    clear_cache()
    start = time.perf_counter()
    try:
        with time_budget(TRIGSIMP_BUDGET):
            raw.applyfunc(sympy.trigsimp)
    except BudgetExceeded:
        return None
    return time.perf_counter() - start


def nested_product_ops(chain: Chain) -> int:
    """count_ops of A1·(A2·(…·An)) multiplied out by SymPy, left unexpanded."""
    links = chain.links(raw=True)
    product = links[-1]
    for link in reversed(links[:-1]):
        product = link * product
    return sympy.count_ops(product)


def process_time(robot: str) -> float:
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "dhsym.cli", "fk", robot], check=True, capture_output=True)
    return time.perf_counter() - start


def main() -> int:
    names = ["planar3r", "scara", "puma560", "stanford", "iiwa7"] + [f"general-{n}" for n in range(2, 7)]
    print(f"{'chain':<11} {'dhsym s':>9} {'trigsimp s':>11} {'ratio':>8} {'ops':>7} {'ops A1(A2..)':>13}  target")
    failures = 0
    for name in names:
        seconds, result = time_dhsym(name)
        baseline = time_trigsimp(name)
        ops = sympy.count_ops(result)
        plain = nested_product_ops(fresh(name)) if name.startswith("general-") else None
        base_text = f"{baseline:11.3f}" if baseline is not None else f"{'>' + str(int(TRIGSIMP_BUDGET)):>11}"
        ratio = (baseline or TRIGSIMP_BUDGET) / seconds
        ratio_text = f"{'>' if baseline is None else ''}{ratio:.0f}x"
        verdict = ""
        if name in TARGETS:
            ok = seconds < TARGETS[name] and (plain is None or ops <= plain)
            failures += not ok
            verdict = f"< {TARGETS[name]} s {'ok' if ok else 'MISSED'}"
        print(f"{name:<11} {seconds:9.3f} {base_text} {ratio_text:>8} {ops:7d} {plain if plain else '':>13}  {verdict}")
    wall = min(process_time("puma560") for _ in range(3))
    ok = wall < 2.5
    failures += not ok
    print(f"\n`dhsym fk puma560` as a process: {wall:.2f} s (target < 2.5 s) {'ok' if ok else 'MISSED'}")
    failures += printing_speed()
    return 1 if failures else 0


def general_robot_file(folder: str, n: int) -> str:
    """A robot file of `general_chain(n)`: every link with its own symbolic a, α and d."""
    rows = "".join(f"  - {{joint: R, theta: theta_{i}, d: d_{i}, a: a_{i}, alpha: alpha_{i}}}\n"
                   for i in range(1, n + 1))
    path = os.path.join(folder, f"general{n}.yaml")
    with open(path, "w", encoding="utf-8") as file:
        file.write(f"name: general {n}-link chain\nconvention: standard\njoints:\n{rows}")
    return path


def command_seconds(argv: list[str]) -> float:
    """CPU seconds of one `dhsym` command in this process (after start-up), from an empty SymPy cache."""
    clear_cache()
    start = time.process_time()
    with contextlib.redirect_stdout(io.StringIO()):
        assert run_command(argv) == 0
    return time.process_time() - start


def printing_speed() -> int:
    """The `fk` command of a general 8-link chain in process, against reading the robot file and
    working out the same transform (`load(path).transform(0, j)`): what printing adds. ⁰T₈ as text
    (16 elements, 327,000 characters) and JSON; LaTeX lays out ⁰T₅ at most (--to 5). Best of three,
    CPU seconds. Targets: text and JSON within 2.5x, LaTeX, whose layout measures the width of each
    line it breaks, within 5x (printing took 20-50x before)."""
    with tempfile.TemporaryDirectory() as folder:
        path = general_robot_file(folder, 8)
        whole = min(read_and_transform(path, 8) for _ in range(3))
        part = min(read_and_transform(path, 5) for _ in range(3))
        print(f"\ngeneral 8-link chain: reading it and working out 0T8 {whole:.3f} s, 0T5 {part:.3f} s of CPU "
              "(the baselines)")
        failures = 0
        for options, baseline, target in ((["--format", "text"], whole, 2.5), (["--format", "json"], whole, 2.5),
                                          (["--format", "latex", "--to", "5"], part, 5)):
            seconds = min(command_seconds(["fk", path, *options]) for _ in range(3))
            ok = seconds / baseline <= target
            failures += not ok
            print(f"  `dhsym fk {' '.join(options)}` in process: {seconds:.3f} s, {seconds / baseline:.1f}x "
                  f"(target <= {target:g}x) {'ok' if ok else 'MISSED'}")
    return failures


def read_and_transform(path: str, end: int) -> float:
    clear_cache()
    start = time.process_time()
    load(path).transform(0, end)
    return time.process_time() - start


if __name__ == "__main__":
    sys.exit(main())
