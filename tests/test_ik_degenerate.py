"""What the printed IK says about where its branches fail: no degenerate case that no reachable
target meets, each place where two roots meet tied to the factor of det J that `dhsym jacobian`
prints and its meaning, every relation an arm of fewer than six joints keeps, and a generated
ik() that gives NaN for a pose such an arm cannot take."""
import importlib.util
import json

import numpy
import pytest
import sympy
from cli_runner import run_dhsym
from ik_checks import numeric_fk, random_joints, sample_constants
from packages import EXAMPLE_ROBOT_DATA
from robots import PITCH_ARM

from dhsym import load
from dhsym.inverse.sentences import Exists, OnAxis, Undetermined
from dhsym.inverse.unreachable import contradicts
from dhsym.latex.ik import snippet

pytestmark = pytest.mark.slow  # real robots solved in closed form: seconds per test


def _ik(*args):
    result = run_dhsym("ik", *args)
    assert result.status == 0, result.stderr
    return result.stdout


def _flat(text: str) -> str:
    return " ".join(text.split())


@pytest.mark.parametrize("name, impossible", [("puma560", "py = 0 and px = 0"), ("stanford", "yc = 0 and xc = 0"),
                                              ("ur5", "d6 r23 − py = 0 and d6 r13 − px = 0")])
def test_a_degenerate_case_no_reachable_target_meets_is_not_printed(name, impossible):
    text = _flat(_ik(name))
    assert "Degenerate:" in text and impossible not in text
    degenerate = json.loads(_ik(name, "--format", "json"))["degenerate"]
    assert not any(case.startswith(impossible.split(" = ")[0].replace(" ", "*")) for case in degenerate)


def test_a_case_stays_where_the_offset_could_be_zero():
    px, py, d2, d3, t1 = sympy.symbols("px py d_2 d_3 theta_1", real=True)
    case = Undetermined((py, px), t1)
    assert contradicts(case, [Exists(px**2 + py**2 - d3**2)], {d3})
    assert not contradicts(case, [Exists(px**2 + py**2 - (d3 - d2)**2)], {d2, d3})  # d3 = d2 reaches it
    assert not contradicts(case, [Exists(px**2 + py**2 + d3**2)], {d3})
    shoulder = Undetermined((px * sympy.cos(t1) + py * sympy.sin(t1), d2), t1)  # not solved for a name: it stays
    assert not contradicts(shoulder, [Exists(px**2 + py**2 - d3**2)], {d3})


def test_the_shoulder_elbow_and_wrist_singularities_are_where_the_roots_meet():
    text = _flat(_ik("puma560"))
    assert ("px² + py² − d3² ≥ 0 (else θ1 has no real value: the target is out of reach); where it is 0 the two "
            "roots meet, a singularity of J: the factor a2 c2 + a3 c23 − d4 s23 of det J, shoulder: the wrist "
            "centre lies in the plane through axis 1 parallel to axis 2") in text
    assert ("a3² + d4² − K² ≥ 0 (else θ3 has no real value: the target is out of reach); where it is 0 the two "
            "roots meet, a singularity of J: the factor d4 c3 + a3 s3 of det J, elbow stretched or folded") in text
    assert "1 − C² ≥ 0 (else θ5 has no real value: the target is out of reach); where it is 0 the two roots meet, " \
           "a singularity of J: the factor s5 of det J, wrist: axes 4 and 6 line up" in text
    jacobian = _flat(run_dhsym("jacobian", "puma560").stdout)  # the same factors as `dhsym jacobian` prints
    for factor in ("a2 c2 + a3 c23 − d4 s23 = 0", "d4 c3 + a3 s3 = 0", "s5 = 0: wrist: axes 4 and 6 line up"):
        assert factor in jacobian
    conditions = json.loads(_ik("puma560", "--format", "json"))["conditions"]
    assert "a singularity of J: the factor a_3*sin(theta_3) + d_4*cos(theta_3) of det J, elbow stretched or " \
           "folded: the wrist centre lies in the plane of axes 2 and 3" in conditions[1]


def test_a_factor_said_to_meet_the_roots_vanishes_where_they_meet():
    # At a pose where the factor is 0 the condition's side is 0 too: the PUMA's elbow stretched (d4 c3 + a3 s3 = 0).
    robot = load("puma560")
    solution = robot.ik().solution
    elbow = next(c for c in solution.conditions if isinstance(c, Exists) and "K" in str(c.expression))
    t3 = robot.joint_variables[2]
    factor = elbow.singular[0].factor
    stretched = sympy.atan2(-factor.coeff(sympy.cos(t3)), factor.coeff(sympy.sin(t3)))
    assert sympy.simplify(factor.subs(t3, stretched)) == 0


