"""Exact vectors and numbers for geometry: zero tests, unit vectors, and snapping of the
rounded floats that robot files contain to exact values (directions such as 0.7071 0 0.7071;
angles such as 1.5708 follow dhsym.core.grid).

>>> snap_length("-1.2e-17"), snap_length("0.425")
(0, 17/40)
>>> unit(vector(0, 3, 4)).T
Matrix([[0, 3/5, 4/5]])
"""
from __future__ import annotations

import functools

import sympy

from ..core import vectors
from ..core.grid import ANGLE_STEP, exact_number

DIRECTION_TOLERANCE = 1e-5  # per component of a unit vector
LENGTH_NOISE = 1e-9  # metres: a written -1.2e-17 is rounding noise, not a length


def vector(*components) -> sympy.Matrix:
    """A 3-vector of exact numbers or expressions."""
    return sympy.Matrix([sympy.sympify(c) for c in components])


def is_zero(value) -> bool:
    """Whether an exact number or expression is zero (square roots and symbols allowed)."""
    value = sympy.sympify(value)
    if value == 0:
        return True
    if value.is_number:
        return abs(sympy.N(value, 60)) < sympy.Float(10) ** -40
    return sympy.simplify(value) == 0


def is_zero_vector(v: sympy.Matrix) -> bool:
    return all(is_zero(c) for c in v)


def tidy(value):
    """A short exact form: radicals denested, rationals combined."""
    value = sympy.sympify(value)
    if value.is_Rational or value.is_Symbol:
        return value
    if value.is_number:
        if not value.has(sympy.Pow):
            return value
        shorter = sympy.sqrtdenest(sympy.radsimp(sympy.expand(value)))
        return shorter if sympy.count_ops(shorter) <= sympy.count_ops(value) else value
    return sympy.simplify(value)


def tidy_vector(v: sympy.Matrix) -> sympy.Matrix:
    return v.applyfunc(tidy)


def unit(v: sympy.Matrix) -> sympy.Matrix:
    """v scaled to length 1 (v must be non-zero); symbols count as positive lengths, as in a
    textbook figure.

    >>> l = sympy.Symbol("l", real=True)
    >>> unit(vector(0, -l, 0)).T, unit(vector(0, sympy.Rational(3, 10) - l, 0)).T
    (Matrix([[0, -1, 0]]), Matrix([[0, -1, 0]]))
    """
    positive = {s: sympy.Dummy(s.name, positive=True) for s in v.free_symbols}
    w = v.xreplace(positive)
    length = sympy.sqrt(sum(c ** 2 for c in w))
    # |l - 3/10| (a sign the symbols leave open) is taken as l - 3/10: one fixed sense for every
    # value of l, where the true unit vector would flip at l = 3/10 and no table could follow it.
    signed = (w / length).applyfunc(lambda c: c.replace(sympy.Abs, lambda inner: inner))
    return tidy_vector(signed).xreplace({d: s for s, d in positive.items()})


def cross(u: sympy.Matrix, v: sympy.Matrix) -> sympy.Matrix:
    """u × v (core.vectors), tidied: the exact column the frame rules compare and print."""
    return tidy_vector(sympy.Matrix(vectors.cross(u, v)))


def dot(u: sympy.Matrix, v: sympy.Matrix):
    """u · v (core.vectors), tidied."""
    return tidy(vectors.dot(u, v))


def rational_turn(angle: sympy.Rational, digits: int = 20) -> tuple[sympy.Rational, sympy.Rational]:
    """(cos, sin) of an angle off the π/12 grid as rationals that are exactly a unit pair, within
    10^-digits rad: from t = tan(angle/2) rounded, cos = (1 − t²)/(1 + t²), sin = 2t/(1 + t²).
    Exact cos(3/10) would make every later expression grow without bound.

    >>> c, s = rational_turn(sympy.Rational(3, 10))
    >>> c**2 + s**2 == 1, abs(float(c) - 0.955336489125606) < 1e-15
    (True, True)
    """
    t = sympy.Rational(str(sympy.N(sympy.tan(angle / 2), digits + 5).round(digits + 3)))
    return (1 - t ** 2) / (1 + t ** 2), 2 * t / (1 + t ** 2)


def snap_length(text: str) -> sympy.Rational:
    """A length as written, exactly; rounding noise below LENGTH_NOISE is zero."""
    written = exact_number(text)
    return sympy.Integer(0) if abs(written) < LENGTH_NOISE else written


def snap_direction(components: list[sympy.Rational]) -> tuple[sympy.Matrix, bool]:
    """A unit vector along the written components; each component is snapped to ±cos(kπ/12)
    when the result is a unit vector within DIRECTION_TOLERANCE. The flag says whether the
    direction moved. Raises ValueError for a zero-length vector.

    >>> snap_direction([0, 0, sympy.Rational(-1)])
    (Matrix([
    [ 0],
    [ 0],
    [-1]]), False)
    >>> snap_direction([sympy.Rational("0.7071"), 0, sympy.Rational("0.7071")])[0].T
    Matrix([[sqrt(2)/2, 0, sqrt(2)/2]])
    """
    written = vector(*components)
    length = float(sympy.sqrt(sum(c ** 2 for c in written)))
    if length < LENGTH_NOISE:
        raise ValueError("zero-length direction")
    floats = [float(c) / length for c in written]
    snapped = vector(*(_nearest_component(f) for f in floats))
    if all(abs(float(s) - f) <= DIRECTION_TOLERANCE for s, f in zip(snapped, floats)) \
            and is_zero(sum(c ** 2 for c in snapped) - 1):
        exact = unit(written)
        return snapped, not is_zero_vector(exact - snapped)
    return unit(written), False


@functools.cache
def _nice_components() -> tuple:
    """The cosines of the multiples of π/12: what a snapped unit-vector component may be
    (worked out on first use, not when every command imports this module)."""
    return tuple(sorted({sympy.nsimplify(sympy.cos(k * ANGLE_STEP)) for k in range(7)}, key=float))


def _nearest_component(value: float) -> sympy.Expr:
    best = min(_nice_components(), key=lambda c: abs(float(c) - abs(value)))
    return best if value >= 0 else -best
