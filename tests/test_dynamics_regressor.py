"""The regressor τ = Y π and the base parameters τ = Y_b π_b: both give the torques of the
program, at random states, on built-in and random arms."""
import numpy
import pytest
import sympy
from hypothesis import given, settings
from strategies import robots

from dhsym import load
from dhsym.dynamics.base import base_parameters
from dhsym.dynamics.codegen import tape_function
from dhsym.dynamics.model import about_origin
from dhsym.dynamics.program import dynamics_program
from dhsym.dynamics.regressor import parameter_symbols, regressor
from dhsym.errors import UserError


def standard_values(robot, values: dict) -> dict:
    """π of the filled masses of `robot` with `values` put in: m, m·c and the inertia about the origin."""
    out = {}
    for k, link in enumerate(robot.filled_masses().links, robot.frame_offset + 1):
        mass, moments, inertia = (sympy.sympify(x).xreplace(values) if not isinstance(x, tuple)
                                  else tuple(sympy.sympify(v).xreplace(values) for v in x) for x in about_origin(link))
        xx, yy, zz, xy, xz, yz = inertia
        out.update(zip(parameter_symbols(k), (xx, xy, xz, yy, yz, zz, *moments, mass)))
    return out


def random_values(symbols, seed: int) -> dict:
    rng = numpy.random.default_rng(seed)
    return {s: sympy.Rational(int(rng.integers(20, 150)), 100) for s in symbols}


def check_regressor(robot) -> None:
    masses = robot.filled_masses()
    result = regressor(robot.chain, masses, robot.frame_offset + 1)
    program = dynamics_program(robot.chain, masses)
    constants = sorted(robot.chain.symbols - set(robot.chain.joint_variables)
                       | masses.symbols(robot.n, robot.frame_offset + 1), key=str)
    values = random_values(constants, 4)
    pi = standard_values(robot, values)
    motion = [*result.variables, *result.rates, *result.accelerations]
    state = list(numpy.random.default_rng(9).uniform(-2, 2, len(motion)))
    point = {**values, **dict(zip(motion, state))}
    Y = tape_function(result.tape, list(point), list(result.Y))(*[float(v) for v in point.values()])
    torque = tape_function(program.tape, list(point), list(program.outputs["tau"]))(
        *[float(v) for v in point.values()])
    assert numpy.allclose(Y.reshape(robot.n, -1) @ [float(pi[p]) for p in result.parameters], torque)


@pytest.mark.parametrize("name", ["planar2r", "scara", "scara_spong", "stanford", "cylindrical_rpp", "puma560"])
def test_the_regressor_times_the_standard_parameters_is_the_torque(name):
    check_regressor(load(name))


@settings(max_examples=10)
@given(robots(max_joints=3))
def test_the_regressor_of_random_arms_gives_their_torques(robot):
    check_regressor(robot)


@pytest.mark.slow
def test_the_puma_has_36_base_parameters_grouped_as_khalil_groups_them():
    robot = load("puma560")
    base = base_parameters(robot.chain, robot.filled_masses())
    assert len(base.kept) == 36
    assert {"ZZR_1", "XXR_2", "ZZR_2", "MXR_2", "XXR_3", "MYR_3", "XXR_6"} <= set(base.names)
    values = dict(zip(base.names, base.values))
    a2, m3, yy2 = sympy.symbols("a_2 m_3 YY_2", real=True)
    assert values["XXR_2"].coeff(yy2) == -1 and values["ZZR_2"].coeff(m3) == a2**2


@pytest.mark.parametrize("name", ["planar2r", "scara", *(pytest.param(name, marks=pytest.mark.slow)
                                                           for name in ("stanford", "puma560", "ur5"))])
def test_base_parameters_give_the_same_torques(name):
    robot = load(name)
    base = base_parameters(robot.chain, robot.filled_masses())
    result = base.regressor
    symbols = sorted(set(result.parameters) | robot.chain.symbols - set(robot.chain.joint_variables)
                     | {sympy.Symbol("g", real=True)}, key=str)
    values = random_values(symbols, 11)
    motion = [*result.variables, *result.rates, *result.accelerations]
    point = {**values, **dict(zip(motion, numpy.random.default_rng(2).uniform(-2, 2, len(motion))))}
    Y = tape_function(result.tape, list(point), list(result.Y))(*[float(v) for v in point.values()])
    Y = Y.reshape(robot.n, -1)
    full = Y @ [float(values[p]) for p in result.parameters]
    kept = [result.parameters.index(k) for k in base.kept]
    reduced = Y[:, kept] @ [float(value.xreplace(values)) for value in base.values]
    assert numpy.allclose(full, reduced)


def test_a_twist_off_the_quarter_turns_is_refused_for_base_parameters():
    from readers import load_robot_text

    robot = load_robot_text("convention: modified\njoints:\n  - {joint: R, alpha: 0, a: 0, d: 0, theta: q_1}\n"
                            "  - {joint: R, alpha: 0.3, a: 1, d: 0, theta: q_2}\n", "arm.yaml")
    with pytest.raises(UserError, match="multiples of π/2"):
        base_parameters(robot.chain, robot.filled_masses())
