"""Closed-form inverse kinematics of the PUMA 560: dhsym's derivation against its peers, in the
same run, as ratios of CPU time (the issue asks for 10x faster than the Robotics Toolbox's
closed-form solver and 100x faster than IKBT).

- dhsym: `robot.ik()` on the built-in puma560 (`dhsym.api.ik.inverse_kinematics`: the
  derivation, decimals as written and the branch names checked against the arm, all that
  `dhsym ik` works out), cold (a fresh robot, empty SymPy cache), the least CPU time of RUNS runs
  (on a shared machine one run may wait for others).
- Robotics Toolbox for Python 1.5.0: `Puma560().analytic_ik()` (symbolic derivation, Pieper's
  method, with python-flint). It is installed with its `[ik]` extra into its own venv
  (build/peers/rtb, never the project's) and run in a subprocess of that venv; where it cannot be
  installed (no network) the benchmark says so and goes on.
- IKBT (UW BioRobotics): not on PyPI (`pip download ikbt` finds no distribution); it runs from a
  git checkout of its repository (`python ikSolver.py`), which a benchmark should not fetch; it
  is not run, and the benchmark says so.
- SymPy doing the same steps, the fallback the issue allows and always run (once: about a
  minute): the whole derivation as Craig §4.7 does it, each step in plain SymPy (product,
  trigsimp, solve); see `sympy_same_steps`. Its first part alone (⁰T₆ and θ1), the baseline
  before 2026-12-02, is printed too.

Run: python benchmarks/ik_peers.py [--no-install]
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import sympy
from peer_venv import peer_python
from sympy.core.cache import clear_cache

import dhsym
from dhsym.api.ik import inverse_kinematics
from dhsym.inverse.solution import target_matrix

ROOT = Path(__file__).resolve().parent.parent
RUNS = 3  # each side's least CPU time of this many cold runs (the peer's in fresh processes)
PEER_VENV = ROOT / "build" / "peers" / "rtb"
PEER_PACKAGE = "roboticstoolbox-python[ik]==1.5.0"
PEER_SCRIPT = """
import time, warnings
warnings.simplefilter("ignore")
import roboticstoolbox as rtb
robot = rtb.models.DH.Puma560()
cpu = time.process_time()
solver = robot.analytic_ik()
print(time.process_time() - cpu)
"""


def cpu_of(function) -> float:
    clear_cache()
    start = time.process_time()
    function()
    return time.process_time() - start


def dhsym_puma() -> float:
    times = []
    for _ in range(RUNS):
        chain = dhsym.load("puma560")  # a fresh chain: nothing of an earlier run is kept
        times.append(cpu_of(lambda chain=chain: inverse_kinematics(chain)))
    return min(times)


def sympy_same_steps() -> tuple[float, float]:
    """What a SymPy user writes for the PUMA, following Craig's §4.7 step by step: the plain
    product ⁰T₆ and trigsimp; then for k = 1, 3, 4, 5 Paul's equation (⁰Tₖ)⁻¹ T = ᵏT₆ (the
    inverse as the product of the links' inverses, trigsimp of both sides), and from it θ1
    (`solve` of element (2, 4)), θ3 (`solve` of the sum of squares of column 4), θ2 + θ3, θ5
    and θ6 (`solve` for the sine and cosine, linear in them) and θ4 (read off as an atan2).
    Returns the CPU time of all of it and of the first part alone (⁰T₆ and θ1, the baseline
    earlier versions of this benchmark used)."""
    chain = dhsym.load("puma560")
    links = chain.links(raw=True)
    target = target_matrix()
    theta_1, _, theta_3, _, theta_5, theta_6 = chain.joint_variables
    sin_23, cos_23 = sympy.symbols("s23 c23")

    def simplified(matrix):
        return matrix.applyfunc(sympy.trigsimp)

    def product(matrices):
        result = sympy.eye(4)
        for matrix in matrices:
            result = result * matrix
        return result

    def paul(k):
        seen = product([link.inv() for link in reversed(links[:k])]) * target
        return simplified(seen), simplified(product(links[k:]))

    def sine_and_cosine(equations, angle):
        sine, cosine = sympy.symbols("s c")
        linear = [sympy.expand_trig(e).subs({sympy.sin(angle): sine, sympy.cos(angle): cosine}) for e in equations]
        return [sympy.atan2(found[sine], found[cosine]) for found in sympy.solve(linear, [sine, cosine], dict=True)]

    answers = {}
    clear_cache()
    start = time.process_time()
    simplified(product(links))  # ⁰T₆, as a student simplifies it
    seen, rest = paul(1)
    answers["theta_1"] = sympy.solve(sympy.Eq(seen[1, 3], rest[1, 3]), theta_1)
    first_part = time.process_time() - start
    squares = [sympy.expand(sum(m[i, 3] ** 2 for i in range(3))) for m in (seen, rest)]
    answers["theta_3"] = sympy.solve(sympy.Eq(squares[0], sympy.trigsimp(squares[1])), theta_3)
    seen, rest = paul(3)
    pair = [sympy.trigsimp(sympy.expand_trig(seen[i, 3] - rest[i, 3])) for i in (0, 1)]
    angle_23 = chain.joint_variables[1] + theta_3
    pair = [e.subs({sympy.sin(angle_23): sin_23, sympy.cos(angle_23): cos_23}) for e in pair]
    answers["theta_23"] = sympy.solve(pair, [sin_23, cos_23], dict=True)
    answers["theta_4"] = sympy.atan2(seen[2, 2], -seen[0, 2])  # ³T₆ column 3 is (−c4 s5, c5, s4 s5)
    seen, rest = paul(4)
    answers["theta_5"] = sine_and_cosine([seen[0, 2] - rest[0, 2], seen[2, 2] - rest[2, 2]], theta_5)
    seen, rest = paul(5)
    answers["theta_6"] = sine_and_cosine([seen[0, 0] - rest[0, 0], seen[2, 0] - rest[2, 0]], theta_6)
    assert all(answers.values()), answers  # every step found its joint
    return time.process_time() - start, first_part


def rtb_puma(python: Path, runs: int = RUNS) -> tuple[float | None, str]:
    """The least CPU time of `runs` derivations, each in a fresh process of the peer's venv."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    times = []
    for _ in range(runs):
        try:
            done = subprocess.run([str(python), "-c", PEER_SCRIPT], capture_output=True, text=True, timeout=3600,
                                  env=env)
        except subprocess.SubprocessError as error:
            return None, f"did not finish: {error}"
        if done.returncode != 0:
            return None, f"failed: {(done.stderr.strip().splitlines() or ['?'])[-1]}"
        times.append(float(done.stdout.split()[-1]))
    return min(times), ""


