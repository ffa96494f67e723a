"""The Robot record: one frame numbering on every surface and in the API, and every field kept
by every reader and transformation (issue 17)."""
from __future__ import annotations

import json

import pytest
import sympy
from cli_runner import run_dhsym
from hypothesis import HealthCheck, given, settings
from readers import load_robot_text
from strategies import robots

import dhsym
from dhsym import Robot
from dhsym.api.robot import notebook_robot
from dhsym.errors import UserError
from dhsym.geometry.convert import convert_robot
from dhsym.io.robotwriter import robot_yaml
from dhsym.velocity.jacobian import jacobian

# A wrist numbered 3..6 with a base and a tool: both kinds of renumbering at once.
MOUNTED_WRIST = """\
name: mounted wrist
source: a test
convention: standard
first_frame: 3
base: [{Tz: 0.5}]
tool: [{Tz: 0.1}]
joints:
  - {joint: R, alpha: -pi/2, a: 0, d: 0,   theta: theta_4}
  - {joint: R, alpha: pi/2,  a: 0, d: 0,   theta: theta_5}
  - {joint: R, alpha: 0,     a: 0, d: d_6, theta: theta_6}
sample: {d_6: 0.25}
notes: mounted on a stand
"""


def run(capsys, *argv) -> tuple[int, str, str]:
    return tuple(run_dhsym(*argv))


@pytest.fixture
def mounted(tmp_path):
    path = tmp_path / "mounted.yaml"
    path.write_text(MOUNTED_WRIST, encoding="utf-8")
    return str(path)


# ---------------------------------------------------------------- the Python API

def test_a_wrist_takes_and_gives_its_printed_frame_numbers():
    wrist = dhsym.load("spherical_wrist")
    assert wrist.frames == [3, 4, 5, 6] and wrist.joints == [4, 5, 6]
    assert wrist.transform(3, 6) == wrist.fk() == wrist.chain.transform(0, 3)
    assert wrist.transform("4", 6) == wrist.transform(4, 6) == wrist.chain.transform(1, 3)  # int and str agree
    assert wrist.link(5) == wrist.chain.link(2) and len(wrist.links()) == 3
    assert wrist.jacobian(frame=3) == jacobian(wrist.chain, frame=0)
    with pytest.raises(UserError, match="^no frame 0 in this robot; frames are 3, 4, 5, 6$"):
        wrist.transform(0, 3)
    with pytest.raises(UserError, match="^no joint 1 in this robot; joints are 4..6$"):
        wrist.link(1)


def test_load_keeps_the_readers_warnings():
    robot = load_robot_text("convention: standard\njoints:\n  - {joint: R, alpha: 90, a: 0, d: 0, theta: q}\n",
                            "w.yaml")
    assert robot.warnings and "90 is taken as radians" in robot.warnings[0]


def test_a_robot_is_immutable_and_copies_keep_every_field():
    wrist = dhsym.load("spherical_wrist")
    with pytest.raises(AttributeError):
        wrist.name = "other"
    with pytest.raises(TypeError):
        wrist.sample[sympy.Symbol("d_6", real=True)] = 1
    renumbered = wrist.replace(frame_offset=0)
    assert renumbered.frames == [0, 1, 2, 3] and renumbered.name == wrist.name and wrist.frames[0] == 3


def test_a_plain_chain_has_no_file_details():
    chain = dhsym.load("planar2r").chain
    assert repr(chain) == "Chain(standard DH, 2 joints: RR)"
    assert not hasattr(chain, "name") and not hasattr(chain, "sample") and not hasattr(chain, "frame_offset")


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(robots())
def test_fk_of_a_robot_is_its_chain_s_with_frames_renumbered(robot):
    chain, offset = robot.chain, robot.frame_offset
    assert robot.fk() == chain.fk()
    numbers = [f for f in robot.frames if isinstance(f, int)]
    assert numbers == list(range(offset, offset + robot.n + 1))
    first, last = numbers[0], numbers[-1]
    assert robot.transform(first, last) == chain.transform(0, chain.n)
    assert robot.transform(str(last), first) == chain.transform(chain.n, 0)
    assert robot.link(offset + 1) == chain.link(1)


# ---------------------------------------------------------------- read, convert, write, read

