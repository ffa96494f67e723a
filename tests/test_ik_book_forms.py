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
    # Spong (2006), the Euler angles: θ = atan2(±√(1 − r33²), r33), φ = atan2(±r23, ±r13), ψ = atan2(±r32, ∓r31)
    not_flipped, flipped = _branches(name)
    assert not_flipped == ["θ5 = atan2(√(1 − r33²), r33)", "θ4 = atan2(r23, r13)", "θ6 = atan2(r32, −r31)"]
    assert flipped == ["θ5 = atan2(−√(1 − r33²), r33)", "θ4 = atan2(−r23, −r13)", "θ6 = atan2(−r32, r31)"]
    text = run_dhsym("ik", name, "--width", "300").stdout
    assert "1 − r33² ≥ 0" in text
    # where s5 = 0 the book's θ6 is atan2(0, 0): the degenerate case says what is taken there
    assert "one member: there θ6 = atan2(r21 c4 − r11 s4, r22 c4 − r12 s4) with the θ4 it finds" in text


def test_a_wrist_alone_is_no_longer_than_spongs():
    from dhsym.inverse import solve

    r = {name: sympy.Symbol(name, real=True) for name in ("r13", "r23", "r31", "r32", "r33")}
    book = [sympy.atan2(sympy.sqrt(1 - r["r33"] ** 2), r["r33"]), sympy.atan2(r["r23"], r["r13"]),
            sympy.atan2(r["r32"], -r["r31"])]
    robot = dhsym.load("spherical_wrist")
    assert _operations(solve(robot.chain, sample=robot.sample)) <= sum(map(sympy.count_ops, book)) == 8


def test_the_pumas_theta6_is_the_third_row_of_its_wrist_rotation_as_siciliano_writes_it():
    # Siciliano et al., the anthropomorphic arm with a spherical wrist: θ6 = atan2(r'32, −r'31), r' = R03ᵀ R,
    # whose third row here is −(c1 s23, s1 s23, c23): three terms a side, the signs of θ5's branch
    not_flipped, flipped = _branches("puma560")[:2]
    assert "θ6  = atan2(r12 c1 s23 + r22 s1 s23 + r32 c23, −r11 c1 s23 − r21 s1 s23 − r31 c23)" in not_flipped
    assert "θ6  = atan2(−r12 c1 s23 − r22 s1 s23 − r32 c23, r11 c1 s23 + r21 s1 s23 + r31 c23)" in flipped


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
    for theta5 in (rng.uniform(0.3, 2.8), -rng.uniform(0.3, 2.8), 0.0, math.pi, 1e-7, 1e-5):
        q = {v: rng.uniform(-math.pi, math.pi) for v in robot.joint_variables}
        q[robot.joint_variables[-2]] = theta5
        target = numpy.array(fk.xreplace({**constants, **q}).evalf(), dtype=float)
        one, batch = evaluate(solution, target), evaluate(solution, target[None])[0]  # math and numpy paths
        assert numpy.allclose(one, batch, equal_nan=True)
        real = [b for b in one if not numpy.isnan(b).any()]
        assert real
        for branch in real:
            reached = fk.xreplace({**constants, **dict(zip(solution.joint_variables, map(sympy.Float, branch)))})
            assert numpy.abs(numpy.array(reached.evalf(), dtype=float) - target).max() < 1e-6


def test_the_ur5s_law_of_cosines_is_written_in_the_coordinates_theta2_uses():
    # Hawkins: cos θ3 = (X² + Y² − a2² − a3²)/(2 a2 a3) with X, Y the wrist's coordinates in the arm's plane
    branch = _branches("ur5")[0]
    assert "X    = px c1 + py s1 + d6 s5 cθ234 − d5 sθ234" in branch
    assert "Y    = pz + d6 s5 sθ234 + d5 cθ234 − d1" in branch
    assert "D    = (X² + Y² − a2² − a3²)/(2 a2 a3)" in branch
    assert "θ2   = atan2(Y, X) − atan2(a3 s3, a2 + a3 c3)" in branch  # Spong's elbow, as Hawkins writes it


