"""Which degenerate cases of a derivation are singularities that `dhsym jacobian` prints: a
factor of det J, matched up to sign.

Only a factor in the chain's own symbols (joint variables and constants) can be one of det J's;
one that holds the target (px, x_c) never is, and needs no determinant. For a wrist-partitioned
arm det J = det A · det C, and det A holds the first three joints only: a factor in the wrist's
variables alone is one of det C's, the wrist axes' 3×3 determinant, worked out in a few
milliseconds where det A takes most of the time (the same factors `dhsym jacobian` prints).

>>> import dhsym
>>> puma = dhsym.load("puma560")
>>> wrist_factors(puma.chain, puma.numbers)
[sin(theta_5)]
"""
from __future__ import annotations

import itertools
import random
from dataclasses import replace
from types import SimpleNamespace

import sympy
from sympy.polys.domains import QQ
from sympy.polys.rings import ring as poly_ring

from ..core.chain import Chain
from ..velocity.determinant import TooManyTerms, as_written, determinant, factored, joint_factors, partitioned_factors
from ..velocity.geometry import TOLERANCE, axis_line, dot, poses, sample_values, wrist_centre
from ..velocity.jacobian import angular_part, axis_frame
from ..velocity.singularities import singularities
from .fresh import reserved, target_symbols
from .sentences import Exists, LinedUp, Singular
from .subproblems import angle_symbol, factor_bases
from .unreachable import reachable_cases


def explain_cases(chain: Chain, derivation, definitions, sample, numbers, nonzero, tie: bool) -> None:
    """What the derivation's existence conditions and degenerate cases mean for the arm: the axes a
    sin θk = 0 lines up, the factor of det J each is (where `tie`: a six-joint arm with a wrist),
    and only the cases some reachable target meets (dhsym.inverse.unreachable). `definitions`:
    the shared ones, before the derivation's assignments; `nonzero`: the constants never 0."""
    say_lined_up(chain, derivation)
    if tie:
        tie_to_jacobian(chain, derivation, definitions, sample, numbers)
    derivation.degenerate, kept = reachable_cases(derivation.degenerate, derivation.conditions, nonzero)
    derivation.vanishing = [(expr, kept.index(k)) for expr, k in derivation.vanishing if k in kept]


def tie_to_jacobian(chain: Chain, derivation, definitions, sample, numbers) -> None:
    """Add to each degenerate case whose expression has a factor of det J, and to each existence
    condition whose boundary (the two roots meet) is where a factor vanishes, that factor and its
    meaning. `chain` has frames 0..n; `sample` and `numbers` are its robot file's (the wrist
    centre is found at its sample values, the factors are written with its numbers)."""
    joints = set(chain.joint_variables)
    found = [(index, factor_bases(expr)) for expr, index in derivation.vanishing]
    possible = [b for _, bases in found for b in bases if b.free_symbols <= chain.symbols and b.free_symbols & joints]
    meeting = [k for k, c in enumerate(derivation.conditions) if isinstance(c, Exists) and c.unknown is not None]
    if not possible and not meeting:
        return
    wrist, centre = set(chain.joint_variables[3:]), wrist_centre(chain, sample=sample)
    if not meeting and all(b.free_symbols & joints <= wrist for b in possible) and centre is not None:
        factors = wrist_factors(chain, numbers, sample)
    else:
        try:  # the factors `dhsym jacobian` prints, without the value it prints besides
            factors = partitioned_factors(chain, centre, numbers) if centre is not None else \
                determinant(chain, numbers=numbers, sample=sample).factors
        except TooManyTerms:  # counted before it is expanded: a general 6R's, which says nothing here
            return
    said = {s.factor: Singular(s.factor, s.template, s.joints)
            for s in singularities(chain, SimpleNamespace(factors=factors), sample=sample)}
    for index, bases in found:
        matched = [g for g in factors for b in bases if sympy.expand(b - g) == 0 or sympy.expand(b + g) == 0]
        if matched:
            derivation.degenerate[index] = replace(derivation.degenerate[index], singular=said[matched[0]])
    names = _in_joints(chain, definitions, derivation)
    for k in meeting:
        product = meeting_factors(chain, derivation.conditions[k].expression.xreplace(names), factors, sample)
        if product:
            derivation.conditions[k] = replace(derivation.conditions[k], singular=tuple(said[f] for f in product))


def _in_joints(chain: Chain, definitions, derivation) -> dict:
    """The target's elements as the forward kinematics gives them, and every name the derivation
    defines in the joint variables: where the branch holds, each is its value at the joints."""
    fk = chain.fk()
    names = dict(zip(target_symbols(reserved(chain)), [fk[r, c] for r in range(3) for c in range(4)]))
    for name, value in list(definitions) + list(derivation.assignments):
        if name not in chain.joint_variables:
            names[name] = derivation.angles.get(name, value.xreplace(names))
    return names


