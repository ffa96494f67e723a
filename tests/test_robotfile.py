"""Robot files: every field of the documented form, expressions, and located errors."""
import pytest
import sympy
from readers import load_robot_text

from dhsym import UserError, load, parse_expression, real_symbol
from dhsym.io.library import builtin_names

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
    assert robot.name == "PUMA 560" and robot.source.startswith("Craig")
    assert robot.convention == "modified" and robot.n == 6
    assert robot.frames[-1] == "tool"
    assert robot.rows[1].alpha == -sympy.pi / 2
    assert [str(s) for s in robot.tool] == ["Tx(l_3)", "Rz(pi/2)"]


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
    assert load_robot_text(fixed).joint_variables == [real_symbol("theta_1")]


def test_degree_looking_twist_warns():
    text = "convention: standard\njoints:\n  - {joint: R, alpha: 90, a: 0, d: 0, theta: q}\n"
    robot = load_robot_text(text, "w.yaml")
    assert list(robot.warnings) == [
        "w.yaml:3:23: joint row 1 alpha: 90 is taken as radians; write 90deg if you meant degrees"]


def test_every_builtin_robot_loads_and_cites_a_source():
    for name in builtin_names():
        chain = load(name)
        assert chain.source, name
        assert set(chain.sample) >= chain.fk().free_symbols - set(chain.joint_variables), name


def _one_row(row: str) -> str:
    return f"convention: standard\njoints:\n  - {{{row}}}\n"


@pytest.mark.parametrize("row, column, fix", [
    ("joint: P, alpha: 0, a: 0, d: d_1, theta: theta_1", 47, "write joint: R if this joint turns"),
    ("joint: P, alpha: 0, a: 0, d: l_1, theta: θ1", 47, "write joint: R if this joint turns"),
    ("joint: P, alpha: 0, a: 0, d: d_1, theta: q_1 + pi/2", 47, "write joint: R if this joint turns"),
    ("joint: R, alpha: 0, a: 0, d: q_1, theta: theta_1", 35, "write joint: P if this joint slides"),
    ("joint: P, alpha: 0, a: 0, d: theta_1, theta: 0", 35, "write joint: R and put theta_1 in theta"),
    ("joint: R, alpha: 0, a: 0, d: 0, theta: d_1", 45, "write joint: P and put d_1 in d"),
    ("joint: R, alpha: 0, a: 0, d: d_1, theta: 0", 47, "d holds d_1: write joint: P if this joint slides"),
])
def test_a_joint_variable_in_the_wrong_column_is_an_error_with_the_fix(row, column, fix):
    with pytest.raises(UserError) as error:
        load_robot_text(_one_row(row), "arm.yaml")
    assert str(error.value).startswith(f"arm.yaml:3:{column}: joint row 1 ")
    assert fix in str(error.value)


@pytest.mark.parametrize("row, variable", [
    ("joint: P, alpha: 0, a: 0, d: d_1, theta: theta_0", "d_1"),  # a constant offset, marked by its subscript
    ("joint: P, alpha: 0, a: 0, d: d_1, theta: beta", "d_1"),  # a constant angle with a name of its own
    ("joint: P, alpha: 0, a: 0, d: d_1, theta: theta_1, var: d_1", "d_1"),  # var settles which one moves
    ("joint: R, alpha: 0, a: 0, d: d_1, theta: theta_1", "theta_1"),  # d_1: the usual offset of a revolute joint
    ("joint: P, alpha: -pi/2, a: 0, d: l_1, theta: 0", "l_1"),  # any name may slide
])
def test_constant_symbols_and_named_variables_stay_allowed(row, variable):
    assert load_robot_text(_one_row(row), "arm.yaml").rows[0].variable.name == variable


@pytest.mark.parametrize("text", ["sqrt(-(theta_1*theta_1))", "sqrt(-l_1^2)", "sqrt(-1)"])
def test_a_value_imaginary_for_every_nonzero_symbol_is_refused(text):
    with pytest.raises(UserError, match="not a real number"):
        parse_expression(text)
