"""Expression printers that write the textbook c/s notation, in text and in LaTeX.

The math objects know nothing of printing; these are SymPy printer subclasses that override
how cos, sin, sums, products, numbers and symbols are written, and remember which
abbreviations they used so that a legend can list exactly those.

Settings follow SymPy's printers: `_default_settings` lists them, and they are given by keyword
or as one dict, `TextPrinter(joint_variables=[t1, t2], ascii=True)` or
`TextPrinter({"joint_variables": [t1, t2]})`; the joint variables may also come first. They are

- `joint_variables`: the chain's joint variables in joint order (they give c1, s23, c123);
- `marked`: symbols printed with a star (the joint variables in a DH table); a printer that
  marks writes every sum with its joint variables first, as a table is written (`θ2* − π/4`);
- `offsets`: {joint variable: offset} kept in the joint's angle (see dhsym.printing.notation);
- `numbers`: a `WrittenNumbers`, how the robot file wrote its numbers (decimals print as
  decimals: 0.425 c2, not (17 c2)/40; see dhsym.core.numbers);
- `first_joint`: the number of the first joint, for labels numbered by row (a wrist whose
  angles are α, β, γ and whose frames start at 3 gets c4, c5, c6);
- `ascii` (text only): plain ASCII.

`printer_settings(chain, numbers, numbering)` gives those but `marked` and `ascii` for a chain,
`chain_settings(robot)` for a robot (its file's numbers and numbering); `render.text_printer(robot)` and
`render.latex_printer(robot)` build printers with them.

Numbers: integers, fractions and multiples of π print as fractions (`π/4`, `1/3`); a rational
that the chain's file wrote as a decimal, or that arithmetic made from such decimals, prints as
a decimal (`0.81725`), exact and readable back. A function of anything but a single symbol is
bracketed: `cos α`, but `cos(0.3)`, `cos(α/2)`.

>>> import sympy
>>> t1, t2, l1, l2 = sympy.symbols("theta_1 theta_2 l_1 l_2", real=True)
>>> px = l1*sympy.cos(t1) + l2*sympy.cos(t1 + t2)
>>> printer = TextPrinter([t1, t2])
>>> printer.doprint(px), sorted(a.label("unicode") for a in printer.used)
('l1 c1 + l2 c12', ['c1', 'c12'])
>>> LatexPrinter([t1, t2]).doprint(px)
'l_{1} c_{1} + l_{2} c_{12}'
>>> from dhsym.core.numbers import WrittenNumbers
>>> TextPrinter([t1, t2], numbers=WrittenNumbers(places=3)).doprint(-sympy.Rational(17, 40) * sympy.cos(t1))
'−0.425 c1'
>>> offset = TextPrinter([t1, t2], offsets={t2: -sympy.pi / 4})
>>> offset.doprint(sympy.sin(t1 + t2 + sympy.pi / 4)), [offset.notation.meaning(a, "unicode") for a in offset.used]
('c12', ['cos(θ1 + θ2 − π/4)'])
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import replace

import sympy
from sympy.printing.latex import LatexPrinter as _SympyLatex
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

from ..core.chain import Chain
from ..core.numbering import PLAIN, Numbering
from ..core.numbers import WrittenNumbers
from ..core.robot import Robot
from .names import display_name, superscript
from .notation import Notation, written_offsets

_BRACKETS = {"text": [("(", ")"), ("[", "]"), ("{", "}")],
             "latex": [("(", ")"), ("[", "]"), ("\\{", "\\}")]}
TEXTBOOK_SETTINGS = {"joint_variables": (), "marked": (), "offsets": None, "numbers": None, "first_joint": 1}


def printer_settings(chain: Chain, numbers: WrittenNumbers | None = None, numbering: Numbering = PLAIN) -> dict:
    """The printer settings a chain implies: its joint variables and offsets, the numbers as its
    file wrote them, the printed number of its first joint."""
    return {"joint_variables": chain.joint_variables, "offsets": written_offsets(chain.rows),
            "numbers": numbers or WrittenNumbers(), "first_joint": numbering.first_joint}


def chain_settings(robot: Robot) -> dict:
    """The printer settings a robot implies: `printer_settings` with its file's numbers and numbering."""
    return printer_settings(robot.chain, robot.numbers, robot.numbering)


