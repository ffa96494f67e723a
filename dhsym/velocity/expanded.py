"""A determinant multiplied out exactly, and a bound on its terms counted before the work.

The entries of a Jacobian are polynomials with rational coefficients in the robot's constants
and the cos/sin of its joint angles. Multiplied out in SymPy's sparse polynomial ring, minor by
minor, their determinant costs milliseconds and comes out as `sympy.expand` would write it
(expansion is canonical), its cancellations done: the HC10's 6×6 determinant in frame 4 of the
modified convention has 9 terms, where expanding the Berkowitz form would write 114,593 first.

How many terms it can have is known before: Leibniz's formula, det = Σ over permutations of a
product of entries, multiplied out term by term, has as many as the permanent of the matrix of
the entries' term counts. No term is lost to cancellation in that count, so it bounds the
result, and the work of the minors.

>>> import sympy
>>> a, b, t = sympy.symbols("a b theta", real=True)
>>> matrix = sympy.Matrix([[a * sympy.cos(t), -b * sympy.sin(t)], [a * sympy.sin(t), b * sympy.cos(t)]])
>>> expanded_det(matrix), leibniz_terms(matrix)
(a*b*sin(theta)**2 + a*b*cos(theta)**2, 2)
"""
from __future__ import annotations

from itertools import combinations

import sympy
from sympy.polys.domains import QQ
from sympy.polys.polyerrors import CoercionFailed
from sympy.polys.rings import PolyRing

from ..core.size import expanded_terms


def expanded_det(matrix: sympy.Matrix) -> sympy.Expr | None:
    """`sympy.expand(matrix.det())` by the polynomial ring of the entries' symbols and cos/sin
    terms, or None when an entry is no polynomial there (√2 from a twist of π/4, a decimal float)."""
    if any(entry.has(sympy.Float) for entry in matrix):
        return None
    atoms = set().union(*(entry.atoms(sympy.Symbol, sympy.cos, sympy.sin) for entry in matrix))
    ring = PolyRing(sorted(atoms, key=sympy.default_sort_key) or [sympy.Dummy()], QQ)
    try:
        rows = [[ring.from_expr(entry) for entry in matrix.row(r)] for r in range(matrix.rows)]
    except (ValueError, CoercionFailed):
        return None
    return minors_det(rows, ring.one).as_expr()


def minors_det(rows: list, one):
    """The determinant of a square matrix (a list of rows) of anything with +, − and ×, `one`
    its unit: expanded along the rows over the minors of the first k rows, each minor (a set of
    columns) worked out once, 2ⁿ of them; no division.

    >>> minors_det([[1, 2, 3], [4, 5, 6], [7, 8, 10]], 1)
    -3
    """
    minors = {(): one}
    for k, row in enumerate(rows):
        minors = {columns: _cofactor_sum(row, k, columns, minors)
                  for columns in combinations(range(len(rows)), k + 1)}
    return minors[tuple(range(len(rows)))]


def _cofactor_sum(row, k: int, columns: tuple, minors: dict):
    """The minor of the first k + 1 rows on `columns`, expanded along its last row, row k."""
    total = None
    for position, column in enumerate(columns):
        term = row[column] * minors[columns[:position] + columns[position + 1:]]
        term = -term if (k + position) % 2 else term
        total = term if total is None else total + term
    return total


def leibniz_terms(matrix: sympy.Matrix) -> int:
    """How many terms the determinant of `matrix` can have when written out (an upper bound,
    counted before any expansion): the permanent of the entries' counts (see the module).

    >>> x, y = sympy.symbols("x y")
    >>> leibniz_terms(sympy.Matrix([[x + y, 1], [x - 1, (x + y)**2]]))
    8
    """
    counts = [[expanded_terms(entry) if entry != 0 else 0 for entry in matrix.row(r)] for r in range(matrix.rows)]
    return permanent(counts)


def permanent(rows: list) -> int:
    """The permanent of a square matrix of counts (the determinant without its signs), minor by
    minor as `minors_det` goes.

    >>> permanent([[1, 2], [3, 4]])
    10
    """
    minors = {(): 1}
    for k, row in enumerate(rows):
        minors = {columns: sum(row[column] * minors[columns[:p] + columns[p + 1:]] for p, column in enumerate(columns))
                  for columns in combinations(range(len(rows)), k + 1)}
    return minors[tuple(range(len(rows)))]


def term_count(expr: sympy.Expr) -> int:
    """The terms of an expanded expression (0 for zero)."""
    return 0 if expr == 0 else len(sympy.Add.make_args(expr))
