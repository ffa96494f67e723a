"""What a `dhsym latex` document shows, as sections of laid-out blocks: the DH table, each link
matrix, the derivation step by step (``--steps``), and the result with a legend of exactly
the abbreviations it uses.

Notation: c_{23} = cos(θ2 + θ3); a bar marks a subtracted angle, c_{12\\bar{4}}; when a joint
number has two digits the indices are separated by commas, c_{1,10}, and frames are always
braced, {}^{9}T_{10}. A step writes ``{}^0T_k = {}^0T_{k-1}\\,{}^{k-1}T_k``.

>>> from dhsym.io.library import load
>>> from dhsym.latex.layout import PAGES
>>> chain = load("planar2r")
>>> parts = sections(chain, 0, 2, True, PAGES["article"], LatexPrinter(chain.joint_variables))
>>> [section.title for section in parts]
['DH table', 'Link 1: ${}^{0}T_{1}$', 'Link 2: ${}^{1}T_{2}$', 'Step 1: ${}^{0}T_{2}$', 'Result: ${}^{0}T_{2}$']
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import pairwise

from ..printing.printers import LatexPrinter
from ..printing.render import latex_array, latex_table_cells, transform_title
from .layout import (
    ALIGNED_EXTRA,
    ALIGNED_ROW,
    ARRAY_ROW,
    FIRST_DISPLAY,
    LEGEND_GAP,
    NEXT_DISPLAY,
    TEXT_LINE,
    Block,
    Page,
    Rows,
    display,
    element_rows,
    matrix_items,
    paragraph,
    row_height,
    step_items,
)
from .width import math_width


@dataclass
class Section:
    """One frame's worth of content before packing (it may need several frames)."""

    part: str  # heading that groups sections in an article: "DH table", "Link matrices", …
    title: str  # frame title, LaTeX text with math in $…$
    items: list = field(default_factory=list)  # Blocks and Rows


def sections(chain, start, end, steps: bool, page: Page, printer: LatexPrinter,
             jacobian: bool = False) -> list[Section]:
    """Everything but the title, in order: table, links, steps, result with its legend."""
    path = _frame_path(chain.frames, start, end)

    def cells(i, j):
        matrix = chain.transform(i, j)
        return [[printer.doprint(matrix[r, c]) for c in range(4)] for r in range(4)]

    def title(i, j):
        return transform_title(i, j, "latex")

    out = [_table_section(chain, page)]
    for i, j in pairwise(path):
        out.append(Section("Link matrices", f"{_link_label(i, j)}: ${title(i, j)}$",
                           matrix_items(title(i, j), cells(i, j), page)))
    for k in range(2, len(path)) if steps else ():
        first, before, here = path[0], path[k - 1], path[k]
        out.append(Section("Derivation step by step", f"Step {k - 1}: ${title(first, here)}$",
                           step_items(title(first, here), f"{title(first, before)}\\,{title(before, here)}",
                                      [cells(first, before), cells(before, here)], cells(first, here), page)))
    # The result once more, with the product it comes from (when it is short) and the legend.
    product = "\\,".join(title(i, j) for i, j in pairwise(path))
    lhs = title(start, end) + (f" = {product}" if len(path) > 2 else "")
    out.append(Section("Result", f"Result: ${title(start, end)}$",
                       matrix_items(lhs, cells(start, end), page, short_lhs=title(start, end))))
    out[-1].items.extend(legend_items(printer, page))
    if jacobian:  # velocity kinematics (dhsym latex --jacobian)
        from .velocity import velocity_sections

        out.extend(velocity_sections(chain, page, steps=steps))
    return out


def _frame_path(frames, start, end) -> list:
    first, last = frames.index(start), frames.index(end)
    return frames[first:last + 1] if first < last else frames[last:first + 1][::-1]


def _link_label(i, j) -> str:
    if "base" in (i, j) or "tool" in (i, j):
        return "Base" if "base" in (i, j) else "Tool"
    return f"Link {max(i, j)}" + (" (inverse)" if i > j else "")


