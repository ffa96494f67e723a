"""What a round of the search (dhsym.inverse.scan) reads off one equation before choosing: its shape
(the one unknown, or the one sum of angles, it holds), its sub-problem form (a, b, c of
a cos θ + b sin θ = c, or a slide's polynomial), and what the witness pose says of it (nothing:
0 = 0; a double root; a pair that does not determine its angle).

>>> import sympy
>>> from dhsym.inverse.equations import Equation
>>> from dhsym.inverse.lookups import Memos
>>> x, t1, t2 = sympy.symbols("x theta_1 theta_2", real=True)
>>> equation = Equation(x, sympy.cos(t1 + t2), "position", ("x",))
>>> shape_of(equation, [t1, t2], set(), Memos())
(theta_1 + theta_2, theta_2)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.size import tree_size
from . import algebra
from . import subproblems as sp
from .witness import number_at

WITNESS_ZERO = 1e-8


@dataclass(frozen=True)
class Candidate:
    """An equation in the form of a sub-problem: `form` is (a, b, c) for an angle, the polynomial's
    coefficients for a slide; `angle` the unknown or the sum of angles it enters through, `variable`
    the unknown it determines."""

    equation: object
    angle: sympy.Expr
    form: tuple
    variable: sympy.Symbol


def vanishes(expr, witness: dict) -> bool:
    """Whether `expr` is zero at the witness pose (as far as the numbers tell)."""
    value = number_at(expr, witness)
    return value is not None and abs(value) < WITNESS_ZERO


def touches(candidate: Candidate, slide: bool, witness) -> bool:
    """Whether the square root's argument of a two-root equation vanishes at the witness pose: an
    equation can touch an arm of fewer than six joints' poses everywhere (one double root), and
    its ±√ of rounding noise would cost digits."""
    argument = sp.root_argument(candidate.form, slide)
    return argument is not None and bool(witness) and vanishes(argument, witness)


def says_nothing(candidate: Candidate, prismatic, witness) -> bool:
    """0 = 0 at the witness pose: the leading coefficients vanish once earlier results hold."""
    if candidate.variable in prismatic:
        return vanishes(candidate.form[0], witness)
    return vanishes(candidate.form[0], witness) and vanishes(candidate.form[1], witness)


def pair_works(first, second, witness) -> bool:
    """A pair determines the angle: its determinant is not zero, nor are both its solutions' numerators."""
    (a1, b1, k1), (a2, b2, k2) = first, second
    if not witness:
        return sp.determinant(first, second, factored=False) != 0 and sp.pair_is_defined(first, second)
    return not vanishes(a1 * b2 - a2 * b1, witness) and not (vanishes(k1 * b2 - b1 * k2, witness)
                                                             and vanishes(a1 * k2 - a2 * k1, witness))


def sizes(equation) -> tuple[int, int]:
    """The tree sizes of an equation's chain side and of the whole."""
    return tree_size(equation.rhs), tree_size(equation.expr)


def shape_of(equation, remaining, prismatic, memos):
    """(the unknown or sum of angles it enters through, the unknown it determines), when the
    equation holds one unknown (or one sum of angles); else None. Structure only, no algebra."""
    expr = equation.expr
    unknown = memos.free_symbols(expr) & set(remaining)
    if not unknown:
        return None
    if unknown & prismatic:
        return (next(iter(unknown)),) * 2 if len(unknown) == 1 else None
    angles = {f.args[0] for f in memos.trig_atoms(expr) if memos.free_symbols(f.args[0]) & unknown}
    if len(angles) == 1:
        (angle,) = angles
        variable = _last(angle, unknown, remaining)
        if variable is not None and (not _outside(expr, angle, unknown) or not (
                expr.xreplace({sympy.cos(angle): 0, sympy.sin(angle): 0}).free_symbols & unknown)):
            return angle, variable
    return (next(iter(unknown)),) * 2 if len(unknown) == 1 else None


def _outside(expr, angle, unknown) -> bool:
    """Whether an unknown occurs anywhere but in cos(angle) and sin(angle): a walk that spares
    rebuilding the expression (when none does, putting 0 for them leaves no unknown)."""
    if isinstance(expr, (sympy.cos, sympy.sin)) and expr.args[0] == angle:
        return False
    if expr.is_Symbol:
        return expr in unknown
    return any(_outside(a, angle, unknown) for a in expr.args)


def candidate(equation, shape, constants, memos) -> Candidate | None:
    """The sub-problem form of `equation` in the unknown `shape` names, or None (kept in `memos`)."""
    angle, variable = shape
    form = memos.remember(memos.forms, (equation.expr, angle, constants), _form, equation.expr, angle, variable,
                          constants, memos)
    return None if form is None else Candidate(equation, angle, form, variable)


def _form(expr, angle, variable, constants, memos):
    if not isinstance(angle, sympy.Symbol) or angle != variable:
        psi = sympy.Dummy("psi")
        replaced = expr.xreplace({sympy.cos(angle): sympy.cos(psi), sympy.sin(angle): sympy.sin(psi)})
        return sp.trig_linear(replaced, psi, constants)
    if any(variable in memos.free_symbols(f) for f in memos.trig_atoms(expr)):
        return sp.trig_linear(expr, variable, constants)
    form = sp.polynomial(expr, variable)
    return tuple(form) if form is not None and form[0] != 0 else None


def _last(angle, unknown, remaining):
    """The unknown of a sum of angles that the sum determines: the last one, with coefficient ±1."""
    for variable in reversed(remaining):
        if variable in unknown and angle.coeff(variable) in (1, -1):
            rest = algebra.expand(angle - angle.coeff(variable) * variable)
            if not rest.free_symbols & {variable}:
                return variable
    return None
