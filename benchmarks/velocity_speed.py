"""Time to the Jacobian in textbook form: dhsym against SymPy on the plain product.

The baseline is the geometric Jacobian built from the plain product (columns z_i × (p − p_i)
and z_i of the unsimplified frames) followed by `sympy.trigsimp` on each element; both run
in this process, so the ratio means something on a busy machine. Also timed: the PUMA's
factored determinant, against SymPy's determinant of the trigsimped Jacobian, factored.
dhsym's times are the best of five cold runs (fresh chain, empty SymPy cache).
Last, the Jacobian of a general 5-link chain in its middle frame against the same code
choosing among its candidate forms by `sympy.count_ops` (as it did before `core.size.length`).
And the factored determinant of a general 3-link arm (all its DH parameters symbols) against
SymPy on the plain product's Jacobian. Run with `make bench`. Targets: 7-axis Jacobian at least
100× faster and under 0.1 s; PUMA determinant under 1 s; the general chain's middle-frame Jacobian
under 2 s; the general 3-link determinant under 1 s (it took 4 s).
"""
from __future__ import annotations

import importlib
import sys
import time

import sympy
from simplify_speed import general_chain
from sympy.core.cache import clear_cache

from dhsym.core.budget import BudgetExceeded, time_budget
from dhsym.io.library import load
from dhsym.velocity import determinant, jacobian
from dhsym.velocity.jacobian import axis_frame

jacobian_module = importlib.import_module("dhsym.velocity.jacobian")  # the package re-exports its function
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


def timed(function, robot: str):
    """Seconds and result of function(chain) on a fresh chain with an empty SymPy cache (the
    loading of the robot file is not timed), or (None, None) past the budget."""
    chain = general_chain(int(robot.split("-")[1])) if robot.startswith("general-") else load(robot)
    clear_cache()
    start = time.perf_counter()
    try:
        with time_budget(BASELINE_BUDGET):
            result = function(chain)
    except BudgetExceeded:
        return None, None
    return time.perf_counter() - start, result


def best_of(runs: int, function, robot: str):
    """dhsym's time as the best of a few cold runs: the machine is shared, SymPy is not."""
    return min((timed(function, robot) for _ in range(runs)), key=lambda pair: pair[0])


def trigsimped_determinant(chain):
    return sympy.factor(plain_jacobian(chain).applyfunc(sympy.trigsimp).det(method="berkowitz"))


def main() -> int:
    failures = 0
    print(f"{'Jacobian':<12} {'dhsym s':>9} {'trigsimp s':>11} {'ratio':>8} {'ops':>6} {'ops trigsimp':>13}  target")
    for name in ROBOTS:
        seconds, ours = best_of(5, jacobian, name)
        baseline, theirs = timed(lambda chain: plain_jacobian(chain).applyfunc(sympy.trigsimp), name)
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
    seconds, result = best_of(5, determinant, "puma560")
    baseline, theirs = timed(trigsimped_determinant, "puma560")
    ok = seconds < 1.0
    failures += not ok
    base_text = f"{baseline:.3f} s" if baseline else f"> {BASELINE_BUDGET:g} s"
    print(f"\nPUMA 560 factored determinant: dhsym {seconds:.3f} s, SymPy (plain Jacobian, trigsimp, det, factor) "
          f"{base_text} (ratio {'>' if not baseline else ''}{(baseline or BASELINE_BUDGET) / seconds:.0f}x); "
          f"target < 1 s {'ok' if ok else 'MISSED'}")
    print(f"  dhsym: det J = {result.value}")
    print(f"  SymPy: det J = {theirs}")
    failures += middle_frame_of_a_general_chain()
    failures += general_three_link_determinant()
    return 1 if failures else 0


def plain_block_determinant(chain):
    """SymPy's way: the linear rows of the plain product's Jacobian, their determinant, factored."""
    return sympy.factor(plain_jacobian(chain)[:3, :].det(method="berkowitz"))


def general_three_link_determinant() -> int:
    """The factored determinant of a general 3-link arm (every DH parameter a symbol; its 3×3 block of
    the point's velocity), against SymPy on the plain product; CPU seconds, dhsym's the least of three
    cold runs."""
    def cpu(function):
        chain = general_chain(3)
        clear_cache()
        start = time.process_time()
        result = function(chain)
        return time.process_time() - start, result

    seconds, result = min((cpu(determinant) for _ in range(3)), key=lambda pair: pair[0])
    baseline, _ = cpu(plain_block_determinant)
    ok = seconds < 1.0
    print(f"\ngeneral 3-link determinant (CPU): dhsym {seconds:.2f} s, SymPy (plain Jacobian, det, factor) "
          f"{baseline:.2f} s (ratio {baseline / seconds:.1f}x); target < 1 s {'ok' if ok else 'MISSED'}")
    print(f"  dhsym: det J = {result.value}")
    return 0 if ok else 1


def middle_frame_of_a_general_chain() -> int:
    """²J of a general 5-link chain, choosing forms by core.size.length and by count_ops."""
    in_frame_2 = lambda chain: jacobian(chain, 2)  # noqa: E731
    seconds, _ = best_of(3, in_frame_2, "general-5")
    chosen_by = jacobian_module.length
    jacobian_module.length = sympy.count_ops
    try:
        baseline, _ = timed(in_frame_2, "general-5")
    finally:
        jacobian_module.length = chosen_by
    ok = seconds < 2.0
    base_text = f"{baseline:.2f} s" if baseline else f"> {BASELINE_BUDGET:g} s"
    print(f"\ngeneral 5-link Jacobian in frame 2: dhsym {seconds:.2f} s, choosing forms by count_ops {base_text} "
          f"(ratio {(baseline or BASELINE_BUDGET) / seconds:.0f}x); target < 2 s {'ok' if ok else 'MISSED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
