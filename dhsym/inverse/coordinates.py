"""The law of cosines written as the books write it: in the coordinates of the vector whose
squared length it measures, D = (X² + Y² − a2² − a3²)/(2 a2 a3), not the squares multiplied
out, with X and Y the same quantities the next step (the pair that gives the shoulder, Spong's
θ2 = atan2(s, r) − atan2(a3 s3, a2 + a3 c3)) solves with.

The search (dhsym.inverse.scan) meets the two in that order: a squared length gives cos θ3 = D,
then two coordinates of the same vector give θ2 by a pair. When that pair comes, its two known
sides are named (X, Y, Z after the frame's axes of the matrix elements they come from), and D
is written in them where that is shorter and the same number on every branch at the witness pose
(the search's generic pose, every choice of the signs); every later step is written in the
names too (scan.in_coordinates).

>>> import sympy
>>> from dhsym.inverse.equations import Equation
>>> px, py, l1, l2, t2 = sympy.symbols("px py l_1 l_2 theta_2", real=True)
>>> distance = Equation(px**2 + py**2, l1**2 + l2**2 + 2*l1*l2*sympy.cos(t2), "position", ("x",),
...                     distance=True, parts=((px, 0), (py, 0), (0, 0)))
>>> law_of_cosines((px**2 + py**2 - l1**2 - l2**2) / (2*l1*l2), distance, {l1, l2})
Law(name=None, scale=1, rest=-l_1**2 - l_2**2, denominator=2*l_1*l_2)
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from itertools import product

import sympy

from ..core.size import length
from . import algebra
from .fresh import TARGET_NAMES, fresh
from .witness import number_at

AGREE = 1e-9  # relative: the rewritten D and the first are one number at the witness pose


@dataclass(frozen=True)
class Law:
    """cos θ = D with D = (scale·‖v‖² + rest)/denominator, `rest` made of the arm's constants
    (with the squares of the coordinates of v the arm fixes), `name` the symbol D."""

    name: sympy.Symbol | None
    scale: sympy.Expr
    rest: sympy.Expr
    denominator: sympy.Expr


def law_of_cosines(c, equation, constants) -> Law | None:
    """The law of cosines' known side `c` read as (scale·‖v‖² + rest)/denominator, where the
    equation is a squared length (its lhs ‖v‖², seen from the target); None where it is not."""
    if not equation.parts:
        return None
    numerator, denominator = sympy.fraction(sympy.together(c))
    squared = algebra.expand(equation.lhs)
    terms = squared.as_coefficients_dict()
    monomial = next((m for m in terms if not m.is_number), None)
    if monomial is None:
        return None
    scale = algebra.expand(numerator).as_coefficients_dict().get(monomial, 0) / terms[monomial]
    rest = algebra.expand(numerator - scale * squared)
    if scale == 0 or not rest.free_symbols <= set(constants):
        return None
    fixed = [there for _, there in equation.parts if sympy.sympify(there).free_symbols <= set(constants)]
    return Law(None, scale, algebra.expand(rest + scale * sum(x ** 2 for x in fixed)), denominator)


def in_pair_coordinates(derivation, candidates, witness) -> None:
    """Where the pair `candidates` solves with two coordinates of a vector whose squared length
    a law of cosines before it measured, name them and write that D in them."""
    letters = [_axis(c.equation.where) for c in candidates]
    if None in letters or letters[0] == letters[1] or not witness:
        return
    knowns = [_unsigned(c.form[2]) for c in candidates]
    if any(k.is_Symbol or k.is_number for k in knowns):
        return
    for law in list(derivation.laws):
        place = next((k for k, (name, _) in enumerate(derivation.assignments) if name == law.name), None)
        if place is None:
            continue
        before = derivation.assignments[place][1]
        names = [sympy.Symbol(fresh(letter, _taken(derivation)), real=True) for letter in letters]
        written = (law.scale * sum(n ** 2 for n in names) + law.rest) / law.denominator
        earlier = {name for name, _ in derivation.assignments[:place]}
        later = {name for name, _ in derivation.assignments[place:]}
        if any(symbol in later and symbol not in earlier for k in knowns for symbol in k.free_symbols):
            continue  # X and Y would be written after the D they define
        if length(written) + sum(length(k) for k in knowns) >= length(before) + length(knowns[0]):
            continue  # not shorter: D stays as it is
        if not _same_on_every_branch(derivation, before, written, dict(zip(names, knowns)), witness):
            continue
        derivation.assignments[place:place + 1] = [*zip(names, knowns), (law.name, written)]
        derivation.coordinates.extend(zip(knowns, names))
        witness.update({n: number_at(k, witness) for n, k in zip(names, knowns)})
        derivation.laws.remove(law)
        return


def _same_on_every_branch(derivation, before, written, names: dict, witness) -> bool:
    """Whether D as it was and D in the coordinates are one number on every branch (each choice of
    the signs σ) at the witness pose's target: the coordinates hold the joints solved so far,
    which a branch's other root changes (the PincherX's waist turned by π). The branches that
    are not real there are passed over; at least one must be compared."""
    signs = [sigma for sigma, _, _ in derivation.signs]
    compared = False
    for choice in product((1, -1), repeat=len(signs)):
        values = {**witness, **dict(zip(signs, choice))}
        for name, expression in derivation.assignments:
            values[name] = number_at(expression, values)
            if values[name] is None:
                break
        else:
            values.update({n: number_at(k, values) for n, k in names.items()})
            first = number_at(before, values)
            second = None if None in values.values() else number_at(written, values)
            if first is None or second is None:
                continue
            if abs(first - second) > AGREE * max(1.0, abs(first)):
                return False
            compared = True
    return compared


_ELEMENT = re.compile(r"element \(([123]), 4\)")


def _axis(where) -> str | None:
    """X, Y or Z: the axis of the frame a position equation reads (its row), else None."""
    said = where[0] if where and isinstance(where[0], str) else ""
    found = _ELEMENT.match(said)
    if found:
        return "XYZ"[int(found.group(1)) - 1]
    if said[:1] in ("x", "y", "z") and said[1:2] == " ":
        return said[0].upper()
    return None


def _unsigned(expr):
    """The coordinate with its target's terms positive, as a book writes px − l3 cφ and pz − d1."""
    targets = [t for t in sympy.Add.make_args(expr) if any(_bare(s) in TARGET_NAMES for s in t.free_symbols)]
    leading = targets[0] if targets else expr
    return -expr if leading.could_extract_minus_sign() else expr


def _bare(symbol) -> str:
    return symbol.name.rstrip("ʹ'")


def _taken(derivation) -> set:
    return set(derivation.reserved) | {str(name) for name, _ in derivation.assignments}
