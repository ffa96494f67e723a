"""Exact expansion by polynomial arithmetic: the equations of inverse kinematics are polynomials
in the cos/sin of the joint angles, the robot's constants and the target's names, with rational
coefficients. Multiplied out in SymPy's sparse polynomial ring they expand many times faster
than `sympy.expand` walks the expression trees, and give the same expression (expansion is
canonical). Where an expression is not such a polynomial (√2 from a twist of π/4, a quotient),
the caller gets None and uses `sympy.expand`. Also here: sin² + cos² = 1 applied the way a
book does, without trigsimp's double angles.

>>> import sympy
>>> x, t = sympy.symbols("x theta", real=True)
>>> first, second = x * sympy.cos(t) + 1, sympy.sin(t) - x
>>> ring = Ring([first, second])
>>> ring.expr(ring.poly(first) * ring.poly(second)) == sympy.expand(first * second)
True
>>> Ring([sympy.sqrt(2) * x]).usable, Ring([0.5 * x]).usable
(False, False)
"""
from __future__ import annotations

import math
from itertools import product

import sympy
from sympy.polys.domains import QQ
from sympy.polys.polyerrors import CoercionFailed
from sympy.polys.rings import PolyRing

from ..core.size import length

PYTHAGORAS_ANGLES = 3  # angles whose squares are rewritten by sin² + cos² = 1: at most 3³ expansions


class Ring:
    """The polynomial ring over the rationals whose generators are the symbols and cos/sin
    terms of `exprs`; `usable` is False when one of them is not a polynomial in those."""

    def __init__(self, exprs):
        atoms = set()
        for expr in exprs:
            atoms |= sympy.sympify(expr).atoms(sympy.Symbol, sympy.cos, sympy.sin)
        self.ring = PolyRing(sorted(atoms, key=sympy.default_sort_key) or [sympy.Dummy()], QQ)
        self.usable = True
        self._polys: dict = {}
        for expr in exprs:
            if self.poly(expr) is None:
                self.usable = False
                break

    def poly(self, expr):
        """`expr` as an element of the ring (kept), or None when it is not a polynomial there."""
        expr = sympy.sympify(expr)
        if expr not in self._polys:
            if expr.has(sympy.Float):  # a decimal stays as SymPy's arithmetic writes it
                self._polys[expr] = None
                return None
            try:
                self._polys[expr] = self.ring.from_expr(expr)
            except (ValueError, CoercionFailed):
                self._polys[expr] = None
        return self._polys[expr]

    def expr(self, poly) -> sympy.Expr:
        """The expanded expression of a ring element."""
        return poly.as_expr()

    def expand(self, expr) -> sympy.Expr:
        """`sympy.expand(expr)`, by the ring where `expr` is one of its polynomials."""
        poly = self.poly(expr) if self.usable else None
        return sympy.expand(expr) if poly is None else poly.as_expr()


def expand(expr) -> sympy.Expr:
    """`sympy.expand(expr)`, multiplied out in the ring of its own symbols and cos/sin terms when
    it is a polynomial there (the same expression, faster), else by SymPy.

    >>> x, y = sympy.symbols("x y")
    >>> expand((x + y) * (x - sympy.cos(y)))
    x**2 + x*y - x*cos(y) - y*cos(y)
    """
    expr = sympy.sympify(expr)
    if expr.is_Atom or expr.has(sympy.Float):
        return sympy.expand(expr)
    if expr.is_Mul:  # a sum over a product of symbols (K/(2 a2)): each term of the sum divided
        over = [f for f in expr.args if f.is_Pow and f.exp.is_Integer and f.exp < 0 and f.base.is_Symbol]
        rest = _polynomial(sympy.Mul(*[f for f in expr.args if f not in over])) if over else None
        if rest is not None:
            divisor = sympy.Mul(*over)
            return sympy.Add(*[t * divisor for t in sympy.Add.make_args(rest.as_expr())])
    poly = _polynomial(expr)
    return sympy.expand(expr) if poly is None else poly.as_expr()


def factor_terms(expr) -> sympy.Expr:
    """`sympy.factor_terms(expr)`, answered at once for a sum that it leaves as it is (see `plain_sum`).

    >>> x, y = sympy.symbols("x y")
    >>> factor_terms(2*x*y + 4*x), factor_terms(x*y - 2*sympy.cos(y))
    (2*x*(y + 2), x*y - 2*cos(y))
    """
    return expr if plain_sum(expr) else sympy.factor_terms(expr)


def over_one_denominator(expr) -> sympy.Expr:
    """`expr` multiplied out, then over one denominator with common factors out; a plain sum of
    monomials (see `plain_sum`) is that already, and is given back at once.

    >>> x, a = sympy.symbols("x a", real=True)
    >>> over_one_denominator((x - a**2) / (2 * a)), over_one_denominator(-(x - 2 * a))
    ((-a**2 + x)/(2*a), 2*a - x)
    """
    expanded = expand(expr)
    return expanded if plain_sum(expanded) else sympy.factor_terms(sympy.together(expanded))


