"""Vectors and inertias carried from one joint frame to the next, each entry named on a tape.

J_{i−1} → J_i is Rx(α) Tx(a) Rz(θ) Tz(d) (Craig's row i). A vector of J_{i−1} seen in J_i is
Rz(θ)ᵀ Rx(α)ᵀ v; one of J_i seen in J_{i−1} is Rx(α) Rz(θ) v. With α a multiple of π/2 the twist
only swaps and negates entries, and SymPy's arithmetic drops every product by 0 and 1 as it is
built: the "customized" recursion of Khalil and Kleinfinger comes for free.

>>> import sympy
>>> from dhsym.dynamics.model import Body
>>> from dhsym.dynamics.tape import Tape
>>> q = sympy.Symbol("q", real=True)
>>> body = Body("R", q, -sympy.pi / 2, 0, q, 0, 1, (0, 0, 0), (0,) * 6)
>>> tape = Tape()
>>> [tape.expanded(x) for x in into_next(tape, body, (0, 0, 1))]
[-sin(q), -cos(q), 0]
"""
from __future__ import annotations

import sympy

from ..core.vectors import cross as plain_cross
from .tape import Tape


def trig(tape: Tape, angle) -> tuple:
    """(cos, sin) of an angle, named: exact numbers for a multiple of π/2."""
    return tape.name(sympy.cos(angle)), tape.name(sympy.sin(angle))


def twist_back(tape: Tape, body, v) -> tuple:
    """Rx(α)·v."""
    c, s = trig(tape, body.twist)
    return tape.vector((v[0], c * v[1] - s * v[2], s * v[1] + c * v[2]))


def twist_forward(tape: Tape, body, v) -> tuple:
    """Rx(α)ᵀ·v."""
    c, s = trig(tape, body.twist)
    return tape.vector((v[0], c * v[1] + s * v[2], -s * v[1] + c * v[2]))


def into_next(tape: Tape, body, v) -> tuple:
    """A vector of J_{i−1} in J_i: Rz(θ)ᵀ Rx(α)ᵀ v."""
    w = twist_forward(tape, body, v)
    c, s = trig(tape, body.angle)
    return tape.vector((c * w[0] + s * w[1], -s * w[0] + c * w[1], w[2]))


def into_previous(tape: Tape, body, v) -> tuple:
    """A vector of J_i in J_{i−1}: Rx(α) Rz(θ) v."""
    c, s = trig(tape, body.angle)
    return twist_back(tape, body, tape.vector((c * v[0] - s * v[1], s * v[0] + c * v[1], v[2])))


def position(tape: Tape, body) -> tuple:
    """The origin of J_i in J_{i−1}."""
    return tape.vector(body.position)


def cross(tape: Tape, u, v) -> tuple:
    return tape.vector(plain_cross(u, v))


def add(tape: Tape, *vectors) -> tuple:
    return tape.vector(sympy.Add(*parts) for parts in zip(*vectors))


def scale(tape: Tape, factor, v) -> tuple:
    return tape.vector(factor * x for x in v)


def times_tensor(tape: Tape, inertia, v) -> tuple:
    """I·v for the six entries (Ixx, Iyy, Izz, Ixy, Ixz, Iyz)."""
    xx, yy, zz, xy, xz, yz = inertia
    return tape.vector((xx * v[0] + xy * v[1] + xz * v[2], xy * v[0] + yy * v[1] + yz * v[2],
                        xz * v[0] + yz * v[1] + zz * v[2]))


def tensor_into_previous(tape: Tape, body, inertia) -> tuple:
    """R I Rᵀ for R = Rx(α) Rz(θ): an inertia of J_i in the axes of J_{i−1}."""
    c, s = trig(tape, body.angle)
    xx, yy, zz, xy, xz, yz = inertia
    # Rz(θ) I Rz(θ)ᵀ, with the sums and differences shared
    cc, ss, cs = tape.name(c * c), tape.name(s * s), tape.name(c * s)
    turned = (cc * xx + ss * yy - 2 * cs * xy, ss * xx + cc * yy + 2 * cs * xy, zz,
              cs * tape.name(xx - yy) + tape.name(cc - ss) * xy, c * xz - s * yz, s * xz + c * yz)
    xx, yy, zz, xy, xz, yz = tape.vector(turned)
    ca, sa = trig(tape, body.twist)  # then Rx(α) · Rx(α)ᵀ
    caa, saa, csa = tape.name(ca * ca), tape.name(sa * sa), tape.name(ca * sa)
    return tape.vector((xx, caa * yy + saa * zz - 2 * csa * yz, saa * yy + caa * zz + 2 * csa * yz,
                        ca * xy - sa * xz, sa * xy + ca * xz, csa * tape.name(yy - zz) + tape.name(caa - saa) * yz))

