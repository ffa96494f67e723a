"""The frame-assignment algorithm: URDFs and random axis geometries → DH table → the same
forward kinematics, computed independently (yourdfpy for URDFs, products of exponentials for axes)."""
import random

import numpy as np
import pytest
import sympy
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dhsym import load
from dhsym.api.robot import notebook_robot
from dhsym.core.chain import Chain, DHRow
from dhsym.geometry.exact import vector
from dhsym.geometry.frames import assign_frames
from dhsym.geometry.lines import JointAxis
from dhsym.geometry.screws import chain_axes, product_of_exponentials, screw_axes
from dhsym.io.library import builtin_names
from dhsym.io.urdf import read_urdf, read_urdf_text
from tests.urdf_builder import serial_urdf, urdf_fk

DATA = "tests/data"
R90 = "1.5707963267948966"
# What the rounded numbers of a URDF stand for: the FK of the URDF is taken with these, since
# dhsym snaps them (and says so); 1.5708 alone would put the URDF's own FK 4e-6 off.
PRECISE = {"1.570796325": repr(float(np.pi / 2)), "1.5708": repr(float(np.pi / 2)), "0.5236": repr(float(np.pi / 6)),
           "0.8660254": repr(float(np.sqrt(0.75)))}


def precise(text: str) -> str:
    for rounded, exact in PRECISE.items():
        text = text.replace(f"{rounded} ", f"{exact} ").replace(f"{rounded}\"", f"{exact}\"")
    return text


def numeric_fk(chain, values) -> np.ndarray:
    substitution = {v: q for v, q in zip(chain.joint_variables, values)}
    substitution.update(getattr(chain, "sample", {}))  # a Robot has sample values, a plain Chain none
    return np.array(chain.fk(raw=True).xreplace(substitution).evalf(), dtype=float)


def assert_same_fk_as_urdf(text, base="link0", tip=None, trials=5):
    urdf = read_urdf_text(text.encode(), "edge.urdf", base, tip)
    tip = tip or urdf.tip
    rng = random.Random(1)
    for convention in ("standard", "modified"):
        chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, convention).robot())
        for _ in range(trials):
            q = [rng.uniform(-2.5, 2.5) for _ in range(chain.n)]
            assert np.allclose(numeric_fk(chain, q), urdf_fk(precise(text), q, base, tip), atol=1e-9), convention
    return urdf


EDGE_CASES = {
    "intersecting": [("revolute", "0 0 0.3", "0 0 0", "0 0 1"), ("revolute", "0 0 0.2", f"{R90} 0 0", "0 0 1")],
    "parallel": [("revolute", "0 0 0.1", "0 0 0", "0 0 1"), ("revolute", "0.4 0.1 0", "0 0 0", "0 0 1"),
                 ("revolute", "0.3 0 0.05", "0 0 0", "0 0 1")],
    "collinear": [("revolute", "0 0 0.1", "0 0 0", "0 0 1"), ("revolute", "0 0 0.5", "0 0 0", "0 0 1"),
                  ("fixed", "0 0 0.05", "0 0 0", None)],
    "anti_parallel": [("revolute", "0 0 0", "0 0 0", "0 0 1"), ("revolute", "0.4 0 0", "0 0 0", "0 0 -1"),
                      ("revolute", "0.3 0 0", "3.141592653589793 0 0", "0 0 1")],
    "skew": [("revolute", "0 0 0.2", "0 0 0", "0 0 1"), ("revolute", "0.1 0.2 0.3", "0 0 0", "1 0 0"),
             ("revolute", "0 0.3 0.1", "0 0.5235987755982988 0", "0 1 0")],
    "prismatic": [("revolute", "0 0 0.3", "0 0 0", "0 0 1"), ("prismatic", "0.2 0 0", "0 0 0", "1 0 0"),
                  ("prismatic", "0 0 0.1", f"0 {R90} 0", "0 0 -1")],
    "fixed_in_the_middle": [("revolute", "0 0 0.3", "0 0 0", "0 0 1"),
                            ("fixed", "0.1 0 0", "0 0 0.7853981633974483", None),
                            ("revolute", "0.2 0 0", f"{R90} 0 0", "0 0 1"), ("fixed", "0 0 0.1", "0 0 0", None)],
    "rounded_angles": [("revolute", "0 0 0.1", "0 0 0", "0 0 1"), ("revolute", "0 0 0", "1.570796325 0 0", "0 0 1"),
                       ("revolute", "0.3 0 0", "-1.5708 0 0.5236", "0 0.5 0.8660254"),
                       ("fixed", "0 0 0.1", "1.5708 0 0", None)],
    "tilted_tool": [("revolute", "0 0 0.1", "0 0 0", "0 0 1"), ("revolute", "0 0.1 0.3", "0 0 0", "0 1 0"),
                    ("fixed", "0.2 0 0.1", "0.3 0.2 0.1", None)],
}


