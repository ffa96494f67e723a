"""Whether both roots of each two-root step reach the pose. An arm of fewer than six joints cannot
reach every target: its equations are more than its unknowns, and the search solves each joint
from some of them. What a branch must reach:

- an arm of three joints or fewer is a positioning arm, as a course teaches it: the elements its
  solution uses (the planar 2R's px, py; elbow up and down reach the same point, turned apart);
- from four joints on, the whole pose the arm was at. The PincherX 100 (a waist and three pitch
  joints) shows why: atan2(py, px) and atan2(−py, −px) both put the wrist in the arm's plane, and
  with the pitch mirrored both point the gripper the same way, but the second is upside down
  (turned by π about the gripper's axis): not the target.

A root that misses is found here in numbers, at a few generic poses: a branch that is real and
misses the pose, while the branch with that one sign flipped reaches it.

>>> import dhsym, sympy
>>> from dhsym.inverse.scan import Derivation
>>> from dhsym.inverse.derive import derive
>>> arm = dhsym.load("planar2r").chain
>>> t1, t2 = arm.joint_variables
>>> solution = derive(arm)
>>> (D, _), = solution.definitions
>>> target, stretch = sorted(solution.branches[0].values()[t1].args, key=lambda a: a.has(t2))  # θ1 = φ − ψ
>>> (y, x), stretch = target.args, -stretch
>>> s1, s2 = sympy.symbols("sigma_1 sigma_2", real=True)
>>> elbow = sympy.atan2(s1 * sympy.sqrt(1 - D**2), D)
>>> both = Derivation(assignments=[(t2, elbow), (t1, sympy.atan2(y, x) - stretch)], signs=[(s1, t2, "law")])
>>> wrong_root(arm, {}, solution.definitions, both, [t1, t2]) is None   # elbow up and down both reach
True
>>> turned = Derivation(assignments=[(t2, elbow), (t1, sympy.atan2(s2 * y, s2 * x) - stretch)],
...                     signs=[(s1, t2, "law"), (s2, t1, "one")])
>>> wrong_root(arm, {}, solution.definitions, turned, [t1, t2])   # θ1 + π points the arm away
theta_1
"""
from __future__ import annotations

from itertools import product

from ..core.chain import Chain, plain
from ..velocity.geometry import poses
from .fresh import reserved, target_symbols
from .witness import SEED, number_at, witness

SEEDS = (SEED, SEED + 1, SEED + 2)  # a wrong root is wrong at any generic pose; three spare a non-real one
POSE_JOINTS = 4  # from this many unknown joints on, a branch must give the whole pose
MISS = 1e-6  # the pose's elements are of order one (lengths of the robot's sample, rotations)


def wrong_root(chain: Chain, sample, definitions, derivation, unknowns):
    """The joint whose two roots do not both reach the pose (the first such, in the derivation's
    order), or None. `definitions` and `derivation.assignments` are computed in order, each sign
    σ = ±1; `unknowns` are the joint variables solved for (the rest are given); the poses are
    drawn with the constants of `sample` (the robot file's)."""
    chain = plain(chain)
    signs = [sigma for sigma, _, _ in derivation.signs]
    blamed = [(k, joint) for k, (_, joint, rule) in enumerate(derivation.signs) if rule != "quartic"]
    if not blamed:
        return None
    steps = list(definitions) + list(derivation.assignments)
    held = set().union(*(expression.free_symbols for _, expression in steps))
    targets = target_symbols(reserved(chain))
    used = [k for k, t in enumerate(targets) if t in held or len(unknowns) >= POSE_JOINTS]
    for seed in SEEDS:
        numbers = witness(chain, sample, seed)
        target = [float(numbers[t]) for t in targets]
        given = {s: float(x) for s, x in numbers.items() if s not in unknowns}
        reached = {choice: _reaches(chain, steps, {**given, **dict(zip(signs, choice))}, target, used)
                   for choice in product((1, -1), repeat=len(signs))}
        for k, joint in blamed:
            for choice, reaches in reached.items():
                flipped = choice[:k] + (-choice[k],) + choice[k + 1:]
                if reaches is False and reached[flipped]:
                    return joint
    return None


def _reaches(chain, steps, values: dict, target: list, used: list) -> bool | None:
    """Whether the branch's joint values give the elements `used` (indices, row by row) of `target`
    (12 numbers); None where the branch has no real value at this pose. An arm of fewer than six
    joints reaches what its solution uses (a planar 2R its px, py), the rest following from that."""
    for name, expression in steps:
        value = number_at(expression, values)
        if value is None:
            return None
        values[name] = value
    rotation, origin = poses(chain, {s: values[s] for s in chain.symbols})[chain.last_frame]
    reached = [x for r in range(3) for x in (*rotation[r], origin[r])]
    return all(abs(reached[k] - target[k]) <= MISS * max(1.0, abs(target[k])) for k in used)
