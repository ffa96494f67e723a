"""What a robot's links weigh: each link's mass, centre of mass and inertia tensor, and gravity.

Link i is the body that joint i moves; its numbers are given in frame i, the frame its row's
transform ends in: the centre of mass `com` = (x, y, z), and the inertia tensor about the centre of
mass with axes parallel to frame i, as its six entries (Ixx, Iyy, Izz, Ixy, Ixz, Iyz): the matrix
[[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]], as a URDF writes it. A field left out (None)
stands for the generic symbols m_i, (x_ci, y_ci, z_ci), (I_xxi, …), numbered as the robot numbers
its joints. `gravity` is the acceleration of gravity in the first frame (the base frame when there
is one, else frame 0); None stands for (0, 0, −g).

>>> link = LinkInertia(mass=sympy.Integer(2))
>>> filled = link.filled(3)
>>> filled.mass, filled.com, filled.inertia[:3]
(2, (x_c3, y_c3, z_c3), (I_xx3, I_yy3, I_zz3))
>>> MassModel().filled(2, first_joint=4).links[1].mass, MassModel().filled(1).gravity
(m_5, (0, 0, -g))
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from .numbers import WrittenNumbers

INERTIA_ENTRIES = ("xx", "yy", "zz", "xy", "xz", "yz")
_TENSOR_INDEX = {(0, 0): 0, (1, 1): 1, (2, 2): 2, (0, 1): 3, (1, 0): 3, (0, 2): 4, (2, 0): 4, (1, 2): 5, (2, 1): 5}
GRAVITY_SYMBOL = sympy.Symbol("g", real=True)


def _real(name: str) -> sympy.Symbol:
    return sympy.Symbol(name, real=True)


def generic_mass(number: int) -> sympy.Symbol:
    return _real(f"m_{number}")


def generic_com(number: int) -> tuple:
    return tuple(_real(f"{axis}_c{number}") for axis in "xyz")


def generic_inertia(number: int) -> tuple:
    return tuple(_real(f"I_{entry}{number}") for entry in INERTIA_ENTRIES)


def tensor(entries) -> sympy.Matrix:
    """The symmetric 3×3 matrix of the six entries (Ixx, Iyy, Izz, Ixy, Ixz, Iyz).

    >>> tensor((1, 2, 3, 4, 5, 6))
    Matrix([
    [1, 4, 5],
    [4, 2, 6],
    [5, 6, 3]])
    """
    return sympy.Matrix(3, 3, lambda r, c: sympy.sympify(entries[_TENSOR_INDEX[r, c]]))


def entries(matrix: sympy.Matrix) -> tuple:
    """The six entries (Ixx, Iyy, Izz, Ixy, Ixz, Iyz) of a symmetric 3×3 matrix."""
    return (matrix[0, 0], matrix[1, 1], matrix[2, 2], matrix[0, 1], matrix[0, 2], matrix[1, 2])


@dataclass(frozen=True)
class LinkInertia:
    """One link's inertial parameters in its frame; None fields are the generic symbols."""

    mass: sympy.Expr | None = None
    com: tuple | None = None
    inertia: tuple | None = None

    @property
    def given(self) -> bool:
        """Whether the robot says anything about this link."""
        return not (self.mass is None and self.com is None and self.inertia is None)

    def filled(self, number: int) -> "LinkInertia":
        """Every field a value: the generic symbols of link `number` where none is given."""
        return LinkInertia(generic_mass(number) if self.mass is None else self.mass,
                           generic_com(number) if self.com is None else tuple(self.com),
                           generic_inertia(number) if self.inertia is None else tuple(self.inertia))

    def moved(self, rotation: sympy.Matrix, offset) -> "LinkInertia":
        """The same link seen from a frame in which this link's frame has orientation `rotation`
        and origin `offset`: com' = R com + p, I' = R I Rᵀ (about the centre of mass). A generic
        (None) field stays generic: any values in one frame are any values in the other.

        >>> half_turn = sympy.diag(1, -1, -1)
        >>> LinkInertia(com=(1, 2, 3), inertia=(1, 2, 3, 4, 5, 6)).moved(half_turn, (10, 0, 0))
        LinkInertia(mass=None, com=(11, -2, -3), inertia=(1, 2, 3, -4, -5, 6))
        """
        com = None if self.com is None else \
            tuple(sympy.expand(x) for x in rotation * sympy.Matrix(self.com) + sympy.Matrix(offset))
        inertia = None if self.inertia is None else \
            tuple(sympy.expand(x) for x in entries(rotation * tensor(self.inertia) * rotation.T))
        return LinkInertia(self.mass, com, inertia)

    @property
    def symbols(self) -> set:
        values = [self.mass] + list(self.com or ()) + list(self.inertia or ())
        return set().union(*(sympy.sympify(v).free_symbols for v in values if v is not None))


@dataclass(frozen=True)
class MassModel:
    """The links' inertial parameters (link 1..n; an empty tuple: all generic), gravity in the
    first frame (None: (0, 0, −g)), and how a robot file wrote their numbers."""

    links: tuple = ()
    gravity: tuple | None = None
    numbers: WrittenNumbers = field(default=WrittenNumbers(), compare=False)

    def __post_init__(self):
        object.__setattr__(self, "links", tuple(self.links))
        if self.gravity is not None:
            object.__setattr__(self, "gravity", tuple(sympy.sympify(x) for x in self.gravity))

    @property
    def given(self) -> bool:
        """Whether the robot says anything about its masses or gravity."""
        return self.gravity is not None or any(link.given for link in self.links)

    def link(self, joint: int) -> LinkInertia:
        """The parameters of link `joint` (1..n) as given (generic where nothing is)."""
        return self.links[joint - 1] if joint <= len(self.links) else LinkInertia()

    def filled(self, n: int, first_joint: int = 1) -> "MassModel":
        """Every link and gravity a value; generic symbols numbered from `first_joint` (a
        wrist whose joints are 4..6: m_4, m_5, m_6)."""
        links = tuple(self.link(k).filled(first_joint + k - 1) for k in range(1, n + 1))
        gravity = (0, 0, -GRAVITY_SYMBOL) if self.gravity is None else self.gravity
        return MassModel(links, gravity, self.numbers)

    def symbols(self, n: int, first_joint: int = 1) -> set:
        """Every symbol the filled model uses (the generic names included)."""
        filled = self.filled(n, first_joint)
        return set().union(*(link.symbols for link in filled.links),
                           *(sympy.sympify(x).free_symbols for x in filled.gravity))
