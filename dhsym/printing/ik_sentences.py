"""The solver's sentences (dhsym.inverse.sentences: when a branch exists, where it degenerates, the
method, a step's sub-problem and note) written out: one `_print_<Record>` per record, shared by
the text and LaTeX printers and by the JSON's plain strings, each style writing the pieces (words,
math, relations) its way and the chain's joints and frames with the robot file's numbers. The
relations a sentence starts with are math, and so are the names it mentions.

>>> import dhsym, sympy
>>> from dhsym.inverse.sentences import ByEquations, Undetermined
>>> from dhsym.printing.ik import text_printer
>>> arm = dhsym.load("planar2r")
>>> px, py = sympy.symbols("px py", real=True)
>>> said = Undetermined((-px, py), arm.joint_variables[0], ByEquations(2))
>>> text_printer(arm).sentence(said)
'px = 0 and py = 0: θ1 is not determined by these equations'
>>> PlainSentences().sentence(said)
'-px = 0 and py = 0: theta_1 is not determined by these equations'
"""
from __future__ import annotations

import re
from dataclasses import dataclass

import sympy
from sympy.printing.str import StrPrinter

from ..inverse.sentences import ByEquations, Frame, Joint, LinedUp, OnAxis
from ..inverse.written import exact_but_named
from . import render
from .ik_words import meaning_text

_GLUE = "\u00a0"  # holds a relation together while a sentence is wrapped
RELATIONS = {"text": {">=": " ≥ ", "<=": " ≤ ", "!=": " ≠ ", "=": " = ", ">": " > ", "<": " < "},
             "latex": {">=": " \\geq ", "<=": " \\leq ", "!=": " \\neq ", "=": " = ", ">": " > ", "<": " < "}}
LINED_UP_UNSAID = "only the sum (or difference) of the angles about them is determined"
SUBPROBLEMS = {"Pieper's distance": "Pieper: a distance that θ{} does not change",
               "Pieper's height": "Pieper: a height that θ{} does not change",
               "Ferrari's quartic": "a quartic in u = tan(θ{}/2), by Ferrari's method"}


@dataclass(frozen=True)
class Math:
    """A piece of a sentence that is math."""

    expr: object


@dataclass(frozen=True)
class Angle(Math):
    """An angle θk or θk + c (a row's offset) in a sentence, written as a book writes it: θk first."""


@dataclass(frozen=True)
class Relation:
    """A piece of a sentence that is a relation, `lhs operator rhs`."""

    lhs: object
    operator: str
    rhs: object = sympy.Integer(0)


