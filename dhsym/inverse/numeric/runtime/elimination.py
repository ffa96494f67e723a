"""Every solution of a closed loop of six joints at once, by elimination (Raghavan and Roth, 1993;
Manocha and Canny, 1994): the loop J1 L1 J2 L2 … J6 L6 = I, whose last link L6 holds the target,
is cut into J3 L3 J4 L4 J5 L5 = L2⁻¹ J2⁻¹ L1⁻¹ J1⁻¹ L6⁻¹ J6⁻¹. A point p and a direction l on
axis 6 do not move under J6, and Raghavan and Roth's fourteen functions of them (l, p, p·p, p·l,
p × l, (p·p) l − 2 (p·l) p) are, on each side, linear in cos and sin (or, for a slide u, in 1, u,
u²) of every joint: 14 equations in 9 products of joints 1, 2 and 27 of joints 3, 4, 5. The 8 of
joints 1, 2 are eliminated linearly, leaving 6 equations; in tan(θ/2) and multiplied by x4
they are 12 equations in 12 products x4ⁱ x5ʲ, a 12 × 12 matrix quadratic in x3 that is singular
exactly at the solutions: a 24 × 24 eigenvalue problem whose eigenvectors give x4 and x5.

numpy only: this file's text goes into the module `dhsym ik --format python` writes for an arm
solved numerically. Which joint is "3" (the loop turned and read either way) is chosen once per
arm (dhsym.inverse.numeric.variants): a choice whose matrix is singular for every x3 (arms with
parallel or meeting axes) is not used.

Each side is of degree one in every joint, so three samples give its coefficients exactly:

>>> at, to_coefficients = sampling("R")
>>> (to_coefficients @ (2 + 3 * numpy.cos(at) - numpy.sin(at))).round(12).tolist()  # 2 + 3 cos θ − sin θ
[2.0, 3.0, -1.0]
"""
import numpy

from .chain import joint_motion, rigid_inverse

SHIFT = 0.7548776662466927  # x3 = SHIFT + 1/y: the eigenvalue y is finite at x3 = ∞ (θ3 = π)
REAL = 1e-3  # an eigenvalue whose angle has an imaginary part below this is a candidate; Newton decides
TWINS = 4  # the most solutions that share the polynomial's joint (a wrist's twins of an elbow's twins)
CLUSTER = 1e-4  # roots of one pose closer than this (radians, or units of the arm's size) are one repeated root
HALF_ANGLE = {"R": numpy.array([[1.0, 0.0, 1.0], [1.0, 0.0, -1.0], [0.0, 2.0, 0.0]]),  # 1, c, s → 1, x, x²
              "P": numpy.eye(3)}
SHIFT_4 = ([j * 3 + k for j in range(3) for k in range(3)], [(j + 1) * 3 + k for j in range(3) for k in range(3)])
SHIFT_5 = ([j * 3 + k for j in range(4) for k in range(2)], [j * 3 + k + 1 for j in range(4) for k in range(2)])


def sampling(kind):
    """(three amounts to sample a joint at, the matrix from the values there to the coefficients on
    1, cos, sin (a turn) or 1, u, u² (a slide, u in units of the arm's size))."""
    if kind == "R":
        at = numpy.array([0.0, 2 * numpy.pi / 3, -2 * numpy.pi / 3])
        basis = numpy.stack([numpy.ones(3), numpy.cos(at), numpy.sin(at)], axis=1)
    else:
        at = numpy.array([-1.0, 0.0, 1.0])
        basis = numpy.stack([numpy.ones(3), at, at * at], axis=1)
    return at, numpy.linalg.inv(basis)


def loop_links(reduced, target):
    """The links (M, 6, 4, 4) after each of the six joints of X0 J1 X1 … J6 X6 = T: X1 … X5, and
    X6 T⁻¹ X0, which closes the loop."""
    closing = reduced[..., 6, :, :] @ rigid_inverse(target) @ reduced[..., 0, :, :]
    inner = numpy.broadcast_to(reduced[..., 1:6, :, :], closing.shape[:-2] + (5, 4, 4))
    return numpy.concatenate([inner, closing[..., None, :, :]], axis=-3)


