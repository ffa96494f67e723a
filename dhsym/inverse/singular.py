"""Which degenerate cases of a derivation are singularities that `dhsym jacobian` prints: a
factor of det J, matched up to sign.

Only a factor in the chain's own symbols (joint variables and constants) can be one of det J's;
one that holds the target (px, x_c) never is, and needs no determinant. For a wrist-partitioned
arm det J = det A · det C, and det A holds the first three joints only: a factor in the wrist's
variables alone is one of det C's, the wrist axes' 3×3 determinant, worked out in a few
milliseconds where det A takes most of the time (the same factors `dhsym jacobian` prints).

>>> import dhsym
>>> wrist_factors(dhsym.load("puma560"))
[sin(theta_5)]
"""
from __future__ import annotations

import sympy

from ..velocity.determinant import as_written, determinant, factored, joint_factors
from ..velocity.geometry import wrist_centre
from ..velocity.jacobian import angular_part, axis_frame


def tie_to_jacobian(chain, derivation) -> None:
    """Add to each degenerate case whose expression has a factor of det J the words that say so."""
    joints = set(chain.joint_variables)
    found = []
    for expr, index in derivation.vanishing:
        bases = {f.base if f.is_Pow else f for f in sympy.Mul.make_args(expr) if not f.is_number}
        found.append((index, bases))
    possible = [b for _, bases in found for b in bases if b.free_symbols <= chain.symbols and b.free_symbols & joints]
    if not possible:
        return
    wrist = set(chain.joint_variables[3:])
    if chain.n == 6 and all(b.free_symbols & joints <= wrist for b in possible) and wrist_centre(chain) is not None:
        factors = wrist_factors(chain)
    else:
        factors = determinant(chain).factors
    for index, bases in found:
        matched = [g for g in factors for b in bases if sympy.expand(b - g) == 0 or sympy.expand(b + g) == 0]
        if matched:
            derivation.degenerate[index] += f"; a singularity of J: the factor {matched[0]} of det J"


def wrist_factors(chain) -> list:
    """The factors of det C (the three wrist axes, in the axis frame of joint 5), in the form and
    order that `determinant(chain).factors` gives them."""
    centre, body = wrist_centre(chain), chain.last_frame
    wrist = [angular_part(chain, j, axis_frame(chain, 5), centre, body) for j in (4, 5, 6)]
    value = as_written(factored(factored(sympy.Matrix(wrist).T.det(method="berkowitz"))), chain.numbers)
    return joint_factors(value, chain)
