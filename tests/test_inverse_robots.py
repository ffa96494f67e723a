"""Closed-form inverse kinematics of the built-in robots: at random joint values q, every real
branch reproduces FK(q) (the target elements the solution uses, for an arm of fewer than six
joints) and one branch equals q; refusals are one clear sentence; out-of-workspace targets and
singular poses give NaN branches or a member of the family, never a traceback."""
import functools
import importlib.util
import math
import random

import numpy
import pytest
import sympy
from ik_checks import derived as solve
from ik_checks import said
from packages import EXAMPLE_ROBOT_DATA, RTB_XACRO
from robots import PITCH_ARM

import dhsym
from dhsym import Robot
from dhsym.api.robot import notebook_robot
from dhsym.inverse.evaluate import evaluate
from dhsym.inverse.sentences import Decoupled, LinedUp
from dhsym.inverse.solution import TARGET_NAMES

pytestmark = pytest.mark.slow  # real robots solved in closed form: seconds to minutes per test

ROBOTS = ["planar2r", "planar3r", "pratihar_2r", "scara", "scara_spong", "cylindrical_rpp", "cylindrical_wrist",
          "spherical_wrist", "spherical_wrist_spong", "stanford", "puma560", "spatial3r", "inline6",
          "asokan_dh_example", "ur5"]


@functools.cache
def solved(name: str, free=()):
    chain = dhsym.load(name)
    return chain, solve(chain, free=free)


def numeric_fk(chain, values: dict) -> numpy.ndarray:
    """FK by numbers, from the plain product of the chain's elementary steps."""
    matrix = chain.fk(raw=True).xreplace({k: sympy.Float(v) for k, v in values.items()})
    return numpy.array(matrix.evalf(), dtype=float)


def random_joints(chain, rng) -> dict:
    return {v: rng.uniform(-math.pi, math.pi) if row.joint == "R" else rng.uniform(0.3, 1.2)
            for v, row in zip(chain.joint_variables, chain.rows)}


def used_elements(solution) -> list[tuple[int, int]]:
    names = {str(s) for _, value in solution.definitions + sum((b.assignments for b in solution.branches), ())
             for s in value.free_symbols}
    return [divmod(k, 4) for k, name in enumerate(TARGET_NAMES) if name in names]


def check_round_trip(chain, solution, rng, trials=4, constants=None):
    chain = notebook_robot(chain)  # a robot record (an imported or converted arm) read in its printed frames
    constants = {**{k: float(v) for k, v in chain.sample.items() if k in chain.chain.symbols}, **(constants or {})}
    # a positioning arm (three joints or fewer) reaches the elements it uses; from four joints on, the pose
    elements = used_elements(solution) if len(solution.joint_variables) < 4 else [(r, c) for r in range(3)
                                                                                   for c in range(4)]
    for _ in range(trials):
        q = {**random_joints(chain, rng), **{k: v for k, v in constants.items() if k in chain.joint_variables}}
        target = numeric_fk(chain, {**constants, **q})
        branches = evaluate(solution, target, constants)
        assert branches.shape == (len(solution.branches), len(solution.joint_variables))
        truth = numpy.array([q[v] for v in solution.joint_variables])
        found = False
        for branch in branches:
            if numpy.isnan(branch).any():
                continue
            reached = numeric_fk(chain, {**constants, **q, **dict(zip(solution.joint_variables, branch))})
            assert max(abs(reached[r, c] - target[r, c]) for r, c in elements) < 1e-7
            found = found or numpy.abs(numpy.angle(numpy.exp(1j * (branch - truth)))).max() < 1e-6
        assert found, "no branch gives back the joint values"


@pytest.mark.parametrize("name", ROBOTS)
def test_every_real_branch_reaches_the_pose_and_one_is_q(name):
    chain, solution = solved(name)
    check_round_trip(chain, solution, random.Random(name))
    assert all(branch.name for branch in solution.branches)
    assert len({branch.name for branch in solution.branches}) == len(solution.branches)


def test_the_puma_is_solved_by_decoupling_with_eight_named_branches():
    _, solution = solved("puma560")
    assert isinstance(solution.method, Decoupled) and said(solution.method).startswith("kinematic decoupling")
    assert len(solution.branches) == 8
    assert {"shoulder right, elbow down, wrist not flipped", "shoulder left, elbow up, wrist flipped"} <= \
        {b.name for b in solution.branches}
    assert any("theta_5" in said(case) for case in solution.degenerate)


def test_the_stanford_arm_names_its_wrist_centre():
    _, solution = solved("stanford")
    assert [str(name) for name, _ in solution.definitions[:3]] == ["x_c", "y_c", "z_c"]
    assert str(solution.definitions[0][1]) == "-d_6*r13 + px"


