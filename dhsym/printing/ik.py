"""Inverse-kinematics solutions for people and programs: the textbook text form (c1, s23,
atan2(y, x), a `where` list of the intermediate quantities, every branch by name) and the JSON
contract (full cos/sin/atan2 with the robot file's names, readable by sympy.sympify).

The target's elements print as a book names them: r11 … r33, px, py, pz (LaTeX r_{11}, p_{x}),
primed where the robot uses the name itself (px′, p_{x}': see dhsym.inverse.fresh);
a quotient prints with its denominator bracketed, (px² + py² − a1² − a2²)/(2 a1 a2), and a sum
starts with the target's terms, positive ones first.

>>> import sympy, dhsym
>>> arm = dhsym.load("planar2r")
>>> px, py, a1, a2 = sympy.symbols("px py a_1 a_2", real=True)
>>> printer = IKTextPrinter(chain_settings(arm))
>>> printer.doprint((px**2 + py**2 - a1**2 - a2**2) / (2 * a1 * a2))
'(px² + py² − a1² − a2²)/(2 a1 a2)'
>>> IKLatexPrinter(chain_settings(arm)).doprint(sympy.atan2(py, px) - sympy.acos(px / a1))
'\\\\mathrm{atan2}(p_{y}, p_{x}) - \\\\arccos(\\\\frac{p_{x}}{a_{1}})'
"""
from __future__ import annotations

import re

import sympy
from sympy.printing.precedence import PRECEDENCE, precedence

from ..core.robot import as_robot
from ..inverse.fresh import plain
from ..inverse.solution import TARGET_NAMES
from ..inverse.written import Written
from . import render
from .ik_lines import assignments_text
from .ik_sentences import solution_names, text_sentence, wrap_sentence
from .names import GREEK_NAMES, display_name
from .notation import Abbreviation
from .printers import ExactPrinter, LatexPrinter, TextPrinter, chain_settings

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
        """A number as the robot file wrote it (see dhsym.inverse.written): 0.0823."""
        return expr.name

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


class IKTextPrinter(_InverseNotation, TextPrinter):
    """Text: atan2(py, px), acos(D), √(1 − D²)."""

    _default_settings = {**TextPrinter._default_settings, "angles": (), "points": (), "targets": TARGET_NAMES}
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


class IKLatexPrinter(_InverseNotation, LatexPrinter):
    r"""LaTeX: \mathrm{atan2}(y, x) (MathJax spaces \operatorname{atan2} as "atan 2"), \arccos, \arcsin, p_{x}."""

    _default_settings = {**LatexPrinter._default_settings, "angles": (), "points": (), "targets": TARGET_NAMES}
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


def text_printer(chain, ascii: bool = False, angles=(), points=(), targets=TARGET_NAMES) -> IKTextPrinter:
    """The text printer of a chain's solution; `angles` (see `named_angles`) print as cφ1, sφ1,
    and `points` (see `target_points`) come first in a sum, as the target's elements (`targets`,
    see `target_names`) do."""
    return IKTextPrinter(chain_settings(chain), ascii=ascii, angles=tuple(angles), points=tuple(points),
                         targets=tuple(targets))


def latex_printer(chain, angles=(), points=(), targets=TARGET_NAMES) -> IKLatexPrinter:
    return IKLatexPrinter(chain_settings(chain), angles=tuple(angles), points=tuple(points), targets=tuple(targets))


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


def target_title(chain, style: str = "unicode") -> str:
    """⁰T₆: the transform `dhsym fk` prints by default, from base (else 0) to tool (else n)."""
    robot = as_robot(chain)
    return render.transform_title(robot.first_frame, robot.last_frame, style)  # as printed


def variable_list(symbols, printer) -> str:
    """θ1, θ2 in the printer's style."""
    return ", ".join(printer.doprint(symbol) for symbol in symbols)