def test_stanfords_shoulder_and_the_ur5s_every_meeting_are_factors_of_det_j():
    stanford = _flat(_ik("stanford"))
    assert ("xc² + yc² − d2² ≥ 0 (else θ1 has no real value: the target is out of reach); where it is 0 the two roots "
            "meet, singularities of J: the factors d3 (joint 3 retracted to zero extension) and s2 (axes 1 and 4 are "
            "parallel) of det J") in stanford
    ur5 = _flat(_ik("ur5"))
    for unknown, factor in (("θ1", "a2 c2 + a3 c23 + d5 s234"), ("θ5", "s5"), ("θ3", "s3")):
        said = (f"≥ 0 (else {unknown} has no real value: the target is out of reach); where it is 0 the two roots "
                f"meet, a singularity of J: the factor {factor} of det J")
        assert said in ur5, said
    jacobian = _flat(run_dhsym("jacobian", "ur5").stdout)  # the same factors as `dhsym jacobian` prints
    assert "det J = a2 a3 s3 s5(a2 c2 + a3 c23 + d5 s234)" in jacobian


@pytest.mark.parametrize("name", ["puma560", "stanford", "ur5"])
def test_where_a_factor_said_is_zero_the_two_roots_meet(name):
    # Put one joint where the factor vanishes; at that pose the condition's two roots give one value.
    robot = load(name)
    result = robot.ik()
    chain, unknowns = robot.chain, list(result.solution.joint_variables)
    constants = sample_constants(robot)
    fk = numeric_fk(robot, constants)
    known = {s: constants[s.name] for s in chain.symbols if s.name in constants}
    rng = numpy.random.default_rng(8)
    tied = [c for c in result.solution.conditions if isinstance(c, Exists) and c.singular]
    assert len(tied) == {"puma560": 3, "stanford": 2, "ur5": 3}[name]
    for condition in tied:
        column = unknowns.index(condition.unknown)
        for singular in condition.singular:
            q = random_joints(chain, rng, 1)[0]
            _vanish(singular.factor.xreplace(known), chain.joint_variables, q)
            found = result.evaluate(numpy.array(fk(*q), dtype=float))
            generic = result.evaluate(numpy.array(fk(*random_joints(chain, rng, 1)[0]), dtype=float))
            values = [found[numpy.isfinite(found).all(axis=1), column], generic[:, column]]
            met, apart = (len(set(numpy.round(v, 5))) for v in values)
            assert 0 < met < apart, (name, singular.factor, values)


def _vanish(factor, joints, q) -> None:
    """Set one joint of q where `factor` is 0 (the last one it holds that can), by bisection."""
    grid = numpy.linspace(-3.1, 3.1, 63)
    for k in sorted((joints.index(v) for v in factor.free_symbols), reverse=True):
        value = sympy.lambdify([joints[k]], factor.xreplace({v: q[j] for j, v in enumerate(joints) if j != k}))
        crossing = next(((a, b) for a, b in zip(grid, grid[1:]) if value(a) * value(b) <= 0), None)
        if crossing is None:
            continue
        below, above = crossing
        for _ in range(60):
            middle = (below + above) / 2
            below, above = (middle, above) if value(below) * value(middle) > 0 else (below, middle)
        q[k] = (below + above) / 2
        return
    raise AssertionError(f"no joint puts {factor} at 0")


def test_the_latex_says_the_singularity_in_words():
    robot = load("puma560")
    latex = snippet(robot.ik().solution, robot)
    assert "a singularity of J: the factor $d_{4} c_{3} + a_{3} s_{3}$ of det J" in latex


def test_a_four_joint_arm_prints_the_plane_its_point_stays_in(tmp_path):
    path = tmp_path / "pitch.yaml"
    path.write_text(PITCH_ARM)
    text = _flat(_ik(str(path)))
    assert "(in every pose of this arm r33 = 0, px r13 + py r23 = 0)" in text
    conditions = json.loads(_ik(str(path), "--format", "json"))["conditions"]
    assert any("px*r13 + py*r23 = 0" in condition for condition in conditions)


