"""The surfaces of `dhsym ik` on the solver's own solutions: JSON that reads back and is
consistent, a generated module that agrees with `evaluate()` and whose every branch reaches
FK(q) with q among them, text that fits, documents that compile, a picture of every branch."""
import numpy as np
import pytest
from cli_runner import run_dhsym
from ik_checks import (
    check_branches_reach,
    check_json,
    import_module,
    numeric_fk,
    random_joints,
    sample_constants,
    used_target,
)
from test_ik_cli import HOST, _pdflatex

from dhsym import load
from dhsym.printing.render import display_width

pytestmark = pytest.mark.slow  # real robots solved in closed form: seconds to minutes per test

ROBOTS = ["planar2r", "planar3r", "scara", "stanford", "puma560", "cylindrical_rpp", "spherical_wrist"]
_CHAINS: dict = {}


def _solved(name):
    """The chain, solved once per test session (chain.ik() keeps its solution)."""
    if name not in _CHAINS:
        _CHAINS[name] = load(name)
    chain = _CHAINS[name]
    return chain, chain.ik()


@pytest.mark.parametrize("name", ROBOTS)
def test_json_module_and_evaluate_agree_and_reach_fk(name, tmp_path):
    chain, result = _solved(name)
    import json

    data = check_json(json.dumps(result.json()), chain)
    path = tmp_path / f"{name}_ik.py"
    path.write_text(result.code())
    module = import_module(path)
    assert module.JOINTS == tuple(data["joint_variables"]) and len(module.BRANCHES) == len(data["solutions"])
    constants = sample_constants(chain)
    joints = random_joints(chain, np.random.default_rng(16), 12)
    compare = used_target(data) if len(data["joint_variables"]) < 6 else None
    check_branches_reach(module.ik, chain, constants, joints, **({"compare": compare} if compare else {}))
    fk = numeric_fk(chain, constants)
    poses = np.array([np.array(fk(*q), dtype=float) for q in joints])
    generated, evaluated = module.ik(poses), result.evaluate(poses)
    assert generated.shape == evaluated.shape == (12, len(data["solutions"]), len(data["joint_variables"]))
    assert np.allclose(generated, evaluated, atol=1e-9, equal_nan=True)


@pytest.mark.parametrize("name", ["puma560", "stanford", "scara"])
def test_text_fits_the_width(name):
    _, result = _solved(name)
    for width in (50, 80):
        text = result.text(width)
        assert max(map(display_width, text.splitlines())) <= width, text
    assert "Branch 1: " in text and "\nwhere c" in text


def test_the_puma_has_eight_named_branches_and_a_wrist_centre_free_derivation():
    _, result = _solved("puma560")
    names = [branch.name for branch in result.branches]
    assert len(names) == len(set(names)) == 8
    assert {"shoulder left", "shoulder right"} == {name.split(", ")[0] for name in names}
    assert result.json()["method"].startswith("kinematic decoupling")


def test_command_line_json_and_python_for_the_puma(tmp_path):
    status, out, err = run_dhsym("ik", "puma560", "--format", "json")
    assert status == 0 and err == ""
    data = check_json(out, load("puma560"))
    status, out, _ = run_dhsym("ik", "puma560", "--format", "python")
    path = tmp_path / "puma_ik.py"
    path.write_text(out)
    ik = import_module(path).ik
    chain = load("puma560")
    q = np.array([0.3, -0.7, 0.9, 0.4, -1.1, 0.6])
    found = ik(np.array(numeric_fk(chain, sample_constants(chain))(*q), dtype=float))
    assert found.shape == (len(data["solutions"]), 6) and np.abs(found - q).max(axis=1).min() < 1e-9


@pytest.mark.parametrize("kind", ["slides", "article"])
def test_the_puma_derivation_compiles_and_fits(tmp_path, kind):
    status, out, _ = run_dhsym("latex", "puma560", "--ik", "--document", kind)
    branches = "{Branches 1 to 8}" if kind == "slides" else "Branch 8: "  # slides: formulas once, with ±
    assert status == 0 and "Step 1 (" in out and branches in out
    assert _pdflatex(tmp_path, kind, out) == (0, [])


def test_branch_names_that_say_the_root_compile_in_the_sign_table_and_as_titles(tmp_path):
    status, out, _ = run_dhsym("latex", "iiwa7", "--ik", "--free", "theta_3", "--document", "slides")
    assert status == 0 and "8 & $-$ & $-$ & $-$ & elbow $-\\surd$, shoulder back, wrist flipped \\\\" in out
    assert _pdflatex(tmp_path, "slides", out) == (0, [])
    status, out, _ = run_dhsym("latex", "iiwa7", "--ik", "--free", "theta_3", "--document", "article")
    assert status == 0 and "Branch 8: elbow $-\\surd$, shoulder back, wrist flipped" in out
    assert _pdflatex(tmp_path, "article", out) == (0, [])


def test_the_ik_snippet_compiles(tmp_path):
    status, out, _ = run_dhsym("ik", "stanford", "--format", "latex")
    assert status == 0 and _pdflatex(tmp_path, "snippet", HOST.format(out)) == (0, [])


