r"""The DH table and the fixed base and tool transforms, laid out so that they fit the line,
by the same rule as the matrices (`layout`): nothing is shrunk.

* A table that fits the line is one ``array``. A wider one (long decimals or long variable
  names from an imported robot) is split into arrays of consecutive columns, each with the
  index column i. If one column alone is too wide, each row's parameters are listed by name,
  ``d_{1} = …``, a long one broken before a top-level sign as a matrix element is.
* A product of fixed steps, ``T_{x}(…)\,R_{z}(…)``, that does not fit the line goes on lines
  of its own, factors filling each line, a factor too wide for a line broken before a sign.

>>> from dhsym.latex.layout import PAGES
>>> header = ["i", "\\theta_i", "d_i", "a_i", "\\alpha_i"]
>>> wide = "0.123456789 + 0.123456789 \\sqrt{2}"
>>> items = table_items(header, [["1", "q_{1}^{*}", wide, wide, wide]], PAGES["slides"], 10)
>>> [item.math.splitlines()[1] for item in items]  # two arrays of columns, each with i
['i & \\theta_i & d_i & a_i \\\\', 'i & \\alpha_i \\\\']
"""
from __future__ import annotations

from ..printing.render import latex_array
from .layout import (
    ALIGNED_EXTRA,
    ARRAY_ROW,
    Block,
    Page,
    Rows,
    break_lines,
    display,
    element_rows,
    row_height,
)
from .width import math_width

ARRAY_COLUMN_PT = 10.0  # \arraycolsep on both sides of each column
ARRAY_RULE_PT = 0.4  # the rule after the index column


def array_width(header: list[str], rows: list[list[str]], page: Page) -> float:
    """The width in em of `latex_array(header, rows)`."""
    columns = [max(math_width(row[c]) for row in [header] + rows) for c in range(len(header))]
    return sum(columns) + page.em(ARRAY_COLUMN_PT * len(columns) + ARRAY_RULE_PT)


def table_items(header: list[str], rows: list[list[str]], page: Page, per_block: int) -> list:
    """The table as displays that fit `page` (at most `per_block` rows each), or as rows of
    named parameters when a single column is too wide."""
    groups = _column_groups(header, rows, page)
    if groups is None:
        return [_named_parameters(header, rows, page)]
    items = []
    for group in groups:
        part_header, part = [header[c] for c in group], [[row[c] for c in group] for row in rows]
        for first in range(0, len(part), per_block):
            chunk = part[first:first + per_block]
            items.append(display(latex_array(part_header, chunk),
                                 3.0 + ARRAY_ROW + sum(row_height(r, array=True) for r in chunk)))
    return items


def _column_groups(header, rows, page: Page) -> list[list[int]] | None:
    """Consecutive columns packed into as few arrays as fit the line, each starting with the
    index column 0; None if one column with the index is already too wide."""
    def fits(columns):
        return array_width([header[c] for c in columns], [[row[c] for c in columns] for row in rows],
                           page) <= page.width

    groups, current = [], [0]
    for column in range(1, len(header)):
        if fits(current + [column]):
            current.append(column)
        elif len(current) == 1:
            return None
        else:
            groups.append(current)
            current = [0, column]
            if not fits(current):
                return None
    return groups + [current]


def _named_parameters(header, rows, page: Page) -> Rows:
    """Each row as its parameters by name, d_{1} = …, one row of the table to a column of `Rows`."""
    columns = []
    for row in rows:
        number = int(row[0])
        names = [name.replace("{i-1}", f"{{{number - 1}}}").replace("_i", f"_{{{number}}}") for name in header[1:]]
        columns.append([element_rows(name, cell, page) for name, cell in zip(names, row[1:], strict=True)])
    return Rows(columns)


def product_display(lhs: str, factors: list[str], page: Page) -> Block:
    r"""`lhs = F_1\,F_2 …` as an aligned display whose lines fit the page.

    >>> from dhsym.latex.layout import PAGES
    >>> block = product_display("{}^{0}T_{1}", ["T_{x}(0.123456789012)"] * 9, PAGES["snippet"])
    >>> block.math.count("\\\\")  # three lines
    2
    """
    first = page.width - math_width(lhs + " =") - ALIGNED_EXTRA
    rest, width = first - 1.0, first  # a \quad indents the later lines
    lines, current = [], ""
    for factor in factors:
        joined = f"{current}\\,{factor}" if current else factor
        if math_width(joined) <= width:
            current = joined
            continue
        if current:
            lines.append(current)
            width = rest
        pieces = break_lines(factor, width, rest)
        lines += pieces[:-1]
        current, width = pieces[-1], rest if len(pieces) > 1 else width
    lines.append(current)
    rows = [f"{lhs} &= {lines[0]}"] + [f"&\\quad {{}}{line}" for line in lines[1:]]
    body = "\\begin{aligned}\n" + " \\\\\n".join(rows) + "\n\\end{aligned}"
    return display(body, sum(row_height([row], array=False) for row in rows))
