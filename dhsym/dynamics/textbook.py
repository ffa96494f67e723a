"""Dynamics results written out element by element, the way a textbook prints them.

A name of the program is written out (`Tape.expanded`) and multiplied out, sin² + cos² = 1 is
applied where it shortens the sum, and then the shortest of a few equal forms is kept: the sum
as it is, grouped by its products of cos/sin with the common factors of each group pulled out,
the same after the sum formulas (c1 c2 − s1 s2 = c12), and grouped by the links' masses first.
Spong's d11 comes out as he prints it, m1 lc1² + m2(l1² + lc2² + 2 l1 lc2 c2) + I1 + I2.

>>> q1, q2, l1, lc2, m2, g = sympy.symbols("q_1 q_2 l_1 lc_2 m_2 g", real=True)
>>> c, s = sympy.cos, sympy.sin
>>> compact(g*l1*m2*s(q2)**2*c(q1) + g*l1*m2*c(q1)*c(q2)**2 + g*lc2*m2*(c(q1)*c(q2) - s(q1)*s(q2)), [m2])
g*m_2*(l_1*cos(q_1) + lc_2*cos(q_1 + q_2))
"""
from __future__ import annotations

import itertools
import math

import sympy

from ..core.size import tree_size
from .tape import operation_count

MAX_TERMS = 20_000  # of all the printed elements, multiplied out; past this they are not written out


def compact(expr: sympy.Expr, masses=(), memo: dict | None = None, multiplied: bool = False) -> sympy.Expr:
    """The shortest textbook form of `expr` (see the module's docstring); `masses` are the
    symbols to group by first; `memo` keeps the sum formulas of the cos/sin sums met before. The
    form given is a candidate too, unless it is `multiplied` out already (with sin² + cos² = 1
    applied: dhsym.dynamics.polynomial)."""
    given, expr = expr, expr if multiplied else pythagoras(sympy.expand(expr))
    if expr.is_Atom or not expr.is_Add:
        return expr
    candidates = [expr, grouped(expr)] + ([given] if not multiplied and given.has(sympy.sin, sympy.cos) else [])
    summed = sum_formulas(expr) if expr.has(sympy.sin, sympy.cos) else expr
    if summed != expr:
        candidates.append(grouped(summed))
    symbols = [m for m in masses if summed.has(m)]
    if symbols:
        by_mass = sympy.collect(summed, symbols, evaluate=False)
        candidates.append(sympy.Add(*[key * grouped(value) for key, value in by_mass.items()]))
    counted: dict = {}  # the candidates share their products of cos/sin: counted once
    return min(candidates, key=lambda candidate: _cost(candidate, counted))


def _cost(expr: sympy.Expr, memo: dict) -> tuple:
    """Operations as code counts them, then the size of the tree: a fast stand-in for count_ops."""
    return operation_count(expr, memo), tree_size(expr)


def sum_formulas(expr: sympy.Expr, memo: dict | None = None) -> sympy.Expr:
    """c1 c2 − s1 s2 = c12 and the other three, wherever two terms differ only in such a pair of
    factors and have equal or opposite coefficients, until none is left.

    >>> a, b, k = sympy.symbols("a b k", real=True)
    >>> c, s = sympy.cos, sympy.sin
    >>> sum_formulas(k*c(a)*c(b) - k*s(a)*s(b) + 2*s(a)*c(b) - 2*c(a)*s(b))
    k*cos(a + b) + 2*sin(a - b)

    A partner's factors are counted, not just collected: s1 c1 c2 pairs with s1 s1 s2 (s1² s2),
    not with s1 s2.

    >>> sum_formulas(s(a)*c(a)*c(b) - s(a)**2*s(b) + s(a)*s(b))
    sin(a)*sin(b) + sin(a)*cos(a + b)
    """
    terms: dict = {}  # the multiset of a term's factors -> its coefficient
    for term in sympy.Add.make_args(expr):
        number, rest = term.as_coeff_Mul()
        key = _multiset(sympy.Mul.make_args(rest))
        terms[key] = terms.get(key, 0) + number
    changed = True
    while changed:
        changed = False
        for key in list(terms):
            if key in terms and _combine(terms, key):
                changed = True
    return sympy.Add(*[sympy.Mul(number, *[f ** k for f, k in key]) for key, number in terms.items()])


