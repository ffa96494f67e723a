r"""Laying out LaTeX math on a page that never shrinks anything: a matrix as a ``bmatrix`` or
as named elements, a long element broken over lines, rows of ``aligned``.

Rules (widths come from `texwidth.math_width`; 3 % of every line is kept free):

* A matrix is a ``bmatrix`` at the body size when it fits the line.
* Otherwise the matrix is named, ``{}^0T_6 = [r_{11} … p_z; 0 0 0 1]``, and its elements
  follow column by column as in Craig and Spong (r_{11}, r_{21}, r_{31}, r_{12}, …, p_z).
* An element wider than the line breaks before a ``+`` or ``-``, at the outermost bracket
  level that leaves the line at least half full; continuation lines are indented by a quad.
* A step ``{}^0T_3 = {}^0T_2\,{}^2T_3`` writes its two factor matrices out only when both
  factors and the product fit the line as matrices; otherwise it is laid out as its product.

Pages: slides are beamer 16:9 at 11 pt (398 pt wide); the article is A4 at 11 pt with 25 mm
margins (455 pt); a snippet (and ``fk --format latex``) fits a plain ``article`` at 10 pt
(345 pt) with ``amsmath``; a notebook line is taken as 54 em.
Heights are estimates in pt, measured once with pdflatex, so that slides can be packed.

>>> rotation = [["c_{1}", "- s_{1}", "0", "0"], ["s_{1}", "c_{1}", "0", "0"], ["0", "0", "1", "0"],
...             ["0", "0", "0", "1"]]
>>> [type(item).__name__ for item in matrix_items("{}^{0}T_{1}", rotation, PAGES["snippet"])]  # one bmatrix
['Block']
>>> element = " + ".join(f"a_{{{k}}} c_{{{k}}}" for k in range(1, 30))  # wider than the line
>>> named, elements = matrix_items("{}^{0}T_{6}", [[element] * 4] * 3 + [["0", "0", "0", "1"]], PAGES["snippet"])
>>> named.latex.splitlines()[3:5]  # the matrix of names; the elements follow on lines of their own
['r_{11} & r_{12} & r_{13} & p_{x} \\\\', 'r_{21} & r_{22} & r_{23} & p_{y} \\\\']
>>> len(elements.columns[0][0])  # r_{11} = a_{1} c_{1} + …, broken into lines
4
"""
from __future__ import annotations

import textwrap
from dataclasses import dataclass

from ..printing.render import ELEMENT_NAMES, bmatrix
from .width import math_width, prefix_widths

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


PAGES = {"slides": Page(398.3, 10.95, 222.0), "article": Page(455.2, 10.95), "snippet": Page(345.0, 10.0),
         "notebook": Page(560.0, 10.0)}  # 54 em: about 870 px of MathJax at 16 px, inside Jupyter's column

# Measured with pdflatex in a beamer frame at 11 pt (pt): a row of `aligned` and of a matrix
# or array (taller with a \frac), a line of text, what a display adds (the first on a frame,
# each further one), the space between element columns; both bmatrix brackets; the column gap.
ALIGNED_ROW, ALIGNED_FRACTION_ROW, ARRAY_ROW, ARRAY_FRACTION_ROW = 16.6, 28.5, 13.6, 16.6
TEXT_LINE, FIRST_DISPLAY, NEXT_DISPLAY, COLUMN_SKIP = 13.6, 16.0, 4.5, 4.0
BRACKETS_PT, COLUMN_GAP_PT, NESTED_FRACTION_EXTRA = 13.4, 10.0, 8.0
# Measured rows of `aligned`: \frac{\sqrt{2}}{4} 28.3 pt against 25.4 for \frac{5\pi}{12};
# 0.1 \sqrt{3} 18.0 pt against 16.3 for a row without a root
ROOT_FRACTION_EXTRA, ROOT_EXTRA = 3.0, 1.8
TALL_ELEMENT_PT = 400.0  # an element taller than this may break across pages (a page of text is 550 pt or more)
ALIGNED_EXTRA, LEGEND_GAP, TEXT_CHARACTER = 1.0, 2.0, 0.5  # em: around `&=`, between entries, per character


# ---------------------------------------------------------------- blocks of a document

