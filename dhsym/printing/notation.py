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

Offsets (``theta: theta_2 - pi/4``): an abbreviation stands for the cosine or sine of the joint
angles *as the table writes them*, offsets included, and the legend says so:
``c12 = cos(θ1 + θ2 − π/4)``. An offset that is a multiple of π/2 folds into the notation
instead (``cos(θ2 − π/2)`` is ``s2``), as lecture notes write it, so that such robots keep their
``c23``/``s23`` form; any other offset (``π/4``, ``0.1``, ``β``) stays in the angle, variable
first. SymPy rewrites ``cos(θ2 − π/4)`` as ``sin(θ2 + π/4)`` on its own; `Notation.as_written`
gives each angle its written offset back before printing (an exact identity).

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
>>> offset = Notation(t[:2], {t[1]: -sympy.pi / 4})
>>> offset.as_written(sympy.sin(t[0] + t[1] + sympy.pi / 4))
cos(theta_1 + theta_2 - pi/4)
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field

import sympy
from sympy.printing.conventions import split_super_sub
from sympy.printing.latex import translate
from sympy.printing.pretty.pretty_symbology import greek_unicode, sub, sup

GREEK_NAMES = {letter: name for name, letter in greek_unicode.items()}  # 'θ' -> 'theta'
PRIME = "\u02b9"  # ʹ, how the inverse kinematics primes a name the robot uses (dhsym.inverse.fresh)
_COMBINING_BAR = "\u0305"
_MINUS = {"unicode": " − ", "ascii": " - ", "latex": " - "}


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

    def __init__(self, joint_variables, offsets=None, write=None, write_sympy=None, first_joint=1):
        """Joint labels come from the names' subscripts when every joint variable has a
        distinct one: θ4, θ5, θ6 of a wrist give c4, c5, c6, and a general row in θ_i gives c_i.
        Otherwise joints are numbered by row, from `first_joint`. Angles named with Greek letters other than θ
        keep their letter in the label: φ2 gives cφ2. `offsets` maps a joint variable to the
        offset its angle keeps (see `written_offsets`); `write` prints an offset in a legend (a
        printer's own), `write_sympy` in SymPy's form (the JSON legend)."""
        joint_variables = list(joint_variables)
        self.offsets = {v: sympy.sympify(o) for v, o in (offsets or {}).items() if o != 0}
        self.write = write or sympy.sstr
        self.write_sympy = write_sympy or sympy.sstr
        self._found: dict = {}  # abbreviation() of each cos/sin seen: term ordering asks again and again
        labels = [_subscript(s.name) for s in joint_variables]
        if any(is_word_name(s.name) for s in joint_variables):
            labels = _suffix_labels([s.name for s in joint_variables])
        elif None not in labels and _lettered(joint_variables):
            labels = [_letter(s.name) + label for s, label in zip(joint_variables, labels)]
        if None in labels or len(set(labels)) != len(labels):
            labels = list(range(first_joint, first_joint + len(joint_variables)))
        elif all(label.isdigit() for label in labels):
            labels = [int(label) for label in labels]
        self.label = dict(zip(joint_variables, labels))
        self.position = {symbol: k for k, symbol in enumerate(joint_variables, 1)}

    def abbreviation(self, expr: sympy.Expr) -> tuple[int, Abbreviation] | None:
        """(sign, abbreviation) if expr is cos/sin of a signed sum of joint angles, each with the
        offset its row keeps (none by default), else None."""
        if not isinstance(expr, (sympy.cos, sympy.sin)):
            return None
        if expr not in self._found:
            self._found[expr] = self._abbreviation(expr)
        return self._found[expr]

    def _abbreviation(self, expr: sympy.Expr) -> tuple[int, Abbreviation] | None:
        split = self._split_angle(expr.args[0])
        if split is None:
            return None
        terms, constant = split
        if not terms or constant != self._offset_of(terms):
            return None
        terms.sort(key=lambda t: t[0])
        sign = 1
        if terms[0][2] < 0:
            terms = [(p, label, -s) for p, label, s in terms]
            sign = 1 if isinstance(expr, sympy.cos) else -1
        function = "c" if isinstance(expr, sympy.cos) else "s"
        return sign, Abbreviation(function, tuple((label, s) for _, label, s in terms), tuple(p for p, _, _ in terms))

    def _split_angle(self, angle: sympy.Expr):
        """([(position, label, ±1), ...], constant) for a signed sum of joint variables plus a
        constant free of them; None for anything else (2θ1, θ1·l)."""
        terms, constants = [], []
        for term in sympy.Add.make_args(angle):
            coefficient, rest = term.as_coeff_Mul()
            if rest in self.position and coefficient in (1, -1):
                terms.append((self.position[rest], self.label[rest], int(coefficient)))
            elif term.free_symbols & self.position.keys():
                return None
            else:
                constants.append(term)
        return terms, sympy.Add(*constants)

    def _offset_of(self, terms) -> sympy.Expr:
        """The offset a signed sum of joint angles carries: θ1 + (θ2 − π/4) carries −π/4."""
        names = {label: symbol for symbol, label in self.label.items()}
        return sympy.Add(*(sign * self.offsets.get(names[label], 0) for _, label, sign in terms))

    def as_written(self, expr):
        """`expr` with every cos/sin of joint angles written with the offsets of its rows.

        SymPy evaluates cos(θ1 + θ2 − π/4) to sin(θ1 + θ2 + π/4); the two differ by a multiple
        of π/2, so the angle as written comes back exactly: sin(x + π/2) = cos x, and so on.
        """
        if not self.offsets or not isinstance(expr, sympy.Basic):
            return expr
        changes = {}
        for trig in expr.atoms(sympy.cos, sympy.sin):
            split = self._split_angle(trig.args[0])
            if split is None or not split[0]:
                continue
            terms, constant = split
            offset = self._offset_of(terms)
            quarter_turns = (constant - offset) / (sympy.pi / 2)
            if constant == offset or not quarter_turns.is_Integer:
                continue
            angle = trig.args[0] - constant + offset
            turns = int(quarter_turns) % 4  # f(angle + turns·π/2) in terms of cos/sin(angle)
            cosine = isinstance(trig, sympy.cos)
            function = sympy.cos if (turns % 2 == 0) == cosine else sympy.sin
            negative = turns in (1, 2) if cosine else turns in (2, 3)
            changes[trig] = (-1 if negative else 1) * function(angle, evaluate=False)
        return expr.xreplace(changes) if changes else expr

    def name_of(self, label) -> str:
        """The symbol name of the joint with this label, as the robot file spells it."""
        return next(symbol.name for symbol, own in self.label.items() if own == label)

    def offset(self, abbreviation: Abbreviation) -> sympy.Expr:
        """The offset in the angle of an abbreviation: −π/4 for c12 = cos(θ1 + θ2 − π/4), else 0."""
        return self._offset_of([(None, label, sign) for label, sign in abbreviation.indices])

    def angle(self, abbreviation: Abbreviation) -> sympy.Expr:
        """The angle an abbreviation takes the cosine or sine of, offsets included."""
        names = {label: symbol for symbol, label in self.label.items()}
        return sympy.Add(*(sign * names[label] for label, sign in abbreviation.indices)) + self.offset(abbreviation)

    def meaning(self, abbreviation: Abbreviation, style: str) -> str:
        """What an abbreviation stands for: 'cos θ1', 'sin(θ2 + θ3)' or 'cos(θ2 − π/4)'; in the
        "sympy" style with the robot file's names, as SymPy reads it back: 'sin(theta_2 + theta_3)'."""
        function = {"c": "cos", "s": "sin"}[abbreviation.function]
        if style == "sympy":
            terms = " ".join(("- " if sign < 0 else "+ ") + self.name_of(number)
                             for number, sign in abbreviation.indices).lstrip("+ ")
            return f"{function}({terms}{self._offset_text(abbreviation, style)})"
        names = {label: symbol for symbol, label in self.label.items()}
        angle = ""
        for position, (number, sign) in enumerate(abbreviation.indices):
            name = display_name(names[number].name, style)
            angle += (_MINUS[style] if sign < 0 else " + " if position else "") + name
        angle += self._offset_text(abbreviation, style)
        single = len(abbreviation.indices) == 1 and self.offset(abbreviation) == 0
        if style == "latex":
            function = "\\" + function
            return f"{function}{{{angle}}}" if single else f"{function}({angle})"
        return f"{function} {angle}" if single else f"{function}({angle})"

    def _offset_text(self, abbreviation: Abbreviation, style: str) -> str:
        """' − π/4' for an abbreviation whose angle keeps an offset, else ''; symbols before numbers."""
        offset, text = self.offset(abbreviation), ""
        write = self.write_sympy if style == "sympy" else self.write
        minus = " - " if style == "sympy" else _MINUS[style]
        for term in sorted(sympy.Add.make_args(offset), key=self.angle_key) if offset != 0 else ():
            negative = term.could_extract_minus_sign()
            text += (minus if negative else " + ") + write(-term if negative else term)
        return text

    def term_key(self, term: sympy.Expr) -> tuple:
        """Order terms by joint: constants first, then by the lowest joint they involve."""
        keys = sorted(self._atom_keys(term))
        unsigned = -term if term.could_extract_minus_sign() else term
        return (tuple(keys), sympy.default_sort_key(unsigned))

    def angle_key(self, term: sympy.Expr) -> tuple:
        """Order the terms of an angle (or of a table cell) as people write them: joint variables
        first in joint order, then other symbols, then numbers: θ2 − π/4, d3 + l1."""
        joints = [self.position[s] for s in term.free_symbols if s in self.position]
        group = 0 if joints else 1 if term.free_symbols else 2
        return (group, min(joints, default=0), sympy.default_sort_key(term))

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


