"""What a `dhsym latex` document shows, as sections of laid-out blocks: the DH table, the
notation (the convention and a legend of exactly the abbreviations the document uses, before
the first product), the link matrices (several to a frame, side by side where they fit), the
derivation step by step (``--steps``), and the result.

Notation: c_{23} = cos(θ2 + θ3); a bar marks a subtracted angle, c_{12\\bar{4}}; when a joint
number has two digits the indices are separated by commas, c_{1,10}, and frames are always
braced, {}^{9}T_{10}. A step writes ``{}^0T_k = {}^0T_{k-1}\\,{}^{k-1}T_k``; with steps, the
last one is the result.

>>> from dhsym.io.library import load
>>> from dhsym.latex.layout import PAGES
>>> arm = load("planar3r")
>>> parts = sections(arm, 0, 3, True, PAGES["article"], LatexPrinter(arm.chain.joint_variables))
>>> [section.title for section in parts]
['DH table', 'Notation', 'Link matrices', 'Step 1: ${}^{0}T_{2}$', 'Result: ${}^{0}T_{3}$']
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import pairwise

from ..core.chain import Frame
from ..core.robot import Robot
from ..printing.printers import LatexPrinter, chain_settings
from ..printing.render import latex_table_cells, transform_title
from .layout import (
    ARRAY_ROW,
    FIRST_DISPLAY,
    NEXT_DISPLAY,
    TEXT_CHARACTER,
    Page,
    bmatrix_width,
    display,
    matrix_items,
    paragraph,
    step_items,
)
from .legend import legend_items
from .tables import product_display, table_items
from .width import math_width

SIDE_BY_SIDE_GAP = "\\qquad"


@dataclass
class Section:
    """One frame's worth of content before packing (it may need several frames)."""

    part: str  # heading that groups sections in an article: "DH table", "Link matrices", …
    title: str  # frame title, LaTeX text with math in $…$
    items: list = field(default_factory=list)  # Blocks and Rows
    headed: bool = False  # an article prints the title too, under its part's heading


def sections(robot: Robot, start: Frame, end: Frame, steps: bool, page: Page, printer: LatexPrinter) -> list[Section]:
    """Everything but the title, in order: table, notation, links, steps, result; `start`, `end`
    are the chain's own frames (0..n), titled with the robot's numbers."""
    chain, numbering = robot.chain, robot.numbering
    path = _frame_path(chain.frames, start, end)

    def cells(i, j):
        matrix = chain.transform(i, j)
        return [[printer.doprint(matrix[r, c]) for c in range(4)] for r in range(4)]

    def title(i, j):
        return transform_title(numbering.frame(i), numbering.frame(j), "latex")

    links = []
    for i, j in pairwise(path):
        link = cells(i, j)
        width = math_width(title(i, j) + " =") + bmatrix_width(link, page)
        links.append((matrix_items(title(i, j), link, page), title(i, j), width))
    out = [_table_section(robot, page), Section("Link matrices", "Link matrices", _side_by_side(links, page))]
    last = len(path) - 1
    for k in range(2, last + 1) if steps else ():
        first, before, here = path[0], path[k - 1], path[k]
        heading = "Result" if k == last else f"Step {k - 1}"
        out.append(Section("Derivation step by step" if k < last else "Result", f"{heading}: ${title(first, here)}$",
                           step_items(title(first, here), f"{title(first, before)}\\,{title(before, here)}",
                                      [cells(first, before), cells(before, here)], cells(first, here), page)))
    if not steps or last < 2:  # the result with the product it comes from (when it is short)
        product = "\\,".join(title(i, j) for i, j in pairwise(path))
        lhs = title(start, end) + (f" = {product}" if len(path) > 2 else "")
        out.append(Section("Result", f"Result: ${title(start, end)}$",
                           matrix_items(lhs, cells(start, end), page, short_lhs=title(start, end))))
    out.insert(1, _notation_section(chain.convention, printer, page))  # now that every abbreviation is known
    return out


def _frame_path(frames, start, end) -> list:
    first, last = frames.index(start), frames.index(end)
    return frames[first:last + 1] if first < last else frames[last:first + 1][::-1]


def _table_section(robot: Robot, page: Page) -> Section:
    """The DH table in the convention's column order, base and tool steps."""
    chain = robot.chain
    printer = _InlineFractions(chain_settings(robot), marked=chain.joint_variables)
    header, rows = latex_table_cells(robot, printer)
    notes = [paragraph("${}^{*}$ marks the joint variable of each row.", page)]
    for which, steps, i, j in (("base", chain.base, "base", 0), ("tool", chain.tool, chain.n, "tool")):
        if steps:
            factors = [f"{s.kind[0]}_{{{s.kind[1]}}}({printer.doprint(s.value)})" for s in steps]
            shown = transform_title(robot.numbering.frame(i), robot.numbering.frame(j), "latex")
            product = "\\,".join(factors)
            lead = f"Fixed {which} transform: "
            if len(lead) * TEXT_CHARACTER + math_width(f"{shown} = {product}.") <= page.width:
                notes.append(paragraph(f"{lead}${shown} = {product}$.", page))
            else:  # too wide for a line of text: the product as a display, broken between factors
                lead_in = paragraph(f"Fixed {which} transform:", page)
                lead_in.keep_with_next = True
                notes += [lead_in, product_display(shown, factors, page)]
    per_block = len(rows)
    if page.height_pt:  # a long table continues on the next frame
        room = page.height_pt - FIRST_DISPLAY - NEXT_DISPLAY * len(notes) - sum(n.height for n in notes)
        per_block = max(3, int((room - 3.0 - ARRAY_ROW) / ARRAY_ROW))
    items = table_items(header, rows, page, per_block)
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


def _notation_section(convention: str, printer: LatexPrinter, page: Page) -> Section:
    """The convention and the legend of every abbreviation the document uses."""
    items = [paragraph(CONVENTION_LATEX[convention], page)]
    items += legend_items(printer, page, heading="Abbreviations")
    return Section("Notation", "Notation", items)


def _side_by_side(links: list[tuple[list, str, float]], page: Page) -> list:
    """The link matrices' blocks, (items, title, width in em), two displays on one line where
    both fit it."""
    out: list = []
    beside = None  # (block, width) that the next matrix may join
    for items, title, width in links:
        if len(items) > 1:  # named elements: never beside another
            items[0].shows = (title,)
            out.extend(items)
            beside = None
            continue
        block = items[0]
        if beside and beside[1] + math_width(SIDE_BY_SIDE_GAP) + width <= page.width:
            left = beside[0]
            out[-1] = display(f"{left.math} {SIDE_BY_SIDE_GAP}\n{block.math}", max(left.height, block.height),
                              shows=left.shows + (title,))
            beside = None
            continue
        out.append(display(block.math, block.height, shows=(title,)))
        beside = (out[-1], width)
    return out
