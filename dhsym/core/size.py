"""How long an expression is, for choosing the shortest of several equal forms.

SymPy's `count_ops` is the measure the textbook comparisons use, but it is slow on large
expressions (110 s for the candidates of one general 5-link Jacobian). `length` is count_ops
while an expression is small, and the number of nodes of its tree past that. A tree has at least
as many nodes as operations (but for a lone negative fraction, −1/2: two operations, one node),
so small forms compare exactly as before, a small form beats a large one, and large forms are
measured in linear time.

>>> t1, t2, a1 = sympy.symbols("theta_1 theta_2 a_1", real=True)
>>> length(a1*sympy.cos(t1) + a1*sympy.cos(t1 + t2))
6
>>> length([sympy.sin(t1), sympy.cos(t2)])
2
>>> tree_size(a1*sympy.cos(t1))
4
"""
from __future__ import annotations

import sympy

EXACT_BELOW = 400  # nodes: below this, count_ops itself (milliseconds)


def length(expr) -> int:
    """count_ops for a small expression (or list of them), its tree size for a large one."""
    if isinstance(expr, (list, tuple, sympy.MatrixBase)):
        return sum(length(x) for x in expr)
    nodes = tree_size(expr)
    return sympy.count_ops(expr) if nodes < EXACT_BELOW else nodes


def tree_size(expr: sympy.Basic, memo: dict | None = None) -> int:
    """Nodes of the expression tree, counting a shared subtree every time it occurs."""
    memo = {} if memo is None else memo
    key = id(expr)
    if key not in memo:
        memo[key] = 1 + sum(tree_size(arg, memo) for arg in expr.args)
    return memo[key]
