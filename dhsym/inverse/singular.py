"""Which degenerate cases of a derivation are singularities that `dhsym jacobian` prints: a
factor of det J, matched up to sign.

Only a factor in the chain's own symbols (joint variables and constants) can be one of det J's;
one that holds the target (px, x_c) never is, and needs no determinant. For a wrist-partitioned
arm det J = det A · det C, and det A holds the first three joints only: a factor in the wrist's
variables alone is one of det C's, the wrist axes' 3×3 determinant, worked out in a few
milliseconds where det A takes most of the time (the same factors `dhsym jacobian` prints).

>>> import dhsym
>>> puma = dhsym.load("puma560")
>>> wrist_factors(puma.chain, puma.numbers)
[sin(theta_5)]
"""
from __future__ import annotations

import itertools
import random
from dataclasses import replace
from types import SimpleNamespace

import sympy

from ..core.chain import Chain
from ..velocity.determinant import TooManyTerms, as_written, determinant, factored, joint_factors, partitioned_factors
from ..velocity.geometry import TOLERANCE, axis_line, dot, poses, sample_values, wrist_centre
from ..velocity.jacobian import angular_part, axis_frame
from ..velocity.singularities import singularities
from .joint_space import TrigRing, in_joints, in_one_ratio
from .on_axis import say_on_axis
from .sentences import Exists, LinedUp, Singular
from .subproblems import angle_symbol, factor_bases
from .unreachable import reachable_cases


def explain_cases(chain: Chain, derivation, definitions, sample, numbers, nonzero, tie: bool) -> None:
    """What the derivation's existence conditions and degenerate cases mean for the arm: the axes a
    sin θk = 0 lines up, the factor of det J each is (where `tie`: a six-joint arm with a wrist),
    only the cases some reachable target meets (dhsym.inverse.unreachable), and the point on an
    axis that each of those is (dhsym.inverse.on_axis). `definitions`:
    the shared ones, before the derivation's assignments; `nonzero`: the constants never 0."""
    say_lined_up(chain, derivation)
    if tie:
        tie_to_jacobian(chain, derivation, definitions, sample, numbers)
    derivation.keep_degenerate(reachable_cases(derivation.degenerate, derivation.conditions, nonzero)[1])
    say_on_axis(chain, derivation, definitions, sample)


def tie_to_jacobian(chain: Chain, derivation, definitions, sample, numbers) -> None:
    """Add to each degenerate case whose expression has a factor of det J, and to each existence
    condition whose boundary (the two roots meet) is where a factor vanishes, that factor and its
    meaning. `chain` has frames 0..n; `sample` and `numbers` are its robot file's (the wrist
    centre is found at its sample values, the factors are written with its numbers)."""
    joints = set(chain.joint_variables)
    found = [(index, factor_bases(expr)) for expr, index in derivation.vanishing]
    possible = [b for _, bases in found for b in bases if b.free_symbols <= chain.symbols and b.free_symbols & joints]
    meeting = [k for k, c in enumerate(derivation.conditions) if isinstance(c, Exists) and c.unknown is not None]
    if not possible and not meeting:
        return
    wrist, centre = set(chain.joint_variables[3:]), wrist_centre(chain, sample=sample)
    if not meeting and all(b.free_symbols & joints <= wrist for b in possible) and centre is not None:
        factors = wrist_factors(chain, numbers, sample)
    else:
        try:  # the factors `dhsym jacobian` prints, without the value it prints besides
            factors = partitioned_factors(chain, centre, numbers) if centre is not None else \
                determinant(chain, numbers=numbers, sample=sample).factors
        except TooManyTerms:  # counted before it is expanded: a general 6R's, which says nothing here
            return
    said = {s.factor: Singular(s.factor, s.template, s.joints)
            for s in singularities(chain, SimpleNamespace(factors=factors), sample=sample)}
    for index, bases in found:
        matched = [g for g in factors for b in bases if sympy.expand(b - g) == 0 or sympy.expand(b + g) == 0]
        if matched:
            derivation.degenerate[index] = replace(derivation.degenerate[index], singular=said[matched[0]])
    names = in_joints(chain, definitions, derivation)
    for k in meeting:
        product = meeting_factors(chain, derivation.conditions[k].expression.xreplace(names), factors, sample)
        if product:
            derivation.conditions[k] = replace(derivation.conditions[k], singular=tuple(said[f] for f in product))


