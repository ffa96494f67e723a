"""`dhsym dynamics`: the equations of motion as Spong prints them, the JSON contract read back by
SymPy, the derivation by either method giving the same τ, the regressor, the numpy module, the
refusal of results too large to print, the numbering of a robot whose frames start past 0, and
the notebook object."""
import json
import re

import numpy
import pytest
import sympy
from cli_runner import run_dhsym

from dhsym.api.dynamics import robot_dynamics
from dhsym.core.inertia import tensor
from dhsym.core.verify import check
from dhsym.dynamics.craig_steps import newton_euler_steps
from dhsym.dynamics.derive import MAX_TERMS, derive, printed_terms
from dhsym.dynamics.lagrange_steps import lagrange_steps
from dhsym.dynamics.model import about_origin
from dhsym.io.library import load
from dhsym.io.robotfile import load_robot_text

q1, q2, l1, lc1, lc2, m1, m2, I1, I2, g = sympy.symbols("q_1 q_2 l_1 l_c1 l_c2 m_1 m_2 I_1 I_2 g", real=True)
c2, s2 = sympy.cos(q2), sympy.sin(q2)
h = -m2 * l1 * lc2 * s2  # Spong's h
BOOK_D = [[m1 * lc1**2 + m2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * c2) + I1 + I2, m2 * (lc2**2 + l1 * lc2 * c2) + I2],
          [m2 * (lc2**2 + l1 * lc2 * c2) + I2, m2 * lc2**2 + I2]]
BOOK_PHI = [(m1 * lc1 + m2 * l1) * g * sympy.cos(q1) + m2 * lc2 * g * sympy.cos(q1 + q2),
            m2 * lc2 * g * sympy.cos(q1 + q2)]
SPONG_TEXT = """\
Inertia matrix M(q) = [dij], symmetric (dji = dij):
d11 = I1 + I2 + lc1² m1 + m2(l1² + lc2² + 2 l1 lc2 c2)
d12 = I2 + lc2 m2(lc2 + l1 c2)
d22 = I2 + lc2² m2

Christoffel symbols cijk = ½(∂dkj/∂qi + ∂dki/∂qj − ∂dij/∂qk) that are not zero, by the equation k
they enter (cjik = cijk):
c121 = c211 = −l1 lc2 m2 s2
c221 = −l1 lc2 m2 s2
c112 = l1 lc2 m2 s2

Coriolis and centrifugal matrix C(q, q̇), Ckj = Σi cijk q̇i (the elements that are not zero):
C11 = c211 q̇2 = −l1 lc2 m2 q̇2 s2
C12 = c121 q̇1 + c221 q̇2 = −l1 lc2 m2 s2(q̇1 + q̇2)
C21 = c112 q̇1 = l1 lc2 m2 q̇1 s2

Gravity vector g(q) = ∂P/∂q, φk = ∂P/∂qk:
φ1 = g[c1(l1 m2 + lc1 m1) + lc2 m2 c12]
φ2 = g lc2 m2 c12

Equations of motion τk = Σj dkj q̈j + Σij cijk q̇i q̇j + φk:
τ1 = d11 q̈1 + d12 q̈2 + 2 c121 q̇1 q̇2 + c221 q̇2² + φ1
τ2 = d21 q̈1 + d22 q̈2 + c112 q̇1² + φ2

where c1 = cos q1, c12 = cos(q1 + q2), c2 = cos q2, s2 = sin q2"""
SMALL_ARMS = ["spong_elbow", "planar2r", "cylindrical_rpp", "planar3r", "scara_spong", "spherical_wrist"]
WRIST_FROM_3 = """name: Wrist numbered from 3
convention: modified
first_frame: 3
joints:
  - {joint: R, alpha: 0,     a: 0, d: 0, theta: theta_4}
  - {joint: R, alpha: -pi/2, a: 0, d: 0, theta: theta_5, mass: m_5, com: [0, 0, 0.1]}
"""


def parsed(text: str, names: dict):
    """A JSON expression read back with SymPy, every name a real symbol (the file's names)."""
    return sympy.parse_expr(text, local_dict=names)


def test_spongs_elbow_prints_as_his_book():
    out = run_dhsym("dynamics", "spong_elbow").ok()
    assert out.startswith("Planar elbow manipulator with its masses (Spong): equations of motion  (standard DH)\n")
    assert out.rstrip("\n").endswith(SPONG_TEXT)


