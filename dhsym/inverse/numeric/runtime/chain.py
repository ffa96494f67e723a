"""A serial chain in numbers, many configurations at once: its pose, its body Jacobian, Newton's
method on the pose and the damped least-squares solver for the solution nearest a seed.

The chain is X0 J1(u1) X1 J2(u2) … Jn(un) Xn: constant transforms X (the DH rows' fixed steps,
the base and the tool, in numbers) between joint motions J, each a turn about or a slide along z
by the joint's amount u (an angle or a length). numpy only: this file's text goes into the
module that `dhsym ik --format python` writes for an arm solved numerically.

>>> import numpy
>>> frames = numpy.stack([numpy.eye(4)] * 3)                         # a planar 2R arm: a1 = 1, a2 = 0.5
>>> frames[1, 0, 3], frames[2, 0, 3] = 1.0, 0.5
>>> pose(frames, "RR", numpy.array([0.0, numpy.pi / 2]))[:2, 3].round(6).tolist()
[1.0, 0.5]
"""
import numpy

Z = numpy.array([0.0, 0.0, 1.0])


def joint_motion(kind, amount):
    """The 4×4 motion of a joint (kind "R": a turn about z; "P": a slide along z) for each amount."""
    amount = numpy.asarray(amount)
    motion = numpy.zeros(amount.shape + (4, 4), dtype=amount.dtype if amount.dtype.kind == "c" else float)
    motion[..., 0, 0] = motion[..., 1, 1] = motion[..., 2, 2] = motion[..., 3, 3] = 1.0
    if kind == "R":
        cosine, sine = numpy.cos(amount), numpy.sin(amount)
        motion[..., 0, 0], motion[..., 0, 1], motion[..., 1, 0], motion[..., 1, 1] = cosine, -sine, sine, cosine
    else:
        motion[..., 2, 3] = amount
    return motion


def rigid_inverse(transform):
    """The inverse of rigid transforms (..., 4, 4): the transposed rotation, the origin moved back."""
    out = numpy.zeros(transform.shape, dtype=transform.dtype)
    rotation_t = numpy.swapaxes(transform[..., :3, :3], -1, -2)
    out[..., :3, :3] = rotation_t
    out[..., :3, 3] = -numpy.einsum("...ij,...j->...i", rotation_t, transform[..., :3, 3])
    out[..., 3, 3] = 1.0
    return out


def pose(frames, kinds, amounts):
    """The chain's end pose (..., 4, 4) for joint amounts (..., n); frames is (n+1, 4, 4) or one set
    per configuration (..., n+1, 4, 4)."""
    result = frames[..., 0, :, :]
    for k, kind in enumerate(kinds):
        result = result @ joint_motion(kind, amounts[..., k]) @ frames[..., k + 1, :, :]
    return numpy.broadcast_to(result, amounts.shape[:-1] + (4, 4))


def pose_and_jacobian(frames, kinds, amounts):
    """(the end pose, the body Jacobian (..., 6, n): rows vx vy vz ωx ωy ωz in the end frame)."""
    count = len(kinds)
    after = frames[..., count, :, :]
    after = numpy.broadcast_to(after, amounts.shape[:-1] + (4, 4))
    jacobian = numpy.zeros(amounts.shape[:-1] + (6, count))
    for k in range(count - 1, -1, -1):  # `after`: the transform from joint k's moving frame to the end
        rotation_t = numpy.swapaxes(after[..., :3, :3], -1, -2)
        if kinds[k] == "R":
            jacobian[..., 3:, k] = rotation_t[..., :, 2]
            jacobian[..., :3, k] = numpy.einsum("...ij,...j->...i", rotation_t, numpy.cross(Z, after[..., :3, 3]))
        else:
            jacobian[..., :3, k] = rotation_t[..., :, 2]
        after = joint_motion(kinds[k], amounts[..., k]) @ after
        if k:
            after = frames[..., k, :, :] @ after
    return frames[..., 0, :, :] @ after, jacobian