@dataclass
class Block:
    """A display or a paragraph, with its estimated height in pt."""

    latex: str
    height: float
    is_display: bool = True
    keep_with_next: bool = False
    alone: tuple[str, str] | None = None  # (frame title, latex) when this block starts a frame
    math: str = ""  # a display's math without \[ \], to stack it with others in one display
    shows: tuple = ()  # the matrices a display shows, e.g. ("{}^{0}T_{1}",), to title its frame


@dataclass
class Rows:
    """Rows of `aligned`: columns of elements of lines, each line (latex, height). A frame
    breaks between columns if it can, else between elements, else between lines."""

    columns: list
    keep_with_next: bool = False

    @property
    def height(self) -> float:
        return sum(height for column in self.columns for element in column for _, height in element)


def display(body: str, height: float, shows: tuple = ()) -> Block:
    """`body` as displayed math, \\[ … \\]."""
    return Block(f"\\[\n{body}\n\\]", height, math=body, shows=shows)


def paragraph(latex: str, page: Page) -> Block:
    """A paragraph of text, its height estimated from its length."""
    return Block(latex, (int(len(latex) * TEXT_CHARACTER / page.width) + 1) * TEXT_LINE, is_display=False)


def row_height(cells, array: bool) -> float:
    """The height in pt of a row of a matrix or array (`array`) or of `aligned` (where a
    fraction inside a fraction is set in display style too, and taller)."""
    fraction = any("\\frac" in cell for cell in cells)
    if array:
        return ARRAY_FRACTION_ROW if fraction else ARRAY_ROW
    if any(_nested_fraction(cell) for cell in cells):
        return ALIGNED_FRACTION_ROW + NESTED_FRACTION_EXTRA
    if any(_root_in_fraction(cell) for cell in cells):
        return ALIGNED_FRACTION_ROW + ROOT_FRACTION_EXTRA
    if fraction:
        return ALIGNED_FRACTION_ROW
    return ALIGNED_ROW + (ROOT_EXTRA if any("\\sqrt" in cell for cell in cells) else 0.0)


def _nested_fraction(tex: str, inner: str = "\\frac") -> bool:
    start = tex.find("\\frac{")
    while start >= 0:
        groups, _ = _groups(tex, start + 5, 2)
        if any(inner in group for group in groups):
            return True
        start = tex.find("\\frac{", start + 1)
    return False


def _root_in_fraction(tex: str) -> bool:
    return _nested_fraction(tex, "\\sqrt")


def lines_under(node, level: int) -> list[tuple[str, float, str]]:
    """(latex, height, what it starts: "line", "element" or "column") for each line under `node`
    of a `Rows` (level 0: all its columns, 1: a column, 2: an element, 3: a line)."""
    if level == 3:
        return [(*node, "line")]
    if level == 2:
        return [(*line, "element" if n == 0 else "line") for n, line in enumerate(node)]
    if level == 1:
        lines = [line for element in node for line in lines_under(element, 2)]
        return [(lines[0][0], lines[0][1] + COLUMN_SKIP, "column")] + lines[1:]
    return [line for column in node for line in lines_under(column, 1)]


def aligned_display(lines, environment: str = "aligned") -> Block:
    """Lines as one display, a little space before each new column. In `align*` (article,
    snippet) a page may break between elements, and between the lines of an element taller
    than TALL_ELEMENT_PT (it would not fit a page)."""
    tall, element = set(), []  # the numbers of lines that continue a tall element
    for number, (_, _, starts) in enumerate(lines + [("", 0.0, "element")]):
        if starts != "line":
            if sum(lines[n][1] for n in element) > TALL_ELEMENT_PT:
                tall.update(element[1:])
            element = []
        element.append(number)
    body = lines[0][0]
    for number, (latex, _, starts) in enumerate(lines[1:], 1):
        breakable = starts != "line" or number in tall
        allow_break = "\\displaybreak[0]" if environment == "align*" and breakable else ""
        body += f"{allow_break} \\\\" + (f"[{COLUMN_SKIP:g}pt]" if starts == "column" else "") + "\n" + latex
    latex = f"\\begin{{{environment}}}\n{body}\n\\end{{{environment}}}"
    height = sum(line[1] for line in lines)
    if environment == "aligned":
        return Block(f"\\[\n{latex}\n\\]", height, math=latex)
    return Block(latex, height)


