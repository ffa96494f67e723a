r"""Branches that differ only in signs, written once as a lecturer writes them on a slide: each
sign that changes from branch to branch as $\pm$ ($\mp$ where it is always the opposite of
another), with a table of the sign each branch takes.

The signs are those the solver chooses: of a square root, and of an atan2's pair (the Stanford
arm's slide, θ2 = atan2(±(x_c c1 + y_c s1), ±z_c)). The branches are compared as printed: two
belong to one family when their assignments name the same quantities in the same order and their
formulas are the same text except for the sign written just before a ``\sqrt`` or the signs of
both arguments of an atan2. A family's choices are the sign patterns over its branches (a pattern
and its opposite are one choice); each is a column of the table, headed by the name whose formula
holds its first $\pm$. Branches that differ in anything else are left to be written one by one.

>>> planar = [("elbow down", [("\\theta_{2}", "\\mathrm{atan2}(\\sqrt{1 - D^{2}}, D)", None, None)]),
...           ("elbow up", [("\\theta_{2}", "\\mathrm{atan2}(-\\sqrt{1 - D^{2}}, D)", None, None)])]
>>> [family] = families(planar)
>>> family.rows[0][1], family.columns, family.signs
('\\mathrm{atan2}(\\pm \\sqrt{1 - D^{2}}, D)', ['\\theta_{2}'], [['+'], ['-']])
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from .layout import break_points

_ROOT = re.compile(r"(?:([+-])\s*)?\\sqrt\{")  # a root and the sign written just before it
_SLOT = "\x00"


@dataclass
class Family:
    """Branches written once: `numbers` (from 1) and `names` of its branches; `rows` of
    (name, formula, (y, x) of an atan2 or None) with ± and ∓; the table's `columns` (the name
    whose formula holds each choice's first ±) and `signs`, per branch, "+" or "-" per column."""

    numbers: list[int]
    names: list[str]
    rows: list[tuple] = field(default_factory=list)
    columns: list[str] = field(default_factory=list)
    signs: list[list[str]] = field(default_factory=list)

    @property
    def mixed(self) -> bool:
        """Whether a formula holds ∓: then the table's words say what ∓ takes."""
        return any("\\mp" in row[1] for row in self.rows)


def families(branches) -> list[Family]:
    """`branches`: (name, rows) in order, each row (name, formula, (y, x) of an atan2 or None,
    the (formula, (y, x)) of atan2(−y, −x) or None), all LaTeX. The families of two or more
    branches with at least one sign that changes, in the order of their first branch; the other
    branches are left out (each is written on its own)."""
    groups: dict = {}
    for number, (name, rows) in enumerate(branches, 1):
        key = tuple((row[0], _oriented(row)[0]) for row in rows)
        groups.setdefault(key, []).append((number, name, rows))
    out = []
    for members in groups.values():
        family = _family(members) if len(members) > 1 else None
        if family is not None:
            out.append(family)
    return out


def _oriented(row) -> tuple[str, str]:
    """(the row's formula with its roots' signs taken out, "+" or "-"): of an atan2 whose pair's
    sign may change, the one of (y, x) and (−y, −x) with fewer arguments that start with a minus,
    "-" where that is (−y, −x); so that branches that differ in that sign print alike."""
    skeleton = _ROOT.sub(_SLOT, row[1])
    if row[3] is None:
        return skeleton, "+"
    options = [(_minuses(parts), _ROOT.sub(_SLOT, formula), sign)
               for formula, parts, sign in ((row[1], row[2], "+"), (*row[3], "-"))]
    if options[0][:2] == options[1][:2]:
        return skeleton, "+"
    return min(options)[1:]


def _minuses(parts) -> int:
    return sum(_ROOT.sub(_SLOT, part).startswith("-") for part in parts)


