"""Decimals as the robot file wrote them, through the solver and back out.

The parser reads `0.0823` as the Rational 823/10000, and SymPy combines rationals: solved with
the numbers in, a UR5 gives `D = (20000 px s1 − 20000 py c1 − 2183)/1646`. So the solver gets a
chain whose written decimals (the lengths a and d, and the translations of the base and tool)
are symbols, one per value, and solves it as it solves a table of names:
`D = (px s1 − py c1 − d4)/d6`. A `Written` symbol's name is its decimal, so every printer
writes it as the file did: `D = (px s1 − py c1 − 0.10915)/0.0823`. Afterwards products, powers
and sums of written numbers are folded into one decimal wherever the file's rule prints the result
as a decimal (see dhsym.core.numbers): `2·0.089159·0.0823 r33` is `0.0146755714 r33`.

>>> import sympy
>>> from dhsym.core.numbers import WrittenNumbers
>>> a, b = Written.of(sympy.Rational(17, 40)), Written.of(sympy.Rational(823, 10000))
>>> a, a.value
(0.425, 17/40)
>>> px = sympy.Symbol("px", real=True)
>>> fold(2 * a * b * px + a**2 - px / b, WrittenNumbers(places=5))
px*0.069955 - px/0.0823 + 0.180625
>>> exact(px / b)
10000*px/823

A decimal too long to read in a formula (an import's a2 = 0.105948100502085, its offset
1.23412150740817 = atan(20/7)) is a `Named` number: the solver and the generated code see the
decimal, the printers write the name `with_names` gives it (a2, β), and folding leaves it alone,
so that D reads (X² + Y² − a2² − 0.01)/(0.2 a2), not a sum of 30 digits.
"""
from __future__ import annotations

from dataclasses import replace

import sympy

from ..core.chain import Chain, DHRow, plain
from ..core.numbers import WrittenNumbers, decimal_text, is_long
from ..core.transforms import Step


class Written(sympy.Symbol):
    """A positive number as the robot file wrote it: a symbol named by its decimal, `0.0823`,
    that the solver treats as a constant and every printer writes as the decimal."""

    @classmethod
    def of(cls, value) -> "Written":
        return cls(decimal_text(sympy.Rational(value)), positive=True)

    @property
    def value(self) -> sympy.Rational:
        return sympy.Rational(self.name)


class Named(Written):
    """A long decimal of the file that a derivation writes by a name (see `with_names`)."""


def with_names(chain: Chain, numbers: WrittenNumbers) -> WrittenNumbers:
    """`numbers` with a name for each long decimal (see core.numbers.is_long) of the chain's
    lengths, revolute joints' offsets and base and tool translations, with the places
    (parameter, row or axis, whether subtracted) it stands in: a length by its place
    (`a_2`, `d_3`; the base's and tool's `b_z`, `t_x`), an offset `beta` (`beta_2`, `beta_3`
    when the offsets differ); none that a symbol of the chain already has.

    >>> q, long = sympy.Symbol("q_1", real=True), sympy.Rational("0.105948100502085")
    >>> chain = Chain([DHRow("R", q - 2 * long, sympy.S.Zero, long, sympy.S.Zero, q)], "standard")
    >>> [(text, name) for text, name, _ in with_names(chain, WrittenNumbers(places=15)).named]
    [('0.105948100502085', 'a_1'), ('0.21189620100417', 'beta')]
    """
    chain, found = plain(chain), {}

    def note(value, parameter, place):
        for term in sympy.Add.make_args(sympy.sympify(value)):  # a number alone, not the coefficient of √2
            if is_long(term) and numbers.decimal(abs(term)):
                found.setdefault(decimal_text(abs(term)), []).append((parameter, place, term < 0))

    for number, row in enumerate(chain.rows, 1):
        note(row.a, "a", number)
        note(row.d, "d", number)
        if row.joint == "R":
            note(row.theta, "theta", number)
    for parameter, steps in (("b", chain.base), ("t", chain.tool)):
        for step in (step for step in steps if not step.is_rotation):
            note(step.value, parameter, step.kind[1])
    angles = [text for text, places in found.items() if places[0][0] == "theta"]
    taken, named = {s.name for s in chain.symbols}, []
    for text, places in found.items():
        parameter, place, _ = places[0]
        name = ("beta" if len(angles) == 1 else f"beta_{place}") if parameter == "theta" else f"{parameter}_{place}"
        if name not in taken:
            taken.add(name)
            named.append((text, name, tuple(places)))
    return replace(numbers, named=tuple(named))


def exact(expr):
    """`expr` with every written number put back as its exact rational."""
    found = {s: s.value for s in getattr(expr, "free_symbols", ()) if isinstance(s, Written)}
    return expr.xreplace(found) if found else expr


def exact_but_named(expr):
    """`expr` with every written number put back as its exact rational but the named ones (a2, β),
    which a sentence writes by name as the formulas do."""
    found = {s: s.value for s in getattr(expr, "free_symbols", ())
             if isinstance(s, Written) and not isinstance(s, Named)}
    return expr.xreplace(found) if found else expr


