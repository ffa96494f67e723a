"""`dhsym import` and the `axes:` form: URDF in, a robot file out that dhsym reads back and that
has the URDF's kinematics; errors are one line with exit status 2 and no output file."""
import os
import re
from pathlib import Path

import numpy as np
import pytest
import sympy
from cli_runner import run_dhsym
from readers import load_robot_file

from dhsym import load
from dhsym.errors import UserError
from dhsym.io.urdf import MAX_URDF_BYTES
from tests.urdf_builder import serial_urdf, urdf_fk

DATA = Path(__file__).parent / "data"


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_an_imported_panda_reads_back_with_the_urdf_kinematics(convention, tmp_path):
    out_file = tmp_path / "panda.yaml"
    status, out, err = run_dhsym("import", DATA / "panda.urdf", "--convention", convention, "-o", out_file)
    assert (status, out) == (0, "")
    assert err == ""  # the URDF's 1.5707963267948966 is π/2 as closely as a double says it: read so without a word
    chain = load_robot_file(out_file)
    assert chain.convention == convention and chain.joint_variables == list(sympy.symbols("q_1:8", real=True))
    assert chain.source == "panda.urdf, links panda_link0 → panda_link8"
    q = [0.3, -0.7, 1.1, -2.0, 0.4, 1.9, -0.6]
    numeric = chain.fk(raw=True).xreplace(dict(zip(chain.joint_variables, q))).evalf()
    urdf_text = (DATA / "panda.urdf").read_text().replace("1.5707963267948966", repr(float(np.pi / 2)))
    assert np.allclose(np.array(numeric, dtype=float), urdf_fk(urdf_text, q, "panda_link0", "panda_link8"), atol=1e-9)


def test_joint_names_become_variables_when_asked():
    status, out, _ = run_dhsym("import", DATA / "ur5.urdf", "--tip", "tool0", "--variables", "urdf")
    assert status == 0 and "theta: shoulder_pan_joint" in out and "theta: wrist_3_joint" in out


def test_several_leaves_are_listed():
    status, out, err = run_dhsym("import", DATA / "ur5.urdf")
    assert (status, out) == (2, "")
    assert err == "dhsym: error: the URDF has 2 leaf links below 'world' (tool0, ee_link); choose one with --tip\n"


def test_a_tip_that_is_not_below_the_base_is_refused():
    status, _, err = run_dhsym("import", DATA / "ur5.urdf", "--base", "forearm_link", "--tip", "shoulder_link")
    assert status == 2 and "'shoulder_link' is not below link 'forearm_link'" in err


def test_a_file_over_2_mib_is_refused_without_reading_it_all(tmp_path):
    huge = tmp_path / "huge.urdf"
    huge.write_bytes(b"<robot name='x'>" + b" " * (3 << 20) + b"</robot>")
    assert MAX_URDF_BYTES < huge.stat().st_size
    status, out, err = run_dhsym("import", huge)
    assert (status, out) == (2, "")
    assert err == f"dhsym: error: {huge}:1:1: file is larger than 2 MiB, the limit for URDF files\n"


def test_an_error_leaves_no_output_file(tmp_path):
    target = tmp_path / "out.yaml"
    target.write_text("old")
    status, _, _ = run_dhsym("import", Path(__file__).parent / "bad_inputs" / "urdf_zero_axis.urdf", "-o", target)
    assert status == 2 and target.read_text() == "old" and os.listdir(tmp_path) == ["out.yaml"]


AXES_ARM = """name: SCARA from its axes
convention: standard
axes:
  - {joint: R, point: [0, 0, 0], direction: [0, 0, 1]}
  - {joint: R, point: [a_1, 0, 0], direction: [0, 0, 1]}
  - {joint: P, point: [a_1 + a_2, 0, 0], direction: [0, 0, -1], var: d_3}
  - {joint: R, point: [a_1 + a_2, 0, 0], direction: [0, 0, -1]}
tool: [{Tx: a_1 + a_2}, {Tz: -d_4}, {Rx: pi}]
sample: {a_1: 0.4, a_2: 0.3, d_4: 0.1}
"""


