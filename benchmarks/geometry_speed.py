"""Time of `dhsym import` (7-axis URDF) and `dhsym convert` (every built-in robot), against
baselines measured in the same run: the start-up of a `dhsym` process (`dhsym list`), reading
the same URDF with yourdfpy, and reading the same robot file with dhsym.

Run with `make bench`. Target (2-core machine): each well under 1 s of work after start-up.
"""
from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

from sympy.core.cache import clear_cache

from dhsym.cli import app as cli
from dhsym.io.library import ROBOTS_DIR, builtin_names
from dhsym.io.robotfile import load_robot_file

PANDA = Path(__file__).parent.parent / "tests" / "data" / "panda.urdf"
TARGET = 1.0  # seconds of work after start-up


def process_seconds(*args: str, repeat: int = 5) -> float:
    """The fastest of `repeat` runs: the least disturbed by the other work on a shared machine."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "dhsym.cli", *args], check=True, capture_output=True)
        times.append(time.perf_counter() - start)
    return min(times)


def in_process_seconds(argv: list[str]) -> float:
    """One cold run of a command inside this process (SymPy's cache emptied first)."""
    clear_cache()
    start = time.perf_counter()
    status = cli.main(argv)
    elapsed = time.perf_counter() - start
    assert status == 0, argv
    return elapsed


def yourdfpy_seconds() -> float | None:
    try:
        import yourdfpy
    except ImportError:
        return None
    start = time.perf_counter()
    yourdfpy.URDF.load(str(PANDA), build_scene_graph=True, load_meshes=False)
    return time.perf_counter() - start


def main() -> int:
    failures = 0
    startup = process_seconds("list")
    whole = process_seconds("import", str(PANDA))
    work = whole - startup
    ok = work < TARGET
    failures += not ok
    print(f"`dhsym import panda.urdf` as a process: {whole:.2f} s, start-up (`dhsym list`) {startup:.2f} s, "
          f"work {work:.2f} s = {whole / startup:.2f}x start-up  (target work < {TARGET:g} s) {'ok' if ok else 'SLOW'}")
    baseline = yourdfpy_seconds()
    inside = in_process_seconds(["import", str(PANDA), "-o", "/dev/null"])
    if baseline:
        print(f"  in process: dhsym import {inside:.3f} s; yourdfpy.URDF.load of the same file {baseline:.3f} s "
              f"(ratio {inside / baseline:.1f}x)")
    print()
    print(f"{'robot':<24} {'convert s':>10} {'read s':>8} {'ratio':>7}")
    worst = 0.0
    for name in builtin_names():
        clear_cache()
        start = time.perf_counter()
        chain = load_robot_file(ROBOTS_DIR / f"{name}.yaml").chain
        read = time.perf_counter() - start
        target = "modified" if chain.convention == "standard" else "standard"
        seconds = in_process_seconds(["convert", name, "--to", target, "-o", "/dev/null"])
        worst = max(worst, seconds)
        print(f"{name:<24} {seconds:>10.3f} {read:>8.3f} {seconds / read:>6.1f}x")
    ok = worst < TARGET
    failures += not ok
    print(f"\nslowest convert: {worst:.3f} s of work (target < {TARGET:g} s) {'ok' if ok else 'SLOW'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
