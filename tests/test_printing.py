"""Text and LaTeX printers: notation, legends, tables."""
import sympy

from dhsym.io.library import load
from dhsym.printing.printers import LatexPrinter, TextPrinter
from dhsym.printing.render import latex_matrix, latex_table, text_legend, text_matrix, text_table, transform_title

t = sympy.symbols("theta_1:13", real=True)


def test_legend_lists_only_used_abbreviations():
    printer = TextPrinter(t[:3])
    printer.doprint(sympy.cos(t[0]) * sympy.sin(t[1] + t[2]))
    assert text_legend(printer) == "where c1 = cos θ1, s23 = sin(θ2 + θ3)"


def test_ascii_mode_has_no_unicode():
    robot = load("scara_spong")
    printer = TextPrinter(robot.joint_variables, ascii=True)
    text = text_matrix(robot.fk(), printer) + text_legend(printer)
    assert text.isascii()
    assert "c(12-4) = cos(theta1 + theta2 - theta4)" in text


def test_two_digit_joints_use_commas():
    printer = LatexPrinter(t)
    assert printer.doprint(sympy.cos(t[0] + t[9])) == "c_{1,10}"
    assert printer.doprint(sympy.cos(t[0] + t[1])) == "c_{12}"


def test_angle_difference_notation():
    printer = LatexPrinter(t[:4])
    assert printer.doprint(sympy.sin(t[0] + t[1] - t[3])) == "s_{12\\bar{4}}"
    assert printer.doprint(sympy.sin(t[1] - t[0])) == "-s_{1\\bar{2}}"


def test_latex_symbols_and_matrix():
    robot = load("planar3r")
    printer = LatexPrinter(robot.joint_variables)
    text = latex_matrix(robot.fk(), printer)
    assert text.startswith("\\begin{bmatrix}") and "l_{1} c_{1} + l_{2} c_{12} + l_{3} c_{123}" in text
    assert transform_title(0, 3, "latex") == "{}^{0}T_{3}"
    assert transform_title(0, "tool", "latex") == "{}^{0}T_{\\mathrm{tool}}"


def test_dh_table_marks_joint_variables_in_convention_order():
    table = text_table(load("stanford"))
    assert table.splitlines()[0].split("│")[1].strip() == "θᵢ"
    assert "d3*" in table and "θ1*" in table
    latex = latex_table(load("puma560"))
    assert "\\alpha_{i-1} & a_{i-1} & d_i & \\theta_i" in latex
    assert "\\theta_{1}^{*}" in latex


def test_wide_matrices_become_element_lists():
    robot = load("puma560")
    text = text_matrix(robot.fk(), TextPrinter(robot.joint_variables), width=100)
    assert text.splitlines()[3] == "px  = c1(a2 c2 + a3 c23 − d4 s23) − d3 s1"


def test_squares_of_sin_and_cos():
    alpha = sympy.Symbol("alpha", real=True)
    expr = sympy.sin(alpha) ** 2 + sympy.cos(t[0]) ** 2
    assert LatexPrinter(t[:1]).doprint(expr) == "\\left(\\sin{\\alpha}\\right)^{2} + c_{1}^{2}"
    assert TextPrinter(t[:1]).doprint(expr) == "(sin α)² + c1²"


def test_general_row_prints_with_its_own_subscript():
    theta_i, d_i, a_i, alpha_i = sympy.symbols("theta_i d_i a_i alpha_i", real=True)
    from dhsym import Chain, DHRow
    link = Chain([DHRow.revolute(theta_i, d_i, a_i, alpha_i)], "standard").link(1)
    printer = LatexPrinter([theta_i])
    assert printer.doprint(link[0, 3]) == "a_{i} c_{i}"
    assert TextPrinter([theta_i]).doprint(link[0, 1]) == "−si cos αi"


def test_a_bracket_never_starts_with_a_minus():
    robot = load("puma560")
    printer = TextPrinter(robot.joint_variables)
    assert printer.doprint(robot.fk()[2, 0]) == "−c23 s5 c6 − s23(c4 c5 c6 − s4 s6)"