def test_the_axes_form_gives_a_table_that_the_commands_use(tmp_path):
    path = tmp_path / "scara.yaml"
    path.write_text(AXES_ARM)
    status, out, _ = run_dhsym("table", path)
    assert status == 0 and "d3*" in out and "π" in out
    chain = load_robot_file(path)
    assert chain.sample and [row.joint for row in chain.rows] == list("RRPR")
    reference = load("scara_spong")  # the same arm, tabled by hand after Spong
    status, out, _ = run_dhsym("check", path, "--against", "scara_spong")
    assert status == 0, out
    assert reference.n == chain.n


def test_import_turns_an_axes_file_into_a_dh_robot_file(tmp_path):
    path = tmp_path / "scara.yaml"
    path.write_text(AXES_ARM)
    status, out, _ = run_dhsym("import", path)
    assert status == 0 and "axes:" not in out and "joints:" in out
    written = tmp_path / "dh.yaml"
    written.write_text(out)
    assert run_dhsym("check", written, "--against", path)[0] == 0


def test_screws_prints_every_joint_and_the_home_pose():
    status, out, _ = run_dhsym("screws", "scara_spong")
    assert status == 0
    assert "S3 (d3) = (0, 0, 0; 0, 0, −1)" in out and "M =" in out


def test_screws_as_json_and_latex():
    import json

    status, out, _ = run_dhsym("screws", "planar2r", "--format", "json")
    data = json.loads(out)
    assert status == 0 and data["screws"]["theta_2"] == ["0", "0", "1", "0", "-a_1", "0"]
    assert data["home"][0] == ["1", "0", "0", "a_1 + a_2"]
    status, out, _ = run_dhsym("screws", "planar2r", "--format", "latex")
    assert status == 0 and out.startswith("\\[\nS = \\begin{bmatrix}") and "M = \\begin{bmatrix}" in out


def test_screws_keep_the_decimals_as_written_in_every_format(tmp_path):
    import json

    path = tmp_path / "decimals.yaml"
    path.write_text("name: decimals\nconvention: standard\njoints:\n"
                    "  - {joint: R, alpha: pi/2, a: 0, d: 0.089159, theta: theta_1}\n"
                    "  - {joint: R, alpha: 0, a: -0.425, d: 0, theta: theta_2}\n")
    data = json.loads(run_dhsym("screws", path, "--format", "json")[1])
    assert data["screws"]["theta_2"] == ["0", "-1", "0", "0.089159", "0", "0"]
    assert data["home"][0][3] == "-0.425"
    latex = run_dhsym("screws", path, "--format", "latex")[1]
    assert "0.089159" in latex and "frac{89159}" not in latex
    assert "0.089159" in run_dhsym("screws", path)[1]


# --- Issue 15: real robots' files import as they come.

TWO_JOINTS = """<?xml version="1.0"?>
<robot name="arm"{namespace}>
  <link name="base"/><link name="upper"/><link name="tip"/>
  <joint name="{first}" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1" rpy="{rpy}"/><axis xyz="0 0 1"/></joint>
  <joint name="{second}" type="revolute"><parent link="upper"/><child link="tip"/>
    <origin xyz="0.3 0 0"/><axis xyz="0 0 1"/></joint>
</robot>
"""


def two_joints(tmp_path, name="arm.urdf", namespace="", first="shoulder", second="elbow", rpy="0 0 0"):
    path = tmp_path / name
    path.write_text(TWO_JOINTS.format(namespace=namespace, first=first, second=second, rpy=rpy))
    return path


def test_a_file_written_by_xacro_imports_without_a_word(tmp_path):
    path = two_joints(tmp_path, namespace=' xmlns:xacro="http://www.ros.org/wiki/xacro"')
    assert run_dhsym("import", path)[::2] == (0, "")


def test_a_default_namespace_is_read_as_none_as_ros_reads_it(tmp_path):
    plain = run_dhsym("import", two_joints(tmp_path))
    declared = run_dhsym("import", two_joints(tmp_path, name="ns.urdf", namespace=' xmlns="http://www.ros.org"'))
    assert declared[0] == 0 and declared[1].replace("ns.urdf", "arm.urdf") == plain[1]


