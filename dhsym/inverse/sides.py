"""The numbers behind the words of a branch's name (dhsym.inverse.naming): for one configuration
of the arm, a signed number per word pair, positive for the first word ("right", "front", "up",
"lefty", "forward", "not flipped"), None where the arm is not of the shape the words describe.
"Up" is the direction of axis 1; points and directions come from velocity.geometry.

>>> import dhsym, math
>>> from dhsym.velocity.geometry import poses
>>> arm = Arm(dhsym.load("planar2r").chain)
>>> a_1, a_2, theta_1, theta_2 = sorted(arm.chain.symbols, key=str)
>>> frames = poses(arm.chain, {a_1: 1.0, a_2: 1.0, theta_1: 0.0, theta_2: math.pi / 2})
>>> MEASURES["planar"].words, MEASURES["planar"].measure(arm, frames, 2) < 0  # the elbow right of the line
(('up', 'down'), True)
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Callable

from ..core.chain import Chain
from ..velocity.geometry import (
    axis_line,
    cross,
    distance_to_axis,
    dot,
    minus,
    nearest_point,
    norm,
    poses,
    sample_values,
)
from .sentences import Meaning, Point

TOLERANCE = 1e-7  # a measure smaller than this says nothing (the pose is between two words)


@dataclass(frozen=True)
class Measure:
    role: str  # printed before the word: "shoulder", "elbow", "wrist", "slide", or "" (righty, lefty)
    words: tuple[str, str]  # (for a positive number, for a negative one)
    measure: Callable  # (Arm, frames, the joint (1..n) whose formula holds the choice) -> float | None


class Arm:
    """The shape of a chain that the words need, worked out once: `centre` its wrist centre's
    frame (velocity.geometry.wrist_centre) or None; whether it is planar (every revolute axis
    parallel to axis 1) and a SCARA (planar, with a slide along those axes)."""

    def __init__(self, chain: Chain, centre=None, sample=None):
        self.chain, self.centre = chain, centre
        self.sample = poses(chain, sample_values(chain, random.Random(3), sample or {}))
        first = axis_line(chain, 1, self.sample)[1]
        parallel = [_parallel(first, axis_line(chain, j, self.sample)[1]) for j in range(1, chain.n + 1)]
        kinds = [row.joint for row in chain.rows]
        self.planar = all(p for p, kind in zip(parallel, kinds) if kind == "R") and kinds.count("R") >= 2
        self.scara = self.planar and any(p for p, kind in zip(parallel, kinds) if kind == "P")

    def wrist(self, frames):
        """(the point the shoulder's words use, what it is: a Point): the wrist centre; for an arm
        without one whose axis 4 is parallel to axis 2 (the UR5's), where axes 5 and 6 (else 4 and 5)
        meet; else the end point."""
        chain = self.chain
        if self.centre is not None:
            return frames[self.centre][1], Point("wrist centre")
        if chain.n >= 5 and _parallel(axis_line(chain, 2, frames)[1], axis_line(chain, 4, frames)[1]):
            for j in range(min(chain.n, 6), 4, -1):
                line, before = axis_line(chain, j, frames), axis_line(chain, j - 1, frames)
                if not _parallel(line[1], before[1]):
                    point = nearest_point(line, before)
                    if distance_to_axis(point, before) < TOLERANCE:
                        return point, Point("meeting", (j - 1, j))
        return frames[chain.last_frame][1], Point("target origin")

    def elbow_wrist(self, frames, joint):
        """(the point the elbow's words use, its name): the wrist centre; else a point on the next
        axis when it is parallel to the elbow's (the UR5's axis 4); else the shoulder words' point."""
        chain = self.chain
        if self.centre is None and joint < chain.n and \
                _parallel(axis_line(chain, joint, frames)[1], axis_line(chain, joint + 1, frames)[1]):
            return axis_line(chain, joint + 1, frames)[0], Point("axis point", (joint + 1,))
        return self.wrist(frames)

    def planar_wrist(self, frames, joint):
        """(a point on the next revolute axis after the elbow, else the end point, its name)."""
        chain = self.chain
        for j in range(joint + 1, chain.n + 1):
            if chain.rows[j - 1].joint == "R":
                return axis_line(chain, j, frames)[0], Point("wrist point", (j,))
        return frames[chain.last_frame][1], Point("end point")

    def slide_axes(self, frames, joint):
        """(the slide j at or after `joint`, the revolute axis r before it that it crosses) or None."""
        chain = self.chain
        for j in range(joint, chain.n + 1):
            if chain.rows[j - 1].joint != "P":
                continue
            before = [r for r in range(1, j) if chain.rows[r - 1].joint == "R"]
            if before and not _parallel(axis_line(chain, j, frames)[1], axis_line(chain, before[-1], frames)[1]):
                return j, before[-1]
        return None

    def wrist_middle(self, joint: int) -> int:
        """The middle one of the three wrist joints a choice of `joint` (one of them) belongs to."""
        n = self.chain.n
        return n - 1 if joint >= n - 2 else 2 if joint <= 3 else joint

    def meaning(self, key: str, joint: int) -> Meaning:
        """What the word `key` means for the choice held by `joint`: its joints and points (1..n)."""
        slide = self.slide_axes(self.sample, joint) or (0, 0)
        middle = self.wrist_middle(joint)
        joints = {"slide": slide[0], "slide_from": slide[1], "a": middle - 1, "b": middle, "c": middle + 1, "one": 1,
                  "two": 2}
        points = {"wrist": self.wrist(self.sample)[1], "elbow_wrist": self.elbow_wrist(self.sample, joint)[1],
                  "planar_wrist": self.planar_wrist(self.sample, joint)[1],
                  "slide_wrist": self.slide_point(self.sample)[1]}
        return Meaning(key, tuple(joints.items()), tuple(points.items()))

    def slide_point(self, frames):
        """(the point a slide's words use: the wrist centre, else the end point; a Point)."""
        if self.centre is not None:
            return frames[self.centre][1], Point("wrist centre")
        return frames[self.chain.last_frame][1], Point("end point")


def _right(arm, frames, joint):
    """Seen from above, the arm's plane (normal to axis 2 through the wrist) right of the line from
    axis 1 to the wrist: the reach's part along axis 2 turned clockwise from its horizontal part."""
    up, shoulder, across = _shoulder(arm, frames)
    if across is None:
        return None
    reach = minus(arm.wrist(frames)[0], shoulder)
    offset = [dot(across, reach) * a for a in across]
    if norm(offset) < TOLERANCE:
        return None  # no offset along axis 2: the shoulder's words are front and back
    return -dot(cross(_flat(reach, up), offset), up)


def _front(arm, frames, joint):
    """Axis 2 off axis 1: the wrist on the side of axis 1 where axis 2 is."""
    up, shoulder, across = _shoulder(arm, frames)
    if across is None:
        return None
    base = axis_line(arm.chain, 1, frames)[0]
    apart = _flat(minus(shoulder, base), up)
    apart = [a - dot(across, apart) * c for a, c in zip(apart, across)]  # the common normal of axes 1 and 2
    if norm(apart) < TOLERANCE:
        return None
    return dot(apart, _flat(minus(arm.wrist(frames)[0], base), up))


def _ahead(end: bool):
    """Axes 1 and 2 meet: the wrist (the end point if `end`) on the side of axis 1 that frame 1's
    x axis points to."""
    def measure(arm, frames, joint):
        up, shoulder, across = _shoulder(arm, frames)
        if across is None or _front(arm, frames, joint) is not None:
            return None
        point, name = arm.wrist(frames)
        if end and name.kind == "target origin":
            return None  # the same as the wrist's word
        base = axis_line(arm.chain, 1, frames)[0]
        x1 = _flat([row[0] for row in frames[1][0]], up)
        if norm(x1) < TOLERANCE:
            return None
        return dot(x1, _flat(minus(frames[arm.chain.last_frame][1] if end else point, base), up))
    return measure


def _up(outward: bool):
    """The elbow (on the axis of `joint`, parallel to axis 2) on the upper side of the line from the
    shoulder to the wrist in the arm's plane, the line drawn going forward: the way the wrist lies
    from the shoulder, or (`outward`) from axis 1. The two differ only when the wrist lies between
    axis 1 and a shoulder off it."""
    def measure(arm, frames, joint):
        found = _elbow_plane(arm, frames, joint)
        if found is None:
            return None
        up, shoulder, across, elbow, wrist = found
        start = axis_line(arm.chain, 1, frames)[0] if outward else shoulder
        reach, bend, out = (minus(a, b) for a, b in ((wrist, shoulder), (elbow, shoulder), (wrist, start)))
        reach, bend, out = ([x - dot(across, v) * a for x, a in zip(v, across)] for v in (reach, bend, out))
        flat = _flat(out, up)
        length = norm(flat)
        if length < TOLERANCE:
            return 0.0  # the wrist straight above the start: neither
        forward = [x / length for x in flat]
        return dot(bend, up) * dot(reach, forward) - dot(reach, up) * dot(bend, forward)
    return measure


def _turned(arm, frames, joint):
    """The elbow (on the axis of `joint`, parallel to axis 2) left of the line from the shoulder to
    the wrist, drawn in the arm's plane with axis 1 up and frame 1's x axis to the right: the way
    the arm bends, whichever side of axis 1 the wrist lies on. (An arm whose waist the orientation
    fixes, as a four-joint arm's, can reach over its back within a branch, where "above the line"
    would turn into "below".)"""
    found = _elbow_plane(arm, frames, joint)
    if found is None:
        return None
    up, shoulder, _, elbow, wrist = found
    right = _flat([row[0] for row in frames[1][0]], up)
    if norm(right) < TOLERANCE:
        return None
    toward_viewer = cross(right, up)
    return dot(cross(minus(wrist, shoulder), minus(elbow, shoulder)), toward_viewer)


def _elbow_plane(arm, frames, joint):
    """(axis 1's direction, a point on axis 2, axis 2's direction, a point on the elbow's axis, the
    elbow words' wrist point) where the elbow (joint `joint`, revolute) turns about an axis parallel
    to axis 2 and axis 2 is perpendicular to axis 1; else None."""
    chain = arm.chain
    up, shoulder, across = _shoulder(arm, frames)
    if across is None or joint < 3 or chain.rows[joint - 1].joint != "R":
        return None
    elbow, third = axis_line(chain, joint, frames)
    if not _parallel(across, third):
        return None
    return up, shoulder, across, elbow, arm.elbow_wrist(frames, joint)[0]


def _left(arm, frames, joint):
    """A planar arm seen from +z0: the elbow (on the axis of `joint`) left of the line from axis 1
    to the wrist point."""
    chain = arm.chain
    if not arm.planar or joint < 2 or chain.rows[joint - 1].joint != "R":
        return None
    base, up = axis_line(chain, 1, frames)
    elbow = axis_line(chain, joint, frames)[0]
    return dot(cross(minus(arm.planar_wrist(frames, joint)[0], base), minus(elbow, base)), up)


def _forward(arm, frames, joint):
    """Along the slide, the wrist ahead of its crossing with the revolute axis before it."""
    axes = arm.slide_axes(frames, joint)
    if axes is None:
        return None
    slide = axis_line(arm.chain, axes[0], frames)
    foot = nearest_point(slide, axis_line(arm.chain, axes[1], frames))
    return dot(minus(arm.slide_point(frames)[0], foot), slide[1])


def _unflipped(arm, frames, joint):
    """(u_a × u_c)·u_b for the directions of the wrist's three axes a, b, c (b its middle joint)."""
    chain, middle = arm.chain, arm.wrist_middle(joint)
    if not 1 < middle < chain.n or any(chain.rows[j - 1].joint != "R" for j in (middle - 1, middle, middle + 1)):
        return None
    a, b, c = (axis_line(chain, j, frames)[1] for j in (middle - 1, middle, middle + 1))
    return dot(cross(a, c), b)


def _shoulder(arm, frames):
    """(axis 1's direction, a point on axis 2, axis 2's direction), the direction None unless
    joints 1 and 2 turn and their axes are perpendicular."""
    chain = arm.chain
    if chain.n < 3 or any(row.joint != "R" for row in chain.rows[:2]):
        return None, None, None
    up = axis_line(chain, 1, frames)[1]
    shoulder, across = axis_line(chain, 2, frames)
    return (up, shoulder, across) if abs(dot(up, across)) < TOLERANCE else (up, None, None)


def _planar_only(scara: bool):
    def measure(arm, frames, joint):
        return _left(arm, frames, joint) if arm.scara == scara else None
    return measure


MEASURES = {"right": Measure("shoulder", ("right", "left"), _right),
            "front": Measure("shoulder", ("front", "back"), _front),
            "ahead": Measure("shoulder", ("front", "back"), _ahead(False)),
            "ahead_end": Measure("shoulder", ("front", "back"), _ahead(True)),
            "up": Measure("elbow", ("up", "down"), _up(False)),
            "up_out": Measure("elbow", ("up", "down"), _up(True)),
            "planar": Measure("elbow", ("up", "down"), _planar_only(False)),
            "turned": Measure("elbow", ("up", "down"), _turned),
            "lefty": Measure("", ("lefty", "righty"), _planar_only(True)),
            "slide": Measure("slide", ("forward", "back"), _forward),
            "flip": Measure("wrist", ("not flipped", "flipped"), _unflipped)}


def _flat(vector, up) -> list:
    """`vector` without its part along `up`."""
    along = dot(vector, up)
    return [x - along * u for x, u in zip(vector, up)]


def _parallel(u, v) -> bool:
    return norm(cross(u, v)) < TOLERANCE
