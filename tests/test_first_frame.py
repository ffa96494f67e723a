"""A robot file's `first_frame` renames frames and joints and nothing else. The same six-joint arm
with a wrist (PUMA-like, Stanford), a base and a tool, its frames numbered from 0 and from k = 1..5:
the Jacobian, det J and its singularities, the screw axes, `check`'s advice and the fk/links LaTeX are
the same up to numbering. Up to numbering means: the same text once each printed number is read,
every number equal or larger by exactly k (a frame or joint label), and the labels do move. The
symbols keep the file's names (θ5 stays θ5, so c23 and s5 never move). The IK side has its own test."""
from __future__ import annotations

import json
import re

import pytest
import sympy
from cli_runner import run_dhsym
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

import dhsym

PUMA_LIKE = """\
name: PUMA-like arm
convention: modified
joints:
  - {joint: R, alpha: 0,     a: 0,   d: 0,   theta: theta_1}
  - {joint: R, alpha: -pi/2, a: 0,   d: 0,   theta: theta_2}
  - {joint: R, alpha: 0,     a: a_2, d: d_3, theta: theta_3}
  - {joint: R, alpha: -pi/2, a: a_3, d: d_4, theta: theta_4}
  - {joint: R, alpha: pi/2,  a: 0,   d: 0,   theta: theta_5}
  - {joint: R, alpha: -pi/2, a: 0,   d: 0,   theta: theta_6}
sample: {a_2: 0.4318, a_3: 0.0203, d_3: 0.1245, d_4: 0.4318}
"""
STANFORD = """\
name: Stanford arm
convention: standard
joints:
  - {joint: R, alpha: -pi/2, a: 0, d: 0,   theta: theta_1}
  - {joint: R, alpha: pi/2,  a: 0, d: d_2, theta: theta_2}
  - {joint: P, alpha: 0,     a: 0, d: d_3, theta: 0}
  - {joint: R, alpha: -pi/2, a: 0, d: 0,   theta: theta_4}
  - {joint: R, alpha: pi/2,  a: 0, d: 0,   theta: theta_5}
  - {joint: R, alpha: 0,     a: 0, d: d_6, theta: theta_6}
sample: {d_2: 0.15, d_6: 0.1}
"""
ARMS = {"puma-like": PUMA_LIKE, "stanford": STANFORD}
BASES = ["[]", "[{Tz: h}]", "[{Rz: pi/2}, {Tx: 1/4}]"]
TOOLS = ["[]", "[{Tz: l_t}]", "[{Rx: pi}, {Tz: 1/10}]"]
# Numbers as printed: ASCII digits, superscript digits (³J), subscript digits (A₆).
SUPERSCRIPTS, SUBSCRIPTS = "⁰¹²³⁴⁵⁶⁷⁸⁹", "₀₁₂₃₄₅₆₇₈₉"
NUMBER = re.compile(f"[0-9]+|[{SUPERSCRIPTS}]+|[{SUBSCRIPTS}]+")


def robot_text(arm: str, base: str, tool: str, first_frame: int, twist_of_row: int | None = None) -> str:
    """The arm's robot file; `twist_of_row` (1..6) gets a wrong twist, for `check` to explain."""
    text = ARMS[arm] + f"base: {base}\ntool: {tool}\nfirst_frame: {first_frame}\n"
    if twist_of_row is not None:
        rows = text.split("  - {")
        rows[twist_of_row] = re.sub(r"alpha: [^,]+,", "alpha: pi/3,", rows[twist_of_row])
        text = "  - {".join(rows)
    return text


def numbers_and_text(output: str) -> tuple[list[int], str]:
    """The numbers printed (each read as an int), and the text around them, spaces collapsed (a
    two-digit label may widen a column)."""
    def value(token: str) -> int:
        return int(token.translate(str.maketrans(SUPERSCRIPTS + SUBSCRIPTS, "0123456789" * 2)))

    return [value(t) for t in NUMBER.findall(output)], re.sub(r"\s+", " ", NUMBER.sub("#", output))


