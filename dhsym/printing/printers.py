"""Expression printers that write the textbook c/s notation, in text and in LaTeX.

The math objects know nothing of printing; these are SymPy printer subclasses that override
how cos, sin, sums, products and symbols are written, and remember which abbreviations they
used so that a legend can list exactly those.

>>> import sympy
>>> t1, t2, l1, l2 = sympy.symbols("theta_1 theta_2 l_1 l_2", real=True)
>>> px = l1*sympy.cos(t1) + l2*sympy.cos(t1 + t2)
>>> printer = TextPrinter([t1, t2])
>>> printer.doprint(px), sorted(a.label("unicode") for a in printer.used)
('l1 c1 + l2 c12', ['c1', 'c12'])
>>> LatexPrinter([t1, t2]).doprint(px)
'l_{1} c_{1} + l_{2} c_{12}'
"""
from __future__ import annotations

import sympy
from sympy.printing.latex import LatexPrinter as _SympyLatex
from sympy.printing.str import StrPrinter

from .notation import Notation, display_name, superscript

_BRACKETS = {"text": [("(", ")"), ("[", "]"), ("{", "}")],
             "latex": [("(", ")"), ("[", "]"), ("\\{", "\\}")]}


class _TextbookMixin:
    """The parts shared by the text and the LaTeX printer."""

    style = "unicode"
    family = "text"
    minus = " − "

    def _setup(self, joint_variables, marked=()):
        self.notation = Notation(joint_variables)
        self.marked = set(marked)  # symbols printed with a star: the joint variables in a DH table
        self.used: set = set()

    def _print_Symbol(self, expr):
        name = display_name(expr.name, self.style)
        return self._mark(name) if expr in self.marked else name

    def _trig(self, expr, exp=None):
        """c12 for a joint-angle sum, else cos(...); LaTeX's Pow printing passes `exp` for sin²."""
        found = self.notation.abbreviation(expr)
        if not found:
            text = self._plain_trig(expr)
            return text if exp is None else f"\\left({text}\\right)^{{{exp}}}"
        sign, abbreviation = found
        self.used.add(abbreviation)
        text = abbreviation.label(self.style) + ("" if exp is None else f"^{{{exp}}}")
        return (self.minus.strip() if sign < 0 else "") + text

    def _print_cos(self, expr, exp=None):
        return self._trig(expr, exp)

    def _print_sin(self, expr, exp=None):
        return self._trig(expr, exp)

    def _print_Add(self, expr, order=None):
        out = ""
        for position, term in enumerate(sorted(expr.args, key=self.notation.term_key)):
            negative, body = self._signed(term)
            if position == 0:
                out = (self.minus.strip() if negative else "") + body
            else:
                out += (self.minus if negative else " + ") + body
        return out

    def _print_Mul(self, expr):
        negative, body = self._signed(expr)
        return (self.minus.strip() if negative else "") + body

    def _signed(self, term) -> tuple[bool, str]:
        """(is negative, text of its magnitude). A bracket never starts with a minus: the sign
        moves in front of the product, so s23(−c4 c5 c6 + s4 s6) prints −s23(c4 c5 c6 − s4 s6)."""
        if not term.is_Mul:
            negative = term.could_extract_minus_sign()
            return negative, self._print(-term if negative else term)
        coefficient, rest = term.as_coeff_Mul()
        negative = bool(coefficient.is_negative)
        factors = []
        for factor in sympy.Mul.make_args(rest):
            if factor.is_Add and min(factor.args, key=self.notation.term_key).could_extract_minus_sign():
                factor, negative = -factor, not negative
            factors.append(factor)
        return negative, self._product(abs(coefficient), factors)

    def _product(self, coefficient, factors) -> str:
        factors = sorted(factors, key=self.notation.factor_key)
        upper = [f for f in factors if not (f.is_Pow and f.exp.is_negative)]
        lower = [1 / f for f in factors if f.is_Pow and f.exp.is_negative]
        if coefficient.is_Rational and coefficient != 1:
            if coefficient.p != 1 or not upper:
                upper.insert(0, sympy.Integer(coefficient.p))
            if coefficient.q != 1:
                lower.insert(0, sympy.Integer(coefficient.q))
        elif coefficient != 1:
            upper.insert(0, coefficient)
        top = self._join([self._factor(f) for f in upper]) if upper else "1"
        if not lower:
            return top
        return self._fraction(top, self._join([self._factor(f) for f in lower]), len(upper) > 1)

    def _factor(self, factor):
        if factor.is_Add:
            opening, closing = _BRACKETS[self.family][_nesting(factor) % 3]
            return opening + self._print(factor) + closing
        return self._print(factor)

    def _join(self, pieces):
        out = pieces[0]
        for piece in pieces[1:]:
            out += piece if self._hugs(piece) else " " + piece
        return out

    def _hugs(self, piece) -> bool:
        """Whether a factor is written without a space before it: a bracket, c1(…), c1[…]."""
        if self.family == "text":
            return piece[:1] in "([{\\" and not piece.startswith("\\sqrt")
        return piece[:1] in "([" or piece.startswith("\\{")


