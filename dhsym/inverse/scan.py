"""The search a student does by hand: among the equations, find one in a single unknown (or a
pair) that is a known sub-problem, solve it, and go on with that unknown known.

Each round takes the best of what is solvable (dhsym.inverse.ranking: the kind of equation first,
then a table of named preferences, then the shortest) and solves it by its rule
(dhsym.inverse.rules). An angle that enters only through a sum of parallel-axis angles
(``θ1 + θ2 + θ3``) is solved as that sum first.

The number of rounds is the number of unknowns, and each looks at a fixed pool of equations: the
work is bounded before it starts. Two roots are told apart by a sign symbol σ = ±1; one
derivation serves every branch.

>>> x, t = sympy.symbols("x theta_1", real=True)
>>> from dhsym.inverse.equations import Equation
>>> found = scan([Equation(x, sympy.cos(t), "position", "x")], [t], set())
>>> found.assignments
[(theta_1, atan2(sigma_1*sqrt(1 - x**2), x))]
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

import sympy

from ..core.size import length
from ..errors import NoClosedForm
from . import algebra
from .fresh import fresh_symbol
from .lookups import Memos
from .mirrored import solve_round
from .ranking import best
from .witness import number_at


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
    coordinates: list = field(default_factory=list)  # (sum, name): a distance's coordinates named (X, Y)
    laws: list = field(default_factory=list)  # the law of cosines' knowns (dhsym.inverse.coordinates.Law)

    def keep_degenerate(self, kept) -> None:
        """Keep the degenerate cases at the indices `kept` (in order), and the pairs in `vanishing`
        that point at them, renumbered."""
        self.vanishing = [(expr, kept.index(k)) for expr, k in self.vanishing if k in kept]
        self.degenerate = [self.degenerate[k] for k in kept]


def scan(equations, unknowns, prismatic, derivation: Derivation | None = None, prefer=("position",),
         constants=frozenset(), witness: dict | None = None, unique=frozenset(), first=(),
         last=()) -> Derivation:
    """Solve `equations` for `unknowns` (in the order a textbook numbers them); `prismatic` is the
    set of those that are slides; `constants` the robot's lengths (never zero). `witness` gives
    numbers for every name at one generic pose: an equation whose coefficients vanish there says
    nothing (0 = 0 once earlier results hold) and is passed over. The joints in `unique` are
    solved only by a rule with one root (their two roots were found not both to reach the pose:
    dhsym.inverse.reach). The unknowns in `first` are solved before the others, in that order,
    wherever an equation gives them (a wrist's θ5, then θ4, as the books do); an unknown in `last`
    (the wrist's θ6) from the pair that mirrors the first's (dhsym.inverse.mirrored). Raises
    UserError when no sub-problem applies."""
    derivation = derivation or Derivation()
    witness = {} if witness is None else witness
    memos = Memos()  # this search's own: nothing kept between searches, nothing shared by two at once
    pool = [e for e in equations if e.expr != 0]
    remaining = list(unknowns)
    pending: list = []  # (variable, expression) for joints written through a sum, assigned at the end
    while remaining:
        option = best(pool, remaining, set(prismatic), prefer, frozenset(constants), witness, memos, unique,
                      frozenset([v for v in first if v in remaining][:1]))
        if option is None:
            solved = [str(v) for v in unknowns if v not in remaining]
            raise NoClosedForm("no closed form by the course's rules: "
                            + (f"after {', '.join(solved)}, " if solved else "")
                            + f"no equation holds only one of {', '.join(map(str, remaining))} as a known sub-problem")
        candidates = option.candidates
        known = {name for name, _ in derivation.assignments}
        settings = (set(prismatic), prefer, frozenset(constants), witness, memos)
        value = in_coordinates(solve_round(pool, option, derivation, settings, last), derivation.coordinates)
        for name, named in derivation.assignments:
            if name not in known and name not in witness:  # a name the rule made (D, K); X, Y come with numbers
                witness[name] = number_at(named, witness)
        variable, angle = candidates[0].variable, candidates[0].angle
        if angle == variable:
            derivation.assignments.append((variable, value))
        else:
            pool = _through_sum(variable, angle, value, pool, pending, derivation, witness, memos)
        remaining.remove(variable)
        ready = True
        while ready:  # a joint written through a sum is assigned once what it is written with is known
            waiting = set(remaining) | {v for v, _ in pending}
            ready = [item for item in pending if not item[1].free_symbols & waiting]
            for item in ready[:1]:
                derivation.assignments.append(item)
                pending.remove(item)
    return derivation


def _through_sum(variable, angle, value, pool, pending, derivation, witness, memos) -> list:
    """A sum of angles solved as one (θ23 = value): name it, write `variable` through it in the
    equations left (returned), and keep `variable`'s own value pending until what it needs is known."""
    phi = fresh_symbol(angle_name(angle, len(derivation.angles) + 1), derivation.reserved)
    derivation.angles[phi] = angle
    derivation.assignments.append((phi, value))
    witness[phi] = number_at(angle, witness)
    coefficient = angle.coeff(variable)
    expression = algebra.expand((phi - (angle - coefficient * variable)) / coefficient)
    pending.append((variable, expression))
    return [replace(e, lhs=e.lhs.xreplace({variable: expression}), rhs=e.rhs.xreplace({variable: expression}))
            if variable in memos.free_symbols(e.lhs) | memos.free_symbols(e.rhs) else e
            for e in pool]  # the rest stay as they are


def in_coordinates(value, coordinates) -> sympy.Expr:
    """`value` with the sums that name a distance's coordinates (X = px c1 + py s1 − …) written
    as their names, where that is shorter."""
    for expression, name in coordinates:
        written = value.subs(expression, name)
        if written != value and length(written) < length(value):
            value = written
    return value


def angle_name(angle, number: int) -> str:
    """The name of a sum of joint angles as a book writes it, θ23 for θ2 + θ3 (Craig's, Spong's),
    where every term is a joint angle numbered 1..9 with one letter; else φk (k = `number`).

    >>> t1, t2, t3, t5 = sympy.symbols("theta_1 theta_2 theta_3 theta_5", real=True)
    >>> angle_name(t2 + t3, 1), angle_name(t1 + t2 + t3, 1), angle_name(t5 + 1, 2), angle_name(t2 - t3, 1)
    ('theta_23', 'theta_123', 'phi_2', 'phi_1')
    """
    terms = [_JOINT.fullmatch(term.name) if term.is_Symbol else None for term in sympy.Add.make_args(angle)]
    if len(terms) > 1 and all(terms) and len({m.group(1) for m in terms}) == 1:
        return f"{terms[0].group(1)}_{''.join(sorted(m.group(2) for m in terms))}"
    return f"phi_{number}"


_JOINT = re.compile(r"([a-z]+)_([1-9])")
