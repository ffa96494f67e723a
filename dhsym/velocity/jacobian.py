"""The geometric Jacobian of a chain, built from its contracted frames.

Column i of the 6×n Jacobian (rows vx, vy, vz, ωx, ωy, ωz) of a point p is, for a revolute
joint i with axis z_i through p_i, ``[z_i × (p − p_i); z_i]``, and for a prismatic joint
``[z_i; 0]``. The axis of joint i is z_{i-1} in the standard convention and z_i in the
modified one.

Nothing is expanded and nothing is simplified afterwards; every entry comes from the
contracted frames, in the form a textbook derives it:

* for a joint that does not move frame k, the lever is ∂ᵏp/∂θ of the contracted position
  ᵏp (c1(a2 c2 + a3 c23 − d4 s23) gives −c1(a2 s2 + a3 s23 + d4 c23));
* otherwise z_i × (p − p_i) is split at a frame m between the axis and the point, Craig's
  way to ³J₆ for the PUMA: ``z × (p_m − p_i)`` is worked out in the axis frame, where z is
  (0, 0, 1) and the cross product is (−y, x, 0) of the contracted ⁱp_m, ``z × (p − p_m)`` in
  frame m; their sum is turned into frame k by the chain's rotations, block by block from the
  inside out and collected by each block's cos/sin (the contraction's own rule). The frame m
  that gives the shortest entries is kept, or the plain ᵏz × (ᵏp − ᵏp_i) when that is shorter.

>>> import dhsym
>>> arm = dhsym.load("planar2r").chain
>>> jacobian(arm)[:2, :]
Matrix([
[-a_1*sin(theta_1) - a_2*sin(theta_1 + theta_2), -a_2*sin(theta_1 + theta_2)],
[ a_1*cos(theta_1) + a_2*cos(theta_1 + theta_2),  a_2*cos(theta_1 + theta_2)]])
>>> jacobian(dhsym.load("puma560").chain, frame=3)[:3, 1]   # Craig's ³J₆, column 2
Matrix([
[a_2*sin(theta_3) - d_4],
[a_2*cos(theta_3) + a_3],
[                     0]])
"""
from __future__ import annotations

import sympy

from ..core.chain import Chain, Frame, plain
from ..core.estimate import estimated_size
from ..core.simplify import block_matrix, collect_by_trig, merge_steps, split_into_blocks
from ..core.size import length
from ..core.transforms import joint_axis_frame
from ..core.vectors import cross
from ..errors import UserError

ROWS = ("vx", "vy", "vz", "ωx", "ωy", "ωz")
ZERO = (sympy.Integer(0),) * 3


def jacobian(chain: Chain, frame: Frame | None = None, point: Frame | None = None,
             body: Frame | None = None) -> sympy.Matrix:
    """ᵏJ: the 6×n geometric Jacobian of frame `point` (default: the last frame), its origin's
    velocity and its angular velocity, expressed in `frame` (default: the first frame, base
    else 0). With `body`, the velocity is that of the point of frame `body` that is at the
    origin of `point` at this instant (a change of reference point: det J does not change).
    Frames are the chain's own, 0..n ("3" as text too); a robot's printed numbers are translated by
    its numbering first."""
    frame, point = chain_frames(chain, frame, point)
    body = point if body is None else chain.frame(body)
    columns = [column(chain, joint, frame, point, body) for joint in range(1, chain.n + 1)]
    return sympy.Matrix([[col[r] for col in columns] for r in range(6)])


def chain_frames(chain: Chain, frame: Frame | None, point: Frame | None) -> tuple[Frame, Frame]:
    """The chain's frames (0..n, "base", "tool") that `frame` and `point` name, checked; None is the
    first frame and the last."""
    frames = plain(chain).frames
    return (frames[0] if frame is None else chain.frame(frame)), (frames[-1] if point is None else chain.frame(point))


def jacobian_size(chain: Chain, frame, point) -> int:
    """Estimated nodes of ᵏJ, before it is built: the transform to the point plus one to each
    joint's axis (a general 8-link chain in frame 0: 203,000 estimated, 200,000 built)."""
    axes = (axis_frame(chain, joint) for joint in range(1, chain.n + 1))
    return estimated_size(chain, frame, point) + sum(estimated_size(chain, frame, axis) for axis in axes)