def test_every_puma_branch_is_drawn_side_by_side():
    from matplotlib.figure import Figure

    from dhsym.plot.branches import draw_branches

    chain, _ = _solved("puma560")
    figure = draw_branches(chain, values={"theta_2": "-30deg", "theta_3": "60deg", "theta_5": "40deg"},
                           figure=Figure())
    assert len(figure.axes) == 8 and figure.get_suptitle().endswith("8 of 8 branches reach the pose")


def test_a_redundant_arm_with_a_free_joint(tmp_path):
    """iiwa7 --free theta_3: the module takes theta_3 as a keyword, agrees with evaluate and reaches FK."""
    chain = load("iiwa7")
    result = chain.ik(free=["theta_3"])
    assert [v.name for v in result.solution.free] == ["theta_3"]
    path = tmp_path / "iiwa_ik.py"
    path.write_text(result.code())
    module = import_module(path)
    assert "theta_3" not in module.JOINTS and ", theta_3):" in result.code()
    constants = sample_constants(chain)
    joints = random_joints(chain, np.random.default_rng(7), 6)
    check_branches_reach(module.ik, chain, constants, joints, free=("theta_3",))
    pose = np.array(numeric_fk(chain, constants)(*joints[0]), dtype=float)
    assert np.allclose(module.ik(pose, theta_3=joints[0][2]), result.evaluate(pose, theta_3=joints[0][2]),
                       atol=1e-9, equal_nan=True)


def test_branches_of_a_redundant_arm_are_drawn_with_the_free_joint_in_its_place():
    from matplotlib.figure import Figure

    from dhsym.plot.branches import branch_values, draw_branches, target_pose

    chain = load("iiwa7")
    values = {"theta_2": "30deg", "theta_3": "20deg", "theta_4": "-60deg"}
    pose = target_pose(chain, values)
    _, joints = branch_values(chain, pose, free=["theta_3"], values=values)
    assert joints.shape == (8, 7) and np.allclose(joints[:, 2], np.radians(20))
    fk = numeric_fk(chain, sample_constants(chain))
    assert all(np.allclose(np.array(fk(*q), dtype=float), pose, atol=1e-8) for q in joints)
    figure = draw_branches(chain, values=values, free=["theta_3"], figure=Figure())
    assert all(ax.get_title().splitlines()[-2].split(", ")[2] == "20°" for ax in figure.axes)


@pytest.mark.parametrize("name, frames", [("puma560", (2, 3, 4)), ("ur5", (1, 2, 5))])
def test_shoulder_and_elbow_names_are_what_the_arm_does(name, frames):
    """Seen from above (z0 up): 'shoulder left' puts the arm's plane left of the line from axis 1
    to the wrist, 'elbow up' puts the elbow above the line from the shoulder to the wrist: checked
    at random poses from the frames' positions (frames: the one on axis 2, on axis 3, the wrist's).
    The UR5's elbow is not above or below that line in a whole branch: its words say the way it
    bends, the elbow left of the line from the shoulder to axis 4 seen with z0 up and x1 right."""
    import sympy

    chain, result = _solved(name)
    constants = sample_constants(chain)
    values = {s: constants[s.name] for s in chain.symbols if s.name in constants}
    at = {k: sympy.lambdify(chain.joint_variables, chain.transform(0, k).subs(values), "numpy")
          for k in {*frames, 1, 3}}
    fk = numeric_fk(chain, constants)
    names = [branch.name for branch in result.branches]
    words = {part for n in names for part in n.split(", ")}
    assert {"shoulder left", "shoulder right"} <= words
    assert {"elbow up", "elbow down"} <= words
    for q in random_joints(chain, np.random.default_rng(8), 6):
        for branch, joints in zip(names, result.evaluate(np.array(fk(*q), dtype=float))):
            if np.isnan(joints).any():
                continue
            (s, n2), (e, _), (w, _) = [(m[:3, 3], m[:3, 2]) for m in (np.array(at[k](*joints), float) for k in frames)]
            up = np.array([0.0, 0.0, 1.0])
            offset = n2 * (n2 @ (w - s))
            left = np.cross(w - s, offset) @ up > 0
            reach, bend = w - s - offset, e - s - n2 * (n2 @ (e - s))
            ahead = reach - (reach @ up) * up
            ahead /= np.linalg.norm(ahead)
            above = (bend @ up) * (reach @ ahead) - (reach @ up) * (bend @ ahead) > 0
            if name == "ur5":
                x1, axis4 = (np.array(at[k](*joints), float) for k in (1, 3))
                right = x1[:3, 0] - (x1[:3, 0] @ up) * up
                above = np.cross(axis4[:3, 3] - s, e - s) @ np.cross(right, up) > 0
            assert ("shoulder left" in branch) == left and ("shoulder right" in branch) == (not left), branch
            if "elbow up" in branch or "elbow down" in branch:
                assert ("elbow up" in branch) == above and ("elbow down" in branch) == (not above), branch


def test_every_line_is_in_the_textbook_notation():
    """The solver's sentences too: 'the factor s5 of det J', not sin(θ5); LaTeX sets a sum of names as one formula."""
    _, result = _solved("puma560")
    text = result.text(100)
    assert "the factor s5 of det J" in " ".join(text.split())
    body = text.split("\nwhere c1")[0]  # the legend says what c23 and s23 are
    assert "sin(θ" not in body and "cos(θ" not in body
    latex = result.latex()._repr_latex_()
    assert "\\theta_{2} + \\theta_{3}" in latex and "sin($" not in latex