class SentenceWriting:
    """`_print_<Record>` for the solver's records; a style writes the pieces (`_pieces`) and
    numbers the chain's joints and frames (the setting `frame_offset`, a robot file's first_frame)."""

    def sentence(self, record) -> str:
        """A record, or a phrase (a tuple of words, joints and frames, or plain words), in this style."""
        if isinstance(record, str):
            return self._said(record)
        return self._said(*record) if isinstance(record, tuple) else self._print(record)

    def _frame(self, frame) -> str:
        return str(frame + self._settings.get("frame_offset", 0) if isinstance(frame, int) else frame)

    def _joint(self, joint: int) -> str:
        return str(joint + self._settings.get("frame_offset", 0))

    def _said(self, *pieces) -> str:
        """Pieces (words, Math, Relation, Joint, Frame, and tuples of them) as one sentence."""
        out = []
        for piece in _flat(pieces):
            if isinstance(piece, Joint):
                piece = self._joint(piece.number)
            elif isinstance(piece, Frame):
                piece = self._frame(piece.frame)
            if isinstance(piece, str) and out and isinstance(out[-1], str):
                out[-1] += piece
            else:
                out.append(piece)
        return self._pieces(out)

    # ---------------------------------------------------------------- when a branch exists

    def _print_Exists(self, said):
        if said.unknown is None:
            return self._said(Relation(said.expression, said.relation))
        if not said.singular:
            meet = "; where it is 0 the two roots meet)"
        elif len(said.singular) == 1:
            meet = ("); where it is 0 the two roots meet, ", self._singular(said.singular[0]))
        else:
            meet = ("); where it is 0 the two roots meet, ", self._singulars(said.singular))
        return self._said(Relation(said.expression, said.relation), " (else ", Math(said.unknown),
                          " has no real value: the target is out of reach", meet)

    def _singular(self, singular) -> tuple:
        """'a singularity of J: the factor s5 of det J, wrist: axes 4 and 6 line up'."""
        meaning = (", ", self._meaning(singular)) if singular.template else ()
        return ("a singularity of J: the factor ", Math(singular.factor), " of det J", *meaning)

    def _singulars(self, singulars) -> tuple:
        """'singularities of J: the factors d3 (joint 3 retracted …) and s2 (axes 1 and 4 …) of det J'."""
        named = [(Math(s.factor), *((" (", self._meaning(s), ")") if s.template else ())) for s in singulars]
        return ("singularities of J: the factors ", *_listed(named[:-1]), " and ", named[-1], " of det J")

    def _meaning(self, singular) -> str:
        """What a factor of det J means, with the joints numbered as printed ('' where it is not said)."""
        return singular.template.format(*(self._joint(j) for j in singular.joints)) if singular.template else ""

    def _print_RealRoot(self, said):
        return self._said("quartic root k (for ", Math(said.joint), f") exists where the root {said.root.name} of the "
                          "quartic is real: 4, 2 or none of the four roots are, and a root that is not real is a "
                          "branch that does not exist")

    def _print_Consistent(self, said):
        joints = f"{said.unknowns} unknown joint{'s' if said.unknowns != 1 else ''}"
        fixed = [(Math(element), " = ", Math(value)) for element, value in said.fixed + said.relations]
        fixed = (" (in every pose of this arm ", _listed(fixed), ")") if fixed else ()
        return self._said(f"the arm has {joints}: only ", _listed([Math(u) for u in said.used]),
                          " are used, and the other elements of the target must be consistent with them", fixed)

    # ---------------------------------------------------------------- where the branches degenerate

    def _print_Undetermined(self, said):
        condition = _listed([Relation(c, "=") for c in said.condition], " and ")
        reason = said.reason
        if isinstance(reason, ByEquations):
            why = " by this equation" if reason.count == 1 else " by these equations"
        elif isinstance(reason, OnAxis):
            point = ("the origin of frame ", Frame(reason.frame)) if reason.point == "frame" else f"the {reason.point}"
            only = ("; only where ", Relation(reason.only[0], "=", reason.only[1])) if reason.only else ()
            why = (" (", point, " on axis ", Joint(reason.joint), *only, ")")
        else:
            why = (" on its own: the axes on either side of ", Math(_joint_symbol(reason.angle)), " line up, and ",
                   self._lined_up(reason), ", a one-parameter family (a numeric evaluation gives one member",
                   *self._member(said), ")")
        factor = () if said.singular is None else ("; ", self._singular(said.singular))
        return self._said(condition, ": ", Math(said.unknown), " is not determined", why, factor)

    def _member(self, said) -> tuple:
        """': there θ6 = atan2(r21 c4 − r11 s4, …) with the θ4 it finds' (the values taken on the family)."""
        if not said.member:
            return ()
        values = _listed([(Math(joint), " = ", Math(value)) for joint, value in said.member], " and ")
        return (": there ", values, " with the ", Math(said.unknown), " it finds")

    def _math(self, piece: Math) -> str:
        """A piece of math in the printer's notation; an angle θk + c with θk first (θ5 + 1)."""
        expr = exact_but_named(piece.expr)
        if isinstance(piece, Angle) and expr.is_Add:
            joint = _joint_symbol(expr)
            offset = expr - joint
            minus = offset.could_extract_minus_sign()
            return self.doprint(joint) + (self.minus if minus else " + ") + self.doprint(-offset if minus else offset)
        return self.doprint(expr)

    def _lined_up(self, lined: LinedUp) -> tuple:
        if not lined.said:
            return (LINED_UP_UNSAID,)
        angle = Angle(lined.angle)
        return ("at ", angle, " = ", Math(sympy.Integer(0)), " only ", Math(lined.total()), " is determined, at ",
                angle, " = ", Math(sympy.pi), " only ", Math(lined.total(at_pi=True)))

    def _print_RootAtPi(self, said):
        joint = Math(said.joint)
        return self._said(Relation(said.leading, "="), ": ", joint, " = ", Math(sympy.pi), " is a root, which "
                          f"{said.root.name} = tan(", joint, "/2) does not reach")

    # ---------------------------------------------------------------- the method

    def _print_Decoupled(self, said):
        arm = _listed([Math(v) for v in said.arm])
        oriented = _listed([Math(v) for v in said.oriented])
        pieper = () if said.quartic is None else (
            " as Pieper solved them: a quartic in tan(θ", Joint(said.quartic), "/2), its roots by radicals (Ferrari)")
        if said.at_start:
            how = (" meet at a point fixed in the base; that point seen from the last frame gives ", arm, pieper,
                   ", the orientation ", oriented)
        else:
            how = (" meet at the wrist centre; the position of the wrist centre gives ", arm, pieper,
                   ", its orientation ", oriented)
        return self._said("kinematic decoupling: the axes of joints ", _joints(said.wrist), how, self._about(said))

    def _print_EulerWrist(self, said):
        return self._said("a spherical wrist: the axes of joints ", _joints(said.joints), " meet in a point; the "
                          "orientation gives the Euler angles", self._about(said))

    def _print_BySubproblems(self, said):
        how = "the sub-problems of the equations (Hawkins's way for three parallel axes)" if said.parallel else \
            "position problem by sub-problems"
        return self._said(how, self._about(said))

    def _about(self, method) -> tuple:
        """What every method line adds: the target elements used, the meaning of the branches' words."""
        used = (" (target elements used: ", _listed([Math(u) for u in method.used]), ")") if method.used else ()
        words = list(dict.fromkeys(meaning_text(meaning, self._joint, self._frame) for meaning in method.words))
        return used + (("; branch names: " + "; ".join(words),) if words else ())

    # ---------------------------------------------------------------- a step of the derivation

    def _print_Subproblem(self, said):
        if said.name in SUBPROBLEMS:
            return self._said(SUBPROBLEMS[said.name].format(self._joint(said.joint)))
        return self._said(said.name + (", one double root" if said.double_root else ""))


