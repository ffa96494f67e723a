"""A URDF's `<limit lower upper>` becomes the imported robot's joint limits, with the frame
assignment's mapping: the DH variable equals the URDF joint's value, so at the URDF's own limits
(and inside them) the DH table's forward kinematics equals the URDF's, computed by yourdfpy; and
`dhsym import -o` writes them so that the file reads back to the same limits."""
import io

import numpy as np
import pytest
from cli_runner import run_dhsym
from packages import EXAMPLE_ROBOT_DATA as ERD
from packages import RTB_XACRO as RTB

import dhsym
from dhsym import import_urdf

pytestmark = pytest.mark.slow  # real robots' URDFs through yourdfpy: seconds each

yourdfpy = pytest.importorskip("yourdfpy", reason="yourdfpy computes the URDF's own kinematics (requirements-dev.txt)")

CASES = [  # (label, file, tip): revolute joints with limits, a continuous joint, a prismatic one
    pytest.param(ERD / "panda_description/urdf/panda.urdf", "panda_hand_tcp", id="panda",
                 marks=pytest.mark.skipif(not ERD.exists(), reason="example-robot-data is not installed")),
    pytest.param(ERD / "ur_description/urdf/ur5_robot.urdf", "tool0", id="ur5",
                 marks=pytest.mark.skipif(not ERD.exists(), reason="example-robot-data is not installed")),
    pytest.param(RTB / "kuka_description/kuka_kr6/urdf/kr6r700sixx.xacro", "tool0", id="kuka_kr6",
                 marks=pytest.mark.skipif(not RTB.exists(), reason="rtb-data is not installed")),
]


def _reference(path):
    if path.suffix == ".xacro":
        pytest.importorskip("xacro")
        from dhsym.io.xacro import expand_xacro

        text = expand_xacro(path)
    else:
        text = path.read_bytes()
    return yourdfpy.URDF.load(io.BytesIO(text), build_scene_graph=True, load_meshes=False,
                              build_collision_scene_graph=False, load_collision_meshes=False)


def _urdf_limits(reference, names):
    limits = []
    for name in names:
        joint = reference.joint_map[name]
        bounded = joint.type in ("revolute", "prismatic") and joint.limit is not None
        limits.append((joint.limit.lower, joint.limit.upper) if bounded else None)
    return limits


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("path, tip", CASES)
def test_imported_limits_are_the_urdf_limits_of_the_same_joint_values(path, tip, convention):
    imported = import_urdf(path, None, tip, convention)
    robot, names = imported.robot, imported.joint_names
    reference = _reference(path)
    expected = _urdf_limits(reference, names)
    got = [None if pair is None else tuple(float(x) for x in pair) for pair in robot.joint_limits or [None] * robot.n]
    assert got == expected and any(pair is not None for pair in got)
    base = robot.source.split("links ")[1].split(" → ")[0]
    fk = robot.chain.fk()
    rng = np.random.default_rng(7)
    inside = [[rng.uniform(*pair) if pair else rng.uniform(-3, 3) for pair in got] for _ in range(2)]
    at_limits = [[pair[k] if pair else 0.5 for pair in got] for k in (0, 1)]
    for values in at_limits + inside:
        numeric = np.array(fk.xreplace(dict(zip(robot.chain.joint_variables, values))).evalf(), dtype=float)
        reference.update_cfg(dict(zip(names, values)))
        assert np.allclose(numeric, reference.get_transform(frame_to=tip, frame_from=base), atol=5e-5)


@pytest.mark.parametrize("path, tip", CASES[:1])
def test_dhsym_import_writes_the_limits_and_they_read_back(path, tip, tmp_path):
    out = tmp_path / "arm.yaml"
    status, stdout, stderr = run_dhsym("import", str(path), "--tip", tip, "-o", str(out))
    assert (status, stdout) == (0, ""), stderr
    assert "limits: [-2.8973, 2.8973]" in out.read_text()
    assert dhsym.load(str(out)).joint_limits == import_urdf(path, None, tip).robot.joint_limits
