"""Rich display for notebooks: DH tables and matrices that render as LaTeX in Jupyter.

Objects here only carry LaTeX text and expose `_repr_latex_`, so the package needs no IPython.

>>> from dhsym.io.library import load
>>> arm = load("planar2r")
>>> print(transform(arm, 0, 2).latex.splitlines()[0])
{}^{0}T_{2} = \\begin{bmatrix}
"""
from __future__ import annotations

from dataclasses import dataclass

from .printers import LatexPrinter
from .render import latex_legend, latex_matrix, latex_table, transform_title


@dataclass(frozen=True)
class Latex:
    """LaTeX math that Jupyter renders; `print()` shows the source."""

    latex: str

    def _repr_latex_(self) -> str:
        return f"$$\n{self.latex}\n$$"

    def __str__(self) -> str:
        return self.latex


def table(chain) -> Latex:
    """The DH table in its convention's column order; joint variables starred."""
    return Latex(latex_table(chain))


def matrix(chain, value, name: str = "", legend: bool = True) -> Latex:
    """Any matrix (or vector) of a chain in c/s notation, with its name and legend."""
    printer = LatexPrinter(chain.joint_variables)
    body = (f"{name} = " if name else "") + latex_matrix(value, printer)
    notes = latex_legend(printer) if legend else ""
    return Latex(body + (f"\\\\[4pt]\n\\scriptstyle {notes}" if notes else ""))


def transform(chain, i, j, raw: bool = False) -> Latex:
    """{i}T_{j} of a chain, simplified unless `raw`."""
    return matrix(chain, chain.transform(i, j, raw=raw), transform_title(i, j, "latex"))


def expression(chain, value, name: str = "") -> Latex:
    """One expression in c/s notation, e.g. a position component."""
    printer = LatexPrinter(chain.joint_variables)
    return Latex((f"{name} = " if name else "") + printer.doprint(value))
