"""dhsym's value of an element written in the lecture's own grouping, and the difference of the two.

A verdict is read by a student next to the slide: the lecture's terms in the lecture's order, and
under them dhsym's value in that same order, with only the terms that differ marked. The printed
text is split at its top-level signs; each printed term is matched with the terms of dhsym's
expanded value that it stands for, and what is left over is added at the end.

>>> import sympy
>>> a, b, c = sympy.symbols("a b c", real=True)
>>> [(str(term), differs) for term, differs in regroup(["c", "a*b", "-b"], a*b + c + a)]
[('c', False), ('a*b', False), ('a', True)]
>>> difference(a*b + c - b, a*b + c + a)
-(a + b)

A printed term that is a product with a bracket is compared inside the bracket:

>>> [(str(term), differs) for term, differs in regroup(["c*(a + b)"], c*(a - b))]
[('c*(a - b)', True)]
"""
from __future__ import annotations

import ast

import sympy

from ..io.expr import parse_expression

MAX_SIMPLIFY_OPS = 80  # a longer difference is shown expanded: simplifying it costs more than it shows


def printed_terms(text: str) -> list[str]:
    """The top-level terms of a printed expression, in the order written, each with its sign.

    >>> printed_terms("-C_1*S_4 + c(1)*(a - b) - x/2")
    ['-C_1*S_4', 'c(1)*(a - b)', '-x/2']
    >>> printed_terms("θ₁ + 1")
    ['θ₁ + 1']
    """
    try:
        tree = ast.parse(text.strip(), mode="eval").body
    except SyntaxError:
        return [text.strip()]  # not Python syntax (subscript digits, ...): one term
    terms: list[str] = []

    def walk(node, negative):
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
            walk(node.left, negative)
            walk(node.right, negative != isinstance(node.op, ast.Sub))
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) and not terms:
            walk(node.operand, not negative)
        else:
            body = ast.get_source_segment(text.strip(), node)
            terms.append(("-" if negative else "") + body)

    walk(tree, False)
    return terms


def regroup(printed, derived: sympy.Expr) -> list[tuple[sympy.Expr, bool]]:
    """dhsym's `derived` as a list of (term, differs) in the order of the `printed` terms.

    `printed` is a list of terms (text for the safe parser, or SymPy). A printed term that dhsym's
    expanded value contains unchanged comes back unchanged; one that differs is replaced by the
    terms of dhsym's value nearest to it (the most factors in common); terms of dhsym's value that
    no printed term stands for come last, marked as differing.
    """
    terms = [parse_expression(t) if isinstance(t, str) else sympy.sympify(t) for t in printed]
    left = dict(_monomials(derived))
    pieces: list = [None] * len(terms)
    for position, term in enumerate(terms):
        own = _monomials(term)
        if all(left.get(m) == k for m, k in own.items()):
            for m in own:
                del left[m]
            pieces[position] = (term, False)
    for position, term in enumerate(terms):
        if pieces[position] is None:
            claimed = _claim(_monomials(term), left)
            pieces[position] = (_in_grouping(term, claimed), True)
    if left:
        pieces.append((sympy.Add(*(k * m for m, k in left.items())), True))
    return pieces


def difference(printed: sympy.Expr, derived: sympy.Expr) -> sympy.Expr:
    """printed − derived, as short as a few cheap rewritings make it (0 when they agree)."""
    plain = sympy.expand(printed - derived)
    candidates = [plain, sympy.factor_terms(plain)]
    if sympy.count_ops(plain) <= MAX_SIMPLIFY_OPS:
        candidates.append(sympy.factor_terms(sympy.trigsimp(plain)))
    return min(candidates, key=sympy.count_ops)


def _monomials(expr) -> dict:
    """{monomial: coefficient} of the expanded expression (cos(θ1 + θ2) stays one factor)."""
    return dict(sympy.expand(expr).as_coefficients_dict())


def _claim(own: dict, left: dict) -> sympy.Expr:
    """Take from `left` the monomials nearest to the printed ones: most factors in common."""
    claimed = []
    for monomial in own:
        if not left:
            break
        factors = set(sympy.Mul.make_args(monomial))
        nearest = max(left, key=lambda m: (len(factors & set(sympy.Mul.make_args(m))), -sympy.count_ops(m)))
        if not factors & set(sympy.Mul.make_args(nearest)) and len(own) > 1:
            continue  # nothing in common: leave it for the end
        claimed.append(left.pop(nearest) * nearest)
    return sympy.Add(*claimed)


def _in_grouping(printed: sympy.Expr, value: sympy.Expr) -> sympy.Expr:
    """`value` written with the printed term's outer factor pulled out, when it divides: c1(a − b)."""
    outer = sympy.Mul(*[f for f in sympy.Mul.make_args(printed) if not f.is_Add])
    if value == 0 or outer == 1 or not any(f.is_Add for f in sympy.Mul.make_args(printed)):
        return value
    inner = sympy.expand(value / outer)
    if any(p.is_Pow and p.exp.is_negative for m in sympy.Add.make_args(inner) for p in sympy.Mul.make_args(m)):
        return value
    return sympy.Mul(outer, inner, evaluate=False)
