"""Branch names that say what is true of the arm. The solver names a branch by the sign of each
square root (or of an atan2's pair) it chose, and the joint's place in the arm (dhsym.inverse.
branches). Here each choice gets the word that the arm's geometry gives it: a word is given when
it holds at every one of twelve poses for every branch (the same word at each pose where it can be
measured), and the two branches that differ in that choice only get opposite words. The words
are measured in dhsym.inverse.sides, "up" being the direction of axis 1:

- shoulder right / left: seen from above, the arm's plane (normal to axis 2, through the wrist)
  lies right / left of the line from axis 1 to the wrist, as a person's right or left arm does:
  the PUMA's, the Stanford arm's, the UR5's (its wrist: where axes 5 and 6 meet);
- shoulder front / back, where axis 2 crosses the line from axis 1 to the wrist (no offset along
  axis 2): the wrist on the side of axis 1 where axis 2 is (an offset a1, as an IRB 140's or the
  Salisbury finger's), else, axes 1 and 2 meeting, on the side that frame 1's x axis points to (the
  inline arm, the spatial 3R); else over the back. The Rhino-like five-axis arm's choice of θ1 puts
  its end point, not its wrist, in front or behind: that is its word;
- elbow up / down: the elbow (on the axis of the choice's joint, parallel to axis 2) above / below
  the line from the shoulder (on axis 2) to the wrist, in the arm's plane: the PUMA's, the inline
  arm's, the spatial 3R's. It holds only where the shoulder's choice also fixes on which side of
  the shoulder the wrist lies. With a shoulder offset (the finger, an IRB 140, a KR 6) the wrist
  can lie between axis 1 and the shoulder, where the line goes backward and "above" turns into
  "below" within a branch; there the line is drawn going the way the wrist lies from axis 1 (which
  the shoulder's choice fixes): the elbow left / right of it, seen with axis 1 up and the wrist to
  its right, which is above / below wherever the wrist is further out than the shoulder. For the
  UR5 (its wrist: the point of axis 4 in the plane of axes 2, 3, 4), the Rhino-like arm and a
  four-joint arm (a waist the tool's orientation fixes) even the side of axis 1 the wrist lies on
  changes within a branch: there the words say the way the arm bends, the elbow left / right of
  the line drawn with axis 1 up and frame 1's x axis to the right (above / below wherever the
  wrist lies ahead of the shoulder);
- elbow up / down of a planar arm, Spong's, drawn with x0 right and y0 up: seen from +z0, the
  elbow left (up) / right (down) of the line from joint 1 to the wrist point (the next revolute
  axis, else the end); Spong's +√ of the elbow's cosine law is elbow down, and the two agree at
  every pose;
- righty / lefty, a SCARA (a planar arm with a slide along its axes), as industry says: seen from
  above, the elbow right / left of the line from axis 1 to the wrist's axis;
- slide forward / back: along a slide (the Stanford arm's d3; the cylindrical arm's d3, whose sign
  the choice of θ1 decides), the wrist on the side of the slide's crossing with the revolute axis
  before it that the slide's axis points to (d3 > 0 with the usual frames), or behind;
- wrist not flipped / flipped: seen from the tip of u5 (the direction of the wrist's middle axis),
  axis 6 is turned from axis 4 counter-clockwise / clockwise: (u4 × u6)·u5 > 0 / < 0. Craig's
  flipped twin (θ4 + π, −θ5, θ6 + π) reverses u5 and keeps u4 and u6 (the same pose), so the twins
  always get opposite words; for the PUMA "not flipped" is θ5's +√, as in Craig.

Where no word holds the name says the root: "shoulder +√", "elbow −√". Every word printed is
defined once in the method line (a `Meaning` each; dhsym.printing.ik_words writes them).

>>> import dhsym
>>> from dhsym.inverse import solve
>>> [branch.name for branch in solve(dhsym.load("puma560").chain).branches][:2]
['shoulder left, elbow up, wrist not flipped', 'shoulder left, elbow up, wrist flipped']
>>> [branch.name for branch in solve(dhsym.load("scara").chain).branches]
['righty', 'lefty']
"""
from __future__ import annotations

import random
from dataclasses import replace

