"""Textbook notation shared by every printer: which symbol is joint i, the c/s abbreviations,
and the order in which terms and factors are written.

Abbreviations: ``c1 = cos θ1``, ``s23 = sin(θ2+θ3)``, ``c123``. A joint that enters with a
minus sign (after a twist of π) carries a bar: ``c12̄4 = cos(θ1+θ2−θ4)``, LaTeX
``c_{12\\bar{4}}``, ASCII ``c(12-4)``. When any joint number has two digits the indices are
separated by commas, so ``c_{1,10}`` cannot be misread as joint 110.

The index is the bare joint number when every joint angle is a θ (``c1 = cos θ1``). When the
angles are named with other Greek letters, or with several (θ1, φ2, ψ3), each index keeps its
letter, so that ``cφ2 = cos φ2`` (LaTeX ``c_{\\phi 2}``) is never confused with the ``c2 = cos θ2``
of another chain: ``cθ1,φ2 = cos(θ1 + φ2)``.

>>> import sympy
>>> t = sympy.symbols("theta_1:5", real=True)
>>> notation = Notation(t)
>>> notation.abbreviation(sympy.cos(t[0] + t[1] - t[3]))
(1, Abbreviation(function='c', indices=((1, 1), (2, 1), (4, -1))))
>>> mixed = Notation(sympy.symbols("theta_1 phi_2", real=True))
>>> mixed.abbreviation(sympy.sin(sum(mixed.label)))[1].label("latex")
's_{\\\\theta 1,\\\\phi 2}'
>>> display_name("theta_1", "unicode"), display_name("theta_1", "latex"), display_name("l_13", "ascii")
('θ1', '\\\\theta_{1}', 'l13')
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy
from sympy.printing.conventions import split_super_sub
from sympy.printing.pretty.pretty_symbology import greek_unicode, sub, sup

GREEK_NAMES = {letter: name for name, letter in greek_unicode.items()}  # 'θ' -> 'theta'
_GREEK_WITHOUT_COMMAND = {"Alpha", "Beta", "Epsilon", "Zeta", "Eta", "Iota", "Kappa", "Mu", "Nu", "Omicron",
                          "omicron", "Rho", "Tau", "Chi"}  # written as Latin letters in TeX
_COMBINING_BAR = "\u0305"


@dataclass(frozen=True)
class Abbreviation:
    """``c`` or ``s`` of a signed sum of joint angles, e.g. ('c', ((1, 1), (2, 1)))."""

    function: str
    indices: tuple  # ((joint label, +1 or -1), ...) in joint order, the first one positive
    order: tuple = field(default=(), repr=False, compare=False)  # joint positions, for sorting

    @property
    def wide(self) -> bool:
        """Whether some label has more than one character, so labels need commas: c_{1,10}."""
        return any(len(str(label)) > 1 for label, _ in self.indices)

    def label(self, style: str) -> str:
        """c12 (unicode/ascii), c_{12} (latex); c(12-4) in ascii when a joint is subtracted."""
        joined = ("," if self.wide else "").join(_index_text(_label_text(n, style), s, style) for n, s in self.indices)
        if style == "latex":
            return f"{self.function}_{{{joined}}}"
        if style == "ascii" and (self.wide or any(s < 0 for _, s in self.indices)):
            joined = f"({joined})"
        return self.function + joined

    def sort_key(self) -> tuple:
        order = self.order or tuple(range(len(self.indices)))
        return (order[0], len(self.indices), order, self.function != "c")


class Notation:
    """Knows the joint variables of one chain, in joint order."""

    def __init__(self, joint_variables):
        """Joint labels come from the names' subscripts when every joint variable has a
        distinct one: θ4, θ5, θ6 of a wrist give c4, c5, c6, and a general row in θ_i gives c_i.
        Otherwise joints are numbered by row. Angles named with Greek letters other than θ
        keep their letter in the label: φ2 gives cφ2."""
        joint_variables = list(joint_variables)
        labels = [_subscript(s.name) for s in joint_variables]
        if None not in labels and _lettered(joint_variables):
            labels = [_letter(s.name) + label for s, label in zip(joint_variables, labels)]
        if None in labels or len(set(labels)) != len(labels):
            labels = list(range(1, len(joint_variables) + 1))
        elif all(label.isdigit() for label in labels):
            labels = [int(label) for label in labels]
        self.label = dict(zip(joint_variables, labels))
        self.position = {symbol: k for k, symbol in enumerate(joint_variables, 1)}

    def abbreviation(self, expr: sympy.Expr) -> tuple[int, Abbreviation] | None:
        """(sign, abbreviation) if expr is cos/sin of a signed sum of joint angles, else None."""
        if not isinstance(expr, (sympy.cos, sympy.sin)):
            return None
        terms = []
        for term in sympy.Add.make_args(expr.args[0]):
            coefficient, rest = term.as_coeff_Mul()
            if rest not in self.position or coefficient not in (1, -1):
                return None
            terms.append((self.position[rest], self.label[rest], int(coefficient)))
        terms.sort(key=lambda t: t[0])
        sign = 1
        if terms[0][2] < 0:
            terms = [(p, label, -s) for p, label, s in terms]
            sign = 1 if isinstance(expr, sympy.cos) else -1
        function = "c" if isinstance(expr, sympy.cos) else "s"
        return sign, Abbreviation(function, tuple((label, s) for _, label, s in terms), tuple(p for p, _, _ in terms))

    def name_of(self, label) -> str:
        """The symbol name of the joint with this label, as the robot file spells it."""
        return next(symbol.name for symbol, own in self.label.items() if own == label)

    def meaning(self, abbreviation: Abbreviation, style: str) -> str:
        """What an abbreviation stands for: 'cos θ1' or 'sin(θ2 + θ3)'; in the "sympy" style
        with the robot file's names, as SymPy reads it back: 'sin(theta_2 + theta_3)'."""
        if style == "sympy":
            terms = " ".join(("- " if sign < 0 else "+ ") + self.name_of(number)
                             for number, sign in abbreviation.indices).lstrip("+ ")
            return f"{'cos' if abbreviation.function == 'c' else 'sin'}({terms})"
        names = {label: symbol for symbol, label in self.label.items()}
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
            elif base in self.position:
                yield (self.position[base], 0, (), False)
            elif base.is_Add:
                inner = [min(self._atom_keys(t), default=None) for t in base.args]
                inner = [k for k in inner if k is not None]
                if inner:
                    yield tuple(min(inner)[:1]) + (99, (), True)

    def factor_key(self, factor: sympy.Expr) -> tuple:
        """Within a product: lengths, then joint cos/sin in joint order, then other functions
        (cos α of a symbolic twist), then brackets: a_i c_i, −s_i cos α_i, c1(…)."""
        base = factor.base if factor.is_Pow else factor
        found = self.abbreviation(base)
        if found:
            return (1, found[1].sort_key(), sympy.default_sort_key(factor))
        rank = 3 if base.is_Add else 2 if base.is_Function else 0
        return (rank, (), sympy.default_sort_key(factor))


