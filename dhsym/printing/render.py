"""Whole results for people: matrices, DH tables, legends and JSON, built on the printers.

Text fits its width: a matrix that fits is printed as a matrix, otherwise as the matrix of
element names followed by the elements column by column (r11, r21, r31, r12, … pz), and an
element longer than the line breaks before a + or − with a hanging indent,
at the outermost bracket level that leaves the line at least half full. The legend, the title
and the notes wrap at the same width.

>>> from dhsym.io.library import load
>>> print(text_table(load("planar3r")))  # doctest: +NORMALIZE_WHITESPACE
i │ αᵢ₋₁ │ aᵢ₋₁ │ dᵢ │ θᵢ
1 │ 0    │ 0    │ 0  │ θ1*
2 │ 0    │ l1   │ 0  │ θ2*
3 │ 0    │ l2   │ 0  │ θ3*
"""
from __future__ import annotations

import bisect
import re
import textwrap
import unicodedata

import sympy

from ..core.chain import Frame
from ..core.robot import Robot
from .names import subscript, superscript
from .printers import ExactPrinter, LatexPrinter, TextPrinter, chain_settings

ELEMENT_NAMES = [["r11", "r12", "r13", "px"], ["r21", "r22", "r23", "py"], ["r31", "r32", "r33", "pz"]]
CONVENTION_NOTES = {
    "standard": "standard (distal) DH: A_i = Rz(θi) Tz(di) Tx(ai) Rx(αi)",
    "modified": "modified (proximal, Craig) DH: T_i = Rx(αi−1) Tx(ai−1) Rz(θi) Tz(di)",
}
_ASCII = str.maketrans({"θ": "theta", "α": "alpha", "−": "-"})
_ASCII_SUBSCRIPTS = str.maketrans({"ᵢ": "i", "₋": "-", "₁": "1"})


ASCII_NOTES = {
    "standard": "standard (distal) DH: A_i = Rz(theta(i)) Tz(d(i)) Tx(a(i)) Rx(alpha(i))",
    "modified": "modified (proximal, Craig) DH: T_i = Rx(alpha(i-1)) Tx(a(i-1)) Rz(theta(i)) Tz(d(i))",
}
MIN_WIDTH = 40  # narrower, and a legend entry such as c(12-4) = cos(theta1 + theta2 - theta4) cannot fit


def convention_note(convention: str, ascii: bool = False) -> str:
    """One line naming the convention and its product of steps."""
    return ASCII_NOTES[convention] if ascii else CONVENTION_NOTES[convention]


def display_width(text: str) -> int:
    """Columns a line takes on a terminal: combining marks (the bar of c124̅) take none."""
    if text.isascii():
        return len(text)
    return len(text) - sum(text.count(ch) for ch in _marks(text))


def _marks(text: str) -> set:
    """The combining marks in `text` (each distinct character is looked up once)."""
    return {ch for ch in set(text) if unicodedata.combining(ch)}


def wrap(text: str, width: int, indent: str = "") -> str:
    """Plain words (titles, notes) wrapped at `width`, continuation lines indented."""
    return "\n".join(textwrap.wrap(text, width, subsequent_indent=indent, break_long_words=False,
                                    break_on_hyphens=False)) or text


def break_element(prefix: str, text: str, width: int) -> str:
    """`prefix + text` in lines of at most `width` columns where possible, broken before a
    top-level + or − (inside a bracket only when the bracket is longer than the line); each
    continuation line is indented two columns past the start of `text`, two more per bracket.

    >>> print(break_element("px  = ", "a1 + b1(c1 + d1 + e1) − f1", 22))
    px  = a1 + b1(c1 + d1
              + e1) − f1
    """
    total = display_width(text)
    if display_width(prefix) + total <= width:
        return prefix + text
    breaks = _breaks(text)  # (position, bracket depth, column) of each space before a + or −
    lines, indent, start, start_column, first, depth = [], prefix, 0, 0, 0, 0
    while first < len(breaks) and len(indent) + total - start_column > width:
        room = width - len(indent)
        last = first
        while last < len(breaks) and breaks[last][2] - start_column <= room:
            last += 1
        chosen = _choose(breaks[first:last], depth, room, start_column) if last > first else breaks[first]
        lines.append(indent + text[start:chosen[0]])
        start, start_column, depth = chosen[0] + 1, chosen[2] + 1, chosen[1]
        indent = " " * (len(prefix) + 2 + 2 * depth)
        first = breaks.index(chosen, first) + 1
    return "\n".join(lines + [indent + text[start:]])


