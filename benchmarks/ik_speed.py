"""Closed-form inverse kinematics: how long the derivation takes, how evaluation compares with
forward kinematics, and how fast a chain with no closed form is refused.

1. Derivation time of the PUMA 560 (kinematic decoupling) and the UR5 (three parallel axes,
   Hawkins's way), cold (fresh chain, empty SymPy cache).
   Both wall-clock and CPU time are printed: on a shared machine the wall clock waits for others.
2. `evaluate()` on 10,000 poses (every branch at once) against numpy FK of the same poses
   (the chain's contracted 0T6, lambdified), as a ratio: the issue wants evaluation at about the
   cost of FK. The ratio is also given per branch (the PUMA has 8, the UR5 8).
3. The generated module (`dhsym ik ROBOT --format python`) against the plain numpy FK a user
   writes (six DH matrices built with np.cos/np.sin, multiplied with @), in the same run:
   every branch of BATCH poses at once against that FK of the same poses, and one pose (a 4x4
   array) against that FK of one pose with numpy; the FK of one pose with `math` (math.cos,
   math.sin into the same 4x4 arrays) is printed too. CPU time, least of 5 runs (batch) or of 7
   timed loops (one pose). Aims of issue 27: batch within 2.5x, one pose within 2x the numpy FK.
4. Refusal time of a general 6R (symbolic twists): decided from the axes, before any algebra.

5. With --all: the time (CPU, least of 3 cold runs) of every built-in robot that has a closed
   form: the derivation (`solve`) and `robot.ik()` as a whole (decimals as written, branch names
   checked against the arm: all that `dhsym ik` works out).

Run: python benchmarks/ik_speed.py [--all]
"""
from __future__ import annotations

import math
import sys
import time
import timeit

import numpy
import sympy
from sympy.core.cache import clear_cache

import dhsym
from dhsym.api.ik import inverse_kinematics
from dhsym.errors import UserError
from dhsym.inverse.codegen import module_text
from dhsym.inverse.evaluate import Program
from dhsym.inverse.solve import solve
from dhsym.io.library import builtin_names

POSES = 10_000
BATCH = 100_000  # poses for the generated module against the plain FK


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


def best_of(function, runs: int = 3, clock=time.perf_counter) -> float:
    times = []
    for _ in range(runs):
        start = clock()
        function()
        times.append(clock() - start)
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


def dh_numbers(robot) -> list[tuple[float, float, float, float]]:
    """(theta offset, d, a, alpha) of each revolute row, in numbers: what a user copies from the table."""
    sample = {k: sympy.Float(v) for k, v in robot.sample.items()}
    numbers = []
    for row in robot.chain.rows:
        assert row.joint == "R" and sympy.diff(row.theta, row.variable) == 1, "revolute rows only"
        offset = row.theta.subs(row.variable, 0)
        numbers.append(tuple(float(sympy.sympify(x).xreplace(sample)) for x in (offset, row.d, row.a, row.alpha)))
    return numbers


def modified_link(ct, st, d, a, ca, sa):
    """Craig's (modified) DH matrix Rx(alpha) Tx(a) Rz(theta) Tz(d) of one pose, written out."""
    return numpy.array([[ct, -st, 0.0, a], [st * ca, ct * ca, -sa, -sa * d], [st * sa, ct * sa, ca, ca * d],
                        [0.0, 0.0, 0.0, 1.0]])


def standard_link(ct, st, d, a, ca, sa):
    """The standard DH matrix Rz(theta) Tz(d) Tx(a) Rx(alpha) of one pose, written out."""
    return numpy.array([[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0.0, sa, ca, d],
                        [0.0, 0.0, 0.0, 1.0]])


