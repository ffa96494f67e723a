"""Equality of expressions and matrices, proven by algebra and by numbers at random points.

Algebra: both sides are expanded into products of cos/sin of single angles and every
``sin(u)**2`` is replaced by ``1 - cos(u)**2``. In that form a trigonometric polynomial is
zero only if it is identically zero, so the test is exact, not a heuristic.

>>> import sympy
>>> t1, t2 = sympy.symbols("theta_1 theta_2", real=True)
>>> verdict = check(sympy.cos(t1 + t2), sympy.cos(t1)*sympy.cos(t2) - sympy.sin(t1)*sympy.sin(t2))
>>> verdict.algebraic, verdict.numeric
(True, True)
>>> bool(check(sympy.sin(t1)**2, 1 - sympy.cos(t2)**2))
False
"""
from __future__ import annotations

import random
from dataclasses import dataclass

import sympy


@dataclass(frozen=True)
class Verdict:
    """Whether two things are equal, by algebra and by numbers."""

    algebraic: bool
    numeric: bool
    max_error: float

    def __bool__(self) -> bool:
        return self.algebraic and self.numeric

    def __str__(self) -> str:
        """What a notebook prints: 'equal: by algebra, and numerically (max error 4e-16)'."""
        if self:
            return f"equal: by algebra, and numerically (max error {self.max_error:.1g})"
        return (f"NOT equal: algebra says {'equal' if self.algebraic else 'different'}, "
                f"numbers differ by up to {self.max_error:.3g}")


def trig_canonical(expr: sympy.Expr) -> sympy.Expr:
    """A form in which a trigonometric polynomial is zero exactly when it is identically zero."""
    expr = sympy.expand(sympy.expand_trig(sympy.sympify(expr)))
    while True:
        squares = {p for p in expr.atoms(sympy.Pow)
                   if isinstance(p.base, sympy.sin) and p.exp.is_Integer and p.exp >= 2}
        if not squares:
            return expr
        expr = sympy.expand(expr.xreplace({p: _without_sin_squared(p) for p in squares}))


def _without_sin_squared(power: sympy.Pow) -> sympy.Expr:
    """sin(u)**k as (1 − cos(u)²)·sin(u)**(k−2)."""
    angle = power.base.args[0]
    return (1 - sympy.cos(angle) ** 2) * sympy.sin(angle) ** (power.exp - 2)


def algebraically_equal(a, b) -> bool:
    difference = trig_canonical(sympy.sympify(a) - sympy.sympify(b))
    if difference == 0:
        return True
    # Trig of plain numbers (cos 2 against cos²1 − sin²1) has no canonical form; such
    # coefficients are compared to 50 digits instead.
    generators = sorted({x for x in difference.atoms(sympy.Symbol, sympy.cos, sympy.sin) if not x.is_number},
                        key=sympy.default_sort_key)
    coefficients = sympy.Poly(difference, *generators).coeffs() if generators else [difference]
    return all(c.is_number and abs(sympy.N(c, 60)) < sympy.Float(10) ** -45 for c in coefficients)


def numeric_error(a, b, trials: int = 12, seed: int = 0) -> float:
    """The largest |a − b| at random values of every symbol (angles and lengths alike);
    a and b may be expressions or matrices of the same shape."""
    differences = [x - y for x, y in zip(_elements(a), _elements(b))]
    symbols = sorted(set().union(*(d.free_symbols for d in differences)), key=lambda s: s.name)
    rng = random.Random(seed)
    function = sympy.lambdify(symbols, differences, modules="math")
    worst = 0.0
    for _ in range(trials if symbols else 1):
        values = function(*[rng.uniform(-3.0, 3.0) for _ in symbols])
        worst = max([worst] + [abs(complex(v)) for v in values])
    return worst


def _elements(x) -> list:
    if isinstance(x, sympy.MatrixBase):
        return list(x)
    return [sympy.sympify(x)]


def check(a, b, tolerance: float = 1e-9, trials: int = 12) -> Verdict:
    """Compare two expressions or two matrices of the same shape, element by element."""
    if isinstance(a, sympy.MatrixBase) or isinstance(b, sympy.MatrixBase):
        a, b = sympy.Matrix(a), sympy.Matrix(b)
        if a.shape != b.shape:
            return Verdict(False, False, float("inf"))
        verdicts = [check(x, y, tolerance, trials) for x, y in zip(a, b)]
        return Verdict(all(v.algebraic for v in verdicts), all(v.numeric for v in verdicts),
                       max(v.max_error for v in verdicts))
    error = numeric_error(a, b, trials)
    return Verdict(algebraically_equal(a, b), error <= tolerance, error)