def assert_same_up_to_numbering(plain: str, renumbered: str, k: int, what: str = "", labelled: bool = True):
    numbers, text = numbers_and_text(plain)
    shifted_numbers, shifted_text = numbers_and_text(renumbered)
    assert shifted_text == text, what
    moved = [(a, b) for a, b in zip(numbers, shifted_numbers, strict=True) if a != b]
    assert all(b == a + k for a, b in moved), (what, moved)
    assert moved or k == 0 or not labelled, f"{what}: no frame or joint label moved"


def outputs(tmp_path, arm: str, base: str, tool: str, first_frame: int, wrong_row: int) -> dict[str, str]:
    """What the command line prints for the arm numbered from `first_frame`."""
    robot = tmp_path / f"arm{first_frame}.yaml"
    robot.write_text(robot_text(arm, base, tool, first_frame), encoding="utf-8")
    wrong = tmp_path / f"wrong{first_frame}.yaml"
    wrong.write_text(robot_text(arm, base, tool, first_frame, wrong_row), encoding="utf-8")
    commands = {"jacobian": ["jacobian", robot], "jacobian json": ["jacobian", robot, "--format", "json"],
                "screws": ["screws", robot], "fk latex": ["fk", robot, "--format", "latex"],
                "links latex": ["links", robot, "--format", "latex"], "check": ["check", wrong, "--against", robot]}
    printed = {}
    for name, args in commands.items():
        result = run_dhsym(*map(str, args), cwd=tmp_path)
        assert result.status == (1 if name == "check" else 0), result.stderr
        printed[name] = result.stdout.replace(str(tmp_path), "DIR").replace(f"arm{first_frame}", "ARM") \
            .replace(f"wrong{first_frame}", "WRONG")
    return printed


@pytest.mark.slow  # a dozen commands on two six-joint arms per example
@settings(max_examples=8, phases=[Phase.explicit, Phase.reuse, Phase.generate])  # no shrinking: seconds each
@given(st.sampled_from(sorted(ARMS)), st.sampled_from(BASES), st.sampled_from(TOOLS), st.integers(1, 5),
       st.integers(1, 6))
def test_first_frame_renames_the_printed_frames_and_joints_only(tmp_path_factory, arm, base, tool, k, wrong_row):
    tmp_path = tmp_path_factory.mktemp("first_frame")
    plain, renumbered = (outputs(tmp_path, arm, base, tool, f, wrong_row) for f in (0, k))
    for name in plain:
        # the screws and the links always name joints; the rest may name only base and tool, or no frame
        assert_same_up_to_numbering(plain[name], renumbered[name], k, name, labelled=name in ("screws", "links latex"))
    assert json.loads(renumbered["jacobian json"])  # it reads back


def _printed(frame, k: int):
    return frame + k if isinstance(frame, int) else frame


@pytest.mark.parametrize(("arm", "base", "tool", "k"), [("puma-like", BASES[2], TOOLS[1], 5),
                                                        ("stanford", BASES[1], TOOLS[2], 2)])
def test_the_notebook_robot_gives_the_same_math_in_printed_numbers(tmp_path, arm, base, tool, k):
    """robot.jacobian(frame, point), det J, its singularities and the screws: the same matrices, with
    the frames named as printed; a singularity names the joints as printed."""
    plain, renumbered = (dhsym.load(_written(tmp_path, robot_text(arm, base, tool, f), f)) for f in (0, k))
    assert renumbered.frames == [_printed(f, k) for f in plain.frames]
    for frame, point in [(None, None), (2, 5), ("base", "tool"), (6, 3)]:
        if frame not in plain.frames or point not in plain.frames:
            continue
        assert renumbered.jacobian(_printed(frame, k), _printed(point, k)) == plain.jacobian(frame, point)
    det, shifted_det = plain.determinant(), renumbered.determinant()
    assert sympy.simplify(shifted_det.value - det.value) == 0
    meanings = [s.meaning for s in plain.singularities(det)]
    for meaning, shifted in zip(meanings, [s.meaning for s in renumbered.singularities(shifted_det)], strict=True):
        assert_same_up_to_numbering(meaning, shifted, k)
    assert dhsym.screws(renumbered).matrix == dhsym.screws(plain).matrix


def _written(tmp_path, text: str, first_frame: int):
    path = tmp_path / f"arm{first_frame}.yaml"
    path.write_text(text, encoding="utf-8")
    return path
