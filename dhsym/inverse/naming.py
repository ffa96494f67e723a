"""Branch names that say what is true of the arm. The solver names a branch by the sign of each
square root it chose (dhsym.inverse.branches): + is "shoulder right", "elbow down". For a planar
arm that is the book's own definition (Spong's elbow down and up, by the sign of the root). For a
spatial arm whose shoulder is joints 1 and 2 (axes crossing at right angles) and whose elbow is
joint 3 (parallel to joint 2), the words are checked against the geometry a textbook draws, with
z0 pointing up, at twelve poses:

- shoulder right / left: seen from above, the plane in which the arm swings (normal to axis 2,
  through the wrist centre) lies to the right / left of the line from axis 1 to the wrist centre,
  as a person's right or left arm does (the PUMA's two shoulder configurations; for an arm with no
  wrist centre whose axis 4 is parallel to axis 2, as the UR5's, the point where axes 5 and 6
  meet stands for it);
- elbow up / down: the elbow (on axis 3) above / below the line from the shoulder (on axis 2) to
  the wrist centre, in that plane; said only of an arm with a wrist centre whose axes 1 and 2
  meet, where the shoulder's root fixes on which side of the shoulder the wrist centre lies (else
  the elbow's side of that line changes with the pose within one branch).

- shoulder front / back, for an arm whose plane passes through axis 1 but whose axis 2 lies off
  axis 1 (a shoulder offset a1, as an IRB 140's): the wrist centre on the side of axis 1 where
  axis 2 is, or reached over the back.

Where the words hold they are given by that geometry; where they cannot be checked (the arm is not
of that shape, or its plane and axis 2 pass through axis 1) the name says the root instead:
"shoulder +√", "elbow −√".

>>> import dhsym
>>> [branch.name for branch in dhsym.load("puma560").ik().branches][:2]
['shoulder left, elbow up, wrist not flipped', 'shoulder left, elbow up, wrist flipped']
"""
from __future__ import annotations

import math
import random
import re
from dataclasses import replace

from ..velocity.geometry import axis_line, distance_to_axis, dot, minus, poses, wrist_centre
from ..velocity.jacobian import cross
from .branches import WORDS
from .solution import Branch

POSES = 12  # the words must hold at every one of these poses
TOLERANCE = 1e-7
_ROLE = re.compile(r"\b(shoulder|elbow)( \([^)]*\))? (right|left|up|down)\b")
DEFINITIONS = {"right": "shoulder right/left: seen from above (z0 up), the arm's plane lies right/left of the line "
                        "from axis 1 to the {wrist}",
               "front": "shoulder front/back: the {wrist} on the side of axis 1 where axis 2 is, or on the other",
               "up": "elbow up/down: the elbow above/below the line from the shoulder to the {wrist}"}


def checked_names(solution, evaluate):
    """`solution` with its shoulder and elbow words checked (see the module docstring); `evaluate`
    gives every branch's joint values at a pose (dhsym.inverse.evaluate)."""
    if not any(_ROLE.search(branch.name) for branch in solution.branches):
        return solution
    chain = solution.chain
    if _planar(chain):
        return solution  # the book's names: the sign of the root
    labels = _geometry(solution, evaluate) if not solution.free else None
    names = []
    for number, branch in enumerate(solution.branches):
        label = labels[number] if labels else None
        names.append(_ROLE.sub(lambda m, label=label: _word(m, label), branch.name))
    if len(set(names)) < len(names):  # the geometry did not tell the branches apart: say the roots
        names = [_ROLE.sub(lambda m: _word(m, None), branch.name) for branch in solution.branches]
    said = {word for label in labels or () for word in label.values()}
    branches = tuple(Branch(name, branch.assignments) for name, branch in zip(names, solution.branches))
    wrist = "wrist centre" if wrist_centre(chain) is not None else "wrist (where axes 5 and 6 meet)"
    meanings = [text.format(wrist=wrist) for key, text in DEFINITIONS.items()
                if key in said or {"right": "left", "front": "back", "up": "down"}[key] in said]
    method = f"{solution.method}; branch names: {'; '.join(meanings)}" if meanings else solution.method
    return replace(solution, branches=branches, method=method)


def _word(match, label) -> str:
    role, joint, word = match.group(1), match.group(2) or "", match.group(3)
    if label and label.get(role):
        return f"{role}{joint} {label[role]}"
    sign = "+" if word == WORDS[role][0] else "−"
    return f"{role}{joint} {sign}√"


def _planar(chain) -> bool:
    """Whether every revolute axis is parallel to the first (a planar arm, a SCARA)."""
    rng = random.Random(3)
    frames = poses(chain, _values(chain, rng))
    first = axis_line(chain, 1, frames)[1]
    return all(_length(cross(first, axis_line(chain, j, frames)[1])) < TOLERANCE
               for j, row in enumerate(chain.rows, 1) if row.joint == "R")


