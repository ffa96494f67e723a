"""Time to the Jacobian in textbook form: dhsym against SymPy on the plain product.

The baseline is the geometric Jacobian built from the plain product (columns z_i × (p − p_i)
and z_i of the unsimplified frames) followed by `sympy.trigsimp` on each element; both run
in this process, so the ratio means something on a busy machine. Also timed: the PUMA's
factored determinant, against SymPy's determinant of the trigsimped Jacobian, factored.
Run with `make bench`. Targets: 7-axis Jacobian at least 100× faster and under 0.1 s; PUMA
determinant under 1 s.
"""
from __future__ import annotations

import sys
import time

import sympy
from sympy.core.cache import clear_cache

from dhsym.core.budget import BudgetExceeded, time_budget
from dhsym.io.library import load
from dhsym.velocity import determinant, jacobian
from dhsym.velocity.jacobian import axis_frame

BASELINE_BUDGET = 120.0  # seconds; past it the baseline is reported as "> budget"
ROBOTS = ["planar3r", "scara_spong", "puma560", "stanford", "iiwa7"]


def plain_jacobian(chain) -> sympy.Matrix:
    """The definition on the plain product, in the first frame, unsimplified."""
    first = chain.first_frame
    position = chain.transform(first, chain.last_frame, raw=True)[:3, 3]
    columns = []
    for joint in range(1, chain.n + 1):
        frame = chain.transform(first, axis_frame(chain, joint), raw=True)
        z = frame[:3, 2]
        if chain.rows[joint - 1].joint == "P":
            columns.append(list(z) + [0, 0, 0])
        else:
            columns.append(list(z.cross(position - frame[:3, 3])) + list(z))
    return sympy.Matrix(columns).T


def timed(function):
    clear_cache()
    start = time.perf_counter()
    try:
        with time_budget(BASELINE_BUDGET):
            result = function()
    except BudgetExceeded:
        return None, None
    return time.perf_counter() - start, result


def main() -> int:
    failures = 0
    print(f"{'Jacobian':<12} {'dhsym s':>9} {'trigsimp s':>11} {'ratio':>8} {'ops':>6} {'ops trigsimp':>13}  target")
    for name in ROBOTS:
        seconds, ours = timed(lambda: jacobian(load(name)))
        baseline, theirs = timed(lambda: plain_jacobian(load(name)).applyfunc(sympy.trigsimp))
        ratio = (baseline or BASELINE_BUDGET) / seconds
        verdict = ""
        if name == "iiwa7":
            ok = seconds < 0.1 and ratio >= 100
            failures += not ok
            verdict = f">= 100x and < 0.1 s {'ok' if ok else 'MISSED'}"
        base_text = f"{baseline:11.3f}" if baseline else f"{'>' + str(int(BASELINE_BUDGET)):>11}"
        their_ops = sympy.count_ops(theirs) if theirs is not None else ""
        print(f"{name:<12} {seconds:9.3f} {base_text} {('>' if not baseline else '') + f'{ratio:.0f}x':>8} "
              f"{sympy.count_ops(ours):6d} {their_ops:>13}  {verdict}")
    seconds, result = timed(lambda: determinant(load("puma560")))
    jac = plain_jacobian(load("puma560")).applyfunc(sympy.trigsimp)
    baseline, _ = timed(lambda: sympy.factor(jac.det(method="berkowitz")))
    ok = seconds < 1.0
    failures += not ok
    base_text = f"{baseline:.3f} s" if baseline else f"> {BASELINE_BUDGET:g} s"
    print(f"\nPUMA 560 factored determinant: dhsym {seconds:.3f} s, SymPy det + factor of the trigsimped "
          f"Jacobian {base_text} (ratio {'>' if not baseline else ''}{(baseline or BASELINE_BUDGET) / seconds:.0f}x); "
          f"target < 1 s {'ok' if ok else 'MISSED'}")
    print(f"  det J = {result.value}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
