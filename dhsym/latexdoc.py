"""`dhsym latex`: the DH table, the link matrices, the derivation and the result as beamer
slides, an article or a snippet of math, laid out so that everything fits its page.

Layout rules (widths are estimated from Computer Modern glyph widths by `math_width`, which
stays within 2 % of TeX's own measure; 3 % of every line is kept free):

* A matrix is a ``bmatrix`` at the body size when it fits the line. Nothing is ever shrunk.
* Otherwise the matrix is named, ``{}^0T_6 = [r_{11} … p_z; 0 0 0 1]``, and its elements
  follow column by column as in Craig and Spong (r_{11}, r_{21}, r_{31}, r_{12}, …, p_z).
* An element wider than the line breaks before a ``+`` or ``-``, at the outermost bracket
  level that leaves the line at least half full; continuation lines are indented by a quad.
* Slides: blocks are packed into frames by estimated height. A matrix column of elements
  stays on one frame; a full frame continues on the next, titled "(cont.)".
* ``--steps``: a step writes its two factor matrices out only when both factors and the
  product fit the line as matrices; otherwise it names them.
* Notation: c_{23} = cos(θ2 + θ3); a bar marks a subtracted angle, c_{12\\bar{4}}; when a joint
  number has two digits the indices are separated by commas, c_{1,10}, and frames are
  always braced, {}^{9}T_{10}.

Pages: slides are beamer 16:9 at 11 pt (398 pt wide); the article is A4 at 11 pt with 25 mm
margins (455 pt); a snippet fits a plain ``article`` at 10 pt (345 pt) with ``amsmath``.

>>> from dhsym.library import load
>>> tex = document(load("planar2r"), "snippet")
>>> "{}^{0}T_{2} = {}^{0}T_{1}\\\\,{}^{1}T_{2} =" in tex and "a_{1} c_{1} + a_{2} c_{12}" in tex
True
"""
from __future__ import annotations

import unicodedata
from dataclasses import dataclass, field
from itertools import pairwise

from sympy.printing.pretty.pretty_symbology import greek_unicode

from .errors import UserError
from .output import write_atomic
from .printing import LatexPrinter
from .render import ELEMENT_NAMES, table_columns, transform_title

NAME = "latex"
DOCUMENTS = ("slides", "article", "snippet")


# ---------------------------------------------------------------- pages and measured heights

@dataclass(frozen=True)
class Page:
    """Line width and font size in pt; the height a frame offers under its title (None where
    pages break by themselves)."""

    width_pt: float
    font_pt: float
    height_pt: float | None = None

    @property
    def width(self) -> float:
        """The line width in em that the layout may fill."""
        return self.width_pt / self.font_pt * 0.97

    def em(self, points: float) -> float:
        return points / self.font_pt


PAGES = {"slides": Page(398.3, 10.95, 222.0), "article": Page(455.2, 10.95), "snippet": Page(345.0, 10.0)}

# Measured with pdflatex in a beamer frame at 11 pt (pt): a row of `aligned` and of a matrix
# or array (taller with a \frac), a line of text, what a display adds (the first on a frame,
# each further one), the space between element columns; both bmatrix brackets; the column gap.
ALIGNED_ROW, ALIGNED_FRACTION_ROW, ARRAY_ROW, ARRAY_FRACTION_ROW = 16.6, 28.5, 13.6, 16.6
TEXT_LINE, FIRST_DISPLAY, NEXT_DISPLAY, COLUMN_SKIP = 13.6, 16.0, 4.5, 4.0
BRACKETS_PT, COLUMN_GAP_PT = 13.4, 10.0
ALIGNED_EXTRA, LEGEND_GAP, TEXT_CHARACTER = 1.0, 2.0, 0.5  # em: around `&=`, between entries, per character


# ---------------------------------------------------------------- width of a math string

_ITALIC = dict(zip("abcdefghijklmnopqrstuvwxyz",
                   (.529, .429, .433, .520, .466, .490, .477, .576, .345, .412, .521, .298, .878,
                    .600, .485, .503, .446, .451, .469, .361, .572, .485, .716, .572, .490, .465), strict=True))
