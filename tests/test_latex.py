"""`dhsym latex` and `dhsym fk/links --format latex`: documents that compile with pdflatex,
fit their pages (no overfull boxes), and print the textbook forms.

Every built-in robot, every test robot (TEST_ROBOTS) and every imported one (IMPORTED) is
compiled six ways (slides with and without --steps, article with --steps, snippet, and
`fk --format latex` and `table --format latex` each wrapped in a minimal amsmath document),
once per module and in parallel (or only those that `-k` selects). A document fails on any
LaTeX error and on any overfull box wider or taller than OVERFULL_TOLERANCE_PT. Documents with
the same preamble are compiled up to BATCH documents to a pdflatex run, each from a new page
after a marker in the log, and each is judged by its own part of the log (loading beamer
is most of the cost of a small document). Golden files:
tests/golden/*.tex; after an intended change of the output, rewrite them with
DHSYM_UPDATE_GOLDEN=1.
"""
import os
import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from itertools import pairwise
from pathlib import Path

import pytest
from cli_runner import run_dhsym
from readers import load_robot_text
from robots import GREEK_PRISMATIC, TEN_JOINTS, TEST_ROBOTS

from dhsym import load
from dhsym.io.library import builtin_names
from dhsym.latex import display
from dhsym.latex import document as latexdoc
from dhsym.latex import layout as texlayout
from dhsym.latex import width as texwidth
from dhsym.latex.results import results_latex, table_latex
from dhsym.printing.printers import LatexPrinter, chain_settings
from dhsym.printing.render import transform_title

GOLDEN = Path(__file__).parent / "golden"
OVERFULL_TOLERANCE_PT = 1.0  # TeX's own \hfuzz is 0.1 pt; 1 pt is invisible on a slide
INSTALL_HINT = ("pdflatex is not installed: run `make tex` (as root it installs TeX Live), or "
                "sudo apt-get install texlive-latex-base texlive-latex-recommended texlive-pictures "
                "texlive-fonts-recommended lmodern poppler-utils")
needs_tex = pytest.mark.skipif(shutil.which("pdflatex") is None, reason=INSTALL_HINT)

VARIANTS = {"slides-steps": ("slides", True), "slides": ("slides", False),
            "article-steps": ("article", True), "snippet": ("snippet", False), "fk": ("fk", False),
            "table": ("table", False)}
SNIPPET_HOST = "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\begin{{document}}\n{}\\end{{document}}\n"

# Robots as `dhsym import` writes them (iCub and Baxter arms from example-robot-data, one with
# the URDF's joint names, one with the long decimals of an older importer), kept as YAML so that
# these tests do not depend on the importer.
IMPORTED = {f"imported-{path.stem}": path
            for path in sorted((Path(__file__).parent / "data" / "imported").glob("*.yaml"))}


def _robot(name: str):
    """A built-in robot, a test robot by its key in TEST_ROBOTS, or an imported one from IMPORTED."""
    if name in TEST_ROBOTS:
        return load_robot_text(TEST_ROBOTS[name], f"{name}.yaml")
    if name in IMPORTED:
        return load_robot_text(IMPORTED[name].read_text(encoding="utf-8"), IMPORTED[name].name)
    return load(name)


def _document(robot, variant: str, **options) -> str:
    kind, steps = VARIANTS[variant]
    if kind == "fk":
        return SNIPPET_HOST.format(results_latex(robot, [(robot.first_frame, robot.last_frame, robot.fk())]) + "\n")
    if kind == "table":  # dhsym table --format latex
        return SNIPPET_HOST.format(table_latex(robot) + "\n")
    text = latexdoc.document(robot, kind, steps=steps, **options)
    return SNIPPET_HOST.format(text) if kind == "snippet" else text


ROBOTS = builtin_names() + list(TEST_ROBOTS) + list(IMPORTED)


