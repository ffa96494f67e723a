"""The product-of-exponentials description of a DH robot (Lynch and Park, Modern Robotics,
section 4.1): the space-frame screw axes S_i = (ω_i, v_i) and the home pose M, symbolically,
and the joint axes of any chain at its zero configuration.

The screw axis of a joint is its axis at the zero configuration: ω the axis's direction and
v = p × ω for a point p on it. Both come from the joint's frame at q = 0, worked out by the
contraction that `fk` uses (so any chain that `fk` prints has its screws). A zero pose of at
most TIDY_MAX_NODES nodes (no entry past TIDY_MAX_ENTRY; every built-in robot, a general 3-link
chain) is simplified further with sympy.simplify, whose time grows fast with the size (a general
4-link chain's would take seconds, 6 links minutes); a larger one keeps the contracted form.

>>> from dhsym.io.library import load
>>> screws = screw_axes(load("planar2r").chain)
>>> screws.matrix.T
Matrix([
[0, 0, 1, 0,    0, 0],
[0, 0, 1, 0, -a_1, 0]])
>>> screws.home[:3, 3].T
Matrix([[a_1 + a_2, 0, 0]])
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain, DHRow, plain
from ..core.simplify import contract
from ..core.size import tree_size
from ..core.transforms import Step, joint_axis_frame
from ..core.vectors import cross
from ..errors import UserError
from .exact import tidy
from .lines import JointAxis

TIDY_MAX_NODES = 600  # nodes of all the joint frames' and the last frame's entries (a general 3-link chain: 445)
TIDY_MAX_ENTRY = 80  # nodes of the largest entry (one of 73 takes sympy.simplify a second)


@dataclass(frozen=True)
class Screws:
    """Screw axes as the columns of a 6×n matrix (ω over v) and the home pose M, in the first
    frame of the chain (base, else 0), with every joint variable zero."""

    matrix: sympy.Matrix
    home: sympy.Matrix


def zero_poses(chain: Chain) -> list[sympy.Matrix]:
    """The pose of each joint's frame at the zero configuration (the frame whose z is the
    joint axis: i−1 in standard DH, i in modified), then the last frame's pose (tool, else n)."""
    steps = zero_steps(chain)
    ends = [len(chain.base) + 4 * k for k in range(chain.n + 1)]  # where frames 0..n end in the steps
    frames = [contract(steps[:end], ()) for end in ends]
    joint_frames = [frames[joint_axis_frame(chain.convention, joint)] for joint in range(1, chain.n + 1)]
    poses = joint_frames + [contract(steps, ())]
    small = _small(poses)
    return [p.applyfunc(lambda e: sympy.simplify(e) if small and e.free_symbols else _numbers(e)) for p in poses]


def zero_steps(chain: Chain) -> list[Step]:
    """The chain's steps, base to tool, with every joint variable zero."""
    zero = {v: 0 for v in chain.joint_variables}
    links = [step for row in chain.rows for step in row.steps(chain.convention)]
    return [Step(step.kind, step.value.xreplace(zero)) for step in [*chain.base, *links, *chain.tool]]


def rate(row: DHRow) -> sympy.Expr:
    """How fast the row's θ (revolute) or d (prismatic) changes with its joint variable: ±1 as a rule."""
    return sympy.diff(row.theta if row.joint == "R" else row.d, row.variable)


def chain_axes(chain: Chain) -> tuple[list[JointAxis], sympy.Matrix]:
    """The joint axes at the zero configuration (base coordinates), each pointing along the
    joint's positive motion (d = −d3 moves along −z), and the tool pose."""
    poses = zero_poses(chain)
    axes = []
    for number, (row, pose) in enumerate(zip(chain.rows, poses), 1):
        sign = rate(row)
        if sign not in (1, -1):
            raise UserError(f"joint {number}: {row.variable} enters its row as {sign}·{row.variable}; only "
                            f"±{row.variable} has a joint axis of its own")
        axes.append(JointAxis(row.joint, pose[:3, 3], sign * pose[:3, 2], row.variable.name))
    return axes, poses[-1]


def screw_axes(chain: Chain) -> Screws:
    """S_i = (ω_i, −ω_i × p_i) for a revolute joint, (0, ω_i) for a prismatic one; and M."""
    poses = zero_poses(plain(chain))
    columns = []
    for row, pose in zip(chain.rows, poses):
        direction, point = rate(row) * pose[:3, 2], pose[:3, 3]
        if row.joint == "R":
            columns.append(list(direction) + [-x for x in cross(direction, point)])
        else:
            columns.append([0, 0, 0] + list(direction))
    small = _small(poses)  # the poses were simplified, and their products can be too
    matrix = sympy.Matrix(columns).T.applyfunc(lambda e: sympy.simplify(sympy.expand(e)) if small else _numbers(e))
    return Screws(matrix, poses[-1])


def exponential(screw: sympy.Matrix, q) -> sympy.Matrix:
    """e^{[S] q} as a 4×4 matrix (Rodrigues' formula; Modern Robotics eq. 3.88 and 3.51)."""
    omega, v = screw[:3, 0], screw[3:, 0]
    result = sympy.eye(4)
    if all(c == 0 for c in omega):
        result[:3, 3] = v * q
        return result
    w = sympy.Matrix([[0, -omega[2], omega[1]], [omega[2], 0, -omega[0]], [-omega[1], omega[0], 0]])
    rotation = sympy.eye(3) + sympy.sin(q) * w + (1 - sympy.cos(q)) * w * w
    result[:3, :3] = rotation
    result[:3, 3] = (sympy.eye(3) * q + (1 - sympy.cos(q)) * w + (q - sympy.sin(q)) * w * w) * v
    return result


def product_of_exponentials(screws: Screws, values) -> sympy.Matrix:
    """T(q) = e^{[S1] q1} ⋯ e^{[Sn] qn} M (Modern Robotics eq. 4.14)."""
    result = sympy.eye(4)
    for i, q in enumerate(values):
        result = result * exponential(screws.matrix[:, i], q)
    return result * screws.home


def _numbers(entry: sympy.Expr) -> sympy.Expr:
    """An entry without symbols in its short exact form (surds combined: (√2/4 + √6/4)(√2/4 − √6/4)
    is −1/4), else as it is; multiplying out numbers is cheap."""
    return entry if entry.free_symbols else tidy(entry)


def _small(poses: list) -> bool:
    """Whether sympy.simplify takes the zero pose's entries in moments (see the module)."""
    sizes = [tree_size(entry) for pose in poses for entry in pose[:3, :]]
    return sum(sizes) <= TIDY_MAX_NODES and max(sizes) <= TIDY_MAX_ENTRY
