"""The closed forms in the books' order and shape: a spherical wrist's middle joint first
(cos θ5 = r33, Spong's and Siciliano's Euler angles), then θ4 from the third column with the
sign the θ5 branch chose (atan2(r23, r13), or atan2(−r23, −r13) where sin θ5 < 0), then θ6; as
`dhsym ik` prints them, and every branch still reaching the pose."""
import math
import random

import numpy
import pytest
import sympy
from cli_runner import run_dhsym

import dhsym
from dhsym.inverse.evaluate import evaluate

pytestmark = pytest.mark.slow  # each solves a robot in closed form


def _branches(name: str) -> list[list[str]]:
    """The lines of each printed branch, stripped, in order."""
    result = run_dhsym("ik", name, "--width", "200")
    assert result.status == 0, result.stderr
    blocks = result.stdout.split("\nBranch ")[1:]
    return [[line.strip() for line in block.split("\n\n")[0].splitlines()[1:]] for block in blocks]


@pytest.mark.parametrize("name", ["spherical_wrist", "spherical_wrist_spong"])
def test_a_wrist_alone_is_solved_theta5_then_theta4_then_theta6_as_the_books_do(name):
    not_flipped, flipped = _branches(name)
    assert not_flipped == ["θ5 = atan2(√(1 − r33²), r33)", "θ4 = atan2(r23, r13)",
                           "θ6 = atan2(r21 c4 − r11 s4, r22 c4 − r12 s4)"]
    assert flipped[:2] == ["θ5 = atan2(−√(1 − r33²), r33)", "θ4 = atan2(−r23, −r13)"]
    assert "1 − r33² ≥ 0" in run_dhsym("ik", name).stdout


def test_the_pumas_theta4_is_craigs_with_the_sign_of_s5_not_s5_itself():
    # Craig (4.80): θ4 = atan2(−r13 s1 + r23 c1, −r13 c1 c23 − r23 s1 c23 + r33 s23), θ4 + 180° on the flip
    branches = _branches("puma560")
    assert "θ4  = atan2(r23 c1 − r13 s1, r33 s23 − r13 c1 c23 − r23 s1 c23)" in branches[0]
    assert "θ4  = atan2(r13 s1 − r23 c1, r13 c1 c23 + r23 s1 c23 − r33 s23)" in branches[1]
    assert not any("s5" in line for branch in branches for line in branch)


@pytest.mark.parametrize("name", ["spherical_wrist", "puma560"])
def test_every_branch_reaches_the_pose_and_the_singular_wrist_gives_a_member(name):
    robot = dhsym.load(name)
    solution = robot.ik().solution
    constants = {k: float(v) for k, v in robot.sample.items() if k in robot.chain.symbols}
    fk = robot.chain.fk(raw=True)
    rng = random.Random(27)
    for theta5 in (rng.uniform(0.3, 2.8), -rng.uniform(0.3, 2.8), 0.0):
        q = {v: rng.uniform(-math.pi, math.pi) for v in robot.joint_variables}
        q[robot.joint_variables[-2]] = theta5
        target = numpy.array(fk.xreplace({**constants, **q}).evalf(), dtype=float)
        real = [b for b in evaluate(solution, target) if not numpy.isnan(b).any()]
        assert real
        for branch in real:
            reached = fk.xreplace({**constants, **dict(zip(solution.joint_variables, map(sympy.Float, branch)))})
            assert numpy.abs(numpy.array(reached.evalf(), dtype=float) - target).max() < 1e-6
