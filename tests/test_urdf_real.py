"""Real robot files as their packages ship them (example-robot-data's URDFs, rtb-data's .xacro
files) import in both conventions with exit status 0, and the DH table's forward kinematics
equals the URDF's own, computed by yourdfpy, at random joint values. Skipped, with the reason,
when a package is not installed (both are in requirements-dev.txt)."""
import functools
import importlib.metadata
import importlib.util
import io
import random
import re
from pathlib import Path

import numpy as np
import pytest
from cli_runner import run_dhsym
from packages import EXAMPLE_ROBOT_DATA as ERD
from packages import RTB_XACRO as RTB
from readers import load_robot_file

from dhsym import import_urdf

pytestmark = pytest.mark.slow  # real robots' URDFs, closed-form solutions: seconds to minutes per test

yourdfpy = pytest.importorskip("yourdfpy", reason="yourdfpy computes the URDF's own kinematics (requirements-dev.txt)")



# (label, folder, file, base, tip); base and tip None: the file's own root and only leaf
EXAMPLE_ROBOT_DATA = [
    ("ur3", "ur_description/urdf/ur3_robot.urdf", None, "tool0"),
    ("ur5", "ur_description/urdf/ur5_robot.urdf", None, "tool0"),
    ("ur10", "ur_description/urdf/ur10_robot.urdf", None, "tool0"),
    ("panda", "panda_description/urdf/panda.urdf", None, "panda_hand_tcp"),
    ("kinova", "kinova_description/robots/kinova.urdf", None, "j2s6s200_end_effector"),
    ("xarm7", "xarm_description/urdf/xarm7.urdf", None, None),
    ("z1", "z1_description/urdf/z1.urdf", None, None),
    ("so100", "so_arm_description/urdf/so100.urdf", None, None),
    ("baxter_left", "baxter_description/urdf/baxter.urdf", "left_arm_mount", "left_gripper"),
    ("baxter_right", "baxter_description/urdf/baxter.urdf", "right_arm_mount", "right_gripper"),
    ("icub_left_arm", "icub_description/robots/icub.urdf", "chest", "l_hand_dh_frame"),
    ("romeo_left_arm", "romeo_description/urdf/romeo.urdf", "torso", "l_wrist"),
    ("talos_left_arm", "talos_data/robots/talos_full_v2.urdf", "torso_2_link", "arm_left_7_link"),
    ("tiago_arm", "tiago_description/robots/tiago.urdf", "torso_lift_link", "arm_tool_link"),
    ("pr2_right_arm", "pr2_description/urdf/pr2.urdf", "torso_lift_link", "r_wrist_roll_link"),
]
RTB_DATA = [
    ("abb_irb140", "abb_irb140_description/urdf/irb140.xacro", None, "tool0"),
    ("kuka_kr3", "kuka_description/kuka_kr3/urdf/kr3r540.xacro", None, "tool0"),
    ("kuka_kr5", "kuka_description/kuka_kr5/urdf/kr5_arc.xacro", None, "tool0"),
    ("kuka_kr6", "kuka_description/kuka_kr6/urdf/kr6r700sixx.xacro", None, "tool0"),
    ("kuka_kr10", "kuka_description/kuka_kr10/urdf/kr10r1100sixx.xacro", None, "tool0"),
    ("kuka_kr16", "kuka_description/kuka_kr16/urdf/kr16_2.xacro", None, "tool0"),
    ("kuka_kr150", "kuka_description/kuka_kr150/urdf/kr150_2.xacro", None, "tool0"),
    ("kuka_kr6r900", "kuka_description/kuka_kr6/urdf/kr6r900sixx.xacro", None, "tool0"),
    ("kuka_kr120", "kuka_description/kuka_kr120/urdf/kr120r2500pro.xacro", None, "tool0"),
    ("kuka_kr210", "kuka_description/kuka_kr210/urdf/kr210l150.xacro", None, "tool0"),  # ROS 1 tags, unprefixed
    ("kuka_iiwa14", "kuka_description/kuka_lbr_iiwa/urdf/lbr_iiwa_14_r820.xacro", None, "tool0"),
    ("puma560", "unimation_puma560_description/urdf/puma560_robot.urdf.xacro", None, None),
    ("frankie_panda", "qut_frankie_description/robots/panda_arm.urdf.xacro", None, None),
    ("px100", "trossen_descriptions/urdf/px100.urdf.xacro", None, "/ee_gripper_link"),
    ("wx250s", "trossen_descriptions/urdf/wx250s.urdf.xacro", None, "/ee_gripper_link"),
]


