"""Inverse-kinematics solutions for people and programs: the textbook text form (c1, s23,
atan2(y, x), a `where` list of the intermediate quantities, every branch by name) and the JSON
contract (full cos/sin/atan2 with the robot file's names, readable by sympy.sympify).

The target's elements print as a book names them: r11 … r33, px, py, pz (LaTeX r_{11}, p_{x}),
primed where the robot uses the name itself (px′, p_{x}': see dhsym.inverse.fresh);
a quotient prints with its denominator bracketed, (px² + py² − a1² − a2²)/(2 a1 a2), and a sum
starts with the target's terms, positive ones first.

>>> import sympy, dhsym
>>> arm = dhsym.load("planar2r").chain
>>> px, py, a1, a2 = sympy.symbols("px py a_1 a_2", real=True)
>>> printer = text_printer(arm)
>>> printer.doprint((px**2 + py**2 - a1**2 - a2**2) / (2 * a1 * a2))
'(px² + py² − a1² − a2²)/(2 a1 a2)'
>>> latex_printer(arm).doprint(sympy.atan2(py, px) - sympy.acos(px / a1))
'\\\\mathrm{atan2}(p_{y}, p_{x}) - \\\\arccos(\\\\frac{p_{x}}{a_{1}})'
"""
from __future__ import annotations

import re

import sympy
from sympy.printing.precedence import PRECEDENCE, precedence

from ..core.chain import Chain
from ..core.numbering import PLAIN, Numbering
from ..core.numbers import WrittenNumbers
from ..inverse.fresh import plain
from ..inverse.solution import TARGET_NAMES
from ..inverse.written import Written
from . import render
from .ik_sentences import LatexSentences, TextSentences
from .names import display_name
from .notation import Abbreviation, written_offsets
from .printers import ExactPrinter, LatexPrinter, TextPrinter

_TARGET = frozenset(TARGET_NAMES)


def target_name(name: str, style: str) -> str:
    """An element of the target as a book writes it, with the primes the derivation gave it where
    the robot uses its name.

    >>> target_name("r11", "latex"), target_name("pxʹ", "unicode"), target_name("pxʹ", "latex")
    ('r_{11}', 'px′', "p_{x}'")
    """
    bare, primes = plain(name)
    text = f"{bare[0]}_{{{bare[1:]}}}" if style == "latex" else bare
    return text + ("′" if style == "unicode" else "'") * primes


