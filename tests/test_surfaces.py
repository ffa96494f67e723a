"""What a reader sees on every surface: one layout rule (notebook displays, `fk/links --format
latex`), abbreviations that keep families of angles apart, frames numbered from a robot file's
`first_frame`, one legend for text, LaTeX and JSON, and robot-file prose with its identifiers
set as math. Compiling with pdflatex is tests/test_latex.py's job."""
import json
import re

import sympy
from cli_runner import run_dhsym
from readers import load_robot_text
from robots import NUMBERED_WRIST as WRIST

from dhsym import load
from dhsym.api import show as display
from dhsym.core.chain import Chain, DHRow
from dhsym.latex import document as latexdoc
from dhsym.latex import layout
from dhsym.latex.prose import tex_prose
from dhsym.latex.results import ARTICLE_TEXT_WIDTH_PT
from dhsym.latex.width import math_width
from dhsym.printing.printers import LatexPrinter, TextPrinter
from dhsym.printing.render import text_legend


def _aligned_lines(latex: str) -> list[str]:
    """The math of each line of the named elements: after `r_{11} &= ` or `&\\quad {}`."""
    pattern = r"^(?:[rp]_\{\w+\} &= |&\\quad \{\})(.*?)(?:\\displaybreak\[0\])?(?: \\\\(?:\[[\d.]+pt\])?)?$"
    return re.findall(pattern, latex, re.MULTILINE)


# ---------------------------------------------------------------- one layout rule

def test_notebook_display_stacks_matrix_elements_and_legend_in_one_array():
    small = display.transform(load("planar2r"), 0, 2).latex
    assert small.startswith("\\begin{array}{l}\n{}^{0}T_{2} =\n\\begin{bmatrix}")
    assert small.index("\\end{bmatrix}") < small.index("\\text{where}") < small.index("c_{1} &= \\cos{\\theta_{1}}")
    assert "\\scriptstyle" not in small and not re.search(r"\\\\\[4pt\]\s*$", small)
    wide = display.transform(load("iiwa7"), 0, 7).latex
    assert "r_{11} & r_{12} & r_{13} & p_{x}" in wide and wide.count("\\begin{aligned}") >= 2
    width = layout.PAGES["notebook"].width
    assert all(math_width(line, display=True) <= width for line in _aligned_lines(wide))
    order = re.findall(r"^([rp]_\{\w+\}) &=", wide, re.MULTILINE)
    assert order == [layout.element_name(r, c) for c in range(4) for r in range(3)]  # Craig's order


def test_fk_latex_fits_an_article_by_default_and_another_width_on_request():
    iiwa = run_dhsym("fk", "iiwa7", "--format", "latex").ok()
    assert "r_{11} & r_{12} & r_{13} & p_{x}" in iiwa and "\\begin{align*}" in iiwa
    page = layout.Page(ARTICLE_TEXT_WIDTH_PT, 10.0)
    lines = _aligned_lines(iiwa)
    assert len(lines) > 12 and all(math_width(line, display=True) <= page.width for line in lines)
    assert "where\n\\begin{align*}\nc_{1} &= \\cos{\\theta_{1}} & s_{1} &= \\sin{\\theta_{1}}" in iiwa
    wide = run_dhsym("fk", "puma560", "--format", "latex", "--text-width", "1500").ok()
    assert "r_{11}" not in wide and wide.count("\\begin{bmatrix}") == 1
    status, _, err = run_dhsym("fk", "puma560", "--format", "latex", "--text-width", "12")
    assert status == 2 and "--text-width: the text width must be between 100 and 2000 pt" in err


def test_a_long_fraction_or_root_opens_so_that_its_inside_breaks():
    t1, t3, a = sympy.symbols("theta_1 theta_3 a_3", real=True)
    element = sympy.sqrt(3) * (a * sympy.cos(t3 + sympy.pi / 6) + 2 * a * sympy.sin(t3 + sympy.pi / 6)
                               + 3 * a * sympy.cos(t1) + a * sympy.sin(t1)) / 2
    tex = LatexPrinter([t1, t3]).doprint(element)  # \frac{\sqrt{3}(… + …)}{2}: the 338 pt slide's kind
    assert tex.startswith("\\frac{\\sqrt{3}(") and layout.break_points(tex) == []  # one unbreakable fraction
    lines = layout.break_lines(tex, 12, 11, display=True)
    assert len(lines) == 3 and lines[0].startswith("\\frac{1}{2}\\sqrt{3}(2 a_{3}")
    assert all(math_width(line, display=True) <= 12 for line in lines)
    assert not any(line.endswith("\\sin(\\theta_{3}") for line in lines)  # a sine's argument only if it must
    # (the angle as written, variable first: \sin(\theta_{3} + \frac{\pi}{6})):
    assert any(line.endswith("\\sin(\\theta_{3}") for line in layout.break_lines(tex, 8, 7, display=True))
    assert layout.open_group("x \\sqrt{a + b + c}", 0, 30) == "x (a + b + c)^{1/2}"
    assert layout.open_group("\\frac{1}{a + b}", 0, 30) is None  # nothing inside can break: the README's limit


# ---------------------------------------------------------------- notation