def test_the_python_api_does_what_the_command_does(tmp_path):
    from dhsym import import_urdf

    imported = import_urdf(DATA / "ur5.urdf", tip="tool0", convention="modified", variables="urdf")
    assert imported.joint_names[0] == "shoulder_pan_joint" and imported.robot.convention == "modified"
    assert imported.robot.joint_variables[0] == sympy.Symbol("shoulder_pan_joint", real=True)
    status, out, _ = run_dhsym("import", DATA / "ur5.urdf", "--tip", "tool0", "--convention", "modified",
                               "--variables", "urdf")
    written = tmp_path / "ur5.yaml"
    written.write_text(out)
    assert status == 0 and load_robot_file(written).rows == imported.robot.rows


def test_a_named_pipe_is_refused_at_once(tmp_path):
    pipe = tmp_path / "arm.urdf"
    os.mkfifo(pipe)  # opening it would wait for a writer that never comes
    status, out, err = run_dhsym("import", pipe)
    assert (status, out) == (2, "")
    assert err == f"dhsym: error: {pipe}: is not a regular file (a pipe, socket or device); give a file\n"


def test_a_utf16_file_reads_like_utf8(tmp_path):
    plain = two_joints(tmp_path)
    wide = tmp_path / "wide.urdf"
    wide.write_bytes(plain.read_text().replace('version="1.0"', 'version="1.0" encoding="UTF-16"').encode("utf-16"))
    assert run_dhsym("import", wide)[1] == run_dhsym("import", plain)[1].replace("arm.urdf", "wide.urdf")


def test_joint_names_print_as_written_in_text_latex_and_json(tmp_path):
    import json

    path = two_joints(tmp_path, first="right_s0", second="right_s1")
    out_file = tmp_path / "baxter.yaml"
    assert run_dhsym("import", path, "--variables", "urdf", "-o", out_file)[0] == 0
    text = run_dhsym("fk", out_file)[1]
    assert "cs0 = cos right_s0" in text and "rights0" not in text
    latex = run_dhsym("fk", out_file, "--format", "latex")[1]
    assert r"c_{s0} &= \cos{\mathrm{right\_s0}}" in latex
    data = json.loads(run_dhsym("fk", out_file, "--format", "json")[1])
    assert data["joint_variables"] == ["right_s0", "right_s1"]


def test_a_joint_named_like_a_fallback_variable_keeps_every_variable_distinct(tmp_path):
    path = two_joints(tmp_path, first="q_2", second="sin")
    status, out, err = run_dhsym("import", path, "--variables", "urdf")
    assert (status, err) == (0, "")
    assert "theta: q_2" in out and "theta: q_2_2" in out


def test_too_many_joints_are_refused_with_a_tip_that_the_command_accepts(tmp_path):
    joints = [("revolute", "0 0 0.1", "0 0 0", "0 0 1")] * 30
    path = tmp_path / "snake.urdf"
    path.write_text(serial_urdf(joints))
    status, out, err = run_dhsym("import", path)
    assert (status, out) == (2, "")
    assert err == ("dhsym: error: the path link0 → link30 has 30 movable joints, more than the 24 a DH table of "
                   "dhsym holds; choose a nearer tip (--tip link24) or a later base (--base)\n")
    assert run_dhsym("import", path, "--tip", "link24")[0] == 0


def test_thousands_of_fixed_joints_are_refused_from_a_count(tmp_path):
    joints = [("revolute", "0.1 0 0", "0 0 0", "0 0 1")] + [("fixed", "0.01 0 0", "0.1 0.2 0.3", None)] * 3000
    path = tmp_path / "long.urdf"
    path.write_text(serial_urdf(joints))
    status, _, err = run_dhsym("import", path)
    assert status == 2 and "has 3001 joints, more than the 200" in err and "--tip link200" in err


def test_a_mimic_joint_on_the_path_is_refused_and_says_why():
    status, _, err = run_dhsym("import", Path(__file__).parent / "bad_inputs" / "urdf_mimic.urdf")
    assert status == 2 and "mimics joint 'left_finger'" in err and "--tip" in err


