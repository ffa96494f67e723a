"""Dynamics: Spong's planar elbow manipulator as he prints it, the two routes (Lagrange in the
robot's own frames, Newton–Euler and composite bodies in the joint frames) equal on every built-in
arm and on random ones, the properties a student checks (M symmetric and positive definite,
Ṁ − 2C skew-symmetric), the generated module, and the refusal of results too large to print."""
import inspect
from pathlib import Path

import mpmath
import numpy
import pytest
import sympy
from hypothesis import given, settings
from readers import load_robot_file, load_robot_text
from strategies import robots_with_masses

from dhsym import load
from dhsym.core.inertia import LinkInertia, MassModel, tensor
from dhsym.dynamics import lagrange
from dhsym.dynamics.codegen import keyword_names, module_text, tape_function
from dhsym.dynamics.derive import derive
from dhsym.dynamics.polynomial import multiplied_out
from dhsym.dynamics.program import dynamics_program
from dhsym.dynamics.tape import differentiate
from dhsym.errors import UserError
from dhsym.geometry.convert import convert_robot
from dhsym.io.library import builtin_names
from dhsym.io.robotwriter import robot_yaml

SPONG = Path(__file__).parent / "data" / "spong_elbow.yaml"
q1, q2, l1, lc1, lc2, m1, m2, I1, I2, g = sympy.symbols("q_1 q_2 l_1 lc_1 lc_2 m_1 m_2 I_1 I_2 g", real=True)
c2, s2 = sympy.cos(q2), sympy.sin(q2)
h = -m2 * l1 * lc2 * s2  # Spong's h
BOOK_D = {(0, 0): m1 * lc1**2 + m2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * c2) + I1 + I2,
          (0, 1): m2 * (lc2**2 + l1 * lc2 * c2) + I2, (1, 1): m2 * lc2**2 + I2}
BOOK_CHRISTOFFEL = {(1, 2, 1): h, (2, 1, 1): h, (2, 2, 1): h, (1, 1, 2): -h}
BOOK_PHI = [(m1 * lc1 + m2 * l1) * g * sympy.cos(q1) + m2 * lc2 * g * sympy.cos(q1 + q2),
            m2 * lc2 * g * sympy.cos(q1 + q2)]


@pytest.fixture(scope="module")
def spong():
    robot = load_robot_file(SPONG)
    return derive(robot.chain, robot.filled_masses())


def test_spongs_inertia_matrix_is_his_and_no_longer(spong):
    for (i, j), book in BOOK_D.items():
        assert sympy.expand(spong.M[i, j] - book) == 0
        assert spong.M[i, j] == spong.M[j, i]
        assert sympy.count_ops(spong.M[i, j]) <= sympy.count_ops(book)
    assert str(spong.M[0, 0]) == "I_1 + I_2 + lc_1**2*m_1 + m_2*(l_1**2 + 2*l_1*lc_2*cos(q_2) + lc_2**2)"


def test_spongs_christoffel_symbols_and_gravity_are_his(spong):
    assert set(spong.christoffel) == set(BOOK_CHRISTOFFEL)  # c111, c122, c212, c222 are zero
    for key, book in BOOK_CHRISTOFFEL.items():
        assert sympy.expand(spong.christoffel[key] - book) == 0
        assert sympy.count_ops(spong.christoffel[key]) <= sympy.count_ops(book)
    for k, book in enumerate(BOOK_PHI):
        assert sympy.expand(spong.g[k] - book) == 0
        assert sympy.count_ops(spong.g[k]) <= sympy.count_ops(book)
    q1d, q2d = spong.rates
    book_c = sympy.Matrix([[h * q2d, h * q2d + h * q1d], [-h * q1d, 0]])
    assert (spong.C - book_c).applyfunc(sympy.expand) == sympy.zeros(2, 2)


