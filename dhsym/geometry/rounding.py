"""Table values as a person writes them: exact where the exact form is short, else a decimal of
SIGNIFICANT digits, with a record of what was rounded so that a note can say so.

Frame assignment produces every kind of exact number: rationals (sums of the decimals written,
or fractions from normalising a direction), surds, multiples of π, atan/acos/atan2 of exact
numbers, and sums and products of these with symbols. A robot file reads numbers, names,
+ − × ÷ powers, sqrt, sin, cos and π only, and a table made from decimals should show decimals:

- a rational whose decimal ends within EXACT_DIGITS significant digits stays exact (0.024645);
- a rational multiple of π with a short fraction stays exact (pi/2, 5*pi/12);
- with `decimals=False` (the input was written exactly: integers, fractions, symbols) short
  fractions and short surds stay exact too (1/3, 3*sqrt(2)/20);
- every other number, and every other numeric coefficient of a symbol, is rounded to
  SIGNIFICANT significant digits. 15 digits is what a double holds, far finer than any robot's
  drawing; the table's forward kinematics stays within about 1e-15 (relative) of the geometry.

`written_text` prints a value the way a robot file writes it (decimals where they end); the
writer (dhsym.io.robotwriter) and the notes use it.

>>> decimal_text(fit(sympy.atan(sympy.Rational(4, 3))))
'0.927295218001612'
>>> print(Rounding("alpha_2", fit(sympy.atan(sympy.Rational(4, 3))), sympy.atan(sympy.Rational(4, 3))))
alpha_2 0.927295218001612 (exactly atan(4/3))
>>> decimal_text(fit(sympy.Rational("0.024645") + 11139 * sympy.sqrt(2) / 400000))
'0.0640273121781848'
>>> fit(3 * sympy.sqrt(2) / 20, decimals=False), fit(sympy.pi / 2), fit(sympy.Rational("0.425"))
(3*sqrt(2)/20, pi/2, 17/40)
>>> fit(sympy.Rational(1, 3), decimals=False), decimal_text(fit(sympy.Rational(1, 3)))
(1/3, '0.333333333333333')

An angle that rounds to the same 15 digits as a multiple of π/12 is written as that multiple
(the rule of dhsym.core.grid at the digits a rounded value keeps); a length never is:

>>> fit(sympy.atan(sympy.Rational(10**16))), fit(sympy.pi / 2 + sympy.Rational(1, 10**17))
(pi/2, pi/2)
>>> decimal_text(fit(sympy.atan(sympy.Rational(10**16)), length=True))
'1.5707963267949'
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import sympy
from sympy.printing.precedence import PRECEDENCE
from sympy.printing.str import StrPrinter

from ..core.grid import ANGLE_STEP
from ..core.numbering import PLAIN, Numbering
from ..core.numbers import WrittenNumbers, decimal_text
from .exact import is_zero

SIGNIFICANT = 15  # digits of a rounded value: a double's precision
EXACT_DIGITS = 20  # a decimal that ends within this many significant digits is written exactly
SHORT = 6  # digits of a numerator or denominator a person writes in a fraction (1/3, 5*pi/12)
SHOWN = 120  # characters of an exact value a note shows
LONG_DENOMINATOR = 1000  # a coefficient over this (terminating) denominator is written as a decimal


@dataclass(frozen=True)
class Rounding:
    """One value that was rounded: where it stands (`alpha_2`, `theta_3 offset`, `tool Rz`),
    the value written, and the exact value it stands for."""

    label: str
    value: sympy.Expr
    exact: sympy.Expr

    def __str__(self) -> str:
        exact = str(self.exact)
        shown = f"exactly {exact}" if len(exact) <= SHOWN else f"from an exact form {len(exact)} characters long"
        return f"{self.label} {written_text(self.value)} ({shown})"


def rounding_note(roundings: list) -> str:
    """The sentence a robot file's notes get for the values rounded in it ('' when none).

    >>> rounding_note([Rounding("a_2", sympy.Rational(1, 8), sympy.Rational(1, 8))])
    'Rounded to 15 significant digits: a_2 0.125 (exactly 1/8).'
    """
    if not roundings:
        return ""
    return f"Rounded to {SIGNIFICANT} significant digits: " + "; ".join(map(str, roundings)) + "."


def joined(*parts: str) -> str:
    """Notes one after another, each but the last ending as a sentence.

    >>> joined("Derived by dhsym import", "", "Rounded: a_2.")
    'Derived by dhsym import. Rounded: a_2.'
    """
    parts = [part.strip() for part in parts if part and part.strip()]
    return " ".join([p if p.endswith((".", "!", "?")) else p + "." for p in parts[:-1]] + parts[-1:])


def fit(value, decimals: bool = True, length: bool = False) -> sympy.Expr:
    """`value` itself when its exact form is one a person writes, else rounded (see the module).
    A `length` keeps no π: a robot file reads π in angles only.

    >>> fit(sympy.pi / 4), decimal_text(fit(sympy.pi / 4, length=True))
    (pi/4, '0.785398163397448')
    """
    value = sympy.sympify(value)
    if value.free_symbols:
        return _fit_symbolic(value, decimals, length)
    return _fit_number(value, decimals, length)


def dh_label(convention: str, row: int, field: str, numbering: Numbering = PLAIN, moving: bool = False) -> str:
    """The DH name of a table cell (`row` 1..n of the chain, named as `numbering` prints it): row 3's
    a is a_3 in the standard convention, a_2 in the modified one (the same common normal either
    way), so a note stays true after conversion.

    >>> dh_label("modified", 3, "alpha"), dh_label("standard", 2, "theta", moving=True)
    ('alpha_2', 'theta_2 offset')
    >>> dh_label("standard", 1, "d", Numbering(3))
    'd_4'
    """
    index = numbering.joint(row) - (1 if convention == "modified" and field in ("a", "alpha") else 0)
    return f"{field}_{index}" + (" offset" if moving else "")


class _WrittenPrinter(StrPrinter):
    """sympy's str form, with terminating fractions as decimals (what a robot file says), except
    denominators the file wrote as fractions; a long coefficient is a decimal too (0.7071*l_1)."""

    def __init__(self, numbers: WrittenNumbers):
        super().__init__({"order": "none"})
        self.numbers = numbers

    def decimal(self, value: sympy.Rational) -> str | None:
        if value.q in self.numbers.fractions and abs(value) not in self.numbers.values:
            return None
        return decimal_text(value) if _terminates(value) else None

    def _print_Rational(self, expr):
        return self.decimal(expr) or super()._print_Rational(expr)

    def _print_Mul(self, expr):
        coefficient, rest = expr.as_coeff_Mul()
        text = self.decimal(coefficient) if coefficient.is_Rational and coefficient.q > LONG_DENOMINATOR else None
        if text is None or rest == 1:
            return super()._print_Mul(expr)
        return f"{text}*{self.parenthesize(rest, PRECEDENCE['Mul'])}"


def _terminates(value: sympy.Rational) -> bool:
    q = int(value.q)
    for prime in (2, 5):
        while q % prime == 0:
            q //= prime
    return q == 1


def written_text(value, numbers: WrittenNumbers | None = None) -> str:
    """A value as a robot file writes it: terminating fractions as decimals unless `numbers`
    (how the chain's file wrote them) has that denominator as a fraction, π and roots by name.

    >>> l = sympy.Symbol("l_1", real=True)
    >>> written_text(sympy.Rational(17, 40) + l / 2), written_text(sympy.Rational(707106781186548, 10**15) * l)
    ('0.425 + l_1/2', '0.707106781186548*l_1')
    """
    return _WrittenPrinter(numbers or WrittenNumbers()).doprint(sympy.sympify(value))


def _fit_number(value: sympy.Expr, decimals: bool, length: bool, alone: bool = True) -> sympy.Expr:
    """`alone`: the number is a value, not a symbol's coefficient (only a value can be an angle)."""
    if value.is_Rational:
        if _short_decimal(value) or (not decimals and _short_fraction(value)):
            return value
    elif length and value.has(sympy.pi):
        return _rounded(value)
    elif (value / sympy.pi).is_Rational and _short_fraction(value / sympy.pi) or not decimals and _short_surd(value):
        return value
    rounded = _rounded(value)
    return rounded if length or not alone else _multiple_rounding_to(rounded) or rounded


def _multiple_rounding_to(rounded: sympy.Rational) -> sympy.Expr | None:
    """The multiple of π/12 (not 0) that rounds to the same SIGNIFICANT digits as an angle, if any:
    the angle is that multiple up to the rounding it would get anyway (core.grid's rule, at a
    double's digits), as when URDF angles of 0.4 and 1.170796326794897 add up to π/2."""
    steps = round(float(rounded) / float(ANGLE_STEP))
    return steps * ANGLE_STEP if steps and _rounded(steps * ANGLE_STEP) == rounded else None


def _fit_symbolic(value: sympy.Expr, decimals: bool, length: bool) -> sympy.Expr:
    """Each numeric coefficient of a symbolic term fitted as a number."""
    symbols = value.free_symbols
    changed, terms = False, []
    for term in sympy.Add.make_args(value):
        coefficient, rest = term.as_independent(*symbols, as_Mul=True)
        fitted = _fit_number(coefficient, decimals, length, alone=rest == 1)
        changed = changed or fitted is not coefficient
        terms.append(fitted * rest)
    return sympy.Add(*terms) if changed else value


def _rounded(value: sympy.Expr) -> sympy.Rational:
    if is_zero(value):  # exactly zero, only not written so
        return sympy.Integer(0)
    return sympy.Rational(Fraction(str(sympy.N(value, SIGNIFICANT))))


def _significant(value: sympy.Rational) -> int | None:
    """How many significant digits the decimal of `value` has; None when it does not end."""
    if not _terminates(value):
        return None
    return len(decimal_text(abs(value)).replace(".", "").lstrip("0").rstrip("0") or "0")


def _short_decimal(value: sympy.Rational) -> bool:
    digits = _significant(value)
    return digits is not None and digits <= EXACT_DIGITS


def _short_fraction(value: sympy.Rational) -> bool:
    return len(str(abs(value.p))) <= SHORT and len(str(value.q)) <= SHORT


def _short_surd(value: sympy.Expr) -> bool:
    """Rationals, square roots and π with short numbers only, as in 3*sqrt(2)/20."""
    allowed = all(isinstance(node, (sympy.Add, sympy.Mul, sympy.Pow, sympy.Rational, type(sympy.pi)))
                  for node in sympy.preorder_traversal(value))
    roots = all(p.exp.q <= 2 for p in value.atoms(sympy.Pow))
    return allowed and roots and all(_short_fraction(r) for r in value.atoms(sympy.Rational)) \
        and len(str(value)) <= 40


