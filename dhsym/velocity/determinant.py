"""The determinant of a Jacobian, factored, and the factors whose vanishing makes it singular.

A 6×6 determinant is the same in every frame and for every reference point: changing either
multiplies J by a matrix of determinant 1. So it is worked out where J is sparse. For a
wrist-partitioned arm (the last three axes meet in a point, the wrist centre), J of the wrist
centre has a zero upper-right block and ``det J = det A · det C``: A the linear velocities of
the first three joints, C the three wrist axes. The PUMA factors in a fraction of a second:

>>> import dhsym
>>> result = determinant(dhsym.load("puma560").chain)
>>> for factor in result.factors:
...     print(factor)
sin(theta_5)
a_3*sin(theta_3) + d_4*cos(theta_3)
a_2*cos(theta_2) + a_3*cos(theta_2 + theta_3) - d_4*sin(theta_2 + theta_3)
>>> sympy.simplify(result.value / sympy.Mul(*result.factors))  # what is left is a constant
-a_2

A Jacobian that is not square has no determinant. For an arm with fewer than six joints the
rows that are zero everywhere are dropped (a planar arm moves only in vx, vy, ωz); when as many
rows as joints remain, or the linear rows alone are as many as the joints, that square block
is used and `block` says which. Otherwise `value` is None and `note` says why.
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Mapping

import sympy

from ..core.chain import Chain, Frame, plain
from ..core.numbering import PLAIN, Numbering
from ..core.numbers import WrittenNumbers
from ..core.simplify import collect_by_trig
from ..core.size import expanded_terms, length, rough_count
from ..geometry.convert import to_convention
from .expanded import expanded_det, leibniz_terms, minors_det, term_count
from .geometry import wrist_centre
from .jacobian import ROWS, angular_part, axis_frame, chain_frames, jacobian, jacobian_size, linear_part

# Terms of a determinant written out, at most, counted before it is expanded (expanded.leibniz_terms): past
# this it is not factored. The UR5's in frame 4 has 336, in frame 1 57,420, and a general six-link chain's
# 9.8 million at best. The count depends on the problem alone, never on the machine.
FACTOR_MAX_TERMS = 50_000
MIDDLE_FRAMES = (4, 3, 5, 2, 1)  # frames by their distance from the middle of a six-joint arm


class TooManyTerms(Exception):
    """A determinant that would expand to more than FACTOR_MAX_TERMS terms; of several matrices,
    `position` is that of the one whose count is least."""

    def __init__(self, terms: int, position: int = 0):
        super().__init__(terms)
        self.terms, self.position = terms, position


@dataclass(frozen=True)
class Determinant:
    """`value`: the factored determinant of `block` (None when none is computed); `factors`:
    the factors with joint variables, each a singular configuration where it is zero."""

    value: sympy.Expr | None
    block: str
    factors: list
    note: str


@dataclass(frozen=True)
class Printed:
    """What `determinant` is told of the robot file, handed down: its numbers as written, the sample
    values of its constants, its numbering."""

    numbers: WrittenNumbers
    sample: Mapping
    numbering: Numbering


def determinant(chain: Chain, frame: Frame | None = None, point: Frame | None = None, *,
                numbers: WrittenNumbers | None = None, sample: Mapping | None = None,
                numbering: Numbering = PLAIN) -> Determinant:
    """The factored determinant of ᵏJ (or of the square block of the rows that move), or a note
    saying why none is computed: J is not square, or its determinant would expand to more than
    FACTOR_MAX_TERMS terms (counted before any expansion, so the answer is the same everywhere).
    `frame`, `point`: the chain's frames (None: the first and the last). From the robot file:
    `numbers` as it wrote them, `sample` values of its constants, the `numbering` its notes print."""
    frame, point = chain_frames(plain(chain), frame, point)  # checked even where J in `frame` is not needed
    printed = Printed(numbers or WrittenNumbers(), sample or {}, numbering)
    try:
        return _determinant(chain, frame, point, printed)
    except TooManyTerms as error:
        return Determinant(None, "", [], f"the determinant would expand to {rough_count(error.terms)} terms, "
                           f"more than the {FACTOR_MAX_TERMS:,} that dhsym factors: not computed.")


def _determinant(chain: Chain, frame: Frame, point: Frame, printed: Printed) -> Determinant:
    n = chain.n
    if n == 6:  # the same in every frame: worked out where it is short, not from J in `frame`
        centre = wrist_centre(chain, sample=printed.sample)
        if centre is not None:
            return _wrist_partitioned(chain, centre, printed)
        return _full(chain, printed)
    if n > 6:
        return Determinant(None, "", [], f"J is 6×{n}: the arm is redundant, and no determinant is computed. "
                           f"It is singular where all {sympy.binomial(n, 6)} of its 6×6 minors vanish (rank < 6); "
                           "those configurations are not worked out.")
    matrix = jacobian(chain, frame, point)
    moving = _moving(matrix)
    blocks = [moving] if len(moving) == n else [[r for r in moving if r < 3], [r for r in moving if r >= 3]]
    square = [rows for rows in blocks if len(rows) == n]
    if not square:
        return Determinant(None, "", [], f"J is 6×{n} and its {len(moving)} rows that move are not {n}, nor are "
                           "its moving linear or angular rows: no square block, no determinant computed.")
    # every frame that keeps `moving` the rows that move (a planar arm: z normal to the plane), the one asked first
    others = dict.fromkeys([*(axis_frame(chain, j) for j in range(1, n + 1)), chain.last_frame])
    turned = (jacobian(chain, other, point) for other in others if other != frame)
    candidates = [matrix] + [candidate for candidate in turned if _moving(candidate) == moving]
    results = [_block(chain, candidates, moving, rows, printed) for rows in square]
    return next((r for r in results if r.value != 0), results[0])


def _moving(matrix) -> list:
    """The rows of J that are not zero everywhere."""
    return [r for r in range(6) if any(x != 0 for x in matrix.row(r))]


def _block(chain: Chain, candidates, moving, rows, printed: Printed) -> Determinant:
    """The determinant of the block `rows` of J, from the frame where it has the fewest terms.
    The candidates' frames turn the block by a rotation within the rows that move, so the
    determinant is the same up to its sign; the sign is that of the frame asked for, the first."""
    n = len(rows)
    block = "rows " + ", ".join(ROWS[r] for r in rows)
    what = "the rows that move" if rows == moving else "the velocity of the point" if rows[0] < 3 else "the axes"
    note = f"J is 6×{n}; the determinant is that of its {n}×{n} block of {block} ({what})."
    squares = [candidate.extract(rows, list(range(n))) for candidate in candidates]
    result = _result(chain, printed, fewest_terms(squares), block, note)
    if _same_sign(result.value, squares[0]):
        return result
    return _result(chain, printed, -result.value, block, note)


def fewest_terms(matrices) -> sympy.Expr:
    """Of several matrices whose determinants are equal up to sign, the determinant multiplied out
    that has the fewest terms (the first on a tie). Raises TooManyTerms, before any work, when each
    could have more than FACTOR_MAX_TERMS."""
    bounds = [leibniz_terms(matrix) for matrix in matrices]
    if min(bounds) > FACTOR_MAX_TERMS:
        raise TooManyTerms(min(bounds), bounds.index(min(bounds)))
    return min((_multiplied_out(m) for m, bound in zip(matrices, bounds) if bound <= FACTOR_MAX_TERMS), key=term_count)


def _multiplied_out(matrix) -> sympy.Expr:
    """The determinant as `sympy.expand` writes it, in the polynomial ring where it is one."""
    det = expanded_det(matrix)
    return sympy.expand(minors_det(matrix.tolist(), sympy.Integer(1))) if det is None else det


def _same_sign(value, square) -> bool:
    """Whether a determinant has the sign of that of `square` (they differ at most in sign), judged
    by numbers where neither is zero.

    A turn of the moving rows about an axis in their plane by π (a twist of π) is a reflection
    within them, so the block's determinant changes sign; the sign is the same everywhere."""
    variables = sorted(value.free_symbols | square.free_symbols, key=str)
    rng = random.Random(0)
    for _ in range(20):
        point = {v: sympy.Float(rng.uniform(-3, 3)) for v in variables}
        x, y = float(value.xreplace(point)), float(minors_det(square.xreplace(point).tolist(), 1))
        if abs(x) > 1e-6 and abs(y) > 1e-6:
            return (x > 0) == (y > 0)
    return True  # zero everywhere we looked: the sign cannot matter


