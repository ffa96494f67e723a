"""Every word in a branch's name is true of the arm in that branch: at random poses, each branch's
joint values (robot.ik().evaluate) put through this file's own numpy forward kinematics give the
geometry the word says (shoulder left/right, front/back, elbow up/down, lefty/righty, slide
forward/back, wrist flipped or not), computed here from the axes, never by dhsym's naming code."""
import importlib.metadata
import importlib.util
import re

import numpy as np
import pytest
import sympy
from cli_runner import run_dhsym
from ik_checks import random_joints, sample_constants
from packages import EXAMPLE_ROBOT_DATA, RTB_XACRO
from robots import PITCH_ARM

from dhsym import load

IRB140 = RTB_XACRO / "abb_irb140_description/urdf/irb140.xacro"
UR10 = EXAMPLE_ROBOT_DATA / "ur_description/urdf/ur10_robot.urdf"
TINY = 1e-6  # a measure this small says nothing (the pose is on the boundary between two words)

# the words each arm's branches must use: pairs of (one word, the other); "√" where its name says the root
FLIP = ("wrist not flipped", "wrist flipped")
WORDS = {
    "puma560": {("shoulder left", "shoulder right"), ("elbow up", "elbow down"), FLIP},
    "stanford": {("shoulder left", "shoulder right"), ("slide forward", "slide back"),
                 FLIP},
    "ur5": {("shoulder left", "shoulder right"), FLIP, ("elbow up", "elbow down")},
    "inline6": {("shoulder front", "shoulder back"), ("elbow up", "elbow down"), FLIP},
    "spatial3r": {("shoulder front", "shoulder back"), ("elbow up", "elbow down")},
    "finger_rrr": {("shoulder front", "shoulder back"), ("elbow up", "elbow down")},
    "iiwa7": {("shoulder front", "shoulder back"), ("elbow +√", "elbow −√"), FLIP},  # with --free theta_3
    "irb140": {("shoulder front", "shoulder back"), ("elbow up", "elbow down"), FLIP},  # imported from rtb-data
    "asokan_dh_example": {("shoulder front", "shoulder back"), ("elbow up", "elbow down")},
    "pitch_arm": {("elbow up", "elbow down")},  # tests/robots.py: a waist and three pitch joints
    "cylindrical_wrist": {("slide forward", "slide back"), FLIP},
    "cylindrical_rpp": {("slide forward", "slide back")},
    "rps_leg": {("slide forward", "slide back")},
    "planar2r": {("elbow up", "elbow down")},
    "planar3r": {("elbow up", "elbow down")},
    "pratihar_2r": {("elbow up", "elbow down")},
    "fourbar_left": {("elbow up", "elbow down")},
    "scara": {("lefty", "righty")},
    "scara_spong": {("lefty", "righty")},
    "spherical_wrist": {FLIP},
    "spherical_wrist_spong": {FLIP},
}


class Frames:
    """Each frame's pose in the first frame, by this file's own product of DH steps."""

    def __init__(self, chain, constants: dict):
        self.chain = chain
        known = {s: sympy.Float(constants[s.name]) for s in chain.symbols if s.name in constants}
        self.steps = [[(s.kind, s.value.xreplace(known)) for s in chain.base]]
        for row in chain.rows:
            if chain.convention == "standard":
                self.steps.append([("Rz", row.theta), ("Tz", row.d), ("Tx", row.a), ("Rx", row.alpha)])
            else:
                self.steps.append([("Rx", row.alpha), ("Tx", row.a), ("Rz", row.theta), ("Tz", row.d)])
            self.steps[-1] = [(kind, sympy.sympify(value).xreplace(known)) for kind, value in self.steps[-1]]
        self.steps.append([(s.kind, s.value.xreplace(known)) for s in chain.tool])

    def at(self, q) -> list:
        """[pose of frame 0, 1, …, n, the end frame] for joint values q."""
        values = dict(zip(self.chain.joint_variables, q))
        pose, out = np.eye(4), []
        for group in self.steps:
            for kind, value in group:
                pose = pose @ _step(kind, float(value.xreplace(values)))
            out.append(pose)
        return out[:-1] + [out[-1]]  # out[0] is frame 0 (after the base), out[n + 1] the end

    def axis(self, poses, joint: int):
        """(a point on the axis of `joint`, its direction)."""
        pose = poses[joint - 1] if self.chain.convention == "standard" else poses[joint]
        return pose[:3, 3], pose[:3, 2]


def _step(kind: str, value: float) -> np.ndarray:
    m = np.eye(4)
    if kind[0] == "T":
        m["xyz".index(kind[1]), 3] = value
        return m
    c, s = np.cos(value), np.sin(value)
    i, j = [(1, 2), (2, 0), (0, 1)]["xyz".index(kind[1])]
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def _meet(line, other):
    """The point of `line` nearest `other`."""
    (p, d), (q, e) = line, other
    w, cosine = q - p, d @ e
    return p + d * ((w @ d - (w @ e) * cosine) / (1 - cosine * cosine))


