"""Which joints to make parameters of a redundant arm. A course makes an elbow joint a parameter,
but not every joint will do: the iiwa's θ4, the elbow between a spherical shoulder and a spherical
wrist (S-R-S), held fixed leaves the two at a fixed distance, and the other six joints move the end
in five ways only. So a joint is named only after a derivation with it made a parameter has
worked: runs of consecutive unknown joints, from the middle of the arm outward, first checked
cheaply (the axes' structure, the motions left: the iiwa's θ4 goes no further), then derived, at
most HINT_DERIVATIONS of them, each bounded like every derivation (dhsym.inverse.bounds).

>>> import dhsym
>>> working_free(dhsym.load("iiwa7"), (), 1)
((theta_3,), 2)
"""
from __future__ import annotations

from ..errors import UserError
from .bounds import redundancy
from .solve import solve
from .structure import analyse
from .written import with_written_symbols

HINT_DERIVATIONS = 3  # derivations tried for a hint, a second or a few each


def working_free(robot, chosen, extra: int) -> tuple[tuple, int]:
    """(the joint variables to make parameters besides `chosen`, else (); how many choices were
    tried): the first run of `extra` consecutive unknown joints, from the middle outward, that
    leaves a closed form."""
    chain = robot.chain
    unknowns = [v for v in chain.joint_variables if v not in set(chosen)]
    middle = (len(unknowns) - extra) // 2
    starts = sorted(range(len(unknowns) - extra + 1), key=lambda start: (abs(start - middle), start))
    derived, tried = 0, 0
    for start in starts:
        run = tuple(unknowns[start:start + extra])
        free = tuple(chosen) + run
        tried += 1
        if not _may_work(robot, free):
            continue
        derived += 1
        if _derives(robot, free):
            return run, tried
        if derived == HINT_DERIVATIONS:
            break
    return (), tried


def _may_work(robot, free) -> bool:
    """Whether the arm with `free` made parameters passes the checks made before any algebra."""
    try:
        analyse(robot, free)
    except UserError:
        return False
    return redundancy(robot, free) is None


def _derives(robot, free) -> bool:
    """Whether the derivation with `free` made parameters ends in a closed form."""
    solving, _ = with_written_symbols(robot, robot.numbers)
    try:
        solve(solving, free=free)
    except UserError:
        return False
    return True