def test_the_json_contract_reads_back_as_the_math():
    data = json.loads(run_dhsym("dynamics", "spong_elbow", "--format", "json").ok())
    assert set(data) >= {"robot", "convention", "joint_variables", "velocities", "M", "C", "g", "parameters"}
    assert data["joint_variables"] == ["q_1", "q_2"] and data["velocities"] == ["q_1_dot", "q_2_dot"]
    assert data["parameters"] == ["I_1", "I_2", "g", "l_1", "l_c1", "l_c2", "m_1", "m_2"]
    names = {n: sympy.Symbol(n, real=True) for n in data["joint_variables"] + data["velocities"] + data["parameters"]}
    qd1, qd2 = names["q_1_dot"], names["q_2_dot"]
    book_c = [[h * qd2, h * (qd1 + qd2)], [-h * qd1, 0]]
    for i in range(2):
        assert sympy.expand(parsed(data["g"][i], names) - BOOK_PHI[i]) == 0
        for j in range(2):
            assert sympy.expand(parsed(data["M"][i][j], names) - BOOK_D[i][j]) == 0
            assert sympy.expand(parsed(data["C"][i][j], names) - book_c[i][j]) == 0


@pytest.mark.parametrize("name", ["planar2r", "cylindrical_rpp", "puma560_akb"])
def test_json_of_other_arms_is_the_derived_math_with_decimals_as_written(name):
    args = ["--to", "3"] if name == "puma560_akb" else []
    data = json.loads(run_dhsym("dynamics", name, "--format", "json", *args).ok())
    robot = load(name)
    names = {n: sympy.Symbol(n, real=True) for n in data["joint_variables"] + data["velocities"] + data["parameters"]}
    result = robot_dynamics(robot if not args else _first_links(robot, 3)).result
    for written, value in zip([*sum(data["M"], []), *sum(data["C"], []), *data["g"]], [*result.M, *result.C,
                                                                                        *result.g]):
        assert sympy.expand(parsed(written, names) - value) == 0
    if name == "puma560_akb":  # decimals, not fractions
        assert "1.624569952" in data["M"][1][1] and "/" not in "".join([*sum(data["M"], []), *data["g"]])


def _first_links(robot, k: int):
    from dhsym.dynamics.equations import first_links

    return first_links(robot, k)


@pytest.mark.parametrize("name", SMALL_ARMS)
def test_lagranges_and_newton_eulers_steps_give_the_same_torques(name):
    """τ_k = d/dt ∂L/∂q̇_k − ∂L/∂q_k from the Lagrange records equals Craig's inward τ_k and the
    printed M q̈ + C q̇ + g; the links' energies add up to ½ q̇ᵀ M q̇ and the potential's slope is g."""
    robot = load(name)
    masses = robot.filled_masses()
    result = derive(robot.chain, masses)
    lagrange = lagrange_steps(robot.chain, masses, result)
    craig = newton_euler_steps(robot.chain, masses)
    n, q, qd, qdd = robot.chain.n, result.variables, result.rates, result.accelerations
    derivative = {(d.i, d.j, d.k): d.value for d in lagrange.derivatives}

    def d(i, j, k):
        return derivative.get((min(i, j), max(i, j), k), 0)

    for eq, inward in zip(lagrange.equations, craig.inward):
        k = eq.k
        change = sum(result.M[k - 1, j - 1] * qdd[j - 1] for j in eq.columns)
        change += sum(d(k, j, i) * qd[i - 1] * qd[j - 1] for i, j in eq.changing)
        slope = sum((d(i, j, k) / (2 if i == j else 1)) * qd[i - 1] * qd[j - 1] for i, j in eq.slopes)
        torque = change - slope + result.g[k - 1]
        assert check(torque, result.tau[k - 1]) and check(inward.torque, result.tau[k - 1])
        assert set(eq.changing) == {(i, j) for i in range(1, n + 1) for j in range(1, n + 1) if d(k, j, i) != 0}
    energy = sum(link.kinetic_linear + link.kinetic_angular for link in lagrange.links)
    potential = sum(link.potential for link in lagrange.links)
    kinetic = (sympy.Matrix(qd).T * result.M * sympy.Matrix(qd))[0] / 2
    rng = numpy.random.default_rng(3)
    symbols = sorted((energy + kinetic + potential + sum(result.g)).free_symbols, key=str)
    for _ in range(3):
        point = {s: sympy.Float(rng.uniform(-2, 2)) for s in symbols}
        assert abs(float((energy - kinetic).xreplace(point))) < 1e-9
        for k in range(n):
            assert abs(float((potential.diff(q[k]) - result.g[k]).xreplace(point))) < 1e-9


