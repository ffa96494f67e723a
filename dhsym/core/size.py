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

import math

import sympy
from sympy.core.cache import cacheit

EXACT_BELOW = 400  # nodes: below this, count_ops itself (milliseconds)
TERMS_CAP = 10**30  # expanded_terms counts no further: far past anything that is worked out


def length(expr) -> int:
    """count_ops for a small expression (or list of them), its tree size for a large one."""
    if isinstance(expr, (list, tuple, sympy.MatrixBase)):
        return sum(length(x) for x in expr)
    nodes = tree_size(expr)
    return operations(expr) if nodes < EXACT_BELOW else nodes


@cacheit
def operations(expr: sympy.Basic) -> int:
    """sympy.count_ops(expr), kept in SymPy's cache: a derivation measures the same candidate forms
    again and again (the PUMA's inverse kinematics 340 times for 114 forms).

    >>> operations(sympy.cos(sympy.Symbol("x")) + 1)
    2
    """
    return sympy.count_ops(expr)


def tree_size(expr: sympy.Basic, memo: dict | None = None) -> int:
    """Nodes of the expression tree, counting a shared subtree every time it occurs."""
    memo = {} if memo is None else memo
    key = id(expr)
    if key not in memo:
        memo[key] = 1 + sum(tree_size(arg, memo) for arg in expr.args)
    return memo[key]


def expanded_terms(expr: sympy.Basic, trig: bool = False, memo: dict | None = None) -> int:
    """How many terms sympy.expand would write out (an upper bound, counted without expanding):
    a sum adds its parts' terms, a product multiplies them, a whole power (a + b)ⁿ of a sum of k
    terms has C(n + k − 1, k − 1). Function arguments are expanded too, so their terms are added.
    With `trig`, cos/sin of a sum of k angles count 2^(k−1) terms, as sympy.expand_trig writes them.

    >>> a, b, c = sympy.symbols("a b c")
    >>> expanded_terms((a + b)**2 * (a + c)), expanded_terms(((a + b)**16 + c)**16)
    (6, 1166803110)
    >>> expanded_terms(sympy.cos(a + b + c), trig=True)
    4
    """
    memo = {} if memo is None else memo
    key = id(expr)
    if key in memo:
        return memo[key]
    if expr.is_Add:
        count = sum(expanded_terms(arg, trig, memo) for arg in expr.args)
    elif expr.is_Mul:
        count = 1
        for arg in expr.args:
            count *= expanded_terms(arg, trig, memo)
    elif expr.is_Pow and expr.exp.is_Integer and expr.exp > 1:
        parts = expanded_terms(expr.base, trig, memo)
        count = math.comb(int(expr.exp) + parts - 1, parts - 1)
    elif isinstance(expr, (sympy.cos, sympy.sin)) and trig and expr.args[0].is_Add:
        angles = expr.args[0].args
        count = 2 ** (len(angles) - 1) + sum(expanded_terms(angle, trig, memo) - 1 for angle in angles)
    else:
        count = 1 + sum(expanded_terms(arg, trig, memo) - 1 for arg in expr.args if not arg.is_Atom)
    memo[key] = count = min(count, TERMS_CAP)
    return count


def rough_count(number: int) -> str:
    """A count in words read at a glance: about 600,000, about 2.4 million, about 1.2 trillion.

    >>> rough_count(612_345), rough_count(2_412_000), rough_count(10**40)
    ('about 610,000', 'about 2.4 million', 'more than a trillion trillion')
    """
    if number >= 10**24:
        return "more than a trillion trillion"
    for size, word in ((10**12, "trillion"), (10**9, "billion"), (10**6, "million")):
        if number >= size:
            return f"about {number / size:.1f} {word}"
    return f"about {round(number, -4):,}" if number >= 100_000 else f"about {number:,}"
