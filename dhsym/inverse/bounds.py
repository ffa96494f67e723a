"""What a derivation will cost, and whether it can end in finitely many branches, measured before
any algebra, so that an arm the search cannot handle is refused at once on any machine:

- the table's entries multiplied out: the equations square the lengths (a squared distance) and
  Pieper's quartic takes their fourth powers; a length (l1 + l2 + l3 + l4)^16, 969 terms, made
  the PUMA's derivation run for minutes. The terms of every entry beyond its first are counted;
- the size of the equations: one matrix equation for each pair of frames, each as large as the
  chain between them (dhsym.core.estimate); a joint made --free still enters every one of them.
  The built-ins' are at most 6,733 nodes (the iiwa's), a planar 24R arm's 69,000;
- the motions the unknown joints make: at a generic pose their axes must move the end in as many
  independent ways as there are unknowns (the rank of their Jacobian columns), else a family of
  solutions replaces the branches: a spatial arm has six, a planar one three.

>>> import dhsym
>>> motion_rank(dhsym.load("iiwa7").chain, range(1, 8)), motion_rank(dhsym.load("planar3r").chain, (1, 2, 3))
(6, 3)
>>> refuse_unbounded(dhsym.load("puma560").chain, "puma560.yaml")  # a textbook arm: nothing to say
"""
from __future__ import annotations

import random
from dataclasses import dataclass

from ..core.chain import Chain, plain
from ..core.estimate import estimated_size
from ..core.sampling import random_pose
from ..core.size import expanded_terms, rough_count
from ..errors import UserError
from ..velocity.geometry import axis_line, cross, minus, norm, poses

ENTRY_EXTRA_TERMS = 40  # (l1 + l2 + l3 + l4)^4, 35 terms, takes the PUMA's derivation from 1 s to 3 s; ^6 (84) to 20 s
POOL_MAX_NODES = 60_000  # general 6R arms with a wrist reach 36,000 (3–4 s); a planar 24R, 18 --free: 69,456 (84 s)
POSE_DOF = 6  # a pose fixes six numbers
RANK_TRIALS = 3  # generic poses: the rank is the largest found (one pose may be singular)
RANK_TOLERANCE = 1e-8  # of unit columns: far above rounding, far below any real motion


def refuse_unbounded(chain: Chain, path: str = "<robot>") -> None:
    """A UserError when the table's entries or the equations would be too large to work with;
    `path` says where the chain comes from (its robot file), for the message."""
    chain = plain(chain)
    entries = [(f"joint row {k} {key}", getattr(row, key)) for k, row in enumerate(chain.rows, 1)
               for key in ("theta", "d", "a", "alpha")]
    entries += [(f"{side} step {k}", step.value) for side, steps in (("base", chain.base), ("tool", chain.tool))
                for k, step in enumerate(steps, 1)]
    extra = {name: expanded_terms(value, trig=True) - 1 for name, value in entries if value != 0}
    total = sum(extra.values())
    if total > ENTRY_EXTRA_TERMS:
        largest = max(extra, key=extra.get)
        raise UserError(f"{path}: {largest} multiplies out to {_count(extra[largest] + 1)} terms, and the "
                        "inverse kinematics' equations square it: dhsym solves tables whose entries multiply out to "
                        f"at most {ENTRY_EXTRA_TERMS} terms beyond the first of each (this one: {_count(total)}); name "
                        "such a sum as a constant (a symbol such as l_1) and give its value in the robot file's sample")
    if pool_size(chain, POOL_MAX_NODES) > POOL_MAX_NODES:
        raise UserError(f"{path}: the inverse kinematics' equations (one for each pair of frames) would hold "
                        f"more than the {POOL_MAX_NODES:,} expression nodes that dhsym searches; a joint made --free "
                        "still enters every equation: write the joints you do not solve for as numbers in a copy of "
                        "the table")


def _count(number: int) -> str:
    return f"{number:,}" if number < 100_000 else rough_count(number)


def pool_size(chain, stop: int | None = None) -> int:
    """Estimated nodes of the chain sides of the equations, one for each pair of frames; counted
    no further than past `stop`."""
    frames, total, memo = chain.frames, 0, {}
    for i, start in enumerate(frames):
        for end in frames[i + 1:]:
            total += estimated_size(chain, start, end, memo=memo)
            if stop is not None and total > stop:
                return total
    return total