@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(robots())
def test_read_convert_write_read_keeps_every_field(robot):
    read = load_robot_text(robot_yaml(robot), "drawn.yaml")  # the robot as a file gives it
    other = "modified" if read.convention == "standard" else "standard"
    converted = notebook_robot(convert_robot(read, other))
    assert converted.file == read.file == "drawn.yaml" and converted.warnings == read.warnings
    again = load_robot_text(robot_yaml(converted), "again.yaml")
    for field in ("name", "source", "notes", "sample", "frame_offset", "numbers", "joint_variables"):
        assert getattr(again, field) == getattr(converted, field) == getattr(read, field), field
    values = {s: sympy.Rational(k + 2, 7) for k, s in enumerate(sorted(read.symbols, key=str))}
    assert (again.fk() - read.fk()).xreplace(values).applyfunc(sympy.nsimplify) == sympy.zeros(4, 4)


def test_convert_on_the_command_line_keeps_first_frame_and_sample(capsys, mounted):
    status, out, _ = run(capsys, "convert", mounted, "--to", "modified")
    assert status == 0 and "first_frame: 3\n" in out and "sample: {d_6: 0.25}" in out
    assert "notes: \"mounted on a stand\"" in out and "name: \"mounted wrist\"" in out


# ---------------------------------------------------------------- every surface numbers frames as fk does

def test_table_numbers_rows_as_the_joints(capsys):
    _, out, _ = run(capsys, "table", "spherical_wrist")
    assert [line.split()[0] for line in out.splitlines()[-3:]] == ["4", "5", "6"]
    _, out, _ = run(capsys, "table", "spherical_wrist", "--format", "latex")
    assert "4 & \\theta_{4}^{*}" in out and "\n1 & " not in out
    _, out, _ = run(capsys, "table", "spherical_wrist", "--format", "json")
    assert [row["number"] for row in json.loads(out)["rows"]] == [4, 5, 6]


def test_jacobian_names_frames_as_printed(capsys):
    status, out, _ = run(capsys, "jacobian", "spherical_wrist", "--frame", "3")
    assert status == 0 and out.startswith("Spherical wrist (3-DoF, roll-pitch-roll): Jacobian ³J of the origin of "
                                          "frame 6, in frame 3")
    status, out, _ = run(capsys, "jacobian", "spherical_wrist", "--frame", "4", "--point", "5", "--format", "json")
    assert status == 0 and (json.loads(out)["frame"], json.loads(out)["point"]) == (4, 5)
    status, _, err = run(capsys, "jacobian", "spherical_wrist", "--frame", "0")
    assert status == 2 and "no frame 0 in this robot; frames are 3, 4, 5, 6" in err
    status, out, _ = run(capsys, "jacobian", "spherical_wrist", "--steps")
    assert status == 0 and "³ω₃" in out and "⁶ω₆" in out and "⁰ω₀" not in out


def test_screws_and_latex_name_frames_as_printed(capsys):
    _, out, _ = run(capsys, "screws", "spherical_wrist")
    assert "screw axes in frame 3" in out and "S4 (θ4)" in out and "S1 " not in out
    _, out, _ = run(capsys, "screws", "spherical_wrist", "--format", "json")
    assert json.loads(out)["frame"] == "3"
    _, out, _ = run(capsys, "latex", "spherical_wrist", "--document", "snippet", "--from", "4", "--to", "6")
    assert "{}^{4}T_{6}" in out and "{}^{1}T" not in out
    status, _, err = run(capsys, "latex", "spherical_wrist", "--document", "snippet", "--from", "0")
    assert status == 2 and "--from: no frame 0" in err


def test_a_robot_with_base_and_tool_numbers_the_frames_between(capsys, mounted):
    robot = dhsym.load(mounted)
    assert robot.frames == ["base", 3, 4, 5, 6, "tool"]
    _, out, _ = run(capsys, "fk", mounted, "--from", "3", "--to", "tool")
    assert "T(3 → tool)" in out
    _, out, _ = run(capsys, "fk", mounted, "--from", "base", "--to", "4", "--format", "json")
    assert (json.loads(out)["from"], json.loads(out)["to"]) == ("base", 4)
    _, out, _ = run(capsys, "jacobian", mounted)
    assert "of the origin of the tool frame, in frame base" in out
    _, out, _ = run(capsys, "screws", mounted)
    assert "screw axes in frame base" in out and "S6 (θ6)" in out
    _, out, _ = run(capsys, "table", mounted)
    assert [line.split()[0] for line in out.splitlines()[-3:]] == ["4", "5", "6"]


