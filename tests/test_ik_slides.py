"""`dhsym latex ROBOT --ik` slides as a lecturer puts them up: branches that differ only in signs
written once with ± (∓) and a table of the sign each branch takes, never a frame of one equation
where it can share one, the method's axes as math, the angles solved as one in every format, and
the book's names for the derivation's quantities. The planar 2R and the PUMA are also checked on
the solutions written by hand (tests/ik_examples.py), whatever the solver finds."""
import json
import re
import shutil
import subprocess

import pytest
from cli_runner import run_dhsym
from test_ik_cli import BY_HAND

from dhsym import load
from dhsym.latex.document import document
from dhsym.latex.ik import prose
from dhsym.latex.ik_signs import families

PUMA_NAMES = [f"shoulder {s}, elbow {e}, wrist {w}" for s in ("left", "right") for e in ("up", "down")
              for w in ("not flipped", "flipped")]


def _frames(tex: str) -> list[tuple[str, str]]:
    """(title, body) of each frame."""
    return re.findall(r"\\begin\{frame\}(?:\[plain\])?(?:\{([^\n]*)\})?\n(.*?)\\end\{frame\}", tex, re.DOTALL)


def _ik_frames(tex: str) -> list[tuple[str, str]]:
    frames = _frames(tex)
    first = next(n for n, (title, _) in enumerate(frames) if title.startswith("Inverse kinematics: the problem"))
    return frames[first:]


def _lone_equations(tex: str) -> list[str]:
    """The titles of the frames of the derivation, its quantities and its branches that show one
    equation: one line of an aligned block that does not continue another."""
    out = []
    for title, body in _ik_frames(tex):
        lines = [line for block in re.findall(r"\\begin\{aligned\}\n(.*?)\\end\{aligned\}", body, re.DOTALL)
                 for line in block.splitlines() if not line.startswith("&\\quad")]
        if title.startswith(("Derivation", "Intermediate", "Branch")) and len(lines) == 1:
            out.append(title)
    return out


def _slides(name: str, solution=None) -> str:
    robot = load(name)
    return document(robot, "slides", ik=lambda: solution if solution is not None else robot.ik().solution)


def test_the_puma_written_by_hand_has_one_frame_of_formulas_with_pm_and_one_sign_table():
    tex = _slides("puma560", BY_HAND["puma560"]())
    titles = [title for title, _ in _ik_frames(tex)]
    assert [title for title in titles if title.startswith("Branch")] == ["Branches 1 to 8", "Branches 1 to 8 (cont.)"]
    formulas = dict(_ik_frames(tex))["Branches 1 to 8"]
    assert "\\theta_{1} &= \\mathrm{atan2}(p_{y}, p_{x}) - \\mathrm{atan2}(d_{3}, \\pm \\sqrt{" in formulas
    assert "\\mathrm{atan2}(K, \\pm \\sqrt{a_{3}^{2} + d_{4}^{2} - K^{2}})" in formulas
    assert formulas.count("\\pm") == 4  # θ1's and θ3's roots, θ4's pair (Craig's flipped wrist) twice
    table = dict(_ik_frames(tex))["Branches 1 to 8 (cont.)"]
    rows = re.findall(r"^(\d) & (.*) \\\\$", table, re.MULTILINE)
    assert [name for _, name in ((n, cells.rsplit(" & ", 1)[1]) for n, cells in rows)] == PUMA_NAMES
    assert rows[0][1].startswith("$+$ & $+$ & $+$") and rows[7][1].startswith("$-$ & $-$ & $-$")
    assert "branch & $\\theta_{1}$ & $\\theta_{3}$ & $\\theta_{4}$ &" in table


def test_no_inverse_kinematics_frame_holds_a_single_equation():
    for name in BY_HAND:
        assert _lone_equations(_slides(name, BY_HAND[name]())) == [], name


def test_coupled_signs_are_written_plus_minus_and_minus_plus():
    rows = [("\\theta_{1}", "\\mathrm{atan2}(\\sqrt{E}, a)", None, None), ("x", "b - \\sqrt{E}", None, None)]
    turned = [("\\theta_{1}", "\\mathrm{atan2}(-\\sqrt{E}, a)", None, None), ("x", "b + \\sqrt{E}", None, None)]
    [family] = families([("one", rows), ("two", turned)])
    assert [row[1] for row in family.rows] == ["\\mathrm{atan2}(\\pm \\sqrt{E}, a)", "b \\mp \\sqrt{E}"]
    assert family.columns == ["\\theta_{1}"] and family.signs == [["+"], ["-"]] and family.mixed


def test_branches_that_differ_in_more_than_signs_are_not_merged():
    one = [("\\theta_{1}", "\\mathrm{atan2}(\\sqrt{E}, a)", None, None)]
    other = [("\\theta_{1}", "\\mathrm{atan2}(-\\sqrt{E}, b)", None, None)]
    assert families([("one", one), ("two", other)]) == []
    tex = _slides("planar2r", _differing_planar2r())
    titles = [title for title, _ in _ik_frames(tex)]
    assert "Branches 1 and 2" in titles  # written one by one, under their names, on one frame
    body = dict(_ik_frames(tex))["Branches 1 and 2"]
    assert "\\textbf{Branch 1: elbow down}" in body and "\\textbf{Branch 2: elbow up}" in body
    assert "\\pm" not in body and "tabular" not in body