def _choose(window: list, depth: int, room: int, start_column: int) -> tuple[int, int, int]:
    """The break to take among those that fit: out of the bracket the line started in if possible,
    else at the outermost level that leaves the line at least half full, else the last one."""
    levels = sorted({w[1] for w in window})
    for level in levels:
        farthest = max(w for w in window if w[1] == level)
        if level < depth or farthest[2] - start_column >= room / 2:
            return farthest
    return max(window, key=lambda w: w[2])


_BRACKET_OR_BREAK = re.compile(r"[(\[{)\]}]| (?=[+−-] )")  # a bracket, or the space before a binary + or −


def _breaks(text: str) -> list[tuple[int, int, int]]:
    """Where an element may break: (position of the space before a binary + or −, bracket depth
    there, display column)."""
    marks = _marks(text)
    marked = [m.start() for m in re.finditer("[" + re.escape("".join(marks)) + "]", text)] if marks else []
    found, depth = [], 0
    for match in _BRACKET_OR_BREAK.finditer(text):
        ch, position = match.group(), match.start()
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif position:
            found.append((position, depth, position - bisect.bisect_left(marked, position)))
    return found


def text_printer(robot: Robot, ascii: bool = False, marked=()) -> TextPrinter:
    """A text printer for `robot`: its joint variables, offsets and numbers as its file wrote them."""
    return TextPrinter(chain_settings(robot), marked=marked, ascii=ascii)


def latex_printer(robot: Robot, marked=(), printer=LatexPrinter) -> LatexPrinter:
    """A LaTeX printer (or a subclass: `printer`) for `robot`, set up like `text_printer`."""
    return printer(chain_settings(robot), marked=marked)


def exact_printer(robot: Robot) -> ExactPrinter:
    """SymPy's own text form for `robot`, as JSON carries it: sympify reads it back."""
    return ExactPrinter(chain_settings(robot))


def transform_title(i, j, style: str = "unicode") -> str:
    """⁰T₆ (unicode), 0T6 (ascii), {}^{0}T_{6} (latex); base/tool frames by name."""
    if style == "latex":
        name = lambda f: f"\\mathrm{{{f}}}" if isinstance(f, str) else str(f)  # noqa: E731
        return f"{{}}^{{{name(i)}}}T_{{{name(j)}}}"
    if style == "unicode" and isinstance(i, int) and isinstance(j, int):
        return f"{superscript(str(i))}T{subscript(str(j))}"
    if isinstance(i, int) and isinstance(j, int):
        return f"{i}T{j}"
    return f"T({i} -> {j})" if style == "ascii" else f"T({i} → {j})"


def text_matrix(matrix: sympy.Matrix, printer: TextPrinter, width: int = 100) -> str:
    """A 4×4 transform as an aligned matrix, or, when too wide, the matrix of names r11 … pz
    over its fixed row 0 0 0 1 and the elements column by column (see `text_grid`)."""
    cells = [[printer.doprint(matrix[r, c]) for c in range(4)] for r in range(4)]
    return text_grid(cells, ELEMENT_NAMES + [cells[3]], 3, printer.style == "ascii", width)