@pytest.mark.parametrize("case", sorted(EDGE_CASES))
def test_edge_case_urdfs_give_the_urdf_kinematics(case):
    assert_same_fk_as_urdf(serial_urdf(EDGE_CASES[case]))


def test_anti_parallel_axes_get_a_twist_of_pi():
    urdf = read_urdf_text(serial_urdf(EDGE_CASES["anti_parallel"]).encode(), "edge.urdf")
    chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, "standard").robot())
    assert chain.rows[0].alpha == sympy.pi and chain.rows[0].a == sympy.Rational(2, 5)


def test_rounded_angles_become_exact_with_a_warning():
    urdf = read_urdf_text(serial_urdf(EDGE_CASES["rounded_angles"]).encode(), "edge.urdf")
    chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, "modified").robot())
    assert all((row.alpha / (sympy.pi / 12)).is_integer for row in chain.rows)
    assert not any(value.has(sympy.Float) for row in chain.rows for value in (row.theta, row.d, row.a, row.alpha))
    assert urdf.warnings[0].startswith("edge.urdf:9:102: angles snapped to the multiples of π/12 they were rounded")
    assert urdf.warnings[0].endswith("this turns any frame by at most 8.6e-06 rad and moves it by at most 5e-07 m")
    assert all(f"{text} → {exact}" in urdf.warnings[0]
               for text, exact in (("1.570796325", "π/2"), ("-1.5708", "-π/2"), ("0.5236", "π/6")))
    assert "axis directions snapped" in urdf.warnings[-1]


def test_lengths_are_the_decimals_written_and_noise_is_zero():
    text = serial_urdf([("revolute", "0 1.2e-17 0.089159", "0 0 0", "0 0 1"),
                        ("revolute", "0.425 0 0", "0 0 0", "1 0 0")])
    urdf = read_urdf_text(text.encode(), "noise.urdf")
    chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, "standard").robot())
    assert [(row.d, row.a) for row in chain.rows] == [(sympy.Rational("0.089159"), 0), (sympy.Rational("0.425"), 0)]
    assert any("1.2e-17 taken as 0" in w for w in urdf.warnings)


@pytest.mark.parametrize("path, tip", [("panda.urdf", None), ("ur5.urdf", "tool0"), ("ur5.urdf", "ee_link")])
def test_real_arms_give_the_urdf_kinematics(path, tip):
    text = open(f"{DATA}/{path}", encoding="utf-8").read()
    urdf = read_urdf(f"{DATA}/{path}", tip=tip)
    assert_same_fk_as_urdf(text, urdf.base, urdf.tip)


def test_the_panda_gives_franka_s_published_modified_table():
    urdf = read_urdf(f"{DATA}/panda.urdf")
    chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, "modified").robot())
    published = [(0, 0, "0.333"), (-1, 0, 0), (1, 0, "0.316"), (1, "0.0825", 0), (-1, "-0.0825", "0.384"),
                 (1, 0, 0), (1, "0.088", "0.107")]  # α/(π/2), a, d; the flange's d = 0.107 sits in row 7
    assert [(row.alpha / (sympy.pi / 2), row.a, row.d) for row in chain.rows] == \
        [(a, sympy.Rational(x), sympy.Rational(d)) for a, x, d in published]
    assert all(row.theta == v for row, v in zip(chain.rows, chain.joint_variables))  # no offsets
    assert chain.base == () and chain.tool == ()


# --- Random geometries: axes → table → FK equals the axes' product of exponentials.

