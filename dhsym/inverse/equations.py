"""The equations of inverse kinematics, as a course writes them: the target moved to frame i by
the inverse of the first links, set equal to the chain from frame i on (Paul's method,
``(⁰T_i)⁻¹ T = ⁱT_n``), element by element, and the squared distances that no rotation changes.

Every matrix is the chain's contracted transform, so the equations are as short as the
forward kinematics. A squared length is worked out step by step instead of by simplifying a
sum of squares: a rotation keeps it, a translation t along an axis adds 2 t·(that coordinate
of what follows) + t².

>>> import dhsym
>>> arm = dhsym.load("planar2r")
>>> squared_length(arm.steps(0, 2), arm.joint_variables)
a_1**2 + 2*a_1*a_2*cos(theta_2) + a_2**2
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import sympy

from ..core.chain import Chain
from ..core.simplify import collect_by_trig, contract
from . import algebra
from .algebra import Ring
from .sentences import Frame, Phrase

ZERO = sympy.Matrix([0, 0, 0])


@dataclass(frozen=True)
class Equation:
    """`lhs` = `rhs`: lhs from the target (moved to a frame by known or unknown first joints),
    rhs from the chain; `kind` "position" (a point) or "orientation" (a rotation element);
    `where` names the matrix element it comes from, for the derivation (a phrase: words and
    the chain's frames); `distance`: a squared distance, where a cosine is the law of cosines'."""

    lhs: sympy.Expr
    rhs: sympy.Expr
    kind: str
    where: Phrase
    source: tuple = ()  # the matrix equation it is an element of (its frames): pairs are taken within one
    distance: bool = False
    parts: tuple = ()  # a squared distance's vector, (target side, chain side) per axis: lhs = Σ (target side)²

    @cached_property
    def expr(self) -> sympy.Expr:  # built once: the search reads it in every round
        return self.lhs - self.rhs


def squared_length(steps, variables, point=ZERO, point_length=0, memo: dict | None = None,
                   ring: Ring | None = None) -> sympy.Expr:
    """‖S₁⋯S_m · point‖², given ‖point‖² (`point_length`), without simplifying a sum of squares.
    `memo` keeps the contracted tails of the steps between calls (Paul's pairs share them)."""
    variables = frozenset(variables)
    memo = {} if memo is None else memo
    total = sympy.sympify(point_length)
    for k, step in enumerate(steps):
        if step.is_rotation or step.value == 0:
            continue
        tail = tuple(steps[k + 1:])
        if tail not in memo:
            memo[tail] = contract(tail, variables)
        after = memo[tail]
        coordinate = (after[:3, :3] * point + after[:3, 3])[step.axis]
        total += 2 * step.value * coordinate + step.value ** 2
    return collect_by_trig(algebra.expand(total) if ring is None else ring.expand(total), variables)


def moved(chain: Chain, frame, point: sympy.Matrix, point_length, known_in=None,
          memo: dict | None = None) -> tuple[sympy.Matrix, sympy.Expr]:
    """The point (known in frame `known_in`, the first by default) seen from `frame`, and its
    squared distance from that frame's origin (`memo` as for `squared_length`)."""
    known_in = chain.first_frame if known_in is None else known_in
    variables = chain.joint_variables
    inverse = chain.transform(frame, known_in)
    seen = inverse[:3, :3] * point + inverse[:3, 3]
    return seen.applyfunc(lambda e: collect_by_trig(algebra.expand(e), frozenset(variables))), \
        squared_length(chain.steps(frame, known_in), variables, point, point_length, memo)


def point_equations(chain: Chain, point: sympy.Matrix, point_length, local: sympy.Matrix, holder,
                    known_in=None) -> list[Equation]:
    """A point known in frame `known_in` (the first by default; the last for a wrist at the start)
    that sits at `local` in frame `holder`: its three coordinates and squared distance, seen from
    each frame between the two."""
    frames = chain.frames
    known_in = chain.first_frame if known_in is None else known_in
    variables = chain.joint_variables
    equations = []
    local_length = sympy.expand(sum(x ** 2 for x in local))
    ends = sorted([frames.index(known_in), frames.index(holder)])
    memo: dict = {}  # contracted tails of steps: the frames' paths share them
    for frame in frames[ends[0]:ends[1] + 1]:
        seen, seen_length = moved(chain, frame, point, point_length, known_in, memo)
        chain_side = chain.transform(frame, holder)
        there = chain_side[:3, :3] * local + chain_side[:3, 3]
        there = there.applyfunc(lambda e: collect_by_trig(algebra.expand(e), frozenset(variables)))
        there_length = squared_length(chain.steps(frame, holder), variables, local, local_length, memo)
        for axis in range(3):
            equations.append(Equation(seen[axis], there[axis], "position",
                                      (f"{'xyz'[axis]} of the point in frame ", Frame(frame)), ("point", frame)))
        equations.append(Equation(seen_length, there_length, "position",
                                  ("squared distance of the point from the origin of frame ", Frame(frame)),
                                  distance=True, parts=tuple(zip(seen, there))))
    return equations


def transform_equations(chain: Chain, target: sympy.Matrix, position: bool, start=None, end=None) -> list[Equation]:
    """(ⁱT_first) T (ʲT_last)⁻¹ = ⁱT_j for every pair of frames i ≤ j (between `start` and `end`):
    the rotation elements, and with `position` the position elements and the squared distance.

    The two sides of each product are expanded once (per i, per j) and only the elements that
    are asked for are multiplied out: expansion is canonical, so the result is the same as
    expanding the whole product, at a fraction of the work."""
    frames, first, last = _frames_between(chain, start, end), chain.first_frame, chain.last_frame
    variables = frozenset(chain.joint_variables)
    columns = 4 if position else 3
    memo: dict = {}  # contracted tails of steps, shared by the squared lengths
    afters = {j: chain.transform(last, j) for j in frames[1:]}
    leads = {i: chain.transform(i, first) for i in frames[:-1]}
    ring = Ring([m[r, c] for m in list(afters.values()) + list(leads.values()) + [target]
                 for r in range(3) for c in range(columns)])
    if ring.usable:  # multiplied out as polynomials: the same expansion, many times faster
        convert, made = ring.poly, lambda e: collect_by_trig(ring.expr(e), variables)  # noqa: E731
    else:
        convert, made = sympy.expand, lambda e: collect_by_trig(sympy.expand(e), variables)  # noqa: E731
    expanded_after = {j: [[convert(after[m, c]) for c in range(columns)] for m in range(3)]
                      for j, after in afters.items()}
    tip_lengths = {}
    written: dict = {}  # a multiplied-out element -> its expression
    equations = []
    for a, i in enumerate(frames):
        if a == len(frames) - 1:
            break
        lead = leads[i]
        before = [[convert(sum(lead[r, m] * target[m, c] for m in range(3)) + (lead[r, 3] if c == 3 else 0))
                   for c in range(columns)] for r in range(3)]
        for j in frames[a + 1:]:
            after = expanded_after[j]
            chain_side = chain.transform(i, j)
            where = (Frame(i), "T", Frame(j))
            for r in range(3):
                for c in range(columns):
                    seen = sum((before[r][m] * after[m][c] for m in range(3)), before[r][3] if c == 3 else 0)
                    if seen not in written:  # the same element recurs in other pairs of frames: written once
                        written[seen] = made(seen)
                    equations.append(Equation(written[seen], chain_side[r, c], _kind(c, j == last),
                                              (f"element ({r + 1}, {c + 1}) of ", *where), (i, j)))
            if position:
                if j not in tip_lengths:
                    tip_lengths[j] = squared_length(chain.steps(last, j), variables, memo=memo, ring=ring)
                found = _length_equation(chain, target, (i, j), afters[j][:3, 3], tip_lengths[j], memo, ring)
                position_elements = equations[-9::4]  # elements (1, 4), (2, 4), (3, 4) of this pair of frames
                equations.append(replace(found, parts=tuple((e.lhs, e.rhs) for e in position_elements)))
    return equations


def _frames_between(chain: Chain, start, end) -> list:
    """The chain's frames from `start` to `end` (None: its first, its last)."""
    frames = chain.frames
    if end is not None:
        frames = frames[:frames.index(end) + 1]
    if start is not None:
        frames = frames[frames.index(start):]
    return frames


def _length_equation(chain: Chain, target, pair, tip, tip_length, memo: dict, ring) -> Equation:
    """The squared length of the vector from frame i's origin to the tip's point `tip` of frame j,
    both ways: through the target and through the chain (`tip_length`: ‖tip‖², seen from the end)."""
    i, j = pair
    variables = frozenset(chain.joint_variables)
    # ‖T·b‖² = ‖b‖² + 2 p·(R b) + ‖p‖² for the unit-orthogonal R of the target
    rotated = target[:3, :3] * tip
    inner = (tip_length + ring.expand(2 * sum(target[k, 3] * rotated[k] for k in range(3))
                                      + sum(target[k, 3] ** 2 for k in range(3))))
    point = rotated + target[:3, 3]
    seen_length = squared_length(chain.steps(i, chain.first_frame), variables, point, inner, memo, ring)
    there_length = squared_length(chain.steps(i, j), variables, memo=memo, ring=ring)
    return Equation(seen_length, there_length, _kind(3, j == chain.last_frame),
                    ("squared length of ", Frame(i), "T", Frame(j)), (i, j), distance=True)


def _kind(column: int, to_last: bool) -> str:
    """"position" for the tip's position, "orientation" for a rotation element, "mixed" for the
    position of an inner frame, which the target's rotation and position give together."""
    return "orientation" if column < 3 else "position" if to_last else "mixed"