def _multiset(factors) -> frozenset:
    """A product's factors as a multiset {(base, power)}: cos(x)**2 is (cos(x), 2)."""
    counted: dict = {}
    for factor in factors:
        base, power = (factor.base, factor.exp) if factor.is_Pow and factor.exp.is_Integer else (factor, 1)
        counted[base] = counted.get(base, 0) + power
    return frozenset(counted.items())


def _joined(multiset: frozenset, factors: list) -> frozenset:
    """The multiset of a product's factors with `factors` multiplied in (each to the power 1),
    counted without building the product."""
    counted = dict(multiset)
    for factor in factors:
        if not factor.is_Number:  # a sum formula that came out a number (cos(π/2 + x) − …) leaves no factor
            counted[factor] = counted.get(factor, 0) + 1
    return frozenset(counted.items())


def _combine(terms: dict, key: frozenset) -> bool:
    """Merge the term `key` with a partner by a sum formula, if it has one."""
    number = terms[key]
    single = sorted((base for base, power in key if power == 1 and isinstance(base, (sympy.cos, sympy.sin))),
                    key=sympy.default_sort_key)  # the same pair first, whatever the hash seed
    swap = {sympy.cos: sympy.sin, sympy.sin: sympy.cos}
    for first, second in itertools.combinations(single, 2):
        a, b = first.args[0], second.args[0]
        if a == b:
            continue
        rest = key - {(first, 1), (second, 1)}
        partner = _joined(rest, [swap[type(first)](a), swap[type(second)](b)])
        other = terms.get(partner)
        if other is None or abs(other) != abs(number):
            continue
        same = other == number
        if isinstance(first, sympy.cos) and isinstance(second, sympy.cos):
            merged = sympy.cos(a - b) if same else sympy.cos(a + b)
        elif isinstance(first, sympy.sin) and isinstance(second, sympy.sin):
            merged = sympy.cos(a - b) if same else -sympy.cos(a + b)
        elif isinstance(first, sympy.sin):  # sin a cos b ± cos a sin b
            merged = sympy.sin(a + b) if same else sympy.sin(a - b)
        else:  # cos a sin b ± sin a cos b
            merged = sympy.sin(a + b) if same else -sympy.sin(a - b)
        if not all(_signed_sum(f.args[0]) for f in merged.atoms(sympy.cos, sympy.sin)):
            continue  # c2 s23 + s2 c23 stays: sin(2θ2 + θ3) has no c/s abbreviation
        del terms[key], terms[partner]
        coefficient, factor = (number * merged).as_coeff_Mul()
        joined = _joined(rest, [factor])
        terms[joined] = terms.get(joined, 0) + coefficient
        if terms[joined] == 0:
            del terms[joined]
        return True
    return False


def _signed_sum(angle: sympy.Expr) -> bool:
    """Whether `angle` is a sum of angles each taken once, ±θ1 ± θ2 … (and a constant): what
    c/s notation writes as c12, s2-3; 2θ2 + θ3 it cannot."""
    return all(term.as_coeff_Mul()[0] in (1, -1) for term in sympy.Add.make_args(angle) if term.free_symbols)


def _split(term: sympy.Expr) -> tuple:
    """(the cos/sin factors, the other factors) of a product."""
    trig, rest = [], []
    for factor in sympy.Mul.make_args(term):
        base = factor.base if factor.is_Pow else factor
        (trig if isinstance(base, (sympy.sin, sympy.cos)) else rest).append(factor)
    return sympy.Mul(*trig), sympy.Mul(*rest)