def _full(chain: Chain, printed: Printed) -> Determinant:
    """det J of a 6-joint arm without a wrist centre. det J is the same in every frame (a rotation of
    both halves has determinant 1) and for every reference point, and in both conventions: the
    same robot written in the other one has its frames on the same joint axes, so J is the same
    for every joint value. In a frame near the middle of the arm the entries are short: the UR5's
    has at most 336 terms from frame 4, 57,420 from frame 1. So in each convention J is built in
    the frame where it is estimated shortest (the middle first on a tie), and det J is factored
    from the one where it has fewer terms (the standard convention on a tie): both conventions of
    an arm print the same determinant (the HC10's has 18 terms in frame 3 of the standard
    convention, 9 in frame 4 of the modified one). Two attempts, whatever the machine."""
    other = to_convention(chain, "modified" if chain.convention == "standard" else "standard")
    chains = sorted([chain, other], key=lambda c: c.convention != "standard")
    places = [(c, min(MIDDLE_FRAMES, key=lambda f: jacobian_size(c, f, c.last_frame))) for c in chains]
    matrices = [jacobian(c, frame) for c, frame in places]
    try:
        det = fewest_terms(matrices)
    except TooManyTerms as error:
        c, frame = places[error.position]
        where = f"frame {printed.numbering.frame(frame)}" + (f" of the {c.convention} convention" if c is other else "")
        return Determinant(None, "J", [], f"the axes of joints 4–6 do not meet in a point, and the full 6×6 "
                           f"determinant would expand to {rough_count(error.terms)} terms even in {where}, where "
                           f"J is shortest; that is more than the {FACTOR_MAX_TERMS:,} that dhsym factors: not "
                           "computed.")
    return _result(chain, printed, det, "J", "")