def test_mixed_families_of_angles_keep_their_letters():
    theta_1, phi_2, psi_3 = sympy.symbols("theta_1 phi_2 psi_3", real=True)
    printer = TextPrinter([theta_1, phi_2, psi_3])
    assert printer.doprint(sympy.cos(theta_1 + phi_2) + sympy.sin(psi_3)) == "cθ1,φ2 + sψ3"
    assert text_legend(printer) == "where cθ1,φ2 = cos(θ1 + φ2), sψ3 = sin ψ3"
    latex = LatexPrinter([theta_1, phi_2, psi_3])
    assert latex.doprint(sympy.cos(phi_2)) == "c_{\\phi 2}"


def test_two_chains_in_one_notebook_do_not_share_c1():
    theta_1, phi_1 = sympy.symbols("theta_1 phi_1", real=True)
    arm = Chain([DHRow.revolute(theta_1, a=1)], "standard")
    leg = Chain([DHRow.revolute(phi_1, a=1)], "standard")
    assert "c_{1} &= \\cos{\\theta_{1}}" in display.transform(arm, 0, 1).latex
    leg_display = display.transform(leg, 0, 1).latex
    assert "c_{\\phi 1} &= \\cos{\\phi_{1}}" in leg_display and "c_{1}" not in leg_display


def test_json_text_and_latex_legends_list_the_same_abbreviations():
    for name in ("puma560", "scara", "finger_rrr"):
        data = json.loads(run_dhsym("fk", name, "--format", "json").ok())
        text = run_dhsym("fk", name, "--ascii").ok().split("\nwhere ")[1]
        labels = re.findall(r"(\S+) = (?:cos|sin)", text)
        assert list(data["abbreviations"]) == labels
        latex = run_dhsym("fk", name, "--format", "latex").ok().split("where")[1]
        assert len(re.findall(r"&= \\(?:cos|sin)", latex)) == len(labels)


# ---------------------------------------------------------------- first frame number

def test_first_frame_numbers_every_output(tmp_path):
    robot = tmp_path / "wrist.yaml"
    robot.write_text(WRIST, encoding="utf-8")
    assert "Wrist numbered as in the lecture: ³T₆" in run_dhsym("fk", str(robot)).ok()
    links = run_dhsym("links", str(robot), "--ascii").ok()
    assert re.findall(r": (\dT\d)", links) == ["3T4", "4T5", "5T6"] and "c4 = cos theta4" in links
    assert "Wrist numbered as in the lecture: ⁴T₆" in run_dhsym("fk", str(robot), "--from", "4").ok()
    data = json.loads(run_dhsym("fk", str(robot), "--from", "6", "--to", "3", "--format", "json").ok())
    assert (data["from"], data["to"]) == (6, 3)
    assert "{}^{3}T_{6} =" in run_dhsym("fk", str(robot), "--format", "latex").ok()
    slides = run_dhsym("latex", str(robot), "--steps").ok()
    assert "Result: ${}^{3}T_{6}$" in slides and "{}^{0}T" not in slides
    status, _, err = run_dhsym("fk", str(robot), "--from", "0")
    assert status == 2 and "no frame 0 in this robot; frames are 3, 4, 5, 6" in err


def test_first_frame_numbers_the_labels_of_angles_without_subscripts(tmp_path):
    """Euler-style angles α, β, γ have no joint numbers of their own: the labels count from the
    first joint, c4 c5 c6 for frames 3..6, as the lecture writes the wrist."""
    robot = tmp_path / "euler.yaml"
    robot.write_text("name: wrist\nconvention: standard\nfirst_frame: 3\njoints:\n"
                     "  - {joint: R, alpha: -pi/2, a: 0, d: 0, theta: alpha}\n"
                     "  - {joint: R, alpha: pi/2, a: 0, d: 0, theta: beta}\n"
                     "  - {joint: R, alpha: 0, a: 0, d: d_6, theta: gamma}\n", encoding="utf-8")
    text = run_dhsym("fk", str(robot)).ok()
    assert "c4 c5 c6 − s4 s6" in text and "where c4 = cos α, s4 = sin α, c5 = cos β" in text
    data = json.loads(run_dhsym("fk", str(robot), "--format", "json").ok())
    assert list(data["abbreviations"])[:2] == ["c4", "s4"]
    assert "c_{4} c_{5} c_{6}" in run_dhsym("fk", str(robot), "--format", "latex").ok()


def test_first_frame_in_notebooks_and_pictures():
    from matplotlib.figure import Figure

    from dhsym.plot import draw

    wrist = load_robot_text(WRIST, "wrist.yaml")
    assert wrist.frame_offset == 3 and wrist.transform(3, 6) == wrist.fk() == wrist.chain.transform(0, 3)
    assert display.transform(wrist, 3, 6).latex.startswith("\\begin{array}{l}\n{}^{3}T_{6} =")
    labels = {text.get_text() for text in draw(wrist, {"d_6": 1}, ax=Figure()).texts}
    assert any("6" in label for label in labels) and not any("0" in label for label in labels)


# ---------------------------------------------------------------- prose of a robot file

def test_identifiers_in_robot_file_prose_are_set_as_math():
    assert tex_prose("offset a_2, d_3; 3T_Tool") == "offset $a_{2}$, $d_{3}$; ${}^{3}T_{\\mathrm{Tool}}$"
    assert tex_prose("planar_test & 50%") == "planar\\_test \\& 50\\%"
    article = latexdoc.document(load("puma560"), "article")
    notes = article.split("Notes: ")[1].split("\n")[0]
    assert "$a_{2}$" in notes and "a\\_2" not in notes
    assert "Robot file: puma560.yaml (built into dhsym)" in article
