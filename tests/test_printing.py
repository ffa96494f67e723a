"""Text and LaTeX printers: notation, legends, tables."""
import pytest
import sympy

from dhsym import load
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
    lines = text_matrix(robot.fk(), TextPrinter(robot.joint_variables), width=100).splitlines()
    # the matrix of names over the fixed bottom row, then the elements column by column (Craig's order)
    assert lines[:5] == ["⎡ r11   r12   r13   px ⎤", "⎢ r21   r22   r23   py ⎥", "⎢ r31   r32   r33   pz ⎥",
                         "⎣ 0     0     0     1  ⎦", ""]
    labels = [line[:3] for line in lines if line[:1] in "rp" and " = " in line]
    assert labels == ["r11", "r21", "r31", "r12", "r22", "r32", "r13", "r23", "r33", "px ", "py ", "pz "]
    assert "px  = c1(a2 c2 + a3 c23 − d4 s23) − d3 s1" in lines


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


# --- SymPy's printer conventions --------------------------------------------------------------

def test_settings_by_keyword_or_as_a_dict_like_sympy():
    expr = sympy.cos(t[0] - t[1])
    assert TextPrinter(joint_variables=t[:2], ascii=True).doprint(expr) == "c(1-2)"
    assert TextPrinter({"joint_variables": t[:2], "ascii": True}).doprint(expr) == "c(1-2)"
    assert TextPrinter(t[:2], ascii=True).doprint(expr) == "c(1-2)"
    assert "joint_variables" in TextPrinter._default_settings and "numbers" in LatexPrinter._default_settings
    with pytest.raises(TypeError, match="Unknown setting 'colour'"):
        TextPrinter(t[:2], colour=True)


def test_greek_letters_come_from_sympys_own_tables():
    from dhsym.printing.names import display_name
    assert [display_name(n, "latex") for n in ("theta_1", "lamda", "Chi_2", "phi_i")] == [
        "\\theta_{1}", "\\lambda", "\\mathrm{X}_{2}", "\\phi_{i}"]
    assert [display_name(n, "unicode") for n in ("theta_1", "psi_12", "θ₁".replace("₁", "_1"))] == ["θ1", "ψ12", "θ1"]


# --- numbers as written ------------------------------------------------------------------------

def _numbers(*literals):
    from dhsym.io.expr import Reading, parse_expression
    reading = Reading()
    for text in literals:
        parse_expression(text, reading=reading)
    return reading.numbers


def test_decimals_stay_decimals_after_arithmetic_and_stay_factors():
    numbers = _numbers("0.425", "0.39225", "0.333", "0.5")
    printer = TextPrinter(t[:2], numbers=numbers)
    assert printer.doprint(sympy.Rational(17, 40) + sympy.Rational(1569, 4000)) == "0.81725"
    assert printer.doprint(sympy.Rational(333, 1000) * sympy.Rational(1, 2)) == "0.1665"
    assert printer.doprint(-sympy.Rational(17, 40) * sympy.cos(t[1])) == "−0.425 c2"
    assert LatexPrinter(t[:2], numbers=numbers).doprint(sympy.Rational(17, 40) * sympy.sin(t[1])) == "0.425 s_{2}"
    assert TextPrinter(t[:2]).doprint(sympy.Rational(17, 40) * sympy.cos(t[1])) == "(17 c2)/40"  # no decimals written


def test_fractions_and_multiples_of_pi_keep_their_form_next_to_decimals():
    numbers = _numbers("0.5", "l/3", "pi/4")
    printer = TextPrinter(t[:1], numbers=numbers)
    l = sympy.Symbol("l", real=True)  # noqa: E741
    assert printer.doprint(l / 3) == "l/3" and printer.doprint(sympy.pi / 4) == "π/4"
    assert printer.doprint(sympy.sqrt(2) / 2 * sympy.cos(t[0])) == "(√2 c1)/2"  # the value of a constant angle
    assert printer.doprint(sympy.Rational(1, 2)) == "0.5" and printer.doprint(sympy.Rational(1, 3)) == "1/3"


# --- angles as written, brackets -----------------------------------------------------------------

def test_an_offset_stays_in_the_angle_as_written():
    printer = TextPrinter(t[:3], offsets={t[1]: -sympy.pi / 4})
    evaluated = sympy.cos(t[0] + t[1] - sympy.pi / 4)
    assert evaluated == sympy.sin(t[0] + t[1] + sympy.pi / 4)  # what SymPy makes of it
    assert printer.doprint(evaluated) == "c12"
    assert printer.doprint(sympy.cos(t[0] + t[1] + t[2] + sympy.pi / 4)) == "−s123"
    assert text_legend(printer) == "where c12 = cos(θ1 + θ2 − π/4), s123 = sin(θ1 + θ2 + θ3 − π/4)"
    latex = LatexPrinter(t[:3], offsets={t[1]: -sympy.pi / 4})
    assert latex.doprint(evaluated) == "c_{12}"
    assert [latex.notation.meaning(a, "latex") for a in latex.used] == [
        "\\cos(\\theta_{1} + \\theta_{2} - \\frac{\\pi}{4})"]


