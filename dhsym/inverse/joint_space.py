"""Expressions of a derivation in the joint variables, and equality of trigonometric polynomials
in them: what proves that an existence condition is a factor of det J squared
(dhsym.inverse.singular) or that a degenerate case is a point on an axis (dhsym.inverse.on_axis).

Each side is written in the joints (the target's elements as the forward kinematics gives them)
and read into the ring of cos θk, sin θk modulo sin² + cos² = 1, where equal functions have equal
normal forms.

>>> import sympy
>>> t1, t2, a, b = sympy.symbols("theta_1 theta_2 a b", real=True)
>>> ring = TrigRing([t1, t2])
>>> side = (a * sympy.cos(t1) + b * sympy.cos(t1 + t2))**2 + (a * sympy.sin(t1) + b * sympy.sin(t1 + t2))**2
>>> ring.multiple(side, a**2 + b**2 + 2 * a * b * sympy.cos(t2)), ring.multiple(side, a**2 + b**2)
(True, False)
"""
from __future__ import annotations

import sympy
from sympy.polys.domains import QQ
from sympy.polys.rings import ring as poly_ring

from ..core.chain import Chain
from .fresh import reserved, target_symbols


def in_joints(chain: Chain, definitions, derivation) -> dict:
    """The target's elements as the forward kinematics gives them, and every name the derivation
    defines in the joint variables: where the branch holds, each is its value at the joints."""
    fk = chain.fk()
    names = dict(zip(target_symbols(reserved(chain)), [fk[r, c] for r in range(3) for c in range(4)]))
    for name, value in list(definitions) + list(derivation.assignments):
        if name not in chain.joint_variables:
            names[name] = derivation.angles.get(name, value.xreplace(names))
    return names


