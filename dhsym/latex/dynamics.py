r"""The equations of motion in `dhsym latex --dynamics`, `dhsym dynamics --format latex` and a
notebook: M(q) element by element (d_{ij}), the Christoffel symbols that are not zero grouped by
the equation they enter, C, the gravity torques φ_k and one equation per joint, with a legend of
the c/s abbreviations they use; the derivation (`steps`) and the regressor come from their own
modules.

Laid out by the one rule of the documents: every element is a line of ``aligned``, broken before a
+ or − when wider than the page; nothing is shrunk.

>>> import dhsym
>>> from dhsym.dynamics.derive import derive
>>> arm = dhsym.load("spong_elbow")
>>> result = derive(arm.chain, arm.filled_masses())
>>> [section.title for section in dynamics_sections(arm, result, PAGES["article"])][:3]
['Inertia matrix $M(q)$', 'Christoffel symbols $c_{ijk}$', 'Coriolis and centrifugal matrix $C(q, \\dot{q})$']
"""
from __future__ import annotations

import dataclasses
import re

import sympy

from ..dynamics.equations import CoriolisElement, textbook_layout
from ..errors import UserError
from ..printing.dynamics import C_VALUES_UP_TO, MotionLatexPrinter
from .aligned_rows import aligned_rows
from .display import Latex
from .layout import (
    PAGES,
    TEXT_LINE,
    Block,
    Page,
    Rows,
    aligned_display,
    display,
    lines_under,
    paragraph,
    stacked,
)
from .legend import legend_items
from .sections import Section
from .width import math_width

PART = "Dynamics"
TEXT_SHARE = 0.9  # of the notebook's line that a line of text fills: text between many small pieces of math
#                  measures up to 7 % wider than the width estimate (the regressor's list of parameters)
TEXTS = {
    "M": "The inertia matrix is symmetric, $d_{ji} = d_{ij}$; its upper triangle:",
    "christoffel": "$c_{ijk} = \\tfrac{1}{2}\\left(\\frac{\\partial d_{kj}}{\\partial q_i} + \\frac{\\partial d_{ki}}"
                   "{\\partial q_j} - \\frac{\\partial d_{ij}}{\\partial q_k}\\right)$, $c_{jik} = c_{ijk}$; those "
                   "that are not zero, by the equation $k$ they enter:",
    "no christoffel": "Every $c_{ijk} = \\tfrac{1}{2}\\left(\\frac{\\partial d_{kj}}{\\partial q_i} + "
                      "\\frac{\\partial d_{ki}}{\\partial q_j} - \\frac{\\partial d_{ij}}{\\partial q_k}\\right)$ "
                      "is zero, and so is $C$.",
    "C": "$C_{kj} = \\sum_i c_{ijk}\\,\\dot{q}_i$; the elements that are not zero:",
    "g": "$\\phi_k = \\partial P / \\partial q_k$, $P$ the potential energy:",
    "tau": "$\\tau_k = \\sum_j d_{kj}\\,\\ddot{q}_j + \\sum_{i,j} c_{ijk}\\,\\dot{q}_i \\dot{q}_j + \\phi_k$:",
}


def dynamics_sections(robot, result, page: Page, printer: MotionLatexPrinter | None = None,
                      legend: bool = True) -> list[Section]:
    """The results of `result` (dhsym.dynamics.derive) for `robot` as sections of a document."""
    printer = printer or MotionLatexPrinter(robot, result)
    layout = textbook_layout(result)
    out = [Section(PART, "Inertia matrix $M(q)$", [paragraph(TEXTS["M"], page), _rows(printer, layout.inertia, page)])]
    if layout.christoffel:
        by_k = [[s for s in layout.christoffel if s.k == k] for k in range(1, layout.n + 1)]
        out.append(Section(PART, "Christoffel symbols $c_{ijk}$", [
            paragraph(TEXTS["christoffel"], page),
            aligned_rows([[printer.sides(s) for s in group] for group in by_k if group], page)]))
        out.append(Section(PART, "Coriolis and centrifugal matrix $C(q, \\dot{q})$", [
            paragraph(TEXTS["C"], page), _rows(printer, layout.coriolis, page, values=layout.n <= C_VALUES_UP_TO)]))
    else:
        out.append(Section(PART, "Christoffel symbols $c_{ijk}$", [paragraph(TEXTS["no christoffel"], page)]))
    out.append(Section(PART, "Gravity vector $g(q)$", [paragraph(TEXTS["g"], page),
                                                        _rows(printer, layout.gravity, page)]))
    out.append(Section(PART, "Equations of motion", [paragraph(TEXTS["tau"], page),
                                                      _rows(printer, layout.motion, page)]))
    if legend:
        out[-1].items.extend(legend_items(printer, page))
    return out


def _rows(printer, records, page: Page, values: bool = False) -> Rows:
    """One column of elements, each broken to the page."""
    return aligned_rows([[_sides(printer, record, values) for record in records]], page)


def _sides(printer, record, values: bool = False) -> tuple[str, str]:
    left, right = printer.sides(record)
    if values and isinstance(record, CoriolisElement):
        right += " = " + printer.doprint(record.value)
    return left, right