def _cases():
    for folder, table, reason in ((ERD, EXAMPLE_ROBOT_DATA, "example-robot-data is not installed"),
                                  (RTB, RTB_DATA, "rtb-data is not installed")):
        for label, relative, base, tip in table:
            skip = [] if folder.exists() else [pytest.mark.skip(reason=reason)]
            if relative.endswith(".xacro") and importlib.util.find_spec("xacro") is None:
                skip = [pytest.mark.skip(reason="the xacro package is not installed")]
            yield pytest.param(label, folder / relative, base, tip, id=label, marks=skip)


@functools.cache
def _urdf_text(path: Path) -> str:
    if path.suffix == ".xacro":
        from dhsym.io.xacro import expand_xacro

        return expand_xacro(path).decode()
    return path.read_text()


@functools.cache
def _reference(path: Path):
    return yourdfpy.URDF.load(io.BytesIO(_urdf_text(path).encode()), build_scene_graph=True, load_meshes=False,
                              build_collision_scene_graph=False, load_collision_meshes=False)


def _urdf_fk(path: Path, names, values, base: str, tip: str) -> np.ndarray:
    robot = _reference(path)
    robot.update_cfg(dict(zip(names, values)))
    return robot.get_transform(frame_to=tip, frame_from=base)


def _assert_same_kinematics(chain, names, path, base, tip):
    rng = random.Random(f"{path.name}{base}{tip}")
    base = base or chain.source.split("links ")[1].split(" → ")[0]
    tip = tip or chain.source.split(" → ")[1]
    fk = chain.fk(raw=True)
    for _ in range(3):
        values = [rng.uniform(-1.5, 1.5) for _ in names]
        numeric = np.array(fk.xreplace(dict(zip(chain.joint_variables, values))).evalf(), dtype=float)
        # angles snapped to the π/12 grid are up to 1e-5 rad from the URDF's decimals (xArm7, SO-100, iCub: 1e-5 m)
        assert np.allclose(numeric, _urdf_fk(path, names, values, base, tip), atol=5e-5)


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("label, path, base, tip", list(_cases()))
def test_the_python_api_gives_the_urdf_kinematics(label, path, base, tip, convention):
    imported = import_urdf(path, base, tip, convention)
    assert imported.robot.convention == convention and imported.robot.n == len(imported.joint_names)
    _assert_same_kinematics(imported.robot, imported.joint_names, path, base, tip)


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("label, path, base, tip", list(_cases()))
def test_dhsym_import_writes_a_file_with_the_urdf_kinematics(label, path, base, tip, convention, tmp_path):
    out = tmp_path / f"{label}.yaml"
    argv = ["import", str(path), "--convention", convention, "-o", str(out)]
    argv += ["--base", base] if base else []
    argv += ["--tip", tip] if tip else []
    status, stdout, stderr = run_dhsym(*argv)
    assert (status, stdout) == (0, ""), stderr
    assert all(line.startswith("dhsym: warning: ") for line in stderr.splitlines())
    chain = load_robot_file(out)
    listed = re.match(r"Derived by dhsym import; joint variables: (.*?)(?:\. |$)", chain.notes).group(1)
    names = [part.split(" = ")[1] for part in listed.split(", ")]
    assert chain.convention == convention and len(names) == chain.n
    _assert_same_kinematics(chain, names, path, base, tip)