class TrigRing:
    """Trigonometric polynomials in the joints as polynomials in c_k, s_k modulo s_k² + c_k² − 1.
    The normal form keeps each s_k to the power 0 or 1 (s_k² is 1 − c_k²): two trigonometric
    polynomials are equal exactly when their normal forms are. Worked in a sparse polynomial ring
    over the rationals, not by SymPy's general reduction (Gröbner division), which took seconds."""

    def __init__(self, joints):
        self.names, self.pairs = {}, []
        for joint in joints:
            c, s = sympy.Dummy("c"), sympy.Dummy("s")
            self.names.update({sympy.cos(joint): c, sympy.sin(joint): s})
            self.pairs.append((s, c))
        self.index = {joint: k for k, joint in enumerate(joints)}

    def multiple(self, side, square) -> bool:
        """Whether side = k · square with k free of the joints (a nonzero constant expression)."""
        trig = [g for pair in self.pairs for g in pair]  # a joint outside cos and sin: a constant, as before
        generators = trig + sorted(side.free_symbols | square.free_symbols, key=str)
        polys, *_ = poly_ring(generators, QQ)
        try:  # each read as a numerator in normal form over a denominator free of the joints
            top, other = self._read(side, polys)[0], self._read(square, polys)[0]
        except _NotPolynomial:
            return False
        return bool(top) and bool(other) and _proportional(top, other, len(trig))

    def _read(self, expr, polys):
        """(numerator, denominator) of `expr` in `polys`, the numerator kept in normal form as it is
        multiplied out (so that px² + py² + pz² shrinks before it is squared), the denominator free
        of the joints; _NotPolynomial for anything else (a joint in a denominator, √2, a decimal)."""
        if expr.is_Add:
            top, below = polys.zero, polys.one
            for numerator, denominator in (self._read(term, polys) for term in expr.args):
                if denominator == below:
                    top += numerator
                else:
                    top, below = top * denominator + numerator * below, below * denominator
            return top, below
        if expr.is_Mul:
            top, below = polys.one, polys.one
            for numerator, denominator in (self._read(factor, polys) for factor in expr.args):
                top, below = self._normal(top * numerator), below * denominator
            return top, below
        if expr.is_Pow and expr.exp.is_Integer:
            numerator, denominator = self._read(expr.base, polys)
            if expr.exp < 0:
                if _holds_joint(numerator, len(self.pairs)):
                    raise _NotPolynomial
                numerator, denominator = denominator, numerator
            return self._normal(numerator ** abs(int(expr.exp))), denominator ** abs(int(expr.exp))
        if isinstance(expr, (sympy.cos, sympy.sin)):
            pair = self._angle(expr.args[0], polys)
            if pair is None:  # not a sum of joints: an offset such as π/2, as expand_trig writes it
                expanded = sympy.expand_trig(expr).xreplace(self.names)
                if expanded == expr:
                    raise _NotPolynomial
                return self._read(expanded, polys)
            return pair[0] if isinstance(expr, sympy.cos) else pair[1], polys.one
        if expr.is_Rational:
            return polys.ground_new(QQ(expr.p, expr.q)), polys.one
        if expr in polys.symbols:
            return polys.gens[polys.symbols.index(expr)], polys.one
        raise _NotPolynomial

    def _angle(self, angle, polys):
        """(cos, sin) of a sum of whole multiples of joints, in normal form; None for another angle."""
        cos, sin = polys.one, polys.zero
        for term in sympy.Add.make_args(angle):
            times, joint = term.as_coeff_Mul()
            if joint not in self.index or not times.is_Integer:
                return None
            c, s = polys.gens[2 * self.index[joint] + 1], polys.gens[2 * self.index[joint]]
            s = s if times > 0 else -s
            for _ in range(abs(int(times))):  # cos(a + b) = ca cb − sa sb, sin(a + b) = sa cb + ca sb
                cos, sin = self._normal(cos * c - sin * s), self._normal(sin * c + cos * s)
        return cos, sin

    def _normal(self, p):
        """p with every s_k² replaced by 1 − c_k² (one pass: the replacement holds no s_k). The
        terms are grouped by the powers of 1 − c_k² they take, each group multiplied once."""
        polys = p.ring
        s_indices = [2 * k for k in range(len(self.pairs))]
        groups: dict = {}
        for monomial, coefficient in p.items():
            exponents, halves = list(monomial), []
            for s_index in s_indices:
                half, exponents[s_index] = divmod(exponents[s_index], 2)
                halves.append(half)
            group = groups.setdefault(tuple(halves), {})
            group[tuple(exponents)] = coefficient  # distinct: the monomial is recovered from both
        total = polys.zero
        for halves, group in groups.items():
            term = polys.from_dict(group)
            for k, half in enumerate(halves):
                if half:
                    term *= (polys.one - polys.gens[2 * k + 1] ** 2) ** half
            total += term
        return total


class _NotPolynomial(Exception):
    """An expression that is not a polynomial in the joints' cos and sin over the constants."""


def _holds_joint(p, joints: int) -> bool:
    return any(any(monomial[:2 * joints]) for monomial in p.keys())


def _proportional(top, other, trig: int) -> bool:
    """Whether top = r · other with r free of the first `trig` generators (both nonzero): r is the
    ratio of their coefficients of one monomial in those generators."""
    chosen = next(iter(other.keys()))[:trig]

    def coefficient(p):  # the part of p at the chosen monomial, as a polynomial in the constants
        return p.ring.from_dict({(0,) * trig + m[trig:]: c for m, c in p.items() if m[:trig] == chosen})

    mine, theirs = coefficient(top), coefficient(other)
    return bool(mine) and top * theirs == other * mine


def in_one_ratio(sides, square, poses) -> bool:
    """Whether `sides` (one side's values at `poses`) are `square` at the same poses times one
    number: the cheap test in numbers before a proof in the ring."""
    values = [float(square.xreplace(pose)) for pose in poses]
    if any(abs(value) < 1e-12 for value in values):
        return False
    ratios = [side / value for side, value in zip(sides, values)]
    return max(ratios) - min(ratios) <= 1e-9 * max(1.0, max(map(abs, ratios)))
