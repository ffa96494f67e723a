"""Spellings that are valid but almost certainly not what the student meant.

Each check returns the text of a warning (the caller adds the file, line and column), or None.
They catch the slips that silently change the kinematics: a misspelt π becomes a new symbol,
a Cyrillic letter that looks like θ or a makes a second symbol that prints like the first,
`1.5708` is not π/2, and `l1` and `l_1` are two symbols that print the same.

>>> misspelt_pi("pi2"), misspelt_pi("Pi"), misspelt_pi("pin")
("'pi2' is a new symbol, not π; did you mean pi/2?", "'Pi' is a new symbol, not π; did you mean pi?", None)
>>> near_multiple_of_pi(sympy.Rational(15708, 10000), 4)
'1.5708 is not exactly π/2; did you mean pi/2?'
>>> printed_key("theta_1") == printed_key("θ1") == printed_key("theta1")
True
"""
from __future__ import annotations

import difflib
import re
import unicodedata

import sympy
from sympy.printing.conventions import split_super_sub
from sympy.printing.pretty.pretty_symbology import greek_unicode

from ..core.grid import DOUBLE_DIGITS, Snaps, exact_number, grid_angle
from ..core.numbers import decimal_text

_PI_SPELLING = re.compile(r"(?i:pi|π|Π)_?(\d*)")
_SUPERSCRIPT = re.compile(r"[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺]")
_NUMBER_THEN_NAME = re.compile(r"(?<![\w.])(\d+(?:\.\d*)?|\.\d+)(\s*)([^\W\d]\w*)")
_NOT_A_NAME = re.compile(r"[eE][+-]?\d|[eE]\Z|[xXoObB][\da-fA-F]*\Z")  # 1e3, 0x1f: Python's own numbers
DECIMAL_COMMA = re.compile(r"\s*-?\d+,\d+\s*")
DEGREE_LOOKING = {15, 30, 45, 60, 90, 120, 135, 150, 180, 270, 360}  # angles that are degrees when written bare
_RADIANS = ("rad", "rads", "radian", "radians")
# Letters of other scripts that look like Latin or Greek ones, with the letter they pass for.
LOOKALIKES = {
    # Cyrillic
    "а": "a", "е": "e", "о": "o", "р": "p", "с": "c", "у": "y", "х": "x", "і": "i", "ј": "j",
    "ѕ": "s", "ԁ": "d", "ԛ": "q", "ԝ": "w", "һ": "h", "ӏ": "l", "ѵ": "v", "ѳ": "θ", "Ѳ": "θ", "п": "π",
    "ф": "φ", "Ф": "Φ", "к": "κ", "ѡ": "ω", "ѱ": "ψ", "Ѱ": "Ψ", "А": "A", "В": "B", "Е": "E", "К": "K",
    "М": "M", "Н": "H", "О": "O", "Р": "P", "С": "C", "Т": "T", "Х": "X", "І": "I", "Ј": "J", "Ѕ": "S",
    "П": "Π", "Г": "Γ", "Л": "Λ", "Ѡ": "Ω", "У": "Y", "Ԛ": "Q", "Ԝ": "W",
    # Armenian
    "օ": "o", "ո": "n", "ս": "u", "հ": "h", "ց": "g",
    # Greek capitals and omicron that pass for Latin letters (no DH table means Greek Alpha by "Α")
    "Α": "A", "Β": "B", "Ε": "E", "Ζ": "Z", "Η": "H", "Ι": "I", "Κ": "K", "Μ": "M", "Ν": "N", "Ο": "O",
    "Ρ": "P", "Τ": "T", "Υ": "Y", "Χ": "X", "ο": "o",
}