_GREEK_WIDTH = {"alpha": .640, "beta": .566, "gamma": .518, "delta": .444, "epsilon": .406, "varepsilon": .466,
                "zeta": .438, "eta": .497, "theta": .469, "vartheta": .592, "iota": .354, "kappa": .576,
                "lambda": .583, "mu": .603, "nu": .494, "xi": .438, "pi": .600, "varpi": .829, "rho": .517,
                "sigma": .571, "tau": .437, "upsilon": .540, "phi": .596, "varphi": .654, "chi": .626,
                "psi": .651, "omega": .622}
_OPERATOR_NAMES = {"cos": 1.338, "sin": 1.228, "tan": 1.339}
_SPACES = {",": .167, ";": .278, ":": .222, "!": -.167, "quad": 1.0, "qquad": 2.0}
_BINARY, _RELATION, _SCRIPT = .778 + 2 * .222, .778 + 2 * .278, 0.8  # + and = with their spaces


def math_width(tex: str, display: bool = False) -> float:
    """Estimated width in em of inline math `tex` (fractions in display style if `display`).

    >>> round(math_width("c_{1} + s_{23}"), 2), math_width("c_{1}") < math_width("c_{12}")
    (3.42, True)
    """
    return _Measure(tex).group(1.0, display)


class _Measure:
    """A small reader of the LaTeX the printers write: glyphs, scripts, \\frac, \\sqrt, spaces."""

    def __init__(self, tex: str):
        self.tex, self.i = tex, 0

    def group(self, scale: float, display: bool) -> float:
        """Width up to the closing brace of the current group, or the end."""
        total, operand, script = 0.0, False, None
        while self.i < len(self.tex):
            ch = self.tex[self.i]
            self.i += 1
            if ch == "}":
                break
            if ch.isspace():
                continue
            if ch in "_^":  # a subscript and a superscript on one base stack: count the wider
                width = self.argument(scale * _SCRIPT)
                total += width + .05 * scale if script is None else max(0.0, width - script)
                script = width if script is None else max(script, width)
                continue
            script = None
            if ch == "{":
                total, operand = total + self.group(scale, display), True
            elif ch == "\\":
                width, operand = self.command(scale, display, operand)
                total += width
            elif ch in "+-=":  # spaced as a binary operator or relation, except in scripts
                spaced = _RELATION if ch == "=" else _BINARY if operand else .778
                total, operand = total + (spaced if scale == 1 else .778) * scale, False
            elif ch == ",":
                total, operand = total + .445 * scale, False
            else:
                total, operand = total + _glyph(ch) * scale, ch not in "(["
        return total

    def argument(self, scale: float) -> float:
        while self.i < len(self.tex) and self.tex[self.i].isspace():
            self.i += 1
        if self.i >= len(self.tex):
            return 0.0
        ch = self.tex[self.i]
        self.i += 1
        if ch == "{":
            return self.group(scale, False)
        return self.command(scale, False, False)[0] if ch == "\\" else _glyph(ch) * scale

    def command(self, scale: float, display: bool, operand: bool) -> tuple[float, bool]:
        """(width, whether an operand ends here) of the command after a backslash."""
        start = self.i
        while self.i < len(self.tex) and self.tex[self.i].isalpha():
            self.i += 1
        self.i += self.i == start  # a one-character command such as \, or \{
        name = self.tex[start:self.i]
        if name.lower() in _GREEK_WIDTH:
            return _GREEK_WIDTH.get(name, .75) * scale, True
        if name in _SPACES:
            return _SPACES[name] * scale, operand
        if name == "frac":
            inner = scale if display else scale * _SCRIPT
            return max(self.argument(inner), self.argument(inner)) + .24 * scale, True
        if name == "sqrt":
            return self.argument(scale) + .833 * scale, True
        if name in ("bar", "hat", "vec", "mathit", "mathbf"):
            return self.argument(scale), True
        if name in ("mathrm", "text", "operatorname"):
            before = self.i
            self.argument(scale)
            return .52 * sum(ch.isalnum() for ch in self.tex[before:self.i]) * scale, True
        if name in _OPERATOR_NAMES:
            return (_OPERATOR_NAMES[name] + 2 * .167) * scale, False
        if name in ("{", "}"):
            return .5 * scale, name == "}"
        if name in ("left", "right"):
            return 0.0, operand
        return 1.0 * scale, True