def test_an_expanded_xacro_arm_has_the_kinematics_of_its_urdf():
    pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")
    from dhsym import import_urdf
    from dhsym.io.xacro import expand_xacro

    path = Path(__file__).parent / "bad_inputs" / "xacro_good_arm.xacro"
    imported = import_urdf(path)
    assert imported.joint_names == ["left_shoulder", "left_elbow", "left_wrist"]
    q = [0.4, -1.1, 0.7]
    numeric = imported.robot.fk(raw=True).xreplace(dict(zip(imported.robot.joint_variables, q))).evalf()
    expected = urdf_fk(expand_xacro(path).decode(), q, "left_base", "left_tip")
    assert np.allclose(np.array(numeric, dtype=float), expected, atol=1e-12)


def test_without_the_xacro_package_a_xacro_file_gets_advice(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "xacro", None)
    status, _, err = run_dhsym("import", Path(__file__).parent / "bad_inputs" / "xacro_good_arm.xacro")
    assert status == 2 and "needs the xacro package (pip install 'dhsym[xacro]')" in err


@pytest.mark.parametrize("encoding, declared", [("utf-16-be", ""), ("utf-16-le", ""), ("utf-8-sig", ""),
                                                ("latin-1", ' encoding="ISO-8859-1"')])
def test_every_xml_encoding_is_decoded_before_it_is_checked(encoding, declared):
    from dhsym.io.xmlsource import parse_xml_text

    text = f'<?xml version="1.0"{declared}?>\n<robot name="bras">\n  <link name="é"/></robot>'
    source = parse_xml_text(text.encode(encoding), "x.urdf")
    assert source.root[0].get("name") == "é" and str(source.place(source.root[0], "name")) == "x.urdf:3:15"
    doctype = text.replace("\n<robot", '\n<!DOCTYPE robot [<!ENTITY a "aa">]>\n<robot')
    with pytest.raises(UserError, match=r"x\.urdf:2:1: DOCTYPE and entity declarations are not allowed"):
        parse_xml_text(doctype.encode(encoding), "x.urdf")


# --- ROS 1 xacro files: tags without the xacro: prefix (ROS-Industrial's KUKA KR210, say).

ROS1_ARM = """<?xml version="1.0"?>
<robot name="old_arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <property name="upper" value="0.425"/>
  <include filename="old_segment.xacro"/>
  <arg name="side" default="left_"/>
  <link name="$(arg side)base"/>
  <if value="${upper > 0}">
    <segment name="shoulder" parent="$(arg side)base" child="$(arg side)upper" z="0.1"/>
  </if>
  <unless value="${upper > 0}"><link name="never"/></unless>
  <xacro:segment name="elbow" parent="$(arg side)upper" child="$(arg side)tip" z="${upper}"/>
  <gazebo><include><uri>model://camera</uri></include><element name="kept"/></gazebo>
</robot>
"""
ROS1_SEGMENT = """<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <!-- a comment with <property name="not_a_tag"/> in it -->
  <macro name="segment" params="name parent child z">
    <link name="${child}"/>
    <joint name="${name}" type="revolute"><parent link="${parent}"/><child link="${child}"/>
      <origin xyz="0 0 ${z}"/><axis xyz="0 0 1"/></joint>
  </macro>
</robot>
"""


def ros1_arm(tmp_path, arm=ROS1_ARM, segment=ROS1_SEGMENT):
    (tmp_path / "old_segment.xacro").write_text(segment)
    path = tmp_path / "old_arm.xacro"
    path.write_text(arm)
    return path


def prefixed(text):
    """The same file as ROS 2's xacro wants it: every tag ROS 1 took without the prefix, prefixed."""
    text = re.sub(r"<(/?)(property|include(?= filename)|arg|if|unless|macro|segment)\b", r"<\1xacro:\2", text)
    return text.replace("<!-- a comment with <xacro:property", "<!-- a comment with <property")


