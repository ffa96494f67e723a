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

from ..core.chain import Chain, plain
from ..core.numbers import WrittenNumbers
from .fresh import TARGET_NAMES, reserved, target_symbols
from .frozen import KeepsForm

__all__ = ["TARGET_NAMES", "Branch", "DerivationStep", "Solution", "target_matrix", "target_symbols"]


def target_matrix(taken=()) -> sympy.Matrix:
    """The target as a matrix of names (fresh against the names `taken`), with the fixed bottom row 0 0 0 1."""
    return sympy.Matrix(3, 4, target_symbols(taken)).col_join(sympy.Matrix([[0, 0, 0, 1]]))


@dataclass(frozen=True)
class DerivationStep(KeepsForm):
    """One equation of the derivation, as a student writes it: `lhs = rhs`, the sub-problem it is
    an instance of (a `Subproblem` of dhsym.inverse.sentences, by name: "law of cosines", "atan2
    of a pair", ...), the unknowns it solves for, and a note: a phrase of words and the chain's
    joints and frames ("element (1, 2) of ", Frame(0), "T", Frame(6)), or plain words."""

    lhs: sympy.Expr
    rhs: sympy.Expr
    subproblem: object
    solves: tuple[sympy.Symbol, ...] = ()
    note: tuple | str = ()


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

    `method` says how it was found (a record of dhsym.inverse.sentences: Decoupled, EulerWrist,
    BySubproblems); `free` are joint variables made parameters (`--free`); `conditions` say when
    a branch exists (Exists: the argument of a square root ≥ 0, the workspace); `degenerate`
    names the poses where a family of solutions replaces the branches (Undetermined: s5 = 0, only
    θ4 + θ6 is determined); `steps` is the derivation in order. A solution written by hand may
    give any of these as plain words. `sample` gives numbers for the chain's constants (its robot
    file's: the defaults of the generated module) and `numbers` how its decimals are written.
    """

    chain: Chain  # the plain chain it solves, frames 0..n
    method: object
    joint_variables: tuple[sympy.Symbol, ...]
    definitions: tuple[tuple[sympy.Symbol, sympy.Expr], ...]
    branches: tuple[Branch, ...]
    free: tuple[sympy.Symbol, ...] = ()
    conditions: tuple = ()
    degenerate: tuple = ()
    steps: tuple[DerivationStep, ...] = field(default=())
    sample: dict = field(default_factory=dict, compare=False)
    numbers: WrittenNumbers = WrittenNumbers()

    def __post_init__(self):
        plain(self.chain)

    @property
    def target_symbols(self) -> tuple[sympy.Symbol, ...]:
        """The names of the target's elements, r11 … pz, each primed where the robot uses it."""
        return target_symbols(reserved(self.chain))

    @property
    def target(self) -> sympy.Matrix:
        return target_matrix(reserved(self.chain))
