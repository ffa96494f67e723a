"""Where a degenerate case is a point of the arm on a joint's axis, as a lecturer says it: the
planar 2R's θ1 is not determined where px = 0 and py = 0, the end point on axis 1; the PUMA's
θ2 + θ3 where px c1 + py s1 = 0 and pz = 0, the wrist centre on axis 2: turning about that axis
does not move the point, so the equations cannot tell its angle.

A case α = 0 and β = 0 says so where α² + β² = k·d² with k a constant, d the distance of the point
from the axis of a joint the case leaves undetermined: the expressions are all 0 exactly where the
point lies on that axis. Tried in numbers at a few poses first, then proven in the ring of the
joints' cos and sin (dhsym.inverse.joint_space). The points tried: the wrist centre, the end point,
then the origins of the frames from the base out. Where the robot file's own numbers keep the point
off the axis in every pose (the UR10's origin of frame 3, 0.612 and 0.5723 from axis 2 along its two
links), no pose meets the case, and it is not printed, as dhsym.inverse.unreachable leaves out the
cases no reachable target meets. Where names stand for the numbers, the case says the relation
between them that it needs (the UR5's a2² = a3²: its two links of one length, folded).

>>> import dhsym
>>> from dhsym.inverse import solve
>>> case = solve(dhsym.load("planar2r").chain).degenerate[0]
>>> case.condition, case.reason
((px, py), OnAxis(joint=1, point='end point', frame=None, only=(a_1**2, a_2**2)))
"""
from __future__ import annotations

import random
from dataclasses import replace

import sympy

from ..core.chain import Chain
from ..velocity.geometry import sample_values, wrist_centre
from ..velocity.jacobian import axis_frame
from .joint_space import TrigRing, in_joints, in_one_ratio
from .sentences import ByEquations, OnAxis, Undetermined
from .written import Written

TRIALS = 3  # poses at which the two sides must be in one ratio before the proof is tried


def say_on_axis(chain: Chain, derivation, definitions, sample) -> None:
    """Give each degenerate case (ByEquations) that is a point on the axis of a joint it leaves
    undetermined that reason instead. `chain` has frames 0..n; `definitions` the shared names before
    the derivation's; `sample` the robot file's numbers for its constants."""
    cases = [(k, case) for k, case in enumerate(derivation.degenerate)
             if isinstance(case, Undetermined) and isinstance(case.reason, ByEquations)]
    if not cases:
        return
    names = in_joints(chain, definitions, derivation)
    rng = random.Random(11)
    poses = [sample_values(chain, rng, sample) for _ in range(TRIALS)]
    ring, points, never = TrigRing(chain.joint_variables), _points(chain, sample), []
    for index, case in cases:
        used = set().union(*(e.free_symbols for e in case.condition))
        if not used <= set(names) | set(poses[0]):  # a sign σ, or a name not in the joints: no point
            continue
        at = [values | {n: float(names[n].xreplace(values)) for n in used & names.keys()} for values in poses]
        sides = [sum(float(e.xreplace(numbers)) ** 2 for e in case.condition) for numbers in at]
        found = _on_axis(chain, case, names, sides, poses, ring, points)
        if found is None:
            continue
        turning = turning_of(found[1], chain.joint_variables)
        if never_zero(turning):
            never.append(index)
        else:
            derivation.degenerate[index] = replace(case, reason=replace(found[0], only=only_where(turning)))
    derivation.keep_degenerate([k for k in range(len(derivation.degenerate)) if k not in never])


def _on_axis(chain: Chain, case, names, sides, poses, ring, points) -> tuple | None:
    """(OnAxis, the distance² in the other joints) of the first joint and point where Σ expression² is the
    point's distance² from the axis times a constant: in numbers at `poses` (where the sides are
    `sides`), then by algebra."""
    side = None
    for joint in [k + 1 for k, v in enumerate(chain.joint_variables) if v in case.unknown.free_symbols]:
        line = axis_frame(chain, joint)
        for point, frame in points:
            if chain.frames.index(frame) <= chain.frames.index(line):
                continue  # a frame before the axis: the joint does not move it
            x, y = chain.transform(line, frame)[:2, 3]
            square = x ** 2 + y ** 2  # in the axis's own frame the axis is z: the distance is x, y
            if not in_one_ratio(sides, square, poses):
                continue
            side = side if side is not None else sympy.Add(*[sympy.expand(e.xreplace(names)) ** 2
                                                             for e in case.condition])
            if ring.multiple(side, square):  # the distance holds the axis's own angle only as a turn about it
                turn = chain.joint_variables[joint - 1]
                return OnAxis(joint, point, frame if point == "frame" else None), square.xreplace({turn: 0})
    return None


