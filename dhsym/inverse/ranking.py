"""Which sub-problem a round of the search (dhsym.inverse.scan) solves next: the best of what is
solvable, by a table of named preferences.

Equations of the preferred kind come first (the tip's position, then rotation elements, then
inner frames' positions, which mix the two; a wrist prefers rotations; a joint whose two roots
were found not both to reach the pose is taken from whichever kind fixes it), and within a kind
the `Preference`s in order; among equals the shortest wins, then the one found first. Equations
are sorted by length within each unknown, and only the shortest few are worked out: a bounded
cost.

>>> [preference.name for preference in Preference][:3]
['CONSTANT_PAIR', 'CONSTANT_SLIDE', 'PAIR_SIGN_KNOWN']
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from enum import IntEnum
from itertools import combinations

from . import subproblems as sp
from .candidates import candidate, pair_works, says_nothing, shape_of, sizes, touches

KINDS = ("position", "orientation", "mixed")
FORMS_PER_UNKNOWN = 8  # the shortest equations per unknown whose sub-problem form is worked out
PAIR_CANDIDATES = 4  # the shortest equations per unknown that are tried in pairs


class Preference(IntEnum):
    """The sub-problems in the order a round prefers them, best first."""

    CONSTANT_PAIR = 0  # atan2 of a pair whose determinant is a non-zero number: one root, never degenerate
    CONSTANT_SLIDE = 1  # a slide from a coordinate with a constant coefficient
    PAIR_SIGN_KNOWN = 2  # atan2 of a pair whose determinant can vanish (degenerate there), its sign known
    PAIR = 3  # ... its sign unknown: atan2(s·det², c·det²)
    TWO_ROOTS = 4  # one equation with two roots: a cos θ + b sin θ = c, the law of cosines, a slide from a distance
    VANISHING_SLIDE = 5  # a slide from a coordinate whose coefficient can vanish: d = z_c/c2 fails where c2 = 0,
    # a pose that is no singularity, so a last resort
    MEETING_ROOTS = 6  # two roots that are one at every pose of the arm: their ± of rounding noise costs digits


@dataclass(frozen=True)
class Option:
    """One way a round can go: its `key` (kind, Preference, length: the least goes first), the `rule`
    that solves it ("pair", "linear", "quadratic", "one") and its candidates (dhsym.inverse.candidates).
    A pair's preference is a lower bound until it is `checked`."""

    key: tuple
    rule: str
    candidates: tuple
    checked: bool = True


def best(pool, remaining, prismatic, prefer, constants, witness, memos, unique=frozenset(),
         first=frozenset()) -> Option | None:
    """The best solvable sub-problem among the equations `pool` for the unknowns `remaining`, or None;
    one for an unknown in `first` (a wrist's middle joint, which the books solve before the
    others) wherever there is one."""
    order = list(prefer) + [k for k in KINDS if k not in prefer]
    kind = lambda c: 0 if c.variable in unique else order.index(c.equation.kind)  # noqa: E731
    grouped = _grouped(pool, remaining, prismatic, order, memos)
    singles = [c for found in _worked(grouped, order, prismatic, constants, witness, memos, unique).values()
               for c in found]
    options = _singles(singles, kind, prismatic, witness, memos, unique) + _pairs(singles, kind, prismatic, memos)
    preferred = [option for option in options if option.candidates[0].variable in first]
    return (preferred and _first(preferred, witness, memos)) or _first(options, witness, memos)


def pairs_for(pool, variable, settings, keep, limit: int = FORMS_PER_UNKNOWN) -> list[Option]:
    """The pairs of equations that determine the angle `variable`, made of the first `limit`
    equations whose forms `keep` admits (shortest first), each pair of one matrix equation: the other
    ways a round could solve it (dhsym.inverse.mirrored). `settings`: (prismatic, prefer,
    constants, witness, memos) of the search."""
    prismatic, prefer, constants, witness, memos = settings
    order = list(prefer) + [k for k in KINDS if k not in prefer]
    singles = []
    for items in _grouped(pool, [variable], prismatic, order, memos).values():
        for *_, equation, shape in items:
            found = candidate(equation, shape, constants, memos) if len(singles) < limit else None
            if found is not None and keep(found) and not says_nothing(found, prismatic, witness):
                singles.append(found)
    kind = lambda c: order.index(c.equation.kind)  # noqa: E731
    working = []
    for option in _pairs(singles, kind, prismatic, memos, limit):
        forms = tuple(c.form for c in option.candidates)
        if memos.remember(memos.works, forms, pair_works, *forms, witness):
            working.append(option)
    return working


def preference(single, prismatic, witness) -> tuple[str, Preference]:
    """(rule, Preference) of one equation solved on its own."""
    if single.variable not in prismatic:
        return "one", Preference.MEETING_ROOTS if touches(single, False, witness) else Preference.TWO_ROOTS
    if len(single.form) == 2:
        return "linear", Preference.CONSTANT_SLIDE if single.form[0].is_number else Preference.VANISHING_SLIDE
    return "quadratic", Preference.MEETING_ROOTS if touches(single, True, witness) else Preference.TWO_ROOTS