def test_the_equations_of_motion_are_the_lagrangian_derivatives(spong):
    """τ = d/dt ∂L/∂q̇ − ∂L/∂q, worked out by SymPy from K and P written by hand."""
    t = sympy.Symbol("t", real=True)
    a, b = sympy.Function("a")(t), sympy.Function("b")(t)
    vc1 = lc1 * a.diff(t)
    kinetic = (m1 * vc1**2 + m2 * (l1**2 * a.diff(t)**2 + lc2**2 * (a.diff(t) + b.diff(t))**2
                                   + 2 * l1 * lc2 * sympy.cos(b) * a.diff(t) * (a.diff(t) + b.diff(t)))
               + I1 * a.diff(t)**2 + I2 * (a.diff(t) + b.diff(t))**2) / 2
    potential = m1 * g * lc1 * sympy.sin(a) + m2 * g * (l1 * sympy.sin(a) + lc2 * sympy.sin(a + b))
    lagrangian = kinetic - potential
    plain = {a.diff(t, 2): sympy.Symbol("q_1_ddot", real=True), b.diff(t, 2): sympy.Symbol("q_2_ddot", real=True),
             a.diff(t): sympy.Symbol("q_1_dot", real=True), b.diff(t): sympy.Symbol("q_2_dot", real=True),
             a: q1, b: q2}
    for k, x in enumerate((a, b)):
        torque = (lagrangian.diff(x.diff(t)).diff(t) - lagrangian.diff(x)).subs(plain)
        assert sympy.expand(torque - spong.tau[k]) == 0


def values_for(symbols, seed: int) -> dict:
    """Random rational values for the constants, and a physical-looking sample for masses."""
    rng = numpy.random.default_rng(seed)
    return {s: sympy.Rational(int(rng.integers(20, 150)), 100) for s in symbols}


def evaluated(program, values: dict):
    """The generated module's functions with the constants bound to `values`."""
    namespace: dict = {}
    exec(compile(module_text(program, "arm", {}), "arm_dynamics.py", "exec"), namespace)
    keywords = {keyword_names(program)[s.name]: float(v) for s, v in values.items() if s in program.constants()}
    return {name: (lambda f: lambda *args: f(*args, **keywords))(namespace[name])
            for name in ("M", "C", "g", "tau", "qdd")}


def lagrange_torque(chain, masses, values: dict, state) -> numpy.ndarray:
    """τ_k = Σ d_kj q̈_j + Σ (∂d_kj/∂q_i − ½ ∂d_ij/∂q_k) q̇_i q̇_j + ∂P/∂q_k, from the Lagrange records in
    the robot's own frames; the derivatives by central differences in 40-digit arithmetic (exact to
    about 1e-24, far below the comparison's 1e-9)."""
    energies = lagrange.link_energies(chain, masses)
    q = chain.joint_variables
    parts = [sympy.lambdify([q], [e.linear.xreplace(values), (e.rotation.T * e.angular).xreplace(values)], "mpmath")
             for e in energies]
    links = [sympy.lambdify([], [sympy.sympify(link.mass).xreplace(values), tensor(link.inertia).xreplace(values)],
                            "mpmath")() for link in masses.links]
    energy = sympy.lambdify([q], sympy.Add(*[e.potential for e in energies]).xreplace(values), "mpmath")

    def mass(x):
        total = mpmath.zeros(chain.n, chain.n)
        for part, (m, inertia) in zip(parts, links):
            linear, angular = (mpmath.matrix(a) for a in part(x))
            total += m * linear.T * linear + angular.T * mpmath.matrix(inertia) * angular
        return total

    position, rate, acceleration = state
    n = chain.n
    with mpmath.workdps(40):
        x, step = [mpmath.mpf(float(v)) for v in position], mpmath.mpf("1e-12")

        def shifted(k, sign):
            return [v + sign * step if i == k else v for i, v in enumerate(x)]

        d_mass = [(mpmath.matrix(mass(shifted(k, 1))) - mpmath.matrix(mass(shifted(k, -1)))) / (2 * step)
                  for k in range(n)]
        d_energy = [(energy(shifted(k, 1)) - energy(shifted(k, -1))) / (2 * step) for k in range(n)]
        M = mpmath.matrix(mass(x))
        out = []
        for k in range(n):
            total = sum(M[k, j] * acceleration[j] for j in range(n)) + d_energy[k]
            total += sum((d_mass[i][k, j] - d_mass[k][i, j] / 2) * rate[i] * rate[j]
                         for i in range(n) for j in range(n))
            out.append(float(total))
    return numpy.array(out)