def _family(members) -> Family | None:
    """One family from its branches' printed rows, or None where no sign changes."""
    family = Family([number for number, _, _ in members], [name for _, name, _ in members])
    choices: dict = {}  # a pattern, taken with + first, -> (its column, the pattern the column's ± has)

    def symbol(label: str, pattern: tuple) -> str | None:
        if len(set(pattern)) == 1:
            return None  # the same sign in every branch: written as it is
        key = pattern if pattern[0] == "+" else _opposite(pattern)
        if key not in choices:
            choices[key] = (len(family.columns), pattern)
            family.columns.append(label)
        return "\\pm" if choices[key][1] == pattern else "\\mp"

    for position, first in enumerate(members[0][2]):
        rows = [branch_rows[position] for _, _, branch_rows in members]
        turned = [_oriented(row)[1] != _oriented(rows[0])[1] for row in rows]  # the pair's sign against branch 1's
        pair = symbol(first[0], tuple("-" if turn else "+" for turn in turned))
        if pair is not None:  # each branch's row in the orientation of branch 1's, which prints alike
            rows = [(row[0], *row[3], None) if turn else row for row, turn in zip(rows, turned, strict=True)]
        signs = [[_sign(match) for match in _ROOT.finditer(row[1])] for row in rows]
        symbols = [symbol(first[0], tuple(branch[slot] for branch in signs)) for slot in range(len(signs[0]))]
        family.rows.append(_written(rows[0], symbols, pair))
    if not family.columns:
        return None
    by_column = sorted(choices.values())
    family.signs = [[pattern[row] for _, pattern in by_column] for row in range(len(members))]
    return family


def _written(row, symbols: list, pair: str | None) -> tuple:
    """(name, formula, (y, x) or None) with the roots' ± and, where the pair's sign changes,
    atan2(±y, ±x), each argument bracketed unless it is a single term."""
    label, formula, parts = row[:3]
    parts = _split(parts, symbols)
    if pair is None:
        return label, _with_signs(formula, symbols), parts
    y, x = (f"{pair} {part}" if _single(part) else f"{pair}({part})" for part in parts)
    return label, f"\\mathrm{{atan2}}({y}, {x})", (y, x)


def _single(tex: str) -> bool:
    return not tex.startswith("-") and not any(depth == 0 for _, depth in break_points(tex))


def _sign(match: re.Match) -> str:
    return "-" if match.group(1) == "-" else "+"


def _opposite(pattern: tuple) -> tuple:
    return tuple("-" if sign == "+" else "+" for sign in pattern)


def _with_signs(formula: str, symbols: list) -> str:
    """`formula` with the root at slot k written after `symbols[k]` (None: as it is)."""
    matches = iter(symbols)

    def replace(match: re.Match) -> str:
        symbol = next(matches)
        return match.group(0) if symbol is None else f"{symbol} \\sqrt{{"

    return _ROOT.sub(replace, formula)


def _split(parts, symbols: list):
    """An atan2's (y, x) with the signs of the whole formula's slots, y's first; None where the
    parts do not hold the whole formula's roots."""
    if parts is None:
        return None
    y, x = parts
    count = len(_ROOT.findall(y))
    if count + len(_ROOT.findall(x)) != len(symbols):
        return None
    return _with_signs(y, symbols[:count]), _with_signs(x, symbols[count:])


def sign_table(family: Family, title) -> str:
    r"""The table of a family: each branch's number, the sign of each column's ±, its name
    (`title` writes a name as LaTeX text).

    >>> print(sign_table(Family([1, 2], ["up", "down"], columns=["\\theta_{2}"], signs=[["+"], ["-"]]), str))
    \begin{tabular}{rcl}
    branch & $\theta_{2}$ & \\
    \hline
    1 & $+$ & up \\
    2 & $-$ & down \\
    \end{tabular}
    """
    header = " & ".join(["branch"] + [f"${column}$" for column in family.columns]) + " &"
    lines = [f"\\begin{{tabular}}{{r{'c' * len(family.columns)}l}}", header + " \\\\", "\\hline"]
    for number, name, signs in zip(family.numbers, family.names, family.signs, strict=True):
        cells = [str(number)] + [f"${sign}$" for sign in signs] + [title(name)]
        lines.append(" & ".join(cells) + " \\\\")
    return "\n".join(lines + ["\\end{tabular}"])
