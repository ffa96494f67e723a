"""Every real solution of an arm at many poses: the elimination's candidates (one or two ways of
reading the loop, chosen once per arm), each polished by Newton's method on the pose, kept when
it reaches the pose, and each solution kept once.

`arm` is a dict: `frames` (n+1, 4, 4) and `kinds` ("RRPRRR") of the chain X0 J1 X1 … Jn Xn;
`slopes` (n,), each joint's amount per unit of its variable (±1 as a rule: θ2 − π/2 turns by θ2);
`free`, the positions of joints given as parameters (a redundant arm's --free); `variants`, the
ways of reading the loop; `scale`, the arm's size; `size`, the most solutions a pose has;
`tolerance`, how near a solution's pose must be to the target. numpy only: this file's text goes
into the module `dhsym ik --format python` writes for an arm solved numerically.

Two copies of a solution are one (the nearer kept, here the first), each pose's in joint order:

>>> rows, values = numpy.array([0, 0, 0]), numpy.array([[0.5, 1.0], [-3.0, 2.0], [0.5 + 1e-9, 1.0]])
>>> distinct(rows, values, "RR", 1, 3, 1.0)[0].tolist()
[[-3.0, 2.0], [0.5, 1.0], [nan, nan]]
"""
import numpy

from .chain import joint_motion, polish, wrapped
from .elimination import candidates

CHUNK = 2048  # poses solved together: bounds the memory of the 24 × 24 eigenproblems
SAME = 1e-6  # two solutions closer than this (radians, or lengths in units of the arm's size) are one


def reduced(arm, free_amounts):
    """The chain of the six unknown joints: (frames (M, 7, 4, 4), their kinds); a free joint's
    motion at its given amount joins the constant transforms around it."""
    frames, kinds, free = arm["frames"], arm["kinds"], arm["free"]
    count = free_amounts.shape[0]
    current = numpy.broadcast_to(frames[0], (count, 4, 4))
    out, unknown = [], ""
    for k, kind in enumerate(kinds):
        if k in free:
            current = current @ joint_motion(kind, free_amounts[:, free.index(k)]) @ frames[k + 1]
        else:
            out.append(current)
            unknown += kind
            current = numpy.broadcast_to(frames[k + 1], (count, 4, 4))
    out.append(current)
    return numpy.stack(out, axis=1), unknown


def solve(arm, target, free_values):
    """Every real solution at each pose: (M, size, n) joint values (the free joints' given values in
    their columns), NaN after the last solution. target (M, 4, 4); free_values (M, number free)."""
    count = target.shape[0]
    out = numpy.full((count, arm["size"], len(arm["kinds"])), numpy.nan)
    for start in range(0, count, CHUNK):
        part = slice(start, start + CHUNK)
        out[part] = _solve_chunk(arm, target[part], free_values[part])
    return out


def _solve_chunk(arm, target, free_values):
    """The first reading of the loop at every pose; each further reading only at the poses where the
    roots so far did not each give a solution of their own (one failed, or repeated another): a
    lost solution may hide there."""
    slopes = numpy.asarray(arm["slopes"], dtype=float)
    free = list(arm["free"])
    frames, kinds = reduced(arm, free_values * slopes[free])
    rows, values, tried = found_by(arm, frames, target, kinds, arm["variants"][0])
    grid = distinct(rows, values, kinds, len(target), arm["size"], arm["scale"])
    roots = numpy.bincount(tried, minlength=len(target))
    for variant in arm["variants"][1:]:
        doubtful = numpy.nonzero(numpy.isfinite(grid[:, :, 0]).sum(axis=1) < roots)[0]
        if not len(doubtful):
            break
        more_rows, more, _ = found_by(arm, frames[doubtful], target[doubtful], kinds, variant)
        rows, values = numpy.concatenate([rows, doubtful[more_rows]]), numpy.concatenate([values, more])
        again = numpy.isin(rows, doubtful)
        grid[doubtful] = distinct(numpy.searchsorted(doubtful, rows[again]), values[again], kinds, len(doubtful),
                                  arm["size"], arm["scale"])
    unknown = [k for k in range(len(arm["kinds"])) if k not in free]
    full = numpy.full(grid.shape[:2] + (len(arm["kinds"]),), numpy.nan)
    full[:, :, unknown] = grid
    full[:, :, free] = numpy.where(numpy.isfinite(grid[:, :, :1]), free_values[:, None, :], numpy.nan)
    return full


def found_by(arm, frames, target, kinds, variant):
    """(the pose of each solution, its six joint values (K, 6), nearest copies first; the pose of
    every root tried) by one reading of the loop."""
    slopes = numpy.asarray(arm["slopes"], dtype=float)[[k for k in range(len(arm["kinds"])) if k not in arm["free"]]]
    rows, amounts = candidates(frames, target, kinds, variant, arm["scale"])
    amounts, missed = polish(frames[rows], kinds, amounts, target[rows])
    good = numpy.nonzero(missed < arm["tolerance"])[0]
    good = good[numpy.argsort(missed[good], kind="stable")]  # of two copies of a solution, the nearer is kept
    return rows[good], wrapped(amounts[good] / slopes, kinds), rows


def distinct(rows, values, kinds, count, size, scale):
    """The solutions of each pose, each once, in order of their joint values: (count, size, n),
    NaN-padded. `rows` names the pose of each solution."""
    order = numpy.argsort(rows, kind="stable")
    rows, values = rows[order], values[order]
    per_pose = numpy.bincount(rows, minlength=count)
    width = max(int(per_pose.max()) if len(rows) else 0, 1)
    slot = numpy.arange(len(rows)) - numpy.repeat(numpy.cumsum(per_pose) - per_pose, per_pose)
    grid = numpy.full((count, width, len(kinds)), numpy.nan)
    grid[rows, slot] = values
    apart = numpy.zeros((count, width, width))
    for k, kind in enumerate(kinds):
        difference = grid[:, :, None, k] - grid[:, None, :, k]
        if kind == "R":
            difference = numpy.remainder(difference + numpy.pi, 2 * numpy.pi) - numpy.pi
        else:
            difference = difference / scale
        apart = numpy.maximum(apart, numpy.abs(difference))
    earlier = numpy.tril(numpy.ones((width, width), dtype=bool), -1)  # [i, j]: j comes before i
    repeated = ((apart < SAME) & earlier[None]).any(axis=2)
    grid[repeated] = numpy.nan
    return _sorted(grid, size)


def _sorted(grid, size):
    """Each pose's solutions in order of joint 1, then joint 2, … (values rounded, so that the order
    does not hang on the last digits), the missing ones last; the first `size` of them."""
    order = numpy.broadcast_to(numpy.arange(grid.shape[1]), grid.shape[:2])
    for k in range(grid.shape[2] - 1, -1, -1):
        key = numpy.take_along_axis(grid[:, :, k], order, axis=1).round(9)
        order = numpy.take_along_axis(order, numpy.argsort(numpy.where(numpy.isnan(key), numpy.inf, key), axis=1,
                                                           kind="stable"), axis=1)
    grid = numpy.take_along_axis(grid, order[:, :, None], axis=1)
    if grid.shape[1] < size:
        grid = numpy.concatenate([grid, numpy.full((grid.shape[0], size - grid.shape[1], grid.shape[2]), numpy.nan)],
                                 axis=1)
    return grid[:, :size]