def snippet(robot, result, method: str = "lagrange", steps: bool = False, regressor: bool = False) -> str:
    """The math for a document with amsmath (`dhsym dynamics --format latex`): titles and text are
    comments."""
    out = [f"% dhsym dynamics: {' '.join(robot.name.split())} ({robot.chain.convention} DH); "
           "needs \\usepackage{amsmath}"]
    for section in all_sections(robot, result, PAGES["snippet"], method, steps, regressor):
        out.append(f"% {' '.join(section.title.split())}")
        for item in section.items:
            block = item if isinstance(item, Block) else aligned_display(lines_under(item.columns, 0), "align*")
            out.append(block.latex if block.is_display else f"% {' '.join(block.latex.split())}")
    return "\n".join(out) + "\n"


def all_sections(robot, result, page: Page, method: str = "lagrange", steps: bool = False,
                 regressor: bool = False) -> list[Section]:
    """The derivation (with `steps`), the results and the regressor (with `regressor`), one legend last."""
    printer = MotionLatexPrinter(robot, result)
    out = []
    if steps:
        from .dynamics_steps import steps_sections

        out += steps_sections(robot, result, page, printer, method)
    out += dynamics_sections(robot, result, page, printer, legend=not regressor)
    if regressor:
        from .dynamics_steps import regressor_sections

        out += regressor_sections(robot, page, printer)
        out[-1].items.extend(legend_items(printer, page))
    return [dataclasses.replace(section, headed=True) for section in out]  # M, C, g … each under its own heading


def document_sections(robot, page: Page, steps: bool = False) -> list[Section]:
    """What `dhsym latex --dynamics` adds: the results, derived here, and with `steps` Lagrange's derivation."""
    from ..dynamics.derive import derive

    return all_sections(robot, derive(robot.chain, robot.filled_masses()), page, steps=steps)


def notebook_display(robot, result, method: str = "lagrange", steps: bool = False,
                     regressor: bool = False) -> Latex:
    """The sections as one display for Jupyter: titles and text as \\text{…} lines between the math."""
    page = PAGES["notebook"]
    items = []
    for section in all_sections(robot, result, page, method, steps, regressor):
        items += _as_text(paragraph(section.title, page), "\\textbf")
        items += [row for item in section.items for row in _as_text(item)]
    return Latex(stacked(items, page))


def notebook_elements(robot, result, names) -> Latex:
    """Some of the results by name, as the notebook shows them: "d22", "c121", "C12", "phi2", "tau1"
    (joints numbered as the robot prints them; ASCII names, as `dhsym dynamics --ascii` writes them).

    >>> import dhsym
    >>> from dhsym.dynamics.derive import derive
    >>> arm = dhsym.load("spong_elbow")
    >>> print(notebook_elements(arm, derive(arm.chain, arm.filled_masses()), ["phi2"]))
    \\begin{array}{l}
    \\begin{aligned}
    \\phi_{2} &= g l_{c2} m_{2} c_{12}
    \\end{aligned}
    \\end{array}
    """
    from ..printing.dynamics import MotionTextPrinter

    layout = textbook_layout(result)
    records = [*layout.inertia, *layout.christoffel, *layout.coriolis, *layout.gravity, *layout.motion]
    named = {MotionTextPrinter(robot, result, ascii=True).sides(record)[0].split(" = ")[0]: record
             for record in records}
    missing = [name for name in names if name not in named]
    if missing:
        raise UserError(f"no element {missing[0]} in these equations; they have {', '.join(named)}")
    printer = MotionLatexPrinter(robot, result)
    page = PAGES["notebook"]
    return Latex(stacked([aligned_rows([[_sides(printer, named[name]) for name in names]], page)], page))


def notebook_matrix(robot, result, value, name: str = "") -> Latex:
    """Any matrix of the dynamics (Ṁ − 2C, a Jacobian) with its rates dotted, and its legend."""
    from ..printing.render import latex_matrix

    printer = MotionLatexPrinter(robot, result)
    body = (f"{name} = " if name else "") + latex_matrix(sympy.Matrix(value), printer)
    page = PAGES["notebook"]
    return Latex(stacked([display(body, 20.0), *legend_items(printer, page)], page))


def _as_text(item, command: str = "\\text") -> list:
    """A paragraph as displays of one line each, its text in \\text{…} and its math as math, the
    lines filled to the notebook's width (MathJax breaks nothing inside a display)."""
    if not isinstance(item, Block) or item.is_display:
        return [item]
    page, rows, line = PAGES["notebook"], [], ""
    for word in re.findall(r"(?:\$[^$]*\$|[^\s$])+", item.latex):  # a word, with any math it holds kept whole
        if line and math_width(_row_math(f"{line} {word}")) > TEXT_SHARE * page.width:
            rows.append(line)
            line = word
        else:
            line = f"{line} {word}" if line else word
    return [display(_row_math(row, command), TEXT_LINE) for row in rows + [line]]


def _row_math(text: str, command: str = "\\text") -> str:
    r"""One line as math: '\text{find }\theta_{1}'."""
    return "".join(piece if position % 2 else f"{command}{{{piece}}}" for position, piece in enumerate(text.split("$"))
                   if piece)
