"""dhsym's simplified matrices equal the textbooks' printed forms and are never longer."""
import pytest
import sympy
import textbook

from dhsym.checking.verify import check
from dhsym.io.library import load
from dhsym.printing.printers import TextPrinter

TEXTBOOK_FORMS = {
    "puma560": textbook.craig_puma_0T6,
    "stanford": textbook.spong_stanford_0T6,
    "scara_spong": textbook.spong_scara_0T4,
    "planar3r": textbook.planar3r_0Ttool,
    "spatial3r": textbook.spatial3r_0T3,
    "spherical_wrist": textbook.spherical_wrist_3T6,
}


@pytest.mark.parametrize("name", sorted(TEXTBOOK_FORMS))
def test_equal_to_textbook_and_no_longer(name):
    ours = load(name).fk()
    printed = TEXTBOOK_FORMS[name]()
    assert check(ours, printed)
    for k in range(12):
        assert sympy.count_ops(ours[k]) <= sympy.count_ops(printed[k]), (name, k, ours[k], printed[k])


def _text(name, row, column):
    robot = load(name)
    return TextPrinter(robot.joint_variables).doprint(robot.fk()[row, column])


def test_planar3r_position_reads_like_the_lecture():
    assert _text("planar3r", 0, 3) == "l1 c1 + l2 c12 + l3 c123"
    assert _text("planar3r", 0, 0) == "c123"


def test_spatial3r_horizontal_reach_is_factored():
    assert _text("spatial3r", 0, 3) == "c1(a2 c2 + a3 c23)"
    assert _text("spatial3r", 2, 3) == "d1 + a2 s2 + a3 s23"


def test_spherical_wrist_has_the_classic_element():
    assert _text("spherical_wrist", 0, 0) == "c4 c5 c6 − s4 s6"


def test_puma_is_grouped_by_joint_order_like_craig():
    assert _text("puma560", 0, 3) == "c1(a2 c2 + a3 c23 − d4 s23) − d3 s1"
    assert _text("puma560", 0, 0) == "c1[c23(c4 c5 c6 − s4 s6) − s23 s5 c6] + s1(c4 s6 + s4 c5 c6)"


def test_scara_twist_of_pi_gives_an_angle_difference():
    robot = load("scara_spong")
    t1, t2, _, t4 = robot.joint_variables
    assert robot.fk()[0, 0] == sympy.cos(t1 + t2 - t4)
    assert _text("scara_spong", 0, 0) == "c124\u0305"


def test_offsets_fold_into_sums():
    from dhsym import Chain, DHRow
    t1, t2, l1, l2 = sympy.symbols("theta_1 theta_2 l_1 l_2", real=True)
    arm = Chain([DHRow.revolute(t1, a=l1), DHRow.revolute(t2 - sympy.pi / 2, a=l2, variable=t2)], "standard")
    assert arm.fk()[0, 3] == l1 * sympy.cos(t1) + l2 * sympy.sin(t1 + t2)


def test_no_floats_in_any_builtin_result():
    from dhsym.io.library import builtin_names
    for name in builtin_names():
        assert not load(name).fk().atoms(sympy.Float), name