def why_unreadable(text: str) -> tuple[str, int] | None:
    """(message, column) for text Python cannot read because of a usual slip, else None.

    >>> why_unreadable("30dg"), why_unreadable("2pi")
    (('write 30deg (or 30°) for degrees', 0), ('a number followed by a name: write 2*pi for a product', 0))
    """
    superscript = _SUPERSCRIPT.search(text)
    if superscript:
        return f"superscript {superscript.group(0)} is not allowed; write a power with ^, as in l_1^2", \
            superscript.start()
    for match in _NUMBER_THEN_NAME.finditer(text):
        number, name = match.group(1), match.group(3)
        if not name[0].isalpha() or _NOT_A_NAME.match(name):
            continue
        if name.lower() in _RADIANS:
            return f"angles are in radians already: write {number}, or {number}deg for degrees", match.start()
        if difflib.get_close_matches(name.lower(), ["deg", "degree", "degrees"], n=1, cutoff=0.6):
            return f"write {number}deg (or {number}°) for degrees", match.start()
        return f"a number followed by a name: write {number}*{name} for a product", match.start()
    if DECIMAL_COMMA.fullmatch(text):
        return f"write decimals with a point: {text.strip().replace(',', '.')}, not {text.strip()}", \
            len(text) - len(text.lstrip())
    return None


def misspelt_pi(name: str) -> str | None:
    """`Pi`, `PI`, `pi2`, `π2`, `Π` are new symbols, not π."""
    match = _PI_SPELLING.fullmatch(name)
    if not match or name in ("pi", "π"):
        return None
    digits = match.group(1)
    spelling = "π" if name[0] in "πΠ" else "pi"
    hint = f"{spelling}/{digits}" if digits else spelling
    return f"{name!r} is a new symbol, not π; did you mean {hint}?"


def lookalike_letters(name: str) -> str | None:
    """A name with a letter of another script that passes for a Latin or Greek one (Cyrillic Ѳ, а)."""
    strangers = [ch for ch in name if ch in LOOKALIKES]
    if not strangers:
        return None
    ch = strangers[0]
    script = unicodedata.name(ch, "").split(" ")[0].capitalize() or "another script's"
    meant = "".join(LOOKALIKES.get(c, c) for c in name)
    kind = "Greek" if LOOKALIKES[ch] in greek_unicode.values() else "Latin"
    return (f"{name}: {ch} is the {script} letter U+{ord(ch):04X}, not the {kind} {LOOKALIKES[ch]}; "
            f"{name} is a new symbol, not {meant}")


def near_multiple_of_pi(value: sympy.Expr, places: int) -> str | None:
    """A decimal angle within rounding of a multiple of π/12, such as 1.5708 or 0.7854.

    Only decimals with at least two places are judged, and "within rounding" allows one unit
    in the last written place (1.5707, a truncated π/2, is caught too).
    """
    if places < 2 or not value.is_Rational or value == 0:
        return None
    steps = sympy.Integer(round(float(value) / (float(sympy.pi) / 12)))
    if steps == 0 or abs(steps) > 48:
        return None
    if abs(float(value) - float(steps * sympy.pi / 12)) > 10.0 ** -places:
        return None
    angle = steps * sympy.pi / 12
    return f"{decimal_text(value)} is not exactly {_pi_text(angle, 'π')}; did you mean {_pi_text(angle, 'pi')}?"


def decimal_angle(value: sympy.Expr, decimals: list, places: int, snaps: Snaps) -> tuple[sympy.Expr, str | None]:
    """A robot file's constant angle as the file means it, and the warning it gets, if any.
    `decimals`: the (literal, place) of the decimals written in the field, `places` the most places.
    The file's decimals are its own (1.5708 gets a "did you mean pi/2?"), except a lone one that is
    a multiple of π/12 to a double's precision (core.grid): that is the multiple, kept in `snaps`.

    >>> decimal_angle(sympy.Rational("-1.570796326794897"), [("1.570796326794897", "arm.yaml:5:24")], 15, Snaps())
    (-pi/2, None)
    >>> decimal_angle(sympy.Rational("1.5708"), [("1.5708", "arm.yaml:5:23")], 4, Snaps())
    (3927/2500, '1.5708 is not exactly π/2; did you mean pi/2?')
    """
    if not decimals:
        return value, None
    if value.is_Rational and len(decimals) == 1:
        literal, where = decimals[0]
        try:
            multiple = grid_angle(literal, DOUBLE_DIGITS, tolerance=0)
        except ValueError:  # not a plain decimal (1_000.5): nothing to read as a multiple
            multiple = None
        if multiple is not None and abs(value) == exact_number(literal):
            snaps.add(literal, multiple, where)
            return sympy.sign(value) * multiple, None
    return value, near_multiple_of_pi(value, places)