@pytest.mark.slow
def test_check_and_too_large_advice_use_the_printed_numbers(capsys, tmp_path):
    rows = "\n".join(f"  - {{joint: R, alpha: alpha_{k}, a: a_{k}, d: d_{k}, theta: theta_{k}}}" for k in range(4, 14))
    path = tmp_path / "long.yaml"
    path.write_text(f"convention: standard\nfirst_frame: 3\njoints:\n{rows}\n", encoding="utf-8")
    status, _, err = run(capsys, "fk", str(path))
    assert status == 2 and "--from 3 --to " in err and "³T₁₃" not in err
    advised = err.split("--from 3 --to ")[1].split(" ")[0]
    status, _, _ = run(capsys, "fk", str(path), "--from", "3", "--to", advised)
    assert status == 0  # the advice is accepted
    assert Robot(dhsym.load("planar2r").chain, frame_offset=3).frames == [3, 4, 5]
    status, out, _ = run(capsys, "check", "spherical_wrist", "--against", "spherical_wrist")
    assert status == 0


def test_check_names_joints_and_rows_as_the_table_numbers_them(capsys, tmp_path):
    text = load_wrist_text().replace("alpha: -pi/2, a: 0, d: 0,   theta: theta_4",
                                     "alpha: 0, a: 0, d: 0,   theta: theta_4")
    path = tmp_path / "homework.yaml"
    path.write_text(text, encoding="utf-8")
    status, out, _ = run(capsys, "check", str(path), "--against", "spherical_wrist")
    assert status == 1 and "joint 5's axis points along" in out and "check the twist α in row 4" in out


def test_ik_plot_and_pictures_use_the_printed_numbers(capsys):
    from matplotlib.figure import Figure

    _, out, _ = run(capsys, "ik", "spherical_wrist")
    assert "Target ³T₆" in out and "the axes of joints 4, 5 and 6 meet in a point" in out
    labels = {text.get_text() for text in dhsym.plot.draw(dhsym.load("spherical_wrist"), ax=Figure()).texts}
    assert any("3" in label for label in labels) and not any("0" in label for label in labels)


def load_wrist_text() -> str:
    from dhsym.io.library import ROBOTS_DIR

    return (ROBOTS_DIR / "spherical_wrist.yaml").read_text(encoding="utf-8")


def test_a_transform_too_large_is_refused_with_the_printed_numbers():
    from dhsym.core.chain import Chain, DHRow

    symbols = [sympy.symbols(f"theta_{k} d_{k} a_{k} alpha_{k}", real=True) for k in range(4, 16)]
    robot = Robot(Chain([DHRow.revolute(t, d, a, al) for t, d, a, al in symbols], "standard"), frame_offset=3)
    with pytest.raises(UserError, match=r"^3T15 would have about [\d,]+ expression nodes"):
        robot.fk()
    with pytest.raises(UserError, match=r"^15T3 would have about"):
        robot.transform(15, 3)


def test_velocity_methods_take_and_give_printed_numbers():
    wrist = dhsym.load("spherical_wrist")
    result = wrist.determinant(frame=4)
    assert [s.meaning for s in wrist.singularities(result)] == ["axes 4 and 6 line up"]
    assert [step.frame for step in wrist.propagate()] == [3, 4, 5, 6]
    assert wrist.jacobian(4, 6) == dhsym.velocity.jacobian(wrist.chain, 1, 3)


def test_the_layers_below_take_a_plain_chain_and_refuse_a_robot():
    """Inside dhsym one numbering counts: frames 0..n of a plain chain. A robot handed to a function
    that expects one is a TypeError at once, never a silent renumbering."""
    from dhsym.geometry.screws import screw_axes
    from dhsym.velocity import determinant, jacobian, propagate, singularities

    wrist = dhsym.load("spherical_wrist")
    calls = [lambda: jacobian(wrist), lambda: determinant(wrist), lambda: propagate(wrist),
             lambda: singularities(wrist, wrist.determinant()), lambda: screw_axes(wrist)]
    for call in calls:
        with pytest.raises(TypeError, match=r"^a plain Chain \(frames 0..n\) is needed here, not Robot"):
            call()
    assert [step.frame for step in propagate(wrist.chain)] == [0, 1, 2, 3]
