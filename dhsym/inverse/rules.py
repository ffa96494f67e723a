"""How a round of the search (dhsym.inverse.scan) solves the sub-problem it chose
(dhsym.inverse.ranking), one function per rule: the value of the unknown (or of a sum of angles),
and what the derivation records with it: the step a student writes, the sign symbol σ = ±1 that
tells two roots apart, when a branch exists, where it degenerates.

>>> import sympy
>>> from dhsym.inverse.candidates import Candidate
>>> from dhsym.inverse.equations import Equation
>>> from dhsym.inverse.lookups import Memos
>>> from dhsym.inverse.scan import Derivation
>>> x, d = sympy.symbols("x d_1", real=True)
>>> found = Derivation()
>>> slide = Candidate(Equation(x, 2 * d, "position", ("x",)), d, (sympy.Integer(2), -x), d)
>>> solve_rule("linear", (slide,), found, (), Memos())
x/2
>>> found.steps[0].subproblem.name
'prismatic joint from a coordinate'
"""
from __future__ import annotations

from dataclasses import replace

import sympy

from ..core.size import length, operations
from . import algebra
from . import subproblems as sp
from .candidates import touches
from .coordinates import in_pair_coordinates, law_of_cosines
from .fresh import fresh, fresh_symbol
from .sentences import ByEquations, Exists, Subproblem, Undetermined
from .solution import DerivationStep


def solve_rule(rule: str, candidates, derivation, constants, memos, witness=None) -> sympy.Expr:
    """The value of the candidates' unknown (or sum) by `rule`, with its steps, conditions and sign symbol."""
    return RULES[rule](candidates, derivation, constants, memos, witness)


def _said(first):
    """(the angle as the steps write it, as the sentences say it): "q3", not "q3 - 123412150740817/1e14"."""
    angle, variable = first.angle, first.variable
    shown = angle if angle != variable else variable
    return shown, variable if (angle - variable).is_number else shown


def by_pair(candidates, derivation, constants, memos, witness=None) -> sympy.Expr:
    """atan2 of a pair: two equations a cos θ + b sin θ = c solved for (cos θ, sin θ)."""
    first = candidates[0]
    angle, variable = first.angle, first.variable
    shown, said = _said(first)
    for index, c in enumerate(candidates, start=1):
        a, b, k = c.form
        derivation.steps.append(DerivationStep(
            a * sympy.cos(shown) + b * sympy.sin(shown), k,
            Subproblem("sum of parallel-axis angles" if angle != variable else "atan2 of a pair"), (variable,),
            (*c.equation.where, f" (equation {index} of 2)")))
    forms = (candidates[0].form, candidates[1].form)
    det = sp.determinant(*forms)
    if not det.is_number and algebra.has_square_pair(det) and length(det) < 60:
        reduced = algebra.pythagoras(det)  # cos² + sin² = 1, but no double angles: a book writes c1, not sin(2θ1)
        if reduced is not det:
            det = min([det, sympy.factor(reduced)], key=length)
    if not det.is_number:  # said in the joints' angles: sin(θ5 + 1), not the sin φ2 it was solved through
        det = det.xreplace(derivation.angles)
        derivation.vanishing.append((det, len(derivation.degenerate)))
        derivation.degenerate.append(sp.degenerate_pair(det, said, forms))
    value = sp.pair(*forms, memos.remember(memos.signs, forms, sp.determinant_sign, *forms), set(constants))
    in_pair_coordinates(derivation, candidates, witness)
    return sine_as_sign(value, derivation)


def sine_as_sign(value, derivation):
    """atan2(s5 y, s5 x) as atan2(σ y, σ x) where θ5 = atan2(σ√…, …) was solved with the sign σ:
    sin θ5 has σ's sign, so the books' θ4 = atan2(r23, r13) on one branch and atan2(−r23, −r13)
    on the other. Anything else is returned as it is."""
    if not isinstance(value, sympy.atan2):
        return value
    y, x = value.args
    shared = set(sympy.Mul.make_args(y)) & set(sympy.Mul.make_args(x))
    for factor in shared:
        sigma = sign_of(factor, derivation)
        if sigma is not None:
            return sympy.atan2(sigma * (y / factor), sigma * (x / factor))
    return value


def sign_of(factor, derivation):
    """σ where `factor` is sin θ and θ = atan2(σ√…, …) (its sine has σ's sign), else None."""
    if not isinstance(factor, sympy.sin) or not factor.args[0].is_Symbol:
        return None
    value = dict(derivation.assignments).get(factor.args[0])
    if not isinstance(value, sympy.atan2) or not value.args[0].is_Mul:
        return None
    signs = {sigma for sigma, _, _ in derivation.signs}
    sigma, rest = value.args[0].as_independent(*signs, as_Add=False)[::-1]
    root_only = rest.is_Pow and rest.exp == sympy.S.Half
    return sigma if sigma in signs and root_only else None


def by_coordinate(candidates, derivation, constants, memos, witness=None) -> sympy.Expr:
    """A slide from a coordinate: a d + b = 0, one root, not determined where a = 0."""
    first = candidates[0]
    variable, (a, b) = first.variable, first.form
    derivation.steps.append(DerivationStep(a * variable, -b, Subproblem("prismatic joint from a coordinate"),
                                           (variable,), first.equation.where))
    if not a.is_number:
        derivation.degenerate.append(Undetermined((a,), variable, ByEquations(1)))
    return sp.prismatic(first.form, None)


