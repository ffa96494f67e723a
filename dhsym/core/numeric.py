"""Forward kinematics in floats: the pose of every frame of a chain at numbers for its symbols.

dhsym's one numeric evaluator. Pictures (plot), the table checker (geometry.compare), the
Jacobian's numeric checks (velocity.geometry: wrist centre, singular poses) and through them the
inverse kinematics' structure tests all walk the chain's own elementary steps (the ones the algebra
multiplies), so a number is the formula evaluated. The constants go in exactly (rationals, π/2) and
are fixed once; each call then costs a few multiplications per step. Plain floats, no numpy: the
layers below the pictures never load it. Many configurations at once: give each joint's values as a
numpy array (all of one length m), and every entry of the poses is an array of m values.

>>> import sympy, dhsym
>>> arm = NumericChain(dhsym.load("planar2r").chain, {"a_1": sympy.Rational(1, 2), "a_2": 0.4})
>>> [(frame, [round(x, 3) for x in origin(pose)]) for frame, pose in arm.poses([0, sympy.pi / 2])]
[(0, [0.0, 0.0, 0.0]), (1, [0.5, 0.0, 0.0]), (2, [0.5, 0.4, 0.0])]
>>> [round(x, 3) for x in arm.axes([0, sympy.pi / 2])[1][0]]   # joint 2 turns about z_1
[0.5, 0.0, 0.0]
>>> import numpy as np
>>> np.array(arm.end([np.array([0, np.pi / 2]), np.array([np.pi / 2, 0])]))[:2, 3].round(3).tolist()
[[0.5, 0.0], [0.4, 0.9]]
"""
from __future__ import annotations

import math
from itertools import pairwise
from typing import Callable, Mapping, Sequence

import sympy

from .chain import Chain, plain
from .transforms import as_expr, joint_axis_frame, turned_plane

Pose = list  # 4×4 floats, row by row: the rotation's columns are the frame's x, y, z axes, column 3 its origin


class NumericChain:
    """`chain` with numbers for its constants (keys are symbols or their names, values exact or
    floats; joint variables among them are ignored), ready to be evaluated at joint values q."""

    def __init__(self, chain: Chain, constants: Mapping):
        named = {getattr(key, "name", str(key)): value for key, value in constants.items()}
        self.variables = tuple(plain(chain).joint_variables)
        fixed_symbols = chain.symbols - set(self.variables)
        missing = sorted(s.name for s in fixed_symbols if s.name not in named)
        if missing:
            raise ValueError(f"no number for {', '.join(missing)}")
        fixed = {s: as_expr(named[s.name]) for s in fixed_symbols}  # numbers only: text is refused
        self.convention = chain.convention
        self.frames = tuple(chain.frames)
        self._first_joint_frame = 1 if chain.base else 0  # the position of frame 0 among `frames`
        self._segments = [[(step.is_rotation, step.axis, _amount(step.value.xreplace(fixed), self.variables))
                           for step in chain.steps(before, after)] for before, after in pairwise(self.frames)]

    def walk(self, q: Sequence) -> list[tuple[object, list[Pose]]]:
        """(frame, the poses after each step that leads to it) for every frame, in the first frame;
        the last pose of each is the frame's own, the first frame's is the identity."""
        q = self._floats(q)
        zero = sum(x * 0.0 for x in q)  # 0.0, or an array of zeros when q holds arrays
        pose = [[zero + (r == c) for c in range(4)] for r in range(4)]
        out = [(self.frames[0], [_copy(pose)])]
        for frame, steps in zip(self.frames[1:], self._segments):
            after = []
            for turns, axis, amount in steps:
                _apply(pose, turns, axis, amount(q))
                after.append(_copy(pose))
            out.append((frame, after or [_copy(pose)]))
        return out

    def poses(self, q: Sequence) -> list[tuple[object, Pose]]:
        """(frame, pose) of every frame (base, 0..n, tool as present), in the first frame."""
        return [(frame, after[-1]) for frame, after in self.walk(q)]

    def end(self, q: Sequence) -> Pose:
        """The pose of the last frame in the first: base (else 0) → tool (else n)."""
        return self.walk(q)[-1][1][-1]

    def axes(self, q: Sequence) -> list[tuple[list, list]]:
        """(a point, the unit direction) of each joint's axis in the first frame: the origin and z of
        the frame that `joint_axis_frame` names (the direction is z itself, whatever way the joint
        variable enters its row)."""
        poses = [pose for _, pose in self.poses(q)]
        out = []
        for joint in range(1, len(self.variables) + 1):
            pose = poses[self._first_joint_frame + joint_axis_frame(self.convention, joint)]
            out.append((origin(pose), [pose[r][2] for r in range(3)]))
        return out

    def _floats(self, q: Sequence) -> list:
        if len(q) != len(self.variables):
            raise ValueError(f"{len(q)} joint values for {len(self.variables)} joints")
        return [x.astype(float) if hasattr(x, "astype") else float(x) for x in q]


def origin(pose: Pose) -> list[float]:
    """The position column of a pose."""
    return [pose[r][3] for r in range(3)]


def _amount(value: sympy.Expr, variables: tuple) -> Callable[[list], float]:
    """q ↦ the step's angle or length. Steps are constants or affine in one joint variable
    (θ2 − π/2, −d3) as a rule: those cost a multiplication; anything else is compiled."""
    moving = [k for k, v in enumerate(variables) if v in value.free_symbols]
    if not moving:
        constant = float(value)
        return lambda q: constant
    if len(moving) == 1:
        k = moving[0]
        intercept, term = value.as_independent(variables[k], as_Add=True)
        slope, rest = term.as_coeff_Mul()
        if rest == variables[k]:
            slope, intercept = float(slope), float(intercept)
            return lambda q: intercept + slope * q[k]
    function = sympy.lambdify(variables, value, modules="math")
    return lambda q: float(function(*q)) if isinstance(q[0], float) else _vectorized(function)(*q)


def _apply(pose: Pose, turns: bool, axis: int, amount: float) -> None:
    """pose ← pose · (the step): a rotation mixes two columns, a translation moves the origin."""
    if turns:
        i, j = turned_plane(axis)
        c, s = (math.cos(amount), math.sin(amount)) if isinstance(amount, float) else _array_cos_sin(amount)
        for row in pose[:3]:
            row[i], row[j] = c * row[i] + s * row[j], c * row[j] - s * row[i]
    else:
        for row in pose[:3]:
            row[3] = row[3] + amount * row[axis]  # a new value: copies made earlier share the old one


def _array_cos_sin(angles) -> tuple:
    import numpy  # loaded already: the caller passed numpy arrays

    return numpy.cos(angles), numpy.sin(angles)


def _vectorized(function):
    import numpy  # loaded already: the caller passed numpy arrays

    return numpy.vectorize(function, otypes=[float])


def _copy(pose: Pose) -> Pose:
    return [row[:] for row in pose]
