"""Joint limits in robot files: a joint row's optional `limits: [lower, upper]`, the least and
greatest value of its joint variable, read with the safe parser and checked where they stand.

    joints:
      - {joint: R, alpha: 0, a: 0, d: 0, theta: theta_1, limits: [-160deg, 160deg]}
      - {joint: P, alpha: 0, a: 0, d: d_2, theta: 0, limits: [0, 0.5]}

A revolute joint's limits are angles (radians, `pi/2`, or degrees, `160deg`), of the variable
itself: with `theta: theta_2 - pi/2` they bound θ2, not θ2 − π/2; a range may be wider than a
turn (±266°). A prismatic joint's are lengths. Limits are numbers: a joint variable or another
symbol has no place in them. (Not to be confused with dhsym.cli.limits, the size limits of output.)

>>> from dhsym.io.robotfile import load_robot_text
>>> robot = load_robot_text('''convention: standard
... joints: [{joint: R, theta: q_1, d: 0, a: 1, alpha: 0, limits: [-pi/2, 170deg]}]''', "arm.yaml")
>>> robot.joint_limits
((-pi/2, 17*pi/18),)
>>> load_robot_text('''convention: standard
... joints: [{joint: R, theta: q_1, d: 0, a: 1, alpha: 0, limits: [1, -1]}]''', "arm.yaml")
Traceback (most recent call last):
dhsym.errors.UserError: arm.yaml:2:64: joint row 1 limits: the lower limit 1 is above the upper limit -1; \
write [lower, upper]
"""
from __future__ import annotations

import sympy
import yaml

from ..errors import UserError
from .suspicious import looks_like_degrees
from .yamlhints import node_kind

ROW_KEY = "limits"
FORM = "[lower, upper] (the least and the greatest value of the joint variable)"


def read_joint_limits(reader, top: dict, chain) -> tuple:
    """The robot file's joint limits, a (lower, upper) pair or None per joint, () when no row has
    any; `reader` is the robot-file reader (dhsym.io.robotfile), `chain` the chain of its rows."""
    row_nodes = reader.sequence(top["joints"][1], "joints") if "joints" in top else []
    limits = []
    for number, (node, row) in enumerate(zip(row_nodes, chain.rows), 1):
        items = {key.value: value for key, value in node.value if key.value == ROW_KEY}
        limits.append(_pair(reader, items[ROW_KEY], f"joint row {number} limits", row, chain.joint_variables)
                      if ROW_KEY in items else None)
    return tuple(limits) if any(limits) else ()


def _pair(reader, node: yaml.Node, what: str, row, variables) -> tuple:
    if not isinstance(node, yaml.SequenceNode):
        raise UserError(f"{what}: must be {FORM}, not {node_kind(node)}", reader.where(node))
    entries = node.value
    if len(entries) != 2:
        raise UserError(f"{what}: must be {FORM}, two values, not {len(entries)}", reader.where(node))
    lower, upper = (_value(reader, entry, what, side, row, variables)
                    for entry, side in zip(entries, ("lower", "upper")))
    if lower > upper:
        raise UserError(f"{what}: the lower limit {lower} is above the upper limit {upper}; write [lower, upper]",
                        reader.where(entries[0]))
    if row.joint == "R" and looks_like_degrees(lower) and looks_like_degrees(upper):
        reader.warn(node, f"{what}: [{lower}, {upper}] is taken as radians; write [{lower}deg, {upper}deg] if you "
                    "meant degrees")
    return lower, upper


def _value(reader, node: yaml.Node, what: str, side: str, row, variables) -> sympy.Expr:
    """One limit: a real number; a prismatic joint's has no π and no degrees."""
    value, reading = reader.read(node, f"{what} {side}", table=False)
    named = sorted(value.free_symbols, key=str)
    moving = [symbol for symbol in named if symbol in variables]
    if moving:
        raise UserError(f"{what}: {moving[0]} is a joint variable; a limit is a number, the {side} bound of "
                        f"{row.variable}", reader.where(node))
    if named:
        raise UserError(f"{what}: the {side} limit must be a number, not {value}; give {named[0]} its value here",
                        reader.where(node))
    if not value.is_real:
        raise UserError(f"{what}: the {side} limit {value} is not a real number", reader.where(node))
    angles = [where for _, where, inside_trig in reading.units if not inside_trig]
    if row.joint == "P" and angles:
        raise UserError(f"{what}: joint {row.variable} slides, so its limits are lengths, not angles", angles[0])
    return value
