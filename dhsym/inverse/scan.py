"""The search a student does by hand: among the equations, find one in a single unknown (or a
pair) that is a known sub-problem, solve it, and go on with that unknown known.

Each round takes the best of what is solvable. Equations of the preferred kind come first (the
tip's position, then rotation elements, then inner frames' positions, which mix the two; a wrist
prefers rotations), and within a kind this order: an atan2 pair whose determinant is a non-zero
number (unique, never degenerate); a slide from a coordinate with a constant coefficient; an
atan2 pair whose determinant can vanish (unique, degenerate where it does; a known sign before an
unknown one); one equation with two roots (``a cos θ + b sin θ = c``, the law of cosines, a slide
from a distance); last, a slide from a coordinate whose coefficient can vanish. Among equals the
shortest wins. An angle that enters only through a sum of parallel-axis angles (``θ1 + θ2 + θ3``)
is solved as that sum first.

The number of rounds is the number of unknowns, and each looks at a fixed pool of equations: the
work is bounded before it starts. Two roots are told apart by a sign symbol σ = ±1; one
derivation serves every branch.

>>> import sympy
>>> x, t = sympy.symbols("x theta_1", real=True)
>>> from dhsym.inverse.equations import Equation
>>> found = scan([Equation(x, sympy.cos(t), "position", "x")], [t], set())
>>> found.assignments
[(theta_1, atan2(sigma_1*sqrt(1 - x**2), x))]
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from itertools import combinations

import sympy

from ..core.size import length, tree_size
from ..errors import UserError
from . import algebra
from . import subproblems as sp
from .fresh import fresh, fresh_symbol
from .lookups import Memos
from .sentences import ByEquations, Exists, Subproblem, Undetermined
from .solution import DerivationStep
from .witness import number_at

WITNESS_ZERO = 1e-8
FORMS_PER_UNKNOWN = 8  # the shortest equations per unknown whose sub-problem form is worked out
PAIR_CANDIDATES = 4  # the shortest equations per unknown that are tried in pairs


@dataclass
class Derivation:
    """What the search found: assignments in order (with sign symbols σ for two roots), the
    sign symbols with the joint they choose for, the steps, existence conditions, degenerate cases."""

    assignments: list = field(default_factory=list)
    signs: list = field(default_factory=list)  # (σ, joint variable, sub-problem)
    steps: list = field(default_factory=list)
    conditions: list = field(default_factory=list)
    degenerate: list = field(default_factory=list)
    vanishing: list = field(default_factory=list)  # (expression, index in degenerate) where a pair is singular
    reserved: frozenset = frozenset()  # the robot's own names, which the derivation's never take (dhsym.inverse.fresh)
    angles: dict = field(default_factory=dict)  # φk -> the sum of angles (or angle and offset) it names


@dataclass(frozen=True)
class Candidate:
    equation: object
    angle: sympy.Expr  # the unknown or the sum of angles it enters through
    form: tuple  # (a, b, c) for an angle, polynomial coefficients for a slide
    variable: sympy.Symbol  # the unknown it determines


def scan(equations, unknowns, prismatic, derivation: Derivation | None = None, prefer=("position",),
         constants=frozenset(), witness: dict | None = None, unique=frozenset()) -> Derivation:
    """Solve `equations` for `unknowns` (in the order a textbook numbers them); `prismatic` is the
    set of those that are slides; `constants` the robot's lengths (never zero). `witness` gives
    numbers for every name at one generic pose: an equation whose coefficients vanish there says
    nothing (0 = 0 once earlier results hold) and is passed over. The joints in `unique` are
    solved only by a rule with one root (their two roots were found not both to reach the pose:
    dhsym.inverse.reach). Raises UserError when no sub-problem applies."""
    derivation = derivation or Derivation()
    witness = {} if witness is None else witness
    memos = Memos()  # this search's own: nothing kept between searches, nothing shared by two at once
    pool = [e for e in equations if e.expr != 0]
    remaining = list(unknowns)
    pending: list = []  # (variable, expression) for joints written through a sum, assigned at the end
    while remaining:
        best = _best(pool, remaining, set(prismatic), prefer, frozenset(constants), witness, memos, unique)
        if best is None:
            solved = [str(v) for v in unknowns if v not in remaining]
            raise UserError("no closed form by the course's rules: "
                            + (f"after {', '.join(solved)}, " if solved else "")
                            + f"no equation holds only one of {', '.join(map(str, remaining))} as a known sub-problem")
        rule, candidates = best
        known = len(derivation.assignments)
        value = _apply(rule, candidates, derivation, constants, memos, witness)
        for name, named in derivation.assignments[known:]:
            witness[name] = number_at(named, witness)
        variable, angle = candidates[0].variable, candidates[0].angle
        if angle == variable:
            derivation.assignments.append((variable, value))
        else:
            phi = fresh_symbol(f"phi_{len(derivation.angles) + 1}", derivation.reserved)
            derivation.angles[phi] = angle
            derivation.assignments.append((phi, value))
            witness[phi] = number_at(angle, witness)
            coefficient = angle.coeff(variable)
            expression = algebra.expand((phi - (angle - coefficient * variable)) / coefficient)
            pool = [replace(e, lhs=e.lhs.xreplace({variable: expression}), rhs=e.rhs.xreplace({variable: expression}))
                    if variable in memos.free_symbols(e.lhs) | memos.free_symbols(e.rhs) else e
                    for e in pool]  # the rest stay as they are
            pending.append((variable, expression))
        remaining.remove(variable)
        ready = True
        while ready:  # a joint written through a sum is assigned once what it is written with is known
            waiting = set(remaining) | {v for v, _ in pending}
            ready = [item for item in pending if not item[1].free_symbols & waiting]
            for item in ready[:1]:
                derivation.assignments.append(item)
                pending.remove(item)
    return derivation


def _vanishes(expr, witness: dict) -> bool:
    value = number_at(expr, witness)
    return value is not None and abs(value) < WITNESS_ZERO


def _best(pool, remaining, prismatic, prefer, constants, witness, memos, unique=frozenset()):
    """(rule, candidates) of the best solvable sub-problem, or None. Equations are sorted by
    length within each unknown first, and only the shortest few are worked out: a bounded cost."""
    order = list(prefer) + [k for k in ("position", "orientation", "mixed") if k not in prefer]
    # a joint in `unique` is taken from whichever kind fixes it, as soon as one does
    kind_rank = lambda c: 0 if c.variable in unique else order.index(c.equation.kind)  # noqa: E731
    groups: dict = {}
    unknown = set(remaining)
    for equation in pool:
        held = memos.free_symbols(equation.expr)
        key = (equation.expr, tuple(v for v in remaining if v in held))  # rounds look at the same equations again
        shape = memos.remember(memos.shapes, key, _shape, equation, remaining, prismatic, memos)
        if shape is not None:
            # first the equations where the unknown is on the chain's side alone, with the shortest
            # chain side: there the coefficients of cos and sin are the chain's constants
            on_target_side = bool(memos.free_symbols(equation.lhs) & unknown)
            sizes = memos.remember(memos.sizes, equation, _sizes, equation)
            groups.setdefault(shape[0], []).append((kind_rank_of(equation, order), on_target_side, *sizes,
                                                    len(groups.get(shape[0], [])), equation, shape))
    # Forms are worked out kind by kind: once one kind gives a candidate, no equation of a later
    # kind can be in the best option (the kind ranks first), and its forms are never needed.
    ordered = {angle: sorted(group, key=lambda item: item[:5]) for angle, group in groups.items()}
    worked: dict = {angle: [] for angle in ordered}
    settled = False  # a kind has given a candidate: later kinds are worked only for the joints in `unique`
    for level in range(len(order)):
        for angle, items in ordered.items():
            alone = items[0][-1][1] in unique  # any kind may give its unique rule, so each kind gets its share
            if settled and not alone:
                continue
            for kind, *_, equation, shape in items:
                if kind != level or len(worked[angle]) >= FORMS_PER_UNKNOWN * (level + 1 if alone else 1):
                    continue
                if shape[1] not in prismatic and memos.silent(equation.expr, shape, witness):
                    continue  # its form, worked out, would say nothing: not worked out
                candidate = _candidate(equation, shape, constants, memos)
                if candidate is not None and not _says_nothing(candidate, prismatic, witness):
                    worked[angle].append(candidate)
        settled = settled or any(c.variable not in unique for found in worked.values() for c in found)
        if settled and not unique:
            break
    singles = [c for found in worked.values() for c in found]
    options = []
    for c in singles:
        if c.variable in unique and (c.variable not in prismatic or len(c.form) != 2):
            continue  # two roots, not both reaching the pose
        if c.variable in prismatic:
            rule = "linear" if len(c.form) == 2 else "quadratic"
            # d = z_c / c2 fails where c2 = 0, a pose that is no singularity: a last resort
            rank = (1 if c.form[0].is_number else 5) if rule == "linear" else (6 if _touches(c, True, witness) else 4)
            options.append(((kind_rank(c), rank, memos.form_length(c.form)), rule, [c]))
        else:
            rank = 6 if _touches(c, False, witness) else 4  # two roots; last where they are one
            options.append(((kind_rank(c), rank, memos.form_length(c.form)), "one", [c]))
    by_source: dict = {}
    for c in singles:
        if c.variable not in prismatic:
            by_source.setdefault((c.angle, c.equation.source), []).append(c)
    for group in by_source.values():
        for first, second in combinations(group[:PAIR_CANDIDATES], 2):
            constant = all(x.is_number for x in first.form[:2] + second.form[:2])
            # rank 2 or 3 (the determinant's sign known or not) is settled only if the pair comes first
            options.append(((max(kind_rank(first), kind_rank(second)), 0 if constant else 2,
                             memos.form_length(first.form) + memos.form_length(second.form)), "pair?",
                            [first, second]))
    return _first(options, witness, memos)


def _first(options, witness, memos):
    """The first of the options with the least key, or None. A pair's key is a lower bound until it
    comes first: only then is it checked (does it determine the angle? is its determinant's sign
    fixed?), so pairs that cannot win cost nothing; the choice is the same as with every key known."""
    pending = [(key, index, rule, candidates) for index, (key, rule, candidates) in enumerate(options)]
    while pending:
        best = min(pending, key=lambda o: o[:2])
        key, index, rule, candidates = best
        if rule != "pair?":
            return rule, candidates
        pending.remove(best)
        forms = (candidates[0].form, candidates[1].form)
        if not memos.remember(memos.works, forms, _pair_works, *forms, witness):
            continue
        if key[1] == 2:
            sign = memos.remember(memos.signs, forms, sp.determinant_sign, *forms)
            key = (key[0], 2 if sign else 3, key[2])
        pending.append((key, index, "pair", candidates))
    return None


def _touches(candidate, slide: bool, witness) -> bool:
    """Whether the square root's argument of a two-root equation vanishes at the witness pose: an
    equation can touch an arm of fewer than six joints' poses everywhere (one double root), and
    its ±√ of rounding noise would cost digits."""
    argument = sp.root_argument(candidate.form, slide)
    return argument is not None and bool(witness) and _vanishes(argument, witness)


def kind_rank_of(equation, order) -> int:
    return order.index(equation.kind)


def _says_nothing(candidate, prismatic, witness) -> bool:
    """0 = 0 at the witness pose: the leading coefficients vanish once earlier results hold."""
    if candidate.variable in prismatic:
        return _vanishes(candidate.form[0], witness)
    return _vanishes(candidate.form[0], witness) and _vanishes(candidate.form[1], witness)


def _pair_works(first, second, witness) -> bool:
    """A pair determines the angle: its determinant is not zero, nor are both its solutions' numerators."""
    (a1, b1, k1), (a2, b2, k2) = first, second
    if not witness:
        return sp.determinant(first, second, factored=False) != 0 and sp.pair_is_defined(first, second)
    return not _vanishes(a1 * b2 - a2 * b1, witness) and not (_vanishes(k1 * b2 - b1 * k2, witness)
                                                              and _vanishes(a1 * k2 - a2 * k1, witness))


