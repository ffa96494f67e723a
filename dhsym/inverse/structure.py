"""The structure of an arm, read from its joint axes before any algebra: which joints are
unknown, whether three consecutive axes meet in a point (a spherical wrist) or are parallel,
and whether a closed form by the course's rules can exist at all.

Pieper's condition decides a six-joint arm: three consecutive axes that meet in a point, or
that are parallel. An arm that has neither is refused here, at once.

>>> import dhsym
>>> analyse(dhsym.load("puma560").chain).wrist
(4, 5, 6)
>>> analyse(dhsym.load("ur5").chain).parallel
(2, 3, 4)
>>> try:
...     analyse(dhsym.load("iiwa7").chain)
... except dhsym.UserError as error:
...     print(error)
the arm has 7 joints and a closed form needs at most 6: it is redundant; make 1 of its joint variables a \
parameter with --free
"""
from __future__ import annotations

import random
from dataclasses import dataclass

from ..core.chain import Chain, plain
from ..core.sampling import random_pose
from ..errors import NoClosedForm, UserError
from ..velocity.geometry import axis_line, cross, distance_to_axis, nearest_point, norm, poses

TOLERANCE = 1e-7
TRIALS = 3


@dataclass(frozen=True)
class Structure:
    """`unknowns`: the joints to solve for (1-based); `wrist`: three consecutive unknown revolute
    joints whose axes meet in one point, at the end of the arm (else None); `parallel`: three
    consecutive unknown revolute joints with parallel axes; `spherical`: every unknown axis
    passes through one point (a wrist on its own: only the orientation decides it)."""

    unknowns: tuple[int, ...]
    wrist: tuple[int, int, int] | None
    parallel: tuple[int, int, int] | None
    spherical: bool
    first_wrist: tuple[int, int, int] | None = None  # the first three axes meet: a wrist at the start


def analyse(chain: Chain, free=(), sample=None) -> Structure:
    """The structure of `chain` (frames 0..n) with the joint variables in `free` made parameters;
    `sample`: numbers for its constants (its robot file's), the rest drawn."""
    chain = plain(chain)
    unknowns = tuple(j for j, v in enumerate(chain.joint_variables, start=1) if v not in set(free))
    if len(unknowns) > 6:  # which joints will do is checked by dhsym.inverse.redundant, which derives with them
        extra = len(unknowns) - 6
        raise UserError(f"the arm has {len(unknowns)} joints and a closed form needs at most 6: it is redundant; "
                        f"make {extra} of its joint variables {'a parameter' if extra == 1 else 'parameters'} "
                        "with --free")
    if not unknowns:
        raise UserError("every joint variable is --free: nothing is left to solve for")
    rng = random.Random(11)
    lines = [{j: axis_line(chain, j, pose) for j in unknowns}
             for pose in (poses(chain, random_pose(chain, rng, sample)) for _ in range(TRIALS))]
    revolute = {j for j in unknowns if chain.rows[j - 1].joint == "R"}
    triples = [unknowns[k:k + 3] for k in range(len(unknowns) - 2)]
    meeting = [t for t in triples if set(t) <= revolute and all(_meet(config, t) for config in lines)]
    parallel = [t for t in triples if set(t) <= revolute and all(_parallel(config, t) for config in lines)]
    wrist = tuple(unknowns[-3:]) if tuple(unknowns[-3:]) in meeting else None
    spherical = len(unknowns) <= 3 and set(unknowns) <= revolute and (
        len(unknowns) < 3 and len(unknowns) > 1 and all(_meet(config, unknowns) for config in lines)
        or tuple(unknowns) in meeting)
    first_wrist = tuple(unknowns[:3]) if len(unknowns) == 6 and tuple(unknowns[:3]) in meeting else None
    if len(unknowns) == 6 and wrist is None and first_wrist is None and not parallel:
        raise NoClosedForm("no closed form by the course's rules: no three consecutive axes meet in a point at the "
                        "start or the end of the arm, or are parallel (Pieper's condition)")
    return Structure(unknowns, wrist, parallel[0] if parallel else None, spherical, first_wrist)


def _meet(config: dict, joints) -> bool:
    """Whether the axes of `joints` pass through one point (the first two not parallel)."""
    first, second = config[joints[0]], config[joints[1]]
    if norm(cross(first[1], second[1])) < TOLERANCE:
        return False
    point = nearest_point(first, second)
    return all(distance_to_axis(point, config[j]) < TOLERANCE for j in joints)


def _parallel(config: dict, joints) -> bool:
    first = config[joints[0]][1]
    return all(norm(cross(first, config[j][1])) < TOLERANCE for j in joints[1:])
