"""The inverse kinematics counts frames and joints one way inside (a plain Chain, frames 0..n) and
prints them the robot file's way (`first_frame`, base and tool): an arm numbered from 1 or from 5
gets the same solution, the same sentences and the same module as one numbered from 0, its
printed frame and joint numbers moved."""
import json
import re

import pytest
import sympy
from cli_runner import run_dhsym

import dhsym
from dhsym.api.ik import inverse_kinematics
from dhsym.io.library import ROBOTS_DIR
from dhsym.latex.ik import snippet

WRIST_ARMS = ("puma560", "stanford")


def numbered(tmp_path, name: str, first_frame: int):
    """The built-in robot `name` written with `first_frame`."""
    text = (ROBOTS_DIR / f"{name}.yaml").read_text(encoding="utf-8")
    path = tmp_path / f"{name}_from_{first_frame}.yaml"
    path.write_text(text.replace("convention:", f"first_frame: {first_frame}\nconvention:", 1), encoding="utf-8")
    return path


@pytest.mark.slow
@pytest.mark.parametrize("name", WRIST_ARMS)
@pytest.mark.parametrize("first_frame", [1, 3, 5])
def test_the_wrist_is_tied_to_det_j_whatever_the_first_frame(tmp_path, name, first_frame):
    """s5 = 0 is the singular factor s5 of det J, however the file numbers its frames (with
    first_frame 1 the solver once found sin(theta_4), from 2 on nothing, from 5 on it exited 70)."""
    status, out, err = run_dhsym("ik", numbered(tmp_path, name, first_frame), "--width", "1000")
    assert (status, err) == (0, "")
    assert "a singularity of J: the factor s5 of det J" in out
    joints = ", ".join(str(k + first_frame) for k in (4, 5)) + f" and {6 + first_frame}"
    assert f"the axes of joints {joints} meet at the wrist centre" in out


def test_the_wrist_factor_is_read_in_the_chains_own_frames():
    from dhsym.inverse.singular import wrist_factors

    puma = dhsym.load("puma560")
    assert wrist_factors(puma.chain, puma.numbers) == [sympy.sin(puma.chain.joint_variables[4])]


DIGITS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉", "01234567890123456789")
NUMBER = re.compile(r"[0-9]+|[⁰¹²³⁴⁵⁶⁷⁸⁹]+|[₀₁₂₃₄₅₆₇₈₉]+")


def layout_free(text: str) -> str:
    """`text` without its line breaks (a two-digit frame number may wrap a line elsewhere)."""
    text = re.sub(r"[{}]", "", text.replace(r"\\[4pt]", " ").replace(r"\text{", ""))
    return " ".join(text.split())


def moved_by(first: str, other: str, offset: int) -> int:
    """How many numbers of `other` are those of `first` moved by `offset` (frame and joint numbers);
    fails unless the two are the same text but for numbers and line breaks, each number the same or
    moved by `offset`."""
    first, other = layout_free(first), layout_free(other)
    assert NUMBER.split(first) == NUMBER.split(other)  # the same text between the numbers
    pairs = [(int(a.translate(DIGITS)), int(b.translate(DIGITS)))
             for a, b in zip(NUMBER.findall(first), NUMBER.findall(other), strict=True)]
    wrong = [(a, b) for a, b in pairs if b not in (a, a + offset)]
    assert not wrong, wrong[:5]
    return sum(b == a + offset != a for a, b in pairs)


def outputs(path) -> dict:
    """What `dhsym ik` writes of the robot file at `path` (text, JSON, LaTeX, the numpy module) and
    the notebook's LaTeX."""
    result = inverse_kinematics(dhsym.load(path))
    return {"text": result.text(), "json": json.dumps(result.json(), ensure_ascii=False, indent=1),
            "latex": snippet(result.solution, result.robot), "notebook": str(result.latex()),
            "python": result.code()}


@pytest.mark.slow  # twelve derivations of a six-joint arm
@pytest.mark.parametrize("name", WRIST_ARMS)
def test_first_frame_0_to_5_with_base_and_tool_changes_only_the_numbers(tmp_path, name):
    """An arm with base and tool numbered from 0..5 gets the same text, JSON, LaTeX and module,
    each frame and joint number moved by first_frame (θ5 stays θ5: the file's name)."""
    text = (ROBOTS_DIR / f"{name}.yaml").read_text(encoding="utf-8")
    text = text.replace("base: []", "base: [{Tz: 1/4}, {Rz: pi/2}]").replace("tool: []", "tool: [{Tz: 1/10}]")
    files = []
    for first_frame in range(6):
        folder = tmp_path / str(first_frame)
        folder.mkdir()
        files.append(folder / f"{name}.yaml")
        files[-1].write_text(text.replace("convention:", f"first_frame: {first_frame}\nconvention:", 1),
                             encoding="utf-8")
    first = outputs(files[0])
    assert "a singularity of J: the factor s5 of det J" in " ".join(first["text"].split())
    for first_frame, path in enumerate(files[1:], 1):
        other = outputs(path)
        moved = {kind: moved_by(first[kind], other[kind], first_frame) for kind in first}
        assert moved["text"] and moved["latex"], moved  # the frames and joints are printed the file's way
        assert f"joints {4 + first_frame}, {5 + first_frame} and {6 + first_frame}" in other["text"]