def _sizes(equation) -> tuple[int, int]:
    """The tree sizes of an equation's chain side and of the whole."""
    return tree_size(equation.rhs), tree_size(equation.expr)


def _shape(equation, remaining, prismatic, memos):
    """(the unknown or sum of angles it enters through, the unknown it determines), when the
    equation holds one unknown (or one sum of angles); else None. Structure only, no algebra."""
    expr = equation.expr
    unknown = memos.free_symbols(expr) & set(remaining)
    if not unknown:
        return None
    if unknown & prismatic:
        return (next(iter(unknown)),) * 2 if len(unknown) == 1 else None
    angles = {f.args[0] for f in memos.trig_atoms(expr) if memos.free_symbols(f.args[0]) & unknown}
    if len(angles) == 1:
        (angle,) = angles
        variable = _last(angle, unknown, remaining)
        if variable is not None and (not _outside(expr, angle, unknown) or not (
                expr.xreplace({sympy.cos(angle): 0, sympy.sin(angle): 0}).free_symbols & unknown)):
            return angle, variable
    return (next(iter(unknown)),) * 2 if len(unknown) == 1 else None


def _outside(expr, angle, unknown) -> bool:
    """Whether an unknown occurs anywhere but in cos(angle) and sin(angle): a walk that spares
    rebuilding the expression (when none does, putting 0 for them leaves no unknown)."""
    if isinstance(expr, (sympy.cos, sympy.sin)) and expr.args[0] == angle:
        return False
    if expr.is_Symbol:
        return expr in unknown
    return any(_outside(a, angle, unknown) for a in expr.args)


