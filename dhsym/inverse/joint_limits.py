"""Joint limits applied to inverse-kinematics branches, numpy only: which joints of a branch are
outside their limits, the branches within them, and the branch nearest a configuration. The
module `dhsym ik --format python` writes for a robot with limits holds this code too
(dhsym.inverse.codegen_limits copies it), so keep it to numpy and free of dhsym's imports.

A revolute joint turns by whole turns to the same place: an angle outside its limits is within
them when a multiple of 2π brings it there (atan2's 3.0 is the joint's −3.28 when the limits are
[−4.6, 0]), and that value is the one returned. `lower`, `upper` are arrays (n,), −inf and inf
for a joint without limits; `revolute` says which joints turn.

>>> import numpy
>>> Q = numpy.array([[3.0, 0.2], [0.5, 0.9], [numpy.nan, numpy.nan]])
>>> lower, upper, revolute = numpy.array([-4.6, -1.0]), numpy.array([0.0, 0.5]), numpy.array([True, False])
>>> within_joint_limits(Q, lower, upper, revolute).round(4)
array([[-3.2832,  0.2   ],
       [    nan,     nan],
       [    nan,     nan]])
>>> joint_limits_outside(Q, lower, upper, revolute)[1].tolist()
[True, True]
>>> nearest_branch(Q, numpy.array([0.4, 1.0]), revolute).tolist()
[0.5, 0.9]
"""
import numpy

LIMIT_TOLERANCE = 1e-9  # a value this far beyond a limit (rounding) is at the limit


def _moved_into_limits(Q, lower, upper, revolute):
    """Q with each revolute angle moved by whole turns to the least value ≥ lower where it is not
    within its limits already."""
    Q = numpy.array(Q, dtype=float)
    inside = (Q >= lower - LIMIT_TOLERANCE) & (Q <= upper + LIMIT_TOLERANCE)
    turnable = revolute & numpy.isfinite(lower)
    with numpy.errstate(invalid="ignore"):
        turned = numpy.where(numpy.isfinite(lower), lower + numpy.remainder(Q - lower, 2 * numpy.pi), Q)
    return numpy.where(~inside & turnable, turned, Q)


def joint_limits_outside(Q, lower, upper, revolute):
    """A boolean array shaped as Q: True for each joint value no whole turn brings within its
    limits (False for NaN, a branch that does not exist)."""
    moved = _moved_into_limits(Q, lower, upper, revolute)
    return (moved < lower - LIMIT_TOLERANCE) | (moved > upper + LIMIT_TOLERANCE)


def within_joint_limits(Q, lower, upper, revolute):
    """Q (B, n) or (N, B, n) with every branch that has a joint outside its limits set to NaN,
    and revolute angles moved by whole turns into their limits where that takes them there."""
    moved = _moved_into_limits(Q, lower, upper, revolute)
    outside = joint_limits_outside(Q, lower, upper, revolute).any(axis=-1)
    moved[outside] = numpy.nan
    return moved


def nearest_branch(Q, q_current, revolute):
    """The branch of Q (B, n), or of each pose of Q (N, B, n), nearest the joint values
    `q_current` (n,): the least sum of squared differences, revolute angles compared modulo 2π;
    NaN where no branch exists."""
    Q = numpy.asarray(Q, dtype=float)
    difference = Q - numpy.asarray(q_current, dtype=float)
    wrapped = numpy.remainder(difference + numpy.pi, 2 * numpy.pi) - numpy.pi
    difference = numpy.where(revolute, wrapped, difference)
    with numpy.errstate(invalid="ignore"):
        distance = numpy.where(numpy.isnan(difference).any(axis=-1), numpy.inf, (difference ** 2).sum(axis=-1))
    best = numpy.argmin(distance, axis=-1)
    chosen = numpy.take_along_axis(Q, best[..., None, None], axis=-2)[..., 0, :]
    found = numpy.isfinite(numpy.take_along_axis(distance, best[..., None], axis=-1))
    return numpy.where(found, chosen, numpy.nan)
