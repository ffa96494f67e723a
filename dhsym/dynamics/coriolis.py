"""C(q, q̇) in the Christoffel form, and the Christoffel symbols themselves.

Spong's Christoffel symbols are c_ijk = ½(∂d_kj/∂q_i + ∂d_ki/∂q_j − ∂d_ij/∂q_k), and
C_kj = Σ_i c_ijk q̇_i. Summed over i, the first term is the time derivative of d_kj and the other
two are derivatives of the momenta p = M q̇, so that

    C = ½ (Ṁ + P − Pᵀ),   P_kj = ∂p_k/∂q_j,

with Ṁ and P found by carrying derivatives through the names of M (`dhsym.dynamics.tape`): one
pass along q̇ and one per joint that M depends on (never q_1), instead of one per symbol. This C
is the one for which Ṁ − 2C is skew-symmetric, and the one Pinocchio's computeCoriolisMatrix gives.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> from dhsym.dynamics.composite import mass_matrix
>>> from dhsym.dynamics.model import rigid_model
>>> from dhsym.dynamics.tape import Tape
>>> tape = Tape()
>>> model = rigid_model(dhsym.load("planar2r").chain, MassModel().filled(2))
>>> C = coriolis_matrix(tape, model, mass_matrix(tape, model))
>>> sympy.expand(tape.expanded(C[1, 0]))
a_1*a_2*m_2*theta_1_dot*sin(theta_2) + a_1*m_2*theta_1_dot*x_c2*sin(theta_2) + a_1*m_2*theta_1_dot*y_c2*cos(theta_2)
"""
from __future__ import annotations

import sympy

from .newton_euler import rate_symbols
from .tape import Tape, differentiate


def coriolis_matrix(tape: Tape, model, M: sympy.Matrix, rates=None) -> sympy.Matrix:
    """C(q, q̇) from the mass matrix M (entries named on `tape`)."""
    n = model.n
    rates = rate_symbols(model.variables) if rates is None else rates
    moving = [k for k, v in enumerate(model.variables) if any(v in tape.depends_on(x) for x in M)]
    dot = differentiate(tape, list(M), dict(zip(model.variables, rates)))
    momenta = [tape.name(sympy.Add(*[M[k, j] * rates[j] for j in range(n)])) for k in range(n)]
    P = sympy.zeros(n, n)
    for j in moving:
        P[:, j] = sympy.Matrix(differentiate(tape, momenta, {model.variables[j]: 1}))
    C = sympy.zeros(n, n)
    for k in range(n):
        for j in range(n):
            C[k, j] = tape.name((dot[k * n + j] + P[k, j] - P[j, k]) / 2)
    return C


def christoffel_symbols(tape: Tape, model, M: sympy.Matrix) -> dict:
    """{(i, j, k): c_ijk} for the symbols that are not zero, joints counted from 1, each a name
    on the tape; c_ijk = c_jik, both listed."""
    n = model.n
    derivatives = {}
    for i, variable in enumerate(model.variables):
        if any(variable in tape.depends_on(x) for x in M):
            derivatives[i] = sympy.Matrix(n, n, differentiate(tape, list(M), {variable: 1}))
    zero = sympy.zeros(n, n)
    symbols = {}
    for i in range(n):
        for j in range(n):
            for k in range(n):
                parts = (derivatives.get(i, zero)[k, j], derivatives.get(j, zero)[k, i], derivatives.get(k, zero)[i, j])
                if not any(parts):  # most are zero: skip building them
                    continue
                value = (parts[0] + parts[1] - parts[2]) / 2
                if value != 0:
                    symbols[i + 1, j + 1, k + 1] = tape.name(value)
    return symbols
