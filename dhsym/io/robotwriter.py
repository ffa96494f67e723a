"""Writing a chain as a robot file that dhsym reads back to the same chain.

Numbers are written as decimals where they end (17/40 → 0.425), else as fractions; π and
square roots by name. Every value is read back through the robot-file parser before the text
is returned, so a file that would not read back the same is never written.

>>> from dhsym.io.library import load
>>> print(robot_yaml(load("planar2r")))  # doctest: +ELLIPSIS
name: "Planar elbow manipulator (2R)"
source: "..."
convention: standard
joints:
  - {joint: R, theta: theta_1, d: 0, a: a_1, alpha: 0}
  - {joint: R, theta: theta_2, d: 0, a: a_2, alpha: 0}
sample: {a_1: 0.5, a_2: 0.4}
...
>>> expression_text(sympy.Symbol("q_1") + sympy.pi / 2), expression_text(sympy.Rational(17, 40))
('q_1 + pi/2', '0.425')
"""
from __future__ import annotations

import json
import re

import sympy
from sympy.printing.str import StrPrinter

from ..errors import UserError
from .robotfile import load_robot_text

COLUMNS = {"standard": ("theta", "d", "a", "alpha"), "modified": ("alpha", "a", "d", "theta")}
_PLAIN = re.compile(r"^[\w.+\-*/() ]+$")


class _DecimalPrinter(StrPrinter):
    """sympy's str form, with terminating fractions as decimals (what a robot file says)."""

    def _print_Rational(self, expr):
        return _decimal(expr) or super()._print_Rational(expr)


def _decimal(value: sympy.Rational) -> str | None:
    """17/40 → '0.425'; None when the decimal does not end."""
    q, twos, fives = int(value.q), 0, 0
    while q % 2 == 0:
        q, twos = q // 2, twos + 1
    while q % 5 == 0:
        q, fives = q // 5, fives + 1
    if q != 1:
        return None
    places = max(twos, fives)
    digits = str(abs(int(value.p)) * 10 ** places // int(value.q)).rjust(places + 1, "0")
    text = digits if places == 0 else f"{digits[:-places]}.{digits[-places:]}"
    return ("-" if value < 0 else "") + text


def expression_text(value) -> str:
    return _DecimalPrinter({"order": "none"}).doprint(sympy.sympify(value))


def _value(value) -> str:
    text = expression_text(value)
    plain = _PLAIN.match(text) and (not text.startswith(("-", "*")) or re.match(r"^-[\w.(]", text))
    return text if plain else json.dumps(text)  # a YAML plain scalar where it reads back as written


def _string(text: str) -> str:
    """A YAML double-quoted string; characters a robot file may not hold raw (DEL, C1 controls) escaped."""
    return "".join(ch if ch.isprintable() or ch in '\n\t' else json.dumps(ch)[1:-1]
                   for ch in json.dumps(text, ensure_ascii=False))


def robot_yaml(chain, notes: str | None = None) -> str:
    """The robot file of `chain`; it reads back to the same rows, base, tool and sample."""
    lines = [f"name: {_string(chain.name)}", f"source: {_string(chain.source)}", f"convention: {chain.convention}",
             "joints:"]
    for row in chain.rows:
        fields = [f"joint: {row.joint}"] + [f"{key}: {_value(getattr(row, key))}" for key in COLUMNS[chain.convention]]
        moving = row.theta if row.joint == "R" else row.d
        if len(moving.free_symbols) > 1:
            fields.append(f"var: {row.variable.name}")
        lines.append("  - {" + ", ".join(fields) + "}")
    for key, steps in (("base", chain.base), ("tool", chain.tool)):
        if steps:
            lines.append(f"{key}: [" + ", ".join(f"{{{s.kind}: {_value(s.value)}}}" for s in steps) + "]")
    if chain.sample:
        lines.append("sample: {" + ", ".join(f"{s.name}: {_value(v)}"
                                             for s, v in sorted(chain.sample.items(), key=lambda i: i[0].name)) + "}")
    notes = chain.notes if notes is None else notes
    if notes:
        lines.append(f"notes: {_string(notes)}")
    text = "\n".join(lines) + "\n"
    _check_reads_back(text, chain)
    return text


def _check_reads_back(text: str, chain) -> None:
    """The written file must give the chain back exactly; anything else is a bug in this writer."""
    try:
        again = load_robot_text(text, "<written>").chain
    except UserError as error:
        raise AssertionError(f"written robot file does not read back: {error}") from None
    same = [(r.joint, r.theta, r.d, r.a, r.alpha, r.variable) for r in again.rows] == \
        [(r.joint, r.theta, r.d, r.a, r.alpha, r.variable) for r in chain.rows]
    if not (same and list(again.base) == list(chain.base) and list(again.tool) == list(chain.tool)):
        raise AssertionError("written robot file reads back as a different chain")
