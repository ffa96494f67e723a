"""A robot's joint limits where inverse kinematics is printed: the line `dhsym ik` adds for a robot
with limits (which branch is within them depends on the target, so the symbolic solution states
them), their JSON, and, at a target in numbers (`dhsym ik --numeric`), the joints of each solution
that are outside them. A revolute angle is within its limits when a whole turn brings it there
(dhsym.inverse.joint_limits).

>>> import dhsym
>>> from dhsym.printing.render import text_printer
>>> arm = dhsym.load("planar2r").replace(joint_limits=[(-sympy.pi, sympy.pi / 2), (0, sympy.Rational(5, 2))])
>>> limits_sentence(arm, text_printer(arm).doprint)
'Joint limits (the robot file’s): θ1\xa0∈\xa0[−180°,\xa090°], θ2\xa0∈\xa0[0,\xa02.5].'
>>> limits_json(arm)
{'theta_1': ['-pi', 'pi/2'], 'theta_2': ['0', '5/2']}
"""
from __future__ import annotations

import sympy


def limits_sentence(robot, show, variables=None) -> str:
    """`Joint limits (the robot file’s): θ1 ∈ [−160°, 160°], …` for the joints among `variables`
    (symbols; all by default) that have limits; `show` writes a symbol as the output does. Each
    joint's limits are joined by no-break spaces (a line breaks between joints, not inside one)."""
    said = [f"{show(row.variable)}\u00a0∈\u00a0[{_value(lower, row.joint)},\u00a0{_value(upper, row.joint)}]"
            for row, (lower, upper) in _limited(robot, variables)]
    return f"Joint limits (the robot file’s): {', '.join(said)}." if said else ""


def limits_json(robot, variables=None) -> dict:
    """{joint variable's name: [lower, upper]}, exact, each readable by `sympy.sympify`."""
    return {row.variable.name: [str(lower), str(upper)] for row, (lower, upper) in _limited(robot, variables)}


def outside_limits(robot, names, solutions) -> list:
    """For each solution (rows of joint values, joints named `names` in order), the names of the
    joints outside their limits; [] for each when the robot has no limits."""
    if not robot.joint_limits:
        return [[] for _ in solutions]
    import numpy

    from ..inverse.codegen_limits import joint_limit_lists
    from ..inverse.joint_limits import joint_limits_outside

    symbols = {symbol.name: symbol for symbol in robot.chain.joint_variables}
    lower, upper, revolute = map(numpy.array, joint_limit_lists(robot.chain, robot.joint_limits,
                                                                [symbols[name] for name in names]))
    outside = joint_limits_outside(numpy.asarray(solutions, dtype=float).reshape(-1, len(names)), lower, upper,
                                   revolute)
    return [[name for name, out in zip(names, row) if out] for row in outside]


def _limited(robot, variables):
    rows = robot.chain.rows
    pairs = robot.joint_limits or [None] * len(rows)
    return [(row, pair) for row, pair in zip(rows, pairs)
            if pair is not None and (variables is None or row.variable in variables)]


def _value(value, joint: str) -> str:
    """A limit as a person reads it: whole degrees for an angle that is one, else the number."""
    degrees = value * 180 / sympy.pi
    if joint == "R" and value != 0 and degrees.is_Integer:
        return f"{degrees}°".replace("-", "−")
    text = str(value) if value.is_Integer else f"{float(value):.6g}"
    return text.replace("-", "−")
