r"""The branches of an inverse-kinematics derivation in the documents: each assignment as lines of
``aligned`` (an atan2 too wide breaks between its arguments), a branch's name as text. On slides,
the branches that differ only in signs are written once with ± and a table of signs (`ik_signs`),
branches of a few lines share a frame, and no frame holds a single equation where it can share
one: a lone intermediate quantity joins the derivation's last frame or the branches'.

>>> from dhsym import load
>>> from dhsym.latex.layout import PAGES
>>> from dhsym.inverse.solution import Branch, Solution
>>> from dhsym.printing.ik import latex_printer
>>> arm = load("planar2r")
>>> t1, t2 = arm.chain.joint_variables
>>> D = sympy.Symbol("D", real=True)
>>> elbow = lambda sign: sympy.atan2(sign * sympy.sqrt(1 - D**2), D)
>>> up_down = [Branch(name, ((t2, elbow(sign)),)) for name, sign in (("down", 1), ("up", -1))]
>>> solution = Solution(arm.chain, "planar arm", (t1, t2), (), tuple(up_down))
>>> [(s.title, len(s.items)) for s in branch_sections(solution, latex_printer(arm.chain), PAGES["slides"])]
[('Branches 1 and 2', 3)]
>>> [s.title for s in branch_sections(solution, latex_printer(arm.chain), PAGES["article"])]
['Branch 1: down', 'Branch 2: up']
"""
from __future__ import annotations

import re

import sympy

from ..printing.ik import latex_name
from .ik_signs import families, sign_table
from .layout import ALIGNED_EXTRA, Block, Page, Rows, break_lines, element_rows, paragraph, row_height
from .packing import pack
from .prose import tex_text
from .sections import Section
from .width import math_width

PART = "Inverse kinematics"
DEFINITIONS = "Intermediate quantities"


def value_rows(label: str, value, printer, page: Page) -> list[tuple[str, float]]:
    r"""`label &= value` as lines of an aligned block; an atan2 too wide for one line breaks
    between its arguments (each broken further if it must), not inside a bracket of the second.

    >>> import dhsym
    >>> from dhsym.latex.layout import PAGES
    >>> from dhsym.printing.ik import latex_printer
    >>> value = sympy.atan2(sum(sympy.symbols("x_1:12")), sum(sympy.symbols("y_1:12")))
    >>> rows = value_rows("\\theta_{1}", value, latex_printer(dhsym.load("planar2r").chain), PAGES["article"])
    >>> [row[-12:] for row, _ in rows]
    ['{8} + x_{9},', '{8} + y_{9})']
    """
    parts = tuple(printer.doprint(argument) for argument in value.args) if isinstance(value, sympy.atan2) else None
    return latex_rows(label, printer.doprint(value), parts, page)


def latex_rows(label: str, formula: str, parts, page: Page) -> list[tuple[str, float]]:
    """`label &= formula` as `value_rows` lays it out, from its LaTeX; `parts`, the (y, x) of an
    atan2 as LaTeX (else None), where it breaks between them."""
    rows = element_rows(label, formula, page)
    if len(rows) == 1 or parts is None:
        return rows
    y, x = parts
    split = element_rows(label, f"\\mathrm{{atan2}}({y},", page)
    width = page.width - math_width(label + " =") - ALIGNED_EXTRA - 1.0
    lines = break_lines(f"{x})", width, width, display=True)
    split += [(row, row_height([row], array=False))
              for row in [f"&\\quad {lines[0]}"] + [f"&\\quad {{}}{line}" for line in lines[1:]]]
    return split if len(split) <= len(rows) else rows


def branch_title(name: str) -> str:
    r"""A branch's name as LaTeX text, a root's sign as math.

    >>> branch_title("shoulder +√, elbow −√, wrist flipped")
    'shoulder $+\\surd$, elbow $-\\surd$, wrist flipped'
    """
    pieces = re.split(r"([+−]√)", name)
    return "".join(f"${'+' if piece[0] == '+' else '-'}\\surd$" if position % 2 else tex_text(piece)
                   for position, piece in enumerate(pieces))


def branch_sections(solution, printer, page: Page) -> list[Section]:
    """A section per branch; on slides, the branches that differ only in the signs of roots as one
    with ± and a table of signs (`ik_signs`), and branches of a few lines together on a frame."""
    printed = [(branch.name, [_printed(name, value, printer) for name, value in branch.assignments])
               for branch in solution.branches]
    slides = page.height_pt is not None
    grouped = {family.numbers[0]: family for family in families(printed)} if slides else {}
    in_family = {number for family in grouped.values() for number in family.numbers}
    out: list[Section] = []
    singles: list[tuple[int, str, list]] = []  # branches written on their own, gathered while they fit a frame
    for number, (name, rows) in enumerate(printed, 1):
        if number in grouped:
            out += _gathered(singles, page)
            singles = []
            out.append(_family_section(grouped[number], page))
        elif number not in in_family:
            singles.append((number, name, [Rows([[latex_rows(*row[:3], page) for row in rows]])]))
    return out + _gathered(singles, page)


