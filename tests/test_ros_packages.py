"""ROS packages as they are laid out (tests/data/ros/: small fixtures written for dhsym, with the
real robots' link offsets): `$(find PKG)` by package.xml upward from the file, in its workspace
and in `--package-path` folders; `--xacro-arg`; `load_yaml` with subscripts. Each imports, and
its kinematics equal those of the xacro package's own, unguarded expansion read by yourdfpy."""
import io
import random
import re
from pathlib import Path

import numpy as np
import pytest
from cli_runner import run_dhsym
from readers import load_robot_file

xacro = pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")
yourdfpy = pytest.importorskip("yourdfpy", reason="yourdfpy computes the URDF's own kinematics (requirements-dev.txt)")

ROS = Path(__file__).parent / "data" / "ros"
# (label, file, base, tip, xacro arguments, --package-path folders), all under tests/data/ros
LAYOUTS = [
    ("irb2400_clone_named_like_the_robot", "abb_irb2400/abb_irb2400_support/urdf/irb2400.xacro", "base_link", "tool0",
     {}, []),
    ("hc10_include_inside_a_macro", "motoman/motoman_hc10_support/urdf/hc10.xacro", "base_link", "tool0", {}, []),
    ("tx2_60_resources_in_another_clone",
     "staubli_ws/src/staubli_experimental/staubli_tx2_60_support/urdf/tx2_60.xacro", "base_link", "tool0", {},
     ["staubli_ws/src"]),
    ("ned2_one_folder_below_urdf", "ned_ros/niryo_robot_description/urdf/ned2/niryo_ned2.urdf.xacro", "base_link",
     "tool_link", {}, []),
    ("open_manipulator_x_sibling_package", "open_manipulator/open_manipulator_description/urdf/om_x/"
     "open_manipulator_x.urdf.xacro", "link1", "end_effector_link", {}, []),
    ("ur5e_arguments_and_yaml", "Universal_Robots_ROS2_Description/urdf/ur.urdf.xacro", "base_link", "tool0",
     {"ur_type": "ur5e", "name": "ur"}, []),
    ("mycobot_urdf_with_a_xacro_property", "mycobot_ros/mycobot_description/urdf/mycobot_280_m5/mycobot_280_m5.urdf",
     "g_base", "joint6_flange", {}, []),
]


def xacro_expansion(path: Path, arguments: dict) -> str:
    """The xacro package's own expansion, unguarded, $(find) answered from the package.xml files."""
    import xacro.substitution_args as substitution

    packages = {re.search(r"<name>(.*?)</name>", manifest.read_text()).group(1): manifest.parent
                for manifest in ROS.rglob("package.xml")}
    saved = substitution._eval_find
    substitution._eval_find = lambda package: str(packages[package])
    try:
        return xacro.process_file(str(path), mappings=dict(arguments)).toprettyxml(indent="  ")
    finally:
        substitution._eval_find = saved


def command(relative, base, tip, arguments, package_paths, *more):
    argv = ["import", str(ROS / relative), "--base", base, "--tip", tip, *more]
    for name, value in arguments.items():
        argv += ["--xacro-arg", f"{name}:={value}"]
    for folder in package_paths:
        argv += ["--package-path", str(ROS / folder)]
    return argv


@pytest.mark.slow  # a second each: SymPy's product and yourdfpy's reading (the expansion test below is fast)
@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("label, relative, base, tip, arguments, package_paths", LAYOUTS, ids=[c[0] for c in LAYOUTS])
def test_each_layout_imports_with_the_kinematics_of_xacros_own_expansion(label, relative, base, tip, arguments,
                                                                          package_paths, convention, tmp_path):
    out = tmp_path / "arm.yaml"
    status, stdout, stderr = run_dhsym(*command(relative, base, tip, arguments, package_paths, "--convention",
                                                convention, "-o", str(out)))
    assert (status, stdout) == (0, "") and all(line.startswith("dhsym: warning: ") for line in stderr.splitlines())
    robot = load_robot_file(out)
    listed = re.match(r"Derived by dhsym import; joint variables: (.*?)(?:\. |$)", robot.notes).group(1)
    names = [part.split(" = ")[1] for part in listed.split(", ")]
    reference = yourdfpy.URDF.load(io.BytesIO(xacro_expansion(ROS / relative, arguments).encode()),
                                   build_scene_graph=True, load_meshes=False)
    fk, rng = robot.chain.fk(raw=True), random.Random(label)
    for _ in range(3):
        values = [rng.uniform(-1.5, 1.5) for _ in names]
        reference.update_cfg(dict(zip(names, values)))
        table = np.array(fk.xreplace(dict(zip(robot.chain.joint_variables, values))).evalf(), dtype=float)
        # angles snapped to π/12 multiples are within 1e-5 rad of the file's decimals (1.5708)
        assert np.allclose(table, reference.get_transform(frame_to=tip, frame_from=base), atol=5e-5)


@pytest.mark.parametrize("label, relative, base, tip, arguments, package_paths", LAYOUTS, ids=[c[0] for c in LAYOUTS])
def test_dhsym_expands_to_the_numbers_xacro_itself_writes(label, relative, base, tip, arguments, package_paths):
    from dhsym.io.xacro import expand_xacro

    ours = expand_xacro(ROS / relative, [], arguments, [ROS / folder for folder in package_paths]).decode()
    assert numbers_of(ours) == numbers_of(xacro_expansion(ROS / relative, arguments))