def _letter(name: str) -> str:
    """The letter of a name, Greek as its Unicode character: phi_2 -> 'φ'."""
    base = split_super_sub(name)[0]
    return greek_unicode.get(base, base)


def _lettered(joint_variables) -> bool:
    """Whether the joint angles (the variables named with a Greek letter) are not all θ."""
    letters = {_letter(s.name) for s in joint_variables} & set(GREEK_NAMES)
    return bool(letters) and letters != {"θ"}


def _label_text(label, style: str) -> str:
    """A joint label in a style: 'φ2' is φ2 (unicode), \\phi 2 (LaTeX), phi2 (ASCII)."""
    text = str(label)
    if text[:1] not in GREEK_NAMES or style == "unicode":
        return text
    name = GREEK_NAMES[text[0]]
    return (greek_latex(name) + " " if style == "latex" else name) + text[1:]


def _subscript(name: str) -> str | None:
    _, _, subs = split_super_sub(name)
    text = subs[0].strip("{}") if len(subs) == 1 else ""
    return text if text.isalnum() else None


def _index_text(label, sign: int, style: str) -> str:
    text = str(label)
    if sign > 0:
        return text
    if style == "latex":  # a bar over a whole lettered label: \overline{\phi 2}
        return f"\\bar{{{text}}}" if text.isalnum() else f"\\overline{{{text}}}"
    return _COMBINING_BAR.join(text) + _COMBINING_BAR if style == "unicode" else f"-{text}"


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
        base = GREEK_NAMES.get(base, base)
    return base + "".join(subs) + "".join("^" + s for s in supers)


def greek_latex(name: str) -> str | None:
    """The TeX for a Greek letter's name, or None if it is no Greek letter.

    >>> greek_latex("theta"), greek_latex("lamda"), greek_latex("Alpha"), greek_latex("l")
    ('\\\\theta', '\\\\lambda', 'A', None)
    """
    if name not in greek_unicode:
        return None
    if name in _GREEK_WITHOUT_COMMAND:
        return name[0].upper() if name[0].isupper() else "o"
    return "\\" + {"lamda": "lambda", "Lamda": "Lambda"}.get(name, name)  # SymPy spells it lamda


def _latex_base(base: str) -> str:
    name = GREEK_NAMES.get(base, base)
    greek = greek_latex(name)
    if greek:
        return greek
    return f"\\mathrm{{{name}}}" if len(name) > 1 else name


def superscript(text: str) -> str:
    """Digits and minus signs raised, as in ⁰T₆; SymPy's own table of Unicode superscripts.

    >>> superscript("-12") + subscript("3")
    '⁻¹²₃'
    """
    return "".join(sup.get(ch, ch) for ch in text)


def subscript(text: str) -> str:
    """Digits and minus signs lowered (₀₁₂…)."""
    return "".join(sub.get(ch, ch) for ch in text)
