"""Pieper's solution of an arm's position problem (Craig, Introduction to Robotics, §4.6), for the
three revolute joints before a spherical wrist when no sub-problem of the search applies.

The wrist centre p_c is known. Seen from the frame of axis 1 at θ1 = 0 (`q`), p_c = Rz(θ1)·g(θ2, θ3):
turning about axis 1 changes neither |q|² (`r_c`) nor q_z, so both give equations in θ2 and θ3
alone. Each has the form a cos θ2 + b sin θ2 = c, with a, b, c linear in c3 and s3; the two are the
components, along two fixed directions, of the same vector turned by θ2, so that c2² + s2² = 1
eliminates θ2 and leaves an equation of degree two in (c3, s3): a quartic in u = tan(θ3/2),
solved by radicals (dhsym.inverse.quartic). θ2 follows from the pair, θ1 from the x and y of q.

The frames are the chain's own in either convention: the arm's transform is written as
F·Rz(θ1)·C1·Rz(θ2)·C2·Rz(θ3)·C3 with the constant matrices read off the chain at θ = 0.

The half-angle step: cos θ = 0 times (1 + u²)² is 1 − u⁴, the quartic −u⁴ + 1 (its roots u = ±1 are
θ = ±π/2; the other two are not real):

>>> c, s = sympy.symbols("c s")
>>> _half_angle(c, c, s, ())
[-1, 0, 0, 0, 1]
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain, plain
from ..core.numbers import WrittenNumbers
from ..core.transforms import joint_axis_frame
from ..errors import UserError
from .fresh import fresh, fresh_symbol
from .quartic import SIGNS, Complex, ferrari
from .scan import Derivation
from .sentences import Joint, OnAxis, RealRoot, RootAtPi, Subproblem, Undetermined
from .solution import DerivationStep
from .written import Written, exact

FRACTIONS = WrittenNumbers()  # a file without decimals: the quartic's numbers are fractions
NAMES = ("A_4", "A_3", "A_2", "A_1", "A_0", "p", "q", "r", "m", "w", "z", "s")


@dataclass
class _Arm:
    """The arm's equations in θ2, θ3 (see the module's docstring), read off the chain at θ = 0: the
    wrist centre `q` seen from axis 1's frame, `h` the centre turned by θ3 into axis 2's frame, axis
    2's frame in axis 1's (`rotation`, `offset`), the two fixed directions `u1`, `u2`, their `det`."""

    joints: list  # the chain's joints 1..n of θ1, θ2, θ3
    turn: int  # +1, or −1 seen from the end
    q: sympy.Matrix
    h: sympy.Matrix
    rotation: sympy.Matrix
    offset: sympy.Matrix
    u1: sympy.Matrix
    u2: sympy.Matrix
    det: sympy.Expr
    c2: sympy.Expr
    s2: sympy.Expr
    c3: sympy.Expr
    s3: sympy.Expr


def pieper(chain: Chain, numbers: WrittenNumbers, point: sympy.Matrix, local: sympy.Matrix, holder, arm,
           derivation: Derivation | None = None, taken=frozenset(), known_in=None) -> Derivation:
    """Add to `derivation` θ1, θ2, θ3 (the variables `arm`, counted from the frame `known_in`) of
    the joints between that frame (the chain's first by default) and the wrist whose centre sits at
    `local` in frame `holder` and at `point` in `known_in`; `taken`: names already in use (the wrist
    centre's); `numbers`: how the robot file wrote its numbers. For a wrist at the start, `known_in`
    is the last frame and `arm` is θ6, θ5, θ4: seen from the end, each joint turns the rest of the
    chain by −θ. Raises UserError when the arm is not of the general kind (then a sub-problem
    applies, or nothing does)."""
    derivation = Derivation() if derivation is None else derivation
    chain = plain(chain)
    shape = _arm(chain, point, local, holder, arm, known_in)
    known = set(map(str, taken)) | {str(s) for s in chain.symbols} | derivation.reserved
    names = _fresh(("r_c", "u", "f_1", "f_2", "k_1", "k_2", "g_1", "g_2") + NAMES, known)
    signs = tuple(fresh_symbol(sign.name, known) for sign in SIGNS)
    r_c = sympy.Symbol(names[0], real=True)
    length = _reduced(sum(x ** 2 for x in shape.h), shape.c3, shape.s3)
    left = ((r_c - length - shape.offset.dot(shape.offset)) / 2 - shape.u1[2] * shape.h[2],
            shape.q[2] - shape.offset[2] - shape.u2[2] * shape.h[2])
    coefficients = _quartic(shape, left, r_c, numbers, arm[2])
    definitions, root = ferrari(coefficients, names[8:], signs)
    _assign(derivation, shape, arm, names, left, definitions, root)
    derivation.signs.extend([(signs[0], arm[2], "quartic"), (signs[1], arm[2], "quartic")])
    _say(derivation, shape, arm, names, length)
    return derivation


def _arm(chain: Chain, point, local, holder, arm, known_in) -> _Arm:
    """The arm's shape at θ = 0 (see `_Arm`); a UserError where it is not of Pieper's general kind."""
    joints = [chain.joint_variables.index(v) + 1 for v in arm]
    if len(arm) != 3 or any(chain.rows[j - 1].joint != "R" for j in joints):
        raise UserError("Pieper's method needs three revolute joints before the wrist")
    known_in = chain.first_frame if known_in is None else known_in
    turn = 1 if known_in == chain.first_frame else -1  # seen from the end, a joint turns the base by −θ
    zero = {v: 0 for v in arm}
    axes = [joint_axis_frame(chain.convention, j) for j in joints]
    at_zero = lambda i, j: chain.transform(i, j).xreplace(zero).applyfunc(sympy.expand)  # noqa: E731
    seen = at_zero(axes[0], known_in)
    q = (seen[:3, :3] * point + seen[:3, 3]).applyfunc(sympy.expand)
    first, second, last = at_zero(axes[0], axes[1]), at_zero(axes[1], axes[2]), at_zero(axes[2], holder)
    _, t2, t3 = arm
    c3, s3 = sympy.cos(t3), sympy.sin(t3)
    centre = last[:3, :3] * local + last[:3, 3]
    h = (second[:3, :3] * _turned(centre, c3, turn * s3) + second[:3, 3]).applyfunc(sympy.expand)
    rotation, offset = first[:3, :3], first[:3, 3]
    u1, u2 = (rotation.T * offset).applyfunc(sympy.expand), rotation.T[:, 2]
    det = sympy.simplify(u1[0] * u2[1] - u1[1] * u2[0])
    if sympy.simplify(exact(det)) == 0:
        raise UserError("Pieper's method: the arm's equations are not of the general kind (axes 1 and 2 meet or are "
                        "parallel), and the sub-problems did not solve them")
    return _Arm(joints, turn, q, h, rotation, offset, u1, u2, det, sympy.cos(t2), sympy.sin(turn * t2), c3, s3)


def _quartic(shape: _Arm, left, r_c, numbers, t3) -> list:
    """A₄ … A₀: θ2 eliminated from the two equations by c2² + s2² = 1, in u = tan(θ3/2)."""
    (u1x, u1y), (u2x, u2y) = shape.u1[:2], shape.u2[:2]
    planar = shape.h[0] ** 2 + shape.h[1] ** 2
    # The quartic's coefficients are numbers for a robot of numbers: each one number (see _in_one_style)
    quadric = _reduced(exact((u2x ** 2 + u2y ** 2) * left[0] ** 2 - 2 * (u1x * u2x + u1y * u2y) * left[0] * left[1]
                             + (u1x ** 2 + u1y ** 2) * left[1] ** 2 - shape.det ** 2 * planar), shape.c3, shape.s3)
    coefficients = _half_angle(quadric, shape.c3, shape.s3, (r_c, exact(shape.q[2])), numbers)
    if sympy.expand(exact(coefficients[0])) == 0:
        raise UserError(f"Pieper's method: the quartic in tan({t3}/2) loses its leading term ({t3} = π solves "
                        "every pose): not handled")
    return coefficients


def _assign(derivation: Derivation, shape: _Arm, arm, names, left, definitions, root) -> None:
    """The assignments: r_c, the quartic's quantities and root u, θ3, then θ2 from the pair (k1, k2)
    = det · Rz(θ2)(f1, f2), then θ1 from the centre's x and y in axis 1's frame."""
    t1, t2, t3 = arm
    r_c, u = sympy.Symbol(names[0], real=True), Complex(names[1])
    f1, f2, k1, k2, g1, g2 = (sympy.Symbol(n, real=True) for n in names[2:8])
    (u1x, u1y), (u2x, u2y), q, turn = shape.u1[:2], shape.u2[:2], shape.q, shape.turn
    scale = sympy.sign(shape.det) if shape.det.is_number else shape.det  # det² > 0: atan2 keeps its quadrant
    g = shape.rotation * _turned(sympy.Matrix([f1, f2, shape.h[2]]), shape.c2, shape.s2) + shape.offset
    derivation.assignments += [(r_c, sum(x ** 2 for x in q)), *definitions, (u, root),
                               (t3, sympy.atan2(2 * u, 1 - u ** 2)),
                               (f1, _tidy(shape.h[0])), (f2, _tidy(shape.h[1])),
                               (k1, _tidy(scale * (u2y * left[0] - u1y * left[1]))),
                               (k2, _tidy(scale * (u1x * left[1] - u2x * left[0]))),
                               (t2, turn * sympy.atan2(k2 * f1 - k1 * f2, k1 * f1 + k2 * f2)),
                               (g1, _tidy(g[0])), (g2, _tidy(g[1])),
                               (t1, turn * sympy.atan2(_tidy(q[1] * g1 - q[0] * g2), _tidy(q[0] * g1 + q[1] * g2)))]


def _say(derivation: Derivation, shape: _Arm, arm, names, length) -> None:
    """The steps a book writes, when the branches exist and where they degenerate."""
    t1, t2, t3 = arm
    r_c, u = sympy.Symbol(names[0], real=True), Complex(names[1])
    f1, f2, k1, k2, g1, g2 = (sympy.Symbol(n, real=True) for n in names[2:8])
    a4, a3, a2, a1, a0 = (sympy.Symbol(n, real=True) for n in names[8:13])
    c2, s2, turn, q, offset = shape.c2, shape.s2, shape.turn, shape.q, shape.offset
    norm = (sympy.sign(shape.det) if shape.det.is_number else shape.det) * shape.det  # (k1, k2) = norm Rz(θ2)(f1, f2)
    j1, j2, _ = (Joint(j) for j in shape.joints)
    derivation.steps += [
        DerivationStep(r_c, _tidy(length + 2 * (shape.u1.T * _turned(shape.h, c2, s2))[0] + offset.dot(offset)),
                       Subproblem("Pieper's distance", shape.joints[0]), (),
                       ("the squared distance of the wrist centre from the origin of axis ", j1, "'s frame")),
        DerivationStep(q[2], _tidy((shape.u2.T * _turned(shape.h, c2, s2))[0] + offset[2]),
                       Subproblem("Pieper's height", shape.joints[0]), (),
                       ("the wrist centre's coordinate along axis ", j1)),
        DerivationStep(a4 * u ** 4 + a3 * u ** 3 + a2 * u ** 2 + a1 * u + a0, sympy.Integer(0),
                       Subproblem("Ferrari's quartic", shape.joints[2]), (t3,),
                       ("θ", j2, " eliminated from the two equations by c", j2, "² + s", j2, "² = 1")),
        DerivationStep(f1 * c2 - f2 * s2, k1 / norm, Subproblem("atan2 of a pair"), (t2,),
                       ("the two equations solved for the vector (f1, f2) turned by θ", j2, " (equation 1 of 2)")),
        DerivationStep(f1 * s2 + f2 * c2, k2 / norm, Subproblem("atan2 of a pair"), (t2,),
                       ("the same (equation 2 of 2)",)),
        DerivationStep(g1 * sympy.cos(t1) - g2 * sympy.sin(turn * t1), q[0], Subproblem("atan2 of a pair"), (t1,),
                       ("the x of the wrist centre in axis ", j1, "'s frame (equation 1 of 2)")),
        DerivationStep(g1 * sympy.sin(turn * t1) + g2 * sympy.cos(t1), q[1], Subproblem("atan2 of a pair"), (t1,),
                       ("its y (equation 2 of 2)",)),
    ]
    derivation.conditions.append(RealRoot(t3, u))
    derivation.degenerate += [Undetermined((f1 ** 2 + f2 ** 2,), t2, OnAxis(shape.joints[1])),
                              Undetermined((g1 ** 2 + g2 ** 2,), t1, OnAxis(shape.joints[0])),
                              RootAtPi(a4, t3, u)]


def _turned(vector, c, s) -> sympy.Matrix:
    """Rz(θ)·vector, with c = cos θ and s = sin θ."""
    x, y, z = vector
    return sympy.Matrix([c * x - s * y, s * x + c * y, z])


def _reduced(expr, c, s):
    """`expr` expanded with s² = 1 − c²: degree at most one in s."""
    expanded = sympy.expand(expr)
    return sympy.expand(expanded.subs(s ** 2, 1 - c ** 2)) if expanded.has(s) else expanded


def _half_angle(expr, c, s, known, numbers=FRACTIONS) -> list:
    """A₄ … A₀ of the quartic in u = tan(θ/2) that `expr` (of degree ≤ 2 in c, s) times (1 + u²)² is,
    each collected in the `known` quantities (r_c and the height), its numbers in one style for the
    five (see `_in_one_style`)."""
    x, y, u = sympy.Dummy("x"), sympy.Dummy("y"), sympy.Dummy("u")
    poly = sympy.Poly(expr.xreplace({c: x, s: y}), x, y)
    if poly.total_degree() > 2:  # a joint between the arm's three (one made free) breaks Pieper's form
        raise UserError("Pieper's method: the wrist centre's equations are not quadratic in the third joint")
    total = [sympy.Integer(0)] * 5  # A₀ … A₄: each term's coefficient times small integers, never a product expanded
    for (i, j), coefficient in poly.terms():
        factor = sympy.Poly((1 - u ** 2) ** i * (2 * u) ** j * (1 + u ** 2) ** (2 - i - j), u)
        for (k,), number in factor.terms():
            total[k] += number * coefficient
    collected = [_collected(total[k], known) for k in range(4, -1, -1)]
    style = _in_one_style([coefficient for terms in collected for coefficient, _ in terms], numbers)
    return [sympy.Add(*[style(coefficient) * monomial for coefficient, monomial in terms]) for terms in collected]


def _collected(expr, known) -> list:
    """[(coefficient, monomial)]: `expr` as a polynomial in the `known` quantities (expanded)."""
    expanded = sympy.expand(expr)
    heads = [k for k in known if not k.is_number and k.free_symbols]
    try:
        poly = sympy.Poly(expanded, *heads) if heads else None
    except sympy.PolynomialError:
        poly = None
    if poly is None:
        return [(expanded, sympy.Integer(1))]
    return [(coefficient, sympy.Mul(*[x ** e for x, e in zip(heads, powers)])) for powers, coefficient in poly.terms()]


def _in_one_style(coefficients, numbers):
    """How the quartic's coefficients are written, one way for all: each a decimal (`Written`), as
    0.1075 zc², where the file's rule writes every rational in them as a decimal, else each one
    number or short expression with fractions, as (43 zc²)/400. (Put in by name, the file's
    decimals would give long sums of products, 0.75 · 0.1⁴ + (3 · 0.2⁴)/16 + …)

    >>> numbers = [sympy.Rational(43, 400), sympy.Rational(9, 20) + sympy.sqrt(2) / 1000]
    >>> [_in_one_style(numbers, WrittenNumbers(places=p))(numbers[1]) for p in (1, 2)]   # 0.1075: 4 places
    [(sqrt(2) + 450)/1000, sqrt(2)*0.001 + 0.45]
    """
    terms = [t.as_coeff_Mul() for coefficient in coefficients for t in sympy.Add.make_args(coefficient)]
    fractions = [abs(r) for r, _ in terms if r.is_Rational and not r.is_Integer]
    if not fractions or any(numbers.decimal(r) is None for r in fractions):
        return _tidy
    decimal = lambda r: r if r.is_Integer else sympy.sign(r) * Written.of(abs(r))  # noqa: E731
    return lambda coefficient: sympy.Add(*(decimal(r) * rest if r.is_Rational else r * rest for r, rest in
                                           (t.as_coeff_Mul() for t in sympy.Add.make_args(coefficient))))


def _tidy(expr):
    return sympy.factor_terms(sympy.expand(expr))


def _fresh(names, taken: set) -> list[str]:
    """Each of `names` fresh against `taken` and the ones before it (dhsym.inverse.fresh)."""
    out = []
    for name in names:
        out.append(fresh(name, taken))
        taken.add(out[-1])
    return out

