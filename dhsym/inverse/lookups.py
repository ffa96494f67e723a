"""What one search (dhsym.inverse.scan) reads again and again, worked out once per search and
kept in a `Memos` object that the search makes for itself: an expression's free symbols and
cos/sin terms (SymPy walks the whole tree on every call), whether an equation says nothing at the
witness pose (found from its values before its form is worked out), each equation's structure,
size and sub-problem form, and what is known of a pair of forms. Nothing is kept between searches
or shared by two at once: two threads solving two arms never touch each other's memos.

>>> import sympy
>>> x, t = sympy.symbols("x theta", real=True)
>>> memos = Memos()
>>> sorted(memos.free_symbols(x * sympy.cos(t)), key=str), memos.trig_atoms(x * sympy.cos(t))
([theta, x], {cos(theta)})
>>> memos.silent(x - 1, (t, t), {x: 2.0, t: 0.3}), memos.silent(x * sympy.cos(t) - 1, (t, t), {x: 2.0, t: 0.3})
(True, False)
"""
from __future__ import annotations

import math

import sympy

from ..core.size import length
from .witness import number_at

SILENT_ZERO = 1e-11  # a and b before division by the robot's lengths: zero by far, rounding apart


class Memos:
    """The memos of one search; `remember(memo, key, work, *arguments)` is the one way each is filled."""

    def __init__(self):
        self.free: dict = {}  # expression -> its free symbols
        self.trig_terms: dict = {}  # expression -> its cos and sin terms
        self.silences: dict = {}  # (equation, shape) -> whether its coefficients vanish at the witness pose
        self.shapes: dict = {}  # (equation, unknowns it holds) -> the unknown or sum it determines
        self.sizes: dict = {}  # equation -> tree sizes of its chain side and of the whole
        self.forms: dict = {}  # (equation, angle, constants) -> its sub-problem form, or None
        self.lengths: dict = {}  # form -> its length
        self.signs: dict = {}  # pair of forms -> the sign of its determinant (None: either)
        self.works: dict = {}  # pair of forms -> whether it determines the angle at the witness pose

    @staticmethod
    def remember(memo: dict, key, work, *arguments):
        """memo[key], worked out by `work(*arguments)` the first time."""
        if key not in memo:
            memo[key] = work(*arguments)
        return memo[key]

    def free_symbols(self, expr) -> set:
        """expr.free_symbols, found once per search: SymPy walks the whole tree on every call."""
        return self.remember(self.free, expr, getattr, expr, "free_symbols")

    def trig_atoms(self, expr) -> set:
        """The cos and sin terms of expr, found once per search."""
        return self.remember(self.trig_terms, expr, expr.atoms, sympy.cos, sympy.sin)

    def form_length(self, form) -> int:
        """length(form), measured once per search: every round compares the same forms again."""
        return self.remember(self.lengths, form, length, form)

    def silent(self, expr, shape, witness) -> bool:
        """Whether an equation a cos ψ + b sin ψ = c in the angle ψ of `shape` has a = b = 0 at the
        witness pose, read off three of its values (ψ = 0, π/2, π: a = (f(0) − f(π))/2 and
        b = f(π/2) − (f(0) + f(π))/2), far below the threshold that the search applies to the
        worked-out form (its a and b are these divided by a product of the robot's lengths): such an
        equation gives no candidate either way, and its form, most of a round's work, is not needed.
        An equation that is not of that form has no form at all, so passing it over changes nothing."""
        if not witness:
            return False
        return self.remember(self.silences, (expr, shape), _coefficients_vanish, expr, shape, witness)


def _coefficients_vanish(expr, shape, witness) -> bool:
    angle, variable = shape
    coefficient = angle.coeff(variable) if angle != variable else 1
    rest = number_at(angle - coefficient * variable, witness) if angle != variable else 0.0
    if rest is None:
        return False
    values = []
    for psi in (0.0, math.pi / 2, math.pi):
        numbers = dict(witness)
        numbers[variable] = (psi - rest) / float(coefficient)
        value = number_at(expr, numbers)
        if value is None:
            return False
        values.append(value)
    a, b = (values[0] - values[2]) / 2, values[1] - (values[0] + values[2]) / 2
    return abs(a) < SILENT_ZERO and abs(b) < SILENT_ZERO