def _table_section(chain, page: Page) -> Section:
    """The DH table in the convention's column order, the convention, base and tool steps."""
    printer = _InlineFractions(chain.joint_variables, marked=chain.joint_variables)
    header, rows = latex_table_cells(chain, printer)
    notes = [paragraph(CONVENTION_LATEX[chain.convention], page),
             paragraph("${}^{*}$ marks the joint variable of each row.", page)]
    for which, steps, i, j in (("base", chain.base, "base", 0), ("tool", chain.tool, chain.n, "tool")):
        if steps:
            motions = "\\,".join(f"{s.kind[0]}_{{{s.kind[1]}}}({printer.doprint(s.value)})" for s in steps)
            notes.append(paragraph(f"Fixed {which} transform: ${transform_title(i, j, 'latex')} = {motions}$.", page))
    per_block = len(rows)
    if page.height_pt:  # a long table continues on the next frame
        room = page.height_pt - FIRST_DISPLAY - NEXT_DISPLAY * len(notes) - sum(n.height for n in notes)
        per_block = max(3, int((room - 3.0 - ARRAY_ROW) / ARRAY_ROW))
    items = []
    for first in range(0, len(rows), per_block):
        chunk = rows[first:first + per_block]
        items.append(display(latex_array(header, chunk),
                             3.0 + ARRAY_ROW + sum(row_height(r, array=True) for r in chunk)))
    return Section("DH table", "DH table", items + notes)


class _InlineFractions(LatexPrinter):
    """Writes -\\pi/2 where a \\frac in a table cell would be set in script size."""

    def _fraction(self, top, bottom, grouped):
        return f"({top})/{bottom}" if grouped else f"{top}/{bottom}"


CONVENTION_LATEX = {
    "standard": "Standard (distal) DH convention: "
                "${}^{i-1}T_{i} = R_{z}(\\theta_{i})\\,T_{z}(d_{i})\\,T_{x}(a_{i})\\,R_{x}(\\alpha_{i})$.",
    "modified": "Modified (proximal, Craig) DH convention: "
                "${}^{i-1}T_{i} = R_{x}(\\alpha_{i-1})\\,T_{x}(a_{i-1})\\,R_{z}(\\theta_{i})\\,T_{z}(d_{i})$.",
}


def legend_items(printer: LatexPrinter, page: Page) -> list:
    """'where c_{1} = \\cos θ_1, s_{1} = …' for exactly the abbreviations used: single angles,
    then sums of angles, each an aligned block with as many entries per row as fit (cos and
    sin of one angle side by side). A block may continue on the next frame."""
    if not printer.used:
        return []
    used = sorted(printer.used, key=lambda a: a.sort_key())
    notes = []
    if any(sign < 0 for a in used for _, sign in a.indices):
        notes.append("a bar over a joint number marks an angle that is subtracted")
    if any(a.wide for a in used):
        notes.append("commas separate the joint numbers when one of them has two digits")
    remark = f" ({'; '.join(notes)})" if notes else ""
    items: list = [Block(f"where{remark}", TEXT_LINE * (1 + len(notes)), is_display=False, keep_with_next=True,
                         alone=("Notation", f"Abbreviations{remark}:"))]
    for group in ([a for a in used if len(a.indices) == 1], [a for a in used if len(a.indices) > 1]):
        if group:
            items.append(Rows([_legend_rows(group, printer, page)], keep_with_next=True))
    items[-1].keep_with_next = False
    return items


def _legend_rows(abbreviations, printer: LatexPrinter, page: Page) -> list:
    entries = [(a.label("latex"), printer.notation.meaning(a, "latex")) for a in abbreviations]
    widest = max(math_width(f"{label} = {meaning}") for label, meaning in entries) + LEGEND_GAP
    per_row = max(1, int((page.width - ALIGNED_EXTRA + LEGEND_GAP) // widest))
    if per_row == 1:  # and a very long sum of angles breaks like a matrix element
        return [element_rows(label, meaning, page) for label, meaning in entries]
    per_row -= per_row % 2  # cos and sin of one angle on one row
    return [[(" & ".join(f"{label} &= {meaning}" for label, meaning in entries[k:k + per_row]), ALIGNED_ROW)]
            for k in range(0, len(entries), per_row)]