def _notebook_displays() -> str:
    """Every robot's table and whole transform as a notebook shows them, on a line as wide as the notebook
    page the layout assumes: pdflatex reads the same LaTeX as MathJax, and nothing overflows."""
    width = texlayout.PAGES["notebook"].width_pt
    preamble = (f"\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\usepackage[textwidth={width}pt,"
                f"paperwidth={width + 60}pt,textheight=3000pt,paperheight=3100pt]{{geometry}}\n"
                "\\begin{document}\n")  # as tall as the 7-axis arm's elements and legend
    body = "".join(f"\\[\n{display.table(chain).latex}\n\\]\n"
                   f"\\[\n{display.matrix(chain, chain.fk(), _title(chain)).latex}\n\\]\n"
                   for chain in map(_robot, ROBOTS))
    return preamble + body + "\\end{document}\n"


def _title(robot) -> str:
    return transform_title(robot.first_frame, robot.last_frame, "latex")


def _width_probe() -> str:
    """A document that logs TeX's own width of every matrix element of every built-in robot."""
    lines = []
    for number, element in enumerate(_all_elements()):
        lines.append(f"\\setbox0\\hbox{{${element}$}}\\typeout{{WIDTH {number} \\the\\wd0}}")
    return SNIPPET_HOST.format("\n".join(lines) + "\n")


def _all_elements() -> list[str]:
    elements = set()
    for name in builtin_names():
        chain = load(name)
        printer = LatexPrinter(chain_settings(chain))
        for i, j in pairwise(chain.frames):
            for matrix in (chain.transform(chain.first_frame, j), chain.transform(i, j)):
                elements.update(printer.doprint(element) for element in matrix)
    return sorted(elements)


RENDERED = ["puma560-slides-steps", "imported-icub_arm_urdf_names-slides", "imported-long_decimals-slides"]
BATCH = 12  # documents to a pdflatex run; several runs go on in parallel
MARK = "DHSYM-DOCUMENT"  # \typeout before each document of a batch: where its part of the log starts


class _Compiled(dict):
    """{job name: (exit status, log text, pdf path)}, each document compiled when first asked for."""

    def __init__(self, folder: Path):
        super().__init__()
        self.folder = folder

    def __missing__(self, job: str):
        self.prefetch([job])
        return self[job]

    def prefetch(self, jobs) -> None:
        """Compile the jobs not compiled yet: in batches of one preamble, the batches in parallel."""
        jobs = [job for job in dict.fromkeys(jobs) if job not in self]
        with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            for results in pool.map(lambda batch: _compile_batch(self.folder, batch),
                                    _batches({job: _source(job) for job in jobs})):
                self.update(results)


def _batches(sources: dict[str, str]) -> list[dict[str, str]]:
    """The jobs in groups of at most BATCH with the same preamble; a document whose PDF is looked at alone."""
    by_preamble: dict[str, list[dict[str, str]]] = {}
    batches = []
    for job, text in sources.items():
        if job in RENDERED:
            batches.append({job: text})
            continue
        groups = by_preamble.setdefault(text.split("\\begin{document}", 1)[0], [])
        if not groups or len(groups[-1]) == BATCH:
            groups.append({})
            batches.append(groups[-1])
        groups[-1][job] = text
    return batches


def _compile_batch(folder: Path, batch: dict[str, str]) -> dict[str, tuple]:
    """{job: (status, its part of the log, the pdf)}; a lone document is compiled as it is."""
    if len(batch) == 1:
        [(job, text)] = batch.items()
        (folder / f"{job}.tex").write_text(text, encoding="utf-8")
        return {job: _pdflatex(folder, job)}
    name = f"batch-{next(iter(batch))}"
    preamble = next(iter(batch.values())).split("\\begin{document}", 1)[0]
    bodies = [f"\\clearpage\\typeout{{{MARK} {job}}}\n"
              + text.split("\\begin{document}\n", 1)[1].rsplit("\\end{document}", 1)[0] for job, text in batch.items()]
    (folder / f"{name}.tex").write_text(preamble + "\\begin{document}\n" + "".join(bodies)
                                        + f"\\clearpage\\typeout{{{MARK} -}}\n\\end{{document}}\n", encoding="utf-8")
    status, log, pdf = _pdflatex(folder, name, halt_on_error=False)  # an error in one leaves the others judged
    parts = re.split(rf"^{MARK} (\S+)$", log, flags=re.MULTILINE)
    found = dict(zip(parts[1::2], parts[2::2]))
    finished = "-" in found and status in (0, 1)
    return {job: (0 if finished and not re.search(r"^! ", found[job], re.MULTILINE) else 1, found[job], pdf)
            if job in found else (1, f"the batch {name} stopped before this document:\n{log[-2000:]}", pdf)
            for job in batch}


