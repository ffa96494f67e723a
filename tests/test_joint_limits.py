"""Joint limits, as a user meets them: `limits:` in a robot file (read, written back), the line
`dhsym ik` prints, the solutions `dhsym ik --numeric` marks outside them, `robot.ik().evaluate(T,
within_limits=True)`, `ik.nearest` and the generated module's `ik(T, within_limits=True)`.
Within-limits is checked here independently: a revolute angle is within when some whole turn
(k = −2 … 2) puts it between the limits."""
import json
import math
from pathlib import Path

import numpy as np
import pytest
import sympy
from cli_runner import run_dhsym
from readers import load_robot_text as notebook_robot_text

import dhsym
from dhsym.io.robotfile import load_robot_text
from dhsym.io.robotwriter import robot_yaml

FIXTURE = Path(__file__).parent / "data" / "puma560_limits.yaml"
DEGREES = [(-160, 160), (-225, 45), (-45, 225), (-110, 110), (-100, 100), (-266, 266)]


def _within(value: float, lower: float, upper: float, revolute: bool = True) -> bool:
    turns = range(-2, 3) if revolute else [0]
    return any(lower - 1e-9 <= value + 2 * math.pi * k <= upper + 1e-9 for k in turns)


def _pose(robot, q) -> np.ndarray:
    values = {**robot.sample, **dict(zip(robot.chain.joint_variables, q))}
    return np.array(robot.fk().subs(values).evalf(), dtype=float)


@pytest.fixture(scope="module")
def puma():
    return dhsym.load(str(FIXTURE))


@pytest.fixture(scope="module")
def puma_ik(puma):
    return puma.ik()


def test_the_file_s_limits_are_exact_radians_of_the_joint_variable(puma):
    assert puma.joint_limits == tuple((sympy.pi * lo / 180, sympy.pi * hi / 180) for lo, hi in DEGREES)


def test_a_written_robot_file_reads_back_with_its_limits(puma):
    text = robot_yaml(puma)
    assert "limits: [-225deg, 45deg]" in text
    assert load_robot_text(text, "again.yaml").joint_limits == puma.joint_limits
    arm = load_robot_text("convention: standard\njoints:\n  - {joint: P, theta: 0, d: d_1, a: 0, alpha: 0, "
                          "limits: [0.05, 0.35]}\n  - {joint: R, theta: theta_2, d: 0, a: 1, alpha: 0}\n", "arm.yaml")
    assert arm.joint_limits == ((sympy.Rational(1, 20), sympy.Rational(7, 20)), None)
    assert "limits: [0.05, 0.35]}" in robot_yaml(arm)
    assert load_robot_text(robot_yaml(arm), "again.yaml").joint_limits == arm.joint_limits


def test_dhsym_convert_keeps_the_limits(tmp_path):
    out = tmp_path / "standard.yaml"
    status, _, stderr = run_dhsym("convert", str(FIXTURE), "--to", "standard", "-o", str(out))
    assert status == 0, stderr
    assert dhsym.load(str(out)).joint_limits == dhsym.load(str(FIXTURE)).joint_limits


PLANAR = ("convention: standard\njoints:\n"
          "  - {joint: R, theta: theta_1, d: 0, a: 0.5, alpha: 0, limits: [-pi/2, 90deg]}\n"
          "  - {joint: R, theta: theta_2, d: 0, a: 0.4, alpha: 0, limits: [0, 2.5]}\n")


def test_dhsym_ik_states_the_limits_in_text_and_json(tmp_path):
    (tmp_path / "arm.yaml").write_text(PLANAR)
    status, text, _ = run_dhsym("ik", str(tmp_path / "arm.yaml"))
    assert status == 0
    assert "\n\nJoint limits (the robot file’s): θ1 ∈ [−90°, 90°], θ2 ∈ [0, 2.5].\n\n" in text
    ik = notebook_robot_text(PLANAR, "arm.yaml").ik()
    assert "Joint limits (the robot file's): theta1 in [-90deg, 90deg], theta2 in [0, 2.5]." in ik.text(ascii=True)
    assert ik.json()["joint_limits"] == {"theta_1": ["-pi/2", "pi/2"], "theta_2": ["0", "5/2"]}
    assert "joint_limits" not in dhsym.load("planar2r").ik().json()  # a robot without limits: as before


@pytest.mark.slow  # the PUMA's solution: seconds
def test_dhsym_ik_states_the_puma_s_limits_in_degrees():
    status, text, _ = run_dhsym("ik", str(FIXTURE))
    said = " ".join(text.split("Joint limits (the robot file’s): ")[1].split("\n\n")[0].split())
    assert said == "θ1 ∈ [−160°, 160°], θ2 ∈ [−225°, 45°], θ3 ∈ [−45°, 225°], θ4 ∈ [−110°, 110°], " \
                   "θ5 ∈ [−100°, 100°], θ6 ∈ [−266°, 266°]."