class _InverseNotation:
    """What the IK printers add to the textbook printers: sums start with the target's terms,
    and atan2, acos, asin print as a book writes them."""

    def _setup(self):
        super()._setup()
        joint_key, factor_key = self.notation.term_key, self.notation.factor_key
        self._negative: dict = {}  # whether a term prints with a minus: asked again and again while sorting
        self._printed: dict = {}
        # instance attributes: the printers ask the notation for the order of terms and factors
        self.targets = frozenset(self._settings.get("targets", TARGET_NAMES))  # primed where the robot has the name
        first = self.targets | {point.name for point in self._settings.get("points", ())}  # px, and xc = px − d6 r13
        self.notation.term_key = lambda term: (not any(s.name in first for s in term.free_symbols),
                                               self._prints_negative(term), joint_key(term))
        self.notation.factor_key = lambda factor: (not _is_written(factor), factor_key(factor))
        angles, joint_abbreviation = self._settings.get("angles", ()), self.notation.abbreviation
        for angle in angles:
            self.notation.label[angle] = angle  # for the legend: cφ1 = cos φ1
        named = {angle: (100 + k,) for k, angle in enumerate(angles)}  # after the joints in the legend
        self.notation.abbreviation = lambda expr: (
            (1, NamedAngle(_FUNCTION[type(expr)], ((expr.args[0], 1),), named[expr.args[0]]))
            if type(expr) in _FUNCTION and expr.args[0] in named else joint_abbreviation(expr))

    def doprint(self, expr):
        key = (expr, self.numbers)  # the branches share most of their assignments; read-back numbers differ
        if key not in self._printed:
            self._printed[key] = super().doprint(by_target(expr, self.targets))
        return self._printed[key]

    def _signed(self, term) -> tuple[bool, str]:
        """(is negative, text of its magnitude), the sign decided by how the terms print, not by
        how SymPy stores them: −(A + B) whose A and B each print with a minus reads A + B, and
        −(a − b) reads b − a. A minus before a bracket of positive terms stays when the bracket
        holds no other, −(r13 c1 + r23 s1), and goes to each term when it does, as Craig writes
        θ23: −(d4 − a2 s3)(px c1 + py s1) − pz(a3 + a2 c3), not −[(d4 − a2 s3)(…) + pz(…)]."""
        if not term.is_Mul:
            return super()._signed(term)
        negative, coefficient, factors = self._sign_parts(term)
        if coefficient == 1 and len(factors) == 1 and factors[0].is_Add:
            total = factors[0]
            if not negative:
                return False, self._print(total)
            spread = -total
            if not self._leads_negative(spread):
                return False, self._print(spread)
            if any(f.is_Add for t in total.args for f in sympy.Mul.make_args(t)):
                return True, self._print(spread)[len(self.minus.strip()):]
        return negative, self._product(coefficient, factors)

    def _in_order(self, terms, key) -> list:
        """A positive number leads a sum that would start with a minus: 1 − r33², not −r33² + 1."""
        ordered = super()._in_order(terms, key)
        lead = next((t for t in ordered if t.is_number and t > 0), None)
        if lead is not None and self._prints_negative(ordered[0]):
            ordered.remove(lead)
            ordered.insert(0, lead)
        return ordered

    def _leads_negative(self, total) -> bool:
        """Whether a sum, printed in its order, starts with a minus (as the terms print)."""
        return self._prints_negative(min(total.args, key=self.notation.term_key))

    def _prints_negative(self, term) -> bool:
        if not term.is_Mul:
            return term.could_extract_minus_sign()
        if term not in self._negative:
            self._negative[term] = self._sign_parts(term)[0]
        return self._negative[term]

    def _print_Written(self, expr):
        """A number as the robot file wrote it (see dhsym.inverse.written): 0.0823; a long one by
        the name the derivation gives it (a2, β)."""
        name = self.numbers.name_of(expr.name)
        return expr.name if name is None else display_name(name, self.style)

    def _join(self, pieces):
        """Factors side by side; two numbers that could not be made one (0.089159² · 0.0823) get a dot."""
        out = pieces[0]
        for piece in pieces[1:]:
            numbers = out[-1:].isdigit() and piece[:1].isdigit()
            out = out + self._times + piece if numbers else super()._join([out, piece])
        return out

    def _print_Symbol(self, expr):
        if expr.name in self.targets:
            return target_name(expr.name, self.style)
        return super()._print_Symbol(expr)

    def _arguments(self, expr) -> str:
        return ", ".join(self._print(argument) for argument in expr.args)


_FUNCTION = {sympy.cos: "c", sympy.sin: "s"}
_SUBSCRIPT = re.compile(r"_\{(\w+)\}('*)$")  # \phi_{1}' -> \phi 1': a prime of the derivation's stays


class NamedAngle(Abbreviation):
    """c or s of an angle the solution names (Craig's planar 3R: φ = θ1 + θ2 + θ3, c_φ, s_φ),
    labelled with its name as a lettered joint is: cφ1 (LaTeX c_{\\phi 1}, ASCII c(phi1)).

    >>> phi = sympy.Symbol("phi_1", real=True)
    >>> [NamedAngle("c", ((phi, 1),)).label(style) for style in ("unicode", "latex", "ascii")]
    ['cφ1', 'c_{\\\\phi 1}', 'c(phi1)']
    """

    @property
    def wide(self) -> bool:
        return False  # one name: no commas to explain

    def label(self, style: str) -> str:
        name = display_name(self.indices[0][0].name, style)
        if style == "latex":
            return self.function + "_{" + _SUBSCRIPT.sub(r" \1\2", name) + "}"  # \phi_{1} -> \phi 1
        return self.function + (f"({name})" if style == "ascii" else name)  # c(phi1), as a lettered joint


def by_target(expr, targets=_TARGET):
    """`expr` with each sum linear in the target's elements grouped by them, as Craig prints s6
    of the PUMA: −r11(c1 c23 s4 − s1 c4) − r21(s1 c23 s4 + c1 c4) + r31 s23 s4. A sum with a
    product or a power of the target's elements (px², px r13) stays as it is.

    >>> r11, r21, a, b = sympy.symbols("r11 r21 a b", real=True)
    >>> by_target(r11*a - r11*b + r21*a)
    a*r21 + r11*(a - b)
    """
    if not isinstance(expr, sympy.Basic) or expr.is_Atom:
        return expr
    args = tuple(by_target(argument, targets) for argument in expr.args)
    if args != expr.args:
        expr = expr.func(*args)
    if not expr.is_Add:
        return expr
    groups: dict = {}
    for term in expr.args:
        found = [f for f in sympy.Mul.make_args(term) if f.is_Symbol and f.name in targets]
        if len(found) > 1 or _has_target(term / found[0] if found else term, targets):
            return expr  # not linear in the target
        groups.setdefault(found[0] if found else None, []).append(term / found[0] if found else term)
    if all(len(terms) < 2 for key, terms in groups.items() if key is not None):
        return expr
    return sympy.Add(*(sympy.Add(*terms) if key is None else key * sympy.Add(*terms)
                       for key, terms in groups.items()))