def _geometry(solution, evaluate):
    """[{"shoulder": "left" | "right" | None, "elbow": "up" | "down" | None}] per branch, the same at
    every pose tried, or None if the arm is not of the shape the words describe."""
    chain = solution.chain
    if chain.n < 4 or any(row.joint != "R" for row in chain.rows[:2]):
        return None
    centre = wrist_centre(chain)
    # The words are about the arm. Behind a wrist centre the wrist's joints cannot move any axis or
    # point the words use, so only the arm's joints are computed (the wrist's formulas are most of
    # the work of compiling a solution); without one every joint is.
    needed = solution.joint_variables[:chain.n - 3] if centre is not None else solution.joint_variables
    skipped = [v for v in solution.joint_variables if v not in needed]
    asked = _keeping(solution, set(needed))
    rng = random.Random(16)
    found: list = [None] * len(solution.branches)
    configurations, targets = [], []
    for _ in range(POSES):
        values = _values(chain, rng)
        rotation, origin = poses(chain, values)[chain.last_frame]
        configurations.append(values)
        targets.append([[*rotation[r], origin[r]] for r in range(3)] + [[0.0, 0.0, 0.0, 1.0]])
    for values, branches in zip(configurations, evaluate(asked, targets, {v: 0.0 for v in skipped})):
        for number, joints in enumerate(branches):
            found_values = {v: float(x) for v, x in zip(solution.joint_variables, joints) if v in needed}
            if any(math.isnan(x) for x in found_values.values()):
                continue
            label = _labels(chain, {**values, **found_values}, centre)
            if label is None:
                return None
            if found[number] is None:
                found[number] = label
            found[number] = {role: word if found[number][role] == word else None for role, word in label.items()}
    return [label or {"shoulder": None, "elbow": None} for label in found]


def _keeping(solution, joints: set):
    """`solution` with each branch assigning only `joints` (and the values they are computed from);
    the other joint variables become parameters, so that a branch's joints are computed whole."""
    if joints == set(solution.joint_variables):
        return solution
    branches = []
    for branch in solution.branches:
        kept = set(joints)
        for name, value in reversed(branch.assignments):  # a kept value keeps what it is computed from
            if name in kept:
                kept |= value.free_symbols
        branches.append(Branch(branch.name, tuple((n, v) for n, v in branch.assignments if n in kept)))
    others = tuple(v for v in solution.joint_variables if v not in joints)
    return replace(solution, branches=tuple(branches), free=tuple(solution.free) + others)


def _values(chain, rng: random.Random) -> dict:
    """Joint angles uniform in (−π, π), slides in (0.5, 1.5), constants from the robot's sample (else
    in (0.5, 1.5)), drawn in the order of the names: the same numbers in every run."""
    values = {}
    for symbol in sorted(chain.symbols, key=lambda s: s.name):
        if symbol in chain.sample:
            values[symbol] = float(chain.sample[symbol])
        elif symbol in chain.joint_variables and chain.rows[chain.joint_variables.index(symbol)].joint == "R":
            values[symbol] = rng.uniform(-math.pi, math.pi)
        else:
            values[symbol] = rng.uniform(0.5, 1.5)
    return values


def _labels(chain, values: dict, centre):
    """The shoulder's and the elbow's words at one configuration, or None if the arm's shape does not fit."""
    frames = poses(chain, values)
    base, up = axis_line(chain, 1, frames)
    shoulder, across = axis_line(chain, 2, frames)
    elbow, third = axis_line(chain, 3, frames)
    if abs(dot(up, across)) > TOLERANCE:
        return None
    normal = cross(up, across)
    crossing = abs(dot(minus(shoulder, base), normal)) < TOLERANCE * _length(normal)  # axes 1 and 2 meet
    # the elbow's side of the line to the wrist is fixed by the roots only when the shoulder's root fixes
    # which way the wrist centre lies from the shoulder: axes 1 and 2 meet, and the arm has a wrist centre
    has_elbow = (chain.rows[2].joint == "R" and _length(cross(across, third)) < TOLERANCE and crossing
                 and centre is not None)
    if centre is not None:
        wrist = frames[centre][1]
    else:
        point, fourth = axis_line(chain, 4, frames)
        if _length(cross(across, fourth)) > TOLERANCE:
            return None
        wrist = point
        for j in range(min(chain.n, 6), 4, -1):  # where axes 5 and 6 meet (the UR5's), else axes 4 and 5
            candidate, _ = axis_line(chain, j, frames)
            if distance_to_axis(candidate, axis_line(chain, j - 1, frames)) < TOLERANCE:
                wrist = candidate
                break
    reach, bend = minus(wrist, shoulder), minus(elbow, shoulder)
    offset = [dot(across, reach) * a for a in across]  # the arm's plane, from the shoulder, along axis 2
    flat = [r - dot(up, reach) * u for r, u in zip(reach, up)]
    side = dot(cross(flat, offset), up)
    in_plane = minus(reach, offset)
    bend = [b - dot(across, bend) * a for b, a in zip(bend, across)]
    length = _length([r - dot(up, in_plane) * u for r, u in zip(in_plane, up)])
    if length < TOLERANCE:
        return {"shoulder": None, "elbow": None}
    forward = [(r - dot(up, in_plane) * u) / length for r, u in zip(in_plane, up)]
    height = dot(bend, up) * dot(in_plane, forward) - dot(in_plane, up) * dot(bend, forward)
    if abs(side) < TOLERANCE:  # no offset along axis 2: the wrist in front of the shoulder or behind it
        apart = minus(shoulder, base)
        apart = [a - dot(up, apart) * u for a, u in zip(apart, up)]
        away = minus(wrist, base)
        ahead = dot(apart, [a - dot(up, away) * u for a, u in zip(away, up)])
        side = 0.0 if _length(apart) < TOLERANCE or abs(ahead) < TOLERANCE else (-1.0 if ahead > 0 else 1.0)
        words = ("front", "back")
    else:
        words = ("right", "left")
    return {"shoulder": None if abs(side) < TOLERANCE else (words[0] if side < 0 else words[1]),
            "elbow": None if abs(height) < TOLERANCE or not has_elbow else ("up" if height > 0 else "down")}


def _length(vector) -> float:
    return math.sqrt(sum(x * x for x in vector))