def test_both_methods_print_the_same_results_after_their_own_derivation():
    lagrange = run_dhsym("dynamics", "scara_spong", "--steps").ok()
    newton = run_dhsym("dynamics", "scara_spong", "--steps", "--method", "newton-euler").ok()
    assert "∂L/∂q̇" not in newton and "∂L/∂θ̇1 = d11 θ̇1" in lagrange
    assert "Inward from the tip" in newton and "¹ω̇₁ = (0, 0, θ̈1)" in newton
    results = [text[text.index("Inertia matrix"):text.index("\nwhere ")] for text in (lagrange, newton)]
    assert results[0] == results[1]


def test_the_regressor_times_the_base_parameters_is_the_torque():
    """Y_b π_b, with π the standard parameters of the file's links about each frame's origin, is τ."""
    robot = load("spong_elbow")
    equations = robot_dynamics(robot)
    found = equations.regressor()
    values = {}
    for k, link in enumerate(robot.filled_masses().links, 1):
        mass, moment, inertia = about_origin(link)
        names = [f"{p}_{k}" for p in ("XX", "YY", "ZZ", "XY", "XZ", "YZ")]
        values.update({sympy.Symbol(n, real=True): x for n, x in zip(names, inertia)})
        values.update({sympy.Symbol(f"M{a}_{k}", real=True): x for a, x in zip("XYZ", moment)})
        values[sympy.Symbol(f"m_{k}", real=True)] = mass
    for k in range(robot.chain.n):
        torque = sum(column.values[k] * column.parameter.value.xreplace(values) for column in found.columns)
        assert check(torque, equations.tau()[k])
    text = run_dhsym("dynamics", "spong_elbow", "--regressor").ok()
    assert "ZZR1 = ZZ1 − l1² m1 − l1² m2\n" in text and "∂τ/∂ZZR1 = (q̈1, 0)\n" in text


def test_the_module_computes_what_the_equations_say():
    robot = load("spong_elbow")
    equations = robot_dynamics(robot)
    namespace: dict = {}
    exec(compile(run_dhsym("dynamics", "spong_elbow", "--format", "python").ok(), "elbow.py", "exec"), namespace)
    rng = numpy.random.default_rng(1)
    state = [rng.uniform(-2, 2, 2) for _ in range(3)]
    point = dict(zip(equations.variables, state[0])) | dict(zip(equations.rates, state[1])) | \
        dict(zip(equations.accelerations, state[2])) | dict(robot.sample)
    expected = [float(x.xreplace(point)) for x in equations.tau()]
    assert numpy.allclose(namespace["tau"](*state), expected) and numpy.allclose(equations.tau(*state), expected)
    assert numpy.allclose(namespace["qdd"](state[0], state[1], expected), state[2])


def test_too_large_to_print_is_refused_at_once_with_what_fits():
    result = run_dhsym("dynamics", "puma560")
    assert result.status == 2 and result.stdout == "" and len(result.stderr.splitlines()) == 1
    fits = int(re.search(r"ask for --to (\d+) \(", result.stderr).group(1))
    assert "--format python, which needs no printing" in result.stderr
    robot = load("puma560")
    assert printed_terms(_first_links(robot, fits).chain, _first_links(robot, fits).filled_masses())[2] <= MAX_TERMS
    wider = _first_links(robot, fits + 1)
    assert printed_terms(wider.chain, wider.filled_masses())[2] > MAX_TERMS
    latex = run_dhsym("latex", "puma560", "--dynamics")
    assert latex.status == 2 and f"ask for dhsym dynamics puma560 --to {fits} (" in latex.stderr
    assert run_dhsym("dynamics", "puma560", "--format", "python").status == 0


def test_steps_too_large_to_show_are_refused_with_the_other_method_or_fewer_links():
    result = run_dhsym("dynamics", "puma560_akb", "--steps", "--method", "newton-euler")
    assert result.status == 2 and "ask for fewer links (--to), or --method lagrange" in result.stderr


