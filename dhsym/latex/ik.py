r"""Inverse kinematics in `dhsym latex --ik` and `dhsym ik --format latex`: the problem (the
target as the matrix of its names), the method (the decoupling), each equation of the derivation
with the sub-problem it is an instance of, the intermediate quantities, every branch, when the
branches exist and where they degenerate, and a legend of the c/s abbreviations used.

Laid out like the transforms: every equation is a line of ``aligned`` broken before a + or −
when wider than the page; nothing is shrunk.

>>> import sympy
>>> from dhsym.inverse.solution import Branch, Solution
>>> from dhsym import load
>>> arm = load("planar2r")
>>> t1, t2 = arm.chain.joint_variables
>>> px, py = sympy.symbols("px py", real=True)
>>> both = Solution(arm.chain, "planar arm", (t1, t2), (), (Branch("one", ((t1, sympy.atan2(py, px)), (t2, 0))),))
>>> [section.title for section in ik_sections(both, arm, PAGES["article"])]
['Inverse kinematics: the problem', 'Branch 1: one']
"""
from __future__ import annotations

import re

import sympy

from ..printing.ik import (
    IKLatexPrinter,
    angle_meanings,
    latex_name,
    solution_printer,
    target_name,
    target_names,
    target_title,
    variable_list,
)
from ..printing.ik_solution import ATAN2_LEGEND, named_numbers, uses_atan2
from .display import Latex
from .ik_branches import DEFINITIONS, PART, branch_sections, heading, merged, value_rows
from .layout import (
    ALIGNED_EXTRA,
    PAGES,
    TEXT_LINE,
    Block,
    Page,
    Rows,
    aligned_display,
    bmatrix,
    break_lines,
    display,
    lines_under,
    matrix_height,
    paragraph,
    row_height,
    stacked,
)
from .legend import legend_items
from .prose import tex_prose
from .sections import Section
from .width import math_width

_MATH_CHARACTERS = {"²": "$^{2}$", "³": "$^{3}$", "√": "$\\surd$"}  # tex_text has no text form for these


def ik_sections(solution, robot, page: Page, headings: bool | None = None) -> list[Section]:
    """The problem and the method; the derivation step by step (if the solver kept its steps);
    the intermediate quantities; one section per branch; existence and degenerate poses; the legend.
    `robot` numbers the frames and joints; `headings` (default: where pages have no frame titles)
    starts each section with its title."""
    chain = solution.chain
    targets = target_names(solution)
    printer = solution_printer(solution, robot.numbering, DocumentPrinter)
    names = [[target_name(targets[4 * r + c], "latex") for c in range(4)] for r in range(3)] + [["0", "0", "0", "1"]]
    unknowns = [v for v in solution.joint_variables if v not in solution.free]
    problem = [paragraph(f"Given the pose of the last frame, find ${variable_list(unknowns, printer)}$. "
                         f"The target is written with the names of its elements:", page),
               display(f"{target_title(chain, robot.numbering, 'latex')} =\n{bmatrix(names)}", matrix_height(names)),
               paragraph(f"Method: {printer.sentence(solution.method)}.", page)]
    if solution.free:
        problem.append(paragraph(f"Free joint variables, kept as parameters: "
                                 f"${variable_list(solution.free, printer)}$.", page))
    count = len(solution.branches)
    problem.append(paragraph(f"{count} branch{'es' if count != 1 else ''}.", page))
    out = [Section(PART, "Inverse kinematics: the problem", problem)]
    if solution.steps:
        out.append(Section(PART, "Derivation", _step_items(solution.steps, printer, page)))
    if solution.definitions:
        rows = [value_rows(latex_name(name), value, printer, page) for name, value in solution.definitions]
        out.append(Section(PART, DEFINITIONS,
                           [paragraph("Used by every branch:", page), Rows([rows])]))
    out += branch_sections(solution, printer, page)
    meanings = angle_meanings(solution)
    if meanings:  # the names a branch solves as one, θ23 = θ2 + θ3, defined after the branches that use them
        said = ", ".join(f"${printer.doprint(name)} = {printer.doprint(value)}$" for name, value in meanings)
        out[-1].items.append(paragraph(f"Angles solved as one: {said}.", page))
    if page.height_pt is not None:  # slides: no frame of a single equation
        out = merged(out, page)
    remarks = [paragraph(f"Condition: {printer.sentence(said)}.", page) for said in solution.conditions]
    remarks += [paragraph(f"Degenerate: {printer.sentence(said)}.", page) for said in solution.degenerate]
    if remarks:
        out.append(Section(PART, "Existence and degenerate poses", remarks))
    out[-1].items.extend(_legend(solution, printer, page))
    if page.height_pt is None if headings is None else headings:  # no frame titles: a heading says which part
        for section in out:
            section.items.insert(0, heading(section.title, page))
    return out