from ..core.sampling import random_pose
from ..velocity.geometry import poses, wrist_centre
from .branches import WORDS
from .pointwise import BranchValues
from .sentences import Meaning, Method
from .sides import MEASURES, TOLERANCE, Arm
from .solution import Branch

POSES = 12  # the words must hold at every one of these poses
CHECKED_AT_LEAST = 3  # poses at which every branch must be measured for a word to be given
ROOT = ("+√", "−√")


def checked_names(solution):
    """`solution` with each branch's words checked against the arm (see the module docstring)."""
    parts = [_parts(branch.name) for branch in solution.branches]
    if not parts or not parts[0] or any(len(p) != len(parts[0]) for p in parts):
        return solution  # "the only solution"
    chain = solution.chain
    joints = [_root_joint(solution, parts, k) for k in range(len(parts[0]))]
    chosen = [None] * len(joints)
    arm = Arm(chain, wrist_centre(chain, sample=solution.sample), solution.sample)
    if any(joints):
        measured = _measured(solution, arm, parts, joints)
        chosen = [_first_holding(measured, parts, k, role) if joints[k] else None
                  for k, (role, _) in enumerate(parts[0])]
    symbols = [chain.joint_variables[j - 1] if j else None for j in joints]
    texts = _names(parts, chosen, symbols)
    if len(set(texts)) < len(texts):  # cannot happen when each word tells twins apart; say the roots then
        chosen = [None] * len(joints)
        texts = _names(parts, chosen, symbols)
    meanings = []
    for k, choice in enumerate(chosen):
        key = choice[0] if choice else "root"
        if key == "slide" and _runs_backwards_behind(measured, choice[1], k):
            key = "slide_signed"
        meaning = arm.meaning(key, joints[k]) if choice else Meaning("root")
        if meaning not in meanings:
            meanings.append(meaning)
    branches = [Branch(text, branch.assignments) for text, branch in zip(texts, solution.branches)]
    branches = tuple(_forward_first(branches, chosen))
    said = replace(solution.method, words=tuple(meanings)) if isinstance(solution.method, Method) else solution.method
    return replace(solution, branches=branches, method=said)


def _runs_backwards_behind(measured, words, k) -> bool:
    """Whether the slide's joint variable is positive on every forward branch and negative on every
    back one, at every pose measured: then "back" means the slide runs backwards (Stanford's d3 < 0),
    which an arm whose slide only extends cannot do."""
    for values, word in zip(measured, words):
        seen = [at[("variable", k)] for at in values if at.get(("variable", k)) is not None]
        if not seen or any((v > TOLERANCE) != (word == 0) or abs(v) <= TOLERANCE for v in seen):
            return False
    return True


def _forward_first(branches, chosen) -> list:
    """The branches in order, those with a slide's "forward" before their "back" twins (a stable
    sort), so that an arm's physical branches come first; other words keep the solver's order."""
    for choice in chosen:
        if choice and choice[0] == "slide":
            order = sorted(range(len(branches)), key=lambda number: choice[1][number])
            return [branches[number] for number in order]
    return branches


def _names(parts, chosen, symbols) -> list[str]:
    """Each branch's name: the word measured for each choice that has one, else the root's sign."""
    names = []
    for number, signs in enumerate(parts):
        said = []
        for k, (role, positive) in enumerate(signs):
            if chosen[k]:
                key, words = chosen[k]
                said.append((MEASURES[key].role, symbols[k], MEASURES[key].words[words[number]]))
            else:
                said.append((role, symbols[k], ROOT[0 if positive else 1]))
        names.append(_text(said))
    return names


def _parts(name: str) -> list:
    """[(role, True for the first word of WORDS[role])] of a name branch_name wrote."""
    parts = []
    for part in name.split(", "):
        role, _, word = part.partition(" ")
        if role not in WORDS:
            return []
        if word.startswith("("):
            word = word.partition(") ")[2]
        parts.append((role, word == WORDS[role][0]))
    return parts