def _source(job: str) -> str:
    if job == "puma560-inverse-slides":
        return _document(load("puma560"), "slides-steps", start=6, end=2)  # the chain's frames
    if job == "width-probe":
        return _width_probe()
    if job == "notebook-displays":
        return _notebook_displays()
    name, variant = next((name, variant) for name in ROBOTS for variant in VARIANTS if job == f"{name}-{variant}")
    return _document(_robot(name), variant)


@pytest.fixture(scope="module")
def compiled(tmp_path_factory, request):
    """The compiled documents; those of the selected robot tests (all, or those `-k` picks) at once."""
    result = _Compiled(tmp_path_factory.mktemp("latex"))
    selected = [item.callspec.params for item in request.session.items
                if getattr(item, "module", None) is request.module and hasattr(item, "callspec")]
    result.prefetch(f"{p['name']}-{p['variant']}" for p in selected if "name" in p and "variant" in p)
    return result


def _pdflatex(folder: Path, job: str, halt_on_error=True):
    command = ["pdflatex", *(["-halt-on-error"] if halt_on_error else []), "-interaction=nonstopmode",
               "-no-shell-escape", f"{job}.tex"]
    result = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=600)
    log = (folder / f"{job}.log").read_text(encoding="latin-1")
    return result.returncode, log, folder / f"{job}.pdf"


def _problems(log: str) -> list[str]:
    errors = re.findall(r"^! .*", log, re.MULTILINE)
    overfull = [m.group(0) for m in re.finditer(r"Overfull \\[hv]box \(([\d.]+)pt too (?:wide|high)\)", log)
                if float(m.group(1)) > OVERFULL_TOLERANCE_PT]
    return errors + overfull


@pytest.mark.slow
@needs_tex
@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("name", ROBOTS)
def test_every_robot_compiles_and_fits(compiled, name, variant):
    status, log, pdf = compiled[f"{name}-{variant}"]
    assert status == 0 and pdf.exists(), _problems(log) or log[-2000:]
    assert _problems(log) == []


@pytest.mark.slow
@needs_tex
def test_notebook_displays_compile_and_fit_the_notebook_line(compiled):
    status, log, _ = compiled["notebook-displays"]
    assert status == 0, _problems(log) or log[-2000:]
    assert _problems(log) == []


@pytest.mark.slow
@needs_tex
def test_inverse_slides_compile(compiled):
    status, log, _ = compiled["puma560-inverse-slides"]
    assert status == 0, _problems(log) or log[-2000:]
    assert _problems(log) == []


@pytest.mark.slow
@needs_tex
def test_width_estimate_matches_tex(compiled):
    """The layout rules rely on it: never more than 2 % short of TeX's width, at most 15 % over."""
    status, log, _ = compiled["width-probe"]
    assert status == 0
    measured = {int(n): float(w) for n, w in re.findall(r"WIDTH (\d+) ([\d.]+)pt", log)}
    elements = _all_elements()
    assert len(measured) == len(elements)
    for number, element in enumerate(elements):
        if measured[number] > 20:  # 10 pt font: 1 em = 10 pt
            ratio = texwidth.math_width(element) * 10 / measured[number]
            assert 0.98 <= ratio <= 1.15, (element, ratio)