def motion_rank(chain: Chain, joints, sample=None) -> int:
    """In how many independent ways the joints `joints` (numbers 1..n) move the end of the arm:
    the rank of their Jacobian columns at a few generic poses (the largest found; the constants of
    `sample`, the robot file's, where it gives them)."""
    chain = plain(chain)
    rng, best = random.Random(24), 0
    for _ in range(RANK_TRIALS):
        frame_poses = poses(chain, random_pose(chain, rng, sample))
        end = frame_poses[chain.last_frame][1]
        columns = []
        for joint in joints:
            point, direction = axis_line(chain, joint, frame_poses)
            column = [*direction, 0.0, 0.0, 0.0] if chain.rows[joint - 1].joint == "P" else \
                [*cross(direction, minus(end, point)), *direction]
            columns.append([x / (norm(column) or 1.0) for x in column])
        best = max(best, _rank(columns))
    return best


def _rank(columns) -> int:
    """The rank of a few vectors, by elimination with the largest pivot first."""
    rows = [list(column) for column in columns]
    rank = 0
    for position in range(len(rows[0]) if rows else 0):
        pivot = max(range(rank, len(rows)), key=lambda r: abs(rows[r][position]), default=None)
        if pivot is None or abs(rows[pivot][position]) < RANK_TOLERANCE:
            continue
        rows[rank], rows[pivot] = rows[pivot], rows[rank]
        for r in range(rank + 1, len(rows)):
            factor = rows[r][position] / rows[rank][position]
            rows[r] = [a - factor * b for a, b in zip(rows[r], rows[rank])]
        rank += 1
    return rank


@dataclass(frozen=True)
class Redundancy:
    """An arm with more unknown joints than the ways they move its end: `unknowns` joints, `rank`
    ways, where all of its `n` joints have `arm_rank` ways."""

    unknowns: int
    rank: int
    n: int
    arm_rank: int

    @property
    def extra(self) -> int:
        """How many more joints must be made parameters."""
        return self.unknowns - self.rank

    @property
    def lost(self) -> bool:
        """Whether the joints made parameters took motions the arm has (the iiwa's θ4: its shoulder and
        wrist are then at a fixed distance): other joints must be the parameters."""
        return self.rank < self.arm_rank

    @property
    def needed(self) -> int:
        """How many parameters the arm needs in all."""
        return self.n - self.arm_rank


def redundancy(chain: Chain, free, sample=None) -> Redundancy | None:
    """How the unknown joints (all but `free`) outnumber the ways they move the end, or None."""
    chain = plain(chain)
    unknowns = [j for j, v in enumerate(chain.joint_variables, 1) if v not in set(free)]
    rank = motion_rank(chain, unknowns, sample)
    if len(unknowns) <= rank:
        return None
    arm_rank = motion_rank(chain, range(1, chain.n + 1), sample) if free else rank
    return Redundancy(len(unknowns), rank, chain.n, arm_rank)


def redundant_message(name: str, free, redundant: Redundancy, example=(), tried: int = 0) -> str:
    """Why a closed form needs other or more joints made parameters, and which (`example`, checked by
    a derivation), or that none of the `tried` choices gave one; `name`: the robot's, for the message."""
    name = name or "the robot"
    ways = lambda count: f"{count} independent way{'s' if count != 1 else ''}"  # noqa: E731
    if redundant.lost:
        chosen = ", ".join(str(v) for v in free) + (" a parameter" if len(free) == 1 else " parameters")
        text = (f"{name} has {redundant.n} joints; with {chosen} the {redundant.unknowns} unknown joints move its "
                f"end in only {ways(redundant.rank)}, where all of its joints move it in {redundant.arm_rank}")
        if not redundant.needed:
            return text + ": it needs no parameter; leave out --free"
        count = redundant.needed
        text += f": make {'another joint' if count == 1 else f'{count} other joints'} the parameter{'s' * (count > 1)}"
    else:
        why = f"a pose fixes only {POSE_DOF}" if redundant.rank == POSE_DOF else f"they move its end in only " \
            f"{ways(redundant.rank)}"
        count = redundant.extra
        text = (f"{name} has {redundant.n} joints, {redundant.unknowns} of them unknown, but {why}: make {count} "
                f"{'more ' if free else ''}of them {'a parameter' if count == 1 else 'parameters'}")
    if example:
        return text + f" with --free, e.g. --free {' '.join(str(v) for v in example)}"
    if tried:
        return text + f" with --free; none of the {tried} choices dhsym tried leaves a closed form by the course's " \
            "rules"
    return text + " with --free"