def flat(items) -> list[Block]:
    """Blocks in order; each `Rows` becomes one align* that pages may break."""
    return [item if isinstance(item, Block) else aligned_display(lines_under(item.columns, 0), "align*")
            for item in items]


def stacked(items, page: Page | None = None) -> str:
    """Blocks and `Rows` as the rows of one display (an `array` of one left-aligned column),
    which MathJax 2, 3 and 4 and pdflatex all lay out the same way: one above the other.

    >>> print(stacked([display("x = 1", 10.0), Block("where", 10.0, is_display=False)]))
    \\begin{array}{l}
    x = 1 \\\\[4pt]
    \\text{where}
    \\end{array}
    """
    rows = []
    for item in items:
        if isinstance(item, Rows):
            rows.append(aligned_display(lines_under(item.columns, 0)).math)
        elif item.is_display:
            rows.append(item.math)
        else:  # text does not break inside \text{}: one row per line that fits the page
            characters = int(page.width / TEXT_CHARACTER) if page else len(item.latex)
            rows += [f"\\text{{{line}}}" for line in textwrap.wrap(item.latex, max(20, characters))]
    return "\\begin{array}{l}\n" + " \\\\[4pt]\n".join(rows) + "\n\\end{array}"


# ---------------------------------------------------------------- matrices

def bmatrix_width(cells, page: Page) -> float:
    columns = [max(math_width(row[c]) for row in cells) for c in range(len(cells[0]))]
    return sum(columns) + page.em(BRACKETS_PT + COLUMN_GAP_PT * (len(columns) - 1))


def matrix_height(cells) -> float:
    return 3.0 + sum(row_height(row, array=True) for row in cells)


def element_name(row: int, column: int) -> str:
    """r_{11} … r_{33}, p_{x} p_{y} p_{z}."""
    name = ELEMENT_NAMES[row][column]
    return f"{name[0]}_{{{name[1:]}}}"


def matrix_items(lhs: str, cells, page: Page, short_lhs: str | None = None) -> list:
    """`lhs = [matrix]` as one display when it fits the line, else the named matrix and its
    elements column by column. `short_lhs` replaces `lhs` where the full one is too wide."""
    if math_width(lhs + " =") + bmatrix_width(cells, page) <= page.width:
        return [display(f"{lhs} =\n{bmatrix(cells)}", matrix_height(cells))]
    names = [[element_name(r, c) for c in range(4)] for r in range(3)] + [cells[3]]
    if short_lhs and math_width(lhs + " =") + bmatrix_width(names, page) > page.width:
        lhs = short_lhs
    columns = [[element_rows(names[r][c], cells[r][c], page) for r in range(3)] for c in range(4)]
    return [display(f"{lhs} =\n{bmatrix(names)}", matrix_height(names)), Rows(columns)]


def element_rows(label: str, tex: str, page: Page) -> list[tuple[str, float]]:
    """`label &= tex` as lines of an aligned block, broken when wider than the page."""
    first = page.width - math_width(label + " =") - ALIGNED_EXTRA
    lines = break_lines(tex, first, first - 1.0, display=True)
    rows = [f"{label} &= {lines[0]}"] + [f"&\\quad {{}}{line}" for line in lines[1:]]
    return [(row, row_height([row], array=False)) for row in rows]


def step_items(name: str, product: str, factors, result, page: Page) -> list:
    """`name = product = [A][B] = [C]` when all three matrices fit, else `matrix_items`."""
    first = math_width(f"{name} = {product} =") + sum(bmatrix_width(f, page) for f in factors) + ALIGNED_EXTRA
    second = math_width(f"{name} =") + bmatrix_width(result, page) + ALIGNED_EXTRA
    if first > page.width or second > page.width:
        return matrix_items(f"{name} = {product}", result, page, short_lhs=name)
    body = (f"\\begin{{aligned}}\n{name} &= {product} =\n" + "\n".join(bmatrix(f) for f in factors)
            + f" \\\\\n&= {bmatrix(result)}\n\\end{{aligned}}")
    return [display(body, max(matrix_height(f) for f in factors) + matrix_height(result) + 3.0)]


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


