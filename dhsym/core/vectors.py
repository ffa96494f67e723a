"""3-vectors as plain sequences: the one cross product and dot product of dhsym, for symbols and
for floats alike (a SymPy Matrix, a tuple or a list of three entries).

>>> cross((1, 0, 0), (0, 1, 0))
(0, 0, 1)
>>> import sympy
>>> x, y = sympy.symbols("x y", real=True)
>>> cross((0, 0, 1), (x, y, 0)), dot((x, y, 0), (1, 2.0, 5))
((-y, x, 0), x + 2.0*y)
"""
from __future__ import annotations


def cross(u, v) -> tuple:
    """u × v, each entry written out without expanding either factor."""
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    """u · v, the sum of the products of the entries."""
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
