"""`dhsym ik`, `dhsym latex --ik` and `chain.ik()`: what a user sees. Solutions come from the
solver where it exists; the planar 2R is also checked on a solution written by hand
(tests/ik_examples.py), so that every surface is tested whatever the solver finds."""
import json
import re
import shutil
import subprocess
import sys

import ik_checks
import ik_examples
import numpy as np
import pytest
from cli_runner import run_dhsym

from dhsym import load
from dhsym.printing.render import display_width

OVERFULL_TOLERANCE_PT = 1.0
HOST = "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\begin{{document}}\n{}\\end{{document}}\n"


BY_HAND = {"planar2r": ik_examples.planar2r, "puma560": ik_examples.puma560}


@pytest.fixture
def by_hand(monkeypatch):
    """`solve` answers with the solutions written by hand (planar 2R, Craig's PUMA 560)."""
    def derive(chain, free=(), **given):
        name = next(key for key in BY_HAND if load(key).chain.rows == chain.rows)
        assert not free
        return BY_HAND[name]()

    monkeypatch.setattr(sys.modules["dhsym.inverse.solve"], "derive", derive)  # the module, not its function


def test_text_is_the_textbook_form_and_fits_the_width(by_hand):
    status, out, err = run_dhsym("ik", "planar2r", "--width", "40")
    assert status == 0 and err == ""
    assert max(map(display_width, out.splitlines())) <= 40
    words = " ".join(out.split())
    assert "D = (px² + py² − a1² − a2²)/(2 a1 a2)" in words
    assert "Branch 1: elbow down θ2 = atan2(√(1 − D²), D)" in words
    assert "θ1 = atan2(py, px) − atan2(a2 s2, a1 + a2 c2)" in words
    assert "where c2 = cos θ2, s2 = sin θ2" in words
    assert "⎡ r11   r12   r13   px ⎤" in out


@pytest.mark.parametrize("width", [40, 60, 100])
def test_puma_text_fits_every_width_and_names_its_eight_branches(by_hand, width):
    status, out, _ = run_dhsym("ik", "puma560", "--width", str(width))
    assert status == 0 and max(map(display_width, out.splitlines())) <= width
    words = " ".join(out.split())
    assert "K = (px² + py² + pz² − a2² − a3² − d3² − d4²)/(2 a2)" in words
    # the hand-written names follow the roots; dhsym checks them against the arm: with the shoulder on the
    # right the arm reaches over, and the root that put the elbow above the line to the wrist puts it below
    assert "Branch 8: shoulder right, elbow up, wrist flipped" in words
    assert "θ1 = atan2(py, px) − atan2(d3, −√(px² + py² − d3²))" in words
    assert "s23 = sin(θ2 + θ3)" in words


@pytest.mark.slow
def test_puma_json_and_module_reach_random_poses_with_all_eight_branches(by_hand, tmp_path):
    chain = load("puma560")
    _, out, _ = run_dhsym("ik", "puma560", "--format", "json")
    data = ik_checks.check_json(out, chain)
    assert len(data["solutions"]) == 8 and data["definitions"][0][0] == "K"
    _, out, _ = run_dhsym("ik", "puma560", "--format", "python")
    (tmp_path / "puma_ik.py").write_text(out)
    module = ik_checks.import_module(tmp_path / "puma_ik.py")
    assert "def ik(T, *, a_2=0.4318, a_3=0.0203, d_3=0.1245, d_4=0.4318):" in out
    joints = ik_checks.random_joints(chain, np.random.default_rng(560), 20)
    ik_checks.check_branches_reach(module.ik, chain, ik_checks.sample_constants(chain), joints)
    poses = np.array([np.array(ik_checks.numeric_fk(chain, ik_checks.sample_constants(chain))(*q), dtype=float)
                      for q in joints])
    assert module.ik(poses).shape == (20, 8, 6) and np.isfinite(module.ik(poses)).all()


def test_ascii_text_has_no_unicode(by_hand):
    status, out, _ = run_dhsym("ik", "planar2r", "--ascii")
    assert status == 0 and out.isascii(), [ch for ch in out if not ch.isascii()]
    assert "theta2 = atan2(sqrt(1 - D^2), D)" in out


def test_json_is_the_contract(by_hand):
    status, out, _ = run_dhsym("ik", "planar2r", "--format", "json")
    data = ik_checks.check_json(out, load("planar2r"))
    assert [branch["name"] for branch in data["solutions"]] == ["elbow down", "elbow up"]
    assert data["definitions"] == [["D", "(-a_1**2 - a_2**2 + px**2 + py**2)/(2*a_1*a_2)"]]


