"""The browser page's Python side (dhsym.web), run natively: what the page shows is what the command
line prints, a robot file's mistakes are the same one line with its place, the drawing is the
arm's forward kinematics, and the page loads nothing that the browser does not have.

The page itself, in Chromium, is tests/test_web_page.py."""
from __future__ import annotations

import json
import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest
from cli_runner import run_dhsym

from dhsym.io.library import ROBOTS_DIR
from dhsym.web.app import builtin_robots, handle

CORPUS = Path(__file__).parent / "bad_inputs"
ARM = """name: my arm
convention: standard
joints:
  - {joint: R, theta: theta_1, d: d_1, a: 0, alpha: pi/2}
  - {joint: R, theta: theta_2, d: 0, a: a_2, alpha: 0}
sample: {d_1: 0.3, a_2: 0.5}
"""


def ask(**request) -> dict:
    request.setdefault("file", "arm.yaml")
    return json.loads(handle(json.dumps(request)))


def builtin(name: str) -> str:
    return (ROBOTS_DIR / f"{name}.yaml").read_text(encoding="utf-8")


def shown_text(answer: dict) -> str:
    """The page's words (text segments and headings), without the math."""
    return " ".join(text for part in answer["parts"] for kind, text in part.get("segments", []) if kind == "text")


@pytest.mark.parametrize("show, command", [("fk", "fk"), ("links", "links"), ("table", "table")])
@pytest.mark.parametrize("width", [345, 900])
def test_the_latex_of_a_transform_or_table_is_the_command_lines(show, command, width, tmp_path):
    (tmp_path / "arm.yaml").write_text(builtin("puma560"))
    answer = ask(kind="show", show=show, yaml=builtin("puma560"), width=width)
    width_option = ["--text-width", str(width)] if command != "table" else []
    printed = run_dhsym(command, "arm.yaml", "--format", "latex", *width_option, cwd=tmp_path).ok()
    assert answer["state"] == "ready"
    if command == "table":  # `dhsym table` has no --text-width: the page's line is its own
        printed = run_dhsym(command, "arm.yaml", "--format", "latex", cwd=tmp_path).ok() if width == 345 else None
    if printed is not None:
        assert answer["latex"] == printed.rstrip("\n")


def test_the_jacobian_and_the_inverse_kinematics_are_the_command_lines_snippets(tmp_path):
    (tmp_path / "arm.yaml").write_text(builtin("planar2r"))
    for command in ("jacobian", "ik"):
        answer = ask(kind="show", show=command, yaml=builtin("planar2r"), width=345)
        printed = run_dhsym(command, "arm.yaml", "--format", "latex", cwd=tmp_path).ok()
        if command == "ik":  # the snippet's first line says what it is and what it needs
            printed = printed.split("\n", 1)[1]
        assert answer["latex"] == printed


def test_the_inverse_kinematics_shows_each_branch_under_its_heading():
    answer = ask(kind="show", show="ik", yaml=builtin("planar2r"), width=500)
    headings = [" ".join(text for _, text in part["segments"]) for part in answer["parts"] if part["kind"] == "heading"]
    assert "Branch 1: elbow down" in headings and "Branch 2: elbow up" in headings
    branch = [["text", "Branch 1: elbow down"]]
    first = next(k for k, part in enumerate(answer["parts"]) if part.get("segments") == branch)
    assert answer["parts"][first + 1]["kind"] == "math" and "\\theta_{2}" in answer["parts"][first + 1]["tex"]


@pytest.mark.parametrize("name", ["puma560", "stanford", "scara", "fourbar_right", "spherical_wrist"])
def test_no_tex_is_left_in_the_words_and_no_page_break_in_the_math(name):
    for show in ("table", "links", "fk", "jacobian"):
        answer = ask(kind="show", show=show, yaml=builtin(name), width=400)
        assert answer["state"] == "ready", answer["message"]
        assert not re.search(r"[\\$]|\{|\}", shown_text(answer)), shown_text(answer)
        assert not any("break" in part["tex"] for part in answer["parts"] if part["kind"] == "math")


def test_a_narrower_line_breaks_the_matrix_into_its_elements():
    wide = ask(kind="show", show="fk", yaml=builtin("planar3r"), width=1400)
    narrow = ask(kind="show", show="fk", yaml=builtin("planar3r"), width=200)
    assert "r_{11} &= " not in wide["latex"] and "r_{11} &= " in narrow["latex"]


def test_any_transform_and_its_frames():
    answer = ask(kind="show", show="fk", yaml=builtin("spherical_wrist"), **{"from": "6", "to": "4"})
    assert answer["frames"] == [3, 4, 5, 6]
    assert answer["title"][-2:] == [["math", "{}^{6}T_{4}"], ["text", " (standard DH)"]]
    same = ask(kind="show", show="fk", yaml=builtin("planar2r"), **{"from": "1", "to": "1"})
    assert same["state"] == "error" and "same frame (1)" in same["message"]


@pytest.mark.parametrize("name", sorted(path.stem for path in CORPUS.glob("*.expected")
                                        if not (CORPUS / f"{path.stem}.args").exists()
                                        and (CORPUS / f"{path.stem}.yaml").exists()))
