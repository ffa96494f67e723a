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

from ..dynamics.equations import CoriolisElement, textbook_layout
from ..printing.dynamics import C_VALUES_UP_TO, MotionLatexPrinter
from .display import Latex
from .layout import PAGES, Block, Page, Rows, aligned_display, element_rows, lines_under, paragraph, stacked
from .legend import legend_items
from .sections import Section

PART = "Dynamics"
DOT_EXTRA = 2.5  # pt: a row with a dotted rate is taller than the layout's measured row
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
            Rows([[_element(printer, s, page) for s in group] for group in by_k if group])]))
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
    return Rows([[_element(printer, record, page, values) for record in records]])


def _element(printer, record, page: Page, values: bool = False) -> list:
    left, right = printer.sides(record)
    if values and isinstance(record, CoriolisElement):
        right += " = " + printer.doprint(record.value)
    return [(tex, height + DOT_EXTRA * ("\\dot" in tex)) for tex, height in element_rows(left, right, page)]


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
    return out


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
        items.append(paragraph(section.title, page))
        items += section.items
    return Latex(stacked([_as_text(item) for item in items], page))


def _as_text(item):
    """A paragraph whose math MathJax must set: its text in \\text{}, its math between (`stacked` wraps
    paragraphs as \\text{} lines)."""
    if not isinstance(item, Block) or item.is_display or "$" not in item.latex:
        return item
    pieces = item.latex.split("$")
    body = "".join(f"\\text{{{piece}}}" if k % 2 == 0 else piece for k, piece in enumerate(pieces) if piece)
    return Block(f"\\[{body}\\]", item.height, math=body)
