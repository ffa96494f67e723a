"""Numbers for the geometric questions the symbolic results raise: where the joint axes are in a
given configuration, whether three axes meet (a wrist centre), where a factor vanishes.

Plain floats, no numpy: the velocity layer sits below the plotting layer.

>>> import dhsym
>>> wrist_centre(dhsym.load("puma560")), wrist_centre(dhsym.load("stanford")), wrist_centre(dhsym.load("ur5"))
(6, 5, None)
"""
from __future__ import annotations

import math
import random

from .jacobian import cross  # one cross product, for symbols and for numbers

TOLERANCE = 1e-9


def sample_values(chain, rng: random.Random, sample=None) -> dict:
    """Joint variables uniform in (−π, π); constants from `sample` (default: the robot's, when
    `chain` is a Robot), else in (0.5, 1.5)."""
    sample = getattr(chain, "sample", {}) if sample is None else sample
    values = {}
    for symbol in sorted(chain.symbols, key=str):
        if symbol in chain.joint_variables:
            values[symbol] = rng.uniform(-math.pi, math.pi)
        elif symbol in sample:
            values[symbol] = float(sample[symbol])
        else:
            values[symbol] = rng.uniform(0.5, 1.5)
    return values


def poses(chain, values: dict) -> dict:
    """Frame -> (rotation rows, origin) in the first frame, for numbers `values` of every symbol."""
    rotation, origin = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 0.0]
    frames = chain.frames
    out = {frames[0]: (rotation, origin)}
    for before, frame in zip(frames, frames[1:]):
        for step in chain.steps(before, frame):
            amount = float(step.value.xreplace(values))
            if step.is_rotation:
                rotation = _times(rotation, _elementary(step.axis, amount))
            else:
                origin = [origin[r] + rotation[r][step.axis] * amount for r in range(3)]
        out[frame] = (rotation, origin)
    return out


def _elementary(axis: int, angle: float) -> list:
    c, s = math.cos(angle), math.sin(angle)
    i, j = [k for k in range(3) if k != axis]
    if axis == 1:
        i, j = j, i
    m = [[1.0 if r == k else 0.0 for k in range(3)] for r in range(3)]
    m[i][i], m[i][j], m[j][i], m[j][j] = c, -s, s, c
    return m


def _times(a, b) -> list:
    return [[sum(a[r][k] * b[k][c] for k in range(3)) for c in range(3)] for r in range(3)]


def axis_line(chain, joint: int, frame_poses: dict) -> tuple:
    """(a point on the axis of `joint`, its unit direction), from `poses`."""
    frame = joint - 1 if chain.convention == "standard" else joint
    rotation, origin = frame_poses[frame]
    return origin, [rotation[r][2] for r in range(3)]


def dot(u, v) -> float:
    return sum(a * b for a, b in zip(u, v))


def minus(u, v) -> list:
    return [a - b for a, b in zip(u, v)]


def distance_to_axis(point, line) -> float:
    """How far `point` is from the line (point, unit direction)."""
    return math.sqrt(sum(x * x for x in cross(line[1], minus(point, line[0]))))


def wrist_centre(chain, trials: int = 3, sample=None):
    """The last frame whose origin lies on the axes of the last three joints (all revolute) in
    every configuration tried, or None: the point where a spherical wrist's axes meet."""
    sample = getattr(chain, "sample", {}) if sample is None else sample
    chain = getattr(chain, "chain", chain)  # a Robot's own chain: frames 0..n
    n = chain.n
    if n < 6 or any(row.joint != "R" for row in chain.rows[-3:]):
        return None
    rng = random.Random(7)
    configurations = [poses(chain, sample_values(chain, rng, sample)) for _ in range(trials)]
    first = chain.frames.index(n - 3 if chain.convention == "standard" else n - 2)
    for frame in reversed(chain.frames[first:]):
        if all(distance_to_axis(pose[frame][1], axis_line(chain, j, pose)) < TOLERANCE
               for pose in configurations for j in (n - 2, n - 1, n)):
            return frame
    return None