def _step_items(steps, printer, page: Page) -> list:
    """Each equation after a line naming the sub-problem it is an instance of and what it solves for."""
    items = []
    for number, step in enumerate(steps, 1):
        solves = f", for ${variable_list(step.solves, printer)}$" if step.solves else ""
        note = f": {printer.sentence(step.note)}" if step.note else ""
        text = paragraph(f"Step {number} ({printer.sentence(step.subproblem)}){solves}{note}.", page)
        text.keep_with_next = True
        items += [text, Rows([[_equation_rows(step.lhs, step.rhs, printer, page)]])]
    if len(steps) > 1:  # the last step never alone on a frame: the one before goes with it if it must
        items[-3].keep_with_next = True
    return items


def _equation_rows(lhs, rhs, printer, page: Page) -> list[tuple[str, float]]:
    """`lhs = rhs` as lines of `aligned`, broken before a + or − to fit the page; a matrix
    equation element by element."""
    if isinstance(lhs, sympy.MatrixBase) or isinstance(rhs, sympy.MatrixBase):
        left, right = sympy.Matrix(lhs), sympy.Matrix(rhs)
        pairs = [(a, b) for a, b in zip(left, right, strict=True) if a != b]
        return [row for a, b in pairs for row in _equation_rows(a, b, printer, page)]
    width = page.width - ALIGNED_EXTRA
    lines = break_lines(f"{printer.doprint(lhs)} = {printer.doprint(rhs)}", width, width - 1.0, display=True)
    first = "{-}" + lines[0][1:] if lines[0].startswith("-") else lines[0]  # a sign, not a minus after the &
    rows = [f"&{first}"] + [f"&\\quad {{}}{line}" for line in lines[1:]]
    return [(row, row_height([row], array=False)) for row in rows]


class DocumentPrinter(IKLatexPrinter):
    """The LaTeX printer of the documents: a sentence's words set as LaTeX text (`prose`)."""

    def _words(self, text: str) -> str:
        return prose(text)


def prose(text: str) -> str:
    """A solver's sentence as LaTeX text (identifiers and transforms such as 1T6 set as math, see
    `tex_prose`); squares and roots, which a text font lacks, as math.

    >>> prose("D² ≤ 1")
    'D$^{2}$ $\\\\leq$ 1'
    >>> prose("(u4 × u6 along −u5)")
    '($u_{4} \\\\times u_{6}$ along $-u_{5}$)'
    """
    text, out, position = str(text), [], 0
    for match in _AXIS_NAMES.finditer(text):  # an axis's direction or a frame's axis, as math
        out += [_characters(text[position:match.start()]), f"${_axis_math(match.group(0))}$"]
        position = match.end()
    return "".join(out) + _characters(text[position:])


_AXIS_NAMES = re.compile(r"(?<![\w+−])[+−]?[uxyz]\d{1,2}(?:\s×\s[+−]?[uxyz]\d{1,2})*(?!\w)")  # u5, +z0, u4 × u6


def _axis_math(text: str) -> str:
    """u4 × u6 as math: u_{4} \\times u_{6}."""
    text = re.sub(r"([uxyz])(\d+)", r"\1_{\2}", text)
    return text.replace("×", "\\times").replace("−", "-")


def _characters(text: str) -> str:
    """Text with its squares and roots as math (`tex_prose` for the rest)."""
    pieces = [""]
    for character in text:
        if character in _MATH_CHARACTERS:
            pieces += [_MATH_CHARACTERS[character], ""]
        else:
            pieces[-1] += character
    return "".join(piece if position % 2 else tex_prose(piece) for position, piece in enumerate(pieces))