def test_generated_module_reaches_every_pose_with_every_branch(by_hand, tmp_path):
    status, out, _ = run_dhsym("ik", "planar2r", "--format", "python")
    assert status == 0 and "import sympy" not in out and "dhsym ik planar2r --format python" in out
    path = tmp_path / "planar2r_ik.py"
    path.write_text(out)
    module = ik_checks.import_module(path)
    chain = load("planar2r")
    assert module.BRANCHES == ("elbow down", "elbow up") and module.JOINTS == ("theta_1", "theta_2")
    joints = ik_checks.random_joints(chain, np.random.default_rng(16), 25)
    position = ["px", "py"]  # two joints reach a point of the plane
    ik_checks.check_branches_reach(module.ik, chain, ik_checks.sample_constants(chain), joints, compare=position)
    other = {"a_1": 1.5, "a_2": 0.7}  # constants as keyword arguments
    ik_checks.check_branches_reach(lambda T: module.ik(T, **other), chain, other, joints[:5], compare=position)


def test_generated_module_shapes_and_nan_outside_the_workspace(by_hand, tmp_path):
    _, out, _ = run_dhsym("ik", "planar2r", "--format", "python")
    (tmp_path / "arm_ik.py").write_text(out)
    ik = ik_checks.import_module(tmp_path / "arm_ik.py").ik
    far = np.eye(4)
    far[0, 3] = 2.0  # a_1 + a_2 = 0.9: out of reach
    near = np.eye(4)
    near[:2, 3] = 0.5, 0.3
    assert ik(far).shape == (2, 2) and np.isnan(ik(far)).all()
    many = ik(np.stack([far, near, near]))
    assert many.shape == (3, 2, 2) and np.isnan(many[0]).all() and np.isfinite(many[1:]).all()
    with pytest.raises(ValueError, match="one pose"):
        ik(np.eye(3))


def test_python_api_has_branches_evaluation_latex_and_code(by_hand):
    arm = load("planar2r")
    result = arm.ik()
    assert arm.ik() is result  # solved once
    assert [b.name for b in result.branches] == ["elbow down", "elbow up"]
    assert "\\mathrm{atan2}" in result.latex().latex and "def ik(T, *, a_1=0.5, a_2=0.4):" in result.code()
    fk = ik_checks.numeric_fk(arm, {"a_1": 0.5, "a_2": 0.4})
    pose = np.array(fk(0.3, 1.2), dtype=float)
    assert np.allclose(result.function()(pose)[0], [0.3, 1.2])  # elbow down: θ2 > 0
    assert "elbow up" in repr(result) and result.json()["robot"] == arm.name


@pytest.mark.parametrize("argv, message", [
    (["ik", "planar2r", "--free", "theta_9"], "--free theta_9: Planar elbow manipulator (2R) has no joint variable "
                                              "theta_9; its joint variables are theta_1, theta_2"),
    (["ik", "iiwa7"], "has 7 joints, 7 of them unknown, but a pose fixes only 6: make 1 of them a parameter"),
    (["latex", "iiwa7", "--ik"], "make 1 of them a parameter with --free"),
    (["latex", "planar2r", "--free", "theta_1"], "--free names the parameters of the inverse kinematics; add --ik"),
    (["ik", "planar2r", "--format", "yaml"], "argument --format: invalid choice: 'yaml'"),
])
def test_user_errors_are_one_line_and_status_2(argv, message):
    status, out, err = run_dhsym(*argv)
    assert status == 2 and out == "" and err.count("\n") == 1 and err.startswith("dhsym: error: ")
    assert message in err


def test_latex_snippet_is_the_derivation(by_hand):
    _, out, _ = run_dhsym("ik", "planar2r", "--format", "latex")
    assert "\\noindent Step 1 (law of cosines), for $\\theta_{2}$" in out
    assert "D &= \\frac{p_{x}^{2} + p_{y}^{2} - a_{1}^{2} - a_{2}^{2}}{2 a_{1} a_{2}}" in out
    assert "\\theta_{2} &= \\mathrm{atan2}(-\\sqrt{1 - D^{2}}, D)" in out
    assert "c_{2} &= \\cos{\\theta_{2}}" in out


def test_the_latex_snippet_sets_its_words_as_text_not_comments(by_hand):
    """Compiled, the snippet must say which step, which branch, which condition: only its first
    line (what it is and what it needs) is a comment."""
    _, out, _ = run_dhsym("ik", "puma560", "--format", "latex")
    first, *lines = out.splitlines()
    assert first.startswith("% dhsym ik: ") and not [line for line in lines if line.lstrip().startswith("%")]
    assert "\\par\\medskip\\noindent\\textbf{Branch 8: shoulder right, elbow up, wrist flipped}" in lines
    assert any(line.startswith("\\noindent Step 1 (") for line in lines)
    labels = [line.removeprefix("\\noindent ").split(":")[0] for line in lines]
    assert "Condition" in labels and "Degenerate" in labels and "where" in labels
    assert "\\noindent \\textbf" not in out and "\\par\n\\begin{align*}" not in out  # no empty line above


