"""The legend of a LaTeX result: exactly the abbreviations its printer has written, as
``where`` and rows of ``aligned`` (cos and sin of one angle side by side), laid out for a page.

The entries come from `printing.render.legend_entries`, the one source every surface uses.

>>> import sympy
>>> from dhsym.latex.layout import PAGES
>>> t = sympy.symbols("theta_1:3", real=True)
>>> printer = LatexPrinter(t)
>>> _ = printer.doprint(sympy.cos(t[0]) * sympy.sin(t[0] + t[1]))
>>> where, singles, sums = legend_items(printer, PAGES["snippet"])
>>> where.latex, singles.columns[0][0][0][0], sums.columns[0][0][0][0]
('where', 'c_{1} &= \\\\cos{\\\\theta_{1}}', 's_{12} &= \\\\sin(\\\\theta_{1} + \\\\theta_{2})')
"""
from __future__ import annotations

from ..printing.printers import LatexPrinter
from ..printing.render import legend_entries, legend_remarks, used_abbreviations
from .layout import ALIGNED_EXTRA, ALIGNED_ROW, LEGEND_GAP, TEXT_LINE, Block, Page, Rows, element_rows
from .width import math_width


def legend_items(printer: LatexPrinter, page: Page, heading: str = "where") -> list:
    """'where c_{1} = \\cos θ_1, s_{1} = …' for exactly the abbreviations used: single angles,
    then sums of angles, each an aligned block with as many entries per row as fit. A block may
    continue on the next frame. `heading` starts the legend (with any remarks in brackets)."""
    if not printer.used:
        return []
    remarks = legend_remarks(printer)
    remark = f" ({'; '.join(remarks)})" if remarks else ""
    colon = "" if heading == "where" else ":"
    items: list = [Block(f"{heading}{remark}{colon}", TEXT_LINE * (1 + len(remarks)), is_display=False,
                         keep_with_next=True, alone=("Notation", f"Abbreviations{remark}:"))]
    entries = dict(zip(used_abbreviations(printer), legend_entries(printer, "latex"), strict=True))
    for sums in (False, True):
        group = [entry for abbreviation, entry in entries.items() if (len(abbreviation.indices) > 1) == sums]
        if group:
            items.append(Rows([_legend_rows(group, page)], keep_with_next=True))
    items[-1].keep_with_next = False
    return items


def _legend_rows(entries, page: Page) -> list:
    widest = max(math_width(f"{label} = {meaning}") for label, meaning in entries) + LEGEND_GAP
    per_row = max(1, int((page.width - ALIGNED_EXTRA + LEGEND_GAP) // widest))
    if per_row == 1:  # and a very long sum of angles breaks like a matrix element
        return [element_rows(label, meaning, page) for label, meaning in entries]
    per_row -= per_row % 2  # cos and sin of one angle on one row
    return [[(" & ".join(f"{label} &= {meaning}" for label, meaning in entries[k:k + per_row]), ALIGNED_ROW)]
            for k in range(0, len(entries), per_row)]
