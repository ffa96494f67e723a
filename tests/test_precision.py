"""A file's own precision: decimal angles that stand for a multiple of π/12 (1.571, 1.5708,
0.262) are read as it, once per file with a bound on what that moves; offsets that add up to a
multiple of π/12 print it; and what dhsym writes reads back without a warning."""
import math
import random
import re
from pathlib import Path

import numpy as np
import pytest
from cli_runner import run_dhsym
from readers import load_robot_file

from dhsym.io.urdf import read_urdf_text
from tests.urdf_builder import serial_urdf, urdf_fk

DOOSAN = Path(__file__).parent / "bad_inputs" / "urdf_doosan_rounded_half_pi.urdf"  # π/2 written as 1.571


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_a_doosan_arm_written_with_1_571_gets_pi_over_2_and_its_inverse_kinematics(convention, tmp_path):
    out = tmp_path / "m1013.yaml"
    status, stdout, stderr = run_dhsym("import", DOOSAN, "--convention", convention, "-o", out)
    assert (status, stdout) == (0, "") and len(stderr.splitlines()) == 1
    assert "-1.571 → -π/2, 1.571 → π/2; this turns any frame by at most 0.0013 rad" in stderr
    written = out.read_text()
    assert "1.571" not in written and "1.57" not in written and "alpha: pi/2" in written
    for command in ("table", "fk", "jacobian"):
        assert run_dhsym(command, out)[2] == ""  # the file dhsym wrote gets no warning
    status, stdout, stderr = run_dhsym("ik", out)
    assert (status, stderr) == (0, "") and "8 branches" in stdout


def _bound(stderr: str) -> tuple[float, float]:
    turn, shift = re.search(r"turns any frame by at most (\S+) rad and moves it by at most (\S+) m", stderr).groups()
    return float(turn), float(shift)


def test_the_printed_bound_holds_against_the_urdf_as_written(tmp_path):
    out = tmp_path / "m1013.yaml"
    turn, shift = _bound(run_dhsym("import", DOOSAN, "-o", out)[2])
    robot = load_robot_file(out)
    fk = robot.fk(raw=True)
    text, rng = DOOSAN.read_text(), random.Random(24)
    for _ in range(5):
        q = [rng.uniform(-3, 3) for _ in range(6)]
        table = np.array(fk.xreplace(dict(zip(robot.joint_variables, q))).evalf(), dtype=float)
        urdf = urdf_fk(text, q, "base_0", "link6")
        moved = np.linalg.norm(table[:3, 3] - urdf[:3, 3])
        turned = math.acos(min(1.0, (np.trace(table[:3, :3].T @ urdf[:3, :3]) - 1) / 2))
        assert 1e-6 < moved <= shift and turned <= turn
    exact = text.replace("1.571", repr(math.pi / 2))  # read as π/2, the table is the URDF's kinematics
    assert np.allclose(table, urdf_fk(exact, q, "base_0", "link6"), atol=1e-12)


def test_a_decimal_is_a_multiple_of_pi_over_12_only_to_the_places_written():
    text = serial_urdf([("revolute", "0 0 0.1", "1.5708 0 0", "0 0 1"),
                        ("revolute", "0.3 0 0", "0 0.262 1.57079", "0 0 1"),
                        ("revolute", "0.2 0 0", "1.6 1.5700 0.0487", "0 0 1"),
                        ("fixed", "0.1 0 0", "0 3.1415 0", None)])
    warnings = read_urdf_text(text.encode(), "precision.urdf").warnings
    assert "rounded from: 1.5708 → π/2, 0.262 → π/12, 1.57079 → π/2;" in warnings[0]
    assert any("3.1415 is not exactly π; did you mean pi?" in w for w in warnings)
    assert any("angles off the π/12 grid (1.6, 1.5700, 0.0487, 3.1415)" in w for w in warnings)


NED2_LIKE = [("fixed", "0 0 0", "0 0 0", None), ("revolute", "0 0 0.1013", "0 0 0", "0 0 1"),
             ("revolute", "0 0 0.065", "1.570796326795 0 0", "0 0 1"),  # xacro's ${PI/2}, PI = 3.14159265359
             ("revolute", "0.012 0.221 0", "0 0 1.570796326795", "0 0 1"),
             ("revolute", "0.0325 0 0", "1.570796326795 0 0", "0 0 1"), ("fixed", "0 0 0.05", "0 0 0", None)]


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_offsets_that_add_up_to_pi_over_2_print_it(convention, tmp_path):
    """The elbow sits off the upper arm's line: θ2 and θ3 get offsets atan(221/12) and atan(12/221),
    whose sum is π/2; rounded each to 15 digits they would print q2 + q3 + 1.570796326794895."""
    text = serial_urdf(NED2_LIKE)
    urdf, out = tmp_path / "ned2.urdf", tmp_path / "ned2.yaml"
    urdf.write_text(text)
    assert run_dhsym("import", urdf, "--convention", convention, "-o", out)[0] == 0
    status, stdout, stderr = run_dhsym("fk", out)
    assert (status, stderr) == (0, "") and "1.5707963" not in stdout and "c23 = cos(q2 + q3)" in stdout
    robot = load_robot_file(out)
    q = [0.3, -0.7, 1.1, -2.0]
    numeric = np.array(robot.fk(raw=True).xreplace(dict(zip(robot.joint_variables, q))).evalf(), dtype=float)
    assert np.allclose(numeric, urdf_fk(text.replace("1.570796326795", repr(math.pi / 2)), q, "link0", "link6"),
                       atol=1e-12)


def test_urdf_angles_that_add_up_to_pi_over_2_in_doubles_print_it(tmp_path):
    text = serial_urdf([("revolute", "0 0 0.1", "0 0 0", "0 0 1"), ("revolute", "0.3 0 0", "0 0 0.4", "0 0 1"),
                        ("revolute", "0.25 0 0", "0 0 1.1707963267948966", "0 0 1")])  # 0.4 + … == π/2 in doubles
    urdf, out = tmp_path / "sum.urdf", tmp_path / "sum.yaml"
    urdf.write_text(text)
    assert run_dhsym("import", urdf, "-o", out)[0] == 0
    assert "tool: [{Rz: -0.4 + pi/2}]" in out.read_text()
    stdout = run_dhsym("fk", out)[1]
    assert "1.5707963" not in stdout and "cos(q1 + q2 + q3)" in stdout