def pose_error(reached, target):
    """The body twist (..., 6) that moves `reached` onto `target`, to first order."""
    step = rigid_inverse(reached) @ target
    turn = step[..., :3, :3]
    spin = 0.5 * numpy.stack([turn[..., 2, 1] - turn[..., 1, 2], turn[..., 0, 2] - turn[..., 2, 0],
                              turn[..., 1, 0] - turn[..., 0, 1]], axis=-1)
    return numpy.concatenate([step[..., :3, 3], spin], axis=-1)


def miss(reached, target):
    """How far a pose is from the target: the largest difference of their 3×4 elements."""
    return numpy.abs(reached[..., :3, :] - target[..., :3, :]).max(axis=(-1, -2))


def damped_step(jacobian, error, damping):
    """The joint step J⁺e of damped least squares: Jᵀ(J Jᵀ + λ² I)⁻¹ e, never singular for λ > 0."""
    square = jacobian @ numpy.swapaxes(jacobian, -1, -2)
    square = square + (damping ** 2)[..., None, None] * numpy.eye(6)
    return numpy.einsum("...ji,...j->...i", jacobian, numpy.linalg.solve(square, error[..., None])[..., 0])


def polish(frames, kinds, amounts, target, steps=20, enough=1e-14):
    """Newton's method on the pose from each start (K, n): (the amounts, how far each misses).
    A start stops as soon as it misses by less than `enough` (relative to the target's size); a
    damping far below the Jacobian's size keeps the step finite at a singular start."""
    amounts = numpy.array(amounts, dtype=float)
    missed = numpy.full(len(amounts), numpy.inf)
    frames = numpy.broadcast_to(frames, (len(amounts),) + frames.shape[-3:])
    active = numpy.arange(len(amounts))
    enough = enough * (1 + numpy.abs(target[..., :3, 3]).max(axis=-1))
    for step in range(steps + 1):
        reached, jacobian = pose_and_jacobian(frames[active], kinds, amounts[active])
        missed[active] = miss(reached, target[active])
        going = numpy.isfinite(missed[active]) & (missed[active] > enough[active])
        active, reached, jacobian = active[going], reached[going], jacobian[going]
        if step == steps or not len(active):
            break
        size = numpy.sqrt((jacobian ** 2).sum(axis=(-1, -2)) + 1e-300)
        amounts[active] += damped_step(jacobian, pose_error(reached, target[active]), 1e-7 * size)
    return amounts, missed


def nearest_amounts(frames, kinds, target, seed, limits=None, steps=200, tolerance=1e-12):
    """The joint amounts nearest `seed` that reach `target`, by damped least squares
    (Levenberg–Marquardt: the damping shrinks while the pose error does, grows when it does not);
    `limits` (n, 2), lower and upper amounts, keeps each joint within them. Returns (amounts, miss)."""
    amounts = numpy.array(seed, dtype=float)
    damping = numpy.full(amounts.shape[:-1], 1e-2)
    for _ in range(steps):
        reached, jacobian = pose_and_jacobian(frames, kinds, amounts)
        error = pose_error(reached, target)
        size = numpy.sqrt((error ** 2).sum(axis=-1))
        if numpy.all(size < tolerance):
            break
        trial = amounts + damped_step(jacobian, error, damping)
        if limits is not None:
            trial = numpy.clip(trial, limits[:, 0], limits[:, 1])
        better = numpy.sqrt((pose_error(pose(frames, kinds, trial), target) ** 2).sum(axis=-1)) < size
        amounts = numpy.where(better[..., None], trial, amounts)
        damping = numpy.where(better, damping / 3, damping * 4)
    return amounts, miss(pose(frames, kinds, amounts), target)


def wrapped(amounts, kinds):
    """Angles of revolute joints in [−π, π); slides as they are."""
    amounts = numpy.array(amounts, dtype=float)
    for k, kind in enumerate(kinds):
        if kind == "R":
            amounts[..., k] = numpy.remainder(amounts[..., k] + numpy.pi, 2 * numpy.pi) - numpy.pi
    return amounts