def _joint_symbol(angle):
    """θk of an angle θk or θk + c."""
    symbols = angle.free_symbols
    return next(iter(symbols)) if len(symbols) == 1 else angle


def _flat(pieces) -> list:
    out = []
    for piece in pieces:
        if isinstance(piece, tuple):
            out += _flat(piece)
        elif piece is not None:
            out.append(piece)
    return out


def _listed(items, between: str = ", ") -> tuple:
    out: list = []
    for item in items:
        out += [between, item] if out else [item]
    return tuple(out)


def _joints(numbers) -> tuple:
    """Joints 4, 5 and 6 (the chain's numbers, printed as the robot numbers them)."""
    joints = [Joint(number) for number in numbers]
    return (*_listed(joints[:-1]), " and ", joints[-1])


class PlainSentences(SentenceWriting, StrPrinter):
    """The sentences as the JSON gives them: expressions as SymPy writes them (`sympy.sympify`
    reads them), relations with >=, joints and frames numbered as the robot file numbers them."""

    _default_settings = {**StrPrinter._default_settings, "frame_offset": 0}

    def _pieces(self, pieces) -> str:
        out = []
        for piece in pieces:
            if isinstance(piece, Math):
                out.append(str(piece.expr))
            elif isinstance(piece, Relation):
                out.append(f"{piece.lhs} {piece.operator} {piece.rhs}")
            else:
                out.append(piece)
        return "".join(out)


class TextSentences(SentenceWriting):
    """For a text printer: the math in its notation, the file's decimals as it writes them."""

    def _pieces(self, pieces) -> str:
        out = []
        with self.numbers_read_back():
            for piece in pieces:
                if isinstance(piece, Math):
                    out.append(self._math(piece))
                elif isinstance(piece, Relation):
                    out.append(relation(piece, self, "text"))
                else:
                    out.append(piece)
        return "".join(out)


class LatexSentences(SentenceWriting):
    """For a LaTeX printer: the math between dollars, the words through `_words` (the documents
    set them as LaTeX text), an equation of a name and a number as one formula."""

    def _words(self, text: str) -> str:
        return text

    def _pieces(self, pieces) -> str:
        out = []
        with self.numbers_read_back():
            for piece in pieces:
                if isinstance(piece, Math):
                    out.append(f"${self._math(piece)}$")
                elif isinstance(piece, Relation):
                    out.append(f"${relation(piece, self, 'latex')}$")
                else:
                    out.append(self._words(piece))
        return "".join(out).replace("$ = $", " = ")  # r_{32} = -1 as one formula


def relation(part: Relation, printer, style: str) -> str:
    """A relation in the printer's notation. An equation to zero starts with a plus, as a book
    writes it: `px − b = 0`, not `−px + b = 0`."""
    lhs, operator, rhs = exact_but_named(part.lhs), part.operator, exact_but_named(part.rhs)
    left = printer.doprint(lhs)
    if rhs == 0 and operator in ("=", "!=") and left[:1] in "−-":
        flipped = printer.doprint(-lhs)
        left = left if flipped[:1] in "−-" else flipped
    return left + RELATIONS[style][operator] + printer.doprint(rhs)


def wrap_sentence(text: str, width: int, indent: str) -> str:
    """A printed sentence wrapped at `width` without cutting a relation between its sides
    (`pz = 0` stays on one line).

    >>> print(wrap_sentence("in every pose r13 = 0, r23 = 0", 20, "  "))
    in every pose
      r13 = 0, r23 = 0
    """
    glued = re.sub(r" (=|≥|≤|≠|>|<|>=|<=|!=) (?=\S)", lambda m: f"{_GLUE}{m.group(1)}{_GLUE}", text)
    return render.wrap(glued, width, indent).replace(_GLUE, " ")
