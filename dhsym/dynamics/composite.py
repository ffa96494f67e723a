"""The mass matrix M(q) by composite rigid bodies (Walker and Orin; Featherstone's CRBA), in the
joint frames, on a tape.

The links i..n, frozen together, form a composite body; its mass, first moment and inertia about
the origin of J_i are link i's plus those of the composite i+1..n carried into J_i (the
parallel-axis theorem in `dhsym.dynamics.model.moved_parameters`, with the rotation about joint
i+1 in it). Turning joint i at unit rate moves the composite i..n alone: the momentum it gets,
ẑ × h and I_o ẑ (a slide: m ẑ and h × ẑ), carried inwards frame by frame, gives column i of M:
d_ki is its moment about (or its force along) the axis of joint k. Every quantity stays in a frame
that moves with the link, so the entries hold only the joints between two frames: Spong's
d22 = m2 lc2² + I2 has no angle at all.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> from dhsym.dynamics.model import rigid_model
>>> from dhsym.dynamics.tape import Tape
>>> tape = Tape()
>>> M = mass_matrix(tape, rigid_model(dhsym.load("planar2r").chain, MassModel().filled(2)))
>>> sympy.expand(tape.expanded(M[1, 1]))
I_zz2 + a_2**2*m_2 + 2*a_2*m_2*x_c2 + m_2*x_c2**2 + m_2*y_c2**2
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from .frames import add, cross, into_previous, position, tensor_into_previous
from .model import RigidModel
from .tape import Tape


@dataclass(frozen=True)
class Composite:
    """Links i..n frozen together, about the origin of J_i: mass, first moment, inertia."""

    link: int
    mass: sympy.Expr
    first_moment: tuple
    inertia: tuple


def composites(tape: Tape, model: RigidModel) -> list[Composite]:
    """The composite bodies i..n for i = 1..n, from the tip inwards."""
    out = []
    mass, h, inertia = None, None, None
    for k in range(model.n - 1, -1, -1):
        body = model.bodies[k]
        if mass is None:
            mass, h, inertia = body.mass, tape.vector(body.first_moment), tape.vector(body.inertia)
        else:
            mass, h, inertia = _carried(tape, model.bodies[k + 1], mass, h, inertia)
            mass = tape.name(mass + body.mass)
            h = add(tape, h, body.first_moment)
            inertia = tape.vector(a + b for a, b in zip(inertia, body.inertia))
        out.append(Composite(k + 1, mass, h, inertia))
    return out[::-1]


def _carried(tape: Tape, body, mass, h, inertia) -> tuple:
    """A composite of J_i (body is link i) seen from J_{i−1}: the parallel-axis theorem."""
    p = position(tape, body)
    turned = into_previous(tape, body, h)
    rotated = tensor_into_previous(tape, body, inertia)
    pp = tape.name(p[0] ** 2 + p[1] ** 2 + p[2] ** 2)
    ph = tape.name(2 * (p[0] * turned[0] + p[1] * turned[1] + p[2] * turned[2]))
    diagonal = [tape.name(mass * tape.name(pp - p[a] ** 2) + ph - 2 * p[a] * turned[a]) for a in range(3)]

    off = [tape.name(-mass * p[a] * p[b] - p[a] * turned[b] - turned[a] * p[b]) for a, b in ((0, 1), (0, 2), (1, 2))]
    moved = tape.vector(x + y for x, y in zip(rotated, diagonal + off))
    return mass, add(tape, turned, tuple(mass * x for x in p)), moved


def mass_matrix(tape: Tape, model: RigidModel, bodies: list[Composite] | None = None) -> sympy.Matrix:
    """M(q), symmetric, each entry a name on the tape (or a symbol, or 0)."""
    bodies = composites(tape, model) if bodies is None else bodies
    n = model.n
    M = sympy.zeros(n, n)
    for i in range(n):
        whole = bodies[i]
        if model.bodies[i].joint == "R":
            force = (-whole.first_moment[1], whole.first_moment[0], sympy.Integer(0))
            moment = (whole.inertia[4], whole.inertia[5], whole.inertia[2])
        else:
            force = (sympy.Integer(0), sympy.Integer(0), whole.mass)
            moment = (whole.first_moment[1], -whole.first_moment[0], sympy.Integer(0))
        gain = model.bodies[i].gain  # the column of a unit rate of the joint's variable
        force, moment = tape.vector(gain * x for x in force), tape.vector(gain * x for x in moment)
        M[i, i] = tape.name(gain * (moment[2] if model.bodies[i].joint == "R" else force[2]))
        for k in range(i - 1, -1, -1):
            after = model.bodies[k + 1]
            pushed = into_previous(tape, after, force)
            moment = add(tape, into_previous(tape, after, moment), cross(tape, position(tape, after), pushed))
            force = pushed
            M[k, i] = M[i, k] = tape.name(model.bodies[k].gain * (moment[2] if model.bodies[k].joint == "R"
                                                                   else force[2]))

    return M
