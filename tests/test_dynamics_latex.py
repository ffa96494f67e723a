"""The equations of motion in LaTeX compile with pdflatex and fit their pages: `dhsym latex --dynamics`
(slides and articles, with the derivation), `dhsym dynamics --format latex` (a snippet with either
method's steps and the regressor) and the notebook display at the notebook's line width. A slide
deck is rendered and looked at: nothing touches the right edge or runs off the bottom."""
import re
import shutil
import subprocess

import pytest
from cli_runner import run_dhsym

from dhsym.api.dynamics import robot_dynamics
from dhsym.io.library import load
from dhsym.latex.layout import PAGES

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed (make tex)")]
OVERFULL_TOLERANCE_PT = 1.0
SNIPPET_HOST = "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\begin{{document}}\n{}\\end{{document}}\n"
DOCUMENTS = {
    "elbow-slides": ["latex", "spong_elbow", "--dynamics", "--steps"],
    "elbow-article": ["latex", "spong_elbow", "--dynamics", "--steps", "--document", "article"],
    "puma-slides": ["latex", "puma560_akb", "--dynamics"],
    "scara-article": ["latex", "scara_spong", "--dynamics", "--steps", "--document", "article"],
    "planar3r-snippet": ["dynamics", "planar3r", "--format", "latex", "--steps", "--method", "newton-euler",
                         "--regressor"],
    "cylindrical-snippet": ["dynamics", "cylindrical_rpp", "--format", "latex", "--steps", "--regressor"],
}


def _source(job: str) -> str:
    if job == "notebook":
        width = PAGES["notebook"].width_pt
        body = robot_dynamics(load("spong_elbow")).latex(steps=True, regressor=True).latex
        return (f"\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\usepackage[textwidth={width}pt,"
                f"paperwidth={width + 60}pt,textheight=3000pt,paperheight=3100pt]{{geometry}}\n"
                f"\\begin{{document}}\n\\[\n{body}\n\\]\n\\end{{document}}\n")
    text = run_dhsym(*DOCUMENTS[job]).ok()
    return SNIPPET_HOST.format(text) if job.endswith("snippet") else text


def _compiled(folder, job: str):
    (folder / f"{job}.tex").write_text(_source(job), encoding="utf-8")
    result = subprocess.run(["pdflatex", "-halt-on-error", "-interaction=nonstopmode", "-no-shell-escape",
                             f"{job}.tex"], cwd=folder, capture_output=True, text=True, timeout=600)
    return result.returncode, (folder / f"{job}.log").read_text(encoding="latin-1"), folder / f"{job}.pdf"


def _problems(log: str) -> list[str]:
    errors = re.findall(r"^! .*", log, re.MULTILINE)
    overfull = [m.group(0) for m in re.finditer(r"Overfull \\[hv]box \(([\d.]+)pt too (?:wide|high)\)", log)
                if float(m.group(1)) > OVERFULL_TOLERANCE_PT]
    return errors + overfull


@pytest.mark.parametrize("job", [*DOCUMENTS, "notebook"])
def test_the_dynamics_compile_and_fit(tmp_path, job):
    status, log, pdf = _compiled(tmp_path, job)
    assert status == 0 and pdf.exists(), _problems(log) or log[-2000:]
    assert _problems(log) == []


@pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm (poppler-utils) is not installed")
def test_the_slides_keep_everything_inside_the_page(tmp_path):
    import matplotlib.image

    status, log, pdf = _compiled(tmp_path, "elbow-slides")
    assert status == 0
    subprocess.run(["pdftoppm", "-r", "40", "-png", str(pdf), str(tmp_path / "page")], check=True, timeout=120)
    images = sorted(tmp_path.glob("page-*.png"))
    assert len(images) >= 12  # the kinematics, each link's energies, the derivatives, the results
    for image in images:
        ink = matplotlib.image.imread(image)[:, :, :3].min(axis=2) < 0.6
        height, width = ink.shape
        assert ink.any(), f"{image.name} is blank"
        assert not ink[:, width - width // 40:].any(), f"{image.name}: something touches the right edge"
        assert not ink[height - height // 25:, : width - width // 8].any(), f"{image.name}: runs off the bottom"


def test_the_article_heads_each_result_and_step():
    text = run_dhsym(*DOCUMENTS["elbow-article"]).ok()
    headings = re.findall(r"\\subsubsection\*\{(.*)\}", text)
    assert headings[:3] == ["Lagrange: link 1", "Lagrange: link 2", "Lagrange: the derivatives of $M$"]
    assert {"Inertia matrix $M(q)$", "Christoffel symbols $c_{ijk}$", "Gravity vector $g(q)$"} <= set(headings)
    assert text.index("\\subsection*{Dynamics}") < text.index("\\subsubsection*{Inertia matrix $M(q)$}")