def turning_of(square, joints) -> tuple | None:
    """(A, B, C) with `square` = A + B cos θ + C sin θ (sin² read as 1 − cos²), θ the one of
    `joints` it holds in a cos or sin; (square, 0, 0) where it holds none; None for anything else.

    >>> t, a2, a3 = sympy.symbols("theta_3 a_2 a_3", real=True)
    >>> turning_of((a2 + a3 * sympy.cos(t))**2 + (a3 * sympy.sin(t))**2, [t])
    (a_2**2 + a_3**2, 2*a_2*a_3, 0)
    """
    held = square.free_symbols & set(joints)
    if len(held) > 1:
        return None
    value = sympy.expand(sympy.expand_trig(square))
    if not held:
        return value, sympy.Integer(0), sympy.Integer(0)
    (joint,) = held
    c, s = sympy.Dummy("c"), sympy.Dummy("s")
    value = sympy.expand(value.xreplace({sympy.cos(joint): c, sympy.sin(joint): s}).subs(s ** 2, 1 - c ** 2))
    if value.has(joint):
        return None
    poly = sympy.Poly(value, c, s)
    if poly.total_degree() > 1:
        return None
    return tuple(poly.coeff_monomial(m) for m in (1, c, s))


def never_zero(turning) -> bool:
    """Whether a distance² A + B cos θ + C sin θ (`turning`) in the robot file's own numbers
    (Written, exact) is positive in every pose: A > √(B² + C²).

    >>> t = sympy.Symbol("theta_3", real=True)
    >>> a2, a3 = Written.of(sympy.Rational(612, 1000)), Written.of(sympy.Rational(5723, 10000))
    >>> never_zero(turning_of((a2 + a3 * sympy.cos(t))**2 + (a3 * sympy.sin(t))**2, [t]))
    True
    >>> never_zero(turning_of((a2 - a2 * sympy.cos(t))**2, [t]))   # folded back onto the axis at θ = 0
    False
    """
    if turning is None:
        return False
    a, b, k = _in_numbers(turning)
    return bool(all(x.is_Rational for x in (a, b, k)) and a > 0 and a ** 2 > b ** 2 + k ** 2)


def only_where(turning) -> tuple:
    """(lhs, rhs): the constants' relation without which a distance² A + B cos θ + C sin θ
    (`turning`) is never 0, A² = B² + C² written as a book does; () where it is 0 in some pose
    whatever the constants, or this cannot tell.

    >>> t, a2, a3 = sympy.symbols("theta_3 a_2 a_3", real=True)
    >>> only_where(turning_of((a2 + a3 * sympy.cos(t))**2 + (a3 * sympy.sin(t))**2, [t]))
    (a_2**2, a_3**2)
    """
    if turning is None:
        return ()
    a, b, k = _in_numbers(turning)
    gap = sympy.expand(a if b == k == 0 else a ** 2 - b ** 2 - k ** 2)
    if gap.is_number:
        return ()
    coefficient, factors = sympy.factor_list(gap)
    if coefficient > 0 and all(e % 2 == 0 for _, e in factors):  # a square: its root, as a book writes it
        gap = sympy.Mul(*[f ** (e // 2) for f, e in factors])
    terms = sympy.Add.make_args(sympy.expand(gap))
    lhs = sympy.Add(*[t for t in terms if not t.could_extract_minus_sign()])
    rhs = -sympy.Add(*[t for t in terms if t.could_extract_minus_sign()])
    return (lhs, rhs) if lhs != 0 else (rhs, lhs)


def _in_numbers(turning) -> tuple:
    """A, B, C with the robot file's own numbers (Written) as their exact values."""
    return tuple(x.xreplace({s: s.value for s in x.free_symbols if isinstance(s, Written)}) for x in turning)


def _points(chain: Chain, sample) -> list:
    """[(point, frame)]: the wrist centre (where the last three axes meet), the end point, then the
    origins of the other frames from the base out (the UR5's wrist point, frame 3, before frame 4)."""
    centre = wrist_centre(chain, sample=sample)
    last = chain.frames[-1]
    points = [("wrist centre", centre)] if centre is not None else []
    points += [("end point", last)] if last != centre else []
    return points + [("frame", f) for f in chain.frames[1:-1] if f != centre]