def meeting_factors(chain: Chain, side, factors, sample, trials: int = 3) -> tuple:
    """The factors f1 … fm of det J with `side` (an existence condition's left side, in the joint
    variables) equal to k (f1 ⋯ fm)², k free of the joints: the two roots meet exactly where one of
    them is 0 (the PUMA's a3² + d4² − K² is (d4 c3 + a3 s3)², Stanford's x_c² + y_c² − d2² is
    d3² s2²). Tried in numbers at a few poses first, the fewest factors first, then proven by algebra:
    both sides in cos and sin of each joint, reduced by sin² + cos² = 1 (a normal form: two
    trigonometric polynomials are equal exactly when theirs are). () where no product is."""
    rng = random.Random(5)
    points = [sample_values(chain, rng, sample) for _ in range(trials)]
    ring = _Ring(chain.joint_variables)
    sides = [float(side.xreplace(values)) for values in points]  # once, for every product
    joined = [f for f in factors if f.free_symbols & set(chain.joint_variables)]
    for size in range(1, len(joined) + 1):
        for product in itertools.combinations(joined, size):
            square = sympy.Mul(*product) ** 2
            ratios = [_ratio(value, square, values) for value, values in zip(sides, points)]
            if None in ratios or max(ratios) - min(ratios) > 1e-9 * max(1.0, max(map(abs, ratios))):
                continue
            if ring.multiple(side, square):
                return product
    return ()


class _Ring:
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


def _ratio(side: float, square, values) -> float | None:
    value = float(square.xreplace(values))
    return None if abs(value) < 1e-12 else side / value


def wrist_factors(chain: Chain, numbers, sample=None) -> list:
    """The factors of det C (the three wrist axes, in the axis frame of joint 5), in the form and
    order that `determinant(chain).factors` gives them, written with `numbers`."""
    centre, body = wrist_centre(chain, sample=sample or {}), chain.last_frame
    wrist = [angular_part(chain, j, axis_frame(chain, 5), centre, body) for j in (4, 5, 6)]
    value = as_written(factored(factored(sympy.Matrix(wrist).T.det(method="berkowitz"))), numbers)
    return joint_factors(value, chain)


def say_lined_up(chain: Chain, derivation) -> None:
    """Where sin θk = 0 lines up two axes, say which of the sum or the difference is determined."""
    for _, index in derivation.vanishing:
        said = derivation.degenerate[index]
        if isinstance(said.reason, LinedUp):
            derivation.degenerate[index] = replace(said, reason=lined_up(chain, said.reason.angle))


def lined_up(chain: Chain, angle) -> LinedUp:
    """Where sin θk = 0 lines up the axes of joints k − 1 and k + 1, which angle they still fix:
    the sum of the angles about the lined-up axes where they point the same way, the difference
    where they point opposite ways; θk = 0 and θk = π swap the two. Joints whose axes are parallel
    to one of the two turn with it (the UR5's θ2 + θ3 + θ4). Measured at one pose. With an offset
    (sin(θk + c) = 0) the axes line up where θk + c is 0 or π.

    >>> import dhsym
    >>> found = lined_up(dhsym.load("puma560").chain, dhsym.load("puma560").joint_variables[4])
    >>> found.total(), found.total(at_pi=True)
    (theta_4 + theta_6, theta_4 - theta_6)
    """
    unsaid = LinedUp(angle)
    joint = angle_symbol(angle)
    if joint not in chain.joint_variables:
        return unsaid
    k = list(chain.joint_variables).index(joint) + 1
    if not 1 < k < chain.n:
        return unsaid
    values = sample_values(chain, random.Random(k))
    values[joint] = -float(angle - joint)  # the angle 0
    frame_poses = poses(chain, values)

    def parallel_run(start, step):  # (joint, ±1) for joint `start` and its parallel neighbours away from k
        reference = axis_line(chain, start, frame_poses)[1]
        run, j = [], start
        while 1 <= j <= chain.n and chain.rows[j - 1].joint == "R":
            along = dot(reference, axis_line(chain, j, frame_poses)[1])
            if abs(abs(along) - 1) > TOLERANCE:
                break
            run.append((j, 1 if along > 0 else -1))
            j += step
        return run, reference

    before, towards = parallel_run(k - 1, -1)
    after, away = parallel_run(k + 1, 1)
    alike = dot(towards, away)
    if not before or not after or abs(abs(alike) - 1) > TOLERANCE:
        return unsaid
    variables = chain.joint_variables
    return LinedUp(angle, tuple((variables[j - 1], s) for j, s in sorted(before)),
                   tuple((variables[j - 1], s if alike > 0 else -s) for j, s in sorted(after)))