def _wrist_partitioned(chain: Chain, centre: Frame, printed: Printed) -> Determinant:
    """det A · det C, each in the frame where it is short: A (linear rows, joints 1–3) in the
    axis frame of joint 3 (Craig's ³J₆), C (angular rows, joints 4–6) in that of joint 5."""
    arm_det, wrist_det = partitioned(chain, centre)
    result = _result(chain, printed, arm_det * wrist_det, "J", "")
    note = (f"The last three axes meet at the origin of frame {printed.numbering.frame(centre)} (the wrist centre), "
            "so det J = (det A)(det C): "
            "A the linear velocities of the wrist centre from joints 1–3, C the wrist axes 4–6.")
    return Determinant(result.value, "J", result.factors, note)


def partitioned(chain: Chain, centre: Frame) -> tuple[sympy.Expr, sympy.Expr]:
    """det A and det C of a wrist-partitioned arm, each factored: A (linear rows, joints 1–3) in
    the axis frame of joint 3 (Craig's ³J₆), C (angular rows, joints 4–6) in that of joint 5."""
    body, arm_frame, wrist_frame = chain.last_frame, axis_frame(chain, 3), axis_frame(chain, 5)
    arm = [linear_part(chain, j, arm_frame, centre, body) for j in (1, 2, 3)]
    wrist = [angular_part(chain, j, wrist_frame, centre, body) for j in (4, 5, 6)]
    return tuple(factored(sympy.Matrix(block).T.det(method="berkowitz")) for block in (arm, wrist))


def partitioned_factors(chain: Chain, centre: Frame, numbers: WrittenNumbers) -> list:
    """The factors of det J of a wrist-partitioned arm, as `determinant(chain).factors` gives them,
    from its two factored blocks without factoring their product again (nor its value)."""
    arm_det, wrist_det = partitioned(chain, centre)
    return joint_factors(as_written(arm_det * wrist_det, numbers), chain)


def _result(chain: Chain, printed: Printed, det, block: str, note: str) -> Determinant:
    value = as_written(factored(det), printed.numbers)
    return Determinant(value, block, joint_factors(value, chain), note)


def joint_factors(value, chain: Chain) -> list:
    """The distinct factors of `value` that hold joint variables, sign-normalised and collected, the
    one with the latest joint first (how the singularities are listed)."""
    variables = set(chain.joint_variables)
    factors = []
    for factor in sympy.Mul.make_args(value):
        base = factor.base if factor.is_Pow else factor
        if base.free_symbols & variables:
            base = -base if base.could_extract_minus_sign() else base
            if base not in factors:
                factors.append(collect_by_trig(base, frozenset(variables)))
    last_joint = {v: k for k, v in enumerate(chain.joint_variables)}
    factors.sort(key=lambda f: -max(last_joint[v] for v in f.free_symbols & variables))
    return factors