def check_both_routes(robot, seed: int = 0) -> None:
    masses = robot.filled_masses()
    program = dynamics_program(robot.chain, masses)
    constants = sorted(set(program.constants()) | (robot.chain.symbols - set(robot.chain.joint_variables))
                       | masses.symbols(robot.n, robot.frame_offset + 1), key=str)
    values = values_for(constants, seed)
    module = evaluated(program, values)
    rng = numpy.random.default_rng(seed + 1)
    state = [rng.uniform(-2, 2, robot.n) for _ in range(3)]
    expected = lagrange_torque(robot.chain, masses, values, state)
    assert numpy.allclose(module["tau"](*state), expected, rtol=1e-9, atol=1e-9)
    M, C, gravity = module["M"](state[0]), module["C"](state[0], state[1]), module["g"](state[0])
    assert numpy.allclose(M @ state[2] + C @ state[1] + gravity, expected, rtol=1e-9, atol=1e-9)
    assert numpy.allclose(module["qdd"](state[0], state[1], expected), state[2], rtol=1e-6, atol=1e-6)


def by_size(names):
    """Arms of five joints or more take seconds each: the fast lane leaves them to `make test`."""
    return [pytest.param(name, marks=pytest.mark.slow) if load(name).n >= 5 else name for name in names]


@pytest.mark.parametrize("name", by_size(builtin_names()))
def test_lagrange_and_newton_euler_agree_on_every_builtin_arm(name):
    check_both_routes(load(name))


@settings(max_examples=10)
@given(robots_with_masses(max_joints=3))
def test_lagrange_and_newton_euler_agree_on_random_arms(robot):
    """Both conventions, prismatic joints, offsets, base and tool, decimals, numbers and names."""
    check_both_routes(robot)


@pytest.mark.parametrize("name", by_size(["puma560", "stanford", "scara_spong", "iiwa7"]))
def test_mass_matrix_is_symmetric_positive_definite_and_passivity_holds(name):
    robot = load(name)
    masses = MassModel(tuple(LinkInertia(sympy.Rational(k + 2, 2), (sympy.Rational(k, 10), 0, sympy.Rational(1, 20)),
                                         (sympy.Rational(1, 10), sympy.Rational(1, 12), sympy.Rational(1, 15), 0, 0, 0))
                             for k in range(robot.n)))
    program = dynamics_program(robot.chain, masses.filled(robot.n))
    tape = program.tape
    M = program.outputs["M"]
    dot = sympy.Matrix(robot.n, robot.n, differentiate(tape, list(M), dict(zip(program.variables, program.rates))))
    values = values_for(program.constants(), 7)
    module = evaluated(program, values)
    rng = numpy.random.default_rng(5)
    for _ in range(3):
        q, qd = rng.uniform(-3, 3, robot.n), rng.uniform(-2, 2, robot.n)
        numbers = M.shape and module["M"](q)
        assert numpy.allclose(numbers, numbers.T) and numpy.linalg.eigvalsh(numbers).min() > 0
        point = {**values, **dict(zip(program.variables, q)), **dict(zip(program.rates, qd))}
        n_matrix = numpy.array(tape.expanded(dot).xreplace(point).evalf(), dtype=float) - 2 * module["C"](q, qd)
        assert numpy.allclose(n_matrix, -n_matrix.T, atol=1e-9)


def test_the_code_computes_many_states_at_once_as_one_by_one():
    robot = load_robot_file(SPONG)
    program = dynamics_program(robot.chain, robot.filled_masses())
    namespace: dict = {}
    exec(compile(module_text(program, robot.name, robot.sample), "spong.py", "exec"), namespace)
    rng = numpy.random.default_rng(2)
    q, qd, qdd = (rng.uniform(-2, 2, (5, 2)) for _ in range(3))
    many = namespace["tau"](q, qd, qdd)
    assert many.shape == (5, 2) and namespace["M"](q).shape == (5, 2, 2)
    assert numpy.allclose(many, [namespace["tau"](*state) for state in zip(q, qd, qdd)])
    with pytest.raises(ValueError, match=r"expected states of shape \(2,\)"):
        namespace["g"]([1.0, 2.0, 3.0])


def test_the_code_makes_only_its_functions_and_joints_public():
    robot = load_robot_file(SPONG)
    namespace: dict = {}
    exec(compile(module_text(dynamics_program(robot.chain, robot.filled_masses()), robot.name, robot.sample),
                 "spong.py", "exec"), namespace)
    public = {name for name, value in namespace.items() if not name.startswith("_") and not inspect.ismodule(value)}
    assert public == {"JOINTS", "M", "C", "g", "tau", "qdd"} == set(namespace["__all__"])
    q, qd = [0.3, -0.7], [1.1, 0.4]
    assert numpy.allclose(namespace["qdd"](q, qd, namespace["tau"](q, qd, [0.5, -2.0])), [0.5, -2.0])


