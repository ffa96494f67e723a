"""The inverse kinematics of arms imported from their makers' files prints numbers a lecturer
would put on a slide: the import's 15-digit lengths and offsets (√(0.1² + 0.035²), atan(20/7))
are named (a2, β) and said once, derived constants stay short (D = (X² + Y² − a2² − 0.01)/…),
and every branch still reaches the pose. Slow: each arm is imported and derived (seconds)."""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest
import sympy
from cli_runner import run_dhsym
from packages import RTB_XACRO

import dhsym
from dhsym.io.urdfimport import import_urdf

pytestmark = pytest.mark.slow

PX100 = RTB_XACRO / "trossen_descriptions/urdf/px100.urdf.xacro"
ROS = Path(__file__).parent / "data" / "ros"
OPEN_MANIPULATOR = ROS / "open_manipulator/open_manipulator_description/urdf/om_x/open_manipulator_x.urdf.xacro"
NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?")
needs_xacro = pytest.mark.skipif(importlib.util.find_spec("xacro") is None, reason="xacro is not installed")


def significant_digits(number: str) -> int:
    return len(number.replace(".", "").lstrip("0"))


def long_numbers(text: str) -> list[str]:
    """The numbers of more than 6 significant digits in a printed text."""
    return [n for n in NUMBER.findall(text) if significant_digits(n) > 6]


def reaches_on_every_branch(robot, ik, seed: int, poses: int = 12) -> None:
    """At random joint values q: every branch of `ik` at T = FK(q), put back through the table's
    forward kinematics (lambdified from `dhsym.fk`, apart from the solver), gives T again, and q
    is one of the branches."""
    variables = list(robot.chain.joint_variables)
    numbers = {s: v for s, v in robot.sample.items() if s in robot.chain.symbols}
    fk = sympy.lambdify(variables, dhsym.fk(robot).subs(numbers), "numpy")
    rng = np.random.default_rng(seed)
    for q in rng.uniform(-1.2, 1.2, (poses, len(variables))):
        target = np.array(fk(*q), dtype=float)
        branches = np.asarray(ik.evaluate(target), dtype=float).reshape(-1, len(variables))
        found = branches[np.isfinite(branches).all(axis=1)]
        assert len(found), q
        for values in found:
            assert np.allclose(np.array(fk(*values), dtype=float), target, atol=1e-9), (q, values)
        gaps = (found - q + np.pi) % (2 * np.pi) - np.pi
        assert np.abs(gaps).max(axis=1).min() < 1e-9, q


@needs_xacro
@pytest.mark.skipif(not PX100.exists(), reason="rtb-data is not installed")
def test_the_pincherx_prints_its_lengths_and_offsets_by_name_and_reaches_on_both_branches():
    robot = import_urdf(PX100, None, "/ee_gripper_link", "standard").robot
    ik = dhsym.ik(robot)
    text = ik.text()
    assert long_numbers(text) == []  # was 0.021224999999999903829089347225, 123412150740817/100000000000000
    lines = [line.strip() for line in text.splitlines()]
    assert "D  = (5(Y² + X² − a2² − 0.01))/a2" in lines  # (X² + Y² − a2² − a3²)/(2 a2 a3), a3 = 0.1
    assert "q3 = β − φ2" in lines
    assert "Named numbers: a2 ≈ 0.105948 (the a of row 2); β ≈ 1.23412 (the θ offset −β of rows 2 and 3); the" in lines
    latex = ik.latex().latex  # as the notebook shows it
    assert long_numbers(latex) == []
    assert "D &= \\frac{5(Y^{2} + X^{2} - a_{2}^{2} - 0.01)}{a_{2}}" in latex
    assert ("\\text{Named numbers: }a_{2} \\approx 0.105948\\text{ (the }a\\text{ of row 2); }"
            "\\beta \\approx 1.23412") in latex
    reaches_on_every_branch(robot, ik, seed=5)


@needs_xacro
def test_the_open_manipulator_x_reads_the_same_from_python_and_from_its_written_file(tmp_path):
    # Its upper arm is L-shaped too (0.128 up, 0.024 ahead): the offset is −β on joint 2 and +β on
    # joint 3, and the lengths 0.124 and 0.126 stay as the file writes them.
    robot = import_urdf(OPEN_MANIPULATOR, "link1", "end_effector_link", "standard").robot
    ik = dhsym.ik(robot)
    text = ik.text()
    assert long_numbers(text) == []
    lines = [line.strip() for line in text.splitlines()]
    assert "D  = (Y² + X² − a2² − 0.015376)/(a2 · 0.248)" in lines  # 0.124² and 2 · 0.124
    assert "q3 = φ2 − β" in lines
    assert any(line.startswith("Named numbers: a2 ≈ 0.130231 (the a of row 2); β ≈ 1.38545 (the θ offset −β of row 2")
               for line in lines)
    reaches_on_every_branch(robot, ik, seed=8)

    written = tmp_path / "om_x.yaml"
    result = run_dhsym("import", str(OPEN_MANIPULATOR), "--base", "link1", "--tip", "end_effector_link",
                       "-o", str(written))
    assert result.status == 0, result.stderr
    assert "theta: q_2 - 1.3854483767992" in written.read_text()  # the file keeps its 15 digits
    printed = run_dhsym("ik", str(written))
    assert printed.status == 0, printed.stderr
    assert printed.stdout.rstrip() == text.rstrip()
    data = run_dhsym("ik", str(written), "--format", "json").stdout
    assert "0.130230564768798" in data and "a_2" not in data  # JSON keeps the table's values, exactly
