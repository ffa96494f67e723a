"""The pair of equations that is a turn: a cos θ + b sin θ = u, −b cos θ + a sin θ = v, solved as
a book solves the planar elbow's θ1, the target's angle less the stretch's,
θ1 = atan2(y, x) − atan2(a2 s2, a1 + a2 c2) (Spong), where that prints shorter than the one atan2
of the pair (dhsym.inverse.subproblems.pair).
"""
from __future__ import annotations

import sympy

from ..core.size import operations
from . import algebra


def turned_pair(first, second, constants=frozenset(), tidy=lambda expr: expr):
    """Where the pair is a turn, a cos θ + b sin θ = u and −b cos θ + a sin θ = v (the point (u, v) is
    the point (a, −b) turned by θ), θ as Spong writes the planar elbow's θ1: the angle of (u, v) less
    the angle of (a, −b), atan2(v, u) − atan2(−b, a); likewise with either equation's sign turned or
    the two swapped. Defined where a² + b² ≠ 0, the pair's degenerate case. Of the ways to write it,
    the shortest; among equals the one with the book's stretch, atan2(a2 s2, a1 + a2 c2) (a positive
    constant in its x, none in its y: `constants`, the robot's lengths), then the fewest minus signs.
    None where no way has such a stretch (the PUMA's θ23 stays Craig's one atan2).

    >>> a1, a2, t2, x, y = sympy.symbols("a_1 a_2 theta_2 x y", real=True)
    >>> c2, s2 = sympy.cos(t2), sympy.sin(t2)
    >>> turned_pair((a1 + a2 * c2, -a2 * s2, x), (a2 * s2, a1 + a2 * c2, y), {a1, a2})
    atan2(y, x) - atan2(a_2*sin(theta_2), a_1 + a_2*cos(theta_2))
    """
    if any(algebra.expand(c).is_number for c in (*first[:2], *second[:2])):
        return None  # a turn by a constant angle (s5 cos θ = x): the single atan2 says it better
    found = []
    for (a1, b1, k1), (a2, b2, k2) in ((first, second), (second, first)):
        for flip in (1, -1):  # −b cos θ + a sin θ = v, or b cos θ − a sin θ = −v
            if algebra.expand(flip * a2 + b1) == 0 and algebra.expand(flip * b2 - a1) == 0:
                for sign in (1, -1):  # both equations negated: the same angle, other signs printed
                    for target in _angles(sign * flip * k2, sign * k1, tidy):
                        for stretch in _angles(-sign * b1, sign * a1, tidy):
                            form = target - stretch
                            stretched = any(_is_stretch(angle, constants) for angle in form.atoms(sympy.atan2))
                            found.append((operations(form), not stretched, _minus_signs(form), form))
    best = min(found, key=lambda option: option[:3], default=None)
    return best[-1] if best and not best[1] else None  # a stretch as the elbow's triangle has it, else one atan2


def _is_stretch(angle, constants) -> bool:
    """Whether atan2(y, x) is the elbow's triangle as a book draws it, atan2(a2 s2, a1 + a2 c2): in the
    robot's lengths and sines and cosines of joints only, a positive length alone in x, none in y."""
    y, x = angle.args
    trig = {f: sympy.S.One for f in angle.atoms(sympy.sin, sympy.cos)}
    return angle.xreplace(trig).free_symbols <= constants and _has_constant(x, constants) and \
        not _has_constant(y, constants, sign=False)


def _has_constant(x, constants, sign: bool = True) -> bool:
    """Whether x has a term in the robot's `constants` alone (a1 in a1 + a2 c2), a positive one
    where `sign`."""
    return any(term.free_symbols and term.free_symbols <= constants and not (sign and term.could_extract_minus_sign())
               for term in sympy.Add.make_args(algebra.expand(x)))


def _minus_signs(form) -> int:
    """How many minus signs a difference of angles prints: its negated terms, and the terms of the
    atan2s' arguments that have a negative coefficient."""
    def negative(expr) -> int:
        return sum(1 for term in sympy.Add.make_args(expr) if term.as_coeff_Mul()[0].is_negative)
    return negative(form) + sum(negative(arg) for angle in form.atoms(sympy.atan2) for arg in angle.args)


def _angles(y, x, tidy) -> tuple:
    """atan2(y, x) written both ways, atan2(y, x) and −atan2(−y, x): the same angle (π and −π are one
    at y = 0, x < 0); the caller keeps the one that prints shortest."""
    y, x = tidy(y), tidy(x)
    return sympy.atan2(y, x), -sympy.atan2(tidy(-y), x)
