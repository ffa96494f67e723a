"""Small URDFs for tests: a serial chain from (type, xyz, rpy, axis) joint specs, and the URDF's
own forward kinematics by yourdfpy, independent of dhsym's reading and frame assignment."""
import io

import numpy as np
import pytest


def serial_urdf(joints, name="test_arm", mesh=None) -> str:
    """joints: (type, "x y z", "r p y", "ax ay az") per joint, base link0 to tip link{n}."""
    links = [f'<link name="link{i}"/>' for i in range(len(joints) + 1)]
    if mesh:
        links[1] = f'<link name="link1"><visual><geometry><mesh filename="{mesh}"/></geometry></visual></link>'
    body = []
    for i, (kind, xyz, rpy, axis) in enumerate(joints, 1):
        limit = '<limit lower="-3" upper="3" effort="1" velocity="1"/>' if kind in ("revolute", "prismatic") else ""
        axis_tag = f'<axis xyz="{axis}"/>' if axis else ""
        body.append(f'<joint name="j{i}" type="{kind}"><parent link="link{i - 1}"/><child link="link{i}"/>'
                    f'<origin xyz="{xyz}" rpy="{rpy}"/>{axis_tag}{limit}</joint>')
    return f'<?xml version="1.0"?>\n<robot name="{name}">\n' + "\n".join(links + body) + "\n</robot>\n"


def urdf_fk(text: str, values, base: str, tip: str) -> np.ndarray:
    """base → tip at the given values of the movable joints, by yourdfpy (the test skips without it)."""
    yourdfpy = pytest.importorskip("yourdfpy", reason="yourdfpy computes the URDF's own kinematics "
                                   "(requirements-dev.txt)")
    robot = yourdfpy.URDF.load(io.BytesIO(text.encode()), build_scene_graph=True, load_meshes=False)
    robot.update_cfg(np.array(values, dtype=float))
    return robot.get_transform(frame_to=tip, frame_from=base)
