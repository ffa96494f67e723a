"""The numeric inverse kinematics (dhsym.inverse.numeric, `dhsym ik --numeric`, the numeric module
of `dhsym ik --format python`): every real solution of any six-joint arm at a pose, each once,
each reaching the pose, the joints that made the pose among them; the same sets as EAIK where
EAIK solves the arm; a redundant arm with a joint given, swept; the solution nearest a seed; and
what the command line says and writes."""
from __future__ import annotations

import json
from pathlib import Path

import numpy
import pytest
import sympy
from cli_runner import run_dhsym

import dhsym
from dhsym.api.ik import numeric_inverse_kinematics
from dhsym.core.chain import Chain, DHRow
from dhsym.core.robot import Robot
from dhsym.core.transforms import Step

DATA = Path(__file__).parent / "data" / "numeric"
COBOT, HUMANOID, GENERAL = (str(DATA / name) for name in ("offset_wrist_cobot.yaml", "humanoid_arm.yaml",
                                                          "general_6r.yaml"))
REACH = 1e-9  # every solution's pose is this near the target (the arms here are a metre or two in size)


def number(rng, low, high):
    return sympy.Rational(round(float(rng.uniform(low, high)), 3)).limit_denominator(1000)


def general_arm(seed: int, kinds: str = "RRRRRR", convention: str = "standard") -> Robot:
    """A six-joint arm with random lengths, twists and offsets (no two axes parallel or meeting),
    slides where `kinds` says P, and a base and a tool."""
    rng = numpy.random.default_rng(seed)
    rows = []
    for k, kind in enumerate(kinds, start=1):
        q = sympy.Symbol(f"q_{k}", real=True)
        d, a, alpha, offset = (number(rng, -0.4, 0.4), number(rng, 0.05, 0.5), number(rng, -3, 3),
                               number(rng, -3, 3))
        rows.append(DHRow.revolute(q + offset, d, a, alpha, variable=q) if kind == "R"
                    else DHRow.prismatic(q + d, offset, a, alpha, variable=q))
    base = [Step("Rz", number(rng, -3, 3)), Step("Tx", number(rng, -0.5, 0.5)), Step("Ry", number(rng, -1, 1))]
    tool = [Step("Tz", number(rng, 0, 0.2)), Step("Rx", number(rng, -3, 3))]
    return Robot(Chain(rows, convention, base, tool), name=f"random {kinds} arm {seed}")


def configurations(inverse, count: int, seed: int):
    """(joint values (count, n), their poses) at random joints: angles in [−π, π), slides ±0.4."""
    rng = numpy.random.default_rng(seed)
    values = numpy.stack([rng.uniform(-numpy.pi, numpy.pi, count) if kind == "R" else rng.uniform(-0.4, 0.4, count)
                          for kind in inverse.arm.kinds], axis=1)
    return values, inverse.pose(values)


def apart(a, b, kinds):
    """The largest difference of two joint vectors, angles on the circle."""
    difference = numpy.array(a, dtype=float) - numpy.array(b, dtype=float)
    for k, kind in enumerate(kinds):
        if kind == "R":
            difference[..., k] = (difference[..., k] + numpy.pi) % (2 * numpy.pi) - numpy.pi
    return numpy.abs(difference).max(axis=-1)


def assert_every_solution(inverse, count: int, seed: int, **given_columns):
    """At `count` random poses: each solution reaches its pose, none repeats, the joints that made
    the pose are among them; returns the number of solutions at each pose."""
    values, poses = configurations(inverse, count, seed)
    given = {name: values[:, inverse.joint_variables.index(name)] for name in inverse.free_variables}
    found = inverse.solve(poses, **given)
    assert found.shape == (count, 16, len(inverse.arm.kinds))
    counts = []
    for q, target, solutions in zip(values, poses, found):
        real = solutions[numpy.isfinite(solutions[:, 0])]
        assert numpy.isnan(solutions[len(real):]).all()  # NaN after the last solution only
        assert numpy.abs(inverse.pose(real) - target).max(initial=0) < REACH
        assert apart(real, q, inverse.arm.kinds).min() < 1e-9
        assert all(apart(real[i], real[j], inverse.arm.kinds) > 1e-6 for i in range(len(real)) for j in range(i))
        counts.append(len(real))
    return counts


