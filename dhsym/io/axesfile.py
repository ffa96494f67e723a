"""The geometric form of a robot file: `axes:` (joint type, a point and a direction per joint,
at the zero configuration, in the base frame) plus `tool:` (the tool frame at the zero
configuration, as steps from the base frame) instead of `joints:`. The DH table in the file's
`convention` is derived by dhsym.geometry.frames; joint variables are `q_1..q_n` unless an axis
names its own with `var:`. At most 24 axes, as for `joints:`; a point is made of numbers and
constants (a joint variable there would move the axis), each of at most MAX_TERMS terms when
multiplied out, counted before any work (the frame assignment simplifies sums and products of
them). When the file writes decimals, the
table shows decimals: values that are not exact decimals are rounded to 15 significant digits
and the notes say so (see dhsym.geometry.rounding).

>>> from dhsym.io.robotfile import load_robot_text
>>> robot = load_robot_text('''
... convention: standard
... axes:
...   - {joint: R, point: [0, 0, 0], direction: [0, 0, 1]}
...   - {joint: R, point: [l_1, 0, 0], direction: [0, 0, 1]}
... tool: [{Tx: l_1 + l_2}]
... ''', "arm.yaml")
>>> [(row.theta, row.d, row.a, row.alpha) for row in robot.chain.rows]
[(q_1, 0, l_1, 0), (q_2, 0, l_2, 0)]
"""
from __future__ import annotations

import sympy

from ..core.numbers import decimal_text
from ..core.size import expanded_terms, rough_count
from ..core.transforms import product
from ..errors import UserError
from ..geometry.exact import is_zero_vector, unit
from ..geometry.frames import assign_frames
from ..geometry.lines import JointAxis
from ..geometry.rounding import rounding_note
from .expr import Reading, parse_expression, real_symbol

AXIS_KEYS = ("joint", "point", "direction", "var")
MAX_TERMS = 40  # of a point's coordinate or a tool step multiplied out: (l_1 + l_2 + l_3 + l_4)^4 has 35
_JOINT_TYPES = {"r": "R", "revolute": "R", "p": "P", "prismatic": "P"}


def axes_chain(reader, top: dict, convention: str):
    """The chain of an `axes:` robot file and a sentence on the values rounded (else ""); `reader`
    is the robot-file reader (it places errors)."""
    for key in ("joints", "base"):
        if key in top:
            raise UserError(f"{key}: cannot be used with axes: (the axes are given in the base frame)",
                            reader.where(top[key][0]))
    if "tool" not in top:
        raise UserError("axes: needs tool: too, the tool frame at the zero configuration as steps from the base",
                        reader.where(top["axes"][0]))
    axes_node = top["axes"][1]
    nodes = reader.sequence(axes_node, "axes")
    if not nodes:
        raise UserError("axes is empty; a robot needs at least one joint", reader.where(axes_node))
    if len(nodes) > reader.max_joints:
        raise UserError(f"{len(nodes)} axes; dhsym handles at most {reader.max_joints}", reader.where(axes_node))
    axes, variables, points = [], [], []
    for number, node in enumerate(nodes, 1):
        axis, variable, point_node = _axis(reader, node, number)
        if variable in variables:
            raise UserError(f"axis {number} var: {variable} is already the variable of axis "
                            f"{variables.index(variable) + 1}", reader.where(node))
        axes.append(axis)
        variables.append(variable)
        points.append(point_node)
    for number, (axis, point_node) in enumerate(zip(axes, points), 1):
        moving = sorted((axis.point.free_symbols & set(variables)), key=str)
        if moving:
            raise UserError(f"axis {number} point: {moving[0]} is a joint variable; the axes are given at the zero "
                            "configuration, in numbers and constants", reader.where(point_node))
    tool_steps = reader.steps(top["tool"][1], "tool", set(variables))
    for number, step in enumerate(tool_steps, 1):
        _refuse_long(step.value, f"tool step {number} {step.kind}", reader.where(top["tool"][1]))
    try:
        assignment = assign_frames(axes, product(tool_steps), convention, variables,
                                   decimals=reader.reading.places > 0)
    except UserError as error:
        raise UserError(error.message, error.where or reader.where(axes_node)) from None
    places = [len(decimal_text(r.value).partition(".")[2]) for r in assignment.roundings if r.value.is_Rational]
    reader.reading.absorb(Reading(places=max(places, default=0)))  # the table shows the rounded values as decimals
    return assignment.chain(), rounding_note(assignment.roundings)