def written_offsets(rows) -> dict:
    """{joint variable: the offset its angle keeps} for the revolute rows of a chain.

    `theta: theta_2 - pi/4` keeps −π/4; a multiple of π/2 folds into the notation and is left
    out (`theta_2 - pi/2` keeps nothing, `theta_2 + pi/2 + 0.1` keeps 0.1).

    >>> from dhsym.core.chain import DHRow
    >>> t2 = sympy.Symbol("theta_2", real=True)
    >>> written_offsets([DHRow.revolute(t2 - sympy.pi / 4), DHRow.revolute(sympy.Symbol("q", real=True) + sympy.pi)])
    {theta_2: -pi/4}
    """
    offsets = {}
    for row in rows:
        if row.joint != "R":
            continue
        slope = sympy.diff(row.theta, row.variable)
        if slope not in (1, -1):
            continue
        offset = row.theta / slope - row.variable
        kept = [t for t in sympy.Add.make_args(offset) if not (t / (sympy.pi / 2)).is_Integer]
        if kept:
            offsets[row.variable] = sympy.Add(*kept)
    return offsets


def is_word_name(name: str) -> bool:
    """Whether a name is a word with underscores, such as a URDF joint's `right_s0` or
    `shoulder_pan_joint`, rather than a letter with indices (`theta_1`, `l_23`): it prints as
    written (LaTeX `\\mathrm{right\\_s0}`), since `rights0` would be no one's name.

    >>> is_word_name("right_s0"), is_word_name("theta_1"), is_word_name("elbow_1"), is_word_name("ab_c")
    (True, False, False, False)
    """
    base, supers, subs = split_super_sub(name)
    numbered = not supers and len(subs) == 1 and subs[0].isdigit()  # elbow_1 stays elbow₁-like: elbow1
    return "_" in name and len(base) > 2 and base not in greek_unicode and base not in GREEK_NAMES and not numbered


