"""Velocity kinematics: the Jacobian from the contracted frames equals the one from the raw
product (linear rows: derivatives of the position; angular rows: the joint axes), in every
frame of every built-in robot; determinants, singularities and Craig's propagation."""
import random

import pytest
import sympy
import textbook
from readers import load_robot_text

import dhsym
from dhsym import load
from dhsym.api.robot import notebook_robot
from dhsym.checking.verify import check, numeric_error
from dhsym.io.library import builtin_names
from dhsym.velocity import ROWS, propagated_jacobian
from dhsym.velocity.jacobian import axis_frame


def reference_jacobian(chain, frame, point):
    """From the plain product, by the definition: ∂p/∂q in the first frame (position of the raw
    product) and the raw z axes, then turned into `frame` with the raw rotation. A robot's frames
    are its printed numbers; the reference works on its chain (frames 0..n)."""
    robot = notebook_robot(chain)
    chain, (frame, point) = robot.chain, robot.numbering.chain_frames(robot.chain, frame, point)
    first = chain.first_frame
    position = chain.transform(first, point, raw=True)[:3, 3]
    order = chain.frames.index
    columns = []
    for joint, q in enumerate(chain.joint_variables, 1):
        if order(point) < order(joint):
            columns.append([0] * 6)
            continue
        z = chain.transform(first, axis_frame(chain, joint), raw=True)[:3, 2]
        angular = [0, 0, 0] if chain.rows[joint - 1].joint == "P" else list(z)
        columns.append([sympy.diff(x, q) for x in position] + angular)
    base = sympy.Matrix(columns).T
    turn = chain.transform(frame, first, raw=True)[:3, :3]
    return sympy.Matrix.vstack(turn * base[:3, :], turn * base[3:, :])


SMALL = [name for name in builtin_names() if load(name).n <= 4]


@pytest.mark.slow
@pytest.mark.parametrize("name", builtin_names())
def test_every_frame_matches_the_raw_product_numerically(name):
    chain = load(name)
    for frame in chain.frames:
        assert numeric_error(chain.jacobian(frame), reference_jacobian(chain, frame, chain.last_frame),
                             trials=3) < 1e-9, (name, frame)


@pytest.mark.parametrize("name", SMALL)
def test_small_arms_match_the_raw_product_by_algebra(name):
    chain = load(name)
    for frame in (chain.first_frame, chain.last_frame):
        assert check(chain.jacobian(frame), reference_jacobian(chain, frame, chain.last_frame)), (name, frame)


def test_other_frames_are_the_first_frame_jacobian_rotated():
    chain = load("puma560")
    first = chain.jacobian()
    for frame in (3, 6):
        turn = chain.transform(frame, 0)[:3, :3]
        rotated = sympy.Matrix.vstack(turn * first[:3, :], turn * first[3:, :])
        assert numeric_error(chain.jacobian(frame), rotated, trials=4) < 1e-9


def test_point_of_an_inner_frame_ignores_the_later_joints():
    chain = load("puma560")
    inner = chain.jacobian(0, 3)
    assert inner[:, 3:] == sympy.zeros(6, 3)
    assert numeric_error(inner, reference_jacobian(chain, 0, 3), trials=3) < 1e-9


TEXTBOOK = {("puma560", 3): textbook.craig_puma_3J6, ("planar2r", 0): textbook.planar2r_0J,
            ("planar3r", 3): textbook.planar3r_3J, ("scara_spong", 0): textbook.spong_scara_0J}


@pytest.mark.parametrize("name, frame", sorted(TEXTBOOK))
def test_textbook_jacobians_are_equal_and_no_longer(name, frame):
    chain = load(name)
    ours, printed = chain.jacobian(frame, chain.n), TEXTBOOK[name, frame]()
    assert check(ours, printed)
    for k in range(len(ours)):
        assert sympy.count_ops(ours[k]) <= sympy.count_ops(printed[k]), (k, ours[k], printed[k])


def test_stanford_prismatic_and_wrist_columns_as_spong_prints_them():
    ours, printed = load("stanford").jacobian()[:, 2:], textbook.spong_stanford_0J_columns_3_to_6()
    assert check(ours[:, :1], printed[:, :1]) and check(ours[3:, 1:], printed[3:, 1:])
    for k in (0, 1, 2):
        assert sympy.count_ops(ours[k, 0]) <= sympy.count_ops(printed[k, 0])


def test_puma_determinant_factors_and_meanings():
    chain = load("puma560")
    result = chain.determinant()
    a2, a3, d4 = (sympy.Symbol(n, real=True) for n in ("a_2", "a_3", "d_4"))
    t2, t3, t5 = chain.joint_variables[1], chain.joint_variables[2], chain.joint_variables[4]
    expected = [sympy.sin(t5), a3 * sympy.sin(t3) + d4 * sympy.cos(t3),
                a2 * sympy.cos(t2) + a3 * sympy.cos(t2 + t3) - d4 * sympy.sin(t2 + t3)]
    assert all(check(ours, theirs) for ours, theirs in zip(result.factors, expected, strict=True))
    full = chain.jacobian()
    assert numeric_error(result.value, full.det(method="berkowitz"), trials=4) < 1e-9
    meanings = [s.meaning for s in chain.singularities(result)]
    assert meanings[0].startswith("wrist: axes 4 and 6 line up")
    assert "elbow" in meanings[1] and "axes 2 and 3" in meanings[1]
    assert "shoulder" in meanings[2] and "axis 1" in meanings[2]