def _glyph(ch: str) -> float:
    if ch in _ITALIC:
        return _ITALIC[ch]
    if ch.isdigit():
        return .5
    return .8 if ch.isupper() else {"(": .389, ")": .389, "[": .278, "]": .278, "|": .278, "*": .5}.get(ch, .6)


# ---------------------------------------------------------------- breaking a long element

def break_points(tex: str) -> list[tuple[int, int]]:
    """(position, bracket depth) of each ' + ' / ' - ' outside any {…} group.

    >>> break_points("c_{1}[a + b] - s_{2}")
    [(7, 1), (12, 0)]
    """
    points, braces, brackets, i = [], 0, 0, 0
    while i < len(tex):
        if tex.startswith(("\\{", "\\}"), i):  # brackets that print, not TeX groups
            brackets += 1 if tex[i + 1] == "{" else -1
            i += 2
            continue
        braces += (tex[i] == "{") - (tex[i] == "}")
        brackets += (tex[i] in "([") - (tex[i] in ")]")
        if braces == 0 and tex.startswith((" + ", " - "), i):
            points.append((i, brackets))
        i += 1
    return points


def break_lines(tex: str, first: float, rest: float) -> list[str]:
    """Split `tex` before '+'/'-' into lines of at most `first`, then `rest` em; the later
    lines start with their sign (TeX does not mind brackets left open on a line).

    >>> break_lines("a + b + c", 3, 3)
    ['a + b', '+ c']
    """
    points, lines, start, width = break_points(tex), [], 0, first
    while math_width(("{}" if lines else "") + tex[start:]) > width:
        prefix = "{}" if lines else ""
        later = [(i, depth) for i, depth in points if i > start]
        if not later:
            break  # one term wider than the line: nothing left to break
        fitting = [(i, depth) for i, depth in later if math_width(prefix + tex[start:i]) <= width] or later[:1]
        outermost = min(depth for _, depth in fitting)
        cut = max(i for i, depth in fitting if depth == outermost)
        if math_width(prefix + tex[start:cut]) < width / 2:  # too short a line: fill it instead
            cut = max(i for i, _ in fitting)
        lines.append(tex[start:cut])
        start, width = cut + 1, rest
    return lines + [tex[start:]]


# ---------------------------------------------------------------- blocks of a document

@dataclass
class Block:
    """A display or a paragraph, with its estimated height in pt."""

    latex: str
    height: float
    is_display: bool = True
    keep_with_next: bool = False
    alone: tuple[str, str] | None = None  # (frame title, latex) when this block starts a frame


@dataclass
class Rows:
    """Rows of `aligned`: columns of elements of lines, each line (latex, height). A frame
    breaks between columns if it can, else between elements, else between lines."""

    columns: list
    keep_with_next: bool = False

    @property
    def height(self) -> float:
        return sum(height for column in self.columns for element in column for _, height in element)


@dataclass
class Section:
    """One frame's worth of content before packing (it may need several frames)."""

    part: str  # heading that groups sections in an article: "DH table", "Link matrices", …
    title: str  # frame title, LaTeX text with math in $…$
    items: list = field(default_factory=list)  # Blocks and Rows


def _display(body: str, height: float) -> Block:
    return Block(f"\\[\n{body}\n\\]", height)


def _text(latex: str, page: Page) -> Block:
    return Block(latex, (int(len(latex) * TEXT_CHARACTER / page.width) + 1) * TEXT_LINE, is_display=False)


def _row_height(cells, array: bool) -> float:
    fraction = any("\\frac" in cell for cell in cells)
    if array:
        return ARRAY_FRACTION_ROW if fraction else ARRAY_ROW
    return ALIGNED_FRACTION_ROW if fraction else ALIGNED_ROW


# ---------------------------------------------------------------- matrices

def bmatrix(cells) -> str:
    return "\\begin{bmatrix}\n" + " \\\\\n".join(" & ".join(row) for row in cells) + "\n\\end{bmatrix}"


def bmatrix_width(cells, page: Page) -> float:
    columns = [max(math_width(row[c]) for row in cells) for c in range(len(cells[0]))]
    return sum(columns) + page.em(BRACKETS_PT + COLUMN_GAP_PT * (len(columns) - 1))


