"""`dhsym jacobian` and `dhsym latex --jacobian`: what a user sees, JSON that reads back,
errors in one line, and documents that compile without overfull boxes."""
import json
import random
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor

import pytest
import sympy
from cli_runner import run_dhsym as run

from dhsym import Chain, DHRow, load
from dhsym.checking.verify import check, numeric_error
from dhsym.latex.document import document
from dhsym.velocity import jacobian

OVERFULL_TOLERANCE_PT = 1.0


def test_puma_in_frame_3_is_craigs_jacobian_with_its_singularities():
    result = run("jacobian", "puma560", "--frame", "3")
    assert result.status == 0 and result.stderr == ""
    out = result.stdout
    assert "Jacobian ³J of the origin of frame 6, in frame 3" in out
    assert "−d3 c23" in out and "a2 c2 + a3 c23 − d4 s23" in out and "a3 + a2 c3" in out
    assert "det J = −a2 s5(d4 c3 + a3 s3)(a2 c2 + a3 c23 − d4 s23)" in out
    assert "s5 = 0: wrist: axes 4 and 6 line up" in out
    assert "c23 = cos(θ2 + θ3)" in out


def test_wide_jacobian_is_listed_element_by_element_and_fits_the_width():
    out = run("jacobian", "iiwa7", "--width", "80").stdout
    assert "J₁₁ = " in out and "J₆₇ = " in out
    assert "⎡ J₁₁   J₁₂   J₁₃   J₁₄   J₁₅   J₁₆   J₁₇ ⎤" in out  # the matrix of names, then the elements
    words = " ".join(out.split())
    assert "the arm is redundant, and no determinant is computed" in words and "not worked out" in words
    assert max(len(line) for line in out.splitlines()[:-3] if line.startswith(("J", " "))) <= 80


GENERAL_3R = """name: general 3R
convention: standard
joints:
  - {joint: R, theta: q_1, d: 0.2433, a: 0.011, alpha: pi/2}
  - {joint: R, theta: q_2, d: 0.03, a: 0.28, alpha: pi/3}
  - {joint: R, theta: q_3, d: 0.02, a: 0.13, alpha: pi/2}
"""


@pytest.mark.parametrize("width", [60, 80])
def test_a_singular_factor_longer_than_the_line_keeps_its_meaning_in_whole_words(width, tmp_path):
    """The factor takes the whole line: it breaks like a matrix element and its meaning follows."""
    (tmp_path / "arm.yaml").write_text(GENERAL_3R)
    out = run("jacobian", tmp_path / "arm.yaml", "--point", "3", "--width", width).stdout
    singular = out.split("singular where\n")[1].split("\n\n")[0].splitlines()
    assert " ".join(line.strip() for line in singular).endswith(
        "= 0: the joint velocities are dependent here (no simpler description found)")
    assert all(len(line) <= width for line in singular) and singular[-1].startswith("    ")


@pytest.mark.slow
def test_json_reads_back_and_has_the_documented_keys():
    data = json.loads(run("jacobian", "stanford", "--format", "json").stdout)
    assert set(data) == {"robot", "convention", "frame", "point", "joint_variables", "matrix", "determinant",
                         "singularities"}
    assert (data["frame"], data["point"]) == (0, 6)
    chain = load("stanford")
    names = {s.name: s for s in chain.symbols}
    read = lambda text: sympy.sympify(text, locals=names)  # noqa: E731
    assert numeric_error(sympy.Matrix([[read(x) for x in row] for row in data["matrix"]]), chain.jacobian()) < 1e-9
    assert check(read(data["determinant"]), sympy.factor(chain.jacobian().det(method="berkowitz"))).numeric
    assert {str(read(s)) for s in data["singularities"]} == {"sin(theta_5)", "d_3", "sin(theta_2)"}


def test_json_for_a_redundant_arm_has_no_determinant():
    data = json.loads(run("jacobian", "iiwa7", "--format", "json").stdout)
    assert data["determinant"] is None and data["singularities"] == []
    assert len(data["matrix"]) == 6 and len(data["matrix"][0]) == 7