def _candidate(equation, shape, constants, memos) -> Candidate | None:
    """The sub-problem form of `equation` in the unknown `shape` names, or None (kept in `memos`)."""
    angle, variable = shape
    form = memos.remember(memos.forms, (equation.expr, angle, constants), _form, equation.expr, angle, variable,
                          constants, memos)
    return None if form is None else Candidate(equation, angle, form, variable)


def _form(expr, angle, variable, constants, memos):
    if not isinstance(angle, sympy.Symbol) or angle != variable:
        psi = sympy.Dummy("psi")
        replaced = expr.xreplace({sympy.cos(angle): sympy.cos(psi), sympy.sin(angle): sympy.sin(psi)})
        return sp.trig_linear(replaced, psi, constants)
    if any(variable in memos.free_symbols(f) for f in memos.trig_atoms(expr)):
        return sp.trig_linear(expr, variable, constants)
    form = sp.polynomial(expr, variable)
    return tuple(form) if form is not None and form[0] != 0 else None


def _last(angle, unknown, remaining):
    """The unknown of a sum of angles that the sum determines: the last one, with coefficient ±1."""
    for variable in reversed(remaining):
        if variable in unknown and angle.coeff(variable) in (1, -1):
            rest = algebra.expand(angle - angle.coeff(variable) * variable)
            if not rest.free_symbols & {variable}:
                return variable
    return None


