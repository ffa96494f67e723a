"""`dhsym ik` on robot files that write their lengths as decimals: every surface writes the
decimals as the file did (no 20000 px s1/1646), the JSON reads back equal to the exact solution,
every branch still reaches FK(q); and `evaluate()` is the generated module, run."""
import json
import random

import numpy as np
import pytest
import sympy
from ik_checks import check_branches_reach, check_json, import_module, numeric_fk, random_joints

from dhsym import load
from dhsym.api.ik import inverse_kinematics
from dhsym.core.numbers import decimal_text
from dhsym.inverse.evaluate import evaluate
from dhsym.inverse.written import Written, exact

UR5_IN_NUMBERS = """name: UR5 with its numbers in the table
convention: standard
joints:
  - {joint: R, alpha: pi/2,  a: 0,        d: 0.089159, theta: theta_1}
  - {joint: R, alpha: 0,     a: -0.425,   d: 0,        theta: theta_2}
  - {joint: R, alpha: 0,     a: -0.39225, d: 0,        theta: theta_3}
  - {joint: R, alpha: pi/2,  a: 0,        d: 0.10915,  theta: theta_4}
  - {joint: R, alpha: -pi/2, a: 0,        d: 0.09465,  theta: theta_5}
  - {joint: R, alpha: 0,     a: 0,        d: 0.0823,   theta: theta_6}
"""
# a PUMA-like arm of our own: a_2 and d_4 the same number, a shoulder offset, a tool and a base
DECIMAL_ARM = """name: decimal arm
convention: modified
joints:
  - {joint: R, alpha: 0,     a: 0,      d: 0,     theta: q_1}
  - {joint: R, alpha: -pi/2, a: 0,      d: 0.125, theta: q_2}
  - {joint: R, alpha: 0,     a: 0.4318, d: 0,     theta: q_3}
  - {joint: R, alpha: -pi/2, a: 0.02,   d: 0.4318, theta: q_4}
  - {joint: R, alpha: pi/2,  a: 0,      d: 0,     theta: q_5}
  - {joint: R, alpha: -pi/2, a: 0,      d: 0,     theta: q_6}
base: [{Tz: 0.67}]
tool: [{Tz: 0.056}]
"""
_SOLVED: dict = {}


def solved(text: str, tmp_path_factory):
    if text not in _SOLVED:
        path = tmp_path_factory.mktemp("robots") / "arm.yaml"
        path.write_text(text)
        chain = load(str(path))
        _SOLVED[text] = chain, inverse_kinematics(chain)
    return _SOLVED[text]


@pytest.mark.slow
@pytest.mark.parametrize("text", [UR5_IN_NUMBERS, DECIMAL_ARM], ids=["ur5", "decimal arm"])
def test_text_latex_and_python_write_the_decimals_of_the_file(text, tmp_path_factory):
    chain, result = solved(text, tmp_path_factory)
    printed = result.text(100)
    latex = result.latex()._repr_latex_()
    code = result.code()
    for output in (printed, latex, code):
        assert not any(len(str(q)) > 2 for q in _denominators(output)), output  # no 20000 px s1/1646
    written = {decimal_text(abs(value)) for row in chain.rows for value in (row.a, row.d)
               if value.is_Rational and value}
    assert written and all(number in printed and number in code for number in written), written
    assert "def ik(T):" in code  # the numbers are in the code, not keyword arguments


def test_the_ur5_in_numbers_reads_like_the_ur5_in_names(tmp_path_factory):
    _, result = solved(UR5_IN_NUMBERS, tmp_path_factory)
    printed = result.text(100)
    assert "C    = (px s1 − py c1 − 0.10915)/0.0823" in printed  # C: a projection, not the law of cosines' D
    assert "atan2(px − 0.0823 r13, 0.0823 r23 − py)" in printed
    # a2² + a3² and 2 a2 a3 by the file's rule: a product of two decimals is a decimal
    assert "D    = (X² + Y² − 0.3344850625)/0.3334125" in printed


@pytest.mark.slow
@pytest.mark.parametrize("text", [UR5_IN_NUMBERS, DECIMAL_ARM], ids=["ur5", "decimal arm"])
def test_json_reads_back_equal_to_the_exact_solution(text, tmp_path_factory):
    chain, result = solved(text, tmp_path_factory)
    data = check_json(json.dumps(result.json()), chain)
    expressions = [(e, v) for (_, e), (_, v) in zip(data["definitions"], result.definitions, strict=True)]
    for branch, solution in zip(data["solutions"], result.branches, strict=True):
        expressions += [(e, v) for (_, e), (_, v) in zip(branch["assignments"], solution.assignments, strict=True)]
    assert any("0.0823*" in e or "0.4318" in e for e, _ in expressions)
    rng = random.Random(5)
    for written, value in expressions:
        back = sympy.sympify(written, rational=True)  # the decimals exactly as written
        truth = exact(value)
        assert not any(isinstance(s, Written) for s in truth.free_symbols)
        names = {s.name: s for s in truth.free_symbols}
        assert {s.name for s in back.free_symbols} == set(names), written
        for _ in range(3):
            point = {s: rng.uniform(-0.9, 0.9) for s in truth.free_symbols}
            at = {s: point[names[s.name]] for s in back.free_symbols}
            a, b = complex(back.evalf(subs=at)), complex(truth.evalf(subs=point))
            assert abs(a - b) <= 1e-9 * (1 + abs(b)), (written, a, b)