def _settings(joint_variables, settings, keywords) -> dict:
    """SymPy's ways of passing settings (a dict, or keywords), plus the joint variables first."""
    if isinstance(joint_variables, dict) and settings is None:
        joint_variables, settings = None, joint_variables
    merged = {**(settings or {}), **keywords}
    if joint_variables is not None:
        merged["joint_variables"] = joint_variables
    return merged


class _TextbookMixin:
    """The parts shared by the text and the LaTeX printer."""

    style = "unicode"
    family = "text"
    minus = " − "

    def _setup(self):
        settings = self._settings
        self.numbers = settings["numbers"] or WrittenNumbers()
        exact = {key: settings[key] for key in ("joint_variables", "offsets", "numbers")}
        self.notation = Notation(settings["joint_variables"], settings["offsets"], write=self._print,
                                 write_sympy=lambda expr: ExactPrinter(exact).doprint(expr),
                                 first_joint=settings["first_joint"])
        self.marked = set(settings["marked"])  # symbols printed with a star: the joint variables in a DH table
        self.used: set = set()
        self._angle = 0  # > 0 while printing the angle of a cos or sin: joint variables come first
        self._texts: dict = {}  # each sub-expression's text: see _print
        self._depths: dict = {}  # each bracket's nesting: see _factor

    def doprint(self, expr):
        """Print `expr`, first giving back each joint angle the offset its row wrote (see Notation.as_written)."""
        return super().doprint(self.notation.as_written(expr))

    def _print(self, expr, **kwargs):
        """Each distinct sub-expression printed once (a large result repeats most of its own: a
        general 8-link ⁰T₈ holds 131 distinct sums, 7,746 times). What a text depends on besides
        the expression is in the key: inside an angle or not, the rule for numbers; the
        abbreviations it used were noted the first time."""
        if kwargs or not isinstance(expr, sympy.Basic) or expr.is_Atom:
            return super()._print(expr, **kwargs)
        key = (expr, self._angle > 0, self.numbers)
        text = self._texts.get(key)
        if text is None:
            text = self._texts[key] = super()._print(expr)
        return text

    @contextmanager
    def numbers_read_back(self):
        """While printing math read back from a solver's sentence: its decimals, written there as
        text, are rationals again, which the file's rule writes (see WrittenNumbers.folded)."""
        numbers = self.numbers
        self.numbers = replace(numbers, folded=False)
        try:
            yield self
        finally:
            self.numbers = numbers

    def _print_Symbol(self, expr):
        name = display_name(expr.name, self.style)
        return self._mark(name) if expr in self.marked else name

    def _trig(self, expr, exp=None):
        """c12 for a joint-angle sum, else cos(...); LaTeX's Pow printing passes `exp` for sin²."""
        found = self.notation.abbreviation(expr)
        if not found:
            self._angle += 1
            try:
                text = self._plain_trig(expr)
            finally:
                self._angle -= 1
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
        key = self.notation.angle_key if (self._angle or self.marked) else self.notation.term_key
        out = ""
        for position, term in enumerate(self._in_order(expr.args, key)):
            negative, body = self._signed(term)
            if position == 0:
                out = (self.minus.strip() if negative else "") + body
            else:
                out += (self.minus if negative else " + ") + body
        return out

    def _in_order(self, terms, key) -> list:
        """The terms of a sum in the order they print."""
        return sorted(terms, key=key)

    def _print_Mul(self, expr):
        negative, body = self._signed(expr)
        return (self.minus.strip() if negative else "") + body

    def _decimal(self, value, alone: bool = False) -> str | None:
        """A rational as the decimal the robot file would write, or None (see dhsym.core.numbers)."""
        text = self.numbers.decimal(value, alone)
        return text.replace("-", self.minus.strip()) if text else None

    def _signed(self, term) -> tuple[bool, str]:
        """(is negative, text of its magnitude). A bracket never starts with a minus: the sign
        moves in front of the product, so s23(−c4 c5 c6 + s4 s6) prints −s23(c4 c5 c6 − s4 s6)."""
        if not term.is_Mul:
            negative = term.could_extract_minus_sign()
            return negative, self._print(-term if negative else term)
        negative, coefficient, factors = self._sign_parts(term)
        return negative, self._product(coefficient, factors)

    def _sign_parts(self, term):
        """(negative, |coefficient|, factors) of a product, each bracket turned to start with a plus."""
        coefficient, rest = term.as_coeff_Mul()
        negative, factors = bool(coefficient.is_negative), []
        for factor in sympy.Mul.make_args(rest):
            if factor.is_Add and self._leads_negative(factor):
                factor, negative = -factor, not negative
            factors.append(factor)
        return negative, abs(coefficient), factors

    def _leads_negative(self, total) -> bool:
        """Whether a sum, printed in its order, starts with a minus."""
        return min(total.args, key=self.notation.term_key).could_extract_minus_sign()

    def _product(self, coefficient, factors) -> str:
        factors = sorted(factors, key=self.notation.factor_key)
        upper = [f for f in factors if not (f.is_Pow and f.exp.is_negative)]
        lower = [1 / f for f in factors if f.is_Pow and f.exp.is_negative]
        if coefficient.is_Rational and coefficient != 1 and decimal_factor(coefficient, factors, self.numbers):
            upper.insert(0, coefficient)  # 0.425 c2, a factor as it was written
        elif coefficient.is_Rational and coefficient != 1:
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
            opening, closing = _BRACKETS[self.family][_nesting(factor, self._depths) % 3]
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

    _default_settings = {**StrPrinter._default_settings, **TEXTBOOK_SETTINGS, "ascii": False}

    def __init__(self, joint_variables=None, settings=None, **keywords):
        StrPrinter.__init__(self, _settings(joint_variables, settings, keywords))
        if self._settings["ascii"]:
            self.style, self.minus = "ascii", " - "
        self._setup()

    def _mark(self, name):
        return name + "*"

    def _plain_trig(self, expr):
        name = type(expr).__name__
        argument = self._print(expr.args[0])
        return f"{name} {argument}" if expr.args[0].is_Symbol else f"{name}({argument})"

    def _print_Pow(self, expr, rational=False):
        if expr.exp == sympy.Rational(1, 2):
            base = self._print(expr.base)
            if self.style == "ascii":
                return f"sqrt({base})"
            return "√" + (base if expr.base.is_Atom and not self._decimal(expr.base) else f"({base})")
        if expr.exp.is_Integer and expr.exp > 1:
            base = self._factor(expr.base) if not expr.base.is_Atom else self._print(expr.base)
            if expr.base.is_Function and not self.notation.abbreviation(expr.base):
                base = f"({base})"  # (sin α)², not sin α²
            return base + ("^" + str(expr.exp) if self.style == "ascii" else superscript(str(expr.exp)))
        return super()._print_Pow(expr, rational)

    def _print_Integer(self, expr):
        return self.minus.strip() + str(-expr) if expr < 0 else str(expr)

    def _print_Rational(self, expr):
        decimal = self._decimal(expr, alone=True)
        if decimal:
            return decimal
        return self.minus.strip() + f"{-expr.p}/{expr.q}" if expr < 0 else f"{expr.p}/{expr.q}"

    def _print_Pi(self, expr):
        return "pi" if self.style == "ascii" else "π"

    def _fraction(self, top, bottom, grouped):
        return (f"({top})" if grouped else top) + "/" + bottom