def _matrix_height(cells) -> float:
    return 3.0 + sum(_row_height(row, array=True) for row in cells)


def element_name(row: int, column: int) -> str:
    """r_{11} … r_{33}, p_{x} p_{y} p_{z}."""
    name = ELEMENT_NAMES[row][column]
    return f"{name[0]}_{{{name[1:]}}}"


def matrix_items(lhs: str, cells, page: Page, short_lhs: str | None = None) -> list:
    """`lhs = [matrix]` as one display when it fits the line, else the named matrix and its
    elements column by column. `short_lhs` replaces `lhs` where the full one is too wide."""
    if math_width(lhs + " =") + bmatrix_width(cells, page) <= page.width:
        return [_display(f"{lhs} =\n{bmatrix(cells)}", _matrix_height(cells))]
    names = [[element_name(r, c) for c in range(4)] for r in range(3)] + [cells[3]]
    if short_lhs and math_width(lhs + " =") + bmatrix_width(names, page) > page.width:
        lhs = short_lhs
    columns = [[element_rows(names[r][c], cells[r][c], page) for r in range(3)] for c in range(4)]
    return [_display(f"{lhs} =\n{bmatrix(names)}", _matrix_height(names)), Rows(columns)]


def element_rows(label: str, tex: str, page: Page) -> list[tuple[str, float]]:
    """`label &= tex` as lines of an aligned block, broken when wider than the page."""
    first = page.width - math_width(label + " =") - ALIGNED_EXTRA
    lines = break_lines(tex, first, first - 1.0)
    rows = [f"{label} &= {lines[0]}"] + [f"&\\quad {{}}{line}" for line in lines[1:]]
    return [(row, _row_height([row], array=False)) for row in rows]


def step_items(name: str, product: str, factors, result, page: Page) -> list:
    """`name = product = [A][B] = [C]` when all three matrices fit, else `matrix_items`."""
    first = math_width(f"{name} = {product} =") + sum(bmatrix_width(f, page) for f in factors) + ALIGNED_EXTRA
    second = math_width(f"{name} =") + bmatrix_width(result, page) + ALIGNED_EXTRA
    if first > page.width or second > page.width:
        return matrix_items(f"{name} = {product}", result, page, short_lhs=name)
    body = (f"\\begin{{aligned}}\n{name} &= {product} =\n" + "\n".join(bmatrix(f) for f in factors)
            + f" \\\\\n&= {bmatrix(result)}\n\\end{{aligned}}")
    return [_display(body, max(_matrix_height(f) for f in factors) + _matrix_height(result) + 3.0)]


# ---------------------------------------------------------------- what a document shows

def sections(robot, start, end, steps: bool, page: Page, printer: LatexPrinter) -> list[Section]:
    """Everything but the title, in order: table, links, steps, result with its legend."""
    chain = robot.chain
    path = _frame_path(chain.frames, start, end)

    def cells(i, j):
        matrix = chain.transform(i, j)
        return [[printer.doprint(matrix[r, c]) for c in range(4)] for r in range(4)]

    def title(i, j):
        return transform_title(i, j, "latex")

    out = [_table_section(robot, page)]
    for i, j in pairwise(path):
        out.append(Section("Link matrices", f"{_link_label(i, j)}: ${title(i, j)}$",
                           matrix_items(title(i, j), cells(i, j), page)))
    for k in range(2, len(path)) if steps else ():
        first, before, here = path[0], path[k - 1], path[k]
        out.append(Section("Derivation step by step", f"Step {k - 1}: ${title(first, here)}$",
                           step_items(title(first, here), f"{title(first, before)}\\,{title(before, here)}",
                                      [cells(first, before), cells(before, here)], cells(first, here), page)))
    # The result once more, with the product it comes from (when it is short) and the legend.
    product = "\\,".join(title(i, j) for i, j in pairwise(path))
    lhs = title(start, end) + (f" = {product}" if len(path) > 2 else "")
    out.append(Section("Result", f"Result: ${title(start, end)}$",
                       matrix_items(lhs, cells(start, end), page, short_lhs=title(start, end))))
    out[-1].items.extend(legend_items(printer, page))
    return out


