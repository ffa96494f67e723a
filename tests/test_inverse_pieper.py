"""Pieper's method for an arm with a spherical wrist whose position problem has no sub-problem
(general twists): the quartic's roots by radicals on their own (exactly, and in the generated
numpy code against numpy.roots), random general arms in both conventions round-tripping, and the
general arm of a robot file with decimals through every output of the CLI."""
import json
import random
import re
import shutil
import subprocess

import ik_checks
import mpmath
import numpy as np
import pytest
import sympy
from cli_runner import run_dhsym
from hypothesis import given, settings
from hypothesis import strategies as st
from ik_checks import derived as solve
from ik_checks import said
from strategies import length_drawer
from test_inverse_robots import check_round_trip

from dhsym import Chain, DHRow, Robot, Step
from dhsym.core.chain import DHRow as Row
from dhsym.core.numbers import decimal_text
from dhsym.geometry.convert import convert_robot
from dhsym.inverse.codegen import module_text
from dhsym.inverse.quartic import Complex, ferrari, root, written_out
from dhsym.inverse.solution import Branch, Solution
from dhsym.inverse.written import Written, exact

GENERAL = """name: general Pieper arm
convention: standard
joints:
  - {joint: R, d: 0.3, a: 0.2, alpha: pi/3, theta: theta_1}
  - {joint: R, d: 0.1, a: 0.5, alpha: pi/4, theta: theta_2}
  - {joint: R, d: 0.0, a: 0.1, alpha: pi/2, theta: theta_3}
  - {joint: R, d: 0.4, a: 0, alpha: -pi/2, theta: theta_4}
  - {joint: R, d: 0, a: 0, alpha: pi/2, theta: theta_5}
  - {joint: R, d: 0.1, a: 0, alpha: 0, theta: theta_6}
"""
# the same arm written with names, its numbers the sample
NAMED = """name: general Pieper arm with names
convention: standard
joints:
  - {joint: R, d: d_1, a: a_1, alpha: pi/3, theta: theta_1}
  - {joint: R, d: d_2, a: a_2, alpha: pi/4, theta: theta_2}
  - {joint: R, d: 0, a: a_3, alpha: pi/2, theta: theta_3}
  - {joint: R, d: d_4, a: 0, alpha: -pi/2, theta: theta_4}
  - {joint: R, d: 0, a: 0, alpha: pi/2, theta: theta_5}
  - {joint: R, d: d_6, a: 0, alpha: 0, theta: theta_6}
sample: {d_1: 0.3, a_1: 0.2, d_2: 0.1, a_2: 0.5, a_3: 0.1, d_4: 0.4, d_6: 0.1}
"""
SIGNS = [(1, 1), (1, -1), (-1, 1), (-1, -1)]


@settings(max_examples=8)
@given(st.lists(st.integers(-9, 9), min_size=4, max_size=4, unique=True), st.integers(1, 5), st.sampled_from([1, -1]))
def test_the_four_roots_by_radicals_are_the_quartics_roots_exactly(roots, scale, sign):
    u = sympy.Symbol("u")
    quartic = sympy.Poly(sign * scale * sympy.prod([2 * u - r for r in roots]), u)
    definitions, expression = ferrari(quartic.all_coeffs())
    found = [_precise(written_out(definitions, root(expression, a, b))) for a, b in SIGNS]
    assert all(abs(value.imag) < 1e-30 for value in found)
    assert np.allclose(sorted(float(value.real) for value in found), sorted(r / 2 for r in roots), rtol=0, atol=1e-30)


def _precise(expression):
    """The value of a constant expression with 60 digits (mpmath), complex on the way as it must be."""
    with mpmath.workdps(60):
        return mpmath.mpc(sympy.lambdify([], expression, "mpmath")())


def test_a_quartic_in_u_squared_alone_has_its_own_formula():
    u = sympy.Symbol("u")
    definitions, expression = ferrari(sympy.Poly((u ** 2 - 4) * (u ** 2 - 9), u).all_coeffs())
    assert "w" not in {str(name) for name, _ in definitions}  # no resolvent cubic: q = 0
    found = sorted(float(_precise(written_out(definitions, root(expression, a, b))).real) for a, b in SIGNS)
    assert found == [-3, -2, 2, 3]