def _is_written(factor) -> bool:
    return isinstance(factor.base if factor.is_Pow else factor, Written)


def _has_target(term, targets) -> bool:
    return any(symbol.name in targets for symbol in term.free_symbols)


class IKTextPrinter(_InverseNotation, TextSentences, TextPrinter):
    """Text: atan2(py, px), acos(D), √(1 − D²); the solver's sentences (dhsym.printing.ik_sentences)."""

    _default_settings = {**TextPrinter._default_settings, "angles": (), "points": (), "targets": TARGET_NAMES,
                         "frame_offset": 0}
    _times = " · "

    def _print_atan2(self, expr):
        return f"atan2({self._arguments(expr)})"

    def _print_acos(self, expr):
        return f"acos({self._arguments(expr)})"

    def _print_asin(self, expr):
        return f"asin({self._arguments(expr)})"

    def _fraction(self, top, bottom, grouped):
        spaced = " " in bottom and not (bottom.startswith("(") and _one_group(bottom))
        return super()._fraction(top, f"({bottom})" if spaced else bottom, grouped)


class IKLatexPrinter(_InverseNotation, LatexSentences, LatexPrinter):
    r"""LaTeX: \mathrm{atan2}(y, x) (MathJax spaces \operatorname{atan2} as "atan 2"), \arccos, \arcsin, p_{x};
    the solver's sentences (dhsym.printing.ik_sentences)."""

    _default_settings = {**LatexPrinter._default_settings, "angles": (), "points": (), "targets": TARGET_NAMES,
                         "frame_offset": 0}
    _times = " \\cdot "

    def _print_atan2(self, expr):
        return f"\\mathrm{{atan2}}({self._arguments(expr)})"

    def _print_acos(self, expr, exp=None):
        return f"\\arccos({self._arguments(expr)})"

    def _print_asin(self, expr, exp=None):
        return f"\\arcsin({self._arguments(expr)})"

    def _fraction(self, top, bottom, grouped):
        if top.startswith("(") and _one_group(top):  # \frac{a + b}{c}, not \frac{(a + b)}{c}
            top = top[1:-1]
        return super()._fraction(top, bottom, grouped)


class IKExactPrinter(ExactPrinter):
    """The JSON form: a written number first in its product, as the file's numbers are written
    (`0.0823*r13`, not `r13*0.0823`); sympy.sympify reads it back."""

    def _print_Written(self, expr):
        return expr.name

    def _print_Mul(self, expr):
        coefficient, rest = expr.as_coeff_Mul()
        factors = sympy.Mul.make_args(rest)
        lead = next((f for f in factors if isinstance(f, Written)), None)
        if lead is None or coefficient not in (1, -1) or len(factors) < 2:
            return super()._print_Mul(expr)
        others = sympy.Mul(*(f for f in factors if f is not lead))
        text = self._print(others)
        if precedence(others) < PRECEDENCE["Mul"] or text.startswith("1/") or text.startswith("-"):
            text = f"({text})"
        return ("-" if coefficient < 0 else "") + f"{lead.name}*{text}"


def _one_group(text: str) -> bool:
    """Whether `text` is one bracketed group, (…), whose opening bracket closes at its end."""
    depth = 0
    for position, ch in enumerate(text):
        depth += ch in "([{"
        depth -= ch in ")]}"
        if depth == 0 and position < len(text) - 1:
            return False
    return depth == 0


def ik_settings(chain: Chain, numbers: WrittenNumbers | None = None, numbering: Numbering = PLAIN) -> dict:
    """The settings of the IK printers for a chain's solution: its joint variables and offsets, how
    its numbers are written, and how its frames and joints are numbered (a robot file's first_frame)."""
    return {"joint_variables": chain.joint_variables, "offsets": written_offsets(chain.rows),
            "numbers": numbers or WrittenNumbers(), "first_joint": numbering.first_joint,
            "frame_offset": numbering.offset}


def text_printer(chain: Chain, numbers=None, numbering: Numbering = PLAIN, ascii: bool = False, angles=(), points=(),
                 targets=TARGET_NAMES) -> IKTextPrinter:
    """The text printer of a chain's solution; `angles` (see `named_angles`) print as cφ1, sφ1,
    and `points` (see `target_points`) come first in a sum, as the target's elements (`targets`,
    see `target_names`) do."""
    return IKTextPrinter(ik_settings(chain, numbers, numbering), ascii=ascii, angles=tuple(angles),
                         points=tuple(points), targets=tuple(targets))


