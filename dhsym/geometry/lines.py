"""Joint axes as exact lines in space, and how two of them relate: skew, intersecting,
parallel, anti-parallel or collinear (the cases of the DH frame-assignment rules).

>>> from dhsym.geometry.exact import vector
>>> z = JointAxis("R", vector(0, 0, 0), vector(0, 0, 1))
>>> relation(z, JointAxis("R", vector(1, 0, 0), vector(0, 0, -1)))
'anti-parallel'
>>> relation(z, JointAxis("R", vector(0, 1, 2), vector(1, 0, 0)))
'skew'
>>> distance_between(z, JointAxis("R", vector(0, 1, 2), vector(1, 0, 0)))
1
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from .exact import cross, dot, is_zero, is_zero_vector, tidy, tidy_vector

RELATIONS = ("skew", "intersecting", "parallel", "anti-parallel", "collinear")


@dataclass(frozen=True)
class JointAxis:
    """A joint's axis at the zero configuration: type R/P, a point on it and the unit direction
    of positive motion (the right-hand rotation axis, or the direction a slider extends)."""

    joint: str
    point: sympy.Matrix
    direction: sympy.Matrix
    name: str = ""

    def __post_init__(self):
        if self.joint not in ("R", "P"):
            raise ValueError(f"joint type must be R or P, not {self.joint!r}")
        if is_zero_vector(self.direction):
            raise ValueError("a joint axis needs a non-zero direction")

    def foot_of(self, point: sympy.Matrix) -> sympy.Matrix:
        """The point of this line nearest to `point`."""
        return tidy_vector(self.point + dot(point - self.point, self.direction) * self.direction)

    def contains(self, point: sympy.Matrix) -> bool:
        return is_zero_vector(self.foot_of(point) - point)

    def __str__(self) -> str:
        p, u = (", ".join(map(str, v)) for v in (self.point, self.direction))
        return f"{self.joint} axis through ({p}) along ({u})"


def relation(first: JointAxis, second: JointAxis) -> str:
    """Which of RELATIONS the two axes are in (directions must be numeric)."""
    normal = cross(first.direction, second.direction)
    if is_zero_vector(normal):
        if first.contains(second.point):
            return "collinear"
        return "parallel" if dot(first.direction, second.direction).is_positive else "anti-parallel"
    offset = second.point - first.point
    return "intersecting" if is_zero(dot(offset, normal)) else "skew"


def distance_between(first: JointAxis, second: JointAxis):
    """The length of the common normal (0 for intersecting or collinear axes)."""
    normal = cross(first.direction, second.direction)
    offset = second.point - first.point
    if is_zero_vector(normal):
        return tidy(sympy.sqrt(sum(c ** 2 for c in offset - dot(offset, first.direction) * first.direction)))
    return tidy(abs(dot(offset, normal)) / sympy.sqrt(sum(c ** 2 for c in normal)))


def normal_feet(first: JointAxis, second: JointAxis) -> tuple[sympy.Matrix, sympy.Matrix]:
    """The feet of the common normal of two non-parallel axes: (on first, on second)."""
    u, v, w = first.direction, second.direction, first.point - second.point
    b = dot(u, v)
    d, e = dot(u, w), dot(v, w)
    denominator = 1 - b ** 2  # directions are unit vectors
    s = tidy((b * e - d) / denominator)
    t = tidy((e - b * d) / denominator)
    return tidy_vector(first.point + s * u), tidy_vector(second.point + t * v)
