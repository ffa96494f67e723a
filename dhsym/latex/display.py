r"""Rich display for notebooks: DH tables and matrices that render as LaTeX in Jupyter, laid
out by the same rule as the documents (`layout`): a matrix that fits the notebook's line is a
matrix; a wider one is the matrix of names ``[r11 … pz]`` with its elements below it, column by
column, long ones broken. The legend goes under the matrix. Everything is one ``array`` of
rows, which MathJax 2, 3 and 4 and pdflatex all stack the same way (MathJax 3 ignores a
``\\`` outside an environment).

Objects here only carry LaTeX text and expose `_repr_latex_`, so the package needs no IPython.
A notebook reaches these as `dhsym.show` (dhsym.api.show: `show.table(arm)`, `show.transform(arm,
0, 2)`, `show.matrix(arm, M, "J")`, `show.expression(arm, e, "p_x")`), with frames as the robot
prints them: not as `display`, a name that would hide IPython's own `display` after
`from dhsym import *`.

>>> from dhsym.io.library import load
>>> arm = load("planar2r")
>>> print(matrix(arm, arm.chain.fk(), "{}^{0}T_{2}").latex.splitlines()[:2])
['\\begin{array}{l}', '{}^{0}T_{2} =']
>>> puma = load("puma560")
>>> "r_{11} & r_{12}" in matrix(puma, puma.chain.fk(), "{}^{0}T_{6}").latex  # too wide: named elements
True
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.robot import Robot
from ..printing.printers import LatexPrinter, chain_settings
from ..printing.render import latex_matrix, latex_printer, latex_table_cells
from .layout import PAGES, Block, display, matrix_height, matrix_items, stacked
from .legend import legend_items
from .tables import table_items

__all__ = ["Latex", "expression", "matrix", "table"]


@dataclass(frozen=True)
class Latex:
    """LaTeX math that Jupyter renders; `print()` shows the source."""

    latex: str

    def _repr_latex_(self) -> str:
        return f"$$\n{self.latex}\n$$"

    def __str__(self) -> str:
        return self.latex


def table(robot: Robot, page: str = "notebook") -> Latex:
    """The DH table in its convention's column order; joint variables starred. A table too
    wide for the `page` is split into tables of columns (see `tables`)."""
    header, rows = latex_table_cells(robot, latex_printer(robot, marked=robot.chain.joint_variables))
    items = table_items(header, rows, PAGES[page], len(rows))
    if len(items) == 1 and isinstance(items[0], Block):
        return Latex(items[0].math)  # the usual case: one array
    return Latex(stacked(items, PAGES[page]))


def matrix(robot: Robot, value, name: str = "", legend: bool = True, page: str = "notebook") -> Latex:
    """Any matrix (or vector) of a robot in c/s notation, with its name and legend. A named
    transform too wide for the `page` ("notebook", or one of the documents') is shown by its
    elements."""
    printer = LatexPrinter(chain_settings(robot))
    value = sympy.Matrix(value)
    if value.shape == (4, 4) and name and list(value[3, :]) == [0, 0, 0, 1]:  # a transform
        cells = [[printer.doprint(value[r, c]) for c in range(4)] for r in range(4)]
        items = matrix_items(name, cells, PAGES[page])
    else:
        body = (f"{name} = " if name else "") + latex_matrix(value, printer)
        items = [display(body, matrix_height([[""]] * value.rows))]
    if legend:
        items += legend_items(printer, PAGES[page])
    return Latex(stacked(items, PAGES[page]))


def expression(robot: Robot, value, name: str = "") -> Latex:
    """One expression in c/s notation, e.g. a position component."""
    printer = LatexPrinter(chain_settings(robot))
    return Latex((f"{name} = " if name else "") + printer.doprint(value))