def latex_printer(chain: Chain, numbers=None, numbering: Numbering = PLAIN, angles=(), points=(), targets=TARGET_NAMES,
                  kind=None) -> IKLatexPrinter:
    """The LaTeX printer of a chain's solution (`kind`: a subclass, the documents' own)."""
    return (kind or IKLatexPrinter)(ik_settings(chain, numbers, numbering), angles=tuple(angles),
                                    points=tuple(points), targets=tuple(targets))


def solution_printer(solution, numbering: Numbering = PLAIN, kind=None, ascii: bool = False):
    """The printer (`kind`: IKTextPrinter, IKLatexPrinter or a subclass) of a whole solution: its
    chain and numbers, the angles it names, the points it writes first, its target's names."""
    settings = ik_settings(solution.chain, solution.numbers, numbering)
    if ascii:
        settings["ascii"] = True
    return (kind or IKTextPrinter)(settings, angles=named_angles(solution), points=target_points(solution),
                                   targets=target_names(solution))


def target_names(solution) -> tuple:
    """The names of a solution's target elements, r11 … pz, primed where the robot uses one."""
    return tuple(symbol.name for symbol in solution.target_symbols)


def target_points(solution) -> tuple:
    """The names a solution gives to quantities linear in the target (the wrist centre,
    xc = px − d6 r13): a book writes them first, as the target's elements, zc − d1 rather than d1 − zc."""
    names = set(target_names(solution))

    def linear(value) -> bool:
        targets = [s for s in sympy.sympify(value).free_symbols if s.name in names]
        form = sympy.Poly(value, *targets) if targets and value.is_polynomial(*targets) else None
        return form is not None and form.total_degree() == 1
    return tuple(name for name, value in solution.definitions if linear(value))


def named_angles(solution) -> tuple:
    """The angles a solution names and takes the cosine or sine of (φ1 = atan2(r21, r11), then
    px − l3 cos φ1): a book abbreviates them as it does the joints', c_φ, s_φ."""
    joints = set(solution.joint_variables)
    pairs = list(solution.definitions) + [pair for branch in solution.branches for pair in branch.assignments]
    inside = {trig.args[0] for _, value in pairs for trig in sympy.sympify(value).atoms(sympy.cos, sympy.sin)}
    return tuple(dict.fromkeys(name for name, _ in pairs if name not in joints and name in inside))


def angle_meanings(solution) -> tuple:
    """(name, the joint angles it stands for) of each angle a branch solves as one and writes a
    joint through (θ2 = θ23 − θ3 gives θ23 = θ2 + θ3; Spong's SCARA: θ4 = θ1 + θ2 − φ1 gives
    φ1 = θ1 + θ2 − θ4): the text defines every name it uses.

    >>> import dhsym
    >>> from dhsym.inverse import solve
    >>> angle_meanings(solve(dhsym.load("puma560").chain))
    ((theta_23, theta_2 + theta_3),)
    """
    angles = {row.variable for row in solution.chain.rows if row.joint == "R"}  # a slide's sum (z_c = d1 + d2) is none
    meanings: dict = {}
    for branch in solution.branches:
        names = {name for name, _ in (*solution.definitions, *branch.assignments)} - set(solution.joint_variables)
        for joint, value in branch.assignments:
            value = sympy.sympify(value)  # a solution written by hand may assign a plain 0
            for name in sorted(names & value.free_symbols - set(meanings), key=str) if joint in angles else ():
                slope = sympy.diff(value, name)
                meaning = sympy.expand((joint - (value - slope * name)) / slope) if slope in (1, -1) else None
                known = angles | {s for s in value.free_symbols if isinstance(s, Written)}  # an offset β too
                if meaning is not None and meaning.free_symbols <= known:  # the joint is the name less other angles
                    meanings[name] = meaning
    return tuple(meanings.items())


def target_title(chain: Chain, numbering: Numbering = PLAIN, style: str = "unicode") -> str:
    """⁰T₆: the transform `dhsym fk` prints by default, from base (else 0) to tool (else n), as numbered."""
    return render.transform_title(numbering.frame(chain.first_frame), numbering.frame(chain.last_frame), style)


def variable_list(symbols, printer) -> str:
    """θ1, θ2 in the printer's style."""
    return ", ".join(printer.doprint(symbol) for symbol in symbols)


def latex_name(symbol: sympy.Symbol) -> str:
    """A name as the LaTeX printers write it: x_{c}, \\theta_{1}, p_{x}."""
    return target_name(symbol.name, "latex") if plain(symbol.name)[0] in _TARGET else display_name(symbol.name, "latex")
