"""Decimal angles that stand for a multiple of π/12: the one rule every reader applies.

Robot descriptions write π/2 as 1.571 (Doosan), 1.5708 (Kinova), 1.570796 (Techman) or
1.5707963267948966 (a program's double). Such a decimal is read as the multiple of π/12 nearest
to it when

- the multiple, written to the decimal's own places, is that decimal: π/2 is 1.571 to three
  places and 1.5708 to four, π/12 is 0.262 to three; the decimal needs at least MIN_PLACES places
  and MIN_DIGITS significant digits (1.6 and 0.26 are too coarse to tell what was meant), or
- the two differ by at most ANGLE_TOLERANCE, whatever the places (1.570796325, or 1.57079, a π/2
  cut off rather than rounded).

0.0487 or 1.5700 (a written trailing zero is a digit) stay as written. A robot file is a table the
user wrote, so it keeps its decimals (1.5708 gets a warning asking for pi/2) unless the decimal has
a double's precision (DOUBLE_DIGITS significant digits), where the change is below what a double
holds; a URDF's angles follow the rule as it stands. Either reader says once per file what it
read as a multiple and how far that can move the frames.

>>> snap_angle("1.571"), snap_angle("0.262"), snap_angle("0.0487"), snap_angle("1.57079")
((pi/2, True), (pi/12, True), (487/10000, False), (pi/2, True))
>>> grid_angle("1.6"), grid_angle("1.5700"), grid_angle("1.5708", DOUBLE_DIGITS, 0)
(None, None, None)
>>> grid_angle("-1.5707963267948966", DOUBLE_DIGITS, 0)
-pi/2
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from fractions import Fraction

import sympy

from ..errors import Location

ANGLE_STEP = sympy.pi / 12
ANGLE_TOLERANCE = 1e-5  # radians, whatever the places: 1.57079 (a cut-off π/2) is 6.3e-6 from it
MIN_PLACES = 2  # decimal places a decimal needs before it is read as a multiple of π/12 it rounds from
MIN_DIGITS = 3  # significant digits it needs: 1.57 is π/2, 0.26 may be any angle near 15°
DOUBLE_DIGITS = 15  # significant digits of a double: a robot file's decimal this precise is a program's π/2
_MANTISSA = re.compile(r"[+-]?(?P<whole>\d*)\.?(?P<fraction>\d*)(?:[eE](?P<exponent>[+-]?\d{1,4}))?")


def precision(text: str) -> tuple[int, int]:
    """(decimal places, significant digits) of a decimal as written; trailing zeros count.

    >>> precision("1.571"), precision("-0.0487"), precision("1.5700"), precision("2.5e-3"), precision("90")
    ((3, 4), (4, 3), (4, 5), (4, 2), (0, 2))
    """
    match = _MANTISSA.fullmatch(text.strip())
    if not match:
        return 0, 0
    exponent = int(match.group("exponent") or 0)
    digits = (match.group("whole") + match.group("fraction")).lstrip("0")
    return max(0, len(match.group("fraction")) - exponent), len(digits)


def exact_number(text: str) -> sympy.Rational:
    """A plain decimal as written, exactly ('0.1' is 1/10); ValueError for anything else, or one
    longer than 40 characters or with an exponent past 30.

    >>> exact_number("-1.571"), exact_number("2.5e-3")
    (-1571/1000, 1/400)
    >>> exact_number("1e999999")
    Traceback (most recent call last):
    ValueError: not a number of a robot's size: '1e999999'
    """
    match = _MANTISSA.fullmatch(text.strip())
    if not match or not (match.group("whole") or match.group("fraction")) or len(text.strip()) > 40 \
            or abs(int(match.group("exponent") or 0)) > 30:
        raise ValueError(f"not a number of a robot's size: {text.strip()!r}")
    return sympy.Rational(Fraction(text.strip()))


def grid_angle(text: str, least_digits: int = MIN_DIGITS, tolerance: float = ANGLE_TOLERANCE) -> sympy.Expr | None:
    """The multiple of π/12 that the decimal `text` stands for by the module's rule, else None.
    A robot file asks for a double's digits and no tolerance (`least_digits`, `tolerance`)."""
    written = exact_number(text)
    steps = round(float(written) / float(ANGLE_STEP))
    multiple = steps * ANGLE_STEP
    gap = abs(sympy.N(written - multiple, 30))
    places, digits = precision(text)
    rounded = places >= MIN_PLACES and digits >= least_digits and gap < sympy.Rational(1, 2) / 10 ** places
    return multiple if rounded or gap <= tolerance else None


def snap_angle(text: str) -> tuple[sympy.Expr, bool]:
    """An angle written in radians: the multiple of π/12 it stands for, else the decimal exactly.
    The flag says whether the value moved."""
    written = exact_number(text)
    multiple = grid_angle(text)
    if multiple is None:
        return written, False
    return multiple, multiple != written


@dataclass
class Snaps:
    """The angles one file wrote that were read as multiples of π/12, and bounds on how far that
    moves its frames: the rotation changes by at most the sum of the changes, and a point at
    most `reach` metres beyond a changed angle moves by at most change × reach."""

    shown: dict = field(default_factory=dict)  # written text -> the multiple read
    where: Location | str | None = None  # the first angle read so
    turn: float = 0.0
    shift: float = 0.0
    lengths: bool = True  # the file's lengths are numbers, so the shift bound is one

    def add(self, text: str, multiple: sympy.Expr, where, reach: float = 0.0) -> None:
        """One angle read as `multiple`; a decimal that is the double nearest to it (a program's
        1.5707963267948966) says the multiple as closely as a double can, and is not listed."""
        written = exact_number(text)
        if float(written) == float(multiple):
            return
        change = abs(float(sympy.N(written - multiple, 30)))
        self.shown.setdefault(text, multiple)
        self.where = self.where or where
        self.turn += change
        self.shift += change * reach

    def warnings(self) -> list[str]:
        """The one warning of the file, in a list; none when nothing was listed.

        >>> snaps = Snaps()
        >>> snaps.add("1.571", sympy.pi / 2, "arm.urdf:6:32", reach=0.5)
        >>> print(*snaps.warnings())
        arm.urdf:6:32: angles snapped to the multiples of π/12 they were rounded from: 1.571 → π/2; this turns any \
frame by at most 0.00021 rad and moves it by at most 0.00011 m
        """
        if not self.shown:
            return []
        listed = ", ".join(f"{text} → {str(value).replace('pi', 'π')}" for text, value in self.shown.items())
        moved = f" and moves it by at most {_rounded_up(self.shift)} m" if self.lengths and self.shift else ""
        return [f"{self.where}: angles snapped to the multiples of π/12 they were rounded from: {listed}; "
                f"this turns any frame by at most {_rounded_up(self.turn)} rad{moved}"]


def _rounded_up(bound: float) -> str:
    """A bound shown with two significant digits, rounded up so that it stays a bound.

    >>> _rounded_up(0.000204), _rounded_up(3.67e-06), _rounded_up(0.0)
    ('0.00021', '3.7e-06', '0')
    """
    if bound <= 0:
        return "0"
    scale = 10.0 ** (math.floor(math.log10(bound)) - 1)
    return f"{math.ceil(bound / scale) * scale:.2g}"
