"""Craig's outward velocity propagation, link by link (Introduction to Robotics, § 5.6).

For a revolute joint i+1 in the modified convention (the axis is z_{i+1}):

    ⁱ⁺¹ωᵢ₊₁ = ⁱ⁺¹Rᵢ ⁱωᵢ + θ̇ᵢ₊₁ ẑ,        ⁱ⁺¹vᵢ₊₁ = ⁱ⁺¹Rᵢ (ⁱvᵢ + ⁱωᵢ × ⁱPᵢ₊₁)

and for a prismatic one ``ⁱ⁺¹ωᵢ₊₁ = ⁱ⁺¹Rᵢ ⁱωᵢ``, ``ⁱ⁺¹vᵢ₊₁ = ⁱ⁺¹Rᵢ (ⁱvᵢ + ⁱωᵢ × ⁱPᵢ₊₁) + ḋᵢ₊₁ ẑ``.
In the standard convention (Spong) the axis of joint i is z_{i-1}, so its rate is added in
frame i−1 before the rotation, and the link is taken in frame i, where it is short:
``ⁱvᵢ = ⁱRᵢ₋₁ ⁱ⁻¹vᵢ₋₁ + ⁱωᵢ × (−ⁱpᵢ₋₁)``. Fixed base and tool steps add no rate.
The joint rates are symbols named after the joint variables (`rate_symbols`); the velocities are linear in them, and
their coefficients are the columns of the Jacobian of the last frame, in the last frame.

>>> import dhsym
>>> arm = dhsym.load("planar2r").chain
>>> steps = propagate(arm)
>>> steps[-1].velocity[1]
a_2*theta_2_dot + theta_1_dot*(a_1*cos(theta_2) + a_2)
>>> propagated_jacobian(arm, steps)[:2, :]
Matrix([
[      a_1*sin(theta_2),   0],
[a_1*cos(theta_2) + a_2, a_2]])
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy
from sympy.simplify.fu import TR10i

from ..core.chain import Chain, Frame, plain
from ..core.simplify import collect_by_trig
from ..core.size import length
from ..core.vectors import cross
from .jacobian import ZERO, axis_frame, derivative, gain, rotate


@dataclass(frozen=True)
class Step:
    """ω and v of frame `frame` (the chain's), in that frame; `joint` is the joint whose rate enters
    here (None for a fixed base or tool step)."""

    frame: Frame
    joint: int | None
    omega: tuple
    velocity: tuple


def rate_symbols(chain: Chain) -> list[sympy.Symbol]:
    """θ̇ᵢ or ḋᵢ of each joint, as real symbols named `<variable>_dot`."""
    return [sympy.Symbol(f"{v.name}_dot", real=True) for v in chain.joint_variables]


def propagate(chain: Chain) -> list[Step]:
    """ω and v of every frame, from the first (at rest) to the last; each step's `frame` is the chain's."""
    rates = rate_symbols(chain)
    variables = frozenset(chain.joint_variables) | frozenset(rates)
    frames = plain(chain).frames
    omega, velocity = ZERO, ZERO
    out = [Step(frames[0], None, omega, velocity)]
    for before, frame in zip(frames, frames[1:]):
        joint = frame if isinstance(frame, int) and frame >= 1 else None
        rate = rates[joint - 1] * gain(chain, joint) if joint else 0
        prismatic = bool(joint) and chain.rows[joint - 1].joint == "P"
        z = (0, 0, rate)
        if joint and axis_frame(chain, joint) == before:  # the axis is z of the frame before (standard DH)
            omega = rotate(chain, frame, before, omega if prismatic else _add(omega, z))
            back = chain.transform(frame, before)[:3, 3]  # ⁱp_{i−1}: the link, short in frame i
            velocity = _add(rotate(chain, frame, before, _add(velocity, z) if prismatic else velocity),
                            cross(omega, [-x for x in back]))
        else:
            velocity = _add(velocity, cross(omega, chain.transform(before, frame)[:3, 3]))
            omega, velocity = rotate(chain, frame, before, omega), rotate(chain, frame, before, velocity)
            if joint:
                omega, velocity = (omega, _add(velocity, z)) if prismatic else (_add(omega, z), velocity)
        omega, velocity = _tidy(omega, rates, variables), _tidy(velocity, rates, variables)
        out.append(Step(frame, joint, omega, velocity))
    return out


def propagated_jacobian(chain: Chain, steps: list[Step] | None = None) -> sympy.Matrix:
    """The Jacobian read off the last step: column i holds the coefficients of joint i's rate."""
    steps = propagate(chain) if steps is None else steps
    last = steps[-1].velocity + steps[-1].omega
    variables = frozenset(chain.joint_variables)
    return sympy.Matrix([[collect_by_trig(derivative(x, rate), variables) for rate in rate_symbols(chain)]
                         for x in last])


def _add(*vectors) -> tuple:
    return tuple(sympy.Add(*parts) for parts in zip(*vectors))


def _tidy(vector, rates, variables) -> tuple:
    """Each entry as Σ (joint rate)·(its coefficient), each coefficient collected by cos/sin and
    with the sum formulas applied where they shorten it, as Craig does by hand at each step
    (c2 s3 + s2 c3 = s23)."""
    joints = frozenset(v for v in variables if v not in rates)
    out = []
    for x in vector:
        parts = [rate * _sum_formulas(collect_by_trig(derivative(x, rate), joints), joints)
                 for rate in rates if x.has(rate)]
        out.append(sympy.Add(*parts) if parts else sympy.Integer(0))
    return tuple(collect_by_trig(sympy.Add(*sympy.Add.make_args(x)), joints) for x in out)


def _sum_formulas(expr, joints):
    """The shortest of expr and expr with sin a cos b + cos a sin b = sin(a + b) (and the other
    three) applied, as nested or after multiplying out: l1 s2 c3 + (l2 + l1 c2) s3 = l1 s23 + l2 s3.

    >>> t2, t3, l1, l2 = sympy.symbols("theta_2 theta_3 l_1 l_2", real=True)
    >>> c, s = sympy.cos, sympy.sin
    >>> _sum_formulas(l1*s(t2)*c(t3) + (l2 + l1*c(t2))*s(t3), {t2, t3})
    l_1*sin(theta_2 + theta_3) + l_2*sin(theta_3)
    """
    if not expr.has(sympy.sin, sympy.cos):
        return expr
    candidates = [expr, TR10i(expr), collect_by_trig(TR10i(sympy.expand(expr)), joints)]
    return min(candidates, key=length)