UNIT_DIRECTIONS = [vector(*v) for v in ((1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0), (0, -1, 0), (0, 0, -1))] + \
    [vector(sympy.sqrt(2) / 2, 0, sympy.sqrt(2) / 2), vector(0, sympy.Rational(3, 5), sympy.Rational(-4, 5))]
coordinates = st.sampled_from([0, 0, sympy.Rational(1, 2), sympy.Rational(-3, 10), 1])
points = st.tuples(coordinates, coordinates, coordinates).map(lambda p: vector(*p))
axes_strategy = st.lists(st.tuples(st.sampled_from("RRP"), points, st.sampled_from(range(len(UNIT_DIRECTIONS)))),
                         min_size=1, max_size=4)


def poe_fk(axes, tool, values) -> np.ndarray:
    rows = []
    for axis in axes:
        omega = axis.direction if axis.joint == "R" else sympy.zeros(3, 1)
        v = -axis.direction.cross(axis.point) if axis.joint == "R" else axis.direction
        rows.append(list(omega) + list(v))
    from dhsym.geometry.screws import Screws
    screws = Screws(sympy.Matrix(rows).T, tool)
    return np.array(product_of_exponentials(screws, values).evalf(), dtype=float)


@pytest.mark.slow
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(axes_strategy, points, st.sampled_from(range(len(UNIT_DIRECTIONS))), st.sampled_from(["standard", "modified"]))
def test_random_axes_to_table_keep_the_kinematics(specs, tool_point, tool_direction, convention):
    axes = [JointAxis(kind, point, UNIT_DIRECTIONS[d]) for kind, point, d in specs]
    z = UNIT_DIRECTIONS[tool_direction]
    x = vector(1, 0, 0) if abs(z[0]) != 1 else vector(0, 1, 0)
    x = (x - x.dot(z) * z) / sympy.sqrt((x - x.dot(z) * z).dot(x - x.dot(z) * z))
    tool = sympy.eye(4)
    tool[:3, 0], tool[:3, 1], tool[:3, 2], tool[:3, 3] = x, z.cross(x), z, tool_point
    chain = notebook_robot(assign_frames(axes, tool, convention).robot())
    rng = random.Random(len(specs))
    for _ in range(3):
        q = [rng.uniform(-2, 2) for _ in axes]
        assert np.allclose(numeric_fk(chain, q), poe_fk(axes, tool, q), atol=1e-9)


# --- Random tables: table → axes → table reproduces the FK.

angles = st.sampled_from([0, sympy.pi / 2, -sympy.pi / 2, sympy.pi, sympy.pi / 4])
lengths = st.sampled_from([0, 0, sympy.Rational(1, 2), sympy.Rational(-2, 5), 1])
rows_strategy = st.lists(st.tuples(st.sampled_from("RP"), angles, lengths, lengths, angles), min_size=1, max_size=4)


@pytest.mark.slow
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rows_strategy, st.sampled_from(["standard", "modified"]), st.sampled_from(["standard", "modified"]))
def test_random_tables_through_their_axes_reproduce_the_kinematics(specs, convention, target):
    q = [sympy.Symbol(f"q_{i}", real=True) for i in range(1, len(specs) + 1)]
    rows = [DHRow.revolute(v + offset, d, a, alpha) if kind == "R" else DHRow.prismatic(v + d, offset, a, alpha)
            for v, (kind, offset, d, a, alpha) in zip(q, specs)]
    chain = Chain(rows, convention)
    axes, tool = chain_axes(chain)
    derived = notebook_robot(assign_frames(axes, tool, target, q).robot())
    rng = random.Random(3)
    for _ in range(3):
        values = [rng.uniform(-2, 2) for _ in q]
        assert np.allclose(numeric_fk(derived, values), numeric_fk(chain, values), atol=1e-9)


@pytest.mark.parametrize("name", builtin_names())
def test_screws_of_every_builtin_robot_give_its_kinematics(name):
    chain = load(name)
    constants = {s: sympy.Rational(random.Random(s.name).randint(2, 9), 10)
                 for s in chain.symbols - set(chain.joint_variables)}
    constants.update(chain.sample)
    rng = random.Random(name)
    q = [rng.uniform(-2, 2) for _ in chain.joint_variables]
    expected = chain.fk(raw=True).xreplace({**constants, **dict(zip(chain.joint_variables, q))})
    poe = product_of_exponentials(screw_axes(chain.chain), q).xreplace(constants)
    assert np.allclose(np.array(expected.evalf(), dtype=float), np.array(poe.evalf(), dtype=float), atol=1e-9)


