"""Closed-form inverse kinematics: how long the derivation takes, how evaluation compares with
forward kinematics, and how fast a chain with no closed form is refused.

1. Derivation time of the PUMA 560 (kinematic decoupling) and the UR5 (three parallel axes,
   Hawkins's way), cold (fresh chain, empty SymPy cache).
   Both wall-clock and CPU time are printed: on a shared machine the wall clock waits for others.
2. `evaluate()` on 10,000 poses (every branch at once) against numpy FK of the same poses
   (the chain's contracted 0T6, lambdified), as a ratio: the issue wants evaluation at about the
   cost of FK. The ratio is also given per branch (the PUMA has 8, the UR5 8).
3. Refusal time of a general 6R (symbolic twists): decided from the axes, before any algebra.

4. With --all: the time (CPU, least of 3 cold runs) of every built-in robot that has a closed
   form: the derivation (`solve`) and `robot.ik()` as a whole (decimals as written, branch names
   checked against the arm: all that `dhsym ik` works out).

Run: python benchmarks/ik_speed.py [--all]
"""
from __future__ import annotations

import math
import sys
import time

import numpy
import sympy
from sympy.core.cache import clear_cache

import dhsym
from dhsym.api.ik import inverse_kinematics
from dhsym.errors import UserError
from dhsym.inverse.evaluate import Program
from dhsym.inverse.solve import solve
from dhsym.io.library import builtin_names

POSES = 10_000


def derive(name: str):
    clear_cache()
    chain = dhsym.load(name)
    start, cpu = time.perf_counter(), time.process_time()
    solution = inverse_kinematics(chain).solution
    return chain, solution, (time.perf_counter() - start, time.process_time() - cpu)


def fk_function(chain):
    """numpy FK: the contracted 0T6 lambdified over the joint variables, constants put in."""
    matrix = chain.fk().xreplace({k: sympy.Float(v) for k, v in chain.sample.items()})
    elements = sympy.lambdify(chain.joint_variables, [matrix[r, c] for r in range(3) for c in range(4)], "numpy")

    def fk(*q):
        stacked = numpy.zeros((len(q[0]), 4, 4))
        stacked[:, 3, 3] = 1.0
        for k, value in enumerate(elements(*q)):
            stacked[:, k // 4, k % 4] = value
        return stacked
    return fk


def poses(chain, fk, count: int) -> numpy.ndarray:
    """`count` random poses (N, 4, 4) by numpy FK."""
    rng = numpy.random.default_rng(1)
    return fk(*[rng.uniform(-math.pi, math.pi, count) for _ in chain.joint_variables])


def best_of(function, runs: int = 3) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def general_6r():
    t = sympy.symbols("theta_1:7", real=True)
    rows = [dhsym.DHRow.revolute(t[k], d=sympy.Symbol(f"d_{k + 1}", real=True),
                                 a=sympy.Symbol(f"a_{k + 1}", real=True),
                                 alpha=sympy.Symbol(f"alpha_{k + 1}", real=True)) for k in range(6)]
    return dhsym.Robot(dhsym.Chain(rows, "standard"), name="general 6R")


def report(name: str) -> None:
    chain, solution, (wall, cpu) = derive(name)
    fk = fk_function(chain)
    targets = poses(chain, fk, POSES)
    evaluate = Program(solution)  # compiled once, as robot.ik().evaluate keeps it for a user's second call
    evaluate(targets[:10])
    fk_time = best_of(lambda: poses(chain, fk, POSES))
    ik_time = best_of(lambda: evaluate(targets))
    result = evaluate(targets)
    branches = len(solution.branches)
    real = numpy.mean(~numpy.isnan(result).any(axis=-1)) * branches
    print(f"{name}: derivation {wall:.2f} s ({cpu:.2f} s of CPU); {branches} branches "
          f"({real:.1f} real per pose on average)")
    print(f"  {POSES} poses: evaluate {ik_time * 1e3:.1f} ms, numpy FK {fk_time * 1e3:.1f} ms, "
          f"ratio {ik_time / fk_time:.1f} (per branch {ik_time / fk_time / branches:.2f})")


def solved(robot):
    """The derivation alone (`solve` of the robot file's chain, with its sample, numbers and name)."""
    return solve(robot.chain, sample=robot.sample, numbers=robot.numbers, name=robot.name)


def derivation_cpu(name: str, runs: int = 3, work=solved) -> float:
    """The least CPU time of `runs` cold derivations (a fresh chain, an empty SymPy cache)."""
    times = []
    for _ in range(runs):
        clear_cache()
        chain = dhsym.load(name)
        start = time.process_time()
        work(chain)
        times.append(time.process_time() - start)
    return min(times)


def every_robot() -> None:
    print("CPU seconds (least of 3 cold runs): solve, robot.ik()")
    for name in builtin_names():
        try:
            print(f"  {name:22s} {derivation_cpu(name):.2f}  {derivation_cpu(name, work=inverse_kinematics):.2f}",
                  flush=True)
        except UserError as error:
            print(f"  {name:22s} refused: {error}")


def main() -> None:
    for name in ("puma560", "ur5"):
        report(name)
    chain = general_6r()
    start = time.perf_counter()
    try:
        inverse_kinematics(chain)
        message = "solved (unexpected)"
    except UserError as error:
        message = str(error)
    print(f"general 6R: refused in {time.perf_counter() - start:.3f} s: {message}")
    if "--all" in sys.argv[1:]:
        every_robot()


if __name__ == "__main__":
    main()
