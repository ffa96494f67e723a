r"""Free text of a robot file (name, source, notes) as LaTeX text that always compiles, with
the identifiers a lecture writes in prose set as math: ``a_2`` as $a_{2}$, ``theta_3`` as
$\theta_{3}$, ``3T_Tool`` as ${}^{3}T_{\mathrm{Tool}}$, ``{2}T_S1`` as ${}^{2}T_{\mathrm{S1}}$.

An identifier is a name of one or two letters, or a Greek letter's name, with a short
subscript (``d_6``, ``alpha_{i-1}``), or a transform between two frames written with a T. Other
words with underscores (``planar_test``) stay text.

>>> tex_prose("a_2 and d_6 of 3T_Tool, {2}T_S1 and 0T3; theta_1 = 90deg")
'$a_{2}$ and $d_{6}$ of ${}^{3}T_{\\mathrm{Tool}}$, ${}^{2}T_{\\mathrm{S1}}$ and ${}^{0}T_{3}$; $\\theta_{1}$ = 90deg'
"""
from __future__ import annotations

import re
import unicodedata

from ..printing.names import GREEK_NAMES, display_name, greek_latex

_SIDE = r"(?:\{(\w{1,8})\}|(\d{1,2}))"
_TRANSFORM = re.compile(r"(?<![\w{}])" + _SIDE + r"T_?(?:\{(\w{1,8})\}|([A-Za-z]\w{0,7}|\d{1,2}))(?![\w{])")
_LETTER_TRANSFORM = re.compile(r"(?<![\w{}])([A-Z])T_(\w{1,8})(?!\w)")
_IDENTIFIER = re.compile(r"(?<![\w\\{}])([A-Za-z]+)_(\{[\w,+\- ]{1,8}\}|[A-Za-z0-9]{1,3})(?![\w{])")

_TEXT_ESCAPES = {"\\": "\\textbackslash{}", "&": "\\&", "%": "\\%", "$": "\\$", "#": "\\#", "_": "\\_",
                 "{": "\\{", "}": "\\}", "~": "\\textasciitilde{}", "^": "\\textasciicircum{}",
                 "−": "$-$", "→": "$\\to$", "×": "$\\times$", "±": "$\\pm$", "≤": "$\\leq$", "≥": "$\\geq$",
                 "≈": "$\\approx$", "°": "\\textdegree{}", "…": "\\dots{}", "–": "--", "—": "---",
                 "‘": "`", "’": "'", "“": "``", "”": "''"}


def tex_text(text: str) -> str:
    """Free text as LaTeX text, every character escaped.

    >>> tex_text("θ1 & 50% of a_2 — Craig")
    '$\\\\theta$1 \\\\& 50\\\\% of a\\\\_2 --- Craig'
    """
    out = []
    for ch in text:
        if ch in _TEXT_ESCAPES:
            out.append(_TEXT_ESCAPES[ch])
        elif ch in GREEK_NAMES:
            tex = greek_latex(GREEK_NAMES[ch])
            out.append(f"${tex}$" if tex.startswith("\\") else tex)
        elif ch.isascii() or unicodedata.name(ch, "").startswith("LATIN"):
            out.append(ch if ch.isprintable() else " ")
        else:
            out.append("?")  # a symbol pdflatex's default fonts may lack
    return "".join(out)


def tex_prose(text: str) -> str:
    """Free text as LaTeX text with its identifiers and transforms set as math; a line may
    break after a slash (file names)."""
    out, position = [], 0
    for start, end, math in _math_spans(text):
        out += [_breakable(text[position:start]), f"${math}$"]
        position = end
    return "".join(out) + _breakable(text[position:])


def _breakable(text: str) -> str:
    return tex_text(text).replace("/", "/\\allowbreak{}")


def _math_spans(text: str) -> list[tuple[int, int, str]]:
    spans = []
    for match in _TRANSFORM.finditer(text):
        spans.append((match.start(), match.end(), _transform(match.group(1) or match.group(2),
                                                             match.group(3) or match.group(4))))
    for match in _LETTER_TRANSFORM.finditer(text):
        spans.append((match.start(), match.end(), _transform(match.group(1), match.group(2))))
    for match in _IDENTIFIER.finditer(text):
        base, subscript = match.group(1), match.group(2).strip("{}")
        if len(base) <= 2 or base in GREEK_NAMES.values():
            spans.append((match.start(), match.end(), display_name(f"{base}_{{{subscript}}}", "latex")
                          if "," in subscript or " " in subscript else display_name(match.group(0), "latex")))
    spans.sort()
    kept, end = [], -1
    for span in spans:  # the first of overlapping matches wins
        if span[0] >= end:
            kept.append(span)
            end = span[1]
    return kept


def _transform(left: str, right: str) -> str:
    def side(frame: str) -> str:
        return frame if frame.isdigit() else f"\\mathrm{{{frame}}}"

    return f"{{}}^{{{side(left)}}}T_{{{side(right)}}}"