def test_a_general_six_link_chain_has_its_screws_and_they_give_its_kinematics():
    """Symbolic twists, lengths and offsets: the zero pose is too large to simplify, so the screw
    axes keep the contracted form fk prints; e^[S1]q1 ⋯ e^[S6]q6 M is still the chain's forward kinematics."""
    symbols = {name: sympy.Symbol(name, real=True) for name in
               [f"{kind}_{i}" for i in range(1, 7) for kind in ("q", "o", "d", "a", "alpha")]}
    rows = [DHRow.revolute(symbols[f"q_{i}"] + symbols[f"o_{i}"], symbols[f"d_{i}"], symbols[f"a_{i}"],
                           symbols[f"alpha_{i}"], variable=symbols[f"q_{i}"]) for i in range(1, 7)]
    chain = Chain(rows, "standard")
    rng = random.Random(6)
    constants = {symbol: rng.uniform(-1, 1) for name, symbol in symbols.items() if not name.startswith("q")}
    q = [rng.uniform(-2, 2) for _ in range(6)]
    poe = product_of_exponentials(screw_axes(chain), q).xreplace(constants)
    expected = chain.fk(raw=True).xreplace({**constants, **dict(zip(chain.joint_variables, q))})
    assert np.allclose(np.array(poe.evalf(), dtype=float), np.array(expected.evalf(), dtype=float), atol=1e-9)


def test_every_step_is_recorded_for_a_notebook():
    urdf = read_urdf(f"{DATA}/ur5.urdf", tip="tool0")
    assignment = assign_frames(urdf.axes, urdf.tool, "standard")
    assert [step.relation for step in assignment.steps] == \
        ["intersecting", "parallel", "parallel", "intersecting", "intersecting", "collinear"]
    assert "flange" in assignment.steps[-1].why
    assert len(assignment.frames) == 7


def test_angles_off_the_grid_give_short_numbers_and_a_warning():
    urdf = read_urdf_text(serial_urdf(EDGE_CASES["tilted_tool"]).encode(), "tilted.urdf")
    chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, "standard").robot())
    values = [v for row in chain.rows for v in (row.theta - row.variable, row.d, row.a, row.alpha)]
    values += [step.value for step in chain.base + chain.tool]
    assert all(max(abs(r.p), r.q) < 10 ** 20 for v in values for r in sympy.sympify(v).atoms(sympy.Rational))
    assert any("off the π/12 grid (0.3, 0.2, 0.1)" in w and "15 significant digits" in w for w in urdf.warnings)


@pytest.mark.parametrize("case", ["fixed_in_the_middle", "skew", "tilted_tool", "rounded_angles"])
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_a_table_made_from_decimals_shows_decimals_and_multiples_of_pi(case, convention):
    urdf = read_urdf_text(serial_urdf(EDGE_CASES[case]).encode(), "edge.urdf")
    chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, convention).robot())
    values = [v for row in chain.rows for v in (row.theta - row.variable, row.d, row.a, row.alpha)]
    values += [step.value for step in chain.base + chain.tool]
    for value in values:
        number = value / sympy.pi if value.has(sympy.pi) else value
        assert number.is_Rational and (value.has(sympy.pi) and number.q <= 12 or 10 ** 40 % number.q == 0), value
    rounded = [v for v in values if v.is_Rational and len(str(v.q)) > 12]
    assert bool(rounded) == ("Rounded to 15 significant digits" in chain.notes)


def test_the_note_names_each_rounded_value_and_its_exact_form():
    text = serial_urdf([("revolute", "0 0 0.1", "0 0 0", "0 0 1"), ("revolute", "0.2 0 0.1", "0 0 0", "0 0.6 0.8")])
    urdf = read_urdf_text(text.encode(), "tilted.urdf")
    for convention, row in (("standard", 0), ("modified", 1)):
        chain = notebook_robot(assign_frames(urdf.axes, urdf.tool, convention).robot())
        assert chain.rows[row].alpha == sympy.Rational("-0.643501108793284")
        assert "alpha_1 -0.643501108793284 (exactly -atan(3/4))" in chain.notes
