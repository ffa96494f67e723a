"""One generic pose in numbers: the joint values, the robot's constants and the target they give.
The search uses it to pass over equations that say nothing (0 = 0) once earlier results hold.

>>> import dhsym, sympy
>>> numbers = witness(dhsym.load("planar2r").chain)
>>> abs(numbers[sympy.Symbol("r33", real=True)] - 1) < 1e-12
True
"""
from __future__ import annotations

import math
import random

import sympy

from ..core.chain import Chain, plain
from ..core.sampling import random_pose
from ..velocity.geometry import poses
from .fresh import reserved, target_symbols

SEED = 20240516


def witness(chain: Chain, sample=None, seed: int = SEED) -> dict:
    """Symbol -> Float for every joint variable, constant and target element at a random pose
    (dhsym.core.sampling); constants from `sample` (the robot file's) where it has them."""
    chain = plain(chain)
    values = random_pose(chain, random.Random(seed), sample)
    rotation, origin = poses(chain, values)[chain.last_frame]
    elements = [x for r in range(3) for x in (*rotation[r], origin[r])]
    values.update(zip(target_symbols(reserved(chain)), elements))
    return {symbol: sympy.Float(value, 17) for symbol, value in values.items()}


def number_at(expr, numbers: dict) -> float | None:
    """The value of `expr` at the pose `numbers`, or None when it cannot be had.

    >>> number_at(sympy.sqrt(sympy.Symbol("x")), {sympy.Symbol("x"): -1.0}) is None
    True
    """
    if not numbers:
        return None
    expr = sympy.sympify(expr)
    try:
        return value_at(expr, numbers)
    except NotANumber:
        pass
    try:  # what the fast walk does not know (a function it has no float for), SymPy evaluates
        return float(expr.xreplace(numbers).evalf(15))
    except (TypeError, ValueError):
        return None


class NotANumber(Exception):
    """The expression has no real value at the pose (a name without one, a complex value)."""


def value_at(expr, numbers: dict) -> float:
    """The value of `expr` with `numbers` put in, in floating point (a hundred times faster than
    SymPy's evalf; the search only asks whether a value is about zero, at a generic pose).
    Raises NotANumber where there is none, as SymPy's float() would.

    >>> x = sympy.Symbol("x", real=True)
    >>> value_at(sympy.atan2(sympy.sqrt(1 - x**2), x), {x: 0.5}) == math.atan2(math.sqrt(0.75), 0.5)
    True
    """
    try:
        value = _walk(expr, numbers)
    except (KeyError, ZeroDivisionError, OverflowError, ValueError) as error:
        raise NotANumber from error
    if isinstance(value, complex):
        raise NotANumber
    return value


_FUNCTIONS = {sympy.cos: math.cos, sympy.sin: math.sin, sympy.atan2: math.atan2, sympy.acos: math.acos,
              sympy.asin: math.asin, sympy.atan: math.atan, sympy.tan: math.tan}


def _walk(expr, numbers):
    if expr.is_Symbol:
        return float(numbers[expr])
    if expr.is_Number:
        if not expr.is_finite:
            raise ValueError(expr)
        return float(expr)
    if expr is sympy.pi:
        return math.pi
    if expr.is_Add:
        return math.fsum(_walk(a, numbers) for a in expr.args)
    if expr.is_Mul:
        result = 1.0
        for a in expr.args:
            result *= _walk(a, numbers)
        return result
    if expr.is_Pow:
        base, exponent = _walk(expr.base, numbers), _walk(expr.exp, numbers)
        if base < 0 and not float(exponent).is_integer():
            raise ValueError(expr)
        return base ** exponent
    function = _FUNCTIONS.get(expr.func)
    if function is None:
        raise KeyError(expr.func)
    return function(*(_walk(a, numbers) for a in expr.args))