def _quartic_module():
    """The generated numpy module of a one-joint 'solution' whose joint is 2 atan(u) for each root u
    of the quartic with the coefficients r11, r12, r13, px, r21: the numerics of every Pieper arm."""
    theta = sympy.Symbol("theta_1", real=True)
    arm = Chain([DHRow.revolute(theta)], "standard")
    r11, r12, r13, px, r21 = sympy.symbols("r11 r12 r13 px r21", real=True)
    definitions, expression = ferrari([r11, r12, r13, px, r21])
    u = Complex("u")
    branches = tuple(Branch(f"root {k}", ((u, root(expression, a, b)), (theta, sympy.atan2(2 * u, 1 - u ** 2))))
                     for k, (a, b) in enumerate(SIGNS, 1))
    namespace: dict = {}
    exec(compile(module_text(Solution(arm, "quartic", (theta,), tuple(definitions), branches), "quartic"), "q", "exec"),
         namespace)
    return namespace["ik"]


def _poses(coefficients):
    poses = np.zeros((len(coefficients), 4, 4))
    poses[:, 0, :4] = coefficients[:, :4]
    poses[:, 1, 0] = coefficients[:, 4]
    return poses


def test_the_generated_code_finds_every_real_root_that_numpy_roots_finds():
    ik = _quartic_module()
    rng = np.random.default_rng(16)
    separated = np.array([np.poly(rng.choice(np.linspace(-4, 4, 41), 4, replace=False)) * rng.uniform(0.2, 3)
                          * rng.choice([-1, 1]) for _ in range(300)])
    general = rng.normal(size=(300, 5))
    coefficients = np.vstack([separated, general])
    found = np.tan(ik(_poses(coefficients))[:, :, 0] / 2)
    for c, values in zip(coefficients, found):
        reference = np.roots(c)
        real = np.sort(reference[np.abs(reference.imag) < 1e-9].real)
        apart = [x for x in real if np.sort(np.abs(reference - x))[1] > 1e-3]  # well-conditioned roots
        ours = values[np.isfinite(values)]
        for x in apart:
            assert np.abs(ours - x).min() < 1e-7 * (1 + abs(x)), (c, x, values)
        scale = np.polyval(np.abs(c), np.abs(ours)) + 1e-6 * np.abs(c).max()  # a root at 0: the terms vanish
        assert np.all(np.abs(np.polyval(c, ours)) <= 1e-8 * scale), (c, values)
        assert len(ours) in (0, 2, 4) and len(ours) >= len(apart)
    assert np.isfinite(found[:300]).all()  # four real roots: four branches


def test_one_pose_in_plain_floats_gives_the_batch_values_of_the_quartic():
    """One pose takes the module's `math`/`cmath` path (called here directly: it raises where ik()
    would fall back to numpy); a root that is not real is NaN there too."""
    ik = _quartic_module()
    one_pose = ik.__globals__["one_pose"]
    rng = np.random.default_rng(27)
    poses = _poses(np.vstack([rng.normal(size=(40, 5)), [[1, 0, -5, 0, 4], [1, -10, 35, -50, 24]]]))
    batch = ik(poses)
    alone = np.array([one_pose(pose) for pose in poses])
    assert np.array_equal(np.isnan(alone), np.isnan(batch)) and np.isnan(batch).any() and np.isfinite(batch).any()
    assert np.allclose(alone, batch, atol=1e-9, equal_nan=True)
    assert np.array_equal(np.array([ik(pose) for pose in poses]), alone, equal_nan=True)


TWISTS = [sympy.pi / 3, sympy.pi / 4, -sympy.pi / 3, 2 * sympy.pi / 3, -sympy.pi / 6]


@st.composite
def general_arms(draw):
    """Six revolute joints, a spherical wrist, an arm with twists that are not 0 or ±90°, shoulder
    offset a1 ≠ 0: no sub-problem solves its position, Pieper's quartic does."""
    length, sample = length_drawer(draw)

    half = sympy.pi / 2
    offset = lambda: draw(st.sampled_from([0, 0, half, -sympy.pi / 6]))  # noqa: E731
    q = sympy.symbols("q_1:7", real=True)
    rows = [Row.revolute(q[0] + offset(), d=length(), a=length(False), alpha=draw(st.sampled_from(TWISTS)),
                         variable=q[0]),
            Row.revolute(q[1] + offset(), d=length(), a=length(False), alpha=draw(st.sampled_from(TWISTS)),
                         variable=q[1]),
            Row.revolute(q[2] + offset(), a=length(), alpha=draw(st.sampled_from([half, -half])), variable=q[2]),
            Row.revolute(q[3] + offset(), d=length(False), alpha=-half, variable=q[3]),
            Row.revolute(q[4] + offset(), alpha=half, variable=q[4]),
            Row.revolute(q[5] + offset(), d=length(), variable=q[5])]
    base = draw(st.sampled_from([[], [Step("Tz", sympy.Rational(1, 4))], [Step("Rz", half), Step("Tx", length())]]))
    tool = draw(st.sampled_from([[], [Step("Tz", length())],
                                 [Step("Rx", sympy.pi), Step("Tz", sympy.Rational(1, 10))]]))
    plain = Chain(rows, "standard", base=base, tool=tool)
    used = {symbol: value for symbol, value in sample.items() if symbol in plain.symbols}
    return convert_robot(Robot(plain, name="random general arm", sample=used),
                         draw(st.sampled_from(["standard", "modified"])))


