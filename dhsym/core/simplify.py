"""Contraction of a chain of elementary steps into textbook form.

The strategy works on the chain's structure instead of searching the expanded product:

1. Cut the steps into *blocks*. Inside a block every rotation keeps the z axis (a joint
   rotation Rz, or a twist of 0 or π), so the joint axes of a block are parallel and their
   angles add up: a twist of π turns the following angles negative, which is where
   SCARA's ``cos(θ1+θ2−θ4)`` comes from. A twist of any other angle starts a new block.
2. Write each block in closed form: its rotation is ``F·Rz(φ)`` (``F`` the block's leading
   twist) and its origin is ``F·Σ Rz(φ_k)·v_k``, the planar-arm sum ``l1 c1 + l2 c12``.
3. Multiply the blocks from the tip inwards, ``B1·(B2·(…·Bg))``, and after each product
   collect every element by the outer block's cos/sin. That nesting is Craig's grouping by
   joint order: ``c1(a2 c2 + a3 c23 − d4 s23) − d3 s1``.

No step expands or searches, so the cost grows linearly with the chain, and the result
equals the plain product by construction (the tests prove it on random chains anyway).

>>> import sympy
>>> from dhsym.core.transforms import Step
>>> t1, t2, l1, l2 = sympy.symbols("theta_1 theta_2 l_1 l_2", real=True)
>>> m = contract([Step("Rz", t1), Step("Tx", l1), Step("Rz", t2), Step("Tx", l2)], {t1, t2})
>>> m[0, 3]
l_1*cos(theta_1) + l_2*cos(theta_1 + theta_2)
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy
from sympy.core.cache import cacheit

from .transforms import Step, product, rotation


@dataclass
class Block:
    """A run of steps whose joint axes are all parallel, after a leading fixed twist."""

    lead: list[Step] = field(default_factory=list)
    body: list[Step] = field(default_factory=list)


def contract(steps, joint_variables) -> sympy.Matrix:
    """The product of `steps` in compact, joint-ordered form."""
    joint_variables = frozenset(joint_variables)
    blocks = split_into_blocks(merge_steps(steps))
    result = None
    for block in reversed(blocks):
        outer = block_matrix(block)
        if result is None:
            result = outer
        else:
            atoms = _block_variables(block) & joint_variables
            result = compose(outer, result, atoms)
    return result if result is not None else sympy.eye(4)


def merge_steps(steps) -> list[Step]:
    """Drop steps of zero and merge neighbours of the same kind (Rx(π/2)·Rx(−π/2) = I)."""
    merged: list[Step] = []
    for step in steps:
        if merged and merged[-1].kind == step.kind:
            step = Step(step.kind, merged.pop().value + step.value)
        if step.value != 0:
            merged.append(step)
    return merged


def keeps_z_axis(step: Step) -> bool:
    """True if the step maps the z axis onto ±z: a translation, any Rz, or Rx/Ry by kπ."""
    if not step.is_rotation or step.kind == "Rz":
        return True
    return _half_turns(step.value) is not None


def _half_turns(angle) -> int | None:
    """k if angle = kπ exactly, else None."""
    ratio = angle / sympy.pi
    return int(ratio) if ratio.is_Integer else None


def split_into_blocks(steps) -> list[Block]:
    blocks = [Block()]
    for step in steps:
        if keeps_z_axis(step):
            blocks[-1].body.append(step)
        elif blocks[-1].body:
            blocks.append(Block(lead=[step]))
        else:
            blocks[-1].lead.append(step)
    return [b for b in blocks if b.lead or b.body]


def block_matrix(block: Block) -> sympy.Matrix:
    """Closed form of one block: rotation F·Rz(φ)·Rx(π)^flip, origin F·Σ Rz(φ_k)·v_k."""
    return _block_matrix(tuple(block.lead), tuple(block.body)).as_mutable()


# A derivation asks for the same blocks many times (its estimates, its transforms, its Jacobian: the
# PUMA's inverse kinematics 98 times for 23 blocks). SymPy's own cache keeps them, so that
# sympy.core.cache.clear_cache() forgets them with everything else.
@cacheit
def _block_matrix(lead: tuple, body: tuple) -> sympy.ImmutableMatrix:
    angle, flipped = sympy.Integer(0), False
    origin = [sympy.Integer(0)] * 3
    sign = lambda value: -value if flipped else value  # noqa: E731 - a twist of π mirrors y and z
    for step in body:
        if step.kind == "Rz":
            angle += sign(step.value)
        elif step.is_rotation:
            if _half_turns(step.value) % 2:
                if step.kind == "Ry":  # Ry(π) = Rz(π)·Rx(π)
                    angle += sign(sympy.pi)
                flipped = not flipped
        else:
            v = [sympy.Integer(0)] * 3
            v[step.axis] = step.value if step.kind == "Tx" else sign(step.value)
            c, s = sympy.cos(angle), sympy.sin(angle)
            origin = [origin[0] + v[0] * c - v[1] * s, origin[1] + v[0] * s + v[1] * c, origin[2] + v[2]]
    rotated = rotation(2, angle) * (rotation(0, sympy.pi) if flipped else sympy.eye(4))
    rotated[:3, 3] = sympy.Matrix(origin)
    return sympy.ImmutableMatrix(product(lead) * rotated)


def compose(outer: sympy.Matrix, inner: sympy.Matrix, atoms) -> sympy.Matrix:
    """outer·inner, each element collected by the cos/sin of the variables in `atoms`."""
    result = sympy.eye(4)
    for r in range(3):
        for c in range(4):
            terms = [outer[r, m] * inner[m, c] for m in range(3) if outer[r, m] != 0 and inner[m, c] != 0]
            if c == 3:
                terms.append(outer[r, 3])
            result[r, c] = collect_by_trig(sympy.Add(*terms), atoms)
    return result


def collect_by_trig(expr: sympy.Expr, variables) -> sympy.Expr:
    """Group the terms of a sum by their product of cos/sin factors of `variables`.

    >>> x, a, b = sympy.symbols("x a b", real=True)
    >>> collect_by_trig(a*sympy.cos(x) + b*sympy.cos(x) + a, {x})
    a + (a + b)*cos(x)
    """
    if not variables or not expr.is_Add:
        return expr
    groups: dict[sympy.Expr, list[sympy.Expr]] = {}
    for term in expr.args:
        key, rest = [], []
        for factor in sympy.Mul.make_args(term):
            (key if _is_trig_of(factor, variables) else rest).append(factor)
        groups.setdefault(sympy.Mul(*key), []).append(sympy.Mul(*rest))
    return sympy.Add(*(_group(key, rests) for key, rests in groups.items()))


def _group(key: sympy.Expr, terms) -> sympy.Expr:
    """key·(Σ terms), pulling out a minus sign that every term shares: −s1(s4 c5 c6 + c4 s6)."""
    total = sympy.Add(*terms)
    if key != 1 and total.is_Add and all(t.could_extract_minus_sign() for t in total.args):
        return sympy.Mul(-1, key, -total)
    return key * total


def _is_trig_of(factor: sympy.Expr, variables) -> bool:
    base = factor.base if factor.is_Pow else factor
    return isinstance(base, (sympy.cos, sympy.sin)) and bool(base.free_symbols & variables)


def _block_variables(block: Block) -> set:
    return {s for step in block.body if step.kind == "Rz" for s in step.value.free_symbols}
