"""The equations of motion as a textbook lays them out: typed records of what is printed, one per
line of the derivation, that the text and LaTeX printers write (`_print_<record>`), so that no
printer works out the structure again and no output is read back.

Spong's order: the inertia matrix element by element (d_ij, the upper triangle: d_ji = d_ij), the
Christoffel symbols c_ijk that are not zero, grouped by the equation k they enter (c_ijk = c_jik
printed once, as c_121 = c_211 = …), the matrix C with C_kj = Σ_i c_ijk q̇_i, the gravity torques
φ_k, and one equation per joint,

    τ_k = Σ_j d_kj q̈_j + Σ_ij c_ijk q̇_i q̇_j + φ_k,

with the terms that are zero left out and c_ijk q̇_i q̇_j + c_jik q̇_j q̇_i written once, twice.
Joints are counted 1..n as the chain counts them; a printer numbers them as the robot prints them.

>>> import dhsym
>>> from dhsym.dynamics.derive import derive
>>> arm = dhsym.load("planar2r")
>>> layout = textbook_layout(derive(arm.chain, arm.filled_masses()))
>>> [(s.i, s.j, s.k) for s in layout.christoffel]
[(1, 2, 1), (2, 2, 1), (1, 1, 2)]
>>> motion = layout.motion[0]
>>> motion.inertia, [(t.i, t.j, t.times) for t in motion.velocity], motion.gravity
((1, 2), [(1, 2, 2), (2, 2, 1)], False)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..errors import UserError
from .derive import Dynamics


@dataclass(frozen=True)
class InertiaElement:
    """d_ij, the element of M(q) in row i and column j."""

    i: int
    j: int
    value: sympy.Expr


@dataclass(frozen=True)
class ChristoffelSymbol:
    """c_ijk = ½(∂d_kj/∂q_i + ∂d_ki/∂q_j − ∂d_ij/∂q_k), i ≤ j; c_jik is the same."""

    i: int
    j: int
    k: int
    value: sympy.Expr


@dataclass(frozen=True)
class CoriolisElement:
    """C_kj = Σ_i c_ijk q̇_i: the i whose c_ijk are not zero, their rates, and the sum."""

    k: int
    j: int
    terms: tuple  # ((i, rate q̇_i), ...)
    value: sympy.Expr


@dataclass(frozen=True)
class GravityTorque:
    """φ_k = ∂P/∂q_k, the torque gravity asks of joint k."""

    k: int
    value: sympy.Expr


@dataclass(frozen=True)
class VelocityTerm:
    """`times` · c_ijk q̇_i q̇_j in the equation of joint k (2 when i ≠ j: c_ijk = c_jik)."""

    i: int
    j: int
    k: int
    times: int
    rates: tuple  # (q̇_i, q̇_j)


@dataclass(frozen=True)
class EquationOfMotion:
    """τ_k = Σ_j d_kj q̈_j + Σ c_ijk q̇_i q̇_j + φ_k, the terms that are not zero: the columns j
    of M's row k, the velocity terms, whether φ_k is there; `accelerations` are q̈_1..q̈_n."""

    k: int
    inertia: tuple
    velocity: tuple
    gravity: bool
    accelerations: tuple


@dataclass(frozen=True)
class TextbookLayout:
    """Every record of the derivation, in the order a book prints them."""

    inertia: tuple
    christoffel: tuple
    coriolis: tuple
    gravity: tuple
    motion: tuple
    n: int


def textbook_layout(result: Dynamics) -> TextbookLayout:
    """The records of a derived `result` (see the module's docstring)."""
    n = result.M.rows
    inertia = tuple(InertiaElement(i + 1, j + 1, result.M[i, j]) for i in range(n) for j in range(i, n))
    symbols = result.christoffel
    christoffel = tuple(ChristoffelSymbol(i, j, k, value) for k in range(1, n + 1) for i in range(1, n + 1)
                        for j in range(i, n + 1) for value in [symbols.get((i, j, k))] if value is not None)
    rates = result.rates
    coriolis = []
    for k in range(1, n + 1):
        for j in range(1, n + 1):
            terms = tuple((i, rates[i - 1]) for i in range(1, n + 1) if (i, j, k) in symbols)
            if terms:
                value = grouped_sum([(symbols[i, j, k], rate) for i, rate in terms])
                coriolis.append(CoriolisElement(k, j, terms, value))
    gravity = tuple(GravityTorque(k + 1, result.g[k]) for k in range(n))
    motion = []
    for k in range(1, n + 1):
        columns = tuple(j for j in range(1, n + 1) if result.M[k - 1, j - 1] != 0)
        velocity = tuple(VelocityTerm(s.i, s.j, k, 1 if s.i == s.j else 2, (rates[s.i - 1], rates[s.j - 1]))
                         for s in christoffel if s.k == k)
        motion.append(EquationOfMotion(k, columns, velocity, result.g[k - 1] != 0, result.accelerations))
    return TextbookLayout(inertia, christoffel, tuple(coriolis), gravity, tuple(motion), n)


def grouped_sum(pairs) -> sympy.Expr:
    """Σ value · factor with the factors of equal values added first: h q̇1 + h q̇2 = h(q̇1 + q̇2).

    >>> h, a, b = sympy.symbols("h a b")
    >>> grouped_sum([(h, a), (h, b), (2, a)])
    2*a + h*(a + b)
    """
    groups: dict = {}
    for value, factor in pairs:
        groups.setdefault(value, []).append(factor)
    return sympy.Add(*[value * sympy.Add(*factors) for value, factors in groups.items()])


def first_links(robot, last: int):
    """The robot with its first `last` links only (chain numbering, 1..n): the arm without what
    comes after, with the masses, gravity and sample values of those links; its name says so.

    >>> import dhsym
    >>> arm = first_links(dhsym.load("puma560"), 3)
    >>> arm.name, arm.chain.n, sorted(map(str, arm.sample))
    ('PUMA 560, to frame 3', 3, ['a_2', 'd_3'])
    """
    from ..core.chain import Chain
    from ..core.inertia import MassModel

    chain, masses, numbering = robot.chain, robot.masses, robot.numbering
    kept = MassModel(masses.links[:last], masses.gravity, masses.numbers)
    part = Chain(chain.rows[:last], chain.convention, chain.base)
    symbols = part.symbols | kept.symbols(last, numbering.first_joint)
    return robot.replace(chain=part, masses=kept, sample={s: v for s, v in robot.sample.items() if s in symbols},
                         joint_limits=robot.joint_limits[:last], name=f"{robot.name}, to frame {numbering.frame(last)}")


def links_to_frame(robot, frame: int, refused):
    """`first_links` up to the robot's frame `frame` as it prints its frames (robot.numbering: a
    wrist whose frames are 3..6 moves frames 4..6); else the UserError `refused(first, last)` says,
    given the first and last frame that a link moves.

    >>> import dhsym
    >>> wrist = dhsym.load("puma560").replace(frame_offset=3)
    >>> links_to_frame(wrist, 5, lambda first, last: f"{first}..{last}").chain.n
    2
    """
    numbering, chain = robot.numbering, robot.chain
    moved = numbering.joints(chain)  # frame k moves with joint k
    if isinstance(frame, bool) or frame not in moved:
        raise UserError(refused(moved[0], moved[-1]))
    return first_links(robot, numbering.chain_frame(frame, chain))
