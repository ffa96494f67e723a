"""Which way of reading an arm's loop the elimination uses, chosen once per arm by trying them.

The loop of six joints can start at any joint and be read either way: twelve eliminations, each
with another joint as the polynomial's unknown. On a general arm all work; on an arm with
parallel or meeting axes (every real one) some give a matrix that is singular for every value of
the unknown, or lose solutions that share the unknown's value (a wrist flipped). Each is tried at
TRIALS poses made from random joint values (a fixed seed: the same choice on every machine):
it passes a pose when the joints that made it are among its solutions. The two that pass the most
(the first of them the one that finds the most solutions) are used together, so that a solution
one of them loses at some pose the other finds.

>>> import dhsym
>>> from dhsym.inverse.numeric.arm import numeric_arm
>>> puma = dhsym.load("puma560")
>>> choice = choose(numeric_arm(puma.chain, sample=puma.sample))
>>> choice.passed, len(choice.variants)
(24, 2)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy

from ...errors import UserError
from .runtime.chain import pose_and_jacobian
from .runtime.solve import SAME, distinct, found_by, reduced

TRIALS = 24  # random poses each reading is tried at
SIZE = 16  # the most solutions a six-joint arm has at a pose (Raghavan and Roth)
MOST = 4  # readings used at most: a second always (a solution one loses at some pose, another finds), more while
#           they add trial poses where the joints are found (arms whose axes meet and are parallel everywhere)
SEED = 20270611
JACOBIAN_RANK = 1e-9  # a singular value of the Jacobian below this (relative) at every trial: the arm has fewer than 6


@dataclass(frozen=True)
class Choice:
    """`variants`: the readings used ((joint order, backwards), ...); `passed`: at how many of the
    TRIALS poses the first (and the pair together) found the joints that made the pose."""

    variants: tuple
    passed: int
    trials: int = TRIALS


def readings(kinds: str):
    """Every way of reading the loop of six joints whose last joint turns (its axis holds a point)."""
    for backwards in (False, True):
        for start in range(6):
            order = tuple((start - k) % 6 if backwards else (start + k) % 6 for k in range(6))
            if kinds[order[5]] == "R":
                yield order, backwards


def trial_poses(arm, free=(), trials: int = TRIALS, seed: int = SEED):
    """(joint values (trials, n), free values (trials, number free), poses (trials, 4, 4)) at random joints."""
    rng = numpy.random.default_rng(seed)
    values = numpy.empty((trials, len(arm.kinds)))
    for k, kind in enumerate(arm.kinds):
        values[:, k] = rng.uniform(-numpy.pi, numpy.pi, trials) if kind == "R" else rng.uniform(-0.5, 0.5, trials) \
            * arm.scale / abs(arm.slopes[k])
    return values, values[:, list(free)], arm.pose(values)


def choose(arm, free=()) -> Choice:
    """The readings to use for `arm` with the joints at positions `free` given: first the one that
    finds the joints at the most trial poses, and among those the one whose roots are solutions
    (not repeated or false) at the most poses; second the one that adds the most poses to it."""
    values, free_values, targets = trial_poses(arm, free)
    runtime = runtime_arm(arm, free, (), SIZE)
    frames, kinds = reduced(runtime, free_values * numpy.asarray(arm.slopes)[list(free)])
    check_rank(arm, free)
    truth = values[:, [k for k in range(len(arm.kinds)) if k not in free]]
    scores = []
    for variant in readings(kinds):
        rows, solved, tried = found_by(runtime, frames, targets, kinds, variant)
        hit = numpy.zeros(len(values), dtype=bool)
        hit[rows[_apart(solved, truth[rows], kinds, arm.scale) < SAME]] = True
        grid = distinct(rows, solved, kinds, len(values), SIZE, arm.scale)
        clean = numpy.isfinite(grid[:, :, 0]).sum(axis=1) == numpy.bincount(tried, minlength=len(values))
        scores.append((hit, clean.sum(), len(rows), variant))
    if not scores:
        raise UserError("the numeric inverse kinematics needs a turning joint among the six to close the loop")
    scores.sort(key=lambda score: (-score[0].sum(), -score[1], -score[2]))
    chosen, covered, left = [scores[0]], scores[0][0], scores[1:]
    while len(chosen) < MOST and left:
        best = max(left, key=lambda s: ((s[0] | covered).sum(), s[0].sum(), s[1]))
        if len(chosen) > 1 and not (best[0] & ~covered).any():
            break
        chosen.append(best)
        left = [s for s in left if s is not best]
        covered = covered | best[0]
    return Choice(tuple(score[3] for score in chosen), int(covered.sum()))


def runtime_arm(arm, free, variants, size) -> dict:
    """The dict dhsym.inverse.numeric.runtime works with (and the generated module holds)."""
    return {"frames": arm.frames, "kinds": arm.kinds, "slopes": arm.slopes, "free": tuple(free),
            "variants": tuple(variants), "scale": arm.scale, "size": size, "tolerance": tolerance(arm)}


def tolerance(arm) -> float:
    """How near a solution's pose is to the target: within 1e-9 (of an arm ten units or more in size,
    1e-10 of its size: an arm in millimetres)."""
    return 1e-9 * max(1.0, arm.scale / 10)


def _apart(a, b, kinds, scale):
    difference = a - b
    for k, kind in enumerate(kinds):
        difference[:, k] = numpy.remainder(difference[:, k] + numpy.pi, 2 * numpy.pi) - numpy.pi if kind == "R" \
            else difference[:, k] / scale
    return numpy.abs(difference).max(axis=1)


def check_rank(arm, free=()) -> None:
    """Refuses an arm whose six joints move the tool in fewer than six directions at every trial pose
    (its solutions are not isolated points: no list of them exists)."""
    values, free_values, _ = trial_poses(arm, free)
    frames, kinds = reduced(runtime_arm(arm, free, (), SIZE), free_values * numpy.asarray(arm.slopes)[list(free)])
    unknown = [k for k in range(len(arm.kinds)) if k not in free]
    _, jacobian = pose_and_jacobian(frames, kinds, values[:, unknown] * numpy.asarray(arm.slopes)[unknown])
    sizes = numpy.linalg.svd(jacobian, compute_uv=False)
    if numpy.all(sizes[:, -1] < JACOBIAN_RANK * sizes[:, 0]):
        rank = int(numpy.median((sizes > JACOBIAN_RANK * sizes[:, :1]).sum(axis=1)))
        raise UserError(f"{arm.name or 'the arm'}: its six joints move the tool in only {rank} independent "
                        "directions at any pose, so a reachable pose has infinitely many solutions and no list of "
                        "them exists")