def _printed(name, value, printer) -> tuple:
    """(name, formula, the (y, x) of an atan2 or None, the formula and (y, x) of atan2(−y, −x) or
    None) as LaTeX: the pair's sign is one a branch may choose (`ik_signs`)."""
    formula = printer.doprint(value)
    if not isinstance(value, sympy.atan2):
        return latex_name(name), formula, None, None
    parts = tuple(printer.doprint(argument) for argument in value.args)
    negated = None
    turned = sympy.atan2(*(-argument for argument in value.args))
    if not any(argument.is_number for argument in value.args) and isinstance(turned, sympy.atan2):
        flipped = tuple(printer.doprint(argument) for argument in turned.args)
        text = printer.doprint(turned)
        if formula == _atan2_text(parts) and text == _atan2_text(flipped):  # printed as its two arguments
            negated = (text, flipped)
    return latex_name(name), formula, parts, negated


def _atan2_text(parts) -> str:
    return f"\\mathrm{{atan2}}({parts[0]}, {parts[1]})"


def _gathered(singles, page: Page) -> list[Section]:
    """Branches written on their own, a section each; on slides, consecutive ones that fit one
    frame together share it, each under its heading."""
    out: list[tuple[list, list]] = []  # (numbers, items) of each section
    for number, name, items in singles:
        headed = [heading(f"Branch {number}: {branch_title(name)}", page)] + items
        if page.height_pt is not None and out and len(pack(out[-1][1] + headed, page.height_pt)) == 1:
            out[-1] = (out[-1][0] + [(number, name)], out[-1][1] + headed)
        else:
            out.append(([(number, name)], headed))
    sections = []
    for numbers, items in out:
        if len(numbers) == 1:
            (number, name), = numbers
            sections.append(Section(PART, f"Branch {number}: {branch_title(name)}", items[1:]))
        else:
            sections.append(Section(PART, f"Branches {_numbers([n for n, _ in numbers])}", items))
    return sections


def _family_section(family, page: Page) -> Section:
    """Branches that differ only in the signs of roots: their formulas once, with ± (∓), and the
    table of the sign each branch takes."""
    rows = Rows([[latex_rows(label, formula, parts, page) for label, formula, parts in family.rows]])
    other = "; $\\mp$ takes the other sign" if family.mixed else ""
    said = paragraph(f"Each branch takes the sign below for $\\pm$ in the formula of the column's name{other}:",
                     page)
    said.keep_with_next = True
    table = Block(sign_table(family, branch_title), (len(family.numbers) + 1) * TABLE_ROW + 2.0, is_display=False)
    words = [set(name.split(", ")) for name in family.names]
    common = [word for word in family.names[0].split(", ") if all(word in others for others in words)]
    title = f"Branches {_numbers(family.numbers)}" + (f": {branch_title(', '.join(common))}" if common else "")
    return Section(PART, title, [rows, said, table])


TABLE_ROW = 13.0  # pt: a row of a tabular at 11 pt, with \hline's share


def _numbers(numbers: list[int]) -> str:
    """1 to 8 for a run, else 1, 2, 5 and 6.

    >>> _numbers([1, 2, 3]), _numbers([1, 2, 5, 6]), _numbers([3, 4])
    ('1 to 3', '1, 2, 5 and 6', '3 and 4')
    """
    if len(numbers) > 2 and numbers == list(range(numbers[0], numbers[-1] + 1)):
        return f"{numbers[0]} to {numbers[-1]}"
    return ", ".join(map(str, numbers[:-1])) + f" and {numbers[-1]}"


def merged(sections: list[Section], page: Page) -> list[Section]:
    """Slides: the intermediate quantities end the derivation's last frame where they fit it;
    else, a single equation, they start the branches' (a frame of one equation says little). A
    lone branch of one line (a one-joint chain's) ends the frame before it, under its heading."""
    out: list[Section] = []
    for section in sections:
        before = out[-1] if out else None
        lone_branch = section.title.startswith("Branch ") and _lines(section.items) == 1
        if before is not None and before.title == DEFINITIONS and section.title.startswith("Branch") and (
                len(before.items[-1].columns[0]) == 1):
            out[-1] = Section(PART, section.title, before.items + section.items)
        elif before is not None and (section.title == DEFINITIONS or lone_branch):
            items = ([heading(section.title, page)] if lone_branch else []) + section.items
            if len(pack(before.items + items, page.height_pt)) == len(pack(before.items, page.height_pt)):
                out[-1] = Section(PART, before.title, before.items + items)
            else:
                out.append(section)
        else:
            out.append(section)
    return out


def _lines(items) -> int:
    """The lines of aligned rows among `items`."""
    return sum(len(element) for item in items if isinstance(item, Rows)
               for column in item.columns for element in column)


def heading(title: str, page: Page) -> Block:
    block = paragraph(f"\\textbf{{{title}}}", page)
    block.keep_with_next = True
    return block