def turned(links, kinds, variant):
    """The loop started at another joint and read forwards or backwards: (links, kinds) in that
    order. Backwards, each joint moves by minus its amount and each link is inverted."""
    order, backwards = variant
    if backwards:
        return rigid_inverse(links[:, [(j - 1) % 6 for j in order]]), "".join(kinds[j] for j in order)
    return links[:, list(order)], "".join(kinds[j] for j in order)


def fourteen(columns):
    """Raghavan and Roth's 14 functions of the direction and the point (columns z and origin, (..., 4, 2))."""
    point, direction = columns[..., :3, 1], columns[..., :3, 0]
    squared = (point * point).sum(axis=-1, keepdims=True)
    along = (point * direction).sum(axis=-1, keepdims=True)
    return numpy.concatenate([direction, point, squared, along, numpy.cross(point, direction),
                              squared * direction - 2 * along * point], axis=-1)


def coefficients(links, kinds, scale):
    """The 14 equations' coefficients: of joints 3, 4, 5 (M, 14, 3, 3, 3) and of 1, 2 (M, 14, 3, 3),
    by sampling each side at three amounts per joint (exact: each side is of degree one)."""
    samples = [sampling(kind) for kind in kinds]
    motions = [joint_motion(kind, at * (scale if kind == "P" else 1.0)) for kind, (at, _) in zip(kinds, samples)]
    third = motions[2] @ links[:, None, 2]  # (M, 3, 4, 4): J3 L3 at the three samples
    fifth = (motions[4] @ links[:, None, 4])[..., 2:]  # only the direction and the point are needed
    left = (motions[3] @ links[:, None, 3])[:, :, None] @ fifth[:, None]
    left = fourteen(third[:, :, None, None] @ left[:, None])  # (M, 3, 3, 3, 14)
    turning_back = [joint_motion(kinds[k], -samples[k][0] * (scale if kinds[k] == "P" else 1.0)) for k in (0, 1)]
    first = rigid_inverse(links[:, 0])[:, None] @ turning_back[0] @ rigid_inverse(links[:, 5])[:, None, :, 2:]
    right = fourteen(rigid_inverse(links[:, 1])[:, None, None] @ turning_back[1][None, None] @ first[:, :, None])
    left = numpy.einsum("ia,jb,kc,mabcq->mqijk", samples[2][1], samples[3][1], samples[4][1], left, optimize=True)
    right = numpy.einsum("ia,jb,mabq->mqij", samples[0][1], samples[1][1], right, optimize=True)
    return left, right


def pencil(left, right, kinds):
    """(the matrix polynomial Σ(x3) = Σ0 + Σ1 x3 + Σ2 x3² (M, 3, 12, 12), the left side with the
    constant term of the right moved over (M, 14, 27), the pseudo-inverse that gives joints 1, 2's
    8 products from the right side (M, 8, 14))."""
    count = left.shape[0]
    moved = left.reshape(count, 14, 27).copy()
    moved[:, :, 0] -= right[:, :, 0, 0]
    products = right.reshape(count, 14, 9)[:, :, 1:]
    basis, sizes, rows_t = numpy.linalg.svd(products)
    null = basis[:, :, 8:]
    kept = sizes > 1e-12 * sizes[:, :1]
    inverse_sizes = numpy.where(kept, 1 / numpy.where(kept, sizes, 1), 0.0)
    pseudo_inverse = (numpy.swapaxes(rows_t, 1, 2) * inverse_sizes[:, None]) @ numpy.swapaxes(basis[:, :, :8], 1, 2)
    six = (numpy.swapaxes(null, 1, 2) @ moved).reshape(count, 6, 3, 3, 3)
    six = numpy.einsum("mrabc,ai,bj,ck->mrijk", six, HALF_ANGLE[kinds[2]], HALF_ANGLE[kinds[3]], HALF_ANGLE[kinds[4]],
                       optimize=True)
    by_power = six.transpose(0, 2, 1, 3, 4).reshape(count, 3, 6, 9)
    sigma = numpy.zeros((count, 3, 12, 12))
    sigma[:, :, :6, :9] = by_power
    sigma[:, :, 6:, 3:] = by_power
    size = numpy.sqrt((sigma ** 2).sum(axis=(1, 3), keepdims=True)) + 1e-300  # each equation scaled to one
    return sigma / size, moved, pseudo_inverse