def with_written_symbols(chain: Chain, sample, numbers) -> tuple:
    """(a copy of `chain` whose written decimals (as `numbers` says the file wrote them) are
    `Written` symbols, the `sample` with their values, {symbol: value}); the chain and sample
    themselves and {} when it has none. Angles (θ offsets, α, base and tool rotations) keep their
    numbers: the solver reads the axes' directions from them."""
    chain, sample, found = plain(chain), dict(sample or {}), {}

    def put(value, named_only=False):
        value = sympy.sympify(value)
        terms = []
        for term in sympy.Add.make_args(value):
            coefficient, rest = term.as_coeff_Mul()
            if coefficient.is_Rational and not coefficient.is_Integer and numbers.decimal(abs(coefficient)):
                named = numbers.name_of(decimal_text(abs(coefficient))) is not None
                if named_only and not named:
                    terms.append(term)
                    continue
                symbol = (Named if named else Written).of(abs(coefficient))
                found[symbol] = symbol.value
                term = (1 if coefficient > 0 else -1) * symbol * rest
            terms.append(term)
        return sympy.Add(*terms)

    rows = [DHRow(row.joint, put(row.theta, True) if row.joint == "R" else row.theta, put(row.d), put(row.a),
                  row.alpha, row.variable) for row in chain.rows]
    moved = [[step if step.is_rotation else Step(step.kind, put(step.value)) for step in steps]
             for steps in (chain.base, chain.tool)]
    if not found:
        return chain, sample, {}
    return Chain(rows, chain.convention, moved[0], moved[1], chain.simplifier), {**sample, **found}, found


def fold(expr, numbers):
    """`expr` with each product, power and sum of numbers and written numbers made one written
    decimal where the file's rule prints it as one (else left as it is)."""
    if not isinstance(expr, sympy.Basic) or expr.is_Atom or not _holds_written(expr):
        return expr
    args = [fold(arg, numbers) for arg in expr.args]
    if expr.is_Mul:
        constant = [a for a in args if _is_constant(a) and exact(a).is_Rational]
        rest = [a for a in args if a not in constant]  # with a surd, √2: 2 · 0.1 √3 is 0.2 √3
        if not any(map(_holds_written, constant)):  # the algebra's own number, s/2: not a decimal
            return _product(args)
        upper = [a for a in constant if not (a.is_Pow and a.exp.is_negative) and not a.is_Rational]
        lower = [1 / a for a in constant if a.is_Pow and a.exp.is_negative]
        for number in (a for a in constant if a.is_Rational):  # 1/2 goes to the denominator as 2
            upper, lower = upper + [sympy.Integer(number.p)], lower + [sympy.Integer(number.q)]
        whole = _written(sympy.Mul(*constant), numbers)
        if whole is not None:
            return sympy.Mul(whole, *rest)
        top, bottom = _written(sympy.Mul(*upper), numbers), _written(sympy.Mul(*lower), numbers)
        top = sympy.Mul(*upper) if top is None else top
        bottom = sympy.Mul(*lower) if bottom is None else bottom
        return sympy.Mul(top, 1 / bottom, *rest)
    if expr.is_Add:  # the constant terms with the same surd summed: 0.2 √3 + 1.2 √3 is 1.4 √3
        groups: dict = {}
        for term in args:
            if _is_constant(term):
                rational = sympy.Mul(*(f for f in sympy.Mul.make_args(term) if exact(f).is_Rational))
                groups.setdefault(term / rational, []).append(rational)
        terms = [a for a in args if not _is_constant(a)]
        for surd, rationals in groups.items():
            whole = _written(sympy.Add(*rationals), numbers) if any(map(_holds_written, rationals)) else None
            terms += [r * surd for r in rationals] if whole is None else [whole * surd]
        return sympy.Add(*terms)
    rebuilt = expr.func(*args)
    if expr.is_Pow and _is_constant(rebuilt):
        whole = _written(rebuilt, numbers)
        return rebuilt if whole is None else whole
    return rebuilt


def _product(factors):
    """The product of `factors` with a number before a sum kept outside it, (f1 s2 + …)/4, as
    sympy.factor_terms writes it (sympy.Mul would multiply it in)."""
    number = sympy.Mul(*(f for f in factors if f.is_Rational))
    rest = sympy.Mul(*(f for f in factors if not f.is_Rational))
    return sympy.Mul(number, rest, evaluate=False) if rest.is_Add and number != 1 else number * rest


def _holds_written(expr) -> bool:
    return any(isinstance(s, Written) for s in expr.free_symbols)


def _is_constant(expr) -> bool:
    """A number, or a product, power or sum of numbers and written numbers only (a named one is
    a name, as a2 is)."""
    return (all(isinstance(s, Written) and not isinstance(s, Named) for s in expr.free_symbols)
            and not expr.has(sympy.Function))


def _written(expr, numbers):
    """A constant as a written decimal (±Written, or an integer), or None if the file's rule would
    not print its value as a decimal."""
    value = exact(expr)
    if not value.is_Rational:
        return None
    if value.is_Integer:
        return value
    if numbers.decimal(abs(value)) is None:
        return None
    return (1 if value > 0 else -1) * Written.of(abs(value))


def as_written(solution, chain: Chain, sample, numbers):
    """A solution of the chain `with_written_symbols` made, given back to `chain` and its `sample`
    with its numbers folded (see `fold`); its numbers say so, and the printers write the rationals
    left (the algebra's own: Ferrari's s/2, cos 60° = 1/2) as fractions. (What the sentences say
    stays as it was: the printers read their numbers exactly.)"""
    pairs = lambda items: tuple((name, fold(value, numbers)) for name, value in items)  # noqa: E731
    steps = tuple(replace(step, lhs=_fold_any(step.lhs, numbers), rhs=_fold_any(step.rhs, numbers))
                  for step in solution.steps)
    return replace(solution, chain=plain(chain), sample=dict(sample or {}), numbers=replace(numbers, folded=True),
                   definitions=pairs(solution.definitions), steps=steps,
                   branches=tuple(replace(branch, assignments=pairs(branch.assignments))
                                  for branch in solution.branches))


def _fold_any(expr, numbers):
    if isinstance(expr, sympy.MatrixBase):
        return expr.applyfunc(lambda element: fold(element, numbers))
    return fold(expr, numbers)