def _grouped(pool, remaining, prismatic, order, memos) -> dict:
    """{angle: [(kind, on the target's side, sizes, place, equation, shape)]} for every equation in one
    unknown (or one sum of angles), each group sorted: first the equations where the unknown is on
    the chain's side alone, with the shortest chain side (there the coefficients of cos and sin are
    the chain's constants)."""
    groups: dict = {}
    unknown = set(remaining)
    for equation in pool:
        held = memos.free_symbols(equation.expr)
        key = (equation.expr, tuple(v for v in remaining if v in held))  # rounds look at the same equations again
        shape = memos.remember(memos.shapes, key, shape_of, equation, remaining, prismatic, memos)
        if shape is not None:
            on_target_side = bool(memos.free_symbols(equation.lhs) & unknown)
            measured = memos.remember(memos.sizes, equation, sizes, equation)
            groups.setdefault(shape[0], []).append((order.index(equation.kind), on_target_side, *measured,
                                                    len(groups.get(shape[0], [])), equation, shape))
    return {angle: sorted(group, key=lambda item: item[:5]) for angle, group in groups.items()}


def _worked(grouped, order, prismatic, constants, witness, memos, unique) -> dict:
    """{angle: [candidates]}: the forms worked out kind by kind. Once one kind gives a candidate, no
    equation of a later kind can be in the best option (the kind ranks first), and its forms are
    never needed, but for the joints in `unique` (any kind may give their one-root rule, so each
    kind gets its share)."""
    worked: dict = {angle: [] for angle in grouped}
    settled = False
    for level in range(len(order)):
        for angle, items in grouped.items():
            alone = items[0][-1][1] in unique
            if settled and not alone:
                continue
            for kind, *_, equation, shape in items:
                if kind != level or len(worked[angle]) >= FORMS_PER_UNKNOWN * (level + 1 if alone else 1):
                    continue
                if shape[1] not in prismatic and memos.silent(equation.expr, shape, witness):
                    continue  # its form, worked out, would say nothing: not worked out
                found = candidate(equation, shape, constants, memos)
                if found is not None and not says_nothing(found, prismatic, witness):
                    worked[angle].append(found)
        settled = settled or any(c.variable not in unique for found in worked.values() for c in found)
        if settled and not unique:
            break
    return worked


def _singles(singles, kind, prismatic, witness, memos, unique) -> list[Option]:
    """An option for each equation solved on its own; none with two roots for a joint in `unique`."""
    options = []
    for single in singles:
        if single.variable in unique and (single.variable not in prismatic or len(single.form) != 2):
            continue  # two roots, not both reaching the pose
        rule, rank = preference(single, prismatic, witness)
        options.append(Option((kind(single), rank, memos.form_length(single.form)), rule, (single,)))
    return options


def _pairs(singles, kind, prismatic, memos, limit: int = PAIR_CANDIDATES) -> list[Option]:
    """An option for each pair of the shortest equations of one matrix equation in the same angle,
    its preference a lower bound (CONSTANT_PAIR, or PAIR_SIGN_KNOWN) until it is checked."""
    by_source: dict = {}
    for single in singles:
        if single.variable not in prismatic:
            by_source.setdefault((single.angle, single.equation.source), []).append(single)
    options = []
    for group in by_source.values():
        for first, second in combinations(group[:limit], 2):
            constant = all(x.is_number for x in first.form[:2] + second.form[:2])
            rank = Preference.CONSTANT_PAIR if constant else Preference.PAIR_SIGN_KNOWN
            length = memos.form_length(first.form) + memos.form_length(second.form)
            options.append(Option((max(kind(first), kind(second)), rank, length), "pair", (first, second), False))
    return options


def _first(options, witness, memos) -> Option | None:
    """The first of the options with the least key, or None. A pair's key is a lower bound until it
    comes first: only then is it checked (does it determine the angle? is its determinant's sign
    fixed?), so pairs that cannot win cost nothing; the choice is the same as with every key known."""
    pending = [(option.key, index, option) for index, option in enumerate(options)]
    while pending:
        chosen = min(pending, key=lambda item: item[:2])
        key, index, option = chosen
        if option.checked:
            return option
        pending.remove(chosen)
        forms = tuple(c.form for c in option.candidates)
        if not memos.remember(memos.works, forms, pair_works, *forms, witness):
            continue
        if key[1] == Preference.PAIR_SIGN_KNOWN:
            sign = memos.remember(memos.signs, forms, sp.determinant_sign, *forms)
            key = (key[0], Preference.PAIR_SIGN_KNOWN if sign else Preference.PAIR, key[2])
        pending.append((key, index, replace(option, key=key, checked=True)))
    return None