@pytest.mark.parametrize("seed, kinds, convention", [(1, "RRRRRR", "standard"), (2, "RRRRRR", "modified"),
                                                     (3, "RRPRRR", "modified"), (4, "PRRRRP", "standard")])
def test_every_solution_of_a_general_arm_reaches_the_pose_and_holds_the_joints(seed, kinds, convention):
    counts = assert_every_solution(numeric_inverse_kinematics(general_arm(seed, kinds, convention)), 20, seed)
    assert max(counts) <= 16 and all(count % 2 == 0 for count in counts)  # real roots of a real polynomial


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(10, 34))
def test_many_general_arms_of_every_kind_in_both_conventions(seed):
    kinds = ["RRRRRR", "RRRRRR", "RPRRRR", "RRRRPR", "PRRRRR", "RPRPRR"][seed % 6]
    arm = general_arm(seed, kinds, ("standard", "modified")[seed % 2])
    assert_every_solution(numeric_inverse_kinematics(arm), 40, seed)


def test_an_offset_wrist_cobot_has_up_to_sixteen_solutions():
    inverse = numeric_inverse_kinematics(dhsym.load(COBOT))
    counts = assert_every_solution(inverse, 60, 5)
    assert sorted(set(counts)) == [4, 8, 12]  # 16 at some poses, too: see the slow test


@pytest.mark.slow
def test_an_offset_wrist_cobot_at_many_poses():
    counts = assert_every_solution(numeric_inverse_kinematics(dhsym.load(COBOT)), 400, 6)
    assert max(counts) == 16


def test_a_redundant_arm_with_a_joint_given():
    inverse = numeric_inverse_kinematics(dhsym.load(HUMANOID), free=["q_3"])
    counts = assert_every_solution(inverse, 30, 7)
    assert max(counts) >= 8


def test_a_sweep_of_the_given_joint_solves_the_pose_at_each_of_its_values():
    inverse = numeric_inverse_kinematics(dhsym.load(HUMANOID), free=["q_3"])
    q = numpy.array([0.3, -0.4, numpy.pi / 6, -0.6, 0.7, -0.8, 0.9])  # q3 on the sweep's 5° grid
    values, solutions = inverse.sweep(inverse.pose(q))
    assert values.shape == (72,) and solutions.shape == (72, 16, 7)
    assert numpy.allclose(numpy.diff(values), numpy.pi / 36)
    real = solutions[numpy.isfinite(solutions[:, :, 0])]
    assert len(real) > 72 and numpy.abs(inverse.pose(real) - inverse.pose(q)).max() < REACH
    given = numpy.broadcast_to(values[:, None], solutions.shape[:2])[numpy.isfinite(solutions[:, :, 0])]
    assert numpy.array_equal(real[:, 2], given)
    at_q = numpy.argmin(numpy.abs(values - q[2]))
    assert apart(solutions[at_q][numpy.isfinite(solutions[at_q, :, 0])], q, "R" * 7).min() < 1e-9


def test_the_nearest_solution_from_a_seed_on_any_arm_and_within_limits():
    inverse = numeric_inverse_kinematics(dhsym.load(HUMANOID))  # seven unknown joints: no list, the nearest one
    q = numpy.array([0.3, -0.4, 0.5, -0.6, 0.7, -0.8, 0.9])
    found = inverse.nearest(inverse.pose(q), q + 0.05)
    assert numpy.abs(inverse.pose(found) - inverse.pose(q)).max() < REACH and apart(found, q, "R" * 7) < 0.2
    limits = numpy.array([[-1.0, 1.0]] * 7)
    within = inverse.nearest(inverse.pose(q), q + 0.05, limits=limits)
    assert (numpy.abs(within) <= 1.0 + 1e-12).all()
    with pytest.raises(dhsym.UserError, match="no solution reaches the pose"):
        inverse.nearest(inverse.pose(q) + numpy.diag([0, 0, 0, 0]) + numpy.pad([[0, 0, 0, 5.0]], ((0, 3), (0, 0))),
                        q)
    with pytest.raises(dhsym.UserError, match="7 unknown joints, but a pose fixes only six"):
        inverse.solve(inverse.pose(q))


