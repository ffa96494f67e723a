"""The printed IK solution of every built-in reads like the textbook's: no redundant signs or
brackets, named angles abbreviated as c_φ, sums grouped by the target's elements as Craig prints
them, sentences whose relations are whole, lines that fit the width, LaTeX that compiles."""
import json
import re

import pytest
import sympy
from cli_runner import run_dhsym
from test_ik_cli import HOST, _pdflatex

from dhsym import load
from dhsym.io.library import builtin_names
from dhsym.latex.ik import snippet
from dhsym.printing.ik import text_printer
from dhsym.printing.render import display_width

pytestmark = pytest.mark.slow  # real robots solved in closed form: seconds to minutes per test

ROBOTS = builtin_names()
FREE = {"iiwa7": ["theta_3"]}  # seven joints: one is a parameter
_SOLVED: dict = {}


def _solved(name):
    if name not in _SOLVED:
        _SOLVED[name] = load(name).ik(free=FREE.get(name, ()))
    return _SOLVED[name]


def _body(text: str) -> str:
    """The text without its legend (`where c1 = cos θ1, …` at the end)."""
    return text.rsplit("\nwhere c", 1)[0]


@pytest.mark.parametrize("name", ROBOTS)
def test_no_bracket_is_negated_when_its_terms_are(name):
    result = _solved(name)
    text, latex = result.text(), snippet(result.solution, result.robot)
    assert not re.search(r"−[(\[{]−", text), text
    assert not re.search(r"-(\(|\[|\\\{)-", latex), latex


@pytest.mark.parametrize("name", ROBOTS)
@pytest.mark.parametrize("width", [100, 60, 40])
def test_every_line_fits_the_width(name, width):
    text = _solved(name).text(width)
    assert max(map(display_width, text.splitlines())) <= width, text


@pytest.mark.parametrize("name", ROBOTS)
def test_no_relation_is_cut_between_lines(name):
    lines = _solved(name).text(60).splitlines()
    assert not [line for line in lines if re.search(r" [=≥≤≠]$", line) or re.match(r"\s*[=≥≤≠] ", line)]
    assert not [line for line in lines if line.endswith(("(modified", "(standard"))]  # the title's convention


def test_planar3r_theta1_is_the_textbook_form():
    text = _solved("planar3r").text()
    # the wrist point (x, y) = (px − l3 cφ, py − l3 sφ) named, as Craig and Spong name it, and θ1 written in it
    assert "  X    = px − l3 cθ123\n  Y    = py − l3 sθ123\n" in text
    assert "  θ1 = atan2(Y, X) − atan2(l2 s2, l1 + l2 c2)" in text
    assert "  θ3 = θ123 − θ1 − θ2" in text  # θ123 = θ1 + θ2 + θ3, named as a book names θ23


def test_a_named_angle_prints_as_c_and_s_of_its_name_and_the_legend_says_so():
    result = _solved("planar3r")
    text = result.text()
    assert "cθ123 = cos θ123, sθ123 = sin θ123" in text and "cos θ123" not in _body(text)
    latex = snippet(result.solution, result.robot)
    assert "c_{\\theta 123} &= \\cos{\\theta_{123}}" in latex and "\\cos{\\theta_{123}})" not in latex
    assert "cos(theta_123)" in json.dumps(result.json())  # the JSON keeps the full form
    assert "c(theta123) = cos theta123" in result.text(ascii=True)  # ASCII labels a named angle as a joint's


def test_puma_reads_as_craig_prints_theta23_and_theta6():
    words = " ".join(_solved("puma560").text().split())
    # Craig (4.69): θ23 = atan2[(−a3 − a2 c3) pz − (c1 px + s1 py)(d4 − a2 s3), …]
    assert "θ23 = atan2(−(d4 − a2 s3)(px c1 + py s1) − pz(a3 + a2 c3), (a3 + a2 c3)(px c1 + py s1)" in words
    assert "θ2 = θ23 − θ3" in words and "φ" not in words
    # Craig (4.83): s6 = −r11(c1 c23 s4 − s1 c4) − r21(s1 c23 s4 + c1 c4) + r31 s23 s4
    assert "θ6 = atan2(r11(s1 c4 − c1 c23 s4) + r31 s23 s4 − r21(c1 c4 + s1 c23 s4)," in words


def test_an_equation_to_zero_starts_with_a_plus_and_values_are_math():
    assert "  px − b = 0 and pz = 0: φ1 is not determined" in _solved("rps_leg").text()
    text = _solved("scara_spong").text()
    assert "r33 = −1" in text and "= -1" not in text
    assert "$r_{33} = -1$" in snippet(_solved("scara_spong").solution, _solved("scara_spong").robot)


def test_the_sign_of_a_bracket_is_decided_by_how_its_terms_print():
    arm = load("planar3r").chain
    printer = text_printer(arm)
    l1, l2, l3 = (sympy.Symbol(f"l_{k}", real=True) for k in (1, 2, 3))
    px, py, a, b = sympy.symbols("px py a b", real=True)
    t1, t2, _ = arm.joint_variables
    s2, c2 = sympy.sin(t2), sympy.cos(t2)
    # −[−l2 s2(py − l3) − (l1 + l2 c2)(px − l3)], as SymPy keeps it: a minus before a sum of brackets
    inner = sympy.Add(l2 * s2 * (l3 - py), (l1 + l2 * c2) * (l3 - px))
    assert printer.doprint(sympy.Mul(-1, inner, evaluate=False)) == "l2 s2(py − l3) + (l1 + l2 c2)(px − l3)"
    assert printer.doprint(sympy.Mul(-1, a - b, evaluate=False)) == "b − a"
    assert printer.doprint(sympy.Mul(-1, a + b, evaluate=False)) == "−(a + b)"
    positive = sympy.Add(a * (l1 + l2 * c2), b * (l3 + l2 * s2))
    assert printer.doprint(sympy.Mul(-1, positive, evaluate=False)) == "−a(l1 + l2 c2) − b(l3 + l2 s2)"
    assert printer.doprint(sympy.atan2(sympy.Mul(-1, inner, evaluate=False), px)).startswith("atan2(l2 s2(py")


def test_json_is_untouched_by_the_text_forms():
    data = _solved("planar3r").json()
    x = dict(data["definitions"])["X"]
    assert "cos(theta_123)" in x and "[" not in x
    sympy.sympify(x)


@pytest.mark.parametrize("name", ROBOTS)
def test_every_builtin_latex_with_ik_compiles_and_fits(name, tmp_path):
    for kind in ("article", "slides"):  # slides: the ± frames and their tables of signs too
        argv = ["latex", name, "--ik", "--document", kind] + (["--free", *FREE[name]] if name in FREE else [])
        status, out, err = run_dhsym(*argv)
        assert status == 0, err
        assert _pdflatex(tmp_path, f"{name}_{kind}", out) == (0, [])
    status, out, err = run_dhsym("ik", name, "--format", "latex", *(["--free", *FREE[name]] if name in FREE else []))
    assert status == 0, err
    assert _pdflatex(tmp_path, f"{name}_snippet", HOST.format(out)) == (0, [])


def test_the_wrist_centre_comes_first_in_a_sum_as_the_target_does():
    words = " ".join(_solved("inline6").text().split())
    assert "D = (xc² + yc² + zc² − 2 d1 zc + d1² − a2² − d4²)/(2 a2 d4)" in words  # Spong's form, expanded
    assert "θ23 = atan2(xc c1 + yc s1, −zc + d1) − atan2(a2 c3, d4 + a2 s3)" in words and "d1 − zc" not in words
