"""What `dhsym ik --numeric` shows: a target pose, the joint values that made it (given, or a
sample configuration), the elements of the target replaced by given numbers, and every real
solution there, with whether the joints that made it are among them.

The sample configuration turns the joints to 0.3, −0.4, 0.5, −0.6, … rad (a slide to a fifth of
the arm's size): a pose in general position, where no two solutions meet; joint values of zero
often put an arm in a singular pose, whose solutions are not isolated.

>>> import dhsym
>>> from dhsym.inverse.numeric.solver import numeric_inverse
>>> puma = dhsym.load("puma560")
>>> found = answer(numeric_inverse(puma.chain, sample=puma.sample, name=puma.name))
>>> len(found.solutions), found.among
(8, 4)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy

from ...errors import UserError
from ..solution import TARGET_NAMES

ROTATION = 1e-6  # a target whose rotation part is further than this from a rotation is refused
SAME = 1e-6


@dataclass(frozen=True)
class Answer:
    """`inverse` (NumericInverse); `joints` {name: value} that make the target (before
    `replaced` {element name: value} replaced some of its elements); `target` (4, 4); the real
    `solutions` (k, n); `among`: the position of the joints in `solutions`, else None;
    `singular`: the joints are a singular configuration (their neighbours are solutions too)."""

    inverse: object
    joints: dict
    replaced: dict
    target: numpy.ndarray
    solutions: numpy.ndarray
    among: int | None
    singular: bool


def sample_configuration(arm) -> dict:
    """{joint variable: value}: 0.3, −0.4, 0.5, … rad, a slide a fifth of the arm's size (two digits)."""
    values = {}
    for k, (name, kind, slope) in enumerate(zip(arm.variables, arm.kinds, arm.slopes)):
        turn = (-1) ** k * (k + 3) / 10
        values[name] = turn if kind == "R" else float(f"{0.2 * arm.scale / abs(slope):.2g}")
    return values


def answer(inverse, joints=None, replaced=None) -> Answer:
    """Every real solution at the pose of `joints` ({name: number}; the others from the sample
    configuration), with the target's elements in `replaced` ({"px": 0.5, ...}) put in."""
    values = {**sample_configuration(inverse.arm), **{name: float(v) for name, v in (joints or {}).items()}}
    q = numpy.array([values[name] for name in inverse.joint_variables])
    target = numpy.array(inverse.pose(q))
    replaced = {name: float(value) for name, value in (replaced or {}).items()}
    for name, value in replaced.items():
        position = TARGET_NAMES.index(name)
        target[position // 4, position % 4] = value
    _check_rotation(target[:3, :3])
    given = {name: values[name] for name in inverse.free_variables}
    solutions = inverse.solutions(target, **given)
    among = _position_of(q, solutions, inverse.arm.kinds) if not replaced else None
    return Answer(inverse, values, replaced, target, solutions, among, not replaced and inverse.singular(q))


def _position_of(q, solutions, kinds):
    for number, solution in enumerate(solutions):
        difference = solution - q
        for k, kind in enumerate(kinds):
            if kind == "R":
                difference[k] = (difference[k] + numpy.pi) % (2 * numpy.pi) - numpy.pi
        if numpy.abs(difference).max() < SAME:
            return number
    return None


def _check_rotation(rotation) -> None:
    off = float(numpy.abs(rotation.T @ rotation - numpy.eye(3)).max())
    if off > ROTATION or numpy.linalg.det(rotation) < 0:
        raise UserError(f"--pose: the target's r11 … r33 are not a rotation (RᵀR differs from the identity by "
                        f"{off:.2g}, det R = {numpy.linalg.det(rotation):.3g}); replace its rotation elements "
                        "together, or only px, py, pz")