def _frame_path(frames, start, end) -> list:
    first, last = frames.index(start), frames.index(end)
    return frames[first:last + 1] if first < last else frames[last:first + 1][::-1]


def _link_label(i, j) -> str:
    if "base" in (i, j) or "tool" in (i, j):
        return "Base" if "base" in (i, j) else "Tool"
    return f"Link {max(i, j)}" + (" (inverse)" if i > j else "")


def _table_section(robot, page: Page) -> Section:
    """The DH table in the convention's column order, the convention, base and tool steps."""
    chain = robot.chain
    printer = _InlineFractions(chain.joint_variables, marked=chain.joint_variables)
    columns = table_columns(robot)
    header = " & ".join(["i"] + [latex for _, _, latex in columns])
    rows = [[str(n)] + [printer.doprint(getattr(row, f)) for f, _, _ in columns] for n, row in enumerate(chain.rows, 1)]
    notes = [_text(CONVENTION_LATEX[chain.convention], page),
             _text("${}^{*}$ marks the joint variable of each row.", page)]
    for which, steps, i, j in (("base", chain.base, "base", 0), ("tool", chain.tool, chain.n, "tool")):
        if steps:
            motions = "\\,".join(f"{s.kind[0]}_{{{s.kind[1]}}}({printer.doprint(s.value)})" for s in steps)
            notes.append(_text(f"Fixed {which} transform: ${transform_title(i, j, 'latex')} = {motions}$.", page))
    per_block = len(rows)
    if page.height_pt:  # a long table continues on the next frame
        room = page.height_pt - FIRST_DISPLAY - NEXT_DISPLAY * len(notes) - sum(n.height for n in notes)
        per_block = max(3, int((room - 3.0 - ARRAY_ROW) / ARRAY_ROW))
    items = []
    for first in range(0, len(rows), per_block):
        chunk = rows[first:first + per_block]
        body = header + " \\\\\n\\hline\n" + " \\\\\n".join(" & ".join(r) for r in chunk)
        items.append(_display("\\begin{array}{c|cccc}\n" + body + "\n\\end{array}",
                              3.0 + ARRAY_ROW + sum(_row_height(r, array=True) for r in chunk)))
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


def legend_items(printer: LatexPrinter, page: Page) -> list:
    """'where c_{1} = \\cos θ_1, s_{1} = …' for exactly the abbreviations used: single angles,
    then sums of angles, each an aligned block with as many entries per row as fit (cos and
    sin of one angle side by side). A block may continue on the next frame."""
    if not printer.used:
        return []
    used = sorted(printer.used, key=lambda a: a.sort_key())
    notes = []
    if any(sign < 0 for a in used for _, sign in a.indices):
        notes.append("a bar over a joint number marks an angle that is subtracted")
    if any(number >= 10 for a in used for number, _ in a.indices):
        notes.append("commas separate the joint numbers when one of them has two digits")
    remark = f" ({'; '.join(notes)})" if notes else ""
    items: list = [Block(f"where{remark}", TEXT_LINE * (1 + len(notes)), is_display=False, keep_with_next=True,
                         alone=("Notation", f"Abbreviations{remark}:"))]
    for group in ([a for a in used if len(a.indices) == 1], [a for a in used if len(a.indices) > 1]):
        if group:
            items.append(Rows([_legend_rows(group, printer, page)], keep_with_next=True))
    items[-1].keep_with_next = False
    return items