@pytest.mark.slow  # seconds of algebra per arm
@settings(max_examples=3)
@given(general_arms(), st.integers(0, 10 ** 6))
def test_random_general_arms_with_a_spherical_wrist_round_trip(chain, seed):
    solution = solve(chain)
    assert "as Pieper solved them" in said(solution.method)
    assert len(solution.branches) == 8 and len({b.name for b in solution.branches}) == 8
    check_round_trip(chain, solution, random.Random(seed), trials=3)


@pytest.fixture(scope="module")
def general_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("pieper") / "general.yaml"
    path.write_text(GENERAL, encoding="utf-8")
    return path


@pytest.mark.slow
def test_the_general_arm_of_a_robot_file_through_every_output(general_file, tmp_path):
    text = run_dhsym("ik", str(general_file)).ok()
    assert "as Pieper solved them" in text and "quartic root 4, wrist flipped" in text
    assert "A4 =" in text and "θ3 = atan2(2 u, 1 − u²)" in text
    chain = _loaded(general_file)
    data = ik_checks.check_json(run_dhsym("ik", str(general_file), "--format", "json").ok(), chain)
    assert [b["name"] for b in data["solutions"]][:2] == ["quartic root 1, wrist not flipped",
                                                        "quartic root 1, wrist flipped"]
    assert dict(data["definitions"])["x_c"] == "px - 0.1*r13"  # decimals as written
    module_path = tmp_path / "general_ik.py"
    module_path.write_text(run_dhsym("ik", str(general_file), "--format", "python").ok(), encoding="utf-8")
    module = ik_checks.import_module(module_path)
    rng = np.random.default_rng(3)
    ik_checks.check_branches_reach(module.ik, chain, ik_checks.sample_constants(chain),
                                   ik_checks.random_joints(chain, rng, 20))
    assert "\\mathrm{atan2}" in run_dhsym("ik", str(general_file), "--format", "latex").ok()
    document = run_dhsym("latex", str(general_file), "--ik").ok()
    if shutil.which("pdflatex"):
        (tmp_path / "general.tex").write_text(document, encoding="utf-8")
        result = subprocess.run(["pdflatex", "-halt-on-error", "-interaction=nonstopmode", "-no-shell-escape",
                                 "general.tex"], cwd=tmp_path, capture_output=True, text=True, timeout=600)
        assert result.returncode == 0, result.stdout[-2000:]


@pytest.fixture(scope="module")
def general_ik(general_file):
    chain = _loaded(general_file)
    return chain, chain.ik()


def test_many_poses_at_once_every_real_branch_reaches_fk_to_1e_9(general_ik):
    chain, ik = general_ik
    fk = ik_checks.numeric_fk(chain, ik_checks.sample_constants(chain))
    joints = ik_checks.random_joints(chain, np.random.default_rng(9), 100)
    poses = np.array([np.array(fk(*q), dtype=float) for q in joints])
    found = ik.evaluate(poses)
    assert found.shape == (100, 8, 6)
    counts = set()
    for q, pose, branches in zip(joints, poses, found):
        existing = branches[np.isfinite(branches).all(axis=1)]
        counts.add(len(existing))
        for values in existing:
            assert np.abs(np.array(fk(*values), dtype=float) - pose).max() < 1e-9
        assert (np.abs(np.angle(np.exp(1j * (existing - q)))).max(axis=1) < 1e-6).any()
    assert counts <= {2, 4, 6, 8} and 8 in counts  # two or four real roots of the quartic, two wrists each
    quartics = _coefficients(ik.solution, poses)
    for c, branches in zip(quartics, found):  # every real root that numpy.roots finds is a branch
        roots = np.roots(c)
        real = roots[np.abs(roots.imag) < 1e-9].real
        ours = np.tan(branches[np.isfinite(branches).all(axis=1), 2] / 2)
        for x in real:
            assert np.abs(ours - x).min() < 1e-6 * (1 + abs(x)), (c, real, ours)
    json.dumps(ik.json())  # the API's JSON is plain data