def test_a_general_arm_with_symbols_needs_numbers_and_takes_them():
    robot = dhsym.load(GENERAL)
    with pytest.raises(dhsym.UserError, match="needs numbers: general 6R has no value for a_1, a_2"):
        numeric_inverse_kinematics(robot)
    rng = numpy.random.default_rng(8)
    numbers = {s.name: float(rng.uniform(0.1, 0.5)) for s in robot.chain.symbols if s.name[0] in "ad"}
    numbers.update({f"alpha_{k}": float(rng.uniform(-3, 3)) for k in range(1, 7)})
    assert_every_solution(numeric_inverse_kinematics(robot, constants=numbers), 10, 8)


def test_the_module_is_the_solver_and_takes_the_given_joint():
    inverse = numeric_inverse_kinematics(dhsym.load(HUMANOID), free=["q_3"])
    namespace: dict = {}
    exec(compile(inverse.code("dhsym ik humanoid_arm.yaml --free q_3"), "humanoid_ik.py", "exec"), namespace)
    values, poses = configurations(inverse, 5, 9)
    got = namespace["ik"](poses, q_3=values[:, 2])
    assert numpy.array_equal(got, inverse.solve(poses, q_3=values[:, 2]), equal_nan=True)
    assert namespace["ik"](poses[0], q_3=values[0, 2]).shape == (16, 7)
    assert namespace["JOINTS"] == inverse.joint_variables
    nearest = namespace["nearest"](poses[0], values[0] + 0.01)
    assert numpy.abs(inverse.pose(nearest) - poses[0]).max() < REACH


# ---- against EAIK (its analytic solutions), where it solves the arm ----

def eaik_robot(arm):
    """The arm as EAIK's H, P and end rotation (its joints' axes and the offsets between them at zero)."""
    binding = pytest.importorskip("eaik.pybindings.EAIK")
    frame, axes, points = arm.frames[0], [], []
    for k in range(len(arm.kinds)):
        axes.append(frame[:3, 2] * numpy.sign(arm.slopes[k]))
        points.append(frame[:3, 3].copy())
        frame = frame @ arm.frames[k + 1]
    offsets = [points[0]] + [b - a for a, b in zip(points, points[1:])] + [frame[:3, 3] - points[-1]]
    return binding.Robot(numpy.array(axes).T, numpy.array(offsets).T, frame[:3, :3], [], True)


def spherical_wrist_arm(seed: int) -> Robot:
    """A random arm whose last three axes meet in a point and whose axes 2 and 3 are parallel (EAIK
    solves it in closed form; with axes 2 and 3 in general position EAIK searches, and finds fewer)."""
    robot = general_arm(seed)
    rows = list(robot.chain.rows)
    rows[1] = DHRow.revolute(rows[1].theta, rows[1].d, rows[1].a, 0, variable=rows[1].variable)
    rows[3] = DHRow.revolute(rows[3].theta, rows[3].d, 0, -sympy.pi / 2, variable=rows[3].variable)
    rows[4] = DHRow.revolute(rows[4].theta, 0, 0, sympy.pi / 2, variable=rows[4].variable)
    return Robot(Chain(rows, "standard", robot.chain.base, robot.chain.tool), name=f"spherical wrist {seed}")


def three_parallel_arm(seed: int) -> Robot:
    """A random arm whose axes 2, 3 and 4 are parallel (the UR layout, other numbers)."""
    robot = general_arm(seed)
    rows = list(robot.chain.rows)
    for k in (1, 2):
        rows[k] = DHRow.revolute(rows[k].theta, rows[k].d, rows[k].a, 0, variable=rows[k].variable)
    return Robot(Chain(rows, "standard", robot.chain.base, robot.chain.tool), name=f"three parallel {seed}")