def _legend_rows(abbreviations, printer: LatexPrinter, page: Page) -> list:
    entries = [(a.label("latex"), printer.notation.meaning(a, "latex")) for a in abbreviations]
    widest = max(math_width(f"{label} = {meaning}") for label, meaning in entries) + LEGEND_GAP
    per_row = max(1, int((page.width - ALIGNED_EXTRA + LEGEND_GAP) // widest))
    if per_row == 1:  # and a very long sum of angles breaks like a matrix element
        return [element_rows(label, meaning, page) for label, meaning in entries]
    per_row -= per_row % 2  # cos and sin of one angle on one row
    return [[(" & ".join(f"{label} &= {meaning}" for label, meaning in entries[k:k + per_row]), ALIGNED_ROW)]
            for k in range(0, len(entries), per_row)]


# ---------------------------------------------------------------- packing slides into frames

def pack(items: list, capacity: float) -> list[list[Block]]:
    """Blocks and `Rows` into frames of `capacity` pt. What fits an empty frame is never split;
    the rows of one `Rows` that share a frame form one `aligned` display."""
    frames = _Frames(capacity)
    for position, item in enumerate(items):
        if isinstance(item, Rows):
            frames.fresh_run = True
            _place(frames, item.columns, level=0)
            continue
        whole, least = _kept_height(items, position, capacity)
        room = frames.room(rows=False)
        if not frames.empty and (least > room or room < whole <= capacity - FIRST_DISPLAY):
            frames.new()
        frames.frames[-1].append(item)
    return frames.blocks()


def _place(frames: _Frames, node, level: int) -> None:
    """The lines under `node` (level 0: all columns, 1: a column, 2: an element, 3: a line)."""
    lines = _lines(node, level)
    height = sum(line[1] for line in lines)
    if height <= frames.room(rows=True):
        frames.add_rows(lines)
    elif not frames.empty and (height <= frames.capacity - FIRST_DISPLAY or level == 3):
        frames.new()
        frames.add_rows(lines)
    elif level == 3:
        frames.add_rows(lines)  # one line taller than a frame: nothing smaller to move
    else:
        for child in node:
            _place(frames, child, level + 1)


def _lines(node, level: int) -> list[tuple[str, float, str]]:
    """(latex, height, what it starts: "line", "element" or "column") for each line under `node`."""
    if level == 3:
        return [(*node, "line")]
    if level == 2:
        return [(*line, "element" if n == 0 else "line") for n, line in enumerate(node)]
    if level == 1:
        lines = [line for element in node for line in _lines(element, 2)]
        return [(lines[0][0], lines[0][1] + COLUMN_SKIP, "column")] + lines[1:]
    return [line for column in node for line in _lines(column, 1)]


def _kept_height(items, position: int, capacity: float) -> tuple[float, float]:
    """(whole, least): the height of a block with all that must follow it on its frame, and
    with only the first column of the rows among them ("where" stays with its legend)."""
    whole, least = 0.0, None
    for item in items[position:]:
        if isinstance(item, Rows) and least is None:  # _place keeps a column together if it can
            column = sum(line[1] for line in _lines(item.columns[0], 1))
            least = whole + NEXT_DISPLAY + (column if column <= capacity - FIRST_DISPLAY else ALIGNED_ROW)
        whole += item.height + (NEXT_DISPLAY if isinstance(item, Rows) or item.is_display else 0.0)
        if not item.keep_with_next:
            break
    return whole, whole if least is None else least


class _Frames:
    """Frames being filled, each a list of Blocks and of runs of aligned lines."""

    def __init__(self, capacity: float):
        self.capacity, self.frames, self.fresh_run = capacity, [[]], False

    @property
    def empty(self) -> bool:
        return not self.frames[-1]

    def room(self, rows: bool) -> float:
        used, entries = 0.0, self.frames[-1]
        for n, entry in enumerate(entries):
            run = isinstance(entry, list)
            height = sum(line[1] for line in entry) if run else entry.height
            used += height + (NEXT_DISPLAY if n else FIRST_DISPLAY) * (run or entry.is_display)
        joins_run = rows and entries and isinstance(entries[-1], list) and not self.fresh_run
        return self.capacity - used - (0.0 if joins_run else NEXT_DISPLAY if entries else FIRST_DISPLAY)

    def new(self) -> None:
        self.frames.append([])
        self.fresh_run = True

    def add_rows(self, lines) -> None:
        if self.fresh_run or not (self.frames[-1] and isinstance(self.frames[-1][-1], list)):
            self.frames[-1].append([])
        self.fresh_run = False
        self.frames[-1][-1].extend(lines)

    def blocks(self) -> list[list[Block]]:
        out = []
        for number, entries in enumerate(f for f in self.frames if f):
            blocks = [_aligned(entry) if isinstance(entry, list) else entry for entry in entries]
            if number and blocks[0].alone:
                blocks[0] = Block(blocks[0].alone[1], blocks[0].height, blocks[0].is_display, alone=blocks[0].alone)
            out.append(blocks)
        return out


def _aligned(lines, environment: str = "aligned") -> Block:
    """Lines as one display, a little space before each new column. In `align*` (article,
    snippet) a page may break between elements."""
    body = lines[0][0]
    for latex, _, starts in lines[1:]:
        allow_break = "\\displaybreak[0]" if environment == "align*" and starts != "line" else ""
        body += f"{allow_break} \\\\" + (f"[{COLUMN_SKIP:g}pt]" if starts == "column" else "") + "\n" + latex
    latex = f"\\begin{{{environment}}}\n{body}\n\\end{{{environment}}}"
    return Block(f"\\[\n{latex}\n\\]" if environment == "aligned" else latex, sum(line[1] for line in lines))


# ---------------------------------------------------------------- the three documents

def document(robot, kind: str = "slides", steps: bool = False, start=None, end=None) -> str:
    """The LaTeX text of a document of `kind` for `robot`, about the transform from frame
    `start` (default: the first) to `end` (default: the last)."""
    chain = robot.chain
    start = _check_frame(chain, chain.first_frame if start is None else start, "--from")
    end = _check_frame(chain, chain.last_frame if end is None else end, "--to")
    if start == end:
        raise UserError(f"--from and --to name the same frame ({start}); choose two different frames")
    page = PAGES[kind]
    content = sections(robot, start, end, steps, page, LatexPrinter(chain.joint_variables))
    return {"slides": _slides, "article": _article, "snippet": _snippet}[kind](robot, content, page)


def _check_frame(chain, frame, option: str):
    if isinstance(frame, str) and frame.lstrip("-").isdigit():
        frame = int(frame)
    if frame not in chain.frames:
        raise UserError(f"{option}: no frame {frame!r} in this robot; frames are "
                        + ", ".join(str(f) for f in chain.frames))
    return frame


def _subtitle(robot) -> str:
    return f"Forward kinematics, {robot.chain.convention} DH convention"


def _slides(robot, content: list[Section], page: Page) -> str:
    out = [SLIDES_PREAMBLE, "\\begin{document}\n",
           "\\begin{frame}[plain]\n\\centering\n{\\usebeamerfont{title}\\usebeamercolor[fg]{title}"
           f"{tex_text(robot.name)}\\par}}\n\\bigskip\n{tex_text(_subtitle(robot))}\\par\n"
           f"\\vfill\n{{\\small\\raggedright Source: {tex_text(robot.source or 'not given')}\\par}}\n"
           "\\end{frame}\n"]
    for section in content:
        title = section.title
        for number, blocks in enumerate(pack(section.items, page.height_pt)):
            if number:
                title = blocks[0].alone[0] if blocks[0].alone else title.removesuffix(" (cont.)") + " (cont.)"
            out.append(f"\\begin{{frame}}{{{title}}}\n" + _join(blocks) + "\n\\end{frame}\n")
    out.append("\\end{document}\n")
    return "\n".join(out)


def _article(robot, content: list[Section], page: Page) -> str:
    out = [ARTICLE_PREAMBLE, "\\begin{document}\n", f"\\section*{{{tex_text(robot.name)}}}\n",
           f"{tex_text(_subtitle(robot))}.\n\nSource: {tex_text(robot.source or 'not given')}\n"]
    if robot.notes:
        out.append(f"Notes: {tex_text(robot.notes)}\n")
    part = None
    for section in content:
        if section.part != part:
            part = section.part
            out.append(f"\\subsection*{{{part}}}\n")
        out.extend([_join(_flat(section.items)), ""])
    out.append("\\end{document}\n")
    return "\n".join(out)


def _snippet(robot, content: list[Section], page: Page) -> str:
    """Only the math; titles and text become comments."""
    out = [f"% dhsym latex: {_comment(robot.name)} ({robot.chain.convention} DH); needs \\usepackage{{amsmath}}",
           f"% Source: {_comment(robot.source or 'not given')}"]
    for section in content:
        out.append(f"\n% {_comment(section.title)}")
        out.extend(block.latex if block.is_display else f"% {_comment(block.latex)}" for block in _flat(section.items))
    return "\n".join(out) + "\n"


def _join(blocks: list[Block]) -> str:
    return "\n".join(b.latex if b.is_display else b.latex + "\\par" for b in blocks)


def _flat(items) -> list[Block]:
    """Blocks in order; each `Rows` becomes one align* that pages may break."""
    return [item if isinstance(item, Block) else _aligned(_lines(item.columns, 0), "align*") for item in items]


SLIDES_PREAMBLE = r"""% Made by dhsym latex. Compile with pdflatex (beamer, lmodern).
\documentclass[11pt,aspectratio=169]{beamer}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usefonttheme[onlymath]{serif}
\setbeamertemplate{navigation symbols}{}
\setbeamertemplate{footline}{\hfill\usebeamerfont{page number in head/foot}\insertframenumber\hspace{2em}\vspace{1ex}}
"""

ARTICLE_PREAMBLE = r"""% Made by dhsym latex. Compile with pdflatex.
\documentclass[11pt,a4paper]{article}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usepackage{amsmath}
\usepackage[margin=25mm]{geometry}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5\baselineskip}
"""


# ---------------------------------------------------------------- text from robot files

_TEXT_ESCAPES = {"\\": "\\textbackslash{}", "&": "\\&", "%": "\\%", "$": "\\$", "#": "\\#", "_": "\\_",
                 "{": "\\{", "}": "\\}", "~": "\\textasciitilde{}", "^": "\\textasciicircum{}",
                 "−": "$-$", "→": "$\\to$", "×": "$\\times$", "±": "$\\pm$", "≤": "$\\leq$", "≥": "$\\geq$",
                 "≈": "$\\approx$", "°": "\\textdegree{}", "…": "\\dots{}", "–": "--", "—": "---",
                 "‘": "`", "’": "'", "“": "``", "”": "''"}
_GREEK_LETTERS = {letter: name for name, letter in greek_unicode.items()}
_GREEK_COMMANDS = {name for name in greek_unicode if name.islower() and name not in ("omicron", "lamda")} | {
    "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega"}


def tex_text(text: str) -> str:
    """Free text of a robot file (name, source, notes) as LaTeX text that always compiles.

    >>> tex_text("θ1 & 50% of a_2 — Craig")
    '$\\\\theta$1 \\\\& 50\\\\% of a\\\\_2 --- Craig'
    """
    out = []
    for ch in text:
        if ch in _TEXT_ESCAPES:
            out.append(_TEXT_ESCAPES[ch])
        elif ch in _GREEK_LETTERS:
            name = _GREEK_LETTERS[ch]
            out.append(f"$\\{name}$" if name in _GREEK_COMMANDS else name[0])
        elif ch.isascii() or unicodedata.name(ch, "").startswith("LATIN"):
            out.append(ch if ch.isprintable() else " ")
        else:
            out.append("?")  # a symbol pdflatex's default fonts may lack
    return "".join(out)


def _comment(text: str) -> str:
    """Text for a LaTeX comment: one line (a newline would end the comment)."""
    return " ".join(text.split())


# ---------------------------------------------------------------- the command

def add_parser(commands) -> None:
    from .cli import add_common_options  # here, not at the top: cli imports this module

    sub = commands.add_parser(NAME, help="write LaTeX: beamer slides, an article or a snippet",
                              description="Write the DH table, every link matrix and the result as LaTeX that "
                              "compiles with pdflatex: beamer slides (16:9), an article, or a snippet of math "
                              "for a document with amsmath. Matrices too wide for the page are written "
                              "element by element (r_11 ... p_z), never shrunk.")
    sub.add_argument("robot", metavar="ROBOT", help="built-in robot name or path to a robot YAML file")
    sub.add_argument("--document", choices=DOCUMENTS, default="slides", help="what to write (default slides)")
    sub.add_argument("--steps", action="store_true",
                     help="derive the result step by step: 0T2 = 0T1 1T2, then 0T3 = 0T2 2T3, ...")
    sub.add_argument("--from", dest="start", metavar="F", help="start frame (default: base, else 0)")
    sub.add_argument("--to", dest="end", metavar="T", help="end frame (default: tool, else n)")
    sub.add_argument("-o", "--output", metavar="FILE", help="write to FILE (atomically) instead of standard output")
    add_common_options(sub)


def run(robot, args) -> str | None:
    text = document(robot, args.document, steps=args.steps, start=args.start, end=args.end)
    if args.output is None:
        return text
    write_atomic(args.output, text, inputs=[robot.path])
    return None