def _root_joint(solution, parts, k):
    """The number (1..n) of the joint whose formula holds choice k: the first joint whose value
    differs, by its formula or by a value it is computed from, in two branches that differ in
    choice k only."""
    for one, other in _twins(parts, k)[:1]:
        second = solution.branches[other].values()
        differs: set = set()
        for name, value in solution.branches[one].assignments:
            if second.get(name) != value or value.free_symbols & differs:
                differs.add(name)
                if name in solution.joint_variables:
                    return solution.chain.joint_variables.index(name) + 1
    return None


def _measured(solution, arm, parts, joints) -> list:
    """[branch][pose] -> {(measure, k): value} at POSES poses."""
    chain = arm.chain  # frames 0..n
    # Behind a wrist centre the wrist's joints move no axis or point the words use but the wrist's
    # own, and (u4 × u6)·u5 does not change with θ4 (it turns axes 5 and 6 together about axis 4) nor
    # with θ6: so only the arm's joints and the wrist's middle one are computed (the wrist's formulas
    # are the longest); without a centre every joint is.
    if arm.centre is not None:
        wrist = set(range(chain.n - 2, chain.n + 1)) - {arm.wrist_middle(j) for j in joints if j and j >= chain.n - 2}
        needed = [v for j, v in enumerate(chain.joint_variables, 1) if j not in wrist and v not in solution.free]
    else:
        needed = [v for v in chain.joint_variables if v not in solution.free]
    zero = {v: 0.0 for v in chain.joint_variables if v not in needed and v not in solution.free}
    branch_values = BranchValues(solution, needed)
    rng = random.Random(16)
    measured: list = [[] for _ in solution.branches]
    keys = [(key, k) for k, (role, _) in enumerate(parts[0]) if joints[k] for key in _candidates(role)]
    slides = {k: chain.joint_variables[axes[0] - 1] for k, joint in enumerate(joints)
              if joint and "slide" in _candidates(parts[0][k][0]) and (axes := arm.slide_axes(arm.sample, joint))}
    for _ in range(POSES):
        values = random_pose(chain, rng, solution.sample)
        rotation, origin = poses(chain, values)[chain.last_frame]
        target = [[*rotation[r], origin[r]] for r in range(3)]
        constants = {s: x for s, x in values.items() if s not in needed}  # the pose's own joints stay unknown
        for number, found in enumerate(branch_values(target, constants)):
            if found is None:
                continue
            frames = poses(chain, {**values, **zero, **{v: found[v] for v in needed}})
            at = {(key, k): MEASURES[key].measure(arm, frames, joints[k]) for key, k in keys}
            at |= {("variable", k): found.get(variable) for k, variable in slides.items()}
            measured[number].append(at)
    return measured


def _candidates(role: str) -> tuple:
    """The words tried for a choice of `role`, in order."""
    return {"shoulder": ("right", "front", "ahead", "slide", "ahead_end"),
            "elbow": ("lefty", "planar", "up", "up_out", "turned", "slide"),
            "wrist": ("flip",), "slide": ("slide",)}[role]


def _first_holding(measured, parts, k, role):
    """(measure key, [the word's index (0, 1) per branch]) of the first measure whose sign is the
    same at every pose of each branch and opposite in two branches that differ in choice k only;
    None if no measure holds."""
    for key in _candidates(role):
        words = []
        for values in measured:
            seen = [v > 0 for v in (at[(key, k)] for at in values) if v is not None and abs(v) > TOLERANCE]
            if len(set(seen)) != 1 or len(seen) < CHECKED_AT_LEAST:
                break
            words.append(0 if seen[0] else 1)
        else:
            if all(words[one] != words[other] for one, other in _twins(parts, k)):
                return key, words
    return None


def _twins(parts, k):
    """The pairs of branches (numbers) that differ in choice k only."""
    return [(one, other) for one, signs in enumerate(parts) for other, others in enumerate(parts)
            if all((a == b) == (i != k) for i, (a, b) in enumerate(zip(signs, others)))]


def _text(said) -> str:
    """'role word, ...' with the joint named where two choices share a role."""
    counts = {}
    for role, _, _ in said:
        counts[role] = counts.get(role, 0) + 1
    parts = []
    for role, joint, word in said:
        if not role:
            parts.append(word)
        elif counts[role] > 1:
            parts.append(f"{role} ({joint}) {word}")
        else:
            parts.append(f"{role} {word}")
    return ", ".join(parts)

