"""dhsym's simplified matrices equal the textbooks' printed forms and are never longer."""
import pytest
import sympy
import textbook

from dhsym import load
from dhsym.checking.verify import check
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


# ViSP's Viper 650/850 (lagadic/visp, vpViper.h: standard DH; the wrist frame w is frame 6, the
# end effector e is d6 further along z6), with its published forward kinematics get_fMw and get_fMe.
VIPER = """
name: Viper
convention: standard
joints:
  - {joint: R, a: a_1, d: d_1, alpha: -pi/2, theta: q_1}
  - {joint: R, a: a_2, d: 0,   alpha: 0,     theta: q_2}
  - {joint: R, a: a_3, d: 0,   alpha: -pi/2, theta: q_3 - pi}
  - {joint: R, a: 0,   d: d_4, alpha: pi/2,  theta: q_4}
  - {joint: R, a: 0,   d: 0,   alpha: -pi/2, theta: q_5}
  - {joint: R, a: 0,   d: 0,   alpha: 0,     theta: q_6 - pi}
tool: [{Tz: d_6}]
"""


def visp_viper():
    """fMw and fMe as vpViper.cpp writes them (c23 = cos(q2 + q3))."""
    q = {i: sympy.Symbol(f"q_{i}", real=True) for i in range(1, 7)}
    a1, a2, a3, d1, d4, d6 = sympy.symbols("a_1 a_2 a_3 d_1 d_4 d_6", real=True)
    c1, c2, c4, c5, c6 = (sympy.cos(q[i]) for i in (1, 2, 4, 5, 6))
    s1, s2, s4, s5, s6 = (sympy.sin(q[i]) for i in (1, 2, 4, 5, 6))
    c23, s23 = sympy.cos(q[2] + q[3]), sympy.sin(q[2] + q[3])
    rotation = [
        [c1 * (c23 * (c4 * c5 * c6 - s4 * s6) - s23 * s5 * c6) - s1 * (s4 * c5 * c6 + c4 * s6),
         -c1 * (c23 * (c4 * c5 * s6 + s4 * c6) - s23 * s5 * s6) + s1 * (s4 * c5 * s6 - c4 * c6),
         c1 * (c23 * c4 * s5 + s23 * c5) - s1 * s4 * s5],
        [-s1 * (c23 * (-c4 * c5 * c6 + s4 * s6) + s23 * s5 * c6) + c1 * (s4 * c5 * c6 + c4 * s6),
         -s1 * (c23 * (c4 * c5 * s6 + s4 * c6) - s23 * s5 * s6) - c1 * (s4 * c5 * s6 - c4 * c6),
         s1 * (c23 * c4 * s5 + s23 * c5) + c1 * s4 * s5],
        [s23 * (s4 * s6 - c4 * c5 * c6) - c23 * s5 * c6, s23 * (c4 * c5 * s6 + s4 * c6) + c23 * s5 * s6,
         -s23 * c4 * s5 + c23 * c5]]
    reach = -c23 * a3 + s23 * d4 + a1 + a2 * c2
    wrist = [c1 * reach, s1 * reach, s23 * a3 + c23 * d4 - a2 * s2 + d1]
    reach_e = c23 * (c4 * s5 * d6 - a3) + s23 * (c5 * d6 + d4) + a1 + a2 * c2
    flange = [c1 * reach_e - s1 * s4 * s5 * d6, s1 * reach_e + c1 * s4 * s5 * d6,
              s23 * (a3 - c4 * s5 * d6) + c23 * (c5 * d6 + d4) - a2 * s2 + d1]

    def matrix(position):
        return sympy.Matrix([row + [p] for row, p in zip(rotation, position)] + [[0, 0, 0, 1]])
    return {"fMw": matrix(wrist), "fMe": matrix(flange)}


@pytest.mark.parametrize("name", ["fMw", "fMe"])
def test_visp_viper_text_and_json_are_no_longer_than_visp(name):
    """The JSON, read back by SymPy, has the text form's brackets: −c23(a + b), never c23(−a − b)."""
    from readers import load_robot_text

    from dhsym.printing import render
    chain = load_robot_text(VIPER)
    ours = chain.transform(0, 6) if name == "fMw" else chain.fk()
    printed = visp_viper()[name]
    assert check(ours, printed)
    exact = render.exact_printer(chain)
    names = {symbol.name: symbol for symbol in ours.free_symbols}
    for k in range(12):
        back = sympy.sympify(exact.doprint(ours[k]), locals=names)
        assert back == ours[k], (name, k)
        assert sympy.count_ops(back) <= sympy.count_ops(printed[k]), (name, k, exact.doprint(ours[k]), printed[k])