@pytest.mark.slow
@needs_tex
@pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm (poppler-utils) is not installed")
@pytest.mark.parametrize("job", RENDERED)
def test_slides_render_with_everything_inside_the_page(compiled, tmp_path, job):
    import matplotlib.image

    _, log, pdf = compiled[job]
    pages = int(re.search(r"Output written on .*\((\d+) pages?", log).group(1))
    subprocess.run(["pdftoppm", "-r", "40", "-png", str(pdf), str(tmp_path / "page")], check=True, timeout=120)
    images = sorted(tmp_path.glob("page-*.png"))
    assert len(images) == pages >= 10  # title, table, notation, links, steps and result, some continued
    for image in images:
        ink = matplotlib.image.imread(image)[:, :, :3].min(axis=2) < 0.6  # dark pixels
        height, width = ink.shape
        assert ink.any(), f"{image.name} is blank"
        assert not ink[:, width - width // 40:].any(), f"{image.name}: something touches the right edge"
        bottom = ink[height - height // 25:, : width - width // 8]  # the frame number sits at the right
        assert not bottom.any(), f"{image.name}: something runs off the bottom"


# ---------------------------------------------------------------- layout rules, no TeX needed

def _table_frames(name: str) -> list[str]:
    return [frame for frame in _frames(latexdoc.document(_robot(name), "slides")) if "{DH table" in frame]


def test_a_table_too_wide_for_the_frame_is_split_into_arrays_of_columns_each_with_i():
    frames = _table_frames("imported-icub_arm_urdf_names")  # long joint names from the URDF
    arrays = [re.findall(r"\\begin\{array\}\{c\|c*\}\n(.*?) \\\\", frame) for frame in frames]
    headers = [header for found in arrays for header in found]
    assert len(headers) == 2 and all(header.startswith("i & ") for header in headers)
    columns = [column for header in headers for column in header.split(" & ")[1:]]
    assert columns == ["\\alpha_{i-1}", "a_{i-1}", "d_i", "\\theta_i"]  # every column once, in order
    assert "l_{shoulder,pitch}^{*}" in "".join(frames)


def test_the_notebook_table_follows_the_same_rule():
    assert display.table(load("puma560")).latex.startswith("\\begin{array}{c|cccc}\ni & \\alpha_{i-1}")
    split = display.table(_robot("imported-long_decimals")).latex
    assert split.startswith("\\begin{array}{l}\n\\begin{array}{c|cc}\ni & \\theta_i & d_i \\\\")
    assert "\\begin{array}{c|cc}\ni & a_i & \\alpha_i \\\\" in split


def test_a_column_too_wide_alone_lists_each_rows_parameters_by_name():
    text = "".join(_table_frames("imported-long_decimals"))
    assert "\\begin{array}" not in text
    assert "d_{1} &= -0.0012345678901234567 + 0.026250000000000006 \\sqrt{2} \\\\\n&\\quad {}+ 0.028877500000000004" \
        in text  # broken before a top-level sign, as a matrix element
    assert "\\alpha_{6} &= \\pi/2" in text and "d_{5} &= q_{5}^{*} + 0.13730000000000001" in text


def test_a_fixed_transform_too_wide_for_the_line_is_a_display_broken_between_factors():
    article = latexdoc.document(_robot("imported-icub_arm"), "article")
    assert "Fixed base transform:\\par\n\\[\n\\begin{aligned}\n{}^{\\mathrm{base}}T_{0} &= T_{x}(" in article
    assert "\\,T_{y}(0.1433) \\\\\n&\\quad {}T_{z}(" in article
    short = load_robot_text("convention: standard\njoints: [{joint: R, alpha: 0, a: l_1, d: 0, theta: theta_1}]\n"
                            "tool: [{Tz: d_6}]\n", "arm.yaml")  # one that fits stays a sentence
    assert "Fixed tool transform: ${}^{1}T_{\\mathrm{tool}} = T_{z}(d_{6})$." in latexdoc.document(short, "article")
    slides = _table_frames("imported-long_decimals")
    lead_in = next(frame for frame in slides if "Fixed base transform:" in frame)
    assert "{}^{\\mathrm{base}}T_{0} &= T_{x}(" in lead_in  # the lead-in never ends a frame alone



def _frames(text: str) -> list[str]:
    return re.findall(r"\\begin\{frame\}.*?\\end\{frame\}", text, re.DOTALL)


def test_short_matrices_are_matrices_long_ones_are_named_elements():
    planar = latexdoc.document(load("planar3r"), "slides")
    assert "& l_{1} c_{1} + l_{2} c_{12} + l_{3} c_{123} \\\\" in planar and "r_{11}" not in planar
    puma = latexdoc.document(load("puma560"), "slides")
    result = [frame for frame in _frames(puma) if "Result" in frame]
    assert "r_{11} & r_{12} & r_{13} & p_{x}" in result[0]
    # Craig's r11, on one line, in textbook order of factors and brackets
    assert ("r_{11} &= c_{1}[c_{23}(c_{4} c_{5} c_{6} - s_{4} s_{6}) - s_{23} s_{5} c_{6}] "
            "+ s_{1}(c_{4} s_{6} + s_{4} c_{5} c_{6})") in result[0]
    assert "p_{z} &= -a_{2} s_{2} - d_{4} c_{23} - a_{3} s_{23}" in "".join(result)


def test_elements_come_column_by_column_and_a_column_stays_on_one_frame():
    for name in ("puma560", "stanford", "iiwa7"):
        frames = _frames(latexdoc.document(load(name), "slides"))
        labels = [re.findall(r"^([rp]_\{\w+\}) &=", frame, re.MULTILINE) for frame in frames if "Result" in frame]
        order = [label for frame in labels for label in frame]
        assert order == [texlayout.element_name(r, c) for c in range(4) for r in range(3)]
        for frame in labels:
            assert len(frame) % 3 == 0, (name, frame)


def test_long_elements_break_before_a_sign_at_the_outermost_bracket():
    slides = latexdoc.document(load("iiwa7"), "slides")
    continuations = re.findall(r"^&\\quad \{\}([+-]) ", slides, re.MULTILINE)
    assert continuations, "the 7-axis arm's elements need more than one line"
    page = texlayout.PAGES["slides"]
    line_pattern = r"^(?:[rp]_\{\w+\} &= |&\\quad \{\})(.*?)(?: \\\\(?:\[[\d.]+pt\])?)?$"
    for line in re.findall(line_pattern, slides, re.MULTILINE):
        assert texwidth.math_width(line) <= page.width


def test_break_lines_keeps_every_character_and_never_splits_a_group():
    element = LatexPrinter(load("iiwa7").joint_variables).doprint(load("iiwa7").fk()[0, 0])
    lines = texlayout.break_lines(element, 12, 11)
    assert len(lines) > 2
    assert " ".join(lines) == element
    for line in lines:
        assert line.count("{") - line.count("\\{") == line.count("}") - line.count("\\}")
        assert texwidth.math_width("{}" + line) <= 12 or not texlayout.break_points(line)
    # the outermost sign first, unless that leaves a line less than half full
    assert texlayout.break_lines("x_{1} x_{2} x_{3} + (b + c)", 5.5, 5.5) == ["x_{1} x_{2} x_{3}", "+ (b + c)"]
    assert texlayout.break_lines("a + (b + c)", 3.5, 3.5) == ["a + (b", "+ c)"]


def test_steps_show_the_product_and_simplified_intermediate_results():
    snippet = latexdoc.document(load("spatial3r"), "snippet", steps=True)
    step1 = snippet.split("% Step 1")[1].split("% Result")[0]
    assert "{}^{0}T_{2} &= {}^{0}T_{1}\\,{}^{1}T_{2} =" in step1 and step1.count("begin{bmatrix}") == 3
    assert "c_{1} c_{2} & -c_{1} s_{2} & s_{1} & a_{2} c_{1} c_{2}" in step1  # simplified, then used again:
    step2 = snippet.split("% Result")[1]  # the last step is the result
    assert "c_{1} c_{2} & -c_{1} s_{2} & s_{1} & a_{2} c_{1} c_{2}" in step2 and "% Step 2" not in snippet
    assert "c_{1} c_{23} & -c_{1} s_{23} & s_{1} & c_{1}(a_{2} c_{2} + a_{3} c_{23})" in step2
    puma = latexdoc.document(load("puma560"), "snippet", steps=True)
    step3 = puma.split("% Step 3")[1].split("% Step 4")[0]
    assert "{}^{0}T_{4} = {}^{0}T_{3}\\,{}^{3}T_{4} =" in step3 and step3.count("begin{bmatrix}") == 1  # names only
    assert "r_{13} &= -c_{1} s_{23}" in step3
    slides = latexdoc.document(load("puma560"), "slides", steps=True)
    titles = re.findall(r"\\begin\{frame\}\{(Step \d+|Result): ", slides)
    assert list(dict.fromkeys(titles)) == [f"Step {k}" for k in range(1, 5)] + ["Result"]  # 0T6 once, not twice
    result = "".join(frame for frame in _frames(slides) if "{Result: " in frame)
    assert "{}^{0}T_{6} = {}^{0}T_{5}\\,{}^{5}T_{6} =" in result and result.count("r_{11} &=") == 1


def test_slides_have_title_table_notation_link_and_result_frames():
    slides = latexdoc.document(load("stanford"), "slides")
    frames = _frames(slides)
    assert "Stanford manipulator" in frames[0] and "Source: Lecture 003" in frames[0]
    assert "Robot file: stanford.yaml (built into dhsym)" in frames[0] and "standard DH convention" in frames[0]
    assert frames[1].startswith("\\begin{frame}{DH table}")
    assert "i & \\theta_i & d_i & a_i & \\alpha_i" in frames[1]  # standard column order
    assert "3 & 0 & d_{3}^{*} & 0 & 0" in frames[1]  # the prismatic variable, as it is, starred
    # the notation comes before the first product: the convention and every abbreviation used
    assert frames[2].startswith("\\begin{frame}{Notation}") and "Standard (distal) DH convention" in frames[2]
    assert "c_{1} &= \\cos{\\theta_{1}} & s_{1} &= \\sin{\\theta_{1}}" in frames[2]
    used = set(re.findall(r"[cs]_\{\d+\}", slides.split("{Notation}")[1].split("\\end{frame}", 1)[1]))
    assert used and all(label + " &= " in frames[2] for label in used)
    assert "c_{3}" not in frames[2]  # joint 3 is prismatic: no c3 anywhere
    # several link matrices to a frame, each frame titled with the ones it shows
    links = [frame for frame in frames if "{Link matrices: " in frame]
    assert 1 <= len(links) < 6 and sum(frame.count("begin{bmatrix}") for frame in links) == 6
    assert links[0].startswith("\\begin{frame}{Link matrices: ${}^{0}T_{1}$ to ")
    assert "s_{2}(d_{3} + d_{6} c_{5})" in slides
    assert "where" not in slides  # the legend is in the notation frame only


def test_modified_table_order_and_base_tool_frames():
    slides = latexdoc.document(load("finger_rrr"), "slides")
    assert "i & \\alpha_{i-1} & a_{i-1} & d_i & \\theta_i" in slides
    assert "Fixed base transform: ${}^{\\mathrm{base}}T_{0} = T_{y}(-d)\\,T_{z}(h)$." in slides
    assert "{Link matrices: ${}^{\\mathrm{base}}T_{0}$ to ${}^{3}T_{\\mathrm{tool}}$}" in slides
    # θ1, ψ1 and φ1 share a subscript: each abbreviation names its angle
    assert "\\psi_{1}" in slides and "c_{\\psi 1,\\phi 1} &= \\cos(\\psi_{1} + \\phi_{1})" in slides


def test_two_digit_joints_greek_names_and_angle_differences():
    ten = latexdoc.document(load_robot_text(TEN_JOINTS, "ten.yaml"), "snippet")
    assert "{}^{9}T_{10}" in ten and "c_{10}" in ten and "c_{1,2,3,4,5,6,7,8,9,10}" in ten
    assert "% Abbreviations (commas separate the joint numbers when one of them has two digits):" in ten
    assert "Ten-link planar arm \\& co: 100\\% planar\\_test, $\\theta$" in latexdoc.document(
        load_robot_text(TEN_JOINTS, "ten.yaml"), "slides")
    greek = latexdoc.document(load_robot_text(GREEK_PRISMATIC, "greek.yaml"), "snippet")
    assert "\\phi_{1}^{*}" in greek and "\\lambda_{1}" in greek and "d_{3}^{*}" in greek
    assert "\\overline{\\psi 2}" in greek and "a bar over a joint number marks an angle that is subtracted" in greek


# ---------------------------------------------------------------- golden files

@pytest.mark.parametrize("name", ["planar3r", "spatial3r", "spherical_wrist"])
def test_golden_snippets(name):
    text = latexdoc.document(load(name), "snippet", steps=True)
    path = GOLDEN / f"{name}.tex"
    if os.environ.get("DHSYM_UPDATE_GOLDEN"):
        path.write_text(text, encoding="utf-8")
    assert _math_only(text) == _math_only(path.read_text(encoding="utf-8"))


def _math_only(text: str) -> list[str]:
    """Lines without the robot's name and source, which the robot file may reword."""
    return [line for line in text.splitlines() if not line.startswith(("% dhsym latex:", "% Source:"))]


def test_golden_files_hold_the_textbook_forms():
    planar = (GOLDEN / "planar3r.tex").read_text()
    assert "c_{123} & -s_{123} & 0 & l_{1} c_{1} + l_{2} c_{12} + l_{3} c_{123}" in planar  # 0T_tool
    spatial = (GOLDEN / "spatial3r.tex").read_text()
    assert "s_{1} c_{23} & -s_{1} s_{23} & -c_{1} & s_{1}(a_{2} c_{2} + a_{3} c_{23})" in spatial
    wrist = (GOLDEN / "spherical_wrist.tex").read_text()
    assert "c_{4} c_{5} c_{6} - s_{4} s_{6} & -c_{4} c_{5} s_{6} - s_{4} c_{6} & c_{4} s_{5} & d_{6} c_{4} s_{5}" \
        in wrist  # Z-Y-Z Euler angles, as the lecture prints 3T6
    assert "-s_{5} c_{6} & s_{5} s_{6} & c_{5} & d_{6} c_{5}" in wrist


# ---------------------------------------------------------------- the command

def test_cli_writes_the_same_text_to_a_file(tmp_path):
    printed = run_dhsym("latex", "planar2r", "--document", "article").ok()
    target = tmp_path / "arm.tex"
    assert run_dhsym("latex", "planar2r", "--document", "article", "-o", target).ok() == ""
    assert target.read_text(encoding="utf-8") == printed
    assert [p.name for p in tmp_path.iterdir()] == ["arm.tex"]  # no temporary file left behind


def test_cli_failures_leave_no_partial_file(tmp_path, monkeypatch):
    target = tmp_path / "slides.tex"
    status, _, error = run_dhsym("latex", "puma560", "--from", "9", "-o", target)
    assert status == 2 and error.count("\n") == 1
    assert "--from: no frame 9 in this robot; frames are 0, 1, 2, 3, 4, 5, 6" in error
    status, _, error = run_dhsym("latex", "puma560", "--from", "2", "--to", "2", "-o", target)
    assert status == 2 and "same frame" in error
    assert not target.exists()

    target.write_text("the lecturer's old slides")

    def broken_rename(source, destination):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", broken_rename)
    status, _, error = run_dhsym("latex", "puma560", "-o", target)
    assert status == 2 and "No space left on device" in error
    assert target.read_text() == "the lecturer's old slides"
    assert [p.name for p in tmp_path.iterdir()] == ["slides.tex"]


def test_cli_from_to_and_inverse():
    forward = run_dhsym("latex", "puma560", "--document", "snippet", "--from", "3", "--to", "6").ok()
    assert "% Result: ${}^{3}T_{6}$" in forward and "{}^{0}T_{1}" not in forward.split("% Link")[1]
    backward = run_dhsym("latex", "puma560", "--document", "snippet", "--from", "6", "--to", "3").ok()
    assert "{}^{6}T_{5} =" in backward and "% Result: ${}^{6}T_{3}$" in backward


@pytest.mark.parametrize("name", ["puma560", "stanford", "iiwa7", "ur5"])
def test_widths_up_to_each_break_point_in_one_pass_are_those_measured_alone(name):
    """How a long element is broken depends on the width of each line up to each break point;
    measuring them in one pass gives exactly what measuring each prefix alone gives."""
    from dhsym.printing.render import latex_printer

    robot = load(name)
    printer = latex_printer(robot)
    for element in robot.fk():
        tex = printer.doprint(element)
        for prefix in ("", "{}"):
            text = prefix + tex
            ends = [i + len(prefix) for i, _ in texlayout.break_points(tex)] + [len(text)]
            for displayed in (False, True):
                assert texwidth.prefix_widths(text, ends, displayed) == \
                    [texwidth.math_width(text[:end], displayed) for end in ends], (name, tex)