def test_the_legend_says_once_that_atan2_takes_the_sine_first(by_hand):
    text = run_dhsym("ik", "planar2r").ok()
    said = "atan2(y, x) is the angle of the point (x, y), y (the sine) first"
    assert " ".join(text.split()).count(said) == 1 and "Spong (2006) writes Atan2(x, y)." in " ".join(text.split())
    assert text.rstrip().splitlines()[-2:] == ["where c2 = cos θ2, s2 = sin θ2", said + "; Spong (2006) writes "
                                                "Atan2(x, y)."]  # with the legend, at the end
    latex = run_dhsym("ik", "planar2r", "--format", "latex").ok()
    assert latex.count("$\\mathrm{atan2}(y, x)$ is the angle of the point $(x, y)$, $y$ (the sine) first") == 1
    assert "Spong (2006) writes $\\mathrm{Atan2}(x, y)$" in latex
    assert latex.count("Atan2") == 1 and text.count("Atan2") == 1


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="pdftotext (poppler-utils) is not installed")
@pytest.mark.parametrize("command", ["ik", "latex"])
@pytest.mark.parametrize("robot", BY_HAND)
def test_the_compiled_snippet_names_every_branch_step_and_condition(by_hand, tmp_path, command, robot):
    argv = ["ik", robot, "--format", "latex"] if command == "ik" else ["latex", robot, "--ik", "--document", "snippet"]
    out = run_dhsym(*argv).ok()
    assert _pdflatex(tmp_path, robot, HOST.format(out)) == (0, [])
    subprocess.run(["pdftotext", f"{robot}.pdf", f"{robot}.txt"], cwd=tmp_path, check=True)
    words = " ".join((tmp_path / f"{robot}.txt").read_text(encoding="utf-8").split())
    solution = json.loads(run_dhsym("ik", robot, "--format", "json").ok())
    assert all(f"Branch {number}: {branch['name']}" in words for number, branch in enumerate(solution["solutions"], 1))
    steps = re.findall(r"Step \d+ \(", out)
    assert steps == re.findall(r"Step \d+ \(", words) and (steps or robot == "puma560")  # the PUMA by hand has none
    assert "Inverse kinematics: the problem" in words and f"{len(solution['solutions'])} branches." in words
    assert words.count("Condition: ") == len(solution["conditions"]) > 0
    assert words.count("Degenerate: ") == len(solution["degenerate"]) > 0
    assert "is the angle of the point (x, y), y (the sine) first" in words


def _pdflatex(folder, job: str, text: str):
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed: run `make tex`")
    (folder / f"{job}.tex").write_text(text, encoding="utf-8")
    command = ["pdflatex", "-halt-on-error", "-interaction=nonstopmode", "-no-shell-escape", f"{job}.tex"]
    result = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=120)
    log = (folder / f"{job}.log").read_text(encoding="latin-1")
    errors = re.findall(r"^! .*", log, re.MULTILINE)
    overfull = [m.group(0) for m in re.finditer(r"Overfull \\[hv]box \(([\d.]+)pt too (?:wide|high)\)", log)
                if float(m.group(1)) > OVERFULL_TOLERANCE_PT]
    return result.returncode, errors + overfull


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
@pytest.mark.parametrize("kind", ["slides", "article", "snippet", "ik"])
@pytest.mark.parametrize("robot", BY_HAND)
def test_documents_with_the_derivation_compile_and_fit(by_hand, tmp_path, kind, robot):
    argv = ["ik", robot, "--format", "latex"] if kind == "ik" else ["latex", robot, "--ik", "--document", kind]
    status, out, _ = run_dhsym(*argv)
    assert status == 0 and ("{Branches 1 " if kind == "slides" else "Branch 2: ") in out  # slides: one ± frame
    text = HOST.format(out) if kind in ("snippet", "ik") else out
    assert _pdflatex(tmp_path, kind, text) == (0, [])


def test_plot_draws_every_branch_at_the_pose_side_by_side(by_hand):
    from matplotlib.figure import Figure

    from dhsym.plot.branches import draw_branches

    figure = draw_branches(load("planar2r"), target={"px": 0.6, "py": 0.3}, figure=Figure())
    titles = [ax.get_title() for ax in figure.axes]
    assert [t.splitlines()[0] for t in titles] == ["1. elbow down", "2. elbow up"]
    assert titles[0].splitlines()[1] == "−10°, 84°" and figure.get_suptitle().endswith("2 of 2 branches reach the pose")
    far = draw_branches(load("planar2r"), target={"px": 2}, figure=Figure())
    assert all("does not reach this pose" in ax.get_title() for ax in far.axes)


def test_plot_command_writes_the_picture_and_refuses_a_wrong_element(by_hand, tmp_path):
    path = tmp_path / "branches.png"
    status, out, err = run_dhsym("plot", "planar2r", "--ik", "px=0.6, py=0.3", "-o", str(path))
    assert (status, out.strip(), err) == (0, str(path), "") and path.read_bytes().startswith(b"\x89PNG")
    status, out, err = run_dhsym("plot", "planar2r", "--ik", "qx=1", "-o", str(tmp_path / "no.png"))
    assert status == 2 and err.count("\n") == 1 and "--ik 'qx=1': expected ELEMENT=NUMBER" in err
    assert not (tmp_path / "no.png").exists()
    status, _, err = run_dhsym("plot", "planar2r", "--free", "theta_1")
    assert status == 2 and "add --ik" in err
