"""The homes of facts that several layers share: the numeric forward kinematics (core.numeric),
the convention's joint axis and the rotations (core.transforms), the cross product (core.vectors).

On random chains (both conventions, prismatic joints, offsets, symbolic twists, base and tool
steps) the numbers are the exact formulas evaluated, and the axis each joint is said to turn
about is the line its motion really turns (or slides) the chain about."""
import math

import pytest
import sympy
from hypothesis import given
from hypothesis import strategies as st
from test_simplify_equals_raw import chains

import dhsym
from dhsym.core.numeric import NumericChain, origin
from dhsym.core.transforms import joint_axis_frame, rotation, turned_plane
from dhsym.core.vectors import cross, dot
from dhsym.errors import UserError
from dhsym.geometry.screws import rate

exact_numbers = st.builds(sympy.Rational, st.integers(-40, 40), st.integers(1, 16))


def _values(chain, data) -> dict:
    """An exact rational for every symbol of the chain."""
    return {s: data.draw(exact_numbers, label=s.name) for s in sorted(chain.symbols, key=str)}


def _floats(matrix) -> list[list[float]]:
    return [[float(x) for x in row] for row in matrix.tolist()]


def _largest_difference(a, b) -> float:
    return max(abs(x - y) for row_a, row_b in zip(a, b) for x, y in zip(row_a, row_b))


@pytest.mark.slow
@given(chains(), st.data())
def test_every_frame_is_the_exact_product_evaluated(chain, data):
    values = _values(chain, data)
    numeric = NumericChain(chain, values)  # the joint variables among the values are ignored here
    poses = numeric.poses([values[v] for v in chain.joint_variables])
    assert [frame for frame, _ in poses] == chain.frames
    for frame, pose in poses:
        exact = chain.transform(chain.first_frame, frame, raw=True).xreplace(values)
        assert _largest_difference(pose, _floats(exact)) < 1e-9, frame


@pytest.mark.slow
@given(chains(), st.data())
def test_the_end_pose_is_the_forward_kinematics(chain, data):
    values = _values(chain, data)
    q = [values[v] for v in chain.joint_variables]
    by_name = {s.name: v for s, v in values.items() if s not in chain.joint_variables}
    assert _largest_difference(NumericChain(chain, by_name).end(q), _floats(chain.fk().xreplace(values))) < 1e-9


@given(chains(), st.data())
def test_each_joint_moves_the_chain_about_the_axis_the_convention_names(chain, data):
    """Turning joint i by δ turns every later frame about its axis line by δ (sliding: moves it along
    the axis): the axis comes from joint_axis_frame, the motion from the steps themselves."""
    values = {s: float(v) for s, v in _values(chain, data).items()}
    numeric = NumericChain(chain, values)
    q = [values[v] for v in chain.joint_variables]
    joint = data.draw(st.integers(1, chain.n), label="joint")
    row, delta = chain.rows[joint - 1], 0.3
    moved = q[:joint - 1] + [q[joint - 1] + delta] + q[joint:]
    point, direction = numeric.axes(q)[joint - 1]
    amount = delta * float(rate(row).xreplace(values))
    before, after = origin(numeric.end(q)), origin(numeric.end(moved))
    if row.joint == "P":
        expected = [p + amount * u for p, u in zip(before, direction)]
    else:
        expected = [c + x for c, x in zip(point, _turned([p - c for p, c in zip(before, point)], direction, amount))]
    assert max(abs(x - y) for x, y in zip(after, expected)) < 1e-9


def _turned(v, u, angle: float) -> list:
    """v turned about the unit vector u by `angle` (Rodrigues' formula, written out here on purpose)."""
    c, s = math.cos(angle), math.sin(angle)
    along = dot(u, v) * (1 - c)
    return [c * x + s * w + along * k for x, w, k in zip(v, cross(u, v), u)]