def text_grid(cells, names, listed_rows: int, ascii: bool, width: int = 100) -> str:
    """Printed `cells` as an aligned matrix when it fits in `width`. Otherwise the rule of every
    surface: the matrix of `names` (when that fits), then the elements of the first
    `listed_rows` rows column by column, as Craig lists them (r11, r21, r31, r12, …), each
    broken at a top-level + or − when longer than the line.

    >>> print(text_grid([["a1 c1 + a2 c12", "0"], ["1", "1"]], [["J11", "J12"], ["J21", "J22"]], 2, False, 18))
    ⎡ J11   J12 ⎤
    ⎣ J21   J22 ⎦
    <BLANKLINE>
    J11 = a1 c1
            + a2 c12
    J21 = 1
    <BLANKLINE>
    J12 = 0
    J22 = 1
    """
    matrix = aligned_matrix(cells, ascii)
    if max(map(display_width, matrix.splitlines())) <= width:
        return matrix
    blocks = []
    named = aligned_matrix(names, ascii)
    if max(map(display_width, named.splitlines())) <= width:
        blocks.append(named)
    label_width = max(display_width(names[r][c]) for r in range(listed_rows) for c in range(len(names[0])))
    for c in range(len(cells[0])):
        labels = [names[r][c] + " " * (label_width - display_width(names[r][c])) + " = " for r in range(listed_rows)]
        blocks.append("\n".join(break_element(labels[r], cells[r][c], width) for r in range(listed_rows)))
    return "\n\n".join(blocks)


def aligned_matrix(cells, ascii: bool) -> str:
    """Rows of cells in aligned columns between brackets (⎡ ⎢ ⎣, or [ ] in ASCII)."""
    widths = [max(display_width(row[c]) for row in cells) for c in range(len(cells[0]))]
    lines = []
    for r, row in enumerate(cells):
        left, right = ("[", "]") if ascii else ("⎡", "⎤") if r == 0 else ("⎣", "⎦") if r == len(cells) - 1 \
            else ("⎢", "⎥")
        body = "   ".join(cell + " " * (w - display_width(cell)) for cell, w in zip(row, widths))
        lines.append(f"{left} {body} {right}")
    return "\n".join(lines)


def legend_entries(printer, style: str) -> list[tuple[str, str]]:
    """(abbreviation, meaning) for exactly the abbreviations the printer has written, in the
    order of the joints: the one source of every legend (text, LaTeX, JSON with `style`
    "sympy")."""
    label_style = "ascii" if style == "sympy" else style
    return [(a.label(label_style), printer.notation.meaning(a, style)) for a in used_abbreviations(printer)]


def used_abbreviations(printer) -> list:
    return sorted(printer.used, key=lambda a: a.sort_key())


def legend_remarks(printer) -> list[str]:
    """What a reader of the legend must be told about the labels the printer has written."""
    used = printer.used
    remarks = []
    if any(sign < 0 for a in used for _, sign in a.indices):
        remarks.append("a bar over a joint number marks an angle that is subtracted")
    if any(isinstance(label, str) and len(label) > 1 and label[0].isalpha() for a in used for label, _ in a.indices):
        remarks.append("each index names its joint angle, and commas separate them")
    elif any(a.wide for a in used):
        remarks.append("commas separate the joint numbers when one of them has two digits")
    return remarks


def text_legend(printer: TextPrinter, width: int = 100) -> str:
    """`where c1 = cos θ1, s1 = sin θ1, ...`, wrapped at `width`; an entry longer than a line
    is broken like an element."""
    entries = legend_entries(printer, printer.style)
    if not entries:
        return ""
    lines, line, indent = [], "where", "      "
    for position, (label, meaning) in enumerate(entries):
        entry = f"{label} = {meaning}" + ("," if position < len(entries) - 1 else "")
        if display_width(line) + 1 + display_width(entry) <= width:
            line += " " + entry
            continue
        if line.strip() != "where":
            lines.append(line)
            line = indent[:-1]
        if display_width(line) + 1 + display_width(entry) > width:
            broken = break_element(indent + f"{label} = ", meaning, width).splitlines()
            broken[-1] += entry[len(label) + 3 + len(meaning):]
            broken[0] = (line + " " + broken[0].lstrip())
            lines += broken[:-1]
            line = broken[-1]
        else:
            line += " " + entry
    return "\n".join(lines + [line])