def test_the_planar_elbow_uses_px_and_py_and_says_so():
    _, solution = solved("planar2r")
    assert used_elements(solution) == [(0, 3), (1, 3)]
    assert "px, py" in said(solution.method) and any("consistent" in said(c) for c in solution.conditions)
    assert [b.name for b in solution.branches] == ["elbow down", "elbow up"]


def test_a_pendulum_has_one_named_solution():
    theta = sympy.Symbol("theta_1", real=True)
    solution = solve(Robot(dhsym.Chain([dhsym.DHRow.revolute(theta, a=1)], "standard"), name="pendulum"))
    assert [(b.name, b.assignments) for b in solution.branches] == [
        ("the only solution", ((theta, sympy.atan2(sympy.Symbol("py", real=True), sympy.Symbol("px", real=True))),))]


def test_a_target_out_of_reach_has_no_branch():
    chain, solution = solved("planar2r")
    far = numpy.eye(4)
    far[0, 3] = 5.0  # a_1 + a_2 = 0.9
    assert numpy.isnan(evaluate(solution, far)).all()


def test_the_wrist_singularity_gives_a_member_of_the_family():
    chain, solution = solved("puma560")
    rng = random.Random(5)
    constants = {k: float(v) for k, v in chain.sample.items()}
    q = {**random_joints(chain, rng), chain.joint_variables[4]: 0.0}
    target = numeric_fk(chain, {**constants, **q})
    branches = evaluate(solution, target)
    real = [b for b in branches if not numpy.isnan(b).any()]
    assert real
    for branch in real:
        reached = numeric_fk(chain, {**constants, **dict(zip(solution.joint_variables, branch))})
        assert numpy.abs(reached - target).max() < 1e-6


def test_many_poses_at_once():
    chain, solution = solved("puma560")
    rng = random.Random(3)
    constants = {k: float(v) for k, v in chain.sample.items()}
    poses = numpy.stack([numeric_fk(chain, {**constants, **random_joints(chain, rng)}) for _ in range(3)])
    together = evaluate(solution, poses)
    assert together.shape == (3, 8, 6)
    assert numpy.allclose(numpy.nan_to_num(together[1]), numpy.nan_to_num(evaluate(solution, poses[1])))


def test_a_redundant_arm_is_refused_and_solved_with_a_free_joint():
    chain = dhsym.load("iiwa7")
    with pytest.raises(dhsym.UserError, match="a pose fixes only 6: make 1 of them a parameter with --free"):
        solve(chain)
    _, solution = solved("iiwa7", ("theta_3",))
    assert solution.free == (chain.joint_variables[2],) and len(solution.joint_variables) == 6
    check_round_trip(chain, solution, random.Random(7), trials=2, constants={chain.joint_variables[2]: 0.4})


def test_a_bad_free_name_is_one_sentence():
    with pytest.raises(dhsym.UserError, match="--free theta_9: .* has no joint variable theta_9; its joint variables"):
        solve(dhsym.load("iiwa7"), free=("theta_9",))


def test_a_general_6r_is_refused_by_its_axes():
    t = sympy.symbols("theta_1:7", real=True)
    alpha = sympy.symbols("alpha_1:7", real=True)
    rows = [dhsym.DHRow.revolute(t[k], d=sympy.Symbol(f"d_{k + 1}", real=True), a=sympy.Symbol(f"a_{k + 1}", real=True),
                                 alpha=alpha[k]) for k in range(6)]
    with pytest.raises(dhsym.UserError, match="no three consecutive axes meet in a point .* or are parallel"):
        solve(Robot(dhsym.Chain(rows, "standard"), name="general 6R"))