def by_distance(candidates, derivation, constants, memos, witness=None) -> sympy.Expr:
    """A slide from a distance: a d² + b d + c = 0, two roots told apart by σ, real where b² − 4ac ≥ 0."""
    first = candidates[0]
    variable, (a, b, c) = first.variable, first.form
    sigma = fresh_symbol(f"sigma_{len(derivation.signs) + 1}", derivation.reserved)
    derivation.steps.append(DerivationStep(a * variable ** 2 + b * variable, -c,
                                           Subproblem("prismatic joint from a distance"), (variable,),
                                           first.equation.where))
    derivation.signs.append((sigma, variable, "prismatic"))
    root = b ** 2 - 4 * a * c if b != 0 else -c / a
    derivation.conditions.append(Exists(sympy.factor_terms(root)))
    return sp.prismatic(first.form, sigma)


def by_one_equation(candidates, derivation, constants, memos, witness=None) -> sympy.Expr:
    """a cos θ + b sin θ = c (the law of cosines where a or b is 0): two roots told apart by σ,
    written in the book's form, real where a² + b² ≥ c²; one root where they meet at every pose."""
    first = candidates[0]
    variable = first.variable
    shown, said = _said(first)
    sigma = fresh_symbol(f"sigma_{len(derivation.signs) + 1}", derivation.reserved)
    slides = {name: value for name, value in derivation.assignments if value.is_polynomial(*value.free_symbols)}
    a, b, c = (algebra.shorter_with(x, slides) for x in first.form)  # the SCARA's d3 cancels from D
    single = (b == 0 or a == 0)  # cos θ = known (or sin θ): the law of cosines' form
    label = _label(a, b, first.equation.distance)
    if touches(first, False, witness):
        return _double_root(a, b, c, (label, letter(label, first.equation)), variable, first.equation.where,
                            derivation)
    shape = "A"
    if not single and c != 0:  # the book's form: the equation's sign and the atan2 identity that print shortest
        a, b, c, shape = min(sp.book_variants(a, b, c, sigma),
                             key=lambda v: operations(v[4]) + operations(v[2]))[:4]
    law = law_of_cosines(c, first.equation, constants) if label == "law of cosines" else None
    c = _named(derivation, letter(label, first.equation), c)
    if law is not None and c.is_Symbol:
        derivation.laws.append(replace(law, name=c))
    derivation.steps.append(DerivationStep(a * sympy.cos(shown) + b * sympy.sin(shown), c, Subproblem(label),
                                           (variable,), first.equation.where))
    derivation.signs.append((sigma, variable, "law" if single else "one"))
    root = sp.existence(a, b, c)
    if root is not None:
        derivation.conditions.append(Exists(root, unknown=said))
    if not (a.is_number or b.is_number) and (a.free_symbols | b.free_symbols) - set(constants):
        derivation.degenerate.append(Undetermined((sp.unsigned(a), sp.unsigned(b)), said, ByEquations(1)))
    elif single and (a + b).free_symbols - set(constants):  # s4 cos θ3 = C: θ3 is lost where s4 = 0
        derivation.degenerate.append(Undetermined((sp.unsigned(a + b),), said, ByEquations(1)))
    return sp.one_equation(a, b, c, sigma, shape)


def _label(a, b, distance: bool) -> str:
    """The sub-problem of a cos θ + b sin θ = c: the law of cosines only where a squared distance
    (a triangle of the arm's lengths) leaves one of cos θ, sin θ; elsewhere, as in an element of a
    rotation (the PUMA's c5) or a projection (the UR5's θ5), a cosine or sine set equal to a known."""
    if a != 0 and b != 0:
        return "a cos θ + b sin θ = c"
    if distance:
        return "law of cosines"
    return "a cos θ = c" if b == 0 else "a sin θ = c"


# The name of a long known side: Spong's D for the law of cosines, Craig's K for a cos θ + b sin θ = c
# from a squared distance (the PUMA's a3 c3 − d4 s3 = K), C (the c of a cos θ = c) from an element or a
# projection: D is the law of cosines' alone, K Craig's alone.
LETTERS = {"law of cosines": "D", "a cos θ + b sin θ = c": "K", "a cos θ = c": "C", "a sin θ = c": "C"}
# a cos θ + b sin θ = c from a point's coordinate: the point's offset from a plane, Spong's d of the
# shoulder offset (the iiwa with θ3 free: yc c1 − xc s1 = d); from a rotation element, C as above.
OFFSET_LETTERS = {"position": "d", "mixed": "d", "orientation": "C"}  # mixed: an inner frame's position


def letter(label: str, equation) -> str:
    """The name of the known side of a `label` step from `equation`, as the books name it."""
    if label == "a cos θ + b sin θ = c" and not equation.distance:
        return OFFSET_LETTERS[equation.kind]
    return LETTERS[label]


def _named(derivation, letter: str, value: sympy.Expr) -> sympy.Expr:
    """A long right-hand side gets a name, as a book names D and K; short ones stay as they are.
    A second of one letter is primed, D′ (a D2 would read as D squared in 1 − D2²)."""
    if value.is_Symbol or value.is_number or length(value) <= 2:
        return value
    name = fresh(letter, derivation.reserved | {str(name) for name, _ in derivation.assignments})
    symbol = sympy.Symbol(name, real=True)
    derivation.assignments.append((symbol, value))
    return symbol


def _double_root(a, b, c, labelled, variable, where, derivation) -> sympy.Expr:
    """The one root where a² + b² = c² at every pose of the arm (see subproblems.double_root);
    `labelled`: the step's sub-problem and the name of its known side."""
    label, name = labelled
    c = _named(derivation, name, c)
    derivation.steps.append(DerivationStep(a * sympy.cos(variable) + b * sympy.sin(variable), c,
                                           Subproblem(label, double_root=True),
                                           (variable,), (*where, "; a² + b² = c² at every pose of the arm")))
    return sp.double_root(a, b, c)


RULES = {"pair": by_pair, "linear": by_coordinate, "quadratic": by_distance, "one": by_one_equation}