def roots(sigma):
    """(y (M, 24), the eigenvectors' top halves (M, 24, 12)) of the companion matrix of
    y² Σ(SHIFT + 1/y): x3 = SHIFT + 1/y, and the top half holds x4ⁱ x5ʲ at that root."""
    square = sigma[:, 0] + SHIFT * sigma[:, 1] + SHIFT ** 2 * sigma[:, 2]
    linear, constant = sigma[:, 1] + 2 * SHIFT * sigma[:, 2], sigma[:, 2]
    try:
        lower = numpy.linalg.solve(square, numpy.concatenate([constant, linear], axis=2))
    except numpy.linalg.LinAlgError:  # singular at SHIFT itself: a least-squares answer, checked later
        lower = numpy.linalg.pinv(square) @ numpy.concatenate([constant, linear], axis=2)
    companion = numpy.zeros((sigma.shape[0], 24, 24))
    companion[:, :12, 12:] = numpy.eye(12)
    companion[:, 12:, :] = -lower
    values, vectors = numpy.linalg.eig(companion)
    return values, numpy.swapaxes(vectors[:, :12, :], 1, 2)


def hidden_amount(kind, y, scale):
    """(the joint amount at eigenvalue y, its imaginary part): a turn θ = 2 atan(SHIFT + 1/y)."""
    if kind == "R":
        imaginary = 2 * numpy.abs(y.imag) / (numpy.abs(y) ** 2 + numpy.abs(SHIFT * y + 1) ** 2)
        return 2 * numpy.arctan2(SHIFT * y.real + 1, y.real), imaginary
    with numpy.errstate(divide="ignore", invalid="ignore"):
        value = SHIFT + 1 / y
    return scale * value.real, numpy.where(numpy.abs(value) < 1e3, numpy.abs(value.imag), numpy.inf)


def ratio_amount(kind, vector, shift, scale):
    """A joint's amount from the eigenvector's products: x = (its entries shifted by one power) / (its entries)."""
    low, high = vector[:, shift[0]], vector[:, shift[1]]
    cross, low_size, high_size = (low * high).sum(axis=1), (low * low).sum(axis=1), (high * high).sum(axis=1)
    if kind == "R":
        return numpy.where(low_size >= high_size, 2 * numpy.arctan2(cross, low_size),
                           2 * numpy.arctan2(high_size, cross))
    return scale * cross / (low_size + 1e-300)


def basis_at(kind, amount, scale):
    """(1, cos, sin) of a turn or (1, u, u²) of a slide, for each amount (K, 3)."""
    if kind == "R":
        return numpy.stack([numpy.ones_like(amount), numpy.cos(amount), numpy.sin(amount)], axis=1)
    unit = amount / scale
    return numpy.stack([numpy.ones_like(unit), unit, unit * unit], axis=1)