@pytest.mark.parametrize("name", ["planar2r", "planar3r", "scara_spong", "spatial3r", "stanford", "inline6"])
def test_each_singular_factor_makes_the_jacobian_lose_rank(name):
    chain = load(name)
    result = chain.determinant()
    assert result.value is not None and result.factors
    rng = random.Random(3)
    rows = list(range(6)) if result.block == "J" else [ROWS.index(r) for r in result.block[5:].split(", ")]
    block = chain.jacobian().extract(rows, list(range(chain.n)))
    for factor in result.factors:
        variable = [v for v in chain.joint_variables if v in factor.free_symbols][-1]
        others = {s: rng.uniform(0.5, 1.5) for s in sorted(chain.symbols, key=str) if s != variable}
        f = sympy.lambdify([variable], factor.subs(others))
        grid = [-3.1 + k * 0.01 for k in range(620)]
        lo = next(x for x in grid if f(x) * f(x + 0.01) <= 0)
        root = sympy.nsolve(factor.subs(others), variable, (lo, lo + 0.01), solver="bisect")
        values = {**others, variable: root}
        numeric = block.subs(values).evalf()
        rank = numeric.rank(iszerofunc=lambda x: abs(x) < 1e-8)
        assert rank < chain.n, (name, factor)


def test_non_square_and_redundant_say_what_is_not_computed():
    iiwa = load("iiwa7").determinant()
    assert iiwa.value is None and "redundant" in iiwa.note and "not" in iiwa.note
    planar = load("planar2r").determinant()
    a1, a2 = sympy.symbols("a_1 a_2", real=True)
    assert planar.block == "rows vx, vy"
    assert check(planar.value, a1 * a2 * sympy.sin(load("planar2r").joint_variables[1]))


@pytest.mark.parametrize("name", ["planar2r", "planar3r", "scara_spong", "stanford", "puma560"])
def test_velocity_propagation_ends_in_the_same_jacobian(name):
    chain = load(name)
    steps = chain.propagate()
    assert steps[-1].frame == chain.last_frame
    verdict = check(propagated_jacobian(chain.chain, steps), chain.jacobian(chain.last_frame))
    assert verdict.numeric and (verdict.algebraic or chain.n > 4)


@pytest.mark.slow
def test_the_ur5_determinant_factors_without_a_wrist_centre():
    """UR5: joints 2, 3, 4 parallel and no wrist centre; the textbook's a2 a3 s3 s5 (a2 c2 + a3 c23 + d5 s234)."""
    ur5 = dhsym.load("ur5")
    t = ur5.joint_variables
    a2, a3, d5 = (dhsym.real_symbol(name) for name in ("a_2", "a_3", "d_5"))
    expected = a2 * a3 * sympy.sin(t[2]) * sympy.sin(t[4]) * (
        a2 * sympy.cos(t[1]) + a3 * sympy.cos(t[1] + t[2]) + d5 * sympy.sin(t[1] + t[2] + t[3]))
    result = ur5.determinant()  # decided by counting terms: a loaded machine cannot change the answer
    assert numeric_error(result.value, expected) < 1e-9
    assert numeric_error(result.value, ur5.jacobian().det(method="berkowitz")) < 1e-9
    assert len(result.factors) == 3
    meanings = [singularity.meaning for singularity in ur5.singularities(result)]
    # the shoulder is where axes 5 and 6 meet crossing the plane of axes 1 and 2; the flange is always
    # in the plane through axis 5 parallel to axis 6, which is no description at all
    assert meanings == ["wrist: axes 4 and 6 are parallel",
                        "shoulder: the origin of frame 5 lies in the plane through axis 1 parallel to axis 2 "
                        "(on axis 1 when there is no offset)",
                        "elbow stretched or folded: axis 4 lies in the plane of axes 2 and 3"]


def test_a_general_six_link_determinant_is_refused_from_its_count_of_terms():
    rows = "".join(f"  - {{joint: R, alpha: alpha_{i}, a: a_{i}, d: d_{i}, theta: theta_{i}}}\n" for i in range(1, 7))
    chain = load_robot_text(f"convention: standard\njoints:\n{rows}", "general6.yaml")
    result = chain.determinant()
    assert result.value is None and result.factors == []
    assert result.note == ("the axes of joints 4–6 do not meet in a point, and the full 6×6 determinant would expand "
                           "to about 9.8 million terms even in frame 4 of the modified convention, where J is "
                           "shortest; that is more than the 50,000 that dhsym factors: not computed.")


def test_axes_that_line_up_and_axes_that_are_only_parallel_are_told_apart():
    """PUMA, s5 = 0: axes 4 and 6 coincide. Stanford, s2 = 0: the boom (axis 4) is parallel to
    axis 1 but d2 away from it, so 'line up' would be wrong."""
    puma, stanford = load("puma560"), load("stanford")
    assert puma.singularities(puma.determinant())[0].meaning == "wrist: axes 4 and 6 line up"
    meanings = [s.meaning for s in stanford.singularities(stanford.determinant())]
    assert "axes 1 and 4 are parallel" in meanings and "wrist: axes 4 and 6 line up" in meanings
