"""The program's results multiplied out as sparse polynomials, fast, with sin² + cos² = 1 applied.

`sympy.expand` on the written-out results of a six-joint arm takes a minute; SymPy's sparse
polynomial rings (dictionaries of exponent tuples) multiply the same in seconds. Every name of the
program becomes a polynomial in the robot's symbols and in cos x, sin x of each angle x, computed
once from its definition; anything else (a square root of a symbol, a symbol in a denominator) is
an opaque generator of its own. Then, angle by angle, sin² is written as 1 − cos² or cos² as
1 − sin², whichever leaves fewer terms.

>>> from dhsym.dynamics.tape import Tape
>>> x, a, b = sympy.symbols("x a b", real=True)
>>> tape = Tape()
>>> value = tape.name(a * sympy.sin(x)**2 + tape.name(a + b) * sympy.cos(x)**2)
>>> multiplied_out(tape, [value])
[a + b*cos(x)**2]
"""
from __future__ import annotations

import math

import sympy
from sympy.polys.domains import EX, QQ
from sympy.polys.rings import ring


def angle_sums(bodies) -> dict:
    """{cos θ_k: …, sin θ_k: …} for each joint whose axis is parallel to the one before: its cos
    and sin through the angle sums of the run, cos θ3 = c23 c2 + s23 s2, so that the results hold
    c23 where the joints turn together, as the book writes them (a twist of π turns the following
    angles negative, as in the contraction, dhsym.core.simplify). Runs start at the first body
    given: M and C never hold joint 1's angle, so `bodies[1:]` keeps a planar arm's c2 a c2.

    >>> from dhsym.io.library import load
    >>> from dhsym.core.inertia import MassModel
    >>> from dhsym.dynamics.model import rigid_model
    >>> model = rigid_model(load("puma560").chain, MassModel().filled(6))
    >>> angle_sums(model.bodies[1:])[sympy.cos(sympy.Symbol("theta_3", real=True))]
    sin(theta_2)*sin(theta_2 + theta_3) + cos(theta_2)*cos(theta_2 + theta_3)
    """
    out, total, sign = {}, None, 1
    for body in bodies:
        half_turns = body.twist / sympy.pi
        if total is None or not half_turns.is_Integer:
            total, sign = body.angle, 1
            continue

        sign = -sign if half_turns % 2 else sign
        before, total = total, total + sign * body.angle
        if body.angle.free_symbols and before.free_symbols:  # after a constant angle, θ is its own sum

            cos, sin = sympy.cos, sympy.sin
            out[cos(body.angle)] = cos(total) * cos(before) + sin(total) * sin(before)
            out[sin(body.angle)] = sign * (sin(total) * cos(before) - cos(total) * sin(before))
    return out


def multiplied_out(tape, values, sums: dict | None = None) -> list:
    """Each value (an expression in names of `tape`) multiplied out, with sin² + cos² = 1 applied
    where it shortens it; SymPy expressions. `sums` (from `angle_sums`) writes the cos and sin of
    some angles through others."""
    values = [sympy.sympify(v) for v in values]
    sums = sums or {}
    written_out = [*values, *(tape.definitions[s] for s in tape.used(values))]
    atoms, opaque = _generators(written_out, tape, sums)
    domain = QQ if all(_rational(n) for n in _numbers(written_out)) else EX
    placeholders = [sympy.Dummy(f"x{k}") for k in range(len(atoms))]
    polynomials, *gens = ring(placeholders, domain)
    position = {atom: k for k, atom in enumerate(atoms)}
    memo: dict = {}

    def convert(expr):
        if expr in tape.definitions or expr in sums:
            if expr not in memo:
                memo[expr] = convert(tape.definitions[expr] if expr in tape.definitions else sums[expr])
            return memo[expr]
        if expr in position:
            return gens[position[expr]]
        if expr in opaque:
            return gens[position[opaque[expr]]]
        if expr.is_number:  # 1/2, and √3/2 from a twist of π/6 (then the coefficients are expressions)
            return polynomials(domain.from_sympy(expr))

        if expr.is_Add:
            return sum((convert(a) for a in expr.args), polynomials.zero)
        if expr.is_Mul:
            return math.prod((convert(a) for a in expr.args), start=polynomials.one)
        if expr.is_Pow:
            return convert(expr.base) ** int(expr.exp)
        raise ValueError(f"no polynomial for {expr}")  # _generators made every other atom opaque

    undo = {placeholder: expr for expr, placeholder in opaque.items()}
    written = [undo.get(atom, atom) for atom in atoms]
    pairs = [(position[a], position[sympy.cos(a.args[0])]) for a in atoms if isinstance(a, sympy.sin)]
    return [_as_expr(_pythagoras(convert(value), pairs, gens), written, domain) for value in values]