def _flat(v, up):
    return v - (v @ up) * up


def _truths(kind: str, frames: Frames, q) -> dict:
    """{word: whether the geometry makes it true, or None when it cannot tell} for arm `kind` at q."""
    chain, poses = frames.chain, frames.at(q)
    n, axis = chain.n, lambda j: frames.axis(poses, j)
    end = poses[-1][:3, 3]
    base, up = axis(1)
    wrist = _meet(axis(n), axis(n - 1)) if n >= 6 else end  # a wrist centre; the UR's axes 5 and 6 meeting
    truths = {}
    if kind in ("puma560", "stanford", "ur5"):  # the arm's plane right or left of the line from axis 1 to the wrist
        s, across = axis(2)
        truths["shoulder left"] = np.cross(wrist - s, across * (across @ (wrist - s))) @ up
    if kind in ("inline6", "spatial3r", "asokan_dh_example", "iiwa7"):  # axes 1 and 2 meet: frame 1's x axis says front
        point = end if kind == "asokan_dh_example" else wrist
        truths["shoulder front"] = _flat(poses[1][:3, 0], up) @ _flat(point - base, up)
    if kind in ("finger_rrr", "irb140"):  # axis 2 off axis 1: its side is the front
        s, across = axis(2)
        apart = _flat(s - base, up)
        truths["shoulder front"] = (apart - (apart @ across) * across) @ _flat(wrist - base, up)
    if kind in ("puma560", "inline6", "spatial3r", "finger_rrr", "irb140"):
        # the elbow above the line from the shoulder to the wrist, the line drawn going forward: the way the
        # wrist lies from axis 1 (where axes 1 and 2 meet, from the shoulder)
        s, across = axis(2)
        reach, bend, out = (v - (v @ across) * across for v in (wrist - s, axis(3)[0] - s, wrist - base))
        ahead = _flat(out, up) / np.linalg.norm(_flat(out, up))
        truths["elbow up"] = (bend @ up) * (reach @ ahead) - (reach @ up) * (bend @ ahead)
    if kind in ("ur5", "asokan_dh_example", "pitch_arm"):
        # the elbow left of the line from the shoulder to axis 4, seen with axis 1 up and frame 1's x axis
        # to the right (the wrist can lie on either side of axis 1 within a branch)
        s = axis(2)[0]
        toward_viewer = np.cross(_flat(poses[1][:3, 0], up), up)
        truths["elbow up"] = np.cross(axis(4)[0] - s, axis(3)[0] - s) @ toward_viewer
    if kind in ("planar2r", "planar3r", "pratihar_2r", "fourbar_left", "scara", "scara_spong"):
        revolute = [j for j, row in enumerate(chain.rows, 1) if row.joint == "R"]
        point = axis(revolute[2])[0] if len(revolute) > 2 else end  # the wrist: the axis after the elbow
        left = np.cross(point - base, axis(2)[0] - base) @ up  # seen from above: the elbow left of the line
        truths["lefty" if kind.startswith("scara") else "elbow up"] = left
    if kind in ("stanford", "cylindrical_wrist", "cylindrical_rpp", "rps_leg"):
        slide = [j for j, row in enumerate(chain.rows, 1) if row.joint == "P"][-1]
        truths["slide forward"] = q[slide - 1]  # the slide's frame starts where it crosses the axis before it
    if FLIP in WORDS[kind]:
        b = n - 1  # the wrist's middle axis
        truths["wrist not flipped"] = np.cross(axis(b - 1)[1], axis(b + 1)[1]) @ axis(b)[1]
    return {word: None if abs(value) < TINY else bool(value > 0) for word, value in truths.items()}


def _check(kind, chain, result, rng, count=6, free=()):
    """Every branch's name says one word of each of the arm's pairs, the words the geometry gives
    at `count` random poses; `free`: joints given to evaluate, as --free values are."""
    constants = sample_constants(chain)
    frames = Frames(chain, constants)
    names = [branch.name for branch in result.branches]
    assert len(set(names)) == len(names), names
    pairs = WORDS[kind]
    for branch in names:  # each name: one word of each pair, nothing else
        parts = branch.split(", ")
        assert len(parts) == len(pairs) and all(sum(p in pair for p in parts) == 1 for pair in pairs), branch
    checked = 0
    for q in random_joints(chain, rng, count):
        pose = frames.at(q)[-1]
        names_of = [v.name for v in chain.joint_variables]
        given = {name: q[names_of.index(name)] for name in free}
        for branch, found in zip(names, result.evaluate(pose, **given)):
            if np.isnan(found).any():
                continue
            joints = np.array(q, dtype=float)  # the free joints as given, the others as found
            joints[[names_of.index(v.name) for v in result.joint_variables]] = found
            reached = frames.at(joints)[-1]  # the branch reaches the pose (an arm of < 6 joints: its point)
            assert np.allclose(reached, pose, atol=1e-8) if chain.n >= 6 else np.allclose(reached[:3, 3], pose[:3, 3])
            for first, truth in _truths(kind, frames, joints).items():
                if truth is None:
                    continue
                second = next(pair[1] for pair in pairs if pair[0] == first)
                assert (first in branch.split(", ")) == truth and (second in branch.split(", ")) == (not truth), \
                    (kind, branch, first, joints)
                checked += 1
    assert checked > 0