def snippet(solution, robot) -> str:
    """The sections of `ik_sections` for a document with amsmath (`dhsym ik --format latex`): the
    words typeset, so that a compiled page says which step, which branch, which condition."""
    out = [f"% dhsym ik: {' '.join(robot.name.split())}; needs \\usepackage{{amsmath}}"]
    sections = ik_sections(solution, robot, PAGES["snippet"], headings=True)
    return "\n".join(out) + "\n" + typeset([item for section in sections for item in section.items])


def typeset(items) -> str:
    r"""Blocks and `Rows` as the lines of a snippet: displays as they are, rows as one align*, and
    each paragraph of text on one line, not indented; a heading (a paragraph in bold) after a small
    space. Text before a display runs on into it, as a display sits in its paragraph, without an
    empty line; text after a display continues that paragraph.

    >>> page = PAGES["snippet"]
    >>> print(typeset([paragraph("\\textbf{Branch 1}", page), paragraph("where", page), display("x = 1", 10.0),
    ...                paragraph("Step 2.", page)]), end="")
    \medskip\noindent\textbf{Branch 1}\par
    \noindent where
    \[
    x = 1
    \]
    Step 2.\par
    """
    blocks = [item if isinstance(item, Block) else aligned_display(lines_under(item.columns, 0), "align*")
              for item in items]
    out = []
    for position, block in enumerate(blocks):
        if block.is_display:
            out.append(block.latex)
            continue
        text = " ".join(block.latex.split())
        after_display = position > 0 and blocks[position - 1].is_display
        if text.startswith("\\textbf{"):
            text = ("\\par" if after_display else "") + "\\medskip\\noindent" + text
        elif not after_display:  # a label, not an indented paragraph
            text = "\\noindent " + text
        follows = blocks[position + 1] if position + 1 < len(blocks) else None
        out.append(text if follows is not None and follows.is_display else text + "\\par")
    return "".join(line + "\n" for line in out)


def _legend(solution, printer, page: Page) -> list:
    """The names the formulas use: the table's long decimals named (an import's a2, β), the c/s
    abbreviations, and atan2's order where a formula holds one (on slides, on the legend's frame)."""
    legend = legend_items(printer, page)
    named = named_numbers(solution.numbers, "latex")
    if named:
        said = Block(named, paragraph(named_numbers(solution.numbers, "unicode"), page).height, is_display=False)
        said.keep_with_next = bool(legend)
        legend.insert(0, said)
    if uses_atan2(solution):
        if legend:
            legend[-1].keep_with_next = True
        height = paragraph(ATAN2_LEGEND["unicode"], page).height  # as long as what it prints, not its markup
        legend.append(Block(ATAN2_LEGEND["latex"], height, is_display=False))
    return legend


def notebook_display(solution, robot):
    """The sections as one display for Jupyter, laid out for the notebook's line: text is set
    as \\text{…} lines with its math between them, which MathJax renders without extensions."""
    page = PAGES["notebook"]
    items = []
    for section in ik_sections(solution, robot, page, headings=False):
        for item in [paragraph(section.title, page)] + section.items:
            items += _text_rows(item.latex, page) if isinstance(item, Block) and not item.is_display else [item]
    return Latex(stacked(items, page))


_WORD = re.compile(r"(?:\$[^$]*\$|[^\s$])+")  # a word, with any math it holds kept whole


def _text_rows(latex: str, page: Page) -> list[Block]:
    r"""A paragraph as displays of one line each: text in \text{…}, math as math.

    >>> [b.math for b in _text_rows("find $\\theta_{1}$.", PAGES["notebook"])]
    ['\\text{find }\\theta_{1}\\text{.}']
    """
    rows, line = [], ""
    for word in _WORD.findall(latex):
        if line and math_width(_row_math(line + " " + word)) > page.width:
            rows.append(line)
            line = word
        else:
            line = f"{line} {word}" if line else word
    rows.append(line)
    return [display(_row_math(row), TEXT_LINE) for row in rows]


def _row_math(text: str) -> str:
    r"""One row as math; the row is already broken, so a break hint (which MathJax cannot read
    inside \text) is left out.

    >>> _row_math("elbow up/\\allowbreak{}down of $\\theta_{2}$")
    '\\text{elbow up/down of }\\theta_{2}'
    """
    pieces = text.replace("\\allowbreak{}", "").split("$")
    return "".join((piece if position % 2 else f"\\text{{{piece}}}") for position, piece in enumerate(pieces)
                   if piece)
