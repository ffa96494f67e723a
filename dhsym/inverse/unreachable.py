"""Degenerate cases that no reachable target meets: a case (every expression of its condition 0)
that makes an existence condition's left side negative names a pose where no branch exists, and
is not printed.

The PUMA's θ1 is not determined where px = py = 0, but its branches exist only where
px² + py² − d3² ≥ 0: at px = py = 0 that side is −d3², below zero for the shoulder offset d3 ≠ 0.
The proof is the substitution itself: each expression of the case is solved for one of the
target's names (or a definition's), the condition's side evaluated there must hold only constants,
and be negative for every real value of them that is not 0. A constant the derivation divides by
(a robot's length, never 0 unless its file says so) counts as not 0; where the side could be 0
(d3 − d2 squared) the case stays.

>>> import sympy
>>> from dhsym.inverse.sentences import Exists, Undetermined
>>> px, py, d3 = sympy.symbols("px py d_3", real=True)
>>> case = Undetermined((py, px), sympy.Symbol("theta_1", real=True))
>>> contradicts(case, [Exists(px**2 + py**2 - d3**2)], {d3})
True
>>> contradicts(case, [Exists(px**2 + py**2 - d3**2)], set())   # d3 could be 0: the case stays
False
"""
from __future__ import annotations

import sympy

from .sentences import Exists, Undetermined


def reachable_cases(degenerate, conditions, nonzero) -> tuple[list, list]:
    """(the degenerate cases some reachable target meets, their indices in `degenerate`);
    `nonzero`: the constants that are never 0."""
    kept = [k for k, case in enumerate(degenerate) if not contradicts(case, conditions, nonzero)]
    return [degenerate[k] for k in kept], kept


def contradicts(case, conditions, nonzero) -> bool:
    """Whether `case` (an Undetermined) makes the left side of one of `conditions` (Exists, ≥ 0)
    negative; `nonzero`: the constants that are never 0."""
    if not isinstance(case, Undetermined):
        return False
    solved = _solved(case.condition, nonzero)
    if solved is None:
        return False
    for said in conditions:
        if isinstance(said, Exists) and said.relation == ">=":
            side = sympy.expand(said.expression.xreplace(solved))
            if side.free_symbols <= set(nonzero) and _negative(side, nonzero):
                return True
    return False


def _solved(condition, nonzero) -> dict | None:
    """Each expression of `condition` solved for a name it holds to the first power with a number as
    coefficient (py = d6 r23 from d6 r23 − py = 0), in turn; None where one is not."""
    solved: dict = {}
    for expr in condition:
        expr = sympy.expand(expr.xreplace(solved))
        names = sorted(expr.free_symbols - set(nonzero), key=sympy.default_sort_key)
        for name in names:
            poly = expr.as_poly(name)
            if poly is not None and poly.degree() == 1 and poly.LC().is_number and poly.LC() != 0:
                solved = {k: v.xreplace({name: -poly.TC() / poly.LC()}) for k, v in solved.items()}
                solved[name] = -poly.TC() / poly.LC()
                break
        else:
            return None
    return solved


def _negative(side, nonzero) -> bool:
    """Whether `side`, even in each of its constants (all in `nonzero`), is below 0 wherever none is 0."""
    positive = {}
    for name in side.free_symbols:
        if sympy.expand(side - side.xreplace({name: -name})) != 0:
            return False  # odd in a constant: its sign decides
        positive[name] = sympy.Symbol(name.name, positive=True)
    return bool(side.xreplace(positive).is_negative)