def test_a_chain_too_large_to_print_is_refused_before_it_is_written_out():
    robot = load("puma560")
    with pytest.raises(UserError, match=r"about [\d,]+ terms .* give the links' masses.*--format python"):
        derive(robot.chain, robot.filled_masses())
    assert dynamics_program(robot.chain, robot.filled_masses()).operations("M").total < 773  # SymPyBotics' M


@settings(max_examples=10)
@given(robots_with_masses(max_joints=3))
def test_masses_are_written_back_and_survive_a_change_of_convention(robot):
    again = load_robot_text(robot_yaml(robot), "arm.yaml")
    assert again.masses == robot.masses
    other = "modified" if robot.convention == "standard" else "standard"
    back = convert_robot(convert_robot(robot, other), robot.convention)
    if (back.chain.rows, back.base, back.tool) == (robot.chain.rows, robot.base, robot.tool):
        assert back.masses == robot.masses  # the same frames: the same numbers (a tool's Tx may move into a row)
    robot = robot.replace(masses=robot.filled_masses())  # every value given: the same body in either frame
    converted = convert_robot(robot, other)  # the same robot: the same torques
    first = dynamics_program(robot.chain, robot.filled_masses())
    second = dynamics_program(converted.chain, converted.filled_masses())
    values = values_for(sorted(set(first.constants()) | set(second.constants()), key=str), 3)
    state = [numpy.full(robot.n, 0.3), numpy.full(robot.n, -0.7), numpy.full(robot.n, 1.1)]
    assert numpy.allclose(evaluated(first, values)["tau"](*state), evaluated(second, values)["tau"](*state))


@pytest.mark.parametrize("name", ["planar2r", "cylindrical_rpp", "planar3r", "spong",
                                  pytest.param("scara_spong", marks=pytest.mark.slow),
                                  pytest.param("spherical_wrist", marks=pytest.mark.slow)])
def test_lagrange_equals_newton_euler_by_algebra(name):
    """τ_k = Σ d_kj q̈_j + Σ (∂d_kj/∂q_i − ½ ∂d_ij/∂q_k) q̇_i q̇_j + ∂P/∂q_k with SymPy's derivatives of the
    Lagrange records, minus Newton–Euler's τ, multiplied out: zero."""
    robot = load_robot_file(SPONG) if name == "spong" else load(name)
    chain, masses = robot.chain, robot.filled_masses()
    program = dynamics_program(chain, masses, parts=("tau",))
    energies = lagrange.link_energies(chain, masses)
    M = lagrange.mass_matrix(chain, masses, energies)
    potential = sympy.Add(*[e.potential for e in energies])
    q, qd, qdd, n = chain.joint_variables, program.rates, program.accelerations, chain.n
    differences = []
    for k in range(n):
        torque = sum(M[k, j] * qdd[j] for j in range(n)) + potential.diff(q[k])
        torque += sum((M[k, j].diff(q[i]) - M[i, j].diff(q[k]) / 2) * qd[i] * qd[j] for i in range(n) for j in range(n))
        differences.append(sympy.expand_trig(torque) - program.outputs["tau"][k])
    assert multiplied_out(program.tape, differences) == [0] * n


@settings(max_examples=10)
@given(robots_with_masses(max_joints=3))
def test_textbook_forms_are_the_programs_values(robot):
    """derive's M, C and g, written out and regrouped, are the program's at random points; or the
    robot is refused as too large, at once."""
    masses = robot.filled_masses()
    try:
        result = derive(robot.chain, masses)
    except UserError as error:
        assert "terms multiplied out" in str(error)
        return
    program = dynamics_program(robot.chain, masses)
    symbols = sorted(set(program.constants()) | set(program.variables) | set(program.rates), key=str)
    values = values_for(symbols, 5)
    evaluate = tape_function(program.tape, symbols, [*program.outputs["M"], *program.outputs["C"],
                                                     *program.outputs["g"]])
    expected = evaluate(*[float(values[s]) for s in symbols])
    written = [float(sympy.sympify(x).xreplace(values)) for x in [*result.M, *result.C, *result.g]]
    assert numpy.allclose(written, expected)
    assert result.M == result.M.T