def test_a_robot_files_mistakes_are_the_command_lines(name):
    """Every case of the corpus that `dhsym fk FILE` reads: the same lines (warnings, then the error)."""
    try:
        text = (CORPUS / f"{name}.yaml").read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        pytest.skip("not UTF-8: a text box in a page cannot hold it")
    expected = (CORPUS / f"{name}.expected").read_text(encoding="utf-8").splitlines()
    if any("too large to print or read" in line for line in expected):
        pytest.skip("the page lays out LaTeX, whose limit is lower than the text's (cli.limits.LATEX_MAX_NODES)")
    answer = ask(kind="show", show="fk", yaml=text, file=f"{name}.yaml")
    seen = [f"dhsym: warning: {warning}" for warning in answer.get("warnings", [])]
    if answer["state"] == "error":
        seen.append(f"dhsym: error: {answer['message']}")
        place = re.match(rf"{re.escape(name)}\.yaml:(\d+):(\d+): ", answer["message"])
        if place:
            assert (answer["line"], answer["column"]) == (int(place.group(1)), int(place.group(2)))
    assert seen == expected
    assert "traceback" not in answer


def test_an_internal_error_is_said_as_a_bug_not_as_the_users_mistake(monkeypatch):
    import dhsym.web.outputs

    monkeypatch.setattr(dhsym.web.outputs, "results_latex", lambda *a, **k: 1 / 0)
    answer = ask(kind="show", show="fk", yaml=ARM)
    assert answer["state"] == "error" and answer["internal"]
    assert answer["message"].startswith("internal error: ZeroDivisionError") and "a bug in dhsym" in answer["message"]


def test_the_slides_are_dhsym_latex(tmp_path):
    (tmp_path / "arm.yaml").write_text(ARM)
    answer = ask(kind="slides", yaml=ARM, jacobian=True)
    assert answer["tex"] == run_dhsym("latex", "arm.yaml", "--jacobian", cwd=tmp_path).ok()
    assert "\\documentclass[11pt,aspectratio=169]{beamer}" in answer["tex"]


def _points(svg: str, kind: str) -> list[tuple[float, float]]:
    line = next(e for e in ElementTree.fromstring(svg).iter() if e.get("class") == kind)
    return [tuple(map(float, pair.split(","))) for pair in line.get("points").split()]


def test_the_drawing_is_the_forward_kinematics_at_the_sliders_values():
    """The planar 2R from above: the link's last point is (a1 c1 + a2 c12, a1 s1 + a2 s12), y upwards."""
    answer = ask(kind="draw", yaml=builtin("planar2r"), values={"theta_1": math.pi / 6, "theta_2": math.pi / 2})
    tip = _points(answer["svg"], "link")[-1]
    a1, a2, t1, t12 = 0.5, 0.4, math.pi / 6, math.pi / 6 + math.pi / 2
    assert tip == pytest.approx((a1 * math.cos(t1) + a2 * math.cos(t12), -(a1 * math.sin(t1) + a2 * math.sin(t12))),
                                abs=1e-4)
    assert [s["name"] for s in answer["sliders"]] == ["theta_1", "theta_2"]


def test_the_drawing_has_every_joint_and_frame():
    svg = ElementTree.fromstring(ask(kind="draw", yaml=builtin("stanford"))["svg"])
    classes = [element.get("class") or "" for element in svg.iter()]
    assert classes.count("joint revolute") == 5 and classes.count("joint prismatic") == 1
    assert sum(c.startswith("axis ") for c in classes) == 3 * 7  # frames 0..6, an x, y and z each
    assert ask(kind="draw", yaml=builtin("stanford"))["sliders"][2]["unit"] == ""  # d3 slides: a length


def test_a_drawing_without_numbers_says_which_are_missing():
    answer = ask(kind="draw", yaml=ARM.replace("sample: {d_1: 0.3, a_2: 0.5}\n", ""))
    assert answer["state"] == "error"
    assert answer["message"] == ("to draw the arm, give a number for a_2, d_1 in the robot file's sample, "
                                 "e.g. sample: {a_2: 0.5}")


def test_the_picker_lists_every_built_in_robot_with_its_file():
    robots = builtin_robots()
    assert [r["name"] for r in robots] == sorted(p.stem for p in ROBOTS_DIR.glob("*.yaml"))
    assert all(r["yaml"] == builtin(r["name"]) and r["title"] for r in robots)


@pytest.mark.slow
def test_the_page_imports_nothing_the_browser_lacks():
    """numpy, matplotlib, lxml and xacro are not in the page (the build ships SymPy, mpmath, PyYAML, dhsym)."""
    probe = ("import json, sys\nfrom dhsym.web.app import handle\n"
             f"text = open({str(ROBOTS_DIR / 'stanford.yaml')!r}).read()\n"
             "ask = lambda **request: json.loads(handle(json.dumps({'yaml': text, **request})))['state']\n"
             "for show in ('table', 'links', 'fk', 'jacobian', 'ik'):\n"
             "    assert ask(kind='show', show=show) == 'ready'\n"
             "assert ask(kind='draw') == ask(kind='slides', ik=True) == 'ready'\n"
             "print(sorted(m for m in ('numpy', 'matplotlib', 'lxml', 'xacro') if m in sys.modules))")
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-2000:]
    assert result.stdout.strip() == "[]"
