"""Real arms against Pinocchio: `dhsym import` carries each URDF's inertias into the DH frames, and
the generated module's tau, M and C equal Pinocchio's RNEA, CRBA and computeCoriolisMatrix at
random states to 1e-9. The DH joint variables are the URDF's joint values (θi = q_i + offset), so
both take the same q. Where dhsym snaps an angle written to a few digits (1.5708 → π/2), both read
a copy of the URDF with that angle written in full, so that they model the same robot.

Joints off the base → tip path (a gripper's fingers) are held at zero in both: dhsym merges their
links into the last one, Pinocchio's reduced model does the same."""
import math
import re

import numpy
import pytest
from packages import EXAMPLE_ROBOT_DATA

from dhsym.dynamics.codegen import module_text
from dhsym.dynamics.program import dynamics_program
from dhsym.io.urdfimport import import_urdf

pin = pytest.importorskip("pinocchio", reason="Pinocchio (pin, requirements-dev.txt) is the reference here")
pytestmark = pytest.mark.slow  # seconds of import and derivation per arm

ARMS = [("ur_description/urdf/ur5_robot.urdf", "ee_link"), ("ur_description/urdf/ur10_robot.urdf", "ee_link"),
        ("panda_description/urdf/panda.urdf", "panda_hand_tcp"), ("z1_description/urdf/z1.urdf", None),
        ("xarm_description/urdf/xarm7.urdf", None), ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector"),
        ("so_arm_description/urdf/so101.urdf", "gripper_frame_link"),
        ("double_pendulum_description/urdf/double_pendulum.urdf", None)]
SHORT_ANGLES = {"1.5708": repr(math.pi / 2), "3.14159": repr(math.pi), "1.570796": repr(math.pi / 2)}


def written_in_full(source, tmp_path):
    """A copy of the URDF with the rounded quarter and half turns of its rpy attributes in full."""
    def full(match):
        words = [("-" if w.startswith("-") else "") + SHORT_ANGLES.get(w.lstrip("-+"), w.lstrip("-+"))
                 for w in match.group(2).split()]
        return f'{match.group(1)}"{" ".join(words)}"'

    text = re.sub(r'(rpy=)"([^"]*)"', full, source.read_text(encoding="utf-8"))
    copy = tmp_path / source.name
    copy.write_text(text, encoding="utf-8")
    return copy


def pinocchio_model(path, joints):
    model = pin.buildModelFromUrdf(str(path))
    others = [model.getJointId(name) for name in list(model.names)[1:] if name not in joints]
    return pin.buildReducedModel(model, others, pin.neutral(model)) if others else model


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("relative, tip", ARMS, ids=[arm[0].split("/")[-1] for arm in ARMS])
def test_generated_dynamics_equal_pinocchio(relative, tip, convention, tmp_path):
    source = EXAMPLE_ROBOT_DATA / relative
    if not source.exists():
        pytest.skip("example-robot-data is not installed")
    path = written_in_full(source, tmp_path)
    imported = import_urdf(path, tip=tip, convention=convention)
    robot = imported.robot
    assert robot.masses.given and robot.sample  # the URDF's inertias, and g = 9.81
    program = dynamics_program(robot.chain, robot.filled_masses())
    namespace: dict = {}
    exec(compile(module_text(program, robot.name, robot.sample), "arm_dynamics.py", "exec"), namespace)
    model = pinocchio_model(path, imported.joint_names)
    assert [model.names[k] for k in range(1, model.njoints)] == imported.joint_names
    data = model.createData()
    rng = numpy.random.default_rng(0)
    for _ in range(10):
        q, qd, qdd = (rng.uniform(-math.pi, math.pi, robot.chain.n) for _ in range(3))
        configuration = pin.integrate(model, pin.neutral(model), q)  # a continuous joint is (cos q, sin q) there
        torque = pin.rnea(model, data, configuration, qd, qdd)
        assert numpy.allclose(namespace["tau"](q, qd, qdd), torque, rtol=0, atol=1e-9)
        crba = pin.crba(model, data, configuration)
        assert numpy.allclose(namespace["M"](q), numpy.triu(crba) + numpy.triu(crba, 1).T, rtol=0, atol=1e-9)
        coriolis = pin.computeCoriolisMatrix(model, data, configuration, qd)
        assert numpy.allclose(namespace["C"](q, qd), coriolis, rtol=0, atol=1e-9)
        gravity = pin.computeGeneralizedGravity(model, data, configuration)
        assert numpy.allclose(namespace["g"](q), gravity, rtol=0, atol=1e-9)
