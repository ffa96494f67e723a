"""What a closed-form inverse-kinematics derivation produces: the contract between the solver
(dhsym.inverse) and every surface that shows it (text, LaTeX, JSON, generated Python).

The target is the 4x4 transform that `dhsym fk` prints by default, written with the names of
its elements (primed where the robot uses one of them itself, see dhsym.inverse.fresh):

>>> target_matrix()[:3, 3].T, target_matrix({"px"})[:3, 3].T
(Matrix([[px, py, pz]]), Matrix([[pxʹ, py, pz]]))

A solution lists `definitions` (intermediate quantities shared by every branch, in order: the
wrist centre `x_c`, `r`, `D`, ...) and `branches`, each an ordered list of assignments. An
assignment may use the target's names, the robot's constants, the definitions and the names
assigned before it in its branch; every joint variable is assigned in every branch.

A solution pickles and deep-copies with its expressions as they are (dhsym.inverse.frozen).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from .fresh import TARGET_NAMES, reserved, target_symbols
from .frozen import KeepsForm

__all__ = ["TARGET_NAMES", "Branch", "Solution", "Step", "target_matrix", "target_symbols"]


def target_matrix(taken=()) -> sympy.Matrix:
    """The target as a matrix of names (fresh against the names `taken`), with the fixed bottom row 0 0 0 1."""
    return sympy.Matrix(3, 4, target_symbols(taken)).col_join(sympy.Matrix([[0, 0, 0, 1]]))


@dataclass(frozen=True)
class Step(KeepsForm):
    """One equation of the derivation, as a student writes it: `lhs = rhs`, the sub-problem it is
    an instance of (e.g. "a cos θ + b sin θ = c", "law of cosines", "atan2 of a pair",
    "prismatic joint from a distance", "sum of parallel-axis angles", "Euler angles of the wrist"),
    the unknowns it solves for, and a short note in words."""

    lhs: sympy.Expr
    rhs: sympy.Expr
    subproblem: str
    solves: tuple[sympy.Symbol, ...] = ()
    note: str = ""


@dataclass(frozen=True)
class Branch(KeepsForm):
    """One solution branch: a name in words ("shoulder left, elbow up, wrist not flipped") and its
    assignments [(name, expression), ...] in the order they are computed."""

    name: str
    assignments: tuple[tuple[sympy.Symbol, sympy.Expr], ...]

    def values(self) -> dict:
        """The assignments as a mapping, name -> expression."""
        return dict(self.assignments)


@dataclass(frozen=True)
class Solution(KeepsForm):
    """A closed-form inverse-kinematics solution of a chain.

    `method` says in words how it was found ("kinematic decoupling: axes 4, 5, 6 meet at the wrist
    centre", "planar arm", ...); `free` are joint variables made parameters (`--free`);
    `conditions` say when a branch exists (the argument of a square root ≥ 0: the workspace);
    `degenerate` names the poses where a family of solutions replaces the branches
    ("s5 = 0: only θ4 + θ6 is determined"); `steps` is the derivation in order.
    """

    chain: object  # the dhsym Chain it solves
    method: str
    joint_variables: tuple[sympy.Symbol, ...]
    definitions: tuple[tuple[sympy.Symbol, sympy.Expr], ...]
    branches: tuple[Branch, ...]
    free: tuple[sympy.Symbol, ...] = ()
    conditions: tuple[str, ...] = ()
    degenerate: tuple[str, ...] = ()
    steps: tuple[Step, ...] = field(default=())

    @property
    def target_symbols(self) -> tuple[sympy.Symbol, ...]:
        """The names of the target's elements, r11 … pz, each primed where the robot uses it."""
        return target_symbols(reserved(self.chain))

    @property
    def target(self) -> sympy.Matrix:
        return target_matrix(reserved(self.chain))
