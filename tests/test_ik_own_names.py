"""A robot may name its lengths and joints as the solver names its own quantities (D, K, px, r13,
sigma_1, phi_1, x_c, Pieper's p and u) or as Python names its built-ins (len, float): the
derivation's names get a prime (D′) and the user's stay. Every surface is checked: the JSON reads
back and never assigns a robot's name, the generated module's branches reach random poses with
the joints among them, the text shows the primes, the LaTeX compiles-ready form has no Unicode
prime."""
import json

import numpy as np
import pytest
import sympy
from cli_runner import run_dhsym
from ik_checks import check_branches_reach, check_json, import_module, random_joints, sample_constants, used_target

from dhsym import Robot, load
from dhsym.core.chain import Chain, DHRow
from dhsym.io.library import ROBOTS_DIR

PLANAR = """name: {name}
convention: standard
joints:
  - {{joint: R, alpha: 0, a: {a1}, d: 0, theta: {t1}}}
  - {{joint: R, alpha: 0, a: {a2}, d: 0, theta: {t2}}}
{third}sample: {sample}
"""


def planar(name, a1="a_1", a2="a_2", t1="theta_1", t2="theta_2", third="", sample=None):
    sample = sample or {a1: 0.5, a2: 0.4}
    return PLANAR.format(name=name, a1=a1, a2=a2, t1=t1, t2=t2, third=third,
                         sample="{" + ", ".join(f"{k}: {v}" for k, v in sample.items()) + "}")


def builtin(name: str, *replacements) -> str:
    text = (ROBOTS_DIR / f"{name}.yaml").read_text(encoding="utf-8")
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new)
    return text


ROBOTS = {
    # a length named D: the law of cosines' D is D′ (the solver's own D missed 4 poses of 4)
    "length_D": planar("2R with D", a1="D", sample={"D": 0.5, "a_2": 0.4}),
    # lengths named as the target's elements
    "lengths_px_py": planar("2R with px, py", a1="px", a2="py", sample={"px": 0.5, "py": 0.4}),
    # joints named φ1..φ3: the sum of the three angles is φ123, as θ123 is a book's (the solver's φ1 missed every pose)
    "joints_phi": planar("3R with phi", t1="phi_1", t2="phi_2", sample={"a_1": 0.5, "a_2": 0.4, "a_3": 0.2},
                         third="  - {joint: R, alpha: 0, a: a_3, d: 0, theta: phi_3}\n"),
    # names Python keeps for itself: a keyword argument `len` hid len() inside the generated ik()
    "python_builtins": planar("2R with len and float", a1="len", a2="float", sample={"len": 0.5, "float": 0.4}),
    # the finger with an offset on θ1: θ1 + 1 is solved as an angle φ1, which was the finger's own joint φ1
    "finger_offset": builtin("finger_rrr", ("theta: theta_1}", "theta: theta_1 + 1}")),
    # the PUMA's K and a sign σ1 of the solver's, and the Stanford arm's wrist centre x_c and the target's r13
    "puma_K_sigma": builtin("puma560", ("d: d_3", "d: sigma_1"), ("d: d_4", "d: K"), ("d_3: 0.1245", "sigma_1: 0.1245"),
                            ("d_4: 0.4318", "K: 0.4318")),
    "stanford_xc_r13": builtin("stanford", ("d: d_2", "d: x_c"), ("d: d_6", "d: r13"), ("d_2: 0.15", "x_c: 0.15"),
                               ("d_6: 0.1", "r13: 0.1")),
}


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    path = tmp_path_factory.mktemp("own_names")
    for name, text in ROBOTS.items():
        (path / f"{name}.yaml").write_text(text, encoding="utf-8")
    return path


SIX_JOINTS = ("puma_K_sigma", "stanford_xc_r13")  # seconds each


@pytest.mark.parametrize("name", [pytest.param(name, marks=pytest.mark.slow) if name in SIX_JOINTS else name
                                  for name in ROBOTS])
def test_every_branch_reaches_the_pose_whatever_the_robot_names(name, folder, tmp_path):
    path = str(folder / f"{name}.yaml")
    chain = load(path)
    data = check_json(run_dhsym("ik", path, "--format", "json").ok(), chain)
    module_path = tmp_path / f"{name}_ik.py"
    module_path.write_text(run_dhsym("ik", path, "--format", "python").ok(), encoding="utf-8")
    module = import_module(module_path)
    compare = used_target(data) if len(data["joint_variables"]) < 6 else None
    check_branches_reach(module.ik, chain, sample_constants(chain), random_joints(chain, np.random.default_rng(5), 8),
                         **({"compare": compare} if compare else {}))
    assert "ʹ" not in run_dhsym("ik", path, "--format", "latex").ok()  # LaTeX writes the prime as '