def _differing_planar2r():
    """The hand-written 2R with the second branch's θ1 written another way: not a sign apart."""
    import sympy

    from dhsym.inverse.solution import Branch

    solution = BY_HAND["planar2r"]()
    first, second = solution.branches
    t2, elbow = second.assignments[0]
    t1, _ = second.assignments[1]
    other = Branch(second.name, ((t2, elbow), (t1, sympy.atan2(sympy.Symbol("py", real=True), 1))))
    from dataclasses import replace

    return replace(solution, branches=(first, other))


def test_the_method_sets_axes_and_products_as_math():
    assert prose("(u4 × u6 along +u5/−u5)") == "($u_{4} \\times u_{6}$ along $+u_{5}$/\\allowbreak{}$-u_{5}$)"
    assert prose("seen from +z0 (x0 right, y0 up)") == "seen from $+z_{0}$ ($x_{0}$ right, $y_{0}$ up)"
    tex = _slides("planar2r")
    assert "seen from $+z_{0}$ ($x_{0}$ right, $y_{0}$ up)" in tex and "+z0" not in tex


@pytest.mark.slow
def test_the_angles_solved_as_one_are_in_the_json_and_the_latex():
    robot = load("planar3r")
    data = json.loads(run_dhsym("ik", "planar3r", "--format", "json").ok())
    assert data["angles_solved_as_one"] == [["theta_123", "theta_1 + theta_2 + theta_3"]]
    said = "Angles solved as one: $\\theta_{123} = \\theta_{1} + \\theta_{2} + \\theta_{3}$."
    assert said in document(robot, "article", ik=lambda: robot.ik().solution)
    assert said in _slides("planar3r")
    assert said in run_dhsym("ik", "planar3r", "--format", "latex").ok()
    assert "Angles solved as one: θ123 = θ1 + θ2 + θ3" in " ".join(run_dhsym("ik", "planar3r").ok().split())
    slides = json.loads(run_dhsym("ik", "cylindrical_wrist", "--format", "json").ok())  # d2 = zc − d1: no angle
    assert slides["angles_solved_as_one"] == [] and "solved as one" not in run_dhsym("ik", "cylindrical_wrist").ok()


@pytest.mark.slow
def test_the_iiwa_names_its_shoulder_offset_d_as_spong_and_keeps_k_for_craigs_elbow():
    words = " ".join(run_dhsym("ik", "iiwa7", "--free", "theta_3").ok().split())
    assert "d = −d5 s3 s4 θ1 = atan2(yc, xc) − atan2(d, √(xc² + yc² − d²))" in words
    assert not re.search(r"\bK\b", words)
    assert "K = (px² + py² + pz² − a2² − a3² − d3² − d4²)/(2 a2)" in " ".join(run_dhsym("ik", "puma560").ok().split())


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("pdftotext") is None or shutil.which("pdflatex") is None,
                    reason="pdflatex and pdftotext (TeX Live, poppler-utils) are needed")
@pytest.mark.parametrize("name, columns, frames", [("puma560", "θ1 θ3 θ5", 2), ("planar2r", "θ2", 1),
                                                   ("stanford", "θ1 θ2 θ5", 2), ("ur5", "θ1 θ5 θ3", 3)])
def test_compiled_slides_show_the_branches_once_with_their_sign_table(tmp_path, name, columns, frames):
    from test_latex import _problems

    tex = _slides(name)
    (tmp_path / "slides.tex").write_text(tex, encoding="utf-8")
    command = ["pdflatex", "-halt-on-error", "-interaction=nonstopmode", "-no-shell-escape", "slides.tex"]
    subprocess.run(command, cwd=tmp_path, capture_output=True, timeout=600)
    assert _problems((tmp_path / "slides.log").read_text(encoding="latin-1")) == []
    subprocess.run(["pdftotext", "slides.pdf", "slides.txt"], cwd=tmp_path, check=True)
    words = " ".join((tmp_path / "slides.txt").read_text(encoding="utf-8").split())
    solution = json.loads(run_dhsym("ik", name, "--format", "json").ok())
    count = len(solution["solutions"])
    assert f"branch {columns}" in words and "±" in words and "Branch 1:" not in words
    for number, branch in enumerate(solution["solutions"], 1):
        assert re.search(rf"\b{number} [+−]( [+−])* {re.escape(branch['name'])}".replace("√", "√?"), words), branch
    titles = [title for title, _ in _ik_frames(tex)]
    assert titles.count(f"Branches 1 to {count}") + titles.count("Branches 1 and 2") == 1
    assert len([title for title in titles if title.startswith("Branches")]) == frames
    assert _lone_equations(tex) == []
    if name == "puma560":
        tight = words.replace(" ", "")  # pdftotext spaces out subscripts
        assert "(u4×u6along+u5/−u5)" in tight and "Anglessolvedasone:θ23=θ2+θ3." in tight
        assert len(titles) == 10  # problem 2, derivation 3, branches 2, existence 2 (the det J factors said), legend 1


def test_a_lone_branch_of_one_line_ends_the_frame_before_it():
    tex = _slides("fourbar_right")  # one joint: one branch of one equation
    assert _lone_equations(tex) == [] and not [title for title, _ in _ik_frames(tex) if title.startswith("Branch")]
    assert "\\textbf{Branch 1: the only solution}\\par\n\\[" in dict(_ik_frames(tex))["Derivation"]