def test_the_puma_solution_is_no_larger_than_craigs():
    """Craig, Introduction to Robotics, §4.7 (the PUMA 560's inverse kinematics), by count_ops."""
    _, solution = solved("puma560")
    mine = {**dict(solution.definitions), **dict(solution.branches[0].assignments)}
    S = lambda name: sympy.Symbol(name, real=True)  # noqa: E731
    px, py, pz, a2, a3, d3, d4, K = (S(n) for n in "px py pz a_2 a_3 d_3 d_4 K".split())
    r11, r13, r21, r23, r31, r33 = (S(n) for n in "r11 r13 r21 r23 r31 r33".split())
    t1, t2, t3, t4, t5 = (S(f"theta_{i}") for i in range(1, 6))
    c1, s1, c3, s3, c4, s4, c5, s5 = (f(t) for t in (t1, t3, t4, t5) for f in (sympy.cos, sympy.sin))
    c23, s23 = sympy.cos(t2 + t3), sympy.sin(t2 + t3)
    root = sympy.sqrt
    craig = {
        "theta_1": sympy.atan2(py, px) - sympy.atan2(d3, root(px ** 2 + py ** 2 - d3 ** 2)),
        "K": (px ** 2 + py ** 2 + pz ** 2 - a2 ** 2 - a3 ** 2 - d3 ** 2 - d4 ** 2) / (2 * a2),
        "theta_3": sympy.atan2(a3, d4) - sympy.atan2(K, root(a3 ** 2 + d4 ** 2 - K ** 2)),
        "theta_23": sympy.atan2((-a3 - a2 * c3) * pz - (c1 * px + s1 * py) * (d4 - a2 * s3),
                             (a2 * s3 - d4) * pz + (a3 + a2 * c3) * (c1 * px + s1 * py)),  # θ23
        "theta_4": sympy.atan2(-r13 * s1 + r23 * c1, -r13 * c1 * c23 - r23 * s1 * c23 + r33 * s23),
        "theta_5": sympy.atan2(-(r13 * (c1 * c23 * c4 + s1 * s4) + r23 * (s1 * c23 * c4 - c1 * s4) - r33 * s23 * c4),
                               -r13 * c1 * s23 - r23 * s1 * s23 - r33 * c23),
        "theta_6": sympy.atan2(-r11 * (c1 * c23 * s4 - s1 * c4) - r21 * (s1 * c23 * s4 + c1 * c4) + r31 * s23 * s4,
                               r11 * ((c1 * c23 * c4 + s1 * s4) * c5 - c1 * s23 * s5)
                               + r21 * ((s1 * c23 * c4 - c1 * s4) * c5 - s1 * s23 * s5)
                               - r31 * (s23 * c4 * c5 + c23 * s5)),
    }
    for name in ("theta_1", "K", "theta_3", "theta_23"):
        assert sympy.count_ops(mine[S(name)]) <= sympy.count_ops(craig[name]), name
    ours = sum(sympy.count_ops(value) for value in mine.values())
    assert ours <= sum(sympy.count_ops(form) for form in craig.values())


@pytest.mark.parametrize("name", ["puma560", "stanford", "ur5", "cylindrical_wrist"])
def test_where_two_axes_line_up_the_angle_said_to_be_determined_is(name):
    """The degenerate sentence's "at θk = 0 only A is determined, at θk = π only B": at such a
    pose, turning the joints so that A (or B) stays the same leaves the tool's orientation as it
    is, and turning them so that A changes does not."""
    from dhsym.core.numeric import NumericChain

    chain = dhsym.load(name)
    lined = next(case.reason for case in solve(chain).degenerate if isinstance(case.reason, LinedUp))
    angle, at_zero, at_pi = str(lined.angle), lined.total(), lined.total(at_pi=True)
    rng = random.Random(5)
    numeric = NumericChain(chain.chain, {s: float(v) for s, v in chain.sample.items()}
                           | {s: 0.7 for s in chain.symbols - set(chain.sample) - set(chain.joint_variables)})
    names = [str(v) for v in chain.joint_variables]
    for value, kept in ((0.0, at_zero), (math.pi, at_pi)):
        q = [rng.uniform(-math.pi, math.pi) for _ in names]
        q[names.index(angle)] = value
        expression = kept
        coefficients = {str(s): float(expression.coeff(s)) for s in expression.free_symbols}
        last = max(coefficients, key=names.index)
        rotation = lambda q: numpy.array(numeric.end(q))[:3, :3]  # noqa: E731
        kept_q, moved_q = list(q), list(q)
        kept_q[names.index(last)] += 0.3 * coefficients[last]  # A grows by 0.3 ...
        first = min(coefficients, key=names.index)
        kept_q[names.index(first)] -= 0.3 * coefficients[first]  # ... and shrinks by 0.3: A is kept
        moved_q[names.index(last)] += 0.3 * coefficients[last]
        assert numpy.allclose(rotation(kept_q), rotation(q), atol=1e-12)
        assert not numpy.allclose(rotation(moved_q), rotation(q), atol=1e-3)


PX100 = RTB_XACRO / "trossen_descriptions/urdf/px100.urdf.xacro"
AL5D = RTB_XACRO / "lynxmotion_al5d_description/urdf/al5d_robot.urdf"
ALEXANDER = EXAMPLE_ROBOT_DATA / "alexander_description/urdf/alexander_v1.lowerBodyOnly.urdf"


@pytest.mark.skipif(not PX100.exists() or importlib.util.find_spec("xacro") is None,
                    reason="rtb-data or xacro is not installed")