def links_of_poses(ct, st, d, a, ca, sa, modified: bool):
    """The DH matrices (N, 4, 4) of N angles given by their cosines and sines, filled in place."""
    matrix = numpy.zeros((len(ct), 4, 4))
    if modified:
        matrix[:, 0, 0], matrix[:, 0, 1], matrix[:, 0, 3] = ct, -st, a
        matrix[:, 1, 0], matrix[:, 1, 1], matrix[:, 1, 2], matrix[:, 1, 3] = st * ca, ct * ca, -sa, -sa * d
        matrix[:, 2, 0], matrix[:, 2, 1], matrix[:, 2, 2], matrix[:, 2, 3] = st * sa, ct * sa, ca, ca * d
    else:
        matrix[:, 0, 0], matrix[:, 0, 1], matrix[:, 0, 2], matrix[:, 0, 3] = ct, -st * ca, st * sa, a * ct
        matrix[:, 1, 0], matrix[:, 1, 1], matrix[:, 1, 2], matrix[:, 1, 3] = st, ct * ca, -ct * sa, a * st
        matrix[:, 2, 1], matrix[:, 2, 2], matrix[:, 2, 3] = sa, ca, d
    matrix[:, 3, 3] = 1.0
    return matrix


def plain_fk(robot, cos=numpy.cos, sin=numpy.sin):
    """FK as a user writes it: each link's DH matrix from cos and sin of its angle, multiplied with @.
    Angles are arrays (N,) for a batch (matrices (N, 4, 4)) or numbers for one pose (4, 4)."""
    modified = robot.chain.convention == "modified"
    numbers = [(offset, d, a, math.cos(alpha), math.sin(alpha)) for offset, d, a, alpha in dh_numbers(robot)]
    assert not robot.chain.base and not robot.chain.tool
    one_link = modified_link if modified else standard_link

    def link(theta, d, a, ca, sa):
        if numpy.ndim(theta) == 0:
            return one_link(cos(theta), sin(theta), d, a, ca, sa)
        return links_of_poses(cos(theta), sin(theta), d, a, ca, sa, modified)

    def fk(*q):
        result = link(q[0] + numbers[0][0], *numbers[0][1:])
        for value, (offset, *constants) in zip(q[1:], numbers[1:]):
            result = result @ link(value + offset, *constants)
        return result
    return fk


def per_call(function, *args) -> float:
    """CPU seconds per call of a fast function: the least of 7 repeats of a timed loop."""
    timer = timeit.Timer(lambda: function(*args), timer=time.process_time)
    loops = max(1, timer.autorange()[0])
    return min(timer.repeat(7, loops)) / loops


def generated_module(name: str) -> None:
    """The module `dhsym ik NAME --format python` prints, against the plain FK (see the docstring, 3)."""
    robot = dhsym.load(name)
    chain, solution = robot.chain, inverse_kinematics(robot).solution
    namespace: dict = {}
    exec(compile(module_text(solution, name), name, "exec"), namespace)  # the module's text, as printed
    ik, fk, fk_math = namespace["ik"], plain_fk(robot), plain_fk(robot, math.cos, math.sin)
    rng = numpy.random.default_rng(27)
    q = [rng.uniform(-math.pi, math.pi, BATCH) for _ in chain.joint_variables]
    targets = fk(*q)
    reference = numpy.array(chain.fk().xreplace({**{k: sympy.Float(v) for k, v in robot.sample.items()},
                                                 **{j: sympy.Float(v[0]) for j, v in zip(chain.joint_variables, q)}}),
                            dtype=float)
    assert numpy.allclose(targets[0], reference), "the plain FK is the robot's"
    fk_batch = best_of(lambda: fk(*q), 5, time.process_time)
    ik_batch = best_of(lambda: ik(targets), 5, time.process_time)
    one = [float(v[0]) for v in q]
    fk_one, fk_one_math, ik_one = per_call(fk, *one), per_call(fk_math, *one), per_call(ik, targets[0])
    branches = len(solution.branches)
    print(f"{name}, generated module ({branches} branches), against the plain numpy FK:")
    print(f"  {BATCH} poses: ik {ik_batch * 1e3:.0f} ms, FK {fk_batch * 1e3:.0f} ms: ratio {ik_batch / fk_batch:.2f} "
          f"(aim 2.5)")
    print(f"  one pose: ik {ik_one * 1e6:.1f} us, FK with numpy {fk_one * 1e6:.1f} us: ratio {ik_one / fk_one:.2f} "
          f"(aim 2); FK with math {fk_one_math * 1e6:.1f} us: ratio {ik_one / fk_one_math:.2f}")


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
    for name in ("puma560", "ur5"):
        generated_module(name)
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
