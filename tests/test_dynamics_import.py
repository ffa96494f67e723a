"""`dhsym import` carries a URDF's <inertial> elements into the DH frames: exactly, links fixed to
a moving link merged by the parallel-axis theorem, a branch off the path held at zero, an inertia
no body has left symbolic with a warning; the robot file it writes reads back the same."""
import sympy
from cli_runner import run_dhsym
from readers import load_robot_text

from dhsym.core.inertia import tensor
from dhsym.io.urdfimport import import_urdf

R = sympy.Rational
ARM = """<robot name="arm">
  <link name="base"/>
  <link name="upper">
    <inertial><origin xyz="0.2 0 0.05"/><mass value="2"/>
      <inertia ixx="0.01" iyy="0.04" izz="0.04" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="forearm">
    <inertial><origin xyz="0 0 0.1" rpy="1.5707963267948966 0 0"/><mass value="1"/>
      <inertia ixx="0.02" iyy="0.01" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="hand">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="finger">
    <inertial><mass value="0.1"/><inertia ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="tip"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="forearm"/>
    <origin xyz="0.4 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="flange" type="fixed"><parent link="forearm"/><child link="hand"/><origin xyz="0.3 0 0"/></joint>
  <joint name="grip" type="prismatic"><parent link="hand"/><child link="finger"/>
    <origin xyz="0 0.05 0"/><axis xyz="0 1 0"/><limit lower="0" upper="0.04" effort="1" velocity="1"/></joint>
  <joint name="tool" type="fixed"><parent link="hand"/><child link="tip"/><origin xyz="0.1 0 0"/></joint>
</robot>
"""


def merged_in_base_frame() -> list:
    """(mass, centre, tensor about it) of links 1 and 2 in the URDF's base frame, worked out by hand:
    the upper arm as written (its joint 0.3 above the base); the forearm (1 kg at 0.1 above the elbow,
    its tensor turned 90° about x: diag(0.02, 0.02, 0.01)), the hand (0.5 kg, 0.3 along) and the
    finger (0.1 kg, held at zero), merged by the parallel-axis theorem."""
    upper = (R(2), sympy.Matrix([R("0.2"), 0, R("0.35")]), sympy.diag(R("0.01"), R("0.04"), R("0.04")))
    parts = [(R(1), sympy.Matrix([R("0.4"), 0, R("0.4")]), sympy.diag(R("0.02"), R("0.02"), R("0.01"))),
             (R("0.5"), sympy.Matrix([R("0.7"), 0, R("0.3")]), sympy.diag(*[R("0.001")] * 3)),
             (R("0.1"), sympy.Matrix([R("0.7"), R("0.05"), R("0.3")]), sympy.zeros(3, 3))]
    mass = sum(m for m, _, _ in parts)
    centre = sum((m * c for m, c, _ in parts), sympy.zeros(3, 1)) / mass
    inertia = sum((own + m * ((c - centre).dot(c - centre) * sympy.eye(3) - (c - centre) * (c - centre).T)
                   for m, c, own in parts), sympy.zeros(3, 3))
    return [upper, (mass, centre, inertia)]


def test_inertias_are_carried_into_the_dh_frames_exactly(tmp_path):
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(ARM, encoding="utf-8")
    for convention in ("standard", "modified"):
        robot = import_urdf(urdf, tip="tip", convention=convention).robot
        zero = {v: 0 for v in robot.chain.joint_variables}
        for k, (link, (mass, centre, inertia)) in enumerate(zip(robot.masses.links, merged_in_base_frame()), 1):
            pose = robot.chain.transform(robot.chain.frames[0], k).xreplace(zero)  # frame k at q = 0
            turn, origin = pose[:3, :3], pose[:3, 3]
            assert link.mass == mass
            assert max(abs(a - b) for a, b in zip(link.com, turn.T * (centre - origin))) < R(1, 10**14)
            assert max(abs(a - b) for a, b in zip(tensor(link.inertia), turn.T * inertia * turn)) < R(1, 10**14)
        assert "links beyond joints off the path (grip) are merged too" in robot.notes
        assert robot.sample == {sympy.Symbol("g", real=True): R("9.81")}


def test_the_written_file_reads_back_with_its_masses(tmp_path):
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(ARM, encoding="utf-8")
    for convention in ("standard", "modified"):
        status, out, err = run_dhsym("import", str(urdf), "--tip", "tip", "--convention", convention)
        assert status == 0 and "mass: 2" in out and "inertia: [" in out
        again = load_robot_text(out, "arm.yaml")
        assert again.masses == import_urdf(urdf, tip="tip", convention=convention).robot.masses


def test_an_inertia_no_body_has_is_left_symbolic_with_a_warning(tmp_path):
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(ARM.replace('ixx="0.01" iyy="0.04" izz="0.04"', 'ixx="0.01" iyy="0.01" izz="0.05"'),
                    encoding="utf-8")
    status, out, err = run_dhsym("import", str(urdf), "--tip", "tip")
    assert status == 0 and "mass: 2" in out
    assert err.splitlines()[-1] == (f"dhsym: warning: {urdf}:4:5: the inertia of DH link 1 is not one a body can have "
                                    "(Ixx + Iyy ≥ Izz fails (0.01 + 0.01 < 0.05)); it is left as the generic symbols "
                                    "I_xx1 … I_yz1")