def test_the_joint_axis_rule_of_each_convention():
    assert [joint_axis_frame("standard", i) for i in (1, 2, 6)] == [0, 1, 5]
    assert [joint_axis_frame("modified", i) for i in (1, 2, 6)] == [1, 2, 6]
    with pytest.raises(UserError, match="unknown convention 'craig'"):
        joint_axis_frame("craig", 1)


def test_the_jacobian_takes_its_axes_from_the_same_rule():
    for name in ("puma560", "planar3r", "stanford"):
        chain = dhsym.load(name).chain
        constants = sorted(chain.symbols - set(chain.joint_variables), key=str)
        lengths = {s: sympy.Rational(k + 2, 3) for k, s in enumerate(constants)}
        numeric = NumericChain(chain, lengths)
        zero = [0] * chain.n
        angular = dhsym.velocity.jacobian(chain)[3:, :].xreplace({v: 0 for v in chain.joint_variables} | lengths)
        for joint, (_, direction) in enumerate(numeric.axes(zero), 1):
            if chain.rows[joint - 1].joint == "R":
                assert max(abs(float(w) - z) for w, z in zip(angular[:, joint - 1], direction)) < 1e-12


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_a_rotation_turns_the_first_axis_of_its_plane_towards_the_second(axis):
    i, j = turned_plane(axis)
    turned = rotation(axis, sympy.pi / 2)[:3, :3] * sympy.eye(3)[:, i]
    assert list(turned) == list(sympy.eye(3)[:, j])
    assert list(cross(sympy.eye(3)[:, i], sympy.eye(3)[:, j])) == list(sympy.eye(3)[:, axis])  # right-handed


def test_the_rotation_about_y_is_the_textbooks():
    c, s = sympy.cos(sympy.Symbol("b")), sympy.sin(sympy.Symbol("b"))
    assert rotation(1, sympy.Symbol("b"))[:3, :3] == sympy.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])


@given(st.lists(st.integers(-9, 9), min_size=3, max_size=3), st.lists(st.integers(-9, 9), min_size=3, max_size=3))
def test_the_cross_product_is_sympys(u, v):
    w = cross(u, v)
    assert list(w) == list(sympy.Matrix(u).cross(sympy.Matrix(v)))
    assert dot(w, u) == dot(w, v) == 0 and dot(u, v) == sympy.Matrix(u).dot(sympy.Matrix(v))


def test_a_numeric_chain_needs_every_constant_and_one_value_per_joint():
    chain = dhsym.load("planar2r").chain
    with pytest.raises(ValueError, match="no number for a_2"):
        NumericChain(chain, {"a_1": 1})
    with pytest.raises(ValueError, match="1 joint values for 2 joints"):
        NumericChain(chain, {"a_1": 1, "a_2": 1}).end([0])


@given(chains(max_links=4), st.data())
def test_many_configurations_at_once_are_each_one_evaluated(chain, data):
    import numpy as np

    values = {s: float(v) for s, v in _values(chain, data).items()}
    numeric = NumericChain(chain, values)
    rng = np.random.default_rng(data.draw(st.integers(0, 100), label="seed"))
    columns = [rng.uniform(-np.pi, np.pi, 5) for _ in chain.joint_variables]
    together = np.array(numeric.end(columns))
    for k in range(5):
        assert np.abs(together[:, :, k] - np.array(numeric.end([c[k] for c in columns]))).max() < 1e-12


def test_a_step_that_is_not_affine_in_its_variable_is_evaluated_too():
    t = sympy.Symbol("t", real=True)
    chain = dhsym.Chain([dhsym.DHRow.revolute(t ** 2 / 2, a=1, variable=t)], "standard")
    pose = NumericChain(chain, {}).end([sympy.Rational(3, 2)])
    assert abs(pose[0][3] - math.cos(9 / 8)) < 1e-15 and abs(pose[1][3] - math.sin(9 / 8)) < 1e-15
    import numpy as np

    many = NumericChain(chain, {}).end([np.array([1.5, 0.0])])
    assert np.allclose(many[0][3], [math.cos(9 / 8), 1.0], atol=1e-15)
