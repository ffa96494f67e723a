r"""Velocity kinematics in `dhsym latex --jacobian` and `dhsym jacobian --format latex`: the
Jacobian, its factored determinant and the singular configurations with their meaning.

The layout rules are those of the transforms: a ``bmatrix`` when the 6×n matrix fits the
line, otherwise the matrix of names ``[J_{11} … J_{6n}]`` and the elements column by column,
an element wider than the line broken before a + or −. Nothing is shrunk.

>>> import dhsym
>>> from dhsym.latex.layout import PAGES
>>> arm = dhsym.load("planar2r")
>>> [s.title for s in velocity_sections(arm, PAGES["article"])]
['Jacobian ${}^{0}J$', 'Determinant and singularities']
"""
from __future__ import annotations

from ..core.chain import Frame
from ..core.robot import Robot
from ..printing.jacobian import (
    RateLatexPrinter,
    element_name,
    jacobian_title,
    joint_label,
    point_words,
    velocity_of,
)
from ..printing.printers import LatexPrinter, chain_settings
from ..velocity import propagate, rate_symbols
from .layout import (
    PAGES,
    Block,
    Page,
    Rows,
    aligned_display,
    bmatrix,
    bmatrix_width,
    display,
    element_rows,
    lines_under,
    matrix_height,
    paragraph,
)
from .legend import legend_items
from .prose import tex_text  # not from .document, which imports this module
from .sections import Section
from .width import math_width

PART = "Velocity kinematics"
DOT_EXTRA = 2.5  # pt: a row with a dotted rate is taller than the layout's measured row


def velocity_sections(robot: Robot, page: Page, frame: Frame | None = None, point: Frame | None = None,
                      steps: bool = False) -> list[Section]:
    """The Jacobian in `frame` (the chain's; default: the first), the propagation if `steps`, the
    determinant and the singularities, with a legend of the abbreviations they use."""
    chain, numbering = robot.chain, robot.numbering
    velocity = velocity_of(robot, chain.frames[0] if frame is None else frame,
                           chain.frames[-1] if point is None else point)
    matrix, result, found = velocity.matrix, velocity.determinant, velocity.singularities
    frame, point = numbering.frame(velocity.frame), numbering.frame(velocity.point)  # as printed, from here on
    printer = RateLatexPrinter(chain.joint_variables, rate_symbols(chain), chain_settings(robot))
    title = jacobian_title(frame, point, "latex")
    out = []
    if steps:
        out.append(Section(PART, "Velocity propagation (Craig)", _propagation_items(robot, printer, page)))
    intro = paragraph(f"Geometric Jacobian of the {tex_text(point_words(point))}, expressed in frame "
                      f"{tex_text(str(frame))}; rows $v_x, v_y, v_z, \\omega_x, \\omega_y, \\omega_z$.", page)
    cells = [[printer.doprint(matrix[r, c]) for c in range(matrix.cols)] for r in range(6)]
    out.append(Section(PART, f"Jacobian ${title}$", [intro] + grid_items(title, cells, page)))
    out.append(Section(PART, "Determinant and singularities", _determinant_items(result, found, printer, page)))
    out[-1].items.extend(legend_items(printer, page))
    return out


def grid_items(lhs: str, cells, page: Page) -> list:
    """`lhs = [matrix]` when it fits the line, else the named matrix and its elements."""
    if math_width(lhs + " =") + bmatrix_width(cells, page) <= page.width:
        return [display(f"{lhs} =\n{bmatrix(cells)}", matrix_height(cells))]
    n = len(cells[0])
    names = [[element_name(r, c, n, "latex") for c in range(n)] for r in range(len(cells))]
    if math_width(lhs + " =") + bmatrix_width(names, page) > page.width:  # a 6×n of names too wide: by column
        return [Rows([[element_rows(names[r][c], cells[r][c], page) for r in range(len(cells))] for c in range(n)])]
    columns = [[element_rows(names[r][c], cells[r][c], page) for r in range(len(cells))] for c in range(n)]
    return [display(f"{lhs} =\n{bmatrix(names)}", matrix_height(names)), Rows(columns)]


def _determinant_items(result, found, printer: LatexPrinter, page: Page) -> list:
    items = []
    if result.value is not None:
        label = "\\det J" if result.block == "J" else "\\det J_{\\mathrm{block}}"
        items.append(Rows([[element_rows(label, printer.doprint(result.value), page)]]))
    if result.note:
        items.append(paragraph(tex_text(result.note), page))
    label = joint_label(printer)
    for singularity in found:
        items.append(paragraph(f"${printer.doprint(singularity.factor)} = 0$: "
                               f"{tex_text(singularity.describe(label))}.", page))
    if result.value is not None and not found:
        items.append(paragraph("No factor has a joint variable: the block is never singular."
                               if result.value != 0 else "Identically zero: singular everywhere.", page))
    return items


def _propagation_items(robot: Robot, printer: LatexPrinter, page: Page) -> list:
    columns = []
    for step in propagate(robot.chain):
        shown = robot.numbering.frame(step.frame)
        frame = f"\\mathrm{{{shown}}}" if isinstance(shown, str) else str(shown)
        column = []
        for symbol, vector in (("\\omega", step.omega), ("v", step.velocity)):
            for axis, x in zip("xyz", vector):
                rows = element_rows(f"{{}}^{{{frame}}}{symbol}_{{{frame},{axis}}}", printer.doprint(x), page)
                column.append([(tex, height + DOT_EXTRA * ("\\dot" in tex)) for tex, height in rows])
        columns.append(column)
    note = paragraph("Craig's outward iteration: each frame's $\\omega$ and $v$ in that frame; the coefficients of "
                     "the joint rates in the last frame are the columns of $J$ there.", page)
    return [note, Rows(columns)]


def snippet(robot: Robot, frame: Frame, point: Frame, steps: bool = False) -> str:
    """The math of `velocity_sections` for a document with amsmath (`dhsym jacobian --format latex`)."""
    out = []
    for section in velocity_sections(robot, PAGES["snippet"], frame, point, steps):
        out.append(f"% {section.title}")
        for item in section.items:
            block = item if isinstance(item, Block) else aligned_display(lines_under(item.columns, 0), "align*")
            out.append(block.latex if block.is_display else f"% {' '.join(block.latex.split())}")
    return "\n".join(out) + "\n"