@pytest.mark.parametrize("path, tip", [(PX100, "/ee_gripper_link"), (AL5D, None)], ids=["px100", "al5d"])
def test_a_four_joint_arm_from_its_maker_reaches_the_whole_pose_on_every_branch(path, tip):
    # A waist and three pitch joints (Trossen's PincherX 100, Lynxmotion's AL5D): the waist + π twin
    # reaches the point with the gripper upside down, so only the elbow's two branches remain.
    from dhsym.io.urdfimport import import_urdf

    robot = import_urdf(path, None, tip, "standard").robot
    solution = solve(robot)
    check_round_trip(robot, solution, random.Random(3), trials=20)
    assert len(solution.branches) == 2


@pytest.mark.skipif(not ALEXANDER.exists(), reason="example-robot-data is not installed")
def test_a_leg_whose_roots_cannot_all_reach_is_refused_not_printed_wrong():
    # Alexander's left leg to the shin (hip x, z, y and the knee: four joints, offsets on every
    # link). No equation gives its joints one root each, and the two-root steps found leave
    # branches that miss the pose: before inverse/reach.py they were printed as answers.
    from dhsym.errors import UserError
    from dhsym.io.urdfimport import import_urdf

    robot = import_urdf(ALEXANDER, None, "LEFT_SHIN_IMU_LINK", "standard").robot
    with pytest.raises(UserError, match=r"one root missed the target \(an arm of 4 unknown joints cannot reach every"):
        solve(robot)


def test_a_waist_and_three_pitch_joints_take_the_waist_from_the_tool_not_the_position(tmp_path):
    # The waist's two roots from px, py (atan2(py, px) and its opposite) both put the tool's point
    # in the arm's plane; only one turns the tool as the target does. A four-joint arm cannot
    # reach every pose, so the search must not keep a root the rest of the target contradicts.
    path = tmp_path / "pitch.yaml"
    path.write_text(PITCH_ARM)
    robot = dhsym.load(str(path))
    solution = solve(robot)
    check_round_trip(robot, solution, random.Random(7), trials=20)
    assert len(solution.branches) == 2
    theta_1 = solution.branches[0].values()[robot.joint_variables[0]]
    assert theta_1.free_symbols <= {sympy.Symbol(n, real=True) for n in ("r13", "r23")}


IIWA14 = RTB_XACRO / "kuka_description/kuka_lbr_iiwa/urdf/lbr_iiwa_14_r820.xacro"


@pytest.mark.skipif(not IIWA14.exists() or importlib.util.find_spec("xacro") is None,
                    reason="rtb-data or xacro is not installed")
def test_a_free_joint_inside_the_arm_that_no_rule_solves_is_refused_not_an_internal_error():
    # KUKA's iiwa 14 as its URDF has it (axes 1 and 3 offset by 0.4 mm): with q_3 free, q_1, q_2, q_4
    # fit no sub-problem, and Pieper's form does not hold with a joint between them (it crashed).
    from dhsym.errors import UserError
    from dhsym.io.urdfimport import import_urdf

    robot = import_urdf(IIWA14, None, "tool0", "standard").robot
    with pytest.raises(UserError, match="no closed form by the course's rules"):
        solve(robot, free=["q_3"])


TOUCHING_ARM = """name: five joints, three meeting at the base
convention: standard
joints:
  - {joint: R, theta: q_1, d: 0, a: 0, alpha: pi/2}
  - {joint: R, theta: q_2, d: 0, a: 0, alpha: pi/2}
  - {joint: R, theta: q_3, d: d_3, a: 0, alpha: pi/2}
  - {joint: R, theta: q_4, d: 0, a: a_4, alpha: pi/2}
  - {joint: R, theta: q_5, d: d_5, a: 0, alpha: pi/2}
sample: {d_3: 0.98, a_4: 0.77, d_5: 0.42}
"""


def test_an_equation_with_a_double_root_at_every_pose_gives_one_root(tmp_path):
    # On this arm's poses a cos q5 + b sin q5 = K holds with a² + b² = K² everywhere: its "two roots"
    # were one root printed twice, and the ±√ of rounding noise lost nine digits (a random arm).
    path = tmp_path / "touching.yaml"
    path.write_text(TOUCHING_ARM)
    robot = dhsym.load(str(path))
    solution = solve(robot)
    assert len(solution.branches) == 2
    q_5 = solution.branches[0].values()[robot.joint_variables[4]]
    assert not any(power.exp == sympy.Rational(1, 2) for power in q_5.atoms(sympy.Pow))  # no square root
    check_round_trip(robot, solution, random.Random(2), trials=20)