class LatexPrinter(_TextbookMixin, _SympyLatex):
    """LaTeX with c_{1}, s_{23}; symbols as \\theta_{1}, l_{1}."""

    style, family, minus = "latex", "latex", " - "
    _default_settings = {**_SympyLatex._default_settings, **TEXTBOOK_SETTINGS}

    def __init__(self, joint_variables=None, settings=None, **keywords):
        _SympyLatex.__init__(self, _settings(joint_variables, settings, keywords))
        self._setup()

    def _mark(self, name):
        return name + "^{*}"

    def _plain_trig(self, expr):
        name = "\\" + type(expr).__name__
        argument = self._print(expr.args[0])
        return f"{name}{{{argument}}}" if expr.args[0].is_Symbol else f"{name}({argument})"

    def _print_Rational(self, expr):
        return self._decimal(expr, alone=True) or super()._print_Rational(expr)

    def _fraction(self, top, bottom, grouped):
        return f"\\frac{{{top}}}{{{bottom}}}"


class ExactPrinter(StrPrinter):
    """SymPy's own text form (`sympy.sympify` reads it back), with names as the robot file spells
    them, decimals as it wrote them and joint angles with their offsets as written: the JSON form.

    >>> t2 = sympy.Symbol("theta_2", real=True)
    >>> ExactPrinter(numbers=WrittenNumbers(places=3), offsets={t2: -sympy.pi / 4},
    ...              joint_variables=[t2]).doprint(-sympy.Rational(17, 40) * sympy.sin(t2 + sympy.pi / 4))
    '-0.425*cos(theta_2 - pi/4)'

    A minus before a bracket goes on a factor that is not a sum, so that reading back keeps the
    grouping (`-(a + b)*cos(c)` would come back as (-a - b)*cos(c), a sign more):

    >>> a, b, c = sympy.symbols("a b c")
    >>> ExactPrinter().doprint(-sympy.cos(c) * (a + b))
    '-cos(c)*(a + b)'
    """

    _default_settings = {**StrPrinter._default_settings, **TEXTBOOK_SETTINGS}

    def __init__(self, joint_variables=None, settings=None, **keywords):
        StrPrinter.__init__(self, _settings(joint_variables, settings, keywords))
        self.numbers = self._settings["numbers"] or WrittenNumbers()
        self.notation = Notation(self._settings["joint_variables"], self._settings["offsets"], write=self._print,
                                 write_sympy=self._print, first_joint=self._settings["first_joint"])
        self._texts: dict = {}

    def doprint(self, expr):
        return super().doprint(self.notation.as_written(expr))

    def _print(self, expr, **kwargs):
        """Each distinct sub-expression printed once, as the textbook printers do."""
        if kwargs or not isinstance(expr, sympy.Basic) or expr.is_Atom:
            return super()._print(expr, **kwargs)
        key = (expr, self.numbers)
        text = self._texts.get(key)
        if text is None:
            text = self._texts[key] = super()._print(expr)
        return text

    def _print_Rational(self, expr):
        return self.numbers.decimal(expr, alone=True) or super()._print_Rational(expr)

    def _print_Mul(self, expr):
        coefficient, rest = expr.as_coeff_Mul()
        factors = sympy.Mul.make_args(rest)
        decimal = decimal_factor(abs(coefficient), factors, self.numbers)
        sign = "-" if coefficient < 0 else ""
        if decimal:
            return f"{sign}{decimal}*{self.parenthesize(rest, precedence(expr), strict=True)}"
        if not (sign and any(f.is_Add for f in factors)):
            return super()._print_Mul(expr)
        # -c1*(a + b), as the text form groups it: "-(a + b)*c1" would read back as c1*(-a - b)
        lead = next((f for f in factors if not f.is_Add and not (f.is_Pow and f.exp.is_negative)), None)
        if lead is None:
            return f"-({super()._print_Mul(-expr)})"
        pieces = ([abs(coefficient)] if coefficient != -1 else []) + [lead, sympy.Mul(*(set(factors) - {lead}))]
        return "-" + "*".join(self.parenthesize(piece, PRECEDENCE["Mul"], strict=True) for piece in pieces)


def decimal_factor(coefficient, factors, numbers: WrittenNumbers) -> str | None:
    """The decimal a product's coefficient prints as, or None to keep a fraction: π/4 stays π/4,
    and √3/2, √2/4 (the values of constant angles, not written decimals) keep their form."""
    if sympy.pi in factors:
        return None
    if coefficient.q in (2, 4) and any(f.is_Pow and f.exp.is_Rational and not f.exp.is_Integer for f in factors):
        return None
    return numbers.decimal(coefficient)


def _nesting(expr, depths: dict) -> int:
    """How many bracket levels a sum contains inside it (0 for a flat sum); `depths` keeps those
    of the sums met, each worked out once."""
    if expr not in depths:
        deepest = 0
        for term in sympy.Add.make_args(expr):
            for factor in sympy.Mul.make_args(term):
                if factor.is_Add:
                    deepest = max(deepest, 1 + _nesting(factor, depths))
        depths[expr] = deepest
    return depths[expr]