def candidates(reduced, target, kinds, variant, scale):
    """Every real root of the loop (a candidate for Newton): (the pose each belongs to (K,), the six
    joints' amounts (K, 6), in the chain's order)."""
    links, order_kinds = turned(loop_links(reduced, target), kinds, variant)
    left, right = coefficients(links, order_kinds, scale)
    sigma, moved, pseudo_inverse = pencil(left, right, order_kinds)
    values, vectors = roots(sigma)
    third, imaginary = hidden_amount(order_kinds[2], values, scale)
    rows, slots = numpy.nonzero(numpy.isfinite(third) & (imaginary < REAL))
    vector = vectors[rows, slots]
    phase = vector[numpy.arange(len(rows)), numpy.abs(vector).argmax(axis=1)]
    vector = (vector * (numpy.conj(phase) / (numpy.abs(phase) + 1e-300))[:, None]).real
    vector = repeated(rows, third[rows, slots], values[rows, slots].real, vector, sigma, order_kinds[2])
    amounts = numpy.zeros((len(rows), 6))
    amounts[:, 2] = third[rows, slots]
    amounts[:, 3] = ratio_amount(order_kinds[3], vector, SHIFT_4, scale)
    amounts[:, 4] = ratio_amount(order_kinds[4], vector, SHIFT_5, scale)
    products = numpy.einsum("ki,kj,kl->kijl", *(basis_at(order_kinds[k], amounts[:, k], scale) for k in (2, 3, 4)))
    first_two = numpy.einsum("kpq,kq->kp", pseudo_inverse[rows],
                             numpy.einsum("kqs,ks->kq", moved[rows], products.reshape(len(rows), 27)))
    first_two = numpy.concatenate([numpy.ones((len(rows), 1)), first_two], axis=1).reshape(len(rows), 3, 3)
    for k, (cosine, sine) in ((0, first_two[:, 1:, 0].T), (1, first_two[:, 0, 1:].T)):
        amounts[:, k] = numpy.arctan2(sine, cosine) if order_kinds[k] == "R" else scale * cosine
    amounts[:, 5] = _closing_angle(links[rows], order_kinds, amounts)
    out = numpy.empty_like(amounts)
    order, backwards = variant
    out[:, list(order)] = -amounts if backwards else amounts
    return rows, out


def repeated(rows, third, y, vector, sigma, kind):
    """The eigenvectors where m roots of one pose coincide (twins that share the polynomial's joint):
    there the eigenvectors mix, but the m smallest singular vectors of the matrix span the m
    solutions' products, and the shift from x4ⁱ to x4ⁱ⁺¹ (and x5ʲ to x5ʲ⁺¹) within that span, an
    m × m eigenproblem, gives each one's. Clusters of one size are worked out together."""
    order = numpy.lexsort((third, rows))
    gap = numpy.diff(third[order])
    gap = numpy.remainder(gap + numpy.pi, 2 * numpy.pi) - numpy.pi if kind == "R" else gap
    joined = (numpy.diff(rows[order]) == 0) & (numpy.abs(gap) < CLUSTER)
    starts = numpy.flatnonzero(numpy.concatenate([[True], ~joined]))
    sizes = numpy.diff(numpy.append(starts, len(order)))
    for size in range(2, TWINS + 1):  # more: a root of the matrix at every pose, no solution
        members = order[starts[sizes == size][:, None] + numpy.arange(size)]  # (clusters, size)
        if not len(members):
            continue
        at, row = y[members].mean(axis=1)[:, None, None], rows[members[:, 0]]
        square = sigma[row, 0] + SHIFT * sigma[row, 1] + SHIFT ** 2 * sigma[row, 2]
        matrix = square * at ** 2 + (sigma[row, 1] + 2 * SHIFT * sigma[row, 2]) * at + sigma[row, 2]
        span = numpy.swapaxes(numpy.linalg.svd(matrix)[2][:, -size:], 1, 2)  # (clusters, 12, size)
        shifts = [numpy.linalg.pinv(span[:, low]) @ span[:, high] for low, high in (SHIFT_4, SHIFT_5)]
        found = span @ numpy.linalg.eig(shifts[0] + 0.5773 * shifts[1])[1]
        phase = numpy.take_along_axis(found, numpy.abs(found).argmax(axis=1)[:, None], axis=1)
        found = (found * numpy.conj(phase) / (numpy.abs(phase) + 1e-300)).real
        vector[members] = numpy.swapaxes(found, 1, 2)
    return vector


def _closing_angle(links, kinds, amounts):
    """Joint 6's angle from the other five: J6 = (J1 L1 … J5 L5)⁻¹ L6⁻¹."""
    product = joint_motion(kinds[0], amounts[:, 0]) @ links[:, 0]
    for k in range(1, 5):
        product = product @ joint_motion(kinds[k], amounts[:, k]) @ links[:, k]
    sixth = rigid_inverse(product) @ rigid_inverse(links[:, 5])
    return numpy.arctan2(sixth[:, 1, 0], sixth[:, 0, 0])
