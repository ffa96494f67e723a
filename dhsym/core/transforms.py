"""Elementary homogeneous transforms and the link matrix of each DH convention.

A chain is a sequence of `Step`s (Rx, Ry, Rz, Tx, Ty, Tz); each convention is just the
order of four steps:

>>> import sympy
>>> th, d, a, al = sympy.symbols("theta d a alpha", real=True)
>>> [str(s) for s in link_steps("standard", th, d, a, al)]
['Rz(theta)', 'Tz(d)', 'Tx(a)', 'Rx(alpha)']
>>> [str(s) for s in link_steps("modified", th, d, a, al)]
['Rx(alpha)', 'Tx(a)', 'Rz(theta)', 'Tz(d)']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..errors import UserError

CONVENTIONS = ("standard", "modified")
STEP_KINDS = ("Rx", "Ry", "Rz", "Tx", "Ty", "Tz")


@dataclass(frozen=True)
class Step:
    """One elementary motion: a rotation about or a translation along a frame axis.

    >>> Step("Tx", 2).matrix()[:3, 3].T
    Matrix([[2, 0, 0]])
    """

    kind: str
    value: sympy.Expr

    def __post_init__(self):
        if self.kind not in STEP_KINDS:
            raise UserError(f"unknown step {self.kind!r}; use one of {', '.join(STEP_KINDS)}")
        object.__setattr__(self, "value", as_expr(self.value))

    @property
    def axis(self) -> int:
        return "xyz".index(self.kind[1])

    @property
    def is_rotation(self) -> bool:
        return self.kind[0] == "R"

    def inverse(self) -> "Step":
        return Step(self.kind, -self.value)

    def matrix(self) -> sympy.Matrix:
        return rotation(self.axis, self.value) if self.is_rotation else translation(self.axis, self.value)

    def __str__(self) -> str:
        return f"{self.kind}({self.value})"


def as_expr(value) -> sympy.Expr:
    """A SymPy number or expression; text must go through dhsym.expr.parse_expression instead.

    >>> as_expr(2), as_expr(sympy.pi)
    (2, pi)
    """
    if isinstance(value, str):
        raise TypeError("pass text through dhsym.parse_expression, not directly")
    return sympy.sympify(value, strict=True)


def rotation(axis: int, angle: sympy.Expr) -> sympy.Matrix:
    """Homogeneous rotation about x (0), y (1) or z (2).

    >>> rotation(2, sympy.pi / 2)[:3, :3]
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])
    """
    c, s = sympy.cos(angle), sympy.sin(angle)
    i, j = turned_plane(axis)
    m = sympy.eye(4)
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def turned_plane(axis: int) -> tuple[int, int]:
    """The axes (i, j) that a rotation about x (0), y (1) or z (2) turns, in right-handed order:
    e_i turns towards e_j, so the matrix has cos at (i, i) and (j, j), −sin at (i, j), sin at (j, i).
    Every rotation of dhsym, exact or in floats, is written with it.

    >>> [turned_plane(axis) for axis in range(3)]
    [(1, 2), (2, 0), (0, 1)]
    """
    return ((1, 2), (2, 0), (0, 1))[axis]


def translation(axis: int, distance: sympy.Expr) -> sympy.Matrix:
    """Homogeneous translation along x (0), y (1) or z (2)."""
    m = sympy.eye(4)
    m[axis, 3] = distance
    return m


def link_steps(convention: str, theta, d, a, alpha) -> list[Step]:
    """The four steps of one DH row; in `modified` rows `a`, `alpha` are a_{i-1}, α_{i-1}."""
    if convention == "standard":
        return [Step("Rz", theta), Step("Tz", d), Step("Tx", a), Step("Rx", alpha)]
    if convention == "modified":
        return [Step("Rx", alpha), Step("Tx", a), Step("Rz", theta), Step("Tz", d)]
    raise UserError(f"unknown convention {convention!r}; use standard or modified")


def joint_axis_frame(convention: str, joint: int) -> int:
    """The frame whose z axis joint `joint` (1..n) turns about or slides along, counted from 0 for
    the frame before joint 1: z_{i−1} in the standard convention (Spong), z_i in the modified one
    (Craig). Every place that needs a joint's axis asks here.

    >>> joint_axis_frame("standard", 1), joint_axis_frame("modified", 1)
    (0, 1)
    """
    if convention not in CONVENTIONS:
        raise UserError(f"unknown convention {convention!r}; use standard or modified")
    return joint - 1 if convention == "standard" else joint


def twist_row(convention: str, joint: int) -> int:
    """The row (1..n; n + 1 where no row holds it) whose α is the twist from the axis of `joint` to
    the axis of the next joint: a row's α turns z of the frame before it into z of its own frame
    in both conventions, so this is the row after the joint's axis frame (`joint_axis_frame`):
    the joint's own row in the standard convention (αᵢ), the next one in the modified (α_i in row
    i + 1). Every place that asks which printed row holds a twist asks here.

    >>> twist_row("standard", 2), twist_row("modified", 2)
    (2, 3)
    """
    return joint_axis_frame(convention, joint) + 1


def product(steps) -> sympy.Matrix:
    """The plain matrix product of the steps, without any simplification."""
    result = sympy.eye(4)
    for step in steps:
        result = result * step.matrix()
    return result


def inverse_transform(matrix: sympy.Matrix) -> sympy.Matrix:
    """Closed-form inverse of a homogeneous transform: [Rᵀ, −Rᵀp; 0, 1]."""
    rotation_t = matrix[:3, :3].T
    result = sympy.eye(4)
    result[:3, :3] = rotation_t
    result[:3, 3] = -rotation_t * matrix[:3, 3]
    return result
