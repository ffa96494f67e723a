"""A robot in numbers for the numeric inverse kinematics: its chain of elementary steps, from the
first frame to the last, multiplied out into constant transforms X0 … Xn around the joint motions
(a turn about z or a slide along z by each joint's amount), as dhsym.inverse.numeric.runtime
uses it.

Every constant needs a number: the values given (`--set`), else the robot file's `sample:`; a
constant with neither is refused with the names that lack one.

>>> import dhsym
>>> arm = numeric_arm(dhsym.load("planar2r").chain, {"a_1": 1, "a_2": 0.5})
>>> arm.kinds, arm.slopes, arm.frames.shape
('RR', (1.0, 1.0), (3, 4, 4))
>>> numeric_arm(dhsym.load("planar2r").chain, {"a_1": 1}).kinds  # no sample values given
Traceback (most recent call last):
dhsym.errors.UserError: the numeric inverse kinematics needs numbers: the robot has no value for a_2; give it with \
--set a_2=… (or numbers in the table, or a sample: line in the robot file)
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy
import sympy

from ...core.chain import Chain, plain
from ...errors import UserError

_TURN_PLANE = {0: (1, 2), 1: (2, 0), 2: (0, 1)}


@dataclass(frozen=True)
class NumericArm:
    """`frames` (n+1, 4, 4) and `kinds` ("RRPRRR") of X0 J1 X1 … Jn Xn; `slopes`, each joint's
    amount per unit of its variable; `variables`, the joint variables' names; `constants`, the
    number used for each constant (by name); `scale`, the arm's size (the sum of its links'
    lengths), the unit of its slides and tolerances."""

    name: str
    convention: str
    frames: numpy.ndarray
    kinds: str
    slopes: tuple
    variables: tuple
    constants: dict
    scale: float

    def pose(self, values):
        """The end pose (4, 4) at joint values (n,) (or poses (N, 4, 4) at (N, n))."""
        from .runtime.chain import pose

        values = numpy.asarray(values, dtype=float)
        return numpy.array(pose(self.frames, self.kinds, values * numpy.asarray(self.slopes)))


def numeric_arm(chain: Chain, given=None, *, sample=None, name: str = "") -> NumericArm:
    """The chain in numbers; `given` maps constants (symbols or names) to numbers and takes
    precedence over `sample` (the robot file's sample values); `name`: the robot's, for messages."""
    chain = plain(chain)
    variables = list(chain.joint_variables)
    numbers = _numbers(chain, given or {}, sample or {}, name)
    frames, kinds, slopes, current, used = [], "", [], numpy.eye(4), []
    for step in chain.steps(chain.first_frame, chain.last_frame):
        value = step.value.xreplace(numbers)
        moving = [v for v in variables if v in value.free_symbols]
        if not moving:
            current = current @ _step_matrix(step.is_rotation, step.axis, value)
            continue
        slope, intercept = _affine(value, moving, step)
        if moving[0] in used or step.axis != 2:
            raise UserError(f"the numeric inverse kinematics needs each joint variable in one turn about or slide "
                            f"along z, not {step.kind}({step.value})")
        current = current @ _step_matrix(step.is_rotation, 2, intercept)
        used.append(moving[0])
        frames.append(current)
        kinds += "R" if step.is_rotation else "P"
        slopes.append(slope)
        current = numpy.eye(4)
    frames.append(current)
    if used != variables:  # a joint variable that moves nothing, or the rows out of order
        raise UserError("the numeric inverse kinematics needs each joint variable in its own row's step, in order")
    scale = sum(float(numpy.linalg.norm(frame[:3, 3])) for frame in frames) or 1.0
    return NumericArm(name, chain.convention, numpy.array(frames), kinds, tuple(slopes),
                      tuple(v.name for v in variables), {s.name: float(v) for s, v in numbers.items()}, scale)


def _numbers(chain: Chain, given, sample, name: str) -> dict:
    """{constant symbol: exact number}: the given values, else the sample values; refused when one lacks both."""
    named = {getattr(key, "name", str(key)): value for key, value in given.items()}
    sample = {s.name: v for s, v in sample.items()}
    constants = sorted(chain.symbols - set(chain.joint_variables), key=lambda s: s.name)
    missing = [s.name for s in constants if s.name not in named and s.name not in sample]
    if missing:
        example = " ".join(f"{name}=…" for name in missing[:3])
        raise UserError(f"the numeric inverse kinematics needs numbers: {name or 'the robot'} has no value for "
                        f"{', '.join(missing)}; give {'it' if len(missing) == 1 else 'them'} with --set {example} "
                        "(or numbers in the table, or a sample: line in the robot file)")
    return {s: sympy.nsimplify(named[s.name]) if s.name in named else sample[s.name] for s in constants}


def _affine(value, moving, step) -> tuple[float, float]:
    """(slope, intercept) of a step that moves with one joint variable: θ2 − π/2 is (1, −π/2)."""
    if len(moving) == 1:
        intercept, term = value.as_independent(moving[0], as_Add=True)
        slope, rest = term.as_coeff_Mul()
        if rest == moving[0] and not intercept.free_symbols and slope != 0:
            return _float(slope), intercept
    raise UserError(f"the numeric inverse kinematics needs each step to move with one joint variable, by a fixed "
                    f"amount per unit, not {step.kind}({step.value})")


def _float(value) -> float:
    number = complex(sympy.N(value, 30))
    if number.imag or not math.isfinite(number.real):
        raise UserError(f"the numeric inverse kinematics needs real numbers, not {value}")
    return number.real


def _step_matrix(turns: bool, axis: int, amount) -> numpy.ndarray:
    """A step's matrix in floats; cos and sin of an exact angle worked out exactly first (cos π/2 is 0, not 6e-17)."""
    matrix = numpy.eye(4)
    amount = sympy.sympify(amount)
    if turns:
        i, j = _TURN_PLANE[axis]
        cosine, sine = _float(sympy.cos(amount)), _float(sympy.sin(amount))
        matrix[i, i], matrix[i, j], matrix[j, i], matrix[j, j] = cosine, -sine, sine, cosine
    else:
        matrix[axis, 3] = _float(amount)
    return matrix