def test_the_planar_3r_names_its_wrist_point_and_writes_d_in_it():
    # Craig's and Spong's planar 3R: the wrist point (x, y) = (px − l3 cφ, py − l3 sφ), then the 2R's D
    text = run_dhsym("ik", "planar3r", "--width", "200").stdout
    for line in ("X    = px − l3 cθ123", "Y    = py − l3 sθ123", "D    = (X² + Y² − l1² − l2²)/(2 l1 l2)",
                 "θ1 = atan2(Y, X) − atan2(l2 s2, l1 + l2 c2)"):
        assert line in text, line
    assert "r11" not in text.split("Branch 1")[0].split("θ123 = atan2(r21, r11)")[1]


@pytest.mark.parametrize("name", ["ur5", "planar3r", "spatial3r"])
def test_with_the_coordinates_named_every_branch_still_reaches_the_pose(name):
    robot = dhsym.load(name)
    solution = robot.ik().solution
    constants = {k: float(v) for k, v in robot.sample.items() if k in robot.chain.symbols}
    constants |= {s: 0.3 for s in robot.chain.symbols - set(robot.joint_variables) - set(constants)}
    fk = robot.chain.fk(raw=True)
    rng = random.Random(3)
    for _ in range(3):
        q = {v: rng.uniform(-math.pi, math.pi) for v in robot.joint_variables}
        target = numpy.array(fk.xreplace({**constants, **q}).evalf(), dtype=float)
        branches = evaluate(solution, target, {str(k): v for k, v in constants.items()})
        real = [b for b in branches if not numpy.isnan(b).any()]
        assert real
        for branch in real:
            reached = fk.xreplace({**constants, **dict(zip(solution.joint_variables, map(sympy.Float, branch)))})
            reached = numpy.array(reached.evalf(), dtype=float)
            rows = 2 if name == "planar3r" else 3  # a planar arm: z is 0 in every pose
            assert numpy.abs(reached[:rows, 3] - target[:rows, 3]).max() < 1e-7


def _operations(solution, branch: int = 0) -> int:
    """count_ops of one branch with the definitions it reads: what a slide shows for one branch."""
    return sum(sympy.count_ops(value) for _, value in (*solution.definitions, *solution.branches[branch].assignments))


def test_the_elbow_arm_and_the_planar_2r_are_no_longer_than_spongs():
    # Spong, Hutchinson and Vidyasagar, Robot Modeling and Control, the inverse position of the
    # planar elbow (2R) and of the articulated (elbow) arm, with the book's wrist-centre names.
    from dhsym.inverse import solve

    S = lambda name: sympy.Symbol(name, real=True)  # noqa: E731
    x, y, a1, a2 = S("px"), S("py"), S("a_1"), S("a_2")
    D = (x ** 2 + y ** 2 - a1 ** 2 - a2 ** 2) / (2 * a1 * a2)
    t2 = S("theta_2")
    planar = [D, sympy.atan2(sympy.sqrt(1 - S("D") ** 2), S("D")),
              sympy.atan2(y, x) - sympy.atan2(a2 * sympy.sin(t2), a1 + a2 * sympy.cos(t2))]
    xc, yc, zc, d1, a3, t3 = S("px"), S("py"), S("pz"), S("d_1"), S("a_3"), S("theta_3")
    elbow = [sympy.atan2(yc, xc),
             (xc ** 2 + yc ** 2 + (zc - d1) ** 2 - a2 ** 2 - a3 ** 2) / (2 * a2 * a3),
             sympy.atan2(sympy.sqrt(1 - S("D") ** 2), S("D")),
             sympy.atan2(zc - d1, sympy.sqrt(xc ** 2 + yc ** 2))
             - sympy.atan2(a3 * sympy.sin(t3), a2 + a3 * sympy.cos(t3))]
    for name, book in (("planar2r", planar), ("spatial3r", elbow)):
        robot = dhsym.load(name)
        solution = solve(robot.chain, sample=robot.sample, numbers=robot.numbers)
        assert _operations(solution) <= sum(map(sympy.count_ops, book)), name
