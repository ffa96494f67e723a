"""Robot files: every field of the documented form, expressions, and located errors."""
import pytest
import sympy

from dhsym import UserError, parse_expression, real_symbol
from dhsym.io.library import builtin_names, load
from dhsym.io.robotfile import load_robot_text

PUMA_TEXT = """\
name: PUMA 560
source: Craig, Introduction to Robotics, Table 3.1
convention: modified
joints:
  - {joint: R, alpha: 0,     a: 0,   d: 0,   theta: theta_1}
  - {joint: R, alpha: -pi/2, a: 0,   d: 0,   theta: theta_2}
  - {joint: R, alpha: 0,     a: a_2, d: d_3, theta: theta_3}
  - {joint: R, alpha: -pi/2, a: a_3, d: d_4, theta: theta_4}
  - {joint: R, alpha: pi/2,  a: 0,   d: 0,   theta: theta_5}
  - {joint: R, alpha: -pi/2, a: 0,   d: 0,   theta: theta_6}
base: []
tool: [{Tx: l_3}, {Rz: pi/2}]
"""


def test_the_issue_example_loads_with_every_field():
    robot = load_robot_text(PUMA_TEXT, "puma.yaml")
    assert robot.chain.name == "PUMA 560" and robot.chain.source.startswith("Craig")
    assert robot.chain.convention == "modified" and robot.chain.n == 6
    assert robot.chain.frames[-1] == "tool"
    assert robot.chain.rows[1].alpha == -sympy.pi / 2
    assert [str(s) for s in robot.chain.tool] == ["Tx(l_3)", "Rz(pi/2)"]


@pytest.mark.parametrize("text, expected", [
    ("90deg", sympy.pi / 2), ("90°", sympy.pi / 2), ("-pi/2", -sympy.pi / 2), ("1/3", sympy.Rational(1, 3)),
    ("0.1", sympy.Rational(1, 10)), ("l_1^2", real_symbol("l_1") ** 2), ("l_1**2", real_symbol("l_1") ** 2),
    ("sqrt(2)/2", sympy.sqrt(2) / 2), ("cos(pi/3)", sympy.Rational(1, 2)),
    ("θ1 + α", real_symbol("θ1") + real_symbol("α")),
    ("theta_2 - pi/2", real_symbol("theta_2") - sympy.pi / 2), ("2*(a+b)", 2 * (real_symbol("a") + real_symbol("b"))),
])
def test_expressions(text, expected):
    assert parse_expression(text) == expected


def test_symbols_are_real():
    assert all(s.is_real for s in parse_expression("l_1*theta_1").free_symbols)


def _error(text):
    with pytest.raises(UserError) as info:
        load_robot_text(text, "bad.yaml")
    return str(info.value)


def test_error_names_file_line_column_and_suggests():
    text = PUMA_TEXT.replace("alpha: pi/2, ", "alpah: pi/2, ")
    assert _error(text) == "bad.yaml:9:16: unknown key 'alpah' in joint row 5; did you mean 'alpha'?"


def test_two_symbols_in_theta_need_var():
    text = "convention: standard\njoints:\n  - {joint: R, alpha: 0, a: 0, d: 0, theta: theta_1 + beta}\n"
    assert "several symbols" in _error(text) and _error(text).startswith("bad.yaml:3:")
    fixed = text.replace("theta_1 + beta}", "theta_1 + beta, var: theta_1}")
    assert load_robot_text(fixed).chain.joint_variables == [real_symbol("theta_1")]


def test_degree_looking_twist_warns():
    text = "convention: standard\njoints:\n  - {joint: R, alpha: 90, a: 0, d: 0, theta: q}\n"
    robot = load_robot_text(text, "w.yaml")
    assert robot.warnings == [
        "w.yaml:3:23: joint row 1 alpha: 90 is taken as radians; write 90deg if you meant degrees"]


def test_every_builtin_robot_loads_and_cites_a_source():
    for name in builtin_names():
        chain = load(name)
        assert chain.source, name
        assert set(chain.sample) >= chain.fk().free_symbols - set(chain.joint_variables), name
