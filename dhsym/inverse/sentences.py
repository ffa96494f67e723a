"""What a derivation says besides its formulas, as small records the printers write out
(dhsym.printing.ik_sentences writes each as text, LaTeX and the JSON's strings): when a branch
exists, where the branches degenerate, and the method. Nothing here is text to read back: an
expression stays an expression, a joint or frame stays a number of the chain (1..n, 0..n), which
the printers write as the robot file numbers it.

>>> import sympy
>>> D, t2 = sympy.symbols("D theta_2", real=True)
>>> Exists(1 - D**2, unknown=t2)
Exists(expression=1 - D**2, relation='>=', unknown=theta_2, singular=())
>>> Undetermined((sympy.sin(t2),), t2, LinedUp(t2)).reason.said
False
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from .frozen import KeepsForm


@dataclass(frozen=True)
class Joint:
    """Joint `number` of the chain (1..n), printed as the robot file numbers it."""

    number: int


@dataclass(frozen=True)
class Frame:
    """Frame `frame` of the chain (0..n, "base", "tool"), printed as the robot file numbers it."""

    frame: int | str


# A phrase: words (str), joints and frames of the chain, in order ("element (1, 2) of ", Frame(0), "T", Frame(6)).
Phrase = tuple


# ------------------------------------------------------------------ when a branch exists


@dataclass(frozen=True)
class Singular(KeepsForm):
    """A factor of det J (`factor`, as `dhsym jacobian` prints it) and its meaning: `template`
    with {0}, {1} … for the joints `joints` (1..n), as dhsym.velocity.singularities words it."""

    factor: sympy.Expr
    template: str = ""
    joints: tuple[int, ...] = ()


@dataclass(frozen=True)
class Exists(KeepsForm):
    """`expression relation 0` (the argument of a square root ≥ 0); `unknown`: what has no real
    value otherwise (the target out of reach), where that is said; `singular`: the factors of det J
    (a Singular each) whose product vanishes exactly where the expression is 0 and the two roots
    meet (Stanford's x_c² + y_c² − d2² is d3² s2²), where there are such factors."""

    expression: sympy.Expr
    relation: str = ">="
    unknown: sympy.Expr | None = None
    singular: tuple[Singular, ...] = ()


@dataclass(frozen=True)
class RealRoot(KeepsForm):
    """Pieper's quartic: the branches of `joint` exist where its root `root` (u = tan(θ/2)) is real."""

    joint: sympy.Symbol
    root: sympy.Symbol


@dataclass(frozen=True)
class Consistent(KeepsForm):
    """An arm of `unknowns` joints (fewer than six) uses only the target elements `used`; the
    others must agree with them, and `fixed` [(element, value)] are the same in every pose, as are
    `relations` [(expression, value)] of several elements (dhsym.inverse.consistency)."""

    unknowns: int
    used: tuple[sympy.Symbol, ...]
    fixed: tuple[tuple[sympy.Symbol, sympy.Expr], ...] = ()
    relations: tuple[tuple[sympy.Expr, sympy.Expr], ...] = ()


# ------------------------------------------------------------------ where the branches degenerate


@dataclass(frozen=True)
class ByEquations:
    """The unknown is not determined by the `count` equations it was solved from (1 or 2)."""

    count: int


@dataclass(frozen=True)
class LinedUp(KeepsForm):
    """sin(angle) = 0 (angle θk, or θk plus a number) lines up the axes on either side of joint k:
    only a sum or difference of the angles about them is determined. `before` and `after` are the
    runs of joints [(variable, ±1)] turning with the axes before and after k, the signs those of
    angle 0 (at angle π the signs after k flip); both empty where that was not measured."""

    angle: sympy.Expr
    before: tuple[tuple[sympy.Symbol, int], ...] = ()
    after: tuple[tuple[sympy.Symbol, int], ...] = ()

    @property
    def said(self) -> bool:
        """Whether the sum and difference were measured."""
        return bool(self.before and self.after)

    def total(self, at_pi: bool = False) -> sympy.Expr:
        """The angle that is still determined (at angle 0, or at angle π)."""
        flip = -1 if at_pi else 1
        return sympy.Add(*(sign * v for v, sign in self.before), *(flip * sign * v for v, sign in self.after))


@dataclass(frozen=True)
class OnAxis:
    """A point of the arm lies on the axis of `joint` (1..n): `point` "wrist centre" (Pieper's case,
    the PUMA's θ2 + θ3), "end point" (the planar 2R's px = 0 and py = 0) or "frame" (the origin of
    frame `frame`, the planar 3R's wrist); `only`: (lhs, rhs), where the point gets there only if
    lhs = rhs (the UR5's a2² = a3²)."""

    joint: int
    point: str = "wrist centre"
    frame: int | None = None
    only: tuple = ()  # (lhs, rhs): the constants' relation without which the point never gets there


@dataclass(frozen=True)
class Undetermined(KeepsForm):
    """Where every expression of `condition` is 0, `unknown` (a joint variable or a sum of
    angles) is not determined, for the `reason` given (ByEquations, LinedUp, OnAxis);
    `singular`: the factor of det J that the condition is (a Singular), where it is one;
    `member`: [(joint, value)] a numeric evaluation takes there instead of the branch's value
    (the wrist's θ6 through θ4 where the books' atan2(σ r32, −σ r31) is atan2(0, 0))."""

    condition: tuple[sympy.Expr, ...]
    unknown: sympy.Expr
    reason: object = ByEquations(2)
    singular: Singular | None = None
    member: tuple[tuple[sympy.Symbol, sympy.Expr], ...] = ()


@dataclass(frozen=True)
class RootAtPi(KeepsForm):
    """Pieper's quartic loses its leading term where `leading` = 0: then θ = π (of `joint`) is a
    root, which the half-angle `root` = tan(θ/2) does not reach."""

    leading: sympy.Symbol
    joint: sympy.Symbol
    root: sympy.Symbol


# ------------------------------------------------------------------ the method


@dataclass(frozen=True)
class Point:
    """A point a branch's word is measured from: `kind` "wrist centre", "meeting" (where the axes
    `axes` meet), "axis point" (the point of axis `axes[0]` in the arm's plane), "wrist point"
    (on axis `axes[0]`), "end point" or "target origin"."""

    kind: str
    axes: tuple[int, ...] = ()


@dataclass(frozen=True)
class Meaning:
    """What one word of the branch names means (`key`, see dhsym.inverse.naming), for the joints
    `joints` {role: joint 1..n} and points `points` {role: Point} of this arm; "root" for the sign
    of a root, where no word holds."""

    key: str
    joints: tuple[tuple[str, int], ...] = ()
    points: tuple[tuple[str, Point], ...] = ()


@dataclass(frozen=True, kw_only=True)
class Method(KeepsForm):
    """How a solution was found. `used`: the target elements an arm of fewer than six joints reads
    (said with the method); `words`: what the words of the branch names mean."""

    used: tuple[sympy.Symbol, ...] = ()
    words: tuple[Meaning, ...] = field(default=())


@dataclass(frozen=True, kw_only=True)
class Decoupled(Method):
    """Kinematic decoupling: the axes of the joints `wrist` (1..n) meet at a point, at the end
    (the wrist centre) or, `at_start`, fixed in the base; that point gives `arm`, by Pieper's
    quartic in the joint `quartic` (1..n) where he solved them, and the orientation `oriented`."""

    wrist: tuple[int, ...]
    arm: tuple[sympy.Symbol, ...]
    oriented: tuple[sympy.Symbol, ...]
    at_start: bool = False
    quartic: int | None = None


@dataclass(frozen=True, kw_only=True)
class EulerWrist(Method):
    """A spherical wrist alone: the axes of `joints` (1..n) meet in a point; Euler angles."""

    joints: tuple[int, ...]


@dataclass(frozen=True, kw_only=True)
class BySubproblems(Method):
    """The search for sub-problems in the equations; `parallel`: Hawkins's way for three parallel axes."""

    parallel: bool = False


# ------------------------------------------------------------------ a step of the derivation


@dataclass(frozen=True)
class Subproblem:
    """The sub-problem a step is an instance of, by name (see NAMES); `joint` (1..n) for the names
    that mention one (Pieper's); `double_root` where a² + b² = c² at every pose."""

    name: str
    joint: int | None = None
    double_root: bool = False


NAMES = ("a cos θ + b sin θ = c", "law of cosines", "a cos θ = c", "a sin θ = c", "atan2 of a pair",
         "sum of parallel-axis angles",
         "prismatic joint from a coordinate", "prismatic joint from a distance", "Pieper's distance",
         "Pieper's height", "Ferrari's quartic")
