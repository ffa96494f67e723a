"""The wrist centre of a spherical wrist, exactly: where the first two wrist axes meet, in the
frame of the link before the wrist, and the same point in the last frame (constant: it lies on
the last axis), from which the target gives it as p_c = p + R·c (Spong's p − d6 R z).

>>> import dhsym
>>> centre(dhsym.load("stanford"), (4, 5, 6))
(3, Matrix([
[0],
[0],
[0]]), Matrix([
[   0],
[   0],
[-d_6]]))
"""
from __future__ import annotations

import sympy

from ..core.transforms import joint_axis_frame


def axis_in(chain, joint: int, frame: int, zero: dict) -> tuple[sympy.Matrix, sympy.Matrix]:
    """(point, unit direction) of the axis of `joint` in `frame`, with the variables in `zero` set."""
    m = chain.transform(frame, joint_axis_frame(chain.convention, joint)).xreplace(zero)
    return m[:3, 3], m[:3, 2]


def centre(chain, wrist) -> tuple[int, sympy.Matrix, sympy.Matrix]:
    """(holder frame, the centre in it, the centre in the last frame) for the wrist joints `wrist`."""
    first = wrist[0]
    holder = first - 1
    zero = {chain.joint_variables[j - 1]: 0 for j in wrist}
    (p1, u1), (p2, u2) = axis_in(chain, first, holder, zero), axis_in(chain, wrist[1], holder, zero)
    w = p1 - p2
    b, d, e = u1.dot(u2), u1.dot(w), u2.dot(w)
    s = _simplified((b * e - d) / (1 - b ** 2))
    point = (p1 + s * u1).applyfunc(_simplified)
    back = chain.transform(chain.last_frame, holder).xreplace(zero)
    in_last = (back[:3, :3] * point + back[:3, 3]).applyfunc(_simplified)
    return holder, point, in_last


def centre_at_start(chain, wrist) -> tuple[int, sympy.Matrix, sympy.Matrix]:
    """(holder frame, the centre in it, the centre in the first frame) for a wrist at the start:
    the first two axes meet at a point fixed in the base, and in the link after the wrist."""
    first = chain.first_frame
    zero = {chain.joint_variables[j - 1]: 0 for j in wrist}
    (p1, u1), (p2, u2) = axis_in(chain, wrist[0], first, zero), axis_in(chain, wrist[1], first, zero)
    w = p1 - p2
    b, d, e = u1.dot(u2), u1.dot(w), u2.dot(w)
    s = _simplified((b * e - d) / (1 - b ** 2))
    point = (p1 + s * u1).applyfunc(_simplified)
    holder = wrist[-1]
    there = chain.transform(holder, first).xreplace(zero)
    return holder, (there[:3, :3] * point + there[:3, 3]).applyfunc(_simplified), point


def _simplified(expr: sympy.Expr) -> sympy.Expr:
    """sympy.simplify, except for what it leaves as it is: a rational number, a symbol, or a
    product of those (the wrist centre is −d6 or d4 in most arms, and simplify costs a tenth of
    the PUMA's derivation)."""
    if all(f.is_Rational or f.is_Symbol for f in sympy.Mul.make_args(expr)):
        return expr
    return sympy.simplify(expr)