def test_steps_print_the_propagation_link_by_link():
    out = run("jacobian", "planar2r", "--steps", "--frame", "2").stdout
    assert "¹ω₁ = (0, 0, θ̇1)" in out and "²v₂ = (a1 θ̇1 s2, a2 θ̇2 + θ̇1(a2 + a1 c2), 0)" in out
    assert "⎡ a1 s2        0  ⎤" in out
    ascii_out = run("jacobian", "planar2r", "--steps", "--ascii").stdout
    assert ascii_out.isascii() and "theta1dot" in ascii_out


def test_a_frame_that_does_not_exist_is_one_line_and_status_2():
    result = run("jacobian", "puma560", "--frame", "9")
    assert result.status == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "--frame: no frame 9" in result.stderr


def test_latex_format_is_math_for_a_document():
    out = run("jacobian", "planar3r", "--format", "latex").stdout
    assert "{}^{0}J =" in out and "\\det J" in out and "l_{1} l_{2} s_{2}" in out


needs_tex = pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
ROBOTS = ["puma560", "planar3r", "stanford", "scara_spong", "iiwa7", "spherical_wrist"]


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    folder = tmp_path_factory.mktemp("velocity-latex")
    jobs = {}
    for name in ROBOTS:
        for kind in ("slides", "article"):
            jobs[f"{name}-{kind}"] = document(load(name), kind, steps=name == "planar3r", jacobian=True)
    for job, text in jobs.items():
        (folder / f"{job}.tex").write_text(text, encoding="utf-8")

    def compile_one(job):
        command = ["pdflatex", "-halt-on-error", "-interaction=nonstopmode", "-no-shell-escape", f"{job}.tex"]
        result = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=180)
        return result.returncode, (folder / f"{job}.log").read_text(encoding="latin-1")

    with ThreadPoolExecutor(max_workers=2) as pool:
        return dict(zip(jobs, pool.map(compile_one, jobs)))


def _problems(log):
    import re

    errors = re.findall(r"^! .*", log, re.MULTILINE)
    overfull = [m.group(0) for m in re.finditer(r"Overfull \\[hv]box \(([\d.]+)pt too (?:wide|high)\)", log)
                if float(m.group(1)) > OVERFULL_TOLERANCE_PT]
    return errors + overfull


@pytest.mark.slow
@needs_tex
@pytest.mark.parametrize("kind", ["slides", "article"])
@pytest.mark.parametrize("name", ROBOTS)
def test_documents_with_the_jacobian_compile_and_fit(compiled, name, kind):
    status, log = compiled[f"{name}-{kind}"]
    assert status == 0, _problems(log) or log[-2000:]
    assert _problems(log) == []


def test_documents_show_the_jacobian_determinant_and_singularities():
    tex = document(load("puma560"), "article", jacobian=True)
    assert "\\subsection*{Velocity kinematics}" in tex
    assert "J_{11} &= -d_{3} c_{1} - s_{1}(a_{2} c_{2} + a_{3} c_{23} - d_{4} s_{23})" in tex
    assert "$s_{5} = 0$: wrist: axes 4 and 6 line up." in tex
    assert "\\det J" in tex


def general_chain_file(tmp_path, links: int):
    rows = "".join(f"  - {{joint: R, alpha: alpha_{i}, a: a_{i}, d: d_{i}, theta: theta_{i}}}\n"
                   for i in range(1, links + 1))
    path = tmp_path / "general.yaml"
    path.write_text("name: general\nconvention: standard\njoints:\n" + rows)
    return path


def test_a_jacobian_too_large_to_print_is_refused_by_its_estimate_naming_a_frame_that_fits(tmp_path):
    path = general_chain_file(tmp_path, 12)
    result = run("jacobian", str(path))
    assert (result.status, result.stdout) == (2, "")
    assert result.stderr == (f"dhsym: error: {path}: the Jacobian of frame 12 in frame 0 would take about 19.2 "
                             "million characters, too large to print or read; express it in a frame nearer the "
                             "point with --frame (--frame 5 fits)\n")
    latex = run("latex", str(path), "--to", "3", "--jacobian")
    assert latex.status == 2 and "the Jacobian of frame 12 in frame 0 would take" in latex.stderr


