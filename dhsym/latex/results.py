r"""Transforms as LaTeX to paste into a document (``dhsym fk/links --format latex``), laid out
by the documents' rule for a given text width: a matrix that fits is a ``bmatrix``, a wider
one is the matrix of names and its elements in ``align*`` (long ones broken), and the legend
follows as ``where`` and rows of ``align*``. Needs ``amsmath``.

>>> from dhsym.io.library import load
>>> arm = load("planar2r")
>>> print(results_latex(arm, [(0, 1, arm.chain.link(1))]))  # doctest: +ELLIPSIS
\[
{}^{0}T_{1} =
\begin{bmatrix}
c_{1} & -s_{1} & 0 & a_{1} c_{1} \\
...
where
\begin{align*}
c_{1} &= \cos{\theta_{1}} & s_{1} &= \sin{\theta_{1}}
\end{align*}
"""
from __future__ import annotations

from ..core.robot import Robot
from ..printing.printers import LatexPrinter, chain_settings
from ..printing.render import latex_printer, latex_table_cells, transform_title
from .layout import PAGES, Page, flat, matrix_items
from .legend import legend_items
from .tables import table_items

ARTICLE_TEXT_WIDTH_PT = PAGES["snippet"].width_pt  # a standard `article` at 10 pt


def results_latex(robot: Robot, results, text_width_pt: float = ARTICLE_TEXT_WIDTH_PT) -> str:
    """(i, j, matrix) results of a robot, i and j the chain's frames, as displays that fit
    `text_width_pt` at 10 pt, titled with the printed frame numbers."""
    page = Page(text_width_pt, PAGES["snippet"].font_pt)
    printer = LatexPrinter(chain_settings(robot))  # decimals and offsets as the file wrote them
    parts = []
    for i, j, matrix in results:
        cells = [[printer.doprint(matrix[r, c]) for c in range(4)] for r in range(4)]
        title = transform_title(robot.numbering.frame(i), robot.numbering.frame(j), "latex")
        parts.append("\n".join(block.latex for block in flat(matrix_items(title, cells, page))))
    legend = flat(legend_items(printer, page))
    return "\n\n".join(parts + (["\n".join(block.latex for block in legend)] if legend else []))


def table_latex(robot: Robot, text_width_pt: float = ARTICLE_TEXT_WIDTH_PT) -> str:
    r"""The DH table (``dhsym table --format latex``) as displays that fit `text_width_pt`: one
    array, or arrays of columns, or each row's parameters by name (see `tables`).

    >>> from dhsym.io.library import load
    >>> print(table_latex(load("planar2r")).splitlines()[:3])
    ['\\[', '\\begin{array}{c|cccc}', 'i & \\theta_i & d_i & a_i & \\alpha_i \\\\']
    """
    page = Page(text_width_pt, PAGES["snippet"].font_pt)
    header, rows = latex_table_cells(robot, latex_printer(robot, marked=robot.chain.joint_variables))
    return "\n".join(block.latex for block in flat(table_items(header, rows, page, len(rows))))