@pytest.mark.parametrize("name", sorted(set(WORDS) - {"irb140", "iiwa7", "pitch_arm"}))
def test_every_word_of_every_branch_is_what_the_arm_does(name):
    chain = load(name)
    _check(name, chain, chain.ik(), np.random.default_rng(12))


def test_a_four_joint_arm_says_elbow_up_or_down_though_its_wrist_reaches_over_the_back(tmp_path):
    # The waist comes from the tool's orientation, so within a branch the wrist point lies in front of
    # axis 1 at some poses and behind it at others: the words are the way the arm bends.
    path = tmp_path / "pitch.yaml"
    path.write_text(PITCH_ARM)
    chain = load(str(path))
    _check("pitch_arm", chain, chain.ik(), np.random.default_rng(4), count=12)


def test_a_redundant_arm_with_a_free_joint_has_its_words_checked_too():
    chain = load("iiwa7")
    _check("iiwa7", chain, chain.ik(free=["theta_3"]), np.random.default_rng(7), free=["theta_3"])


def test_the_pumas_eight_branches_are_every_combination_of_the_three_choices():
    names = {branch.name for branch in load("puma560").ik().branches}
    assert names == {f"shoulder {s}, elbow {e}, wrist {w}" for s in ("left", "right") for e in ("up", "down")
                     for w in ("flipped", "not flipped")}


HEADS = {"shoulder left": "shoulder right/left: ", "shoulder right": "shoulder right/left: ",
         "shoulder front": "shoulder front/back: ", "shoulder back": "shoulder front/back: ",
         "elbow up": "elbow up/down: ", "elbow down": "elbow up/down: ", "lefty": "righty/lefty: ",
         "righty": "righty/lefty: ", "slide forward": "slide forward/back: ", "slide back": "slide forward/back: ",
         "wrist not flipped": "wrist not flipped/flipped: ", "wrist flipped": "wrist not flipped/flipped: "}


@pytest.mark.parametrize("name", ["puma560", "scara", "stanford", "ur5", "spatial3r", "planar2r", "finger_rrr"])
def test_each_word_printed_is_defined_once_where_the_method_is_said(name):
    result = load(name).ik()
    said = result.json()["method"].split("branch names: ")[1]
    used = {"+√/−√: " if part.endswith("√") else HEADS[part]
            for branch in result.branches for part in branch.name.split(", ")}
    for head in set(HEADS.values()) | {"+√/−√: "}:
        assert said.count(head) == (head in used), (name, head, said)


@pytest.mark.skipif(not UR10.exists(), reason="example-robot-data is not installed")
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_an_imported_ur10_says_the_same_words_as_the_ur5(convention):
    from dhsym import import_urdf

    chain = import_urdf(UR10, None, "tool0", convention).robot
    _check("ur5", chain, chain.ik(), np.random.default_rng(10))


@pytest.mark.skipif(not IRB140.exists() or importlib.util.find_spec("xacro") is None,
                    reason="rtb-data or xacro is not installed")
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_an_imported_irb140_with_its_shoulder_offset_has_every_word(convention):
    from dhsym import import_urdf

    chain = import_urdf(IRB140, None, "tool0", convention).robot
    _check("irb140", chain, chain.ik(), np.random.default_rng(140))


@pytest.mark.parametrize("name", ["stanford", "cylindrical_rpp", "cylindrical_wrist", "rps_leg"])
def test_a_slide_that_runs_backwards_is_said_and_its_branches_come_last(name):
    # Stanford's 8 branches are 4 physical ones: the other 4 put d3 < 0. The method line says so
    # (measured, not assumed: the slide's variable has the word's sign at every pose measured),
    # and the branches a real arm can take are listed first.
    out = run_dhsym("ik", name, "--width", "200").ok()
    names = re.findall(r"^Branch \d+: (.*)$", out, re.MULTILINE)
    half = len(names) // 2
    assert len(names) >= 2
    assert all("slide forward" in n for n in names[:half]) and all("slide back" in n for n in names[half:])
    assert "where the slide runs backwards (its joint variable < 0" in out