def axis_frame(chain: Chain, joint: int):
    """The frame whose z axis is the axis of `joint` (1..n): i − 1 (standard) or i (modified).

    >>> import dhsym
    >>> axis_frame(dhsym.load("planar2r").chain, 1), axis_frame(dhsym.load("puma560").chain, 1)
    (0, 1)
    """
    if not 1 <= joint <= chain.n:
        raise UserError(f"no joint {joint}; joints are 1..{chain.n}")
    return joint_axis_frame(chain.convention, joint)


def moves(chain: Chain, joint: int, point) -> bool:
    """Whether `joint` moves the frame `point`: frame i and every frame after it move with joint i."""
    return chain.frames.index(point) >= chain.frames.index(joint)


def column(chain: Chain, joint: int, frame, point, body=None) -> list:
    """The six entries of column `joint` of ᵏJ for the origin of `point`, moving with `body`."""
    return linear_part(chain, joint, frame, point, body) + angular_part(chain, joint, frame, point, body)


def linear_part(chain: Chain, joint: int, frame, point, body=None) -> list:
    """vx, vy, vz of column `joint`: z × (p − p_axis) (revolute) or z (prismatic)."""
    if not moves(chain, joint, point if body is None else body):
        return list(ZERO)
    if chain.rows[joint - 1].joint == "P":
        return [gain(chain, joint) * x for x in axis(chain, frame, joint)]
    if moves(chain, joint, point) and not moves(chain, joint, frame):
        return lever(chain, joint, frame, point)  # a derivative: the gain is in it already
    return [gain(chain, joint) * x for x in lever(chain, joint, frame, point)]


def angular_part(chain: Chain, joint: int, frame, point, body=None) -> list:
    """ωx, ωy, ωz of column `joint`: the joint axis z (revolute), zero (prismatic)."""
    if chain.rows[joint - 1].joint == "P" or not moves(chain, joint, point if body is None else body):
        return list(ZERO)
    return [gain(chain, joint) * x for x in axis(chain, frame, joint)]


def gain(chain: Chain, joint: int) -> sympy.Expr:
    """How fast the row's θ (revolute) or d (prismatic) changes with its variable: 1 for
    θ2 − π/2, −1 for a slide written d = −d3."""
    row = chain.rows[joint - 1]
    return derivative(row.theta if row.joint == "R" else row.d, row.variable)


def lever(chain: Chain, joint: int, frame, point) -> list:
    """z × (p − p_axis) in `frame`, the shortest of the ways that apply:

    * when the joint does not move `frame`, it is ∂ᵏp/∂θ of the contracted position ᵏp, which
      keeps the contraction's grouping (c1(a2 c2 + a3 c23 − d4 s23) gives −c1(a2 s2 + …));
    * split at the frame nearest to `frame` between axis and point (`split_lever`);
    * the cross product ᵏz × (ᵏp − ᵏp_axis) of contracted vectors, short when the axis is
      parallel to z_k (the planar arm in its tool frame: l1 s23 + l2 s3).
    """
    variables = frozenset(chain.joint_variables)
    if moves(chain, joint, point) and not moves(chain, joint, frame):
        position = chain.transform(frame, point)[:3, 3]
        return [collect_by_trig(derivative(x, chain.joint_variables[joint - 1]), variables) for x in position]
    axis = axis_frame(chain, joint)
    offset = chain.transform(frame, point)[:3, 3] - chain.transform(frame, axis)[:3, 3]
    candidates = [[collect_by_trig(x, variables) for x in cross(chain.transform(frame, axis)[:3, 2], offset)]]
    for pivot in pivots(chain, axis, frame, point):
        turned = rotate(chain, frame, pivot, lever_in(chain, axis, pivot, point))
        candidates.append([collect_by_trig(x, variables) for x in turned])
    return min(candidates, key=length)


def pivots(chain: Chain, axis, frame, point) -> list:
    """Where to split the lever: the frame nearest to `frame` between the axis and the point and
    its neighbours, the axis frame and the one after it (the end of a run of parallel axes, as
    frame 3 for the PUMA's joint 2), and the point: a few, so that long chains stay fast."""
    order = chain.frames.index
    first, last = order(axis), order(point)
    nearest = min(max(order(frame), first), last)
    wanted = {first, first + 1, nearest - 1, nearest, nearest + 1, last}
    return [chain.frames[k] for k in sorted(wanted) if first <= k <= last]