def _named(derivation, letter: str, value: sympy.Expr) -> sympy.Expr:
    """A long right-hand side gets a name, as a book names D and K; short ones stay as they are."""
    if value.is_Symbol or value.is_number or length(value) <= 2:
        return value
    taken = {str(name) for name, _ in derivation.assignments}
    name = next(n for n in (fresh(n, derivation.reserved) for n in [letter] + [f"{letter}_{k}" for k in range(2, 99)])
                if n not in taken)
    symbol = sympy.Symbol(name, real=True)
    derivation.assignments.append((symbol, value))
    return symbol


def _apply(rule, candidates, derivation, constants, memos, witness=None) -> sympy.Expr:
    """The value of the candidates' unknown (or sum), with its steps, conditions and sign symbol."""
    first = candidates[0]
    angle, variable = first.angle, first.variable
    shown = angle if angle != variable else variable
    said = variable if (angle - variable).is_number else shown  # "q3", not "q3 - 123412150740817/1e14"
    if rule == "pair":
        for index, c in enumerate(candidates, start=1):
            a, b, k = c.form
            derivation.steps.append(DerivationStep(
                a * sympy.cos(shown) + b * sympy.sin(shown), k,
                Subproblem("sum of parallel-axis angles" if angle != variable else "atan2 of a pair"), (variable,),
                (*c.equation.where, f" (equation {index} of 2)")))
        det = sp.determinant(candidates[0].form, candidates[1].form)
        if not det.is_number and algebra.has_square_pair(det) and length(det) < 60:
            reduced = algebra.pythagoras(det)  # cos² + sin² = 1, but no double angles: a book writes c1, not sin(2θ1)
            if reduced is not det:
                det = min([det, sympy.factor(reduced)], key=length)
        forms = (candidates[0].form, candidates[1].form)
        if not det.is_number:  # said in the joints' angles: sin(θ5 + 1), not the sin φ2 it was solved through
            det = det.xreplace(derivation.angles)
            derivation.vanishing.append((det, len(derivation.degenerate)))
            derivation.degenerate.append(sp.degenerate_pair(det, said, forms))
        return sp.pair(*forms, memos.remember(memos.signs, forms, sp.determinant_sign, *forms))
    sigma = fresh_symbol(f"sigma_{len(derivation.signs) + 1}", derivation.reserved)
    if rule == "linear":
        a, b = first.form
        derivation.steps.append(DerivationStep(a * variable, -b, Subproblem("prismatic joint from a coordinate"),
                                               (variable,), first.equation.where))
        if not a.is_number:
            derivation.degenerate.append(Undetermined((a,), variable, ByEquations(1)))
        return sp.prismatic(first.form, sigma)
    if rule == "quadratic":
        a, b, c = first.form
        derivation.steps.append(DerivationStep(a * variable ** 2 + b * variable, -c,
                                               Subproblem("prismatic joint from a distance"), (variable,),
                                               first.equation.where))
        derivation.signs.append((sigma, variable, "prismatic"))
        root = b ** 2 - 4 * a * c if b != 0 else -c / a
        derivation.conditions.append(Exists(sympy.factor_terms(root)))
        return sp.prismatic(first.form, sigma)
    slides = {name: value for name, value in derivation.assignments if value.is_polynomial(*value.free_symbols)}
    a, b, c = (algebra.shorter_with(x, slides) for x in first.form)  # the SCARA's d3 cancels from D
    law = (b == 0 or a == 0)
    if _touches(first, False, witness):
        return _double_root(a, b, c, law, variable, first.equation.where, derivation)
    shape = "A"
    if not law and c != 0:  # the book's form: the equation's sign and the atan2 identity that print shortest
        a, b, c, shape = min(sp.book_variants(a, b, c, sigma),
                             key=lambda v: sympy.count_ops(v[4]) + sympy.count_ops(v[2]))[:4]
    c = _named(derivation, "D" if law else "K", c)
    derivation.steps.append(DerivationStep(a * sympy.cos(shown) + b * sympy.sin(shown), c,
                                           Subproblem("law of cosines" if law else "a cos θ + b sin θ = c"),
                                           (variable,), first.equation.where))
    derivation.signs.append((sigma, variable, "law" if law else "one"))
    root = sp.existence(a, b, c)
    if root is not None:
        derivation.conditions.append(Exists(root, unknown=said))
    if not (a.is_number or b.is_number) and (a.free_symbols | b.free_symbols) - set(constants):
        derivation.degenerate.append(Undetermined((sp.unsigned(a), sp.unsigned(b)), said, ByEquations(1)))
    return sp.one_equation(a, b, c, sigma, shape)


def _double_root(a, b, c, law, variable, where, derivation) -> sympy.Expr:
    """The one root where a² + b² = c² at every pose of the arm (see subproblems.double_root)."""
    c = _named(derivation, "D" if law else "K", c)
    derivation.steps.append(DerivationStep(a * sympy.cos(variable) + b * sympy.sin(variable), c,
                                           Subproblem("law of cosines" if law else "a cos θ + b sin θ = c",
                                                      double_root=True),
                                           (variable,), (*where, "; a² + b² = c² at every pose of the arm")))
    return sp.double_root(a, b, c)
