"""What one search (dhsym.inverse.scan) reads again and again, worked out once per search: an
expression's free symbols and cos/sin terms (SymPy walks the whole tree on every call), and
whether an equation says nothing at the witness pose, found from its values before its form is
worked out.

>>> import sympy
>>> x, t = sympy.symbols("x theta", real=True)
>>> clear()
>>> sorted(free_symbols(x * sympy.cos(t)), key=str), trig_atoms(x * sympy.cos(t))
([theta, x], {cos(theta)})
>>> silent(x - 1, (t, t), {x: 2.0, t: 0.3}), silent(x * sympy.cos(t) - 1, (t, t), {x: 2.0, t: 0.3})
(True, False)
"""
from __future__ import annotations

import math

import sympy

from .witness import number_at

SILENT_ZERO = 1e-11  # a and b before division by the robot's lengths: zero by far, rounding apart

_free: dict = {}  # expression -> its free symbols
_trig_terms: dict = {}  # expression -> its cos and sin terms
_silences: dict = {}  # (equation, shape) -> whether its coefficients vanish at the witness pose


def clear() -> None:
    """Forget everything: kept within one search only, so memory stays bounded across many."""
    for memo in (_free, _trig_terms, _silences):
        memo.clear()


def silent(expr, shape, witness) -> bool:
    """Whether an equation a cos ψ + b sin ψ = c in the angle ψ of `shape` has a = b = 0 at the
    witness pose, read off three of its values (ψ = 0, π/2, π: a = (f(0) − f(π))/2 and
    b = f(π/2) − (f(0) + f(π))/2), far below the threshold that the search applies to the
    worked-out form (its a and b are these divided by a product of the robot's lengths): such an
    equation gives no candidate either way, and its form, most of a round's work, is not needed.
    An equation that is not of that form has no form at all, so passing it over changes nothing."""
    if not witness:
        return False
    key = (expr, shape)
    if key not in _silences:
        _silences[key] = _coefficients_vanish(expr, shape, witness)
    return _silences[key]


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


def free_symbols(expr) -> set:
    """expr.free_symbols, found once per search: SymPy walks the whole tree on every call."""
    if expr not in _free:
        _free[expr] = expr.free_symbols
    return _free[expr]


def trig_atoms(expr) -> set:
    """The cos and sin terms of expr, found once per search."""
    if expr not in _trig_terms:
        _trig_terms[expr] = expr.atoms(sympy.cos, sympy.sin)
    return _trig_terms[expr]