def as_written(value: sympy.Expr, numbers) -> sympy.Expr:
    """A factored determinant with each factor scaled back to the decimals its robot file wrote:
    factoring makes 0.425 c2 + 0.39225 c23 into (8500 c2 + 7845 c23)/20000 (the printers write
    17/40 as 0.425 again).

    >>> from dhsym.core.numbers import WrittenNumbers
    >>> c2, c3 = sympy.symbols("c2 c3")
    >>> as_written(3 * c3 * (8500 * c2 + 7845) / 20000, WrittenNumbers(6, values=frozenset({sympy.Rational(17, 40)})))
    3*c3*(17*c2/40 + 1569/4000)
    """
    if not numbers.places:
        return value
    coefficient, factors = value.as_coeff_mul()
    scaled, changed = [], False
    for factor in factors:
        base, exponent = factor.as_base_exp()
        scale = _written_scale(base, numbers) if base.is_Add else None
        if scale is None:
            scaled.append(factor)
            continue
        scaled.append(sympy.Pow(sympy.expand(base * scale), exponent))
        coefficient, changed = coefficient / scale ** exponent, True
    return sympy.Mul(coefficient, *scaled, evaluate=False) if changed else value


def _written_scale(base: sympy.Add, numbers):
    """The factor that turns the coefficients of `base` into decimals as written: one of them
    into a value the file wrote and the others into decimals, else None."""
    coefficients = [abs(term.as_coeff_Mul()[0]) for term in base.args]
    if not all(c.is_Rational for c in coefficients):
        return None
    for written in sorted(numbers.values, key=lambda v: (-v.q, v)):
        for coefficient in coefficients:
            scale = written / coefficient
            if scale != 1 and all(numbers.decimal(c * scale, alone=True) for c in coefficients):
                return scale
    return None


def factored(expr: sympy.Expr) -> sympy.Expr:
    """Factor a polynomial in cos/sin, then shorten each factor with sin² = 1 − cos². Raises
    TooManyTerms, before any work, when it would expand to more than FACTOR_MAX_TERMS terms.

    >>> t4, t5 = sympy.symbols("theta_4 theta_5", real=True)
    >>> factored(-sympy.sin(t4)**2*sympy.sin(t5) - sympy.cos(t4)**2*sympy.sin(t5))
    -sin(theta_5)
    """
    if expr == 0:
        return sympy.Integer(0)
    terms = expanded_terms(expr)
    if terms > FACTOR_MAX_TERMS:
        raise TooManyTerms(terms)
    result = sympy.factor(sympy.expand(expr))
    shortened = sympy.Mul(*[_pythagoras(f) for f in sympy.Mul.make_args(result)])
    return sympy.factor(shortened) if shortened != result else result


def _harmonic(pair: sympy.Add) -> bool:
    """Whether a sum of two terms is a x + b y, x and y each one cos or sin, a and b free of them
    and a/b a symbol's ratio or a rational ≠ ±1 (a3 s3 + d4 c3): no identity shortens it (tan of
    a rational multiple of π is rational only at 0 and ±1), and trigsimp need not try.

    >>> a, b, t = sympy.symbols("a b t")
    >>> _harmonic(a * sympy.sin(t) + b * sympy.cos(t)), _harmonic(a * sympy.sin(t) + a * sympy.cos(t))
    (True, False)
    >>> _harmonic(sympy.sqrt(3) * sympy.sin(t) + sympy.cos(t)), _harmonic(3 * sympy.sin(t) + 4 * sympy.cos(t))
    (False, True)
    """
    coefficients = []
    for term in pair.args:
        coefficient, trig = term.as_independent(sympy.sin, sympy.cos, as_Add=False)
        if not isinstance(trig, (sympy.sin, sympy.cos)) or coefficient.has(sympy.sin, sympy.cos):
            return False
        coefficients.append(coefficient)
    ratio = sympy.cancel(coefficients[0] / coefficients[1])  # √3 s + c is 2 sin(θ + π/6): tan π/6 is √3/3
    return not ratio.is_number or (ratio.is_Rational and abs(ratio) != 1)


def _pythagoras(factor: sympy.Expr) -> sympy.Expr:
    base, exponent = (factor.base, factor.exp) if factor.is_Pow else (factor, 1)
    if base.is_Add and len(base.args) == 2 and length(base) <= 12 and not _harmonic(base):  # s2 c23 − s23 c2 = −s3
        summed = sympy.trigsimp(base)
        if length(summed) < length(base):
            return summed ** exponent
    squares = {p: (1 - sympy.cos(p.base.args[0]) ** 2) * p.base ** (p.exp - 2) for p in base.atoms(sympy.Pow)
               if isinstance(p.base, sympy.sin) and p.exp.is_Integer and p.exp >= 2}
    if not squares:
        return factor
    reduced = sympy.expand(base.xreplace(squares))
    return (reduced if length(reduced) < length(base) else base) ** exponent