def text_solution(solution, width: int = 100, ascii: bool = False) -> str:
    """The whole solution as text that fits `width`: title, target, method, definitions, each
    branch, when branches exist, the degenerate poses, and the legend of c/s abbreviations."""
    chain = solution.chain
    targets = target_names(solution)
    printer = text_printer(chain, ascii, named_angles(solution), target_points(solution), targets)
    style = "ascii" if ascii else "unicode"
    title = f"{chain.name}: inverse kinematics  ({chain.convention}\u00a0DH)"  # "(modified DH)" kept whole
    blocks = [render.wrap(title, width, "  ").replace("\u00a0", " ")]
    target = [[target_name(targets[4 * r + c], style) for c in range(4)] for r in range(3)] + [["0", "0", "0", "1"]]
    blocks.append(render.wrap(f"Target {target_title(chain, style)}, the pose to reach (what `dhsym fk` prints):",
                              width, "  ") + "\n" + render.aligned_matrix(target, ascii))
    names = solution_names(solution)
    about = [f"Method: {text_sentence(solution.method, names, printer)}."]
    if solution.free:
        about.append(f"Free (parameters): {variable_list(solution.free, printer)}.")
    count = len(solution.branches)
    about.append(f"{count} branch{'es' if count != 1 else ''}.")
    blocks.append(render.wrap(" ".join(about), width, "  "))
    if solution.definitions:
        blocks.append("where\n" + assignments_text(solution.definitions, printer, width))
    for number, branch in enumerate(solution.branches, 1):
        heading = render.wrap(f"Branch {number}: {branch.name}", width, "  ")
        blocks.append(heading + "\n" + assignments_text(branch.assignments, printer, width))
    for title, lines in (("Exists when", solution.conditions), ("Degenerate", solution.degenerate)):
        if lines:
            blocks.append(f"{title}:\n" + "\n".join(wrap_sentence("  " + text_sentence(line, names, printer), width,
                                                                  "    ") for line in lines))
    legend = render.text_legend(printer, width)
    text = "\n\n".join(blocks + ([legend] if legend else []))
    return ascii_text(text) if ascii else text


_ASCII = {"−": "-", "–": "-", "≥": ">=", "≤": "<=", "≠": "!=", "·": "*", "×": "x", "√": "sqrt", "±": "+-",
          "→": "->", "…": "...", "²": "^2", "³": "^3", "⁻": "^-", "¹": "^1", "₀": "0", "′": "'", "ʹ": "'"}


def ascii_text(text: str) -> str:
    """Text for --ascii: the solver's sentences may hold Greek letters, squares and signs.

    >>> ascii_text("s5 = 0: only θ4 + θ6 is determined; D² ≤ 1")
    's5 = 0: only theta4 + theta6 is determined; D^2 <= 1'
    """
    out = []
    for ch in text:
        if ch.isascii():
            out.append(ch)
        else:
            out.append(_ASCII.get(ch) or GREEK_NAMES.get(ch) or "?")
    return "".join(out)


def json_solution(solution) -> dict:
    """The JSON contract: full forms with the robot file's names and decimals as written;
    `sympy.sympify` reads every expression back."""
    chain = solution.chain
    exact = IKExactPrinter(chain_settings(chain))
    pairs = lambda items: [[name.name, exact.doprint(value)] for name, value in items]  # noqa: E731
    return {
        "robot": chain.name,
        "convention": chain.convention,
        "joint_variables": [symbol.name for symbol in solution.joint_variables],
        "free": [symbol.name for symbol in solution.free],
        "method": solution.method,
        "target": list(target_names(solution)),
        "definitions": pairs(solution.definitions),
        "solutions": [{"name": branch.name, "assignments": pairs(branch.assignments)}
                      for branch in solution.branches],
        "conditions": list(solution.conditions),
        "degenerate": list(solution.degenerate),
    }


def latex_name(symbol: sympy.Symbol) -> str:
    """A name as the LaTeX printers write it: x_{c}, \\theta_{1}, p_{x}."""
    return target_name(symbol.name, "latex") if plain(symbol.name)[0] in _TARGET else display_name(symbol.name, "latex")
