"""Numeric poses of a chain's frames at given values: what pictures and loop closure need.

The numbers come from the same DH steps the algebra uses, so a picture is the formula evaluated.

>>> from dhsym.io.library import load
>>> poses = frame_poses(load("planar2r"), {"theta_1": 0, "theta_2": sympy.pi / 2})
>>> [(frame, pose[:2, 3].round(3).tolist()) for frame, pose in poses]
[(0, [0.0, 0.0]), (1, [0.5, 0.0]), (2, [0.5, 0.4])]
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy

from ..core.chain import Chain, plain
from ..core.numeric import NumericChain, origin
from ..core.robot import Robot
from ..errors import UserError
from ..io.expr import parse_expression


def frame_poses(robot: Robot, values=None) -> list[tuple]:
    """The numeric 4×4 pose of every frame of the chain (base, 0..n, tool as present) in the first frame.

    `values` maps symbols or their names to numbers (or to expression text such as "30deg").
    Missing constants come from the robot file's `sample`, missing joint variables are 0.

    >>> from dhsym.io.library import load
    >>> [f for f, _ in frame_poses(load("fourbar_right"), {"phi_1": 0})]
    ['base', 0, 1, 'tool']
    """
    return skeleton(robot.chain, resolve_values(robot, values)).poses


def resolve_values(robot: Robot, values=None) -> dict:
    """Every symbol of the robot's chain mapped to a float: given, else its file's sample (constants)
    or 0 (joints).

    >>> from dhsym.io.library import load
    >>> sorted((s.name, v) for s, v in resolve_values(load("planar2r"), {"theta_1": "90deg"}).items())
    [('a_1', 0.5), ('a_2', 0.4), ('theta_1', 1.5707963267948966), ('theta_2', 0.0)]
    """
    if not isinstance(robot, Robot):
        raise TypeError(f"a robot is drawn, not a {type(robot).__name__}; a plain chain is Robot(chain)")
    sample = {str(symbol): value for symbol, value in robot.sample.items()}
    chain = robot.chain
    symbols = {s.name: s for s in chain.symbols}
    given = {}
    for key, value in (values or {}).items():
        name = key.name if isinstance(key, sympy.Symbol) else str(key)
        if name not in symbols:
            raise UserError(f"{name} is not a symbol of this robot; its symbols are {', '.join(sorted(symbols))}")
        given[name] = as_number(value, name)
    variables = {v.name for v in chain.joint_variables}
    resolved, missing = {}, []
    for name, symbol in symbols.items():
        if name in given:
            resolved[symbol] = given[name]
        elif name in variables:
            resolved[symbol] = 0.0
        elif name in sample:
            resolved[symbol] = as_number(sample[name], name)
        else:
            missing.append(name)
    if missing:
        raise UserError(f"no value for {', '.join(sorted(missing))}; give a number for each "
                        "(the robot file's sample does not have one)")
    return resolved


def as_number(value, name: str) -> float:
    """A float from a number or from expression text ("30deg"); `name` is for the error message.

    >>> as_number("90deg", "theta_1")
    1.5707963267948966
    """
    if isinstance(value, str):
        value = parse_expression(value)
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise UserError(f"value of {name} must be a number, not {value}") from None
    if not np.isfinite(number):
        raise UserError(f"value of {name} must be a finite number")
    return number


@dataclass
class Skeleton:
    """What a picture needs: frame poses, the link polyline and where the joints are."""

    poses: list  # (frame, 4×4 pose)
    ground: list  # points from the first frame to frame 0 (the fixed base steps)
    links: list  # points from frame 0 to the last frame, through the corner between d and a
    joints: list  # (kind "R" or "P", point)


def skeleton(chain: Chain, numbers: dict) -> Skeleton:
    """The numeric picture of `chain` at `numbers` (a float for every symbol: `resolve_values`),
    from core.numeric."""
    q = [numbers[v] for v in plain(chain).joint_variables]
    numeric = NumericChain(chain, numbers)
    walk = numeric.walk(q)  # (frame, the poses after each step that leads to it)
    poses = [(frame, np.array(after[-1])) for frame, after in walk]
    points = [np.array(origin(after[-1])) for _, after in walk]  # each frame's origin
    zero = 1 if chain.base else 0  # where frame 0 is in `walk`
    ground = points[:2] if chain.base else []
    links = [points[zero]]
    for _, after in walk[zero + 1:zero + 1 + chain.n]:
        # the corner after Tz(d) (standard) or Tx(a) (modified): a row with both d and a bends there
        links += [np.array(origin(after[1])), np.array(origin(after[-1]))]
    if chain.tool:
        links.append(points[-1])
    joints = [(row.joint, np.array(point)) for row, (point, _) in zip(chain.rows, numeric.axes(q))]
    return Skeleton(poses, ground, _without_repeats(links), joints)


def _without_repeats(points: list) -> list:
    kept = [points[0]]
    for point in points[1:]:
        if np.linalg.norm(point - kept[-1]) > 1e-12:
            kept.append(point)
    return kept


def is_planar(robot: Robot, values=None) -> bool:
    """True when every z axis is parallel to the first frame's z, all points lie in one plane
    normal to it, and no joint is prismatic (a prismatic joint would leave the plane).

    >>> from dhsym.io.library import load
    >>> is_planar(load("planar3r")), is_planar(load("scara")), is_planar(load("puma560"))
    (True, False, False)
    """
    return planar_skeletons([skeleton(robot.chain, resolve_values(robot, values))])


def planar_skeletons(skeletons) -> bool:
    """True when the skeletons (one picture may hold several chains) all lie in one plane."""
    points = np.array([p for s in skeletons for p in s.ground + s.links])
    tolerance = 1e-9 * max(1.0, extent(points))
    return all(
        abs(abs(pose[2, 2]) - 1) < 1e-9 for s in skeletons for _, pose in s.poses
    ) and np.ptp(points[:, 2]) < tolerance and all(kind == "R" for s in skeletons for kind, _ in s.joints)


def extent(points: np.ndarray) -> float:
    """The largest side of the points' bounding box, the scale a picture is drawn to."""
    return float(np.max(np.ptp(points, axis=0))) if len(points) else 0.0