def numbers_of(urdf: str) -> dict:
    """Every joint's origin, axis and limits, as floats, and the links, of a URDF text."""
    from lxml import etree

    root = etree.fromstring(re.sub(r"^\s*<\?xml[^>]*\?>", "", urdf).encode())
    found = {"links": sorted(link.get("name") for link in root.iter("link"))}
    for joint in root.iter("joint"):
        values = []
        for tag, key in (("origin", "xyz"), ("origin", "rpy"), ("axis", "xyz"), ("limit", "lower"), ("limit", "upper")):
            element = joint.find(tag)
            values.append([float(word) for word in element.get(key, "").split()] if element is not None else None)
        found[joint.get("name")] = values
    return found


def test_a_package_in_no_searched_folder_is_named_with_where_dhsym_looked():
    relative, base, tip, arguments, _ = LAYOUTS[2][1:]
    status, stdout, stderr = run_dhsym(*command(relative, base, tip, arguments, []))
    assert status == 2 and stdout == ""
    assert re.fullmatch(r"dhsym: error: \S+/tx2_60\.xacro:3:28: \$\(find staubli_resources\): no ROS package "
                        r"staubli_resources \(a folder whose package\.xml has <name>staubli_resources</name>\) in "
                        r"\S+/staubli_ws/src/staubli_experimental; give the folder that holds it with --package-path "
                        r"DIR \(dhsym does not search ROS_PACKAGE_PATH\)\n", stderr)


def test_a_package_path_that_is_not_a_folder_is_one_error(tmp_path):
    relative, base, tip, arguments, _ = LAYOUTS[0][1:]
    status, _, stderr = run_dhsym(*command(relative, base, tip, arguments, []), "--package-path", str(tmp_path / "no"))
    assert status == 2 and stderr == f"dhsym: error: --package-path {tmp_path / 'no'}: no such folder\n"


def make_package(folder: Path, name: str) -> Path:
    (folder / "urdf").mkdir(parents=True)
    (folder / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    return folder


def test_packages_outside_the_workspace_and_the_package_paths_are_never_read(tmp_path):
    arm = make_package(tmp_path / "ws" / "robot_repo" / "arm_support", "arm_support")
    make_package(tmp_path / "ws" / "other_repo" / "gripper_description", "gripper_description")
    (tmp_path / "ws" / "other_repo" / "gripper_description" / "urdf" / "g.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="finger"/></robot>')
    top = arm / "urdf" / "arm.xacro"
    top.write_text('<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <xacro:include filename="$(find gripper_description)/urdf/g.xacro"/>\n  <link name="base"/>\n'
                   '  <joint name="j" type="revolute"><parent link="base"/><child link="finger"/><axis xyz="0 0 1"/>'
                   '</joint></robot>')
    status, _, stderr = run_dhsym("import", str(top))
    assert status == 2 and "no ROS package gripper_description" in stderr and "robot_repo;" in stderr
    status, stdout, stderr = run_dhsym("import", str(top), "--package-path", str(tmp_path / "ws"))
    assert status == 0 and "links base → finger" in stdout and stderr == ""


def test_a_link_out_of_the_trees_is_refused_where_it_is_included(tmp_path):
    arm = make_package(tmp_path / "ws" / "arm_support", "arm_support")
    outside = tmp_path / "elsewhere.xacro"
    outside.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="finger"/></robot>')
    (arm / "urdf" / "part.xacro").symlink_to(outside)
    top = arm / "urdf" / "arm.xacro"
    top.write_text('<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <xacro:include filename="part.xacro"/></robot>')
    status, _, stderr = run_dhsym("import", str(top))
    assert status == 2 and stderr.startswith(f"dhsym: error: {top}:2:28: xacro:include of part.xacro: outside the "
                                             "robot's folder")


def test_the_search_is_bounded_and_says_so(tmp_path, monkeypatch):
    import dhsym.io.packages as packages

    monkeypatch.setattr(packages, "MAX_FOLDERS", 3)
    arm = make_package(tmp_path / "ws" / "arm_support", "arm_support")
    for number in range(5):
        (tmp_path / "ws" / f"folder_{number}").mkdir()
    top = arm / "urdf" / "arm.xacro"
    top.write_text('<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                   '  <xacro:include filename="$(find gripper)/g.xacro"/></robot>')
    status, _, stderr = run_dhsym("import", str(top))
    assert status == 2 and "(the search stopped after 3 folders)" in stderr


def test_xacro_arguments_for_a_plain_urdf_are_ignored_with_a_warning():
    urdf = Path(__file__).parent / "data" / "ur5.urdf"
    status, stdout, stderr = run_dhsym("import", str(urdf), "--tip", "tool0", "--xacro-arg", "ur_type:=ur5e")
    assert status == 0 and stdout.startswith('name: "ur5"')
    ignored = f"dhsym: warning: {urdf}: --xacro-arg is ignored: the file is a URDF, not a xacro file"
    assert ignored in stderr.splitlines()