def _axis(reader, node, number: int):
    what = f"axis {number}"
    items = reader.mapping(node, what, AXIS_KEYS)
    for key in ("joint", "point", "direction"):
        if key not in items:
            raise UserError(f"{what} is missing {key!r}", reader.where(node))
    joint_node = items["joint"][1]
    kind = _JOINT_TYPES.get(reader.text(joint_node, f"{what} joint").strip().lower())
    if kind is None:
        raise UserError(f"{what} joint: must be R (revolute) or P (prismatic), not {joint_node.value!r}",
                        reader.where(joint_node))
    point = _triple(reader, items["point"][1], f"{what} point")
    direction_node = items["direction"][1]
    direction = _triple(reader, direction_node, f"{what} direction")
    if any(not c.is_number for c in direction):
        raise UserError(f"{what} direction: must be numbers, not symbols", reader.where(direction_node))
    if is_zero_vector(direction):
        raise UserError(f"{what} direction: has zero length", reader.where(direction_node))
    variable = _variable(reader, items["var"][1], what) if "var" in items else real_symbol(f"q_{number}")
    return JointAxis(kind, point, unit(direction)), variable, items["point"][1]


def _variable(reader, node, what: str) -> sympy.Symbol:
    """The joint variable `var:` names, as the rest of the file reads that name (θ₁ is θ_1, as
    in a point); a constant, a function or a word that is not a name is refused."""
    name = reader.text(node, f"{what} var").strip()
    try:
        value = parse_expression(name)
    except UserError:
        value = None
    if value is not None and value.has(sympy.pi):
        raise UserError(f"{what} var: {name!r} is the constant π, not a name; call the variable q_1 or "
                        "theta_1, for example", reader.where(node))
    if not isinstance(value, sympy.Symbol):
        raise UserError(f"{what} var: {name!r} is not a name a robot file can use for a joint variable; call "
                        "it q_1 or theta_1, for example", reader.where(node))
    return value


def _triple(reader, node, what: str) -> sympy.Matrix:
    values = reader.sequence(node, what)
    if len(values) != 3:
        raise UserError(f"{what} must be a list of 3 values [x, y, z], not {len(values)}", reader.where(node))
    triple = sympy.Matrix([reader.expression(value, f"{what}") for value in values])
    for value, value_node in zip(triple, values):
        _refuse_long(value, what, reader.where(value_node))
    return triple


def _refuse_long(value: sympy.Expr, what: str, where) -> None:
    """A UserError for a value that multiplies out to more than MAX_TERMS terms, from a count made
    before any work: the frame assignment simplifies sums and products of such values.

    >>> _refuse_long(sympy.sympify("(l_1 + l_2 + l_3 + l_4)^16"), "axis 2 point", "arm.yaml:4:30")
    Traceback (most recent call last):
    dhsym.errors.UserError: arm.yaml:4:30: axis 2 point: this value would multiply out to about 969 terms, more than \
the 40 that dhsym's frame assignment takes; name it as a constant (a symbol such as l_1) and give its value in the \
robot file's sample
    """
    terms = expanded_terms(value)
    if terms > MAX_TERMS:
        raise UserError(f"{what}: this value would multiply out to {rough_count(terms)} terms, more than the "
                        f"{MAX_TERMS} that dhsym's frame assignment takes; name it as a constant (a symbol such as "
                        "l_1) and give its value in the robot file's sample", where)
