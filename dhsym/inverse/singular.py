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

import random

import sympy

from ..core.chain import Chain
from ..core.robot import Robot
from ..velocity.determinant import as_written, determinant, factored, joint_factors
from ..velocity.geometry import TOLERANCE, axis_line, dot, poses, sample_values, wrist_centre
from ..velocity.jacobian import angular_part, axis_frame
from .subproblems import LINED_UP_UNSAID, angle_symbol, factor_bases, lined_up_angle


def tie_to_jacobian(chain: Chain, derivation, sample, numbers) -> None:
    """Add to each degenerate case whose expression has a factor of det J the words that say so.
    `chain` has frames 0..n; `sample` and `numbers` are its robot file's (the wrist centre is
    found at its sample values, the factors are written with its numbers)."""
    joints = set(chain.joint_variables)
    found = []
    for expr, index in derivation.vanishing:
        bases = factor_bases(expr)
        found.append((index, bases))
    possible = [b for _, bases in found for b in bases if b.free_symbols <= chain.symbols and b.free_symbols & joints]
    if not possible:
        return
    wrist = set(chain.joint_variables[3:])
    if chain.n == 6 and all(b.free_symbols & joints <= wrist for b in possible) and \
            wrist_centre(chain, sample=sample) is not None:
        factors = wrist_factors(chain, numbers, sample)
    else:
        factors = determinant(Robot(chain, sample=sample, numbers=numbers)).factors
    for index, bases in found:
        matched = [g for g in factors for b in bases if sympy.expand(b - g) == 0 or sympy.expand(b + g) == 0]
        if matched:
            derivation.degenerate[index] += f"; a singularity of J: the factor {matched[0]} of det J"


def wrist_factors(chain: Chain, numbers, sample=None) -> list:
    """The factors of det C (the three wrist axes, in the axis frame of joint 5), in the form and
    order that `determinant(chain).factors` gives them, written with `numbers`."""
    centre, body = wrist_centre(chain, sample=sample or {}), chain.last_frame
    wrist = [angular_part(chain, j, axis_frame(chain, 5), centre, body) for j in (4, 5, 6)]
    value = as_written(factored(factored(sympy.Matrix(wrist).T.det(method="berkowitz"))), numbers)
    return joint_factors(value, chain)


def say_lined_up(chain, derivation) -> None:
    """Where sin θk = 0 lines up two axes, say which of the sum or the difference is determined."""
    for expr, index in derivation.vanishing:
        angle, sentence = lined_up_angle(expr), derivation.degenerate[index]
        if angle is not None and LINED_UP_UNSAID in sentence:
            derivation.degenerate[index] = sentence.replace(LINED_UP_UNSAID, lined_up(chain, angle))


def lined_up(chain, angle) -> str:
    """Where sin θk = 0 lines up the axes of joints k − 1 and k + 1, which angle they still fix:
    the sum of the angles about the lined-up axes where they point the same way, the difference
    where they point opposite ways; θk = 0 and θk = π swap the two. Joints whose axes are parallel
    to one of the two turn with it (the UR5's θ2 + θ3 + θ4). Measured at one pose. With an offset
    (sin(θk + c) = 0) the axes line up where θk + c is 0 or π.

    >>> import dhsym
    >>> lined_up(dhsym.load("puma560").chain, dhsym.load("puma560").joint_variables[4])
    'at theta_5 = 0 only theta_4 + theta_6 is determined, at theta_5 = pi only theta_4 - theta_6'
    """
    joint = angle_symbol(angle)
    if joint not in chain.joint_variables:
        return LINED_UP_UNSAID
    k = list(chain.joint_variables).index(joint) + 1
    if not 1 < k < chain.n:
        return LINED_UP_UNSAID
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
        return LINED_UP_UNSAID

    def total(run, sign=1):
        return " ".join(f"{'+' if sign * s > 0 else '-'} {chain.joint_variables[j - 1]}" for j, s in sorted(run))

    first = total(before).removeprefix("+ ")
    same, opposite = total(after, 1 if alike > 0 else -1), total(after, -1 if alike > 0 else 1)
    return f"at {angle} = 0 only {first} {same} is determined, at {angle} = pi only {first} {opposite}"
