"""A solver's sentences (conditions, degenerate poses, the method) in the printers' notation:
the relations they start with as math, the names and sums of names they mention as math, and
lines wrapped so that no relation is cut in two.

>>> import dhsym
>>> from dhsym.printing.ik import text_printer
>>> printer = text_printer(dhsym.load("planar2r"))
>>> text_sentence("-px + a_1 = 0 and py = 0: theta_1 is not determined", ["px", "py", "a_1", "theta_1"], printer)
'px − a1 = 0 and py = 0: θ1 is not determined'
"""
from __future__ import annotations

import re

from ..errors import UserError
from ..io.expr import parse_expression, real_symbol
from . import render

_RELATION = re.compile(r"^(.+?)\s*(>=|<=|!=|=|>|<)\s*(.+)$")
_NAME = r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)?ʹ*"  # ʹ: a prime of the derivation's (dhsym.inverse.fresh)
_TERM = rf"(?:(?:sin|cos)\([^()]*\)|{_NAME}(?![\w(]))"
_MATH_RUN = re.compile(rf"(?<![\w.'’]){_TERM}(?: [+-] {_TERM})*")  # theta_2 + theta_3, sin(theta_5); not Pieper's s
_VALUE = re.compile(r"(?<== )-?(?:\d+(?:\.\d+)?|pi)(?![\w.])")  # "r32 = -1", "theta_5 = pi": math
_GLUE = "\u00a0"  # holds a relation together while a sentence is wrapped
RELATIONS = {"text": {">=": " ≥ ", "<=": " ≤ ", "!=": " ≠ ", "=": " = ", ">": " > ", "<": " < "},
             "latex": {">=": " \\geq ", "<=": " \\leq ", "!=": " \\neq ", "=": " = ", ">": " > ", "<": " < "}}


def sentence_parts(text: str, names) -> list:
    """A solver's sentence ("1 - D**2 >= 0 (else …)", "a_3 = 0 and d_4 = 0: theta_3 is not
    determined") as parts to print: ("relation", lhs, operator, rhs) for each relation it starts
    with (up to a colon or a bracket), read by dhsym's safe parser, and ("words", text, math) for
    the rest, where `math` lists (start, end, expression) for the names, sums of names and sines
    and cosines of them that the words mention (theta_2 + theta_3, sin(theta_5)), each printed
    as math. A sentence that starts with no relation stays words.

    >>> sentence_parts("1 - D**2 >= 0 (else no branch)", ["D"])[0]
    ('relation', 1 - D**2, '>=', 0)
    >>> sentence_parts("only theta_4 + theta_6 is determined; the factor sin(theta_5)", ["theta_4", "theta_5",
    ...                "theta_6"])[0][2]
    [(5, 22, theta_4 + theta_6), (49, 61, sin(theta_5))]
    """
    cuts = [len(text)] + [m.start() for m in re.finditer(r": | \(", text)]
    for cut in sorted(set(cuts)):
        relations = _relations(text[:cut])
        if relations:
            rest = text[cut:]
            return relations + ([("words", rest, _mentioned(rest, names))] if rest else [])
    return [("words", text, _mentioned(text, names))]


def _relations(math: str) -> list:
    """[("relation", lhs, operator, rhs), ("words", " and ", []), …] for `math`, or [] if it is not
    a conjunction of relations the safe parser reads."""
    parts = []
    for clause in math.split(" and "):
        match = _RELATION.match(clause.strip())
        try:
            sides = [parse_expression(match.group(1)), parse_expression(match.group(3))] if match else None
        except UserError:
            sides = None
        if sides is None:
            return []
        if parts:
            parts.append(("words", " and ", []))
        parts.append(("relation", sides[0], match.group(2), sides[1]))
    return parts


def _mentioned(text: str, names) -> list:
    """(start, end, expression) for each run of math in `text` that names only the chain's and the
    solution's names: a name, a sum of them, sin or cos of them; and each number after `= `."""
    wanted, found = set(names), []
    for match in _VALUE.finditer(text):
        found.append((match.start(), match.end(), parse_expression(match.group(0))))
    for match in _MATH_RUN.finditer(text):
        used = {m.group(0) for m in re.finditer(_NAME, match.group(0))}
        if not used - {"sin", "cos"} or not used - {"sin", "cos"} <= wanted:
            continue
        try:
            expression = parse_expression(match.group(0))
        except UserError:
            continue
        found.append((match.start(), match.end(), expression.xreplace({s: real_symbol(s.name)
                                                                         for s in expression.free_symbols})))
    return sorted(found, key=lambda run: run[0])


def solution_names(solution) -> list[str]:
    """The names a solver's sentence may mention: the chain's symbols, the definitions', the target's."""
    return ([s.name for s in solution.chain.symbols] + [name.name for name, _ in solution.definitions]
            + [s.name for s in solution.target_symbols])


def text_sentence(text: str, names, printer) -> str:
    """A solver's sentence in the printer's notation: '1 − D² ≥ 0', 's5 = 0: only θ4 + θ6 is determined'."""
    out = []
    with printer.numbers_read_back():
        for part in sentence_parts(text, names):
            if part[0] == "relation":
                out.append(relation(part, printer, "text"))
            else:
                out.append(_math_printed(part[1], part[2], printer))
    return "".join(out)


def _math_printed(text: str, math, printer) -> str:
    """`text` with each run of math in `math` as the printer writes it: sin(theta_5) -> s5."""
    out, position = [], 0
    for start, end, expression in math:
        out += [text[position:start], printer.doprint(expression)]
        position = end
    return "".join(out) + text[position:]




def relation(part, printer, style: str) -> str:
    """A ("relation", lhs, operator, rhs) part in the printer's notation. An equation to zero
    starts with a plus, as a book writes it: `px − b = 0`, not `−px + b = 0`."""
    _, lhs, operator, rhs = part
    left = printer.doprint(lhs)
    if rhs == 0 and operator in ("=", "!=") and left[:1] in "−-":
        flipped = printer.doprint(-lhs)
        left = left if flipped[:1] in "−-" else flipped
    return left + RELATIONS[style][operator] + printer.doprint(rhs)


def wrap_sentence(text: str, width: int, indent: str) -> str:
    """A printed sentence wrapped at `width` without cutting a relation between its sides
    (`pz = 0` stays on one line).

    >>> print(wrap_sentence("in every pose r13 = 0, r23 = 0", 20, "  "))
    in every pose
      r13 = 0, r23 = 0
    """
    glued = re.sub(r" (=|≥|≤|≠|>|<|>=|<=|!=) (?=\S)", lambda m: f"{_GLUE}{m.group(1)}{_GLUE}", text)
    return render.wrap(glued, width, indent).replace(_GLUE, " ")