def _suffix_labels(names: list) -> list:
    """Short joint labels for word names: what follows their common prefix up to an underscore,
    when that is at most four letters or digits (right_s0 → s0, left_j1 → j1); else None for each.

    >>> _suffix_labels(["right_s0", "right_s1", "right_e0"]), _suffix_labels(["shoulder_pan", "elbow"])
    (['s0', 's1', 'e0'], [None, None])
    """
    common = os.path.commonprefix(names).rfind("_") + 1  # cut after an underscore: right_s0 → s0, not 0
    rests = [name[common:] for name in names]
    if len(names) > 1 and all(rest.isalnum() and rest.isascii() and len(rest) <= 4 for rest in rests):
        return rests
    return [None] * len(names)


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
    """A symbol name as a textbook writes it: theta_1 -> θ1 (unicode), \\theta_{1} (LaTeX); a name
    the inverse kinematics primed (dhsym.inverse.fresh), phi_1ʹ, as φ1′ (unicode), \\phi_{1}' (LaTeX)."""
    bare = name.rstrip(PRIME)
    if bare != name and bare:
        return display_name(bare, style) + ("′" if style == "unicode" else "'") * (len(name) - len(bare))
    if is_word_name(name):
        return "\\mathrm{" + name.replace("_", "\\_") + "}" if style == "latex" else name
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
    """The TeX for a Greek letter's name (SymPy's own translation), or None if it is no Greek letter.

    >>> greek_latex("theta"), greek_latex("lamda"), greek_latex("Alpha"), greek_latex("l")
    ('\\\\theta', '\\\\lambda', '\\\\mathrm{A}', None)
    """
    return translate(name) if name in greek_unicode else None


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
