"""What each singular factor means for the arm, in words a lecture would use.

Each factor of the determinant is tried at configurations where it vanishes (found by
numbers: the other joints at random values, the factor's last joint scanned for a change of
sign), against the geometric situations a course names, in this order:

* a prismatic joint at zero extension (d3 = 0);
* two joint axes that line up (the wrist: axes 4 and 6 when s5 = 0);
* the arm stretched or folded at joint j: the point lies in the plane of the parallel axes
  j − 1 and j (the elbow);
* the point in the plane through axis a parallel to axis b: over axis a (the shoulder; on the
  axis itself when the arm has no sideways offset).

A factor that none of them describes is said to be so.

>>> import dhsym
>>> from dhsym.velocity.determinant import determinant
>>> puma = dhsym.load("puma560")
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

import sympy

from .geometry import TOLERANCE, axis_line, cross, distance_to_axis, dot, minus, poses, sample_values, wrist_centre

SCAN_STEPS = 720


@dataclass(frozen=True)
class Singularity:
    """A factor whose vanishing makes J singular, and what that means: `template` in plain
    words with {0}, {1} … for the joints in `joints` (row numbers 1..n)."""

    factor: sympy.Expr
    template: str
    joints: tuple = ()

    @property
    def meaning(self) -> str:
        return self.describe()

    def describe(self, label=str) -> str:
        """The meaning with each joint written by `label(row number)` (a wrist's rows 1..3
        print as 4..6 when its variables are θ4..θ6)."""
        return self.template.format(*(label(j) for j in self.joints))


def singularities(chain, determinant, point=None) -> list[Singularity]:
    """One Singularity per factor of `determinant` (a velocity.determinant.Determinant)."""
    centre = wrist_centre(chain) if chain.n >= 6 else None
    point = centre if centre is not None else (chain.last_frame if point is None else point)
    name = "wrist centre" if centre is not None else POINT_NAMES.get(point, f"origin of frame {point}")
    return [Singularity(f, *meaning(chain, f, point, name)) for f in determinant.factors]


POINT_NAMES = {"tool": "tool point", "base": "origin of the base frame"}


def meaning(chain, factor, point, name: str) -> tuple[str, tuple]:
    """The first geometric description that holds wherever `factor` vanishes: (template, joints)."""
    variables = [v for v in chain.joint_variables if v in factor.free_symbols]
    joint = chain.joint_variables.index(variables[-1]) + 1
    if factor == variables[-1] and chain.rows[joint - 1].joint == "P":
        return "joint {0} retracted to zero extension", (joint,)
    roots = _roots(chain, factor, variables[-1])
    if not roots:
        return "no real configuration found where this factor vanishes (for random dimensions)", ()
    n = chain.n
    revolute = [j for j in range(1, n + 1) if chain.rows[j - 1].joint == "R"]
    generic = poses(chain, sample_values(chain, random.Random(11)))
    if len(variables) == 1:
        pairs = sorted(((a, b) for a in revolute for b in revolute if a < b), key=lambda p: abs(sum(p) - 2 * joint))
        for a, b in pairs:  # the pair around the joint first: axes 4 and 6 for θ5
            if not _parallel(chain, a, b, generic) and all(_parallel(chain, a, b, pose) for pose in roots):
                return f"{'wrist: ' if a > n - 3 and n >= 6 else ''}axes {{0}} and {{1}} line up", (a, b)
        for j in (joint, joint + 1):
            if not (1 < j <= n and _parallel(chain, j - 1, j, generic)):
                continue
            stretched = f"{'elbow' if n >= 6 else 'arm'} stretched or folded: "
            if all(_in_plane(chain, j - 1, j, pose[point][1], pose) for pose in roots):
                return stretched + f"the {name} lies in the plane of axes {{0}} and {{1}}", (j - 1, j)
            for k in range(j + 1, n + 1):  # a planar 3R: axis 3 (the wrist), not the tool point
                if all(_in_plane(chain, j - 1, j, axis_line(chain, k, pose)[0], pose) for pose in roots):
                    return stretched + "axis {2} lies in the plane of axes {0} and {1}", (j - 1, j, k)
    for a in revolute:
        for b in range(a + 1, n + 1):
            if not _parallel(chain, a, b, generic) and all(_over(chain, a, b, point, pose) for pose in roots):
                return (f"{'shoulder: ' if a == 1 else ''}the {name} lies in the plane through axis {{0}} parallel "
                        "to axis {1} (on axis {0} when there is no offset)"), (a, b)
    return "the joint velocities are dependent here (no simpler description found)", ()


def _roots(chain, factor, variable, configurations: int = 3) -> list:
    """Poses of the chain at up to `configurations` zeros of `factor`, others at random values."""
    rng = random.Random(5)
    found = []
    for _ in range(configurations * 3):
        values = sample_values(chain, rng)
        f = sympy.lambdify([variable], factor.xreplace({s: v for s, v in values.items() if s != variable}), "math")
        span = math.pi if chain.rows[chain.joint_variables.index(variable)].joint == "R" else 3.0
        grid = [-span + 2 * span * k / SCAN_STEPS for k in range(SCAN_STEPS + 1)]
        for lo, hi in zip(grid, grid[1:]):
            if f(lo) == 0 or f(lo) * f(hi) < 0:
                values[variable] = _bisect(f, lo, hi)
                found.append(poses(chain, values))
                break
        if len(found) == configurations:
            break
    return found


def _bisect(f, lo: float, hi: float) -> float:
    for _ in range(60):
        middle = (lo + hi) / 2
        if f(lo) * f(middle) <= 0:
            hi = middle
        else:
            lo = middle
    return (lo + hi) / 2


def _parallel(chain, a: int, b: int, pose) -> bool:
    return math.dist(cross(axis_line(chain, a, pose)[1], axis_line(chain, b, pose)[1]), (0, 0, 0)) < 1e-6


def _in_plane(chain, a: int, b: int, where, pose) -> bool:
    """The point `where` lies in the plane of the parallel axes a and b."""
    first, second = axis_line(chain, a, pose), axis_line(chain, b, pose)
    normal = cross(first[1], minus(second[0], first[0]))
    size = math.dist(normal, (0, 0, 0))
    if size < TOLERANCE:  # the two axes coincide: any point is in a plane with them
        return distance_to_axis(where, first) < 1e-6
    return abs(dot(normal, minus(where, first[0]))) / size < 1e-6


def _over(chain, a: int, b: int, point, pose) -> bool:
    """The point lies in the plane through axis a that is parallel to axis b."""
    first, second = axis_line(chain, a, pose), axis_line(chain, b, pose)
    normal = cross(first[1], second[1])
    return abs(dot(normal, minus(pose[point][1], first[0]))) / math.dist(normal, (0, 0, 0)) < 1e-6