def test_a_multiple_of_half_pi_folds_into_the_notation():
    from dhsym import Chain, DHRow, Robot
    from dhsym.printing.printers import printer_settings
    arm = Chain([DHRow.revolute(t[0]), DHRow.revolute(t[1] - sympy.pi / 2), DHRow.revolute(t[2] + sympy.pi / 6)],
                "standard")
    assert printer_settings(arm)["offsets"] == {t[2]: sympy.pi / 6}
    printer = TextPrinter(printer_settings(arm))
    assert printer.doprint(arm.fk()[0, 0]) == "s123"  # cos(θ1 + θ2 − π/2 + θ3 + π/6)
    assert text_legend(printer) == "where s123 = sin(θ1 + θ2 + θ3 + π/6)"
    table = text_table(Robot(arm))
    assert "θ2* − π/2" in table and "θ3* + π/6" in table


def test_a_function_of_anything_but_a_symbol_is_bracketed():
    alpha = sympy.Symbol("alpha", real=True)
    printer = TextPrinter(t[:1])
    assert printer.doprint(sympy.cos(alpha)) == "cos α"
    assert printer.doprint(sympy.cos(alpha / 2)) == "cos(α/2)"
    assert printer.doprint(sympy.cos(sympy.Rational(3, 10))) == "cos(3/10)"
    assert TextPrinter(t[:1], numbers=_numbers("0.3")).doprint(sympy.sin(sympy.Rational(3, 10))) == "sin(0.3)"
    assert LatexPrinter(t[:1]).doprint(sympy.cos(alpha / 2)) == "\\cos(\\frac{\\alpha}{2})"
    assert LatexPrinter(t[:1]).doprint(sympy.cos(alpha)) == "\\cos{\\alpha}"


# --- text that fits its width ------------------------------------------------------------------

def test_long_elements_break_at_top_level_signs_and_the_legend_wraps():
    from dhsym.printing.render import break_element
    robot = load("iiwa7")
    printer = TextPrinter(robot.joint_variables)
    for width in (40, 60, 80):
        text = text_matrix(robot.fk(), printer, width=width) + "\n" + text_legend(printer, width)
        assert max(len(line) for line in text.splitlines()) <= width, width
    assert break_element("x = ", "a1 + b1(c1 + d1) − e1", 20).splitlines() == ["x = a1 + b1(c1 + d1)", "      − e1"]
    assert break_element("x = ", "a1 + b1(c1 + d1 + e1)", 18).splitlines() == ["x = a1 + b1(c1", "        + d1 + e1)"]
    wide = TextPrinter(t, ascii=True)
    wide.doprint(sympy.cos(t[0] + t[1] - t[3] + t[9]))
    assert all(len(line) <= 40 for line in text_legend(wide, 40).splitlines())


def test_json_form_reads_back_to_the_same_expression_with_no_extra_sign():
    """'-(a + b)*c1' would read back as c1*(-a - b), one operation more than the text form's
    −c1(a + b); the exact form puts the minus on a factor that is not a sum."""
    from dhsym.io.library import builtin_names
    from dhsym.printing.printers import ExactPrinter
    a, b, c = sympy.symbols("a b c", real=True)
    assert ExactPrinter().doprint(-sympy.cos(c) * (a + b)) == "-cos(c)*(a + b)"
    assert ExactPrinter().doprint(-2 * sympy.cos(c) * (a + b) / c) == "-2*cos(c)*(a + b)/c"
    for name in builtin_names():
        robot = load(name)
        exact = ExactPrinter(robot.joint_variables)
        for element in robot.fk():
            names = {symbol.name: symbol for symbol in element.free_symbols}
            assert sympy.sympify(exact.doprint(element), locals=names) == element, (name, element)


def test_an_ik_printer_prints_the_same_whatever_it_printed_before():
    # The IK printer keeps what it printed (the branches share most assignments); a solver's sentence
    # reads its decimals back under other number rules, and must not get the other rule's text.
    from dhsym.core.numbers import WrittenNumbers
    from dhsym.printing.ik import text_printer

    px = sympy.Symbol("px", real=True)
    value = sympy.Rational(17, 40) * px

    def printed(read_back_first: bool) -> tuple:
        printer = text_printer(load("planar2r"))
        printer.numbers = WrittenNumbers(places=3, values=frozenset({sympy.Rational(17, 40)}), folded=True)
        with printer.numbers_read_back():
            read = printer.doprint(value) if read_back_first else None
        plain = printer.doprint(value)
        with printer.numbers_read_back():
            read = printer.doprint(value) if not read_back_first else read
        return plain, read

    assert printed(True) == printed(False) == ("(17 px)/40", "0.425 px")