def grouped(expr: sympy.Expr) -> sympy.Expr:
    """The terms grouped by their product of cos/sin factors, the common factors of each group
    pulled out: g l1 m2 c1 + g lc1 m1 c1 → g c1 (l1 m2 + lc1 m1).

    >>> x, a, b, g = sympy.symbols("x a b g", real=True)
    >>> grouped(g*a*sympy.cos(x) + g*b*sympy.cos(x) + 2*a*g)
    g*(2*a + (a + b)*cos(x))
    """
    groups: dict = {}
    for term in sympy.Add.make_args(expr):
        trig, rest = _split(term)
        groups.setdefault(trig, []).append(rest)
    return pulled_out([key * pulled_out(rest) for key, rest in groups.items()])


def pulled_out(terms: list) -> sympy.Expr:
    """The sum of `terms` with what they all share written once in front: a minus sign, a whole
    number, and symbols or cos/sin to the lowest power they have in every term.

    >>> a, b, c = sympy.symbols("a b c", real=True)
    >>> pulled_out([-2*a**2*b, -4*a*b*c])
    -2*a*b*(a + 2*c)
    """
    if len(terms) < 2:
        return sympy.Add(*terms)
    powers = [term.as_powers_dict() for term in terms]
    shared = {}
    for base in powers[0]:
        if not base.is_Number and all(base in p for p in powers[1:]):
            lowest = min(p[base] for p in powers)
            if lowest.is_Integer and lowest > 0:
                shared[base] = lowest
    coefficients = [term.as_coeff_Mul()[0] for term in terms]
    whole = all(c.is_Integer for c in coefficients)
    number = sympy.Integer(math.gcd(*[int(c) for c in coefficients])) if whole else sympy.Integer(1)
    number = -number if all(c.is_negative for c in coefficients) else number
    factor = number * sympy.Mul(*[base**power for base, power in shared.items()])
    if factor == 1:
        return sympy.Add(*terms)
    return factor * sympy.Add(*[term / factor for term in terms])


def pythagoras(expr: sympy.Expr) -> sympy.Expr:
    """sin²x + cos²x = 1, for each angle x in turn: the multiplied-out sum with sin² written as
    1 − cos², or cos² as 1 − sin², whichever has fewer terms (the sum itself when neither helps).

    >>> x, a, b = sympy.symbols("x a b", real=True)
    >>> pythagoras(a*sympy.sin(x)**2 + a*sympy.cos(x)**2 + b*sympy.cos(x)**2)
    a + b*cos(x)**2
    """
    angles = {f.args[0] for f in expr.atoms(sympy.sin, sympy.cos)}
    for angle in sorted(angles, key=sympy.default_sort_key):
        sin, cos = sympy.sin(angle), sympy.cos(angle)
        if not (expr.has(sin) and expr.has(cos)):
            continue
        best = expr
        for square, other in ((sin, cos), (cos, sin)):
            powers = {p: square ** (p.exp % 2) * (1 - other**2) ** (p.exp // 2)
                      for p in expr.atoms(sympy.Pow) if p.base == square and p.exp.is_Integer and p.exp >= 2}
            if powers:
                candidate = sympy.expand(expr.xreplace(powers))
                if len(sympy.Add.make_args(candidate)) < len(sympy.Add.make_args(best)):
                    best = candidate
        expr = best
    return expr


def expanded_terms(tape, values) -> int:
    """How many terms `values` (names of `tape`) would have multiplied out, counted on the
    names without writing anything out: a sum adds, a product multiplies, a power (a + b)ᵏ of a
    sum of t terms has C(t + k − 1, k). An upper bound: cancellations are not foreseen."""
    memo: dict = {}

    def terms(expr) -> int:
        if expr in tape.definitions:
            if expr not in memo:
                memo[expr] = terms(tape.definitions[expr])
            return memo[expr]
        if expr.is_Atom:
            return 1
        if expr.is_Add:
            return sum(terms(arg) for arg in expr.args)
        if expr.is_Mul:
            return math.prod(terms(arg) for arg in expr.args)
        if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0:
            count = terms(expr.base)
            return math.comb(count + int(expr.exp) - 1, int(expr.exp))
        return 1

    return sum(terms(sympy.sympify(value)) for value in values)
