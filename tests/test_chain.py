"""Link matrices of both conventions against the hand-derived general forms, frames, inverses."""
import pytest
import sympy

from dhsym import Chain, DHRow, Step, UserError, load
from dhsym.checking.verify import check

th, d, a, al = sympy.symbols("theta_1 d_1 a_1 alpha_1", real=True)
c, s, ca, sa = sympy.cos(th), sympy.sin(th), sympy.cos(al), sympy.sin(al)


def test_standard_link_matrix_is_the_lectures_general_form():
    # Lecture 003 / Spong: A_i = Rz(θ) Tz(d) Tx(a) Rx(α)
    expected = sympy.Matrix([[c, -s * ca, s * sa, a * c], [s, c * ca, -c * sa, a * s], [0, sa, ca, d], [0, 0, 0, 1]])
    chain = Chain([DHRow.revolute(th, d, a, al)], "standard")
    assert chain.link(1) == expected
    assert chain.link(1, raw=True) == expected


def test_modified_link_matrix_is_craigs_form():
    # Craig eq. (3.6): T_i = Rx(α_{i-1}) Tx(a_{i-1}) Rz(θ_i) Tz(d_i)
    expected = sympy.Matrix([[c, -s, 0, a], [s * ca, c * ca, -sa, -sa * d], [s * sa, c * sa, ca, ca * d], [0, 0, 0, 1]])
    chain = Chain([DHRow.revolute(th, d, a, al)], "modified")
    assert sympy.simplify(chain.link(1) - expected) == sympy.zeros(4)
    assert check(chain.link(1, raw=True), expected)


def test_prismatic_variable_is_d():
    q = sympy.Symbol("d_3", real=True)
    row = DHRow.prismatic(q)
    assert row.variable == q and row.joint == "P"
    assert Chain([row], "standard").fk()[2, 3] == q


def test_row_with_two_symbols_needs_a_named_variable():
    t, b = sympy.symbols("theta_1 beta", real=True)
    with pytest.raises(UserError, match="exactly one joint variable"):
        DHRow.revolute(t + b)
    assert DHRow.revolute(t + b, variable=t).variable == t


def test_frames_include_base_and_tool_only_when_present():
    assert load("planar2r").frames == [0, 1, 2]
    assert load("planar3r").frames == [0, 1, 2, 3, "tool"]
    assert load("fourbar_right").frames == ["base", 0, 1, "tool"]


def test_unknown_frame_is_a_user_error():
    with pytest.raises(UserError, match="no frame 7"):
        load("planar2r").transform(0, 7)


def test_inverse_is_closed_form_and_exact():
    chain = load("planar2r")
    l1, l2 = sympy.symbols("a_1 a_2", real=True)
    t2 = chain.joint_variables[1]
    inverse = chain.transform(2, 0)
    assert inverse[0, 3] == -l1 * sympy.cos(t2) - l2
    assert check(inverse * chain.fk(), sympy.eye(4))


def test_raw_inverse_is_rt_minus_rt_p():
    chain = load("spatial3r")
    forward = chain.fk(raw=True)
    inverse = chain.transform(3, 0, raw=True)
    assert inverse[:3, :3] == forward[:3, :3].T
    assert inverse[:3, 3] == -forward[:3, :3].T * forward[:3, 3]


def test_products_compose():
    chain = load("puma560")
    assert check(chain.transform(0, 3) * chain.transform(3, 6), chain.fk())


def test_base_and_tool_steps_are_applied():
    t = sympy.Symbol("theta_1", real=True)
    h, length = sympy.symbols("h l", real=True)
    chain = Chain([DHRow.revolute(t)], "standard", base=[Step("Tz", h)], tool=[Step("Tx", length)])
    assert chain.fk()[:3, 3] == sympy.Matrix([length * sympy.cos(t), length * sympy.sin(t), h])


def test_any_twist_angle_is_exact():
    t = sympy.Symbol("theta_1", real=True)
    chain = Chain([DHRow.revolute(t, alpha=sympy.pi / 6)], "standard")
    assert chain.fk()[2, 2] == sympy.sqrt(3) / 2
    assert not chain.fk().atoms(sympy.Float)


def test_simplification_strategy_is_injectable():
    calls = []

    def plain(steps, variables):
        calls.append(len(steps))
        from dhsym.core.transforms import product
        return product(steps)

    chain = Chain([DHRow.revolute(th, a=a)], "standard", simplifier=plain)
    chain.fk()
    assert calls == [4]


def test_lecture_planar3r_in_standard_convention_gives_the_same_tool_pose():
    # Lecture 000 writes the planar 3R in Craig's modified convention with a tool frame Tx(l3);
    # Spong's standard table (θi, 0, li, 0) puts frame 3 at the tool point directly.
    modified = load("planar3r")
    thetas = modified.joint_variables
    lengths = sympy.symbols("l_1 l_2 l_3", real=True)
    standard = Chain([DHRow.revolute(t, a=length) for t, length in zip(thetas, lengths)], "standard")
    assert check(standard.fk(), modified.fk())
    assert standard.fk() == modified.fk()  # the same textbook form, not only the same value


def test_a_chain_shows_itself_in_a_notebook():
    puma = load("puma560")
    assert repr(puma) == "Robot('PUMA 560', modified DH, 6 joints: RRRRRR, frames 0..6)"
    table = puma._repr_latex_()
    assert table.startswith("$$\n\\begin{array}{c|cccc}") and table.endswith("\\end{array}\n$$")
    assert "2 & -\\frac{\\pi}{2} & 0 & 0 & \\theta_{2}^{*}" in table