def lever_in(chain: Chain, axis, pivot, point) -> list:
    """z × (p − p_axis) in frame `pivot` (between the axis frame and the point), in two parts:
    z × (p_m − p_axis) worked out in the axis frame, where z = (0, 0, 1) and the cross product
    is (−y, x, 0) of the contracted ᵃp_m, and z × (p − p_m) in frame m itself.

    >>> import dhsym
    >>> lever_in(dhsym.load("puma560").chain, 2, 3, 6)    # Craig's ³J₆, column 2
    [a_2*sin(theta_3) - d_4, a_2*cos(theta_3) + a_3, 0]
    """
    near = far = ZERO
    if pivot != axis:
        x, y, _ = chain.transform(axis, pivot)[:3, 3]
        near = rotate(chain, pivot, axis, (-y, x, 0))
    if pivot != point:
        far = cross(chain.transform(pivot, axis)[:3, 2], chain.transform(pivot, point)[:3, 3])
    variables = frozenset(chain.joint_variables)
    return [collect_by_trig(a + b, variables) for a, b in zip(near, far)]


def derivative(expr, variable):
    """∂expr/∂variable by the rules a student uses (sums, products, cos, sin, powers), keeping
    the nesting: c1(a2 c2 + a3 c23) gives −c1(a2 s2 + a3 s23). SymPy's diff does the same but
    spends most of its time on assumptions; anything unusual is left to it.

    >>> t1, t2, a = sympy.symbols("theta_1 theta_2 a", real=True)
    >>> derivative(sympy.cos(t1) * (a * sympy.cos(t2) + sympy.sin(t1 + t2)), t2)
    (-a*sin(theta_2) + cos(theta_1 + theta_2))*cos(theta_1)
    """
    if not expr.has(variable):
        return sympy.Integer(0)
    if expr == variable:
        return sympy.Integer(1)
    if expr.is_Add:
        return sympy.Add(*[derivative(term, variable) for term in expr.args])
    if expr.is_Mul:
        factors = expr.args
        return sympy.Add(*[sympy.Mul(*factors[:k], derivative(f, variable), *factors[k + 1:])
                           for k, f in enumerate(factors) if f.has(variable)])
    if isinstance(expr, (sympy.cos, sympy.sin)):
        inner = derivative(expr.args[0], variable)
        outer = -sympy.sin(expr.args[0]) if isinstance(expr, sympy.cos) else sympy.cos(expr.args[0])
        return outer * inner
    if expr.is_Pow and expr.exp.is_Integer:
        return expr.exp * expr.base ** (expr.exp - 1) * derivative(expr.base, variable)
    return sympy.diff(expr, variable)


def rotate(chain: Chain, target, source, vector) -> tuple:
    """ᵗR_s·v, turned block by block from the inside out like the contraction multiplies a
    transform, each product collected by that block's cos/sin: a vector, not a 4×4 matrix.

    >>> import dhsym
    >>> rotate(dhsym.load("puma560").chain, 0, 3, (0, 0, 1))   # z3 in frame 0
    (-sin(theta_1), cos(theta_1), 0)
    """
    vector = tuple(sympy.sympify(x) for x in vector)
    if target == source:
        return vector
    variables = frozenset(chain.joint_variables)
    steps = [step for step in chain.steps(target, source) if step.is_rotation]
    for block in reversed(split_into_blocks(merge_steps(steps))):
        turn = block_matrix(block)
        atoms = {s for step in block.body if step.kind == "Rz" for s in step.value.free_symbols} & variables
        vector = tuple(collect_by_trig(sympy.Add(*[turn[r, m] * vector[m] for m in range(3)
                                                  if turn[r, m] != 0 and vector[m] != 0]), atoms) for r in range(3))
    return vector


def axis(chain: Chain, frame, joint: int) -> list:
    """The axis of `joint` in `frame`: z of its axis frame, turned into `frame`."""
    return list(rotate(chain, frame, axis_frame(chain, joint), (0, 0, 1)))