def table_columns(convention: str) -> list[tuple[str, str, str]]:
    """(row field, unicode header, LaTeX header) in the order the convention's books use."""
    if convention == "modified":
        return [("alpha", "αᵢ₋₁", "\\alpha_{i-1}"), ("a", "aᵢ₋₁", "a_{i-1}"), ("d", "dᵢ", "d_i"),
                ("theta", "θᵢ", "\\theta_i")]
    return [("theta", "θᵢ", "\\theta_i"), ("d", "dᵢ", "d_i"), ("a", "aᵢ", "a_i"), ("alpha", "αᵢ", "\\alpha_i")]


def text_table(robot: Robot, ascii: bool = False) -> str:
    """The DH table in the convention's column order, rows numbered as the robot's joints (4..6
    for a wrist whose frames are 3..6); * marks each joint variable."""
    chain = robot.chain
    printer = text_printer(robot, ascii=ascii, marked=chain.joint_variables)
    columns = table_columns(chain.convention)
    headers = ["i"] + [_ascii_header(header) if ascii else header for field, header, _ in columns]
    body = [[str(n)] + [printer.doprint(getattr(row, field)) for field, _, _ in columns]
            for n, row in zip(robot.numbering.joints(chain), chain.rows)]
    widths = [max(len(r[k]) for r in [headers] + body) for k in range(len(headers))]
    separator = " | " if ascii else " │ "
    lines = [separator.join(cell.ljust(w) for cell, w in zip(line, widths)).rstrip() for line in [headers] + body]
    return "\n".join(lines)


def _ascii_header(header: str) -> str:
    """αᵢ₋₁ -> alpha(i-1), θᵢ -> theta(i)."""
    return header[0].translate(_ASCII) + "(" + header[1:].translate(_ASCII_SUBSCRIPTS) + ")"


def latex_matrix(matrix: sympy.Matrix, printer: LatexPrinter) -> str:
    return bmatrix([[printer.doprint(matrix[r, c]) for c in range(matrix.cols)] for r in range(matrix.rows)])


def bmatrix(cells) -> str:
    """A bmatrix of cells that are already LaTeX (element names or printed expressions)."""
    return "\\begin{bmatrix}\n" + " \\\\\n".join(" & ".join(row) for row in cells) + "\n\\end{bmatrix}"


def latex_table(robot: Robot) -> str:
    """The DH table of a robot as a LaTeX array; joint variables carry a star."""
    return latex_array(*latex_table_cells(robot, latex_printer(robot, marked=robot.chain.joint_variables)))


def latex_table_cells(robot: Robot, printer: LatexPrinter) -> tuple[list[str], list[list[str]]]:
    """The header and the rows of the DH table as LaTeX cells, written by `printer`; rows numbered
    as the robot's joints."""
    chain = robot.chain
    columns = table_columns(chain.convention)
    header = ["i"] + [latex for _, _, latex in columns]
    rows = [[str(n)] + [printer.doprint(getattr(row, f)) for f, _, _ in columns]
            for n, row in zip(robot.numbering.joints(chain), chain.rows)]
    return header, rows


def latex_array(header: list[str], rows: list[list[str]]) -> str:
    """A DH table (or part of one) as an array with a rule under its header."""
    body = " & ".join(header) + " \\\\\n\\hline\n" + " \\\\\n".join(" & ".join(row) for row in rows)
    return "\\begin{array}{c|" + "c" * (len(header) - 1) + "}\n" + body + "\n\\end{array}"


def json_result(robot: Robot, i: Frame, j: Frame, matrix: sympy.Matrix) -> dict:
    """A result any SymPy user can read back: full cos/sin, the robot file's symbol names; `i`,
    `j` are the chain's frames, written with the robot's numbers."""
    printer, exact = text_printer(robot, ascii=True), exact_printer(robot)
    for element in matrix:
        printer.doprint(element)  # collects the abbreviations the text form uses
    return {
        "robot": robot.name,
        "convention": robot.chain.convention,
        "from": robot.numbering.frame(i),
        "to": robot.numbering.frame(j),
        "joint_variables": [s.name for s in robot.chain.joint_variables],
        "matrix": [[exact.doprint(matrix[r, c]) for c in range(4)] for r in range(4)],
        "abbreviations": dict(legend_entries(printer, "sympy")),
    }
