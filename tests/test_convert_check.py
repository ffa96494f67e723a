"""`dhsym convert` and `dhsym check`: every built-in robot converts and back, and check agrees;
check explains a wrong twist, a shifted zero, a moved axis, a different tool or base."""
import pytest
from readers import load_robot_file, load_robot_text

from dhsym import load
from dhsym.cli import app as cli
from dhsym.geometry.compare import compare
from dhsym.geometry.convert import to_convention
from dhsym.io.library import ROBOTS_DIR, builtin_names

INLINE6 = (ROBOTS_DIR / "inline6.yaml").read_text(encoding="utf-8")
ROW_4 = "{joint: R, alpha: pi/2,  a: 0,   d: d_4, theta: theta_4}"


def other(convention: str) -> str:
    return "modified" if convention == "standard" else "standard"


@pytest.mark.parametrize("name", builtin_names())
def test_every_builtin_robot_converts_and_back_with_the_same_kinematics(name, tmp_path, capsys):
    chain = load(name)
    converted = tmp_path / "converted.yaml"
    back = tmp_path / "back.yaml"
    assert cli.main(["convert", name, "--to", other(chain.convention), "-o", str(converted)]) == 0
    assert cli.main(["convert", str(converted), "--to", chain.convention, "-o", str(back)]) == 0
    assert load_robot_file(converted).convention == other(chain.convention)
    assert load_robot_file(back).joint_variables == chain.joint_variables
    capsys.readouterr()
    for path in (converted, back):
        assert cli.main(["check", str(path), "--against", name]) == 0
        assert "same kinematics" in capsys.readouterr().out


def test_conversion_keeps_symbols_and_variables():
    converted = to_convention(load("puma560").chain, "standard")
    assert [row.variable.name for row in converted.rows] == [f"theta_{i}" for i in range(1, 7)]
    assert {s.name for s in converted.symbols} == {s.name for s in load("puma560").symbols}


def variant(old: str, new: str) -> object:
    assert old in INLINE6
    return load_robot_text(INLINE6.replace(old, new), "homework.yaml")


def test_a_wrong_twist_sign_is_named_with_its_row():
    verdict = compare(variant(ROW_4, ROW_4.replace("alpha: pi/2", "alpha: -pi/2")), load("inline6"))
    assert (verdict.same, verdict.kind, verdict.joint) == (False, "offset", 4)
    assert "the sign of α (and of a) in row 4 is flipped" in verdict.message


def test_a_wrong_twist_names_the_joint_whose_axis_moves():
    verdict = compare(variant(ROW_4, ROW_4.replace("alpha: pi/2", "alpha: 0")), load("inline6"))
    assert (verdict.same, verdict.kind, verdict.joint) == (False, "direction", 5)
    assert "points along (0, 0, -1) at the zero pose; the reference's points along (0, 1, 0)" in verdict.message
    assert "check the twist α in row 4" in verdict.message


def test_the_lecture_s_two_wrist_tables_differ_by_two_half_turn_zeros():
    row_5 = "{joint: R, alpha: -pi/2, a: 0,   d: 0,   theta: theta_5}"
    example2_wrist = INLINE6.replace(ROW_4, ROW_4.replace("alpha: pi/2", "alpha: -pi/2")) \
        .replace(row_5, row_5.replace("alpha: -pi/2", "alpha: pi/2"))
    verdict = compare(load_robot_text(example2_wrist, "example2_wrist.yaml"), load("inline6"))
    assert verdict.kind == "offset" and "the zeros of joints 4 and 6 differ by π and π" in verdict.message


@pytest.mark.parametrize("old, new, kind", [("tool: []", "tool: [{Tz: 0.1}]", "tool"),
                                            ("base: []", "base: [{Rz: pi/3}]", "base")])
def test_only_the_base_or_tool_differs(old, new, kind):
    verdict = compare(variant(old, new), load("inline6"))
    assert (verdict.same, verdict.kind) == (False, kind)


def test_check_exits_1_with_one_line_for_a_student(tmp_path, capsys):
    homework = tmp_path / "homework.yaml"
    homework.write_text(INLINE6.replace(ROW_4, ROW_4.replace("alpha: pi/2", "alpha: -pi/2")), encoding="utf-8")
    assert cli.main(["check", str(homework), "--against", "inline6"]) == 1
    out, err = capsys.readouterr()
    assert err == "" and out.count("\n") == 1 and "flipped" in out


def test_check_exits_2_for_an_unreadable_reference(capsys):
    assert cli.main(["check", "inline6", "--against", "no_such_robot.yaml"]) == 2
    assert capsys.readouterr().err.startswith("dhsym: error: no_such_robot.yaml: cannot read file")


def test_different_joint_counts_and_types_are_said_plainly():
    assert compare(load("spatial3r"), load("inline6")).kind == "joints"
    verdict = compare(load("cylindrical_rpp"), load("spatial3r"))
    assert verdict.kind == "joints" and "joint 2 is prismatic in yours but revolute" in verdict.message