def plain_sum(expr) -> bool:
    """Whether `expr` is a sum of monomials (integer coefficients, whole powers of symbols and
    cos/sin of symbols) with nothing for factor_terms or together to take out: the coefficients'
    gcd is 1, not every sign is minus, and no symbol or cos/sin is in every term. Such a sum is
    what both give back, and telling it costs a walk over the terms, not their gcd.

    >>> x, y = sympy.symbols("x y")
    >>> plain_sum(x*y + 2*sympy.sin(x)), plain_sum(x*y + x), plain_sum(-x - y), plain_sum(2*x + 4*y)
    (True, False, False, False)
    """
    if not expr.is_Add:
        return False
    divisor, positive, common = 0, False, None
    for term in expr.args:
        coefficient, rest = term.as_coeff_Mul()
        if not coefficient.is_Integer:
            return False
        divisor = math.gcd(divisor, abs(int(coefficient)))
        positive = positive or coefficient > 0
        bases = set()
        for factor in sympy.Mul.make_args(rest) if rest != 1 else ():
            base, exponent = (factor.base, factor.exp) if factor.is_Pow else (factor, 1)
            if not (exponent == 1 or (getattr(exponent, "is_Integer", False) and exponent > 0)):
                return False
            if not (base.is_Symbol or (isinstance(base, (sympy.cos, sympy.sin)) and base.args[0].is_Symbol)):
                return False
            bases.add(base)
        common = bases if common is None else common & bases
    return divisor == 1 and positive and not common


def _polynomial(expr):
    """`expr` in the ring over the rationals of its symbols and cos/sin terms, or None."""
    atoms = expr.atoms(sympy.Symbol, sympy.cos, sympy.sin)
    if not atoms or expr.has(sympy.Float):
        return None
    try:
        return PolyRing(sorted(atoms, key=sympy.default_sort_key), QQ).from_expr(expr)
    except (ValueError, CoercionFailed):
        return None


def has_square_pair(expr) -> bool:
    """Whether sin(x)**k and cos(x)**k of one angle both occur: only then can cos² + sin² = 1
    shorten (a cheap test that spares the search most determinants)."""
    powers = {(type(p.base), p.base.args[0], p.exp) for p in expr.atoms(sympy.Pow)
              if isinstance(p.base, (sympy.sin, sympy.cos))}
    return any((sympy.cos, x, k) in powers for f, x, k in powers if f is sympy.sin)


def pythagoras(expr: sympy.Expr) -> sympy.Expr:
    """The shortest of the forms that sin²x = 1 − cos²x or cos²x = 1 − sin²x give, for each angle
    whose square occurs (the identity a book uses; no double angles, where SymPy's trigsimp
    writes 2 s1 c1 as sin 2θ1, at a hundred times the cost); `expr` itself when none is shorter.

    >>> t, a = sympy.symbols("theta a", real=True)
    >>> pythagoras(1 + 2*a*sympy.cos(t) + a**2*sympy.sin(t)**2 + a**2*sympy.cos(t)**2)
    a**2 + 2*a*cos(theta) + 1
    """
    angles = sorted({p.base.args[0] for p in expr.atoms(sympy.Pow)
                     if isinstance(p.base, (sympy.sin, sympy.cos)) and p.exp == 2}, key=sympy.default_sort_key)
    best, shortest = expr, length(expr)
    for choice in product((None, sympy.sin, sympy.cos), repeat=min(len(angles), PYTHAGORAS_ANGLES)):
        rules = {f(x) ** 2: 1 - (sympy.cos(x) if f is sympy.sin else sympy.sin(x)) ** 2
                 for f, x in zip(choice, angles) if f is not None}
        if rules:
            reduced = expand(expr.xreplace(rules))
            if length(reduced) < shortest:
                best, shortest = reduced, length(reduced)
    return best


def shorter_with(expr, known: dict):
    """`expr` with the `known` values (polynomials) written in where that makes it shorter, as the
    SCARA's slide d3 = −(pz + d4) cancels from the law of cosines, leaving Spong's D; a name
    inside a function (the angle of c23) is kept.

    >>> px, pz, d3, d4 = sympy.symbols("px pz d3 d4", real=True)
    >>> shorter_with(px**2 + pz**2 - d3**2 - 2*d3*d4 - d4**2, {d3: -(pz + d4)})
    px**2
    """
    inside = set().union(*(f.free_symbols for f in expr.atoms(sympy.Function)))  # an angle stays an angle
    used = {name: value for name, value in known.items() if name in expr.free_symbols - inside}
    if not used:
        return expr
    written = over_one_denominator(expr.xreplace(used))
    return written if length(written) < length(expr) else expr