def test_the_generated_ik_of_a_four_joint_arm_gives_nan_off_its_plane(tmp_path):
    path = tmp_path / "pitch.yaml"
    path.write_text(PITCH_ARM)
    module = tmp_path / "pitch_ik.py"
    module.write_text(_ik(str(path), "--format", "python"))
    spec = importlib.util.spec_from_file_location("pitch_ik", module)
    ik = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(ik)
    robot = load(str(path))
    fk = sympy.lambdify(robot.joint_variables, robot.chain.fk().xreplace(robot.sample), "numpy")
    pose = numpy.array(fk(0.3, 0.4, -0.5, 0.2), dtype=float)
    assert numpy.isfinite(ik.ik(pose)).all()
    off = pose.copy()
    off[:3, 3] += 0.166 * pose[:3, 2]  # out of the arm's plane (the tool's z is its normal)
    assert numpy.isnan(ik.ik(off)).all()
    both = ik.ik(numpy.stack([pose, off]))
    assert numpy.isfinite(both[0]).all() and numpy.isnan(both[1]).all()


def test_the_iiwa_with_its_first_joint_free_names_s4_zero():
    text = _flat(_ik("iiwa7", "--free", "theta_1"))
    assert "s4 = 0: θ3 is not determined (the wrist centre on axis 3" in text  # the elbow stretched


@pytest.mark.parametrize("name, words, point, axis", [
    ("planar2r", "px = 0 and py = 0: θ1 is not determined (the end point on axis 1; only where a1² = a2²)", 2, 0),
    ("planar3r", "θ1 is not determined (the origin of frame 3 on axis 1; only where l1² = l2²)", 3, 0),
    ("puma560", "px c1 + py s1 = 0 and pz = 0: θ2 + θ3 is not determined (the wrist centre on axis 2; only where "
                "a2² = a3² + d4²)", 4, 2),
    ("ur5", "a2 + a3 c3 = 0 and a3 s3 = 0: θ2 is not determined (the origin of frame 3 on axis 2; only where "
            "a2² = a3²)", 3, 1)])
def test_a_case_said_on_an_axis_is_where_that_point_lies_on_it(name, words, point, axis):
    # The test's own geometry: the origin of frame `point` and the z axis of frame `axis` in numbers,
    # at random poses; the case's expressions are all 0 exactly where the distance between them is:
    # their sum of squares is a constant times the distance squared.
    robot = load(name)
    assert words in _flat(_ik(name))
    solution = robot.ik().solution
    (case,) = [c for c in solution.degenerate if isinstance(c, Undetermined) and isinstance(c.reason, OnAxis)]
    chain, constants = robot.chain, sample_constants(robot)
    known = {s: constants[s.name] for s in chain.symbols if s.name in constants}
    joints = list(chain.joint_variables)
    where = sympy.lambdify(joints, chain.transform(chain.frames[axis], chain.frames[point]).subs(known), "numpy")
    fk = numeric_fk(robot, constants)
    names = ["r11", "r12", "r13", "px", "r21", "r22", "r23", "py", "r31", "r32", "r33", "pz"]
    rng, ratios = numpy.random.default_rng(4), []
    for q in random_joints(chain, rng, 5):
        pose = numpy.array(fk(*q), dtype=float)
        values = {**{v: q[k] for k, v in enumerate(joints)}, **known,
                  **{sympy.Symbol(n, real=True): pose[k // 4, k % 4] for k, n in enumerate(names)}}
        side = sum(float(e.xreplace(values)) ** 2 for e in case.condition)
        x, y = numpy.array(where(*q), dtype=float)[:2, 3]
        ratios.append(side / (x * x + y * y))
    assert numpy.ptp(ratios) < 1e-9 * max(ratios) and min(ratios) > 0, ratios


def test_a_case_the_files_numbers_keep_off_the_axis_is_not_printed(tmp_path):
    # The UR10 of example-robot-data: its origin of frame 3 is 0.612 and 0.5723 from axis 2 along its
    # two links, never on it; the UR5 written with names keeps the case (a2 = a3 would meet it).
    urdf = EXAMPLE_ROBOT_DATA / "ur_description" / "urdf" / "ur10_robot.urdf"
    if not urdf.exists():
        pytest.skip("example-robot-data is not installed")
    robot = tmp_path / "ur10.yaml"
    result = run_dhsym("import", str(urdf), "--tip", "tool0", "-o", str(robot))
    assert result.status == 0, result.stderr
    text = _flat(_ik(str(robot)))
    assert "Degenerate: s5 = 0" in text and "c3 = 0 and" not in text
    assert "θ2 is not determined (the origin of frame 3 on axis 2; only where a2² = a3²)" in _flat(_ik("ur5"))
