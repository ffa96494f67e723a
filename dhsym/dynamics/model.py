"""The rigid bodies the recursions work on: each link in the frame on its own joint axis.

Dynamics is simplest in the frame whose z axis is the link's joint axis and which moves with the
link: Craig's frame i (modified DH), called here the joint frame J_i. A modified chain has it
already; a standard chain (Spong's frame i sits at the far end of link i, on the next axis) is
regrouped first (`dhsym.geometry.convert`), which keeps frame 0 and every joint variable, and each
link's parameters are carried from Spong's frame i to J_i: F_i = J_i · Tx(a_i) · Rx(α_i). This is
where the textbook's own reduction happens: Spong's planar arm gives its centre of mass at
(lc1 − l1, 0, 0) in frame 1, which is (lc1, 0, 0) in J_1.

The recursions need a link's parameters about the origin of J_i: the mass m, the first moment
h = m·c and the inertia about the origin, I_o = I_c + m(|c|² 1 − c cᵀ), all linear in the standard
inertial parameters (the regressor's π).

>>> import dhsym
>>> from dhsym.core.inertia import LinkInertia, MassModel
>>> l1, lc1 = sympy.symbols("l_1 lc_1", real=True)
>>> masses = MassModel((LinkInertia(com=(lc1 - l1, 0, 0), inertia=(0, 0, 0, 0, 0, 0)),))
>>> arm = dhsym.Chain([dhsym.DHRow.revolute(sympy.Symbol("q_1", real=True), a=l1)], "standard")
>>> model = rigid_model(arm, masses.filled(1))
>>> model.bodies[0].first_moment, model.gravity
((lc_1*m_1, 0, 0), (0, 0, -g))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import LinkInertia, MassModel, entries, tensor
from ..core.transforms import rotation
from ..geometry.convert import to_convention

STANDARD_NAMES = ("XX", "YY", "ZZ", "XY", "XZ", "YZ", "MX", "MY", "MZ")  # Khalil's names, and the mass m_i


@dataclass(frozen=True)
class Body:
    """Link i in its joint frame J_i: how J_i sits on J_{i−1} (Rx(twist) Tx(length) Rz(angle)
    Tz(offset), Craig's row i), and the link's mass, first moment h and inertia about J_i's origin
    (six entries Ixx, Iyy, Izz, Ixy, Ixz, Iyz)."""

    joint: str
    variable: sympy.Symbol
    twist: sympy.Expr
    length: sympy.Expr
    angle: sympy.Expr
    offset: sympy.Expr
    mass: sympy.Expr
    first_moment: tuple
    inertia: tuple

    @property
    def gain(self) -> sympy.Expr:
        """How fast the joint turns (or slides) with its variable: −1 for θ = −q, 1 mostly."""
        return sympy.diff(self.angle if self.joint == "R" else self.offset, self.variable)

    @property
    def position(self) -> tuple:

        """The origin of J_i in J_{i−1}: Rx(α)·(a, 0, d)... = (a, −sin α·d, cos α·d)."""
        return (self.length, -sympy.sin(self.twist) * self.offset, sympy.cos(self.twist) * self.offset)


@dataclass(frozen=True)
class RigidModel:
    """The bodies 1..n and the acceleration of gravity in J_0 (frame 0)."""

    bodies: tuple
    gravity: tuple

    @property
    def n(self) -> int:
        return len(self.bodies)

    @property
    def variables(self) -> list:
        return [body.variable for body in self.bodies]


def about_origin(link: LinkInertia) -> tuple:
    """(m, h, I_o) of a filled link: the first moment m·c and the inertia about the frame's origin
    (parallel-axis theorem), as six entries."""
    m, c = link.mass, sympy.Matrix(link.com)
    inertia = tensor(link.inertia) + m * ((c.T * c)[0] * sympy.eye(3) - c * c.T)
    return m, tuple(m * x for x in c), entries(inertia)


def moved_parameters(parameters: tuple, turn: sympy.Matrix, offset) -> tuple:
    """(m, h, I_o) of a body seen from a frame in which its frame has orientation `turn` and origin
    `offset`: linear in (m, h, I_o), so that the regressor's parameters move the same way.

    >>> moved_parameters((2, (0, 0, 0), (1, 1, 1, 0, 0, 0)), sympy.eye(3), (1, 0, 0))[1:]
    ((2, 0, 0), (1, 3, 3, 0, 0, 0))
    """
    m, h, inertia = parameters
    p, turned = sympy.Matrix(offset), turn * sympy.Matrix(h)
    about = turn * tensor(inertia) * turn.T + m * ((p.T * p)[0] * sympy.eye(3) - p * p.T) \
        + 2 * (p.T * turned)[0] * sympy.eye(3) - p * turned.T - turned * p.T
    return m, tuple(sympy.expand(x) for x in turned + m * p), tuple(sympy.expand(x) for x in entries(about))


def standard_parameters(number: int) -> tuple:
    """The ten standard inertial parameters of link `number` as symbols, in (m, h, I_o) form:
    m_i, (MX_i, MY_i, MZ_i), (XX_i, YY_i, ZZ_i, XY_i, XZ_i, YZ_i)."""
    names = [sympy.Symbol(f"{name}_{number}", real=True) for name in STANDARD_NAMES]
    return sympy.Symbol(f"m_{number}", real=True), tuple(names[6:]), tuple(names[:6])


def rigid_model(chain: Chain, masses: MassModel, parameters: list | None = None) -> RigidModel:
    """The bodies of `chain` with the filled `masses` (or, for the regressor, `parameters`: each
    link's (m, h, I_o) about the origin of the chain's own frame i)."""
    if len(masses.links) != chain.n:
        raise ValueError(f"{len(masses.links)} links' masses for a chain of {chain.n} joints")
    parameters = parameters or [about_origin(link) for link in masses.links]
    if chain.convention == "standard":  # Spong's frame i → J_i: F_i = J_i · Tx(a_i) Rx(α_i)
        parameters = [moved_parameters(p, rotation(0, row.alpha)[:3, :3], (row.a, 0, 0))
                      for p, row in zip(parameters, chain.rows)]
    modified = to_convention(chain, "modified")
    bodies = tuple(Body(row.joint, row.variable, row.alpha, row.a, row.theta, row.d, m, h, inertia)
                   for row, (m, h, inertia) in zip(modified.rows, parameters))
    first = modified.frames[0]
    turn = modified.transform(0, first)[:3, :3] if first != 0 else sympy.eye(3)
    gravity = tuple(sympy.expand(x) for x in turn * sympy.Matrix(masses.gravity))
    return RigidModel(bodies, gravity)