def meeting_factors(chain: Chain, side, factors, sample, trials: int = 3) -> tuple:
    """The factors f1 … fm of det J with `side` (an existence condition's left side, in the joint
    variables) equal to k (f1 ⋯ fm)², k free of the joints: the two roots meet exactly where one of
    them is 0 (the PUMA's a3² + d4² − K² is (d4 c3 + a3 s3)², Stanford's x_c² + y_c² − d2² is
    d3² s2²). Tried in numbers at a few poses first, the fewest factors first, then proven by algebra:
    both sides in cos and sin of each joint, reduced by sin² + cos² = 1 (a normal form: two
    trigonometric polynomials are equal exactly when theirs are). () where no product is."""
    rng = random.Random(5)
    points = [sample_values(chain, rng, sample) for _ in range(trials)]
    ring = TrigRing(chain.joint_variables)
    sides = [float(side.xreplace(values)) for values in points]  # once, for every product
    joined = [f for f in factors if f.free_symbols & set(chain.joint_variables)]
    for size in range(1, len(joined) + 1):
        for product in itertools.combinations(joined, size):
            square = sympy.Mul(*product) ** 2
            if not in_one_ratio(sides, square, points):
                continue
            if ring.multiple(side, square):
                return product
    return ()


def wrist_factors(chain: Chain, numbers, sample=None) -> list:
    """The factors of det C (the three wrist axes, in the axis frame of joint 5), in the form and
    order that `determinant(chain).factors` gives them, written with `numbers`."""
    centre, body = wrist_centre(chain, sample=sample or {}), chain.last_frame
    wrist = [angular_part(chain, j, axis_frame(chain, 5), centre, body) for j in (4, 5, 6)]
    value = as_written(factored(factored(sympy.Matrix(wrist).T.det(method="berkowitz"))), numbers)
    return joint_factors(value, chain)


def say_lined_up(chain: Chain, derivation) -> None:
    """Where sin θk = 0 lines up two axes, say which of the sum or the difference is determined."""
    for _, index in derivation.vanishing:
        said = derivation.degenerate[index]
        if isinstance(said.reason, LinedUp):
            derivation.degenerate[index] = replace(said, reason=lined_up(chain, said.reason.angle))


def lined_up(chain: Chain, angle) -> LinedUp:
    """Where sin θk = 0 lines up the axes of joints k − 1 and k + 1, which angle they still fix:
    the sum of the angles about the lined-up axes where they point the same way, the difference
    where they point opposite ways; θk = 0 and θk = π swap the two. Joints whose axes are parallel
    to one of the two turn with it (the UR5's θ2 + θ3 + θ4). Measured at one pose. With an offset
    (sin(θk + c) = 0) the axes line up where θk + c is 0 or π.

    >>> import dhsym
    >>> found = lined_up(dhsym.load("puma560").chain, dhsym.load("puma560").joint_variables[4])
    >>> found.total(), found.total(at_pi=True)
    (theta_4 + theta_6, theta_4 - theta_6)
    """
    unsaid = LinedUp(angle)
    joint = angle_symbol(angle)
    if joint not in chain.joint_variables:
        return unsaid
    k = list(chain.joint_variables).index(joint) + 1
    if not 1 < k < chain.n:
        return unsaid
    values = sample_values(chain, random.Random(k))
    values[joint] = -float(angle - joint)  # the angle 0
    frame_poses = poses(chain, values)

    def parallel_run(start, step):  # (joint, ±1) for joint `start` and its parallel neighbours away from k
        reference = axis_line(chain, start, frame_poses)[1]
        run, j = [], start
        while 1 <= j <= chain.n and chain.rows[j - 1].joint == "R":
            along = dot(reference, axis_line(chain, j, frame_poses)[1])
            if abs(abs(along) - 1) > TOLERANCE:
                break
            run.append((j, 1 if along > 0 else -1))
            j += step
        return run, reference

    before, towards = parallel_run(k - 1, -1)
    after, away = parallel_run(k + 1, 1)
    alike = dot(towards, away)
    if not before or not after or abs(abs(alike) - 1) > TOLERANCE:
        return unsaid
    variables = chain.joint_variables
    return LinedUp(angle, tuple((variables[j - 1], s) for j, s in sorted(before)),
                   tuple((variables[j - 1], s if alike > 0 else -s) for j, s in sorted(after)))
