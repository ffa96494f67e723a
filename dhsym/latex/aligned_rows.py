r"""Rows of equations under one alignment, as the dynamics and its derivation lay them out: each
`left = right` a line of ``aligned``, the right side broken before a + or − to the room the widest
left side leaves, and each row as tall as its dots and stacked scripts make it.

>>> from dhsym.latex.layout import PAGES
>>> rows = aligned_rows([[("d_{11}", "I_{1} + m_{1}"), ("\\phi_{1}", "g m_{1}")]], PAGES["article"])
>>> [row for element in rows.columns[0] for row, _ in element]
['d_{11} &= I_{1} + m_{1}', '\\phi_{1} &= g m_{1}']
"""
from __future__ import annotations

from .layout import ALIGNED_EXTRA, Page, Rows, break_lines, row_height
from .width import math_width

DOT_EXTRA = 2.5  # pt: a row with a dotted rate is taller than the layout's measured row
SCRIPT_EXTRA = 2.0  # pt: and one with a squared subscripted name, c_{23}^{2} (measured: PUMA slides)


def aligned_rows(columns, page: Page) -> Rows:
    """Columns of (left, right) pairs as the rows of `aligned`, each right side broken before a + or
    − to the room the widest left side leaves (one `aligned` aligns them all at =)."""
    widest = max(math_width(left + " =") for column in columns for left, _ in column)
    room = page.width - widest - ALIGNED_EXTRA
    out = []
    for column in columns:
        elements = []
        for left, right in column:
            lines = break_lines(right, room, room - 1.0, display=True)
            rows = [f"{left} &= {lines[0]}"] + [f"&\\quad {{}}{line}" for line in lines[1:]]
            elements.append([(row, row_height([row], array=False) + taller(row)) for row in rows])
        out.append(elements)
    return Rows(out)


def taller(tex: str) -> float:
    """What a row of the dynamics needs beyond the layout's measured row: dots, stacked scripts."""
    return DOT_EXTRA * ("\\dot" in tex) + SCRIPT_EXTRA * ("}^{" in tex)