def _coefficients(solution, poses):
    """A₄ … A₀ of the quartic at each pose, from the solution's definitions in numbers (real ones only)."""
    values = {sympy.Symbol(name, real=True): poses[:, k // 4, k % 4] for k, name in enumerate(ik_checks.TARGET_NAMES)}
    for name, expression in solution.definitions:
        if name.name == "p":
            break
        function = sympy.lambdify(list(values), exact(expression), "numpy")
        values[name] = function(*values.values()) * np.ones(len(poses))
    return np.stack([values[sympy.Symbol(f"A_{k}", real=True)] for k in range(4, -1, -1)], axis=1)


def _loaded(path):
    from dhsym import load

    return load(str(path))


@pytest.mark.parametrize("convention", ["modified", pytest.param("standard", marks=pytest.mark.slow)])
def test_a_general_arm_after_a_wrist_at_the_start_is_solved_from_the_end(convention):
    q = sympy.symbols("q_1:7", real=True)
    lengths = sympy.symbols("L_1:5", real=True)
    half, tenth = sympy.pi / 2, sympy.Rational(1, 10)
    rows = [Row.revolute(q[0], d=3 * tenth, alpha=-half), Row.revolute(q[1], alpha=half),
            Row.revolute(q[2], d=lengths[0], a=tenth, alpha=sympy.pi / 3),
            Row.revolute(q[3], d=2 * tenth, a=lengths[1], alpha=sympy.pi / 4),
            Row.revolute(q[4], a=lengths[2], alpha=half), Row.revolute(q[5], d=lengths[3])]
    sample = {symbol: sympy.Rational(k + 3, 10) for k, symbol in enumerate(lengths)}
    chain = convert_robot(Robot(Chain(rows, "standard"), name="wrist first", sample=sample), convention)
    solution = solve(chain)
    assert "seen from the last frame gives q_4, q_5, q_6 as Pieper solved them: a quartic in tan(θ4/2)" \
        in said(solution.method)
    assert solution.branches[0].name == "quartic root 1, wrist not flipped"
    check_round_trip(chain, solution, random.Random(4), trials=3)


def test_the_json_evaluated_by_sympy_gives_q_and_every_step_of_the_derivation_holds(general_ik):
    chain, ik = general_ik
    data = ik.json()
    q = [0.4, -0.7, 1.1, 0.3, -0.9, 2.0]
    fk = ik_checks.numeric_fk(chain, ik_checks.sample_constants(chain))
    pose = np.array(fk(*q), dtype=float)
    values = {sympy.Symbol(name): sympy.Float(pose[k // 4, k % 4], 30)
              for k, name in enumerate(ik_checks.TARGET_NAMES)}
    for name, expression in data["definitions"]:  # complex on the way where the quartic needs it
        values[sympy.Symbol(name)] = sympy.sympify(expression).xreplace(values).evalf(30)
    arms = []  # the arm's joints of each branch: the assignments up to theta_1 (the wrist's come after)
    for branch in data["solutions"]:
        known = dict(values)
        for name, expression in branch["assignments"]:
            known[sympy.Symbol(name)] = sympy.sympify(expression).xreplace(known).evalf(30)
            if name == "theta_1":
                break
        joints = [complex(known[sympy.Symbol(v)]) for v in data["joint_variables"][:3]]
        if all(abs(j.imag) < 1e-12 for j in joints):
            arms.append(([j.real for j in joints], known))
    assert len(arms) in (4, 8)  # two or four real roots, each with both wrists
    match = [known for joints, known in arms
             if np.allclose(np.angle(np.exp(1j * (np.array(joints) - q[:3]))), 0, atol=1e-9)]
    assert match, arms
    steps = [step for step in ik.solution.steps
             if step.subproblem.name in ("Pieper's distance", "Pieper's height", "Ferrari's quartic")
             or step.solves and str(step.solves[0]) in ("theta_1", "theta_2")]
    assert len(steps) == 7
    by_name = {symbol.name: value for symbol, value in match[0].items()}
    for step in steps:  # the equations the derivation prints are true at the pose (its decimals are symbols)
        equation = exact(step.lhs - step.rhs)
        names = {s: by_name[s.name] for s in equation.free_symbols if s.name in by_name}
        difference = complex(equation.xreplace(names).evalf(30))
        assert abs(difference) < 1e-12, step


def test_the_decimal_arm_prints_no_decimal_that_its_file_did_not_write_or_fold(general_ik):
    chain, ik = general_ik
    text, latex = ik.text(100), ik.latex()._repr_latex_()
    solution = ik.solution
    expressions = [value for _, value in solution.definitions] + [step.lhs - step.rhs for step in solution.steps] \
        + [value for branch in solution.branches for _, value in branch.assignments]
    folded = {s for e in expressions for s in e.free_symbols if isinstance(s, Written)}
    written = {decimal_text(value) for value in chain.numbers.values if value}
    assert all(chain.numbers.decimal(s.value) for s in folded)  # folded by the file's rule, 0.38 = 0.2² + 0.5² + …
    for output in (text, latex):
        printed = set(re.findall(r"(?<![\w.])\d+\.\d+", output))
        assert printed and printed <= written | {s.name for s in folded}, printed - written
    assert not re.search(r"\d\.\d+ (s|A3|q)\b", text)  # Ferrari's 1/2 and 1/4 were 0.5 s, 0.25 A3, 0.5 q²
    lines = _printed_lines(text)
    assert lines["u"] == "s/2 + √(−z − 2 p − (2 q)/s)/2 − A3/(4 A4)" and "q²/2" in lines["w"]
    assert "\\frac{s}{2}" in latex and "\\frac{A_{3}}{4 A_{4}}" in latex
    quartic = [lines[f"A{k}"] for k in range(5)]  # one style: 43/400 is no decimal by the file's rule, nor is 9/20
    assert not any(re.search(r"\d\.\d", line) for line in quartic) and "(9 rc zc)/20" in lines["A2"], quartic
    assert "(s1 s2 s3)/2" in lines["C"]  # cos 60° = 1/2, not 0.5 (C: the wrist's cosine from an element)


@pytest.mark.slow  # the named arm's algebra
def test_the_decimal_arm_has_the_shape_of_the_same_arm_written_with_names(general_ik, tmp_path):
    _, ik = general_ik
    path = tmp_path / "named.yaml"
    path.write_text(NAMED, encoding="utf-8")
    named_chain = _loaded(path)
    named_ik = named_chain.ik()
    named = named_ik.solution
    sample = dict(named_chain.sample)
    ours = list(ik.solution.definitions) + list(ik.solution.branches[0].assignments)
    theirs = list(named.definitions) + list(named.branches[0].assignments)
    assert [name for name, _ in ours] == [name for name, _ in theirs]
    assert [b.name for b in ik.solution.branches] == [b.name for b in named.branches]
    for (name, value), (_, expected) in zip(ours, theirs):  # the same quantities, equal at the sample
        assert sympy.expand(exact(value) - expected.xreplace(sample)) == 0, name
    decimal, by_name = _printed_lines(ik.text(100)), _printed_lines(named_ik.text(100))
    length = re.compile(r"\b[ad]\d\b")
    same = [name for name, line in by_name.items() if not length.search(line)]
    assert {"p", "q", "r", "m", "w", "z", "s", "u", "θ3", "θ2", "θ1", "C", "θ4", "θ5", "θ6"} <= set(same)
    assert all(decimal[name] == by_name[name] for name in same), [(decimal[n], by_name[n]) for n in same]
    numbers = {f"{symbol.name[0]}{symbol.name[2:]}": decimal_text(value) for symbol, value in sample.items()}
    for name in ("f1", "f2", "g1"):  # a length alone in a term is its decimal: a2 + a3 c3 + d4 s3 is 0.5 + 0.1 c3 + …
        assert decimal[name] == length.sub(lambda m: numbers[m.group(0)], by_name[name])


def _printed_lines(text):
    """{name: its value as printed, lines joined} for the definitions and the first branch of `dhsym ik`'s text."""
    lines, current = {}, None
    for line in text.split("where\n", 1)[1].split("\n\nBranch 2")[0].splitlines():
        match = re.match(r"  (\S+) += (.*)$", line)
        if match:
            current = match.group(1)
            lines[current] = match.group(2)
        elif current and line.startswith("         "):
            lines[current] += " " + line.strip()
        else:
            current = None
    return lines