def break_lines(tex: str, first: float, rest: float, display: bool = False) -> list[str]:
    r"""Split `tex` before '+'/'-' into lines of at most `first`, then `rest` em; the later
    lines start with their sign (TeX does not mind brackets left open on a line). Fractions
    are measured in display style if `display` (as in `aligned`). A fraction or square root
    too wide for a line is opened so that its inside can break: ``\frac{1}{2}(…)``.

    >>> break_lines("a + b + c", 3, 3)
    ['a + b', '+ c']
    >>> break_lines("\\frac{a + b + c}{2}", 3, 3, display=True)
    ['\\frac{1}{2}(a', '+ b', '+ c)']
    """
    points, lines, start, width = break_points(tex), [], 0, first
    while True:
        prefix = "{}" if lines else ""
        remaining, later = prefix + tex[start:], [(i, depth) for i, depth in points if i > start]
        shift = len(prefix) - start  # the rest of the text, and up to each later point, measured in one pass
        *widths, whole = prefix_widths(remaining, [i + shift for i, _ in later] + [len(remaining)], display)
        if whole <= width:
            break
        upto = dict(zip((i for i, _ in later), widths))
        fitting = [(i, depth) for i, depth in later if upto[i] <= width]
        if not fitting:  # the first term alone is too wide: open a fraction or root inside it
            opened = open_group(tex, start, later[0][0] if later else len(tex))
            if opened:
                tex, points = opened, break_points(opened)
                continue
        if not later:
            break  # one term wider than the line: nothing left to break
        fitting = fitting or later[:1]
        outermost = min(depth for _, depth in fitting)
        cut = max(i for i, depth in fitting if depth == outermost)
        if upto[cut] < width / 2:  # too short a line: fill it instead
            cut = max(i for i, _ in fitting)
        lines.append(tex[start:cut])
        start, width = cut + 1, rest
    return lines + [tex[start:]]


def open_group(tex: str, start: int, end: int) -> str | None:
    r"""`tex` with the widest \frac or \sqrt that starts between `start` and `end` (outside any
    {…} group) rewritten so that the signs inside it can break a line, or None if none can:
    ``\frac{N}{D}`` becomes ``\frac{1}{D}(N)``, ``\sqrt{X}`` becomes ``(X)^{1/2}``.

    >>> open_group("c_{1} \\sqrt{a + b}", 0, 20)
    'c_{1} (a + b)^{1/2}'
    """
    candidates = []
    for i, depth in _group_starts(tex):
        if start <= i < end and depth == 0 and tex.startswith(("\\frac{", "\\sqrt{"), i):
            groups, after = _groups(tex, tex.index("{", i), 2 if tex.startswith("\\frac", i) else 1)
            inside = groups[0]
            if break_points(inside):
                candidates.append((math_width(tex[i:after]), i, groups, after))
    if not candidates:
        return None
    _, i, groups, after = max(candidates)
    inside = groups[0]
    opening, closing = ("\\{", "\\}") if "[" in inside else ("[", "]") if "(" in inside else ("(", ")")
    wrapped = f"{opening}{inside}{closing}" if any(depth == 0 for _, depth in break_points(inside)) else inside
    if len(groups) == 2:
        space = "" if wrapped[0] in "([\\" else " "
        return f"{tex[:i]}\\frac{{1}}{{{groups[1]}}}{space}{wrapped}{tex[after:]}"
    return f"{tex[:i]}{wrapped}^{{1/2}}{tex[after:]}"


def _group_starts(tex: str):
    """(position, brace depth) of each backslash."""
    depth = 0
    for i, ch in enumerate(tex):
        if ch == "\\":
            yield i, depth
        elif ch == "{" and not tex[i - 1:i] == "\\":
            depth += 1
        elif ch == "}" and not tex[i - 1:i] == "\\":
            depth -= 1


def _groups(tex: str, i: int, count: int) -> tuple[list[str], int]:
    """The contents of `count` {…} groups from position `i`, and the position after them."""
    groups = []
    for _ in range(count):
        depth, begin = 0, i
        while True:
            if tex.startswith(("\\{", "\\}"), i):
                i += 2
                continue
            depth += (tex[i] == "{") - (tex[i] == "}")
            i += 1
            if depth == 0:
                break
        groups.append(tex[begin + 1:i - 1])
    return groups, i
