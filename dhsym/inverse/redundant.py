"""Which joints to make parameters of a redundant arm. A course makes an elbow joint a parameter,
but not every joint will do: the iiwa's θ4, the elbow between a spherical shoulder and a spherical
wrist (S-R-S), held fixed leaves the two at a fixed distance, and the other six joints move the end
in five ways only. So a joint is named only after a derivation with it made a parameter has
worked: runs of consecutive unknown joints, from the middle of the arm outward, first checked
cheaply (the axes' structure, the motions left: the iiwa's θ4 goes no further), then derived, at
most HINT_DERIVATIONS of them, each bounded like every derivation (dhsym.inverse.bounds).

>>> import dhsym
>>> iiwa = dhsym.load("iiwa7")
>>> working_free(iiwa.chain, iiwa.sample, iiwa.numbers, (), 1)
((theta_3,), 2)
"""
from __future__ import annotations

from ..core.chain import Chain, plain
from ..errors import UserError
from .bounds import redundancy
from .derive import derive
from .structure import analyse
from .written import with_written_symbols

HINT_DERIVATIONS = 3  # derivations tried for a hint, a second or a few each


def working_free(chain: Chain, sample, numbers, chosen, extra: int) -> tuple[tuple, int]:
    """(the joint variables to make parameters besides `chosen`, else (); how many choices were
    tried): the first run of `extra` consecutive unknown joints, from the middle outward, that
    leaves a closed form (derived with the robot file's `sample` and `numbers`)."""
    chain = plain(chain)
    unknowns = [v for v in chain.joint_variables if v not in set(chosen)]
    middle = (len(unknowns) - extra) // 2
    starts = sorted(range(len(unknowns) - extra + 1), key=lambda start: (abs(start - middle), start))
    derived, tried = 0, 0
    for start in starts:
        run = tuple(unknowns[start:start + extra])
        free = tuple(chosen) + run
        tried += 1
        if not _may_work(chain, sample, free):
            continue
        derived += 1
        if _derives(chain, sample, numbers, free):
            return run, tried
        if derived == HINT_DERIVATIONS:
            break
    return (), tried


def _may_work(chain: Chain, sample, free) -> bool:
    """Whether the arm with `free` made parameters passes the checks made before any algebra."""
    try:
        analyse(chain, free, sample)
    except UserError:
        return False
    return redundancy(chain, free, sample) is None


def _derives(chain: Chain, sample, numbers, free) -> bool:
    """Whether the derivation with `free` made parameters ends in a closed form."""
    solving, solving_sample, _ = with_written_symbols(chain, sample, numbers)
    try:
        derive(solving, free, sample=solving_sample, numbers=numbers)
    except UserError:
        return False
    return True
