"""What each singular factor means for the arm, in words a lecture would use.

Each factor of the determinant is tried at configurations where it vanishes (found by
numbers: the other joints at random values, one of the factor's joints scanned for a change of
sign), against the geometric situations a course names, in this order:

* a prismatic joint at zero extension (d3 = 0);
* two joint axes that line up (the wrist: axes 4 and 6 when s5 = 0), or are parallel;
* the arm stretched or folded at joint j: the point lies in the plane of the parallel axes
  j − 1 and j (the elbow);
* the point in the plane through axis a parallel to axis b: over axis a (the shoulder; on the
  axis itself when the arm has no sideways offset); when the point is never there, the origin
  of another frame (the UR5's is where axes 5 and 6 meet, the origin of frame 5).

A description counts only if it holds wherever the factor vanishes and not at a random pose:
the flange of the UR5 is always in the plane through axis 5 parallel to axis 6, which says
nothing.

A factor that none of them describes is said to be so.

>>> import dhsym
>>> from dhsym.velocity.determinant import determinant
>>> puma = dhsym.load("puma560").chain
>>> for singularity in singularities(puma, determinant(puma)):
...     print(singularity.meaning)
wrist: axes 4 and 6 line up
elbow stretched or folded: the wrist centre lies in the plane of axes 2 and 3
shoulder: the wrist centre lies in the plane through axis 1 parallel to axis 2 (on axis 1 when there is no offset)
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Mapping

import sympy

from ..core.chain import Chain, Frame, plain
from ..core.numbering import PLAIN, Numbering
from ..core.vectors import cross, dot
from .geometry import TOLERANCE, axis_line, distance_to_axis, minus, poses, sample_values, wrist_centre

SCAN_STEPS = 720


@dataclass(frozen=True)
class Singularity:
    """A factor whose vanishing makes J singular, and what that means: `template` in plain
    words with {0}, {1} … for the joints in `joints` (row numbers 1..n)."""

    factor: sympy.Expr
    template: str
    joints: tuple = ()
    first_joint: int = 1  # the number printed for row 1 (a wrist numbered 3..6: 4)

    @property
    def meaning(self) -> str:
        return self.describe(lambda row: str(row + self.first_joint - 1))

    def describe(self, label=str) -> str:
        """The meaning with each joint written by `label(row number)` (a wrist's rows 1..3
        print as 4..6 when its variables are θ4..θ6)."""
        return self.template.format(*(label(j) for j in self.joints))


def singularities(chain: Chain, determinant, point: Frame | None = None, *, sample: Mapping | None = None,
                  numbering: Numbering = PLAIN) -> list[Singularity]:
    """One Singularity per factor of `determinant` (a velocity.determinant.Determinant); `point`: the
    chain's frame (default: the last). `sample`: the robot file's values of its constants (for the
    numbers), `numbering`: how the meanings number frames and joints."""
    point = plain(chain).frames[-1] if point is None else chain.frame(point)
    sample = sample or {}
    centre = wrist_centre(chain, sample=sample) if chain.n >= 6 else None
    point = centre if centre is not None else point
    name = "wrist centre" if centre is not None else \
        POINT_NAMES.get(point, f"origin of frame {numbering.frame(point)}")
    return [Singularity(f, *meaning(chain, f, point, name, sample, numbering), numbering.first_joint)
            for f in determinant.factors]


POINT_NAMES = {"tool": "tool point", "base": "origin of the base frame"}


def meaning(chain: Chain, factor, point: Frame, name: str, sample: Mapping | None = None,
            numbering: Numbering = PLAIN) -> tuple[str, tuple]:
    """The first geometric description that holds wherever `factor` vanishes: (template, joints).
    `sample` gives the constants' values, `numbering` the frames' printed numbers."""
    sample = sample or {}
    variables = [v for v in chain.joint_variables if v in factor.free_symbols]
    joint = chain.joint_variables.index(variables[-1]) + 1
    if factor == variables[-1] and chain.rows[joint - 1].joint == "P":
        return "joint {0} retracted to zero extension", (joint,)
    roots = _roots(chain, factor, variables, sample=sample)
    if not roots:
        return "no real configuration found where this factor vanishes (for random dimensions)", ()
    n = chain.n
    revolute = [j for j in range(1, n + 1) if chain.rows[j - 1].joint == "R"]
    generic = poses(chain, sample_values(chain, random.Random(11), sample))
    def holds(test, *args) -> bool:  # test(*args, pose) where the factor vanishes, and not everywhere
        return all(test(*args, pose) for pose in roots) and not test(*args, generic)

    if len(variables) == 1:
        pairs = sorted(((a, b) for a in revolute for b in revolute if a < b), key=lambda p: abs(sum(p) - 2 * joint))
        for a, b in pairs:  # the pair around the joint first: axes 4 and 6 for θ5
            if holds(_parallel, chain, a, b):
                wrist = "wrist: " if a > n - 3 and n >= 6 else ""
                if all(_collinear(chain, a, b, pose) for pose in roots):
                    return wrist + "axes {0} and {1} line up", (a, b)
                return wrist + "axes {0} and {1} are parallel", (a, b)  # the Stanford arm's 1 and 4, d2 apart
        for j in (joint, joint + 1):
            if not (1 < j <= n and _parallel(chain, j - 1, j, generic)):
                continue
            stretched = f"{'elbow' if n >= 6 else 'arm'} stretched or folded: "
            if holds(_origin_in_plane, chain, j - 1, j, point):
                return stretched + f"the {name} lies in the plane of axes {{0}} and {{1}}", (j - 1, j)
            for k in range(j + 1, n + 1):  # a planar 3R: axis 3 (the wrist), not the tool point
                if holds(_axis_in_plane, chain, j - 1, j, k):
                    return stretched + "axis {2} lies in the plane of axes {0} and {1}", (j - 1, j, k)
    # the point first, then the other origins from the tip down: the UR5's shoulder singularity is
    # where axes 5 and 6 meet (the origin of frame 5), not its flange, crossing a plane
    origins = [(point, name)] + [(f, f"origin of frame {numbering.frame(f)}") for f in reversed(chain.frames)
                                 if f != point]
    for where, called in origins:
        for a in revolute:
            for b in range(a + 1, n + 1):
                if not _parallel(chain, a, b, generic) and holds(_over, chain, a, b, where):
                    return (f"{'shoulder: ' if a == 1 else ''}the {called} lies in the plane through axis {{0}} "
                            "parallel to axis {1} (on axis {0} when there is no offset)"), (a, b)
    return "the joint velocities are dependent here (no simpler description found)", ()


def _roots(chain: Chain, factor, variables, configurations: int = 3, sample=None) -> list:
    """Poses of the chain at up to `configurations` zeros of `factor`: the other joints at random
    values, one of its `variables` scanned for a change of sign, the last first (θ5 of s5), then
    the others (a2 c2 + a3 c23 + d5 s234 has a zero in θ2 whatever θ3 and θ4, not always in θ4)."""
    rng = random.Random(5)
    found = []
    for _ in range(configurations * 3):
        values = sample_values(chain, rng, sample)
        for variable in reversed(variables):
            root = _root_in(chain, factor, variable, values)
            if root is not None:
                found.append(poses(chain, {**values, variable: root}))
                break
        if len(found) == configurations:
            break
    return found


def _root_in(chain: Chain, factor, variable, values) -> float | None:
    """A zero of `factor` in `variable` (the others at `values`), or None."""
    f = sympy.lambdify([variable], factor.xreplace({s: v for s, v in values.items() if s != variable}), "math")
    span = math.pi if chain.rows[chain.joint_variables.index(variable)].joint == "R" else 3.0
    grid = [-span + 2 * span * k / SCAN_STEPS for k in range(SCAN_STEPS + 1)]
    for lo, hi in zip(grid, grid[1:]):
        if f(lo) == 0 or f(lo) * f(hi) < 0:
            return _bisect(f, lo, hi)
    return None


def _bisect(f, lo: float, hi: float) -> float:
    for _ in range(60):
        middle = (lo + hi) / 2
        if f(lo) * f(middle) <= 0:
            hi = middle
        else:
            lo = middle
    return (lo + hi) / 2


def _parallel(chain: Chain, a: int, b: int, pose) -> bool:
    return math.dist(cross(axis_line(chain, a, pose)[1], axis_line(chain, b, pose)[1]), (0, 0, 0)) < 1e-6


def _collinear(chain: Chain, a: int, b: int, pose) -> bool:
    return _parallel(chain, a, b, pose) and distance_to_axis(axis_line(chain, b, pose)[0],
                                                             axis_line(chain, a, pose)) < 1e-6


def _in_plane(chain: Chain, a: int, b: int, where, pose) -> bool:
    """The point `where` lies in the plane of the parallel axes a and b."""
    first, second = axis_line(chain, a, pose), axis_line(chain, b, pose)
    normal = cross(first[1], minus(second[0], first[0]))
    size = math.dist(normal, (0, 0, 0))
    if size < TOLERANCE:  # the two axes coincide: any point is in a plane with them
        return distance_to_axis(where, first) < 1e-6
    return abs(dot(normal, minus(where, first[0]))) / size < 1e-6


def _origin_in_plane(chain: Chain, a: int, b: int, frame, pose) -> bool:
    return _in_plane(chain, a, b, pose[frame][1], pose)


def _axis_in_plane(chain: Chain, a: int, b: int, joint: int, pose) -> bool:
    """Axis `joint`, parallel to a and b, lies in their plane (a point of it does)."""
    return _in_plane(chain, a, b, axis_line(chain, joint, pose)[0], pose)


def _over(chain: Chain, a: int, b: int, point, pose) -> bool:
    """The point lies in the plane through axis a that is parallel to axis b."""
    first, second = axis_line(chain, a, pose), axis_line(chain, b, pose)
    normal = cross(first[1], second[1])
    return abs(dot(normal, minus(pose[point][1], first[0]))) / math.dist(normal, (0, 0, 0)) < 1e-6