def assert_same_sets_as_eaik(robot, count: int, seed: int):
    inverse = numeric_inverse_kinematics(robot)
    eaik = eaik_robot(inverse.arm)
    assert eaik.has_known_decomposition(), eaik.get_kinematic_family()
    values, poses = configurations(inverse, count, seed)
    for target, ours in zip(poses, inverse.solve(poses)):
        theirs = numpy.array(eaik.calculate_IK(target).Q).reshape(-1, 6) * numpy.abs(inverse.arm.slopes)
        # EAIK's own flag (is_LS) marks even exact solutions of some arms as least-squares: its pose decides
        theirs = theirs[numpy.abs(inverse.pose(theirs) - target).max(axis=(1, 2)) < 1e-8]
        ours = ours[numpy.isfinite(ours[:, 0])]
        assert all(apart(ours, q, "R" * 6).min(initial=9) < 1e-6 for q in theirs)
        assert all(apart(theirs, q, "R" * 6).min(initial=9) < 1e-6 for q in ours)


@pytest.mark.parametrize("name", ["puma560", "ur5"])
def test_the_same_solutions_as_eaik_on_the_puma_and_the_ur5(name):
    assert_same_sets_as_eaik(dhsym.load(name), 20, 10)


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(6))
def test_the_same_solutions_as_eaik_on_random_arms_it_solves(seed):
    assert_same_sets_as_eaik(spherical_wrist_arm(seed), 40, seed)
    assert_same_sets_as_eaik(three_parallel_arm(seed), 40, seed)


# ---- the command line ----

def test_the_refusal_of_a_closed_form_names_the_numeric_command():
    result = run_dhsym("ik", COBOT)
    assert (result.status, result.stdout) == (2, "")
    assert result.stderr.splitlines() == [
        "dhsym: error: no closed form by the course's rules: no three consecutive axes meet in a point at the start "
        "or the end of the arm, or are parallel (Pieper's condition); "
        f"`dhsym ik {COBOT} --numeric` gives every solution in numbers"]


def test_numeric_text_shows_the_method_the_arm_the_target_and_every_solution():
    out = run_dhsym("ik", COBOT, "--numeric").ok()
    lines = out.splitlines()
    assert lines[0] == "offset-wrist cobot: inverse kinematics in numbers  (standard DH)"
    assert "Raghavan and Roth's elimination" in out and "3 │ q3* + π/2 │ 0" in out and "tool: Rz(π)" in out
    assert "at q1 = 0.3, q2 = −0.4, q3 = 0.5, q4 = −0.6, q5 = 0.7, q6 = −0.8:" in " ".join(out.split())
    assert "8 solutions (every real one, each once; angles in radians):" in lines
    marked = [line for line in lines if line.endswith("← the joints that made the target")]
    assert len(marked) == 1 and marked[0].split()[1:7] == ["0.300000", "−0.400000", "0.500000", "−0.600000",
                                                           "0.700000", "−0.800000"]


def test_numeric_json_holds_the_target_and_solutions_that_reach_it():
    result = json.loads(run_dhsym("ik", COBOT, "--numeric", "--format", "json", "--q", "q_1=30deg",
                                  "--pose", "px=0.4, pz=0.5").ok())
    assert result["numeric"] is True and result["joints"]["q_1"] == pytest.approx(numpy.pi / 6)
    assert result["replaced"] == {"px": 0.4, "pz": 0.5} and result["joints_among_solutions"] is None
    target, solutions = numpy.array(result["target"]), numpy.array(result["solutions"])
    assert target[0, 3] == 0.4 and target[2, 3] == 0.5 and len(solutions) > 0
    inverse = numeric_inverse_kinematics(dhsym.load(COBOT))
    assert numpy.abs(inverse.pose(solutions) - target).max() < REACH


