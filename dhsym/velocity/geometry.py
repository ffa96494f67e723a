"""Numbers for the geometric questions the symbolic results raise: where the joint axes are in a
given configuration, whether three axes meet (a wrist centre), where a factor vanishes.

The poses come from core.numeric, the one numeric evaluator (plain floats, no numpy: the velocity
layer sits below the plotting layer); the vectors from core.vectors.

>>> import dhsym
>>> [wrist_centre(dhsym.load(name).chain) for name in ("puma560", "stanford", "ur5")]
[6, 5, None]
"""
from __future__ import annotations

import math
import random
from typing import Mapping

from ..core.chain import Chain, plain
from ..core.numeric import NumericChain
from ..core.sampling import random_pose
from ..core.vectors import cross, dot
from .jacobian import axis_frame

# cross and dot live in core.vectors; they are named here too for the modules that take them from here
__all__ = ["TOLERANCE", "axis_line", "cross", "distance_to_axis", "dot", "minus", "nearest_point", "norm", "poses",
           "sample_values", "wrist_centre"]

TOLERANCE = 1e-9


def sample_values(chain: Chain, rng: random.Random, sample: Mapping | None = None) -> dict:
    """A random pose by the package's one rule (dhsym.core.sampling): joint variables uniform in
    (−π, π), constants from `sample` (a robot file's), else in (0.5, 1.5)."""
    return random_pose(chain, rng, sample)


_EVALUATORS: dict = {}  # (chain, its constants' values) -> NumericChain: many poses of one arm set it up once
EVALUATORS_KEPT = 32


def poses(chain: Chain, values: dict) -> dict:
    """Frame -> (rotation rows, origin) in the first frame, for numbers `values` of every symbol."""
    variables = set(chain.joint_variables)
    key = (id(chain), tuple(sorted((s.name, values[s]) for s in values if s not in variables)))
    held = _EVALUATORS.get(key)
    if held is None or held[0] is not chain:  # an id can be reused once its chain is gone
        if len(_EVALUATORS) >= EVALUATORS_KEPT:
            _EVALUATORS.clear()
        held = _EVALUATORS[key] = (chain, NumericChain(chain, values))
    numeric = held[1]
    return {frame: ([row[:3] for row in pose[:3]], [row[3] for row in pose[:3]])
            for frame, pose in numeric.poses([values[v] for v in chain.joint_variables])}


def axis_line(chain: Chain, joint: int, frame_poses: dict) -> tuple:
    """(a point on the axis of `joint`, its unit direction), from `poses`."""
    rotation, origin = frame_poses[axis_frame(chain, joint)]
    return origin, [rotation[r][2] for r in range(3)]


def minus(u, v) -> list:
    return [a - b for a, b in zip(u, v)]


def norm(vector) -> float:
    return math.sqrt(dot(vector, vector))


def distance_to_axis(point, line) -> float:
    """How far `point` is from the line (point, unit direction)."""
    return norm(cross(line[1], minus(point, line[0])))


def nearest_point(line, other) -> list:
    """The point of `line` nearest the line `other`, both (point, unit direction), not parallel.

    >>> nearest_point(([0, 0, 0], [1, 0, 0]), ([2, 1, 5], [0, 0, 1]))
    [2.0, 0.0, 0.0]
    """
    (p, d), (q, e) = line, other
    w = minus(q, p)
    cosine = dot(d, e)
    t = (dot(w, d) - dot(w, e) * cosine) / (1 - cosine * cosine)
    return [a + t * b for a, b in zip(p, d)]


def wrist_centre(chain: Chain, trials: int = 3, sample: Mapping | None = None):
    """The last frame whose origin lies on the axes of the last three joints (all revolute) in
    every configuration tried, or None: the point where a spherical wrist's axes meet. `sample`:
    numbers for the constants (a robot file's), else random ones."""
    n = plain(chain).n
    if n < 6 or any(row.joint != "R" for row in chain.rows[-3:]):
        return None
    rng = random.Random(7)
    configurations = [poses(chain, sample_values(chain, rng, sample)) for _ in range(trials)]
    first = chain.frames.index(axis_frame(chain, n - 2))
    for frame in reversed(chain.frames[first:]):
        if all(distance_to_axis(pose[frame][1], axis_line(chain, j, pose)) < TOLERANCE
               for pose in configurations for j in (n - 2, n - 1, n)):
            return frame
    return None
