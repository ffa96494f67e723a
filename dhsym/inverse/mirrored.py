"""A spherical wrist's last angle as the books write it (Spong's and Siciliano's Euler angles):
from the row of the wrist's rotation that mirrors the column its first angle came from, with the
sign the middle angle's branch chose,

    θ4 = atan2(σ r23, σ r13),   θ6 = atan2(σ r32, −σ r31),

rather than through θ4 (θ6 = atan2(r21 c4 − r11 s4, r22 c4 − r12 s4), twice as long).

The two are one angle wherever s5 ≠ 0. Where s5 = 0 the row is (0, 0) and θ4 is not determined:
there the form through θ4 gives a member of the family, so the degenerate case keeps it as its
`member`, and the generated code computes it where |s5| is below dhsym.inverse.codegen's LINED_UP.

>>> import dhsym
>>> from dhsym.inverse.solve import solve
>>> wrist = solve(dhsym.load("spherical_wrist").chain)
>>> [str(value) for _, value in wrist.branches[0].assignments][2]
'atan2(r32, -r31)'
>>> case = wrist.degenerate[0]
>>> case.condition, str(case.member[0][1])
((sin(theta_5),), 'atan2(-r11*sin(theta_4) + r21*cos(theta_4), -r12*sin(theta_4) + r22*cos(theta_4))')
"""
from __future__ import annotations

from dataclasses import replace

import sympy

from ..core.size import operations
from . import subproblems as sp
from .ranking import pairs_for
from .rules import sign_of, sine_as_sign, solve_rule
from .sentences import LinedUp, Undetermined


def solve_round(pool, option, derivation, settings, last=()) -> sympy.Expr:
    """The value a round of the search finds by `option`'s rule; for the wrist's last angle (in
    `last`) by the books' pair where that prints shorter than `option`'s value (which is then the
    degenerate case's member). `settings`: (prismatic, prefer, constants, witness, memos) of the search."""
    prismatic, prefer, constants, witness, memos = settings
    if option.rule != "pair" or option.candidates[0].variable not in last:
        return solve_rule(option.rule, option.candidates, derivation, constants, memos, witness)
    through = solve_rule(option.rule, option.candidates, _scratch(derivation), constants, memos, witness)
    signs = {sigma for sigma, _, _ in derivation.signs}
    book = None if through.free_symbols & signs else _book_pair(pool, option, derivation, settings)
    if book is None or operations(book[1]) >= operations(through):
        return solve_rule(option.rule, option.candidates, derivation, constants, memos, witness)
    cases = len(derivation.degenerate)
    value = solve_rule("pair", book[0].candidates, derivation, constants, memos, witness)
    _keep_member(derivation, cases, option.candidates[0].variable, through)
    return value


def _scratch(derivation):
    """A copy of the derivation whose lists a rule may add to without changing the derivation."""
    return replace(derivation, **{name: list(getattr(derivation, name)) for name in
                                  ("assignments", "signs", "steps", "conditions", "degenerate", "vanishing",
                                   "coordinates", "laws")}, angles=dict(derivation.angles))


def _book_pair(pool, option, derivation, settings):
    """(the pair option, its value) of the shortest pair whose atan2 carries the middle angle's sign
    σ instead of its sine, or None."""
    constants, memos = settings[2], settings[4]
    variable = option.candidates[0].variable
    sines = {sympy.sin(name) for name, _ in derivation.assignments
             if name.is_Symbol and sign_of(sympy.sin(name), derivation) is not None}
    if not sines:
        return None
    found = []
    pool = [equation for equation in pool if _may_share(equation.expr, variable, sines)]
    for other in pairs_for(pool, variable, settings, lambda c: _shares(c.form, sines)):
        forms = tuple(c.form for c in other.candidates)
        if found and sum(operations(x) for form in forms for x in form) > min(found)[0]:
            continue  # its atan2 is built from products of these terms: it prints no shorter, and tidying it costs
        value = sp.pair(*forms, memos.remember(memos.signs, forms, sp.determinant_sign, *forms), set(constants))
        signed = sine_as_sign(value, derivation)
        if signed is not value:
            found.append((operations(signed), len(found), other, signed))
    return min(found, key=lambda item: item[:2])[2:] if found else None


def _may_share(expr, variable, sines) -> bool:
    """Whether every term of `expr` that turns with `variable` holds one same sine: a test on the
    equation as it stands, before its form is worked out, that spares the forms _shares rejects."""
    turning = [term for term in sympy.Add.make_args(expr) if term.has(sympy.cos(variable), sympy.sin(variable))]
    return bool(turning) and any(all(term.has(sine) for term in turning) for sine in sines)


def _shares(form, sines) -> bool:
    """Whether both of the form's coefficients (a cos θ + b sin θ = c) hold one of the sines as a factor."""
    a, b, _ = form
    return any(all(x == 0 or sine in sympy.Mul.make_args(x) for x in (a, b)) for sine in sines)


def _keep_member(derivation, cases: int, variable, member) -> None:
    """The book pair's own degenerate case (sin θ5 = 0 again, for θ6) is the middle angle's case
    said once more: dropped, and that case keeps `variable` = `member` as the value a numeric
    evaluation takes there."""
    for case in derivation.degenerate[cases:]:
        earlier = next((k for k, known in enumerate(derivation.degenerate[:cases])
                        if _lined_up(known) and known.condition == case.condition), None)
        if earlier is None:
            continue
        known = derivation.degenerate[earlier]
        derivation.degenerate[earlier] = replace(known, member=(*known.member, (variable, member)))
        index = derivation.degenerate.index(case)
        derivation.degenerate.pop(index)
        derivation.vanishing = [(expr, k if k < index else k - 1) for expr, k in derivation.vanishing if k != index]
    if len(derivation.degenerate) > cases:  # no earlier case to join: the new one carries the member
        last = derivation.degenerate[-1]
        if _lined_up(last):
            derivation.degenerate[-1] = replace(last, member=((variable, member),))


def _lined_up(case) -> bool:
    """Whether a degenerate case is axes lining up about a joint (s5 = 0)."""
    return isinstance(case, Undetermined) and isinstance(case.reason, LinedUp)