def _as_expr(polynomial, atoms: list, domain) -> sympy.Expr:
    """The sum of the terms, written with the atoms themselves."""
    terms = []
    for monomial, coefficient in polynomial.items():
        factors = [atoms[k] ** power if power > 1 else atoms[k] for k, power in enumerate(monomial) if power]
        terms.append(sympy.Mul(domain.to_sympy(coefficient), *factors))
    return sympy.Add(*terms)



def _generators(written_out: list, tape, sums: dict) -> tuple:
    """(the generators: the robot's symbols, cos and sin of each angle, placeholders of the opaque
    parts; {opaque part: its placeholder}) of the values and the definitions they use, `written_out`."""
    atoms, opaque = set(), {}
    waiting = list(written_out)
    while waiting:
        expr = waiting.pop()
        if expr in sums:
            waiting.append(sums[expr])
        elif expr.is_Atom:

            if expr.is_Symbol and expr not in tape.definitions:
                atoms.add(expr)
        elif isinstance(expr, (sympy.cos, sympy.sin)):
            atoms.update({sympy.cos(expr.args[0]), sympy.sin(expr.args[0])})
        elif expr.is_Pow and not (expr.exp.is_Integer and expr.exp >= 0) and not expr.base.is_Number:
            opaque.setdefault(expr, sympy.Dummy(f"opaque{len(opaque)}"))
        elif expr.is_Add or expr.is_Mul or expr.is_Pow:
            waiting.extend(expr.args)
        elif not expr.is_Number:
            opaque.setdefault(expr, sympy.Dummy(f"opaque{len(opaque)}"))
    atoms |= set(opaque.values())
    return sorted(atoms, key=sympy.default_sort_key), opaque


def _numbers(written_out: list) -> set:
    found = set()
    for expr in written_out:
        found |= {a for a in expr.atoms(sympy.Number, sympy.Pow) if a.is_Number or a.base.is_Number and a.is_number}
    return found


def _rational(number) -> bool:
    return number.is_Rational


def _pythagoras(polynomial, pairs, gens):
    """sin² = 1 − cos² or cos² = 1 − sin², angle by angle, whichever gives fewer terms, over and over
    while the terms get fewer (one angle's rewriting can open another's: s2²(s4² + c4² − 1) is 0
    only once s2² is left alone)."""
    shorter = True
    while shorter and polynomial:
        shorter = False
        degrees = polynomial.degrees()
        for s, c in pairs:
            if degrees[s] < 2 and degrees[c] < 2:
                continue
            for square, other in ((s, c), (c, s)):

                candidate = _reduce(polynomial, square, other, gens)
                if len(candidate) < len(polynomial):
                    polynomial, shorter = candidate, True
    return polynomial



def _reduce(polynomial, square: int, other: int, gens):
    """x² → 1 − y² in every term (x the generator at `square`, y at `other`), on the dictionary of
    terms: (1 − y²)ᵏ by the binomial theorem."""
    changed = [(monomial, coefficient) for monomial, coefficient in polynomial.items() if monomial[square] >= 2]
    if not changed:
        return polynomial
    out = {monomial: coefficient for monomial, coefficient in polynomial.items() if monomial[square] < 2}
    for monomial, coefficient in changed:
        power = monomial[square]
        kept = list(monomial)
        kept[square] = power % 2
        base = kept[other]
        for k in range(power // 2 + 1):
            kept[other] = base + 2 * k
            key = tuple(kept)
            factor = math.comb(power // 2, k) * (-1) ** k
            value = coefficient if factor == 1 else coefficient * factor  # rationals are slow: skip × 1 and 0 +
            known = out.get(key)
            total = value if known is None else known + value
            if total:
                out[key] = total
            else:
                del out[key]
    return polynomial.ring(out)