def test_ros1_tags_without_the_prefix_are_xacro_tags_with_one_warning_per_file(tmp_path):
    pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")
    path = ros1_arm(tmp_path)
    status, out, err = run_dhsym("import", path)
    assert status == 0 and "source: \"old_arm.xacro, links left_base → left_tip\"" in out
    assert err.splitlines() == [
        f"dhsym: warning: {path}:3:3: <property>, <include>, <arg>, <if>, <segment>, <unless> without the xacro: "
        "prefix are read as xacro tags, as ROS 1's xacro read them (deprecated there; ROS 2's xacro leaves them "
        "as plain XML)",
        f"dhsym: warning: {tmp_path / 'old_segment.xacro'}:3:3: <macro> without the xacro: prefix is read as a "
        "xacro tag, as ROS 1's xacro read it (deprecated there; ROS 2's xacro leaves it as plain XML)"]
    modern = tmp_path / "modern"
    modern.mkdir()
    same = ros1_arm(modern, prefixed(ROS1_ARM), prefixed(ROS1_SEGMENT))
    assert "<property" not in same.read_text() and "<macro" not in (modern / "old_segment.xacro").read_text()
    status, modern_out, modern_err = run_dhsym("import", same)
    assert (status, modern_err) == (0, "") and modern_out == out


def test_what_ros1_did_not_take_for_xacro_stays_plain_xml(tmp_path):
    pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")
    from dhsym.io.xacro import expand_xacro

    warnings = []
    text = expand_xacro(ros1_arm(tmp_path), warnings).decode()
    assert "<include>" in text and "<uri>model://camera</uri>" in text  # Gazebo's include holds an element
    assert '<element name="kept"/>' in text  # only xacro:element makes elements
    assert "never" not in text and "<property" not in text and "<macro" not in text and "<segment" not in text
    assert len(warnings) == 2


def _expanded(tmp_path, name: str, text: str, warnings: list | None = None) -> tuple:
    """(path, the URDF that dhsym's xacro makes of `text` written to tmp_path/name)."""
    pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")
    from dhsym.io.xacro import expand_xacro

    path = tmp_path / name
    path.write_text(text)
    return path, expand_xacro(path, warnings).decode()


def test_a_ros2_file_keeps_a_plain_element_named_like_its_macro(tmp_path):
    warnings = []
    _, text = _expanded(tmp_path, "modern.xacro", '<robot name="m" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                        '  <xacro:macro name="inertial" params="m"><mass value="${m}"/></xacro:macro>\n'
                        '  <link name="a"><inertial><mass value="2"/></inertial></link>\n'
                        '  <link name="b"><xacro:inertial m="3"/></link></robot>', warnings)
    assert warnings == [] and "<inertial>" in text and '<mass value="2"/>' in text and '<mass value="3"/>' in text


def test_an_unprefixed_include_keeps_every_guard(tmp_path):
    pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")
    path = ros1_arm(tmp_path, ROS1_ARM.replace('"old_segment.xacro"', '"/etc/passwd"'))
    status, out, err = run_dhsym("import", path)
    assert (status, out) == (2, "")
    assert err == f"dhsym: error: {path}:4:22: xacro:include of /etc/passwd: only .xacro, .urdf and .xml files " \
                  "are included\n"


def test_a_property_named_pi_hides_pi_as_in_xacro(tmp_path):
    _, text = _expanded(tmp_path, "rough.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                        '  <xacro:property name="pi" value="3.141592654"/>\n'
                        '  <link name="a" rpy="${-pi/2} ${e}"/></robot>')
    assert 'rpy="-1.570796327 2.718281828459045"' in text


def test_an_unprefixed_insert_block_inserts_the_block(tmp_path):
    warnings = []
    path, text = _expanded(tmp_path, "block.xacro", '<robot name="b">\n  <macro name="hinge" params="*origin">\n'
                           '    <joint name="j" type="revolute"><insert_block name="origin"/></joint></macro>\n'
                           '  <hinge><origin xyz="0 0 0.7"/></hinge></robot>', warnings)
    assert '<joint name="j" type="revolute">\n    <origin xyz="0 0 0.7"/>' in text and "insert_block" not in text
    assert [w.split(" without")[0] for w in warnings] == [f"{path}:2:3: <macro>, <insert_block>, <hinge>"]
