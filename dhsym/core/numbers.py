"""How a chain's numbers were written, so that every printer writes them back the same way.

Arithmetic stays exact: the parser reads `0.425` as the Rational 17/40. What it also records is
*how* the file wrote its numbers: the most decimal places of any decimal literal, and the
denominators it wrote as fractions. A printer then writes a rational as a decimal when

- the file wrote decimals at all (`places > 0`),
- the rational has a finite decimal expansion of at most `2 × places` places (so sums and
  products of the written decimals stay decimals: 0.425 + 0.39225 = 0.81725, 0.333·0.5 = 0.1665),
- and its denominator is not one the file wrote as a fraction (`l_1/2`, `1/3` keep their form),
  unless it stands alone and is the value of a decimal the file wrote (`d: 0.5` next to `l_1/2`
  prints 0.5, and l_1/2 prints l1/2).

Integers, fractions in a file without decimals and multiples of π print as before.

An inverse solution holds the file's decimals as symbols named by their decimal, and arithmetic on
them folded into such symbols (dhsym.inverse.written): its numbers are `folded`, and any other
rational is the algebra's own (Ferrari's s/2, cos 60° = 1/2), written as a fraction unless it stands
alone and is the value of a decimal the file wrote (an angle's offset).

>>> numbers = WrittenNumbers(places=5)
>>> numbers.decimal(sympy.Rational(3269, 4000)), numbers.decimal(sympy.Rational(1, 3))
('0.81725', None)
>>> WrittenNumbers(places=1, fractions=frozenset({2})).decimal(sympy.Rational(1, 2)) is None
True
>>> WrittenNumbers(places=1, values=frozenset({sympy.Rational(1, 2)}), folded=True).decimal(sympy.Rational(1, 2))
>>> WrittenNumbers(places=1, values=frozenset({sympy.Rational(1, 2)}), folded=True).decimal(sympy.Rational(1, 2), True)
'0.5'
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

FRACTION_PLACES = 6  # in a solution, a rational whose decimal needs more places is the file's, not the algebra's
ROUNDED_DIGITS = 10  # a decimal of more significant digits is a rounded value (an import's 15), not one typed


@dataclass(frozen=True)
class WrittenNumbers:
    """The decimal places and fraction denominators a robot file wrote its numbers with."""

    places: int = 0  # the most decimal places of any decimal literal; 0 when the file wrote none
    fractions: frozenset = frozenset()  # denominators written as fractions, as in l_1/2 or 1/3
    values: frozenset = frozenset()  # the values of the decimal literals, without sign
    folded: bool = False  # the decimals are symbols already (an inverse solution): other rationals are fractions
    named: tuple = ()  # (decimal, name, places) of long decimals a derivation names: see `Named`

    def name_of(self, decimal: str) -> str | None:
        """The name a derivation gives the long decimal `decimal` (`a_2`, `beta`), or None."""
        return next((name for text, name, _ in self.named if text == decimal), None)

    def decimal(self, value, alone: bool = False) -> str | None:
        """The exact decimal text of a rational the printers should write as a decimal, else None.
        `alone`: the rational is a term or a cell of its own, not the coefficient of a product."""
        if not self.places or not getattr(value, "is_Rational", False) or value.is_Integer:
            return None
        if (10 ** (2 * self.places)) % value.q:
            return None
        if self.folded and (_places(value.q) > FRACTION_PLACES or alone and _places(value.q) <= self.places):
            return decimal_text(value)  # from the decimals (a long one; a sum of offsets): not the algebra's own
        if (self.folded or value.q in self.fractions) and not (alone and abs(value) in self.values):
            return None
        return decimal_text(value)


def table_numbers(values) -> WrittenNumbers:
    """How a table made of the exact decimals `values` is written (a URDF's import): the places of
    the longest, and every value without sign, as reading its robot file back would give.

    >>> table_numbers([sympy.Rational("0.09305"), -sympy.Rational("1.234"), sympy.Integer(2)]).places
    5
    """
    decimals = {abs(v) for v in values if v.is_Rational and not v.is_Integer and _terminates(v.q)}
    return WrittenNumbers(max((_places(v.q) for v in decimals), default=0), values=frozenset(decimals))


def is_long(value) -> bool:
    """Whether a decimal has more significant digits than ROUNDED_DIGITS: a value an import rounded
    to 15 (√449/200 is 0.105948100502085), which a derivation names instead of writing it out.

    >>> [is_long(sympy.Rational(text)) for text in ("0.105948100502085", "0.113575", "0.1234567")]
    [True, False, False]
    """
    if not getattr(value, "is_Rational", False) or value.is_Integer or not _terminates(value.q):
        return False
    return len(decimal_text(abs(value)).replace(".", "").lstrip("0")) > ROUNDED_DIGITS


def _terminates(q: int) -> bool:
    while q % 2 == 0:
        q //= 2
    while q % 5 == 0:
        q //= 5
    return q == 1


def decimal_text(value: sympy.Rational) -> str:
    """The finite decimal expansion of a rational whose denominator divides a power of ten.

    >>> decimal_text(sympy.Rational(-17, 40)), decimal_text(sympy.Rational(89159, 1000000))
    ('-0.425', '0.089159')
    """
    places = _places(value.q)
    digits = str(abs(value.p) * 10**places // value.q).rjust(places + 1, "0")
    text = digits[:-places] + "." + digits[-places:] if places else digits
    return ("-" if value.p < 0 else "") + text


def _places(q: int) -> int:
    """Decimal places of 1/q for q = 2^i 5^j: max(i, j)."""
    twos = fives = 0
    while q % 2 == 0:
        q, twos = q // 2, twos + 1
    while q % 5 == 0:
        q, fives = q // 5, fives + 1
    if q != 1:
        raise ValueError("no finite decimal expansion")
    return max(twos, fives)