def test_a_robot_numbered_from_frame_3_prints_its_own_joint_numbers():
    robot = load_robot_text(WRIST_FROM_3, "wrist.yaml")
    out = robot_dynamics(robot).text()
    assert "d44 = " in out and "d55 = " in out and "τ5 = d54 θ̈4 + d55 θ̈5" in out and "d11" not in out
    assert "c445 = " in out and "φ5 = " in out
    assert set(robot_dynamics(robot).christoffel) <= {(i, j, k) for i in (4, 5) for j in (4, 5) for k in (4, 5)}
    data = robot_dynamics(robot).json()
    assert {(c["i"], c["j"], c["k"]) for c in data["christoffel"]} == set(robot_dynamics(robot).christoffel)
    steps = robot_dynamics(robot).text(steps=True)
    assert "Link 4\nrc4 = " in steps and "∂L/∂θ̇5 = d54 θ̇4 + d55 θ̇5" in steps


def test_ascii_output_is_ascii():
    for args in (["--steps"], ["--steps", "--method", "newton-euler"], ["--regressor"]):
        assert run_dhsym("dynamics", "spong_elbow", "--ascii", *args).ok().isascii()


def test_the_published_puma_table_is_used_with_a_warning_that_names_the_inequality():
    result = run_dhsym("table", "puma560_akb")
    assert result.status == 0
    assert result.stderr.endswith("joint row 3 inertia: Ixx + Izz ≥ Iyy fails by 0.0075 (0.066 + 0.0125 < 0.086), "
                                  "8.7 % of Iyy: no body has exactly these moments; used as written, as a measured "
                                  "table's may miss by up to 10 % (more is refused)\n")


def test_the_notebook_object():
    equations = robot_dynamics(load("spong_elbow"))
    assert equations.M == equations.M.T and equations.christoffel[1, 2, 1] == equations.christoffel[2, 1, 1]
    assert "c_{121} = c_{211}" in equations.latex().latex and "\\text{" in equations._repr_latex_()
    assert equations.code().startswith('"""Dynamics of Planar elbow manipulator')
    tau = equations.tau(numpy.zeros((4, 2)), numpy.zeros((4, 2)), numpy.zeros((4, 2)), g=0.0)
    assert tau.shape == (4, 2) and not tau.any()
    assert tensor(load("spong_elbow").filled_masses().links[0].inertia)[2, 2] == I1


def test_the_notebook_object_takes_the_first_links_and_shows_elements_by_name():
    import dhsym
    from dhsym.errors import UserError

    arm = dhsym.equations_of_motion(load("stanford"), to=3)
    assert arm.robot.name == "Stanford manipulator (RRP + spherical wrist), to frame 3" and arm.M.shape == (3, 3)
    assert arm.text() == run_dhsym("dynamics", "stanford", "--to", "3").stdout.rstrip("\n")
    elbow = robot_dynamics(load("spong_elbow"))
    shown = elbow.show("d22", "phi2").latex
    assert "d_{22} &= I_{2} + l_{c2}^{2} m_{2}" in shown and "\\phi_{2} &= g l_{c2} m_{2} c_{12}" in shown
    assert "\\dot{M} - 2C = " in elbow.matrix(sympy.zeros(2, 2), "\\dot{M} - 2C").latex
    with pytest.raises(UserError, match="no element d33 in these equations; they have d11, d12, d22, c121"):
        elbow.show("d33")
    with pytest.raises(UserError, match="to=3: the last frame whose link moves is one of 1..2"):
        dhsym.equations_of_motion(load("spong_elbow"), to=3)


def test_the_puma_prints_its_christoffel_symbols_in_c_s_notation():
    robot = load("puma560_akb")
    result = derive(robot.chain, robot.filled_masses())
    printed = [*result.M, *result.g, *result.christoffel.values()]
    angles = {f.args[0] for value in printed for f in value.atoms(sympy.sin, sympy.cos)}
    assert all(term.as_coeff_Mul()[0] in (1, -1) for angle in angles for term in sympy.Add.make_args(angle)
               if term.free_symbols), angles  # no sin(2θ2 + θ3): c2 s23 + s2 c23 as the book writes it
    program, symbols, _ = printed_terms(robot.chain, robot.filled_masses())
    for key in [(1, 2, 1), (1, 1, 2)]:
        verdict = check(result.christoffel[key], program.tape.expanded(symbols[key]))
        assert verdict and verdict.algebraic, key
