"""Textbook notation shared by every printer: which symbol is joint i, the c/s abbreviations,
and the order in which terms and factors are written.

Abbreviations: ``c1 = cos θ1``, ``s23 = sin(θ2+θ3)``, ``c123``. A joint that enters with a
minus sign (after a twist of π) carries a bar: ``c12̄4 = cos(θ1+θ2−θ4)``, LaTeX
``c_{12\\bar{4}}``, ASCII ``c(12-4)``. When any joint number has two digits the indices are
separated by commas, so ``c_{1,10}`` cannot be misread as joint 110.

>>> import sympy
>>> t = sympy.symbols("theta_1:5", real=True)
>>> notation = Notation(t)
>>> notation.abbreviation(sympy.cos(t[0] + t[1] - t[3]))
(1, Abbreviation(function='c', indices=((1, 1), (2, 1), (4, -1))))
>>> display_name("theta_1", "unicode"), display_name("theta_1", "latex"), display_name("l_13", "ascii")
('θ1', '\\\\theta_{1}', 'l13')
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy
from sympy.printing.conventions import split_super_sub
from sympy.printing.pretty.pretty_symbology import greek_unicode

_GREEK_NAME = {letter: name for name, letter in greek_unicode.items()}
_COMBINING_BAR = "\u0305"


@dataclass(frozen=True, order=True)
class Abbreviation:
    """``c`` or ``s`` of a signed sum of joint angles, e.g. ('c', ((1, 1), (2, 1)))."""

    function: str
    indices: tuple  # ((joint number, +1 or -1), ...), ascending, the first one positive

    def label(self, style: str) -> str:
        """c12 (unicode/ascii), c_{12} (latex); c(12-4) in ascii when a joint is subtracted."""
        wide = any(number >= 10 for number, _ in self.indices)
        joined = ("," if wide else "").join(_index_text(n, s, style) for n, s in self.indices)
        if style == "latex":
            return f"{self.function}_{{{joined}}}"
        if style == "ascii" and (wide or any(s < 0 for _, s in self.indices)):
            joined = f"({joined})"
        return self.function + joined

    def sort_key(self) -> tuple:
        return (self.indices[0][0], len(self.indices), self.indices, self.function != "c")


class Notation:
    """Knows the joint variables of one chain, in joint order."""

    def __init__(self, joint_variables):
        """Joint numbers come from the names' subscripts (θ4, θ5, θ6 of a wrist give c4, c5,
        c6) when every name has a distinct numeric one, else from the row order."""
        joint_variables = list(joint_variables)
        numbers = [_subscript_number(s.name) for s in joint_variables]
        if None in numbers or len(set(numbers)) != len(numbers):
            numbers = range(1, len(joint_variables) + 1)
        self.index = dict(zip(joint_variables, numbers))

    def abbreviation(self, expr: sympy.Expr) -> tuple[int, Abbreviation] | None:
        """(sign, abbreviation) if expr is cos/sin of a signed sum of joint angles, else None."""
        if not isinstance(expr, (sympy.cos, sympy.sin)):
            return None
        terms = []
        for term in sympy.Add.make_args(expr.args[0]):
            coefficient, rest = term.as_coeff_Mul()
            if rest not in self.index or coefficient not in (1, -1):
                return None
            terms.append((self.index[rest], int(coefficient)))
        terms.sort()
        sign = 1
        if terms[0][1] < 0:
            terms = [(i, -s) for i, s in terms]
            sign = 1 if isinstance(expr, sympy.cos) else -1
        return sign, Abbreviation("c" if isinstance(expr, sympy.cos) else "s", tuple(terms))

    def name_of(self, number: int) -> str:
        """The symbol name of joint `number`, as the robot file spells it."""
        return next(symbol.name for symbol, n in self.index.items() if n == number)

    def meaning(self, abbreviation: Abbreviation, style: str) -> str:
        """What an abbreviation stands for: 'cos θ1' or 'sin(θ2 + θ3)'."""
        names = {number: symbol for symbol, number in self.index.items()}
        angle = ""
        for position, (number, sign) in enumerate(abbreviation.indices):
            name = display_name(names[number].name, style)
            minus = {"unicode": " − ", "ascii": " - ", "latex": " - "}[style]
            angle += (minus if sign < 0 else " + " if position else "") + name
        function = {"c": "cos", "s": "sin"}[abbreviation.function]
        if style == "latex":
            function = "\\" + function
            return f"{function}({angle})" if len(abbreviation.indices) > 1 else f"{function}{{{angle}}}"
        return f"{function}({angle})" if len(abbreviation.indices) > 1 else f"{function} {angle}"

    def term_key(self, term: sympy.Expr) -> tuple:
        """Order terms by joint: constants first, then by the lowest joint they involve."""
        keys = sorted(self._atom_keys(term))
        unsigned = -term if term.could_extract_minus_sign() else term
        return (tuple(keys), sympy.default_sort_key(unsigned))

    def _atom_keys(self, expr: sympy.Expr):
        for factor in sympy.Mul.make_args(expr):
            base = factor.base if factor.is_Pow else factor
            found = self.abbreviation(base)
            if found:
                yield found[1].sort_key()
            elif base in self.index:
                yield (self.index[base], 0, (), False)
            elif base.is_Add:
                inner = [min(self._atom_keys(t), default=None) for t in base.args]
                inner = [k for k in inner if k is not None]
                if inner:
                    yield tuple(min(inner)[:1]) + (99, (), True)

    def factor_key(self, factor: sympy.Expr) -> tuple:
        """Within a product: plain constants, then joint cos/sin in joint order, then brackets."""
        base = factor.base if factor.is_Pow else factor
        found = self.abbreviation(base)
        if found:
            return (1, found[1].sort_key(), sympy.default_sort_key(factor))
        if base.is_Add:
            return (2, (), sympy.default_sort_key(factor))
        return (0, (), sympy.default_sort_key(factor))


def _subscript_number(name: str) -> int | None:
    _, _, subs = split_super_sub(name)
    text = subs[0].strip("{}") if len(subs) == 1 else ""
    return int(text) if text.isdigit() else None


def _index_text(number: int, sign: int, style: str) -> str:
    text = str(number)
    if sign > 0:
        return text
    return {"latex": f"\\bar{{{text}}}", "unicode": _COMBINING_BAR.join(text) + _COMBINING_BAR, "ascii": f"-{text}"}[style]


def display_name(name: str, style: str) -> str:
    """A symbol name as a textbook writes it: theta_1 -> θ1 (unicode), \\theta_{1} (LaTeX)."""
    base, supers, subs = split_super_sub(name)
    subs = [s.strip("{}") for s in subs]
    supers = [s.strip("{}") for s in supers]
    if style == "latex":
        base = _latex_base(base)
        text = base + "".join(f"_{{{s}}}" for s in subs[:1])
        if len(subs) > 1:
            text = base + "_{" + ",".join(subs) + "}"
        return text + "".join(f"^{{{s}}}" for s in supers)
    if style == "unicode":
        base = greek_unicode.get(base, base)
    else:
        base = _GREEK_NAME.get(base, base)
    return base + "".join(subs) + "".join("^" + s for s in supers)


def _latex_base(base: str) -> str:
    name = _GREEK_NAME.get(base, base)
    name = {"lamda": "lambda", "Lamda": "Lambda"}.get(name, name)  # SymPy's spelling, not TeX's
    if name in greek_unicode and name.lower() not in ("omicron",):
        return "\\" + name if name not in ("Alpha", "Beta", "Epsilon", "Zeta", "Eta", "Iota", "Kappa", "Mu",
                                           "Nu", "Omicron", "Rho", "Tau", "Chi") else name[0]
    if len(name) > 1:
        return f"\\mathrm{{{name}}}"
    return name