class TextPrinter(_TextbookMixin, StrPrinter):
    """Plain text, Unicode by default (θ1, −, √) or ASCII (`ascii=True`)."""

    def __init__(self, joint_variables, marked=(), ascii=False):
        StrPrinter.__init__(self, {})
        self._setup(joint_variables, marked)
        if ascii:
            self.style, self.minus = "ascii", " - "

    def _mark(self, name):
        return name + "*"

    def _plain_trig(self, expr):
        name = type(expr).__name__
        argument = self._print(expr.args[0])
        return f"{name} {argument}" if expr.args[0].is_Atom else f"{name}({argument})"

    def _print_Pow(self, expr, rational=False):
        if expr.exp == sympy.Rational(1, 2):
            base = self._print(expr.base)
            if self.style == "ascii":
                return f"sqrt({base})"
            return "√" + (base if expr.base.is_Atom else f"({base})")
        if expr.exp.is_Integer and expr.exp > 1:
            base = self._factor(expr.base) if not expr.base.is_Atom else self._print(expr.base)
            if expr.base.is_Function and not self.notation.abbreviation(expr.base):
                base = f"({base})"  # (sin α)², not sin α²
            return base + ("^" + str(expr.exp) if self.style == "ascii" else superscript(str(expr.exp)))
        return super()._print_Pow(expr, rational)

    def _print_Integer(self, expr):
        return self.minus.strip() + str(-expr) if expr < 0 else str(expr)

    def _print_Rational(self, expr):
        return self.minus.strip() + f"{-expr.p}/{expr.q}" if expr < 0 else f"{expr.p}/{expr.q}"

    def _print_Pi(self, expr):
        return "pi" if self.style == "ascii" else "π"

    def _fraction(self, top, bottom, grouped):
        return (f"({top})" if grouped else top) + "/" + bottom


class LatexPrinter(_TextbookMixin, _SympyLatex):
    """LaTeX with c_{1}, s_{23}; symbols as \\theta_{1}, l_{1}."""

    style, family, minus = "latex", "latex", " - "

    def __init__(self, joint_variables, marked=()):
        _SympyLatex.__init__(self, {})
        self._setup(joint_variables, marked)

    def _mark(self, name):
        return name + "^{*}"

    def _plain_trig(self, expr):
        name = "\\" + type(expr).__name__
        argument = self._print(expr.args[0])
        return f"{name}{{{argument}}}" if expr.args[0].is_Atom else f"{name}({argument})"

    def _fraction(self, top, bottom, grouped):
        return f"\\frac{{{top}}}{{{bottom}}}"


def _nesting(expr) -> int:
    """How many bracket levels a sum contains inside it (0 for a flat sum)."""
    deepest = 0
    for term in sympy.Add.make_args(expr):
        for factor in sympy.Mul.make_args(term):
            if factor.is_Add:
                deepest = max(deepest, 1 + _nesting(factor))
    return deepest