def test_a_general_six_link_jacobian_in_a_middle_frame_is_built():
    """The shortest of the candidate forms is chosen by a linear-time length for large entries
    (count_ops took minutes here); by numbers it is the plain ᵏz × (ᵏp − ᵏp_i), ᵏz."""
    symbols = [sympy.symbols(f"alpha_{i} a_{i} d_{i} theta_{i}", real=True) for i in range(1, 7)]
    general = Chain([DHRow.revolute(t, d, a, al) for al, a, d, t in symbols], "standard")
    frame = 3
    origin = general.transform(frame, 6)[:3, 3]
    columns = []
    for joint in range(1, 7):
        axis = general.transform(frame, joint - 1)
        z, p = axis[:3, 2], axis[:3, 3]
        columns.append(list(z.cross(origin - p)) + list(z))
    assert numeric_error(jacobian(general, frame), sympy.Matrix(columns).T, trials=3) < 1e-9


OFFSET_WRIST = """name: offset-wrist cobot (the Yaskawa HC10's dimensions)
convention: standard
joints:
  - {joint: R, theta: q_1, d: 0.275, a: 0, alpha: -pi/2}
  - {joint: R, theta: q_2 - pi/2, d: 0, a: 0.7, alpha: pi}
  - {joint: R, theta: q_3 + pi/2, d: 0, a: 0, alpha: pi/2}
  - {joint: R, theta: q_4, d: -0.5, a: 0, alpha: -pi/2}
  - {joint: R, theta: q_5, d: -0.162, a: 0, alpha: pi/2}
  - {joint: R, theta: q_6, d: -0.13, a: 0, alpha: pi}
"""


@pytest.mark.slow
def test_an_offset_wrist_arm_has_the_same_determinant_in_both_conventions(tmp_path):
    """det J does not depend on the convention: the modified table of the same arm (whose own
    frames would write it out to 114,593 terms the Berkowitz way) prints the same factors."""
    standard = tmp_path / "cobot.yaml"
    standard.write_text(OFFSET_WRIST)
    modified = tmp_path / "cobot_modified.yaml"
    assert run("convert", standard, "--to", "modified", "-o", modified).status == 0
    outputs = [run("jacobian", path) for path in (standard, modified)]
    assert [result.status for result in outputs] == [0, 0]
    determinants = [result.stdout.split("det J = ")[1].split("\nwhere")[0] for result in outputs]
    assert determinants[0] == determinants[1] and "not computed" not in determinants[0]
    assert determinants[0].startswith("−0.35(0.2268 s2 c3 s4 s5 + 0.2268 s2 s3 c4 s4 c5 − 0.7 s2 s3 s5")
    for path in (standard, modified):
        arm = load(str(path))
        assert det_error(arm.determinant().value, arm.jacobian()) < 1e-9


def det_error(value, matrix, trials: int = 4) -> float:
    """The largest difference between `value` and the determinant of `matrix` at random joint values."""
    rng, worst = random.Random(7), 0.0
    for _ in range(trials):
        point = {s: sympy.Float(rng.uniform(-3, 3)) for s in value.free_symbols | matrix.free_symbols}
        worst = max(worst, abs(float(value.xreplace(point)) - float(matrix.xreplace(point).det())))
    return worst


@pytest.mark.slow
def test_the_determinant_of_a_general_three_link_arm_is_its_linear_block(tmp_path):
    """Every DH parameter a symbol: the 3×3 determinant of the point's velocity, multiplied out
    where it has fewest terms (frame 2: 26, where frame 0 has 212)."""
    rows = "".join(f"  - {{joint: R, theta: theta_{i}, d: d_{i}, a: a_{i}, alpha: alpha_{i}}}\n" for i in range(1, 4))
    path = tmp_path / "general3.yaml"
    path.write_text(f"convention: standard\njoints:\n{rows}")
    arm = load(str(path))
    result = arm.determinant()
    assert result.block == "rows vx, vy, vz"
    assert det_error(result.value, arm.jacobian()[:3, :]) < 1e-9
    printed = run("jacobian", path)
    assert printed.status == 0 and "det J[rows vx, vy, vz] = −a3(" in printed.stdout