def test_the_python_module_of_an_arm_with_no_closed_form_is_numeric():
    result = run_dhsym("ik", COBOT, "--format", "python")
    assert result.status == 0
    assert result.stderr.splitlines() == [
        "dhsym: warning: no closed form by the course's rules: no three consecutive axes meet in a point at the start "
        "or the end of the arm, or are parallel (Pieper's condition): the module finds every solution numerically"]
    namespace: dict = {}
    exec(compile(result.stdout, "cobot_ik.py", "exec"), namespace)
    inverse = numeric_inverse_kinematics(dhsym.load(COBOT))
    values, poses = configurations(inverse, 4, 11)
    found = namespace["ik"](poses)
    assert found.shape == (4, 16, 6) and f"Made by `dhsym ik {COBOT} --format python`" in result.stdout
    assert all(apart(f[numpy.isfinite(f[:, 0])], q, "R" * 6).min() < 1e-9 for f, q in zip(found, values))


def test_a_redundant_arm_on_the_command_line_takes_the_given_joint_from_q():
    out = run_dhsym("ik", HUMANOID, "--free", "q_3", "--numeric", "--q", "q_3=0.2").ok()
    assert "with q3 given, numerically" in out and "q3 = 0.2" in out
    marked = [line for line in out.splitlines() if line.endswith("← the joints that made the target")]
    assert marked and marked[0].split()[3] == "0.200000"


@pytest.mark.parametrize("args, message", [
    ([COBOT, "--q", "q_1=0.2"], "--q gives numbers to the numeric solution; add --numeric"),
    ([COBOT, "--numeric", "--format", "latex"], "the numeric solution has no LaTeX form; use --format text, json or "
                                                "python"),
    ([COBOT, "--numeric", "--pose", "px"], "--pose 'px': expected ELEMENT=NUMBER, the element one of r11 … r33, px, "
                                           "py, pz"),
    ([COBOT, "--numeric", "--pose", "r11=2"], "--pose: the target's r11 … r33 are not a rotation"),
    ([HUMANOID, "--numeric"], "humanoid arm has 7 unknown joints, but a pose fixes only six: its solutions are not "
                              "isolated; give 1 of them with --free (e.g. --free q_4)"),
    ([GENERAL], f"`dhsym ik {GENERAL} --numeric` gives every solution in numbers once its constants have numbers: "
                "add --set a_1=… a_2=… a_3=… …"),
    ([GENERAL, "--format", "python"], "(Pieper's condition); a numeric module needs numbers: general 6R has no "
                                      "value for a_1, a_2"),
])
def test_numeric_mistakes_are_one_line(args, message):
    result = run_dhsym("ik", *args)
    assert (result.status, result.stdout) == (2, "") and len(result.stderr.splitlines()) == 1
    assert message in result.stderr


def test_a_general_arm_with_symbols_is_solved_once_set_gives_numbers():
    rng = numpy.random.default_rng(12)
    numbers = [f"{kind}_{k}={rng.uniform(0.1, 0.5) if kind != 'alpha' else rng.uniform(-3, 3):.3f}"
               for kind in ("a", "d", "alpha") for k in range(1, 7)]
    out = run_dhsym("ik", GENERAL, "--numeric", "--set", *numbers).ok()
    assert "← the joints that made the target" in out and "with a1 = " in out


def test_an_arm_that_moves_in_five_directions_is_told_no_list_exists():
    arm = str(Path(__file__).parent / "data" / "imported" / "long_decimals.yaml")
    result = run_dhsym("ik", arm)  # the closed form's refusal names the parameter that solves it
    assert (result.status, result.stdout) == (2, "") and result.stderr.endswith("--free q_3\n")
    result = run_dhsym("ik", arm, "--numeric")
    assert (result.status, result.stdout) == (2, "") and len(result.stderr.splitlines()) == 1
    assert result.stderr.endswith("Imported arm with long decimals: its six joints move the tool in only 5 independent "
                                  "directions at any pose, so a reachable pose has infinitely many solutions and no "
                                  "list of them exists\n")


def test_ascii_text_is_ascii():
    out = run_dhsym("ik", COBOT, "--numeric", "--ascii").ok()
    assert out.isascii() and out.count("<- the joints that made the target") == 1
