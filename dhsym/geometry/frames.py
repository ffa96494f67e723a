"""The DH frame-assignment algorithm, standard and modified, with a record of every step.

Input: the joint axes at the zero configuration (lines in the base frame, each pointing along
positive motion) and the tool pose. Output: the DH frames, the table, and the fixed base and
tool steps, so that base → tool equals the input for every joint value.

The rules, as the lectures teach them and as manufacturers' tables follow them:
- z of the frame on joint i's axis points along positive motion, so each DH variable equals
  the joint value (θi = qi + offset, no sign flip);
- x_i lies along the common normal of axes i and i+1: through the intersection point for
  intersecting axes, chosen so that d is zero for parallel ones, any normal for collinear ones;
  of its two senses the one closer to the previous x is taken, so offsets are zero where they
  can be (a negative a is fine);
- the tool's z line closes the chain: when it is collinear with the last joint axis, the last
  frame sits at the flange.

>>> from dhsym.geometry.exact import vector
>>> from dhsym.geometry.lines import JointAxis
>>> axes = [JointAxis("R", vector(0, 0, 0), vector(0, 0, 1)), JointAxis("R", vector(1, 0, 0), vector(0, 0, 1))]
>>> tool = sympy.eye(4); tool[0, 3] = 2
>>> result = assign_frames(axes, tool, "standard")
>>> [(r.theta, r.d, r.a, r.alpha) for r in result.chain().rows]
[(q_1, 0, 1, 0), (q_2, 0, 1, 0)]
>>> print(result.steps[0].why)
axis 1 and axis 2 are parallel: the normal is taken through the origin of frame 0, so that d is zero
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from ..core.chain import Chain, DHRow
from ..core.grid import ANGLE_STEP
from ..core.robot import Robot
from ..core.transforms import CONVENTIONS, Step, twist_row
from ..errors import UserError
from .exact import cross, dot, is_zero_vector, tidy_vector, unit
from .lines import JointAxis, distance_between, normal_feet, relation
from .rigid import angle, frame_pose, pose_steps, relative
from .rounding import Rounding, dh_label, fit, joined, rounding_note


@dataclass(frozen=True)
class NormalStep:
    """How x_i was found between axis i and axis i+1 (axis n+1 is the tool's z line)."""

    index: int  # i
    relation: str  # skew, intersecting, parallel, anti-parallel, collinear
    x: sympy.Matrix  # unit direction of x_i
    near_foot: sympy.Matrix  # where the normal leaves axis i
    far_foot: sympy.Matrix  # where it meets axis i+1
    why: str


@dataclass(frozen=True)
class Frame:
    """A DH frame at the zero configuration, in base coordinates."""

    label: str
    origin: sympy.Matrix
    x: sympy.Matrix
    z: sympy.Matrix

    @property
    def pose(self) -> sympy.Matrix:
        return frame_pose(self.origin, self.x, self.z)


@dataclass
class Assignment:
    """What the algorithm found: frames, the steps that placed them, the table and base/tool."""

    convention: str
    axes: list
    frames: list  # Frame 0..n
    steps: list  # NormalStep 1..n
    rows: list  # (joint, theta, d, a, alpha) with the joint variables in
    variables: list
    base: list
    tool: list
    roundings: list = field(default_factory=list)  # rounding.Rounding of each value rounded

    def chain(self) -> Chain:
        """The chain of the table found."""
        rows = [DHRow(joint, theta, d, a, alpha, variable)
                for (joint, theta, d, a, alpha), variable in zip(self.rows, self.variables)]
        return Chain(rows, self.convention, self.base, self.tool)

    def robot(self, **details) -> Robot:
        """The chain as a Robot with `details` (name, source, notes...); its notes end with a
        sentence on the values rounded, if any."""
        details["notes"] = joined(details.get("notes", ""), rounding_note(self.roundings))
        return Robot(self.chain(), **details)


def default_variables(count: int) -> list[sympy.Symbol]:
    return [sympy.Symbol(f"q_{i}", real=True) for i in range(1, count + 1)]


def assign_frames(axes: list[JointAxis], tool_pose: sympy.Matrix, convention: str,
                  variables: list | None = None, decimals: bool = True) -> Assignment:
    """Run the algorithm on joint axes (base coordinates, zero configuration) and a tool pose.
    The table's values are exact where a person writes them so, else rounded (see
    geometry.rounding); `decimals` says the input was written in decimals (a URDF is), so that
    surds and long fractions become decimals too."""
    if convention not in CONVENTIONS:
        raise UserError(f"unknown convention {convention!r}; use standard or modified")
    if not axes:
        raise UserError("a robot needs at least one joint axis")
    for number, axis in enumerate(axes, 1):
        if any(not c.is_number for c in axis.direction):
            raise UserError(f"joint {number}: the axis direction must be numbers, not symbols")
    variables = variables or default_variables(len(axes))
    tool_line = JointAxis("R", tool_pose[:3, 3], tool_pose[:3, 2], "tool")
    lines = list(axes) + [tool_line]
    reference = _base_reference(axes[0])
    steps, previous_x, previous_foot = [], reference, axes[0].foot_of(sympy.zeros(3, 1))
    for i in range(1, len(axes) + 1):
        step = _normal(i, lines[i - 1], lines[i], previous_x, previous_foot, last=i == len(axes))
        steps.append(step)
        previous_x, previous_foot = step.x, step.far_foot
    return _tabulate(convention, axes, steps, tool_pose, variables, decimals)


def _base_reference(first: JointAxis) -> sympy.Matrix:
    """The base x made perpendicular to axis 1 (else the base y): the sense x_1 should prefer."""
    for candidate in (sympy.Matrix([1, 0, 0]), sympy.Matrix([0, 1, 0])):
        along = candidate - dot(candidate, first.direction) * first.direction
        if not is_zero_vector(along):
            return unit(along)
    raise AssertionError("x and y cannot both be parallel to a unit vector")


def _prefer(x: sympy.Matrix, previous_x: sympy.Matrix) -> sympy.Matrix:
    """Of ±x, the sense that makes the smaller angle with the previous x (offsets zero where possible)."""
    return -x if dot(x, previous_x).is_negative else x


def _normal(i: int, axis: JointAxis, following: JointAxis, previous_x, previous_foot, last: bool) -> NormalStep:
    kind = relation(axis, following)
    name = "the tool's z line" if last else f"axis {i + 1}"
    pair = f"axis {i} and {name}"
    start = axis.foot_of(previous_foot)  # d is zero when the normal leaves axis i here
    if kind in ("skew", "intersecting"):
        near, far = normal_feet(axis, following)
        x = _prefer(unit(cross(axis.direction, following.direction)), previous_x)
        if kind == "intersecting":
            why = f"{pair} intersect: x_{i} is along their cross product, through the intersection point"
        else:
            why = (f"{pair} are skew: x_{i} is along their common normal, of length "
                   f"{distance_between(axis, following)}")
        return NormalStep(i, kind, x, near, far, why)
    if kind == "collinear":
        foot = following.point if last else start
        why = (f"{pair} are collinear: x_{i} keeps the direction of x_{i - 1}, "
               + ("the frame sits at the flange" if last else "the origin stays where it was (d zero)"))
        return NormalStep(i, kind, previous_x, foot, foot, why)
    far = following.foot_of(start)
    x = _prefer(unit(far - start), previous_x)
    x = previous_x if is_zero_vector(cross(x, previous_x)) else x  # same line: keep it exactly
    why = (f"{pair} are {kind}: the normal is taken through the origin of frame {i - 1}, so that d is zero")
    return NormalStep(i, kind, x, start, far, why)


def _tabulate(convention, axes, steps, tool_pose, variables, decimals) -> Assignment:
    """Frames from the normals, then the table rows, base and tool steps, fitted for writing."""
    n = len(axes)
    base_origin = axes[0].foot_of(sympy.zeros(3, 1))
    if convention == "standard":
        frames = [Frame("0", base_origin, steps[0].x, axes[0].direction)]
        z_after = [a.direction for a in axes[1:]] + [tool_pose[:3, 2]]
        frames += [Frame(str(s.index), s.far_foot, s.x, z) for s, z in zip(steps, z_after)]
    else:
        frames = [Frame("0", base_origin, steps[0].x, axes[0].direction)]
        frames += [Frame(str(s.index), s.near_foot, s.x, a.direction) for s, a in zip(steps, axes)]
    roundings: list = []

    def fitted(value, label: str, length: bool, written=None):
        written = written if written is not None else fit(value, decimals, length)
        if written is not value:
            roundings.append(Rounding(label, written, value))
        return written

    exact = [_row(convention, frames[i - 1], frames[i]) for i in range(1, n + 1)]
    base_steps, tool_steps = pose_steps(frames[0].pose), pose_steps(relative(frames[n].pose, tool_pose))
    turns = _z_turns(convention, exact, base_steps, tool_steps)
    written = dict(zip([place for place, _, _ in turns], _summing_to_grid(turns, decimals)))
    rows = []
    for i, values in enumerate(exact, 1):
        joint = axes[i - 1].joint
        moving = "theta" if joint == "R" else "d"
        values = {key: fitted(value, dh_label(convention, i, key, moving=key == moving), key in ("a", "d"),
                              written[i] if key == "theta" else None)
                  for key, value in values.items()}
        values[moving] = variables[i - 1] + values[moving]
        rows.append((joint, values["theta"], values["d"], values["a"], values["alpha"]))
    base = [Step(s.kind, fitted(s.value, f"base {s.kind}", s.kind[0] == "T", _turn(written, "base", s)))
            for s in base_steps]
    tool = [Step(s.kind, fitted(s.value, f"tool {s.kind}", s.kind[0] == "T", _turn(written, "tool", s)))
            for s in tool_steps]
    return Assignment(convention, list(axes), frames, steps, rows, list(variables), base, tool, roundings)


def _z_turns(convention: str, exact: list, base_steps: list, tool_steps: list) -> list:
    """(place, angle, twist from the z axis before) of each turn about a z axis along the chain:
    the base's when it turns about z alone, each row's θ constant (place: the row number), and the
    tool's first turn when it is about z; the twist is None where no z axis comes before."""
    base_turns = [step for step in base_steps if step.kind[0] == "R"]
    turns = [("base", base_turns[0].value, None)] if [s.kind for s in base_turns] == ["Rz"] else []
    for i, values in enumerate(exact):  # row i + 1's θ turns about the axis of joint i + 1; the twist before it
        twist = exact[twist_row(convention, i) - 1]["alpha"] if i else (0 if turns else None)
        turns.append((i + 1, values["theta"], twist))
    tool_turns = [step for step in tool_steps if step.kind[0] == "R"]
    if tool_turns and tool_turns[0].kind == "Rz":
        after = twist_row(convention, len(exact))  # the twist after the last joint's axis, where a row holds one
        turns.append(("tool", tool_turns[0].value, exact[after - 1]["alpha"] if after <= len(exact) else 0))
    return turns


def _turn(written: dict, place: str, step: Step):
    """The written angle of the base's or tool's turn about z, None for any other step."""
    return written.get(place) if step.kind == "Rz" else None


def _summing_to_grid(turns: list, decimals: bool) -> list:
    """The angles of `turns` (see _z_turns) as written: each fitted, except that where the turns
    about a run of parallel z axes add up to a multiple of π/12 (the forward kinematics prints
    their sum, as in cos(q2 + q3 + π/2)), a rounded one is written as that multiple less the others
    as written, so that the sum stays exact. An anti-parallel pair (twist π) subtracts instead.

    >>> from dhsym.geometry.rounding import written_text
    >>> thetas = [sympy.atan(sympy.Rational(221, 12)), sympy.atan(sympy.Rational(12, 221))]  # a sum of π/2
    >>> [written_text(theta) for theta in _summing_to_grid([(1, thetas[0], None), (2, thetas[1], 0)], True)]
    ['1.51655095372531', '-1.51655095372531 + pi/2']
    """
    written, exact_sum, written_sum, sign = [], sympy.Integer(0), sympy.Integer(0), 1
    for _, theta, twist in turns:
        if twist not in (0, sympy.pi):
            exact_sum, written_sum, sign = sympy.Integer(0), sympy.Integer(0), 1
        elif twist == sympy.pi:
            sign = -sign
        value = fit(theta, decimals)
        exact_sum += sign * theta
        if value is not theta and theta.is_number:
            total = fit(exact_sum, decimals)
            if total != 0 and (total / ANGLE_STEP).is_integer:
                value = sign * (total - written_sum)
        written_sum += sign * value
        written.append(value)
    return written


def _row(convention, before: Frame, after: Frame) -> dict:
    """One table row's constants (θ and d without the joint variable) from two consecutive
    frames, both at the zero configuration."""
    if convention == "standard":
        theta = angle(dot(before.x, after.x), dot(cross(before.x, after.x), before.z))
        d = dot(_foot_on_previous_z(before, after) - before.origin, before.z)
        a = dot(after.origin - before.origin, after.x)
        alpha = angle(dot(before.z, after.z), dot(cross(before.z, after.z), after.x))
    else:
        alpha = angle(dot(before.z, after.z), dot(cross(before.z, after.z), before.x))
        a = dot(after.origin - before.origin, before.x)
        theta = angle(dot(before.x, after.x), dot(cross(before.x, after.x), after.z))
        d = dot(after.origin - before.origin, after.z)
    return {"theta": theta, "d": d, "a": a, "alpha": alpha}


def _foot_on_previous_z(before: Frame, after: Frame) -> sympy.Matrix:
    """Where x_i (through the new origin) meets the previous z axis: the end of d_i."""
    return tidy_vector(after.origin - dot(after.origin - before.origin, after.x) * after.x)
