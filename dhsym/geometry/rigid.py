"""Exact rigid transforms: a frame from its origin and axes, and a fixed transform written
back as the elementary steps a robot file's `base:`/`tool:` lists take.

>>> from dhsym.geometry.exact import vector
>>> pose = frame_pose(vector(1, 0, 0), x=vector(0, 1, 0), z=vector(0, 0, 1))
>>> [str(s) for s in pose_steps(pose)]
['Tx(1)', 'Rz(pi/2)']
>>> [str(s) for s in pose_steps(sympy.eye(4))]
[]
"""
from __future__ import annotations

import sympy

from ..core.transforms import Step, inverse_transform, product
from .exact import cross, is_zero, tidy


def frame_pose(origin: sympy.Matrix, x: sympy.Matrix, z: sympy.Matrix) -> sympy.Matrix:
    """The 4×4 pose of a frame with unit axes x, z (y = z × x) at `origin`."""
    pose = sympy.eye(4)
    pose[:3, 0], pose[:3, 1], pose[:3, 2], pose[:3, 3] = x, cross(z, x), z, origin
    return pose


def relative(first: sympy.Matrix, second: sympy.Matrix) -> sympy.Matrix:
    """The pose of `second` seen from `first`, both given in one common frame."""
    return (inverse_transform(first) * second).applyfunc(tidy)


def angle(cosine, sine) -> sympy.Expr:
    """The exact angle in (−π, π] with this cosine and sine."""
    if is_zero(sine):
        return sympy.Integer(0) if sympy.sympify(cosine).is_positive else sympy.pi
    return tidy(sympy.atan2(tidy(sine), tidy(cosine)))


def pose_steps(pose: sympy.Matrix) -> list[Step]:
    """Steps Tx Ty Tz Rz Ry Rx (zero ones left out) whose product is `pose` exactly."""
    steps = [Step(kind, tidy(pose[axis, 3])) for axis, kind in enumerate(("Tx", "Ty", "Tz"))
             if not is_zero(pose[axis, 3])]
    r = pose[:3, :3]
    if is_zero(r[2, 0] - 1) or is_zero(r[2, 0] + 1):  # pitch ±π/2: only the sum/difference of yaw, roll counts
        pitch = -sympy.pi / 2 if is_zero(r[2, 0] - 1) else sympy.pi / 2
        yaw, roll = angle(r[1, 1], -r[0, 1]), sympy.Integer(0)
    else:
        yaw, pitch, roll = angle(r[0, 0], r[1, 0]), angle(sympy.sqrt(tidy(r[0, 0] ** 2 + r[1, 0] ** 2)), -r[2, 0]), \
            angle(r[2, 2], r[2, 1])
    steps += [Step(kind, value) for kind, value in (("Rz", yaw), ("Ry", pitch), ("Rx", roll)) if not is_zero(value)]
    return steps


def steps_pose(steps) -> sympy.Matrix:
    """The exact product of steps, tidied (the inverse of pose_steps)."""
    return product(steps).applyfunc(tidy)