@pytest.mark.slow  # the PUMA's solutions: seconds
def test_dhsym_ik_numeric_marks_each_solution_outside_the_limits():
    status, text, _ = run_dhsym("ik", str(FIXTURE), "--numeric", "--format", "json")
    found = json.loads(text)
    limits = [(math.radians(lo), math.radians(hi)) for lo, hi in DEGREES]
    expected = [[name for name, value, pair in zip(found["joint_variables"], solution, limits)
                 if not _within(value, *pair)] for solution in found["solutions"]]
    assert found["outside_limits"] == expected
    assert any(expected) and not all(expected)
    status, text, _ = run_dhsym("ik", str(FIXTURE), "--numeric")
    rows = text.split("solutions (every real one")[1].splitlines()[2:2 + len(expected)]
    assert [("outside limits: " + ", ".join(n.replace("theta_", "θ") for n in names)) in row if names
            else "outside" not in row for row, names in zip(rows, expected)] == [True] * len(rows)
    assert f"{sum(not names for names in expected)} of {len(rows)} within the joint limits." in text


@pytest.mark.slow
@pytest.mark.parametrize("q", [[0.3, -0.4, 0.5, -0.6, 0.7, -0.8], [-2.5, -3.5, 3.0, 1.5, -1.2, 4.0]])
def test_evaluate_within_limits_keeps_exactly_the_branches_within_them(puma, puma_ik, q):
    T = _pose(puma, q)
    every, kept = puma_ik.evaluate(T), puma_ik.evaluate(T, within_limits=True)
    limits = [(math.radians(lo), math.radians(hi)) for lo, hi in DEGREES]
    for branch, chosen in zip(every, kept):
        inside = not np.isnan(branch).any() and all(_within(v, *pair) for v, pair in zip(branch, limits))
        assert np.isnan(chosen).all() != inside
        if inside:  # the same joint positions, moved by whole turns into the limits, reaching T
            assert all(lo - 1e-9 <= v <= hi + 1e-9 for v, (lo, hi) in zip(chosen, limits))
            assert np.allclose(np.remainder(chosen - branch + 1, 2 * np.pi) - 1, 0, atol=1e-12)
            assert np.allclose(_pose(puma, chosen), T, atol=1e-9)
    nearest = puma_ik.nearest(kept, np.array(q) + 2 * np.pi)  # angles compared modulo 2π
    assert np.allclose(np.remainder(nearest - q + 1, 2 * np.pi) - 1, 0, atol=1e-9)


@pytest.mark.slow
def test_the_generated_module_drops_the_same_branches(puma, puma_ik):
    namespace = {}
    exec(compile(puma_ik.code("dhsym ik puma560_limits.yaml --format python"), "<ik>", "exec"), namespace)
    poses = np.stack([_pose(puma, q) for q in ([0.3, -0.4, 0.5, -0.6, 0.7, -0.8], [1.0, -2.0, 0.2, 0.4, 0.5, 3.0])])
    assert np.array_equal(namespace["ik"](poses, within_limits=True), puma_ik.evaluate(poses, within_limits=True),
                          equal_nan=True)
    assert np.array_equal(namespace["ik"](poses), puma_ik.evaluate(poses), equal_nan=True)
    q = np.array([1.0, -2.0, 0.2, 0.4, 0.5, 3.0])
    assert np.allclose(namespace["nearest"](namespace["ik"](poses), q)[1], q)


def test_a_robot_without_limits_keeps_every_branch_and_its_module():
    arm = dhsym.load("planar2r")
    ik = arm.ik()
    T = np.eye(4)
    T[:2, 3] = [0.5, 0.4]
    assert np.array_equal(ik.evaluate(T, within_limits=True), ik.evaluate(T))
    assert "within_limits" not in ik.code()


def test_an_angle_outside_the_limits_by_a_turn_is_moved_into_them():
    arm = dhsym.load("planar2r").replace(joint_limits=[(0, 2 * sympy.pi), None])
    T = np.eye(4)
    T[:2, 3] = [0.3, -0.5]  # θ1 of both branches is negative as atan2 gives it
    every, kept = arm.ik().evaluate(T), arm.ik().evaluate(T, within_limits=True)
    assert (every[:, 0] < 0).all() and np.allclose(kept[:, 0], every[:, 0] + 2 * np.pi)
    assert np.allclose(kept[:, 1], every[:, 1])