def main() -> None:
    install = "--no-install" not in sys.argv[1:]
    ours = dhsym_puma()
    print(f"dhsym, PUMA 560 derivation: {ours:.2f} s of CPU (least of {RUNS} cold runs)")
    python, reason = peer_python(PEER_VENV, PEER_PACKAGE, install)
    if python is not None:
        theirs, reason = rtb_puma(python)
    if python is not None and theirs is not None:
        print(f"Robotics Toolbox 1.5.0 analytic_ik(), PUMA 560: {theirs:.2f} s of CPU (least of {RUNS} runs): "
              f"dhsym is {theirs / ours:.0f}x faster (the issue asks for 10x)")
    else:
        print(f"Robotics Toolbox 1.5.0: {reason}; compared with SymPy doing the same steps below")
    print("IKBT: not installable (not on PyPI: `pip download ikbt` finds no distribution; it runs from a git "
          "checkout of its repository): not run; compared with SymPy doing the same steps below")
    baseline, first_part = sympy_same_steps()
    print(f"SymPy doing the same steps (Craig's 4.7: plain product 0T6, Paul's equations for k = 1, 3, 4, 5 "
          f"with trigsimp, solve for each joint): {baseline:.2f} s of CPU (one run): dhsym is {baseline / ours:.0f}x "
          f"faster (the issue asks 100x of IKBT)")
    print(f"  of which 0T6 and theta_1 alone (this benchmark's baseline before 2026-12-02): {first_part:.2f} s: "
          f"{first_part / ours:.0f}x")


if __name__ == "__main__":
    main()