@pytest.mark.parametrize("text", [UR5_IN_NUMBERS, DECIMAL_ARM], ids=["ur5", "decimal arm"])
def test_every_branch_still_reaches_fk(text, tmp_path_factory, tmp_path):
    chain, result = solved(text, tmp_path_factory)
    path = tmp_path / "arm_ik.py"
    path.write_text(result.code())
    joints = random_joints(chain, np.random.default_rng(7), 8)
    check_branches_reach(import_module(path).ik, chain, {}, joints)
    check_branches_reach(result.evaluate, chain, {}, joints)


@pytest.mark.slow
@pytest.mark.parametrize("robot", ["puma560", "ur5", "planar2r"])
def test_evaluate_is_the_generated_module_with_nan_where_a_branch_does_not_exist(robot, tmp_path):
    chain = load(robot)
    result = chain.ik()
    path = tmp_path / f"{robot}_ik.py"
    path.write_text(result.code())
    module = import_module(path)
    constants = {str(k): float(v) for k, v in chain.sample.items()}
    fk = numeric_fk(chain, constants)
    poses = np.array([np.array(fk(*q), dtype=float) for q in random_joints(chain, np.random.default_rng(3), 20)])
    far = np.eye(4)
    far[:3, 3] = 100.0
    poses = np.concatenate([poses, far[None]])
    generated, evaluated = module.ik(poses), result.evaluate(poses)
    assert np.array_equal(generated, evaluated, equal_nan=True)  # the same code, not two that agree
    assert np.isnan(evaluated[-1]).all()  # out of reach: no branch
    reached = np.isfinite(evaluated[:-1]).all(axis=-1)
    assert reached.any(axis=1).all()
    assert (np.isnan(evaluated[:-1]).all(axis=-1) | reached).all()  # a branch exists whole or not at all
    assert np.array_equal(module.ik(poses[0]), result.evaluate(poses[0]), equal_nan=True)


def test_evaluate_asks_for_a_free_joint_and_takes_constants_by_name_or_symbol():
    from dhsym.errors import UserError

    chain = load("planar2r")
    result = chain.ik()
    pose = np.eye(4)
    pose[:2, 3] = [0.8, 0.0]
    a_1, a_2 = sorted(chain.sample, key=str)
    by_name = result.evaluate(pose, **{a_1.name: 0.5, a_2.name: 0.3})  # a_1 + a_2 = 0.8: stretched out
    by_symbol = evaluate(result.solution, pose, {a_1: 0.5, a_2: 0.3})
    assert np.allclose(by_name, 0) and np.allclose(by_symbol, 0)
    assert not np.allclose(np.nan_to_num(result.evaluate(pose)), 0)  # the sample lengths, 0.5 and 0.4, bend
    iiwa = load("iiwa7").ik(free=["theta_3"])
    with pytest.raises(UserError, match="no value for theta_3"):
        iiwa.evaluate(np.eye(4))


def _denominators(text: str) -> list[int]:
    """The integers that follow a '/' in a text (fractions such as 2183/1646)."""
    import re

    return [int(m) for m in re.findall(r"/\(?(\d+)(?![.\d])", text)]


OFFSET_ARM = """name: planar 3R with decimal offsets
convention: standard
joints:
  - {{joint: R, theta: q_1 + {first}, d: 0, a: 0.3, alpha: 0}}
  - {{joint: R, theta: q_2 - {second}, d: 0, a: 0.25, alpha: 0}}
  - {{joint: R, theta: q_3 + 0.5, d: 0, a: 0.1, alpha: 0}}
"""


@pytest.mark.parametrize("first, second, constant", [("0.25", "0.125", "0.625"),
                                                     ("0.1234567", "0.7654321", "0.1419754")])
def test_a_sum_of_the_files_offsets_prints_as_a_decimal(first, second, constant, tmp_path):
    # q3 = φ1 − q1 − q2 − (its offsets): the constant is the file's decimals added, not the algebra's
    # own fraction (it printed as 5/8, and a 16-digit fraction on the SO-100)
    path = tmp_path / "offsets.yaml"
    path.write_text(OFFSET_ARM.format(first=first, second=second))
    text = str(inverse_kinematics(load(str(path))).text())
    assert f"{constant}" in next(line for line in text.splitlines() if line.strip().startswith("q3 ="))