def looks_like_degrees(value: sympy.Expr) -> bool:
    """Whether an angle is a whole number of degrees that people write, such as 90 or -180.

    >>> looks_like_degrees(sympy.Integer(-90)), looks_like_degrees(sympy.Integer(2))
    (True, False)
    """
    return value.is_Integer and abs(int(value)) in DEGREE_LOOKING


def _pi_text(angle: sympy.Expr, pi: str) -> str:
    """k π/12 as written in a robot file: pi/2, -pi/2, 5*pi/12, 2*pi."""
    ratio = angle / sympy.pi
    sign = "-" if ratio < 0 else ""
    p, q = abs(ratio.p), ratio.q
    text = pi if p == 1 else f"{p}*{pi}"
    return sign + (text if q == 1 else f"{text}/{q}")


def printed_key(name: str) -> tuple:
    """What a name prints as, ignoring how it was spelt: theta_1, theta1 and θ1 all print θ1."""
    base, supers, subs = split_super_sub(name)
    base = _GREEK_NAMES.get(base, base)
    return base, tuple(s.strip("{}") for s in subs), tuple(s.strip("{}") for s in supers)


def printed_text(name: str) -> str:
    """The name as the text output prints it: theta_1 -> θ1 (the same rule as dhsym.printing)."""
    base, subs, supers = printed_key(name)
    return greek_unicode.get(base, base) + "".join(subs) + "".join("^" + s for s in supers)


_GREEK_NAMES = {letter: word for word, letter in greek_unicode.items()}  # 'θ' -> 'theta'


def misplaced_variable(joint: str, column: str, name: str, named_var: bool) -> str | None:
    """Why `name` in `column` (theta or d) of a `joint` (R or P) row reads as a joint variable
    in the wrong column, or None. `named_var`: the row names its variable with var, which
    settles the question. θ and q name joint angles, q any joint variable; d_1 in d of a
    revolute row is an offset, and a subscript 0 marks a constant (theta_0).

    >>> print(misplaced_variable("P", "theta", "theta_1", False)[:89])
    theta_1 looks like a joint variable, but joint: P (prismatic) moves along d and keeps the
    >>> misplaced_variable("P", "theta", "theta_0", False), misplaced_variable("R", "d", "d_1", False)
    (None, None)
    """
    if named_var:
        return None
    base, subs, _ = printed_key(name)
    if subs and subs[0] in ("0", "00", "off", "offset"):
        return None
    kind, other = ("P (prismatic)", "R") if joint == "P" else ("R (revolute)", "P")
    motion = "moves along d and keeps theta constant" if joint == "P" else "turns about z and keeps d constant"
    moving, verb = ("d", "turns") if joint == "P" else ("theta", "slides")
    if column != moving and (base == "q" or (joint == "P" and base == "theta")):
        return (f"{name} looks like a joint variable, but joint: {kind} {motion}; write joint: {other} if this "
                f"joint {verb}, or move the variable to {moving} (or name it with var to keep {name} a constant)")
    if column == moving and base == ("theta" if joint == "P" else "d"):
        named = "an angle" if joint == "P" else "a length along z"
        return (f"{name} is named like {named}, but joint: {kind} {motion[:motion.index(' and')]}; write "
                f"joint: {other} and put {name} in {'theta' if joint == 'P' else 'd'} if this joint {verb}, "
                f"or name it with var to keep it here")
    return None