def test_the_robots_names_stay_and_the_derivations_are_primed(folder):
    text = run_dhsym("ik", str(folder / "length_D.yaml")).ok()
    assert "D′ = (px² + py² − D² − a2²)/(2 D a2)" in text
    assert "θ2 = atan2(√(1 − D′²), D′)" in text
    assert "⎡ r11   r12   r13   px ⎤" in text  # the target's names are not the robot's: unprimed
    text = run_dhsym("ik", str(folder / "lengths_px_py.yaml")).ok()
    assert "⎡ r11   r12   r13   px′ ⎤" in text and "py′" in text
    assert "D = (px′² + py′² − px² − py²)/(2 px py)" in " ".join(text.split())
    data = json.loads(run_dhsym("ik", str(folder / "lengths_px_py.yaml"), "--format", "json").ok())
    assert data["target"][3] == "pxʹ" and data["target"][:3] == ["r11", "r12", "r13"]
    latex = run_dhsym("ik", str(folder / "lengths_px_py.yaml"), "--format", "latex").ok()
    assert "p_{x}'" in latex
    ascii_text = run_dhsym("ik", str(folder / "joints_phi.yaml"), "--ascii").ok()
    assert "phi123 = atan2(r21, r11)" in ascii_text


def test_a_python_builtin_named_constant_is_a_keyword_that_hides_nothing(folder):
    robot = load(str(folder / "python_builtins.yaml"))
    ik = robot.ik()
    assert "def ik(T, *, float_=0.4, len_=0.5):" in ik.code()
    pose = np.array(robot.fk().subs({**dict(robot.sample), **dict(zip(robot.joint_variables, (0.3, 0.9)))}),
                    dtype=float)
    found = ik.function()(pose, len_=0.5, float_=0.4)
    assert np.nanmin(np.abs(found - [0.3, 0.9]).max(axis=1)) < 1e-9
    assert np.allclose(ik.evaluate(pose, len=0.5, float=0.4), found, equal_nan=True)


def test_a_name_with_a_leading_underscore_gets_a_python_name_at_once():
    """The API takes any SymPy symbol; `_l` made code() and evaluate() loop forever."""
    t1, t2, l1, l2 = sympy.symbols("theta_1 theta_2 _l __", real=True)
    robot = Robot(Chain([DHRow.revolute(t1, a=l1), DHRow.revolute(t2, a=l2)], "standard"), name="underscores",
                  sample={l1: sympy.Rational(1, 2), l2: sympy.Rational(2, 5)})
    ik = robot.ik()
    assert "l_=0.5" in ik.code() and "symbol_" in ik.code()
    pose = np.array(robot.fk().subs({l1: 0.5, l2: 0.4, t1: 0.3, t2: 0.9}), dtype=float)
    assert np.nanmin(np.abs(ik.evaluate(pose) - [0.3, 0.9]).max(axis=1)) < 1e-9


@pytest.mark.slow  # Pieper's quartic: seconds of algebra
def test_pieper_names_the_robot_uses_are_primed(tmp_path):
    from test_inverse_pieper import NAMED  # the general arm with its lengths named

    text = NAMED.replace("d_1", "p").replace("a_1", "u").replace("d_2", "sigma_a")
    path = tmp_path / "pieper_names.yaml"
    path.write_text(text, encoding="utf-8")
    chain = load(str(path))
    data = check_json(run_dhsym("ik", str(path), "--format", "json").ok(), chain)
    assert {"pʹ", "uʹ"} <= {name for name, _ in data["definitions"]} | {
        name for branch in data["solutions"] for name, _ in branch["assignments"]}
    module_path = tmp_path / "pieper_ik.py"
    module_path.write_text(run_dhsym("ik", str(path), "--format", "python").ok(), encoding="utf-8")
    check_branches_reach(import_module(module_path).ik, chain, sample_constants(chain),
                         random_joints(chain, np.random.default_rng(2), 6))


def test_the_branch_pictures_pass_constants_by_the_robots_own_names(folder):
    from matplotlib.figure import Figure

    from dhsym.plot.branches import branch_values, draw_branches

    robot = load(str(folder / "python_builtins.yaml"))
    pose = np.array(robot.fk().subs({**dict(robot.sample), **dict(zip(robot.joint_variables, (0.3, 0.9)))}),
                    dtype=float)
    names, joints = branch_values(robot, pose, constants={"len": 0.5, "float": 0.4})
    assert len(names) == 2 and np.nanmin(np.abs(joints - [0.3, 0.9]).max(axis=1)) < 1e-9
    assert draw_branches(robot, values={"theta_1": 0.3, "theta_2": 0.9}, figure=Figure()).axes
