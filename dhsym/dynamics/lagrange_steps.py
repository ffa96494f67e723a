"""Lagrange's derivation as a lecture shows it (Spong, the chapter on the Euler–Lagrange equations):
each link's centre of mass, its Jacobians and energies, then the Lagrangian's derivatives.

For link i, with r_ci its centre of mass in the first frame, Jv_ci = ∂r_ci/∂q, Jω_i the joints'
axes and ω_i = R_iᵀ Jω_i q̇ its angular velocity in its own frame:

    K_i = ½ m_i q̇ᵀ Jv_ciᵀ Jv_ci q̇  +  ½ ω_iᵀ I_i ω_i,      P_i = −m_i gᵀ r_ci,

so that K = ½ q̇ᵀ M q̇. With L = K − P, ∂L/∂q̇_k = Σ_j d_kj q̇_j, and

    d/dt ∂L/∂q̇_k = Σ_j d_kj q̈_j + Σ_ij ∂d_kj/∂q_i q̇_i q̇_j,
    ∂L/∂q_k = ½ Σ_ij ∂d_ij/∂q_k q̇_i q̇_j − φ_k,

whose difference τ_k collects into the Christoffel form (dhsym.dynamics.equations). The records
hold the values in textbook form; the derivatives of M are listed once each, by name.

How much there is to write is counted first (`steps_terms`): the terms of each link's Jv_ci,
squared, as its kinetic energy multiplies them. The PUMA's six links are past MAX_STEP_TERMS; its
first three are not.

>>> import dhsym
>>> from dhsym.dynamics.derive import derive
>>> arm = dhsym.load("spong_elbow")
>>> steps = lagrange_steps(arm.chain, arm.filled_masses(), derive(arm.chain, arm.filled_masses()))
>>> steps.links[1].kinetic_angular
I_2*(q_1_dot + q_2_dot)**2/2
>>> [(d.i, d.j, d.k) for d in steps.derivatives], steps.derivatives[0].value
([(1, 1, 2), (1, 2, 2)], -2*l_1*l_c2*m_2*sin(q_2))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel, tensor
from ..errors import UserError
from .derive import Dynamics
from .lagrange import link_energies
from .textbook import compact

MAX_STEP_TERMS = 4_000  # Σ over the links of (terms of Jv_ci)²: a SCARA has 1,800, the PUMA's six links 7,100


@dataclass(frozen=True)
class LinkEnergyStep:
    """Link i: its centre of mass r_ci and Jacobians Jv_ci, Jω_i (3 × n) in the first frame, its
    angular velocity ω_i in its own frame, the two parts of its kinetic energy and its potential
    energy; its mass and inertia (about the centre of mass, frame i's axes) for the formulas."""

    link: int
    com: tuple
    linear: sympy.Matrix
    angular: sympy.Matrix
    omega: tuple
    kinetic_linear: sympy.Expr
    kinetic_angular: sympy.Expr
    potential: sympy.Expr


@dataclass(frozen=True)
class MassDerivative:
    """∂d_ij/∂q_k (i ≤ j) that is not zero; `variable` is q_k."""

    i: int
    j: int
    k: int
    variable: sympy.Symbol
    value: sympy.Expr


@dataclass(frozen=True)
class LagrangeEquation:
    """Joint k's derivatives of L, by name: ∂L/∂q̇_k = Σ_j d_kj q̇_j, its time derivative (the d_kj q̈_j and
    the (i, j) of the ∂d_kj/∂q_i q̇_i q̇_j that are not zero) and ∂L/∂q_k (the (i, j), i ≤ j, of the
    ∂d_ij/∂q_k terms, and whether φ_k is there)."""

    k: int
    columns: tuple
    changing: tuple  # ((i, j), ...): ∂d_kj/∂q_i q̇_i q̇_j
    slopes: tuple  # ((i, j), ...): ∂d_ij/∂q_k q̇_i q̇_j, halved when i = j
    gravity: bool
    variables: tuple
    rates: tuple
    accelerations: tuple


@dataclass(frozen=True)
class LagrangeSteps:
    links: tuple
    derivatives: tuple
    equations: tuple


def steps_terms(chain: Chain, masses: MassModel) -> int:
    """Σ over the links of the squared number of terms of Jv_ci multiplied out: the size of what
    the steps write, counted before any of it is simplified."""
    total = 0
    for energy in link_energies(chain, masses):
        terms = sum(len(sympy.Add.make_args(sympy.expand(x))) for x in energy.linear)
        total += terms * terms
    return total


def lagrange_steps(chain: Chain, masses: MassModel, result: Dynamics) -> LagrangeSteps:
    """The records of Lagrange's derivation for `chain` with the filled `masses`, whose results
    (`derive`) are `result`; refused when `steps_terms` is past MAX_STEP_TERMS."""
    size = steps_terms(chain, masses)
    if size > MAX_STEP_TERMS:
        raise UserError(f"Lagrange's steps would write products of about {size:,} terms, more than the "
                        f"{MAX_STEP_TERMS:,} dhsym shows; ask for fewer links (--to), or --method newton-euler")
    rates, n = sympy.Matrix(result.rates), chain.n
    weights = [link.mass for link in masses.links if isinstance(link.mass, sympy.Symbol)]
    links = []
    for energy, link in zip(link_energies(chain, masses), masses.links):
        linear = energy.linear.applyfunc(compact)
        omega = [compact(x) for x in energy.rotation.T * energy.angular * rates]
        square = linear.T * linear
        quadratic = sympy.Add(*[compact(square[a, b], weights) * (1 if a == b else 2) * rates[a] * rates[b]
                                for a in range(n) for b in range(a, n)])
        spin = (sympy.Matrix(omega).T * tensor(link.inertia) * sympy.Matrix(omega))[0]
        spin = spin.xreplace({p: (-p.base) ** p.exp for p in spin.atoms(sympy.Pow)  # (θ̇1 + θ̇2)², not (−θ̇1 − θ̇2)²
                              if p.base.is_Add and p.exp.is_even and p.base.could_extract_minus_sign()})
        links.append(LinkEnergyStep(energy.link, tuple(compact(x) for x in energy.com), linear, energy.angular,
                                    tuple(omega), link.mass * quadratic / 2, spin / 2,
                                    compact(energy.potential, weights)))
    variables = result.variables
    derivatives = tuple(MassDerivative(i + 1, j + 1, k + 1, v, value) for k, v in enumerate(variables)
                        for i in range(n) for j in range(i, n)
                        for value in [compact(sympy.diff(result.M[i, j], v), weights)] if value != 0)
    found = {(d.i, d.j, d.k) for d in derivatives}

    def varies(i, j, k):
        return (min(i, j), max(i, j), k) in found

    equations = tuple(LagrangeEquation(
        k, tuple(j for j in range(1, n + 1) if result.M[k - 1, j - 1] != 0),
        tuple((i, j) for j in range(1, n + 1) for i in range(1, n + 1) if varies(k, j, i)),
        tuple((i, j) for i in range(1, n + 1) for j in range(i, n + 1) if varies(i, j, k)),
        result.g[k - 1] != 0, variables, result.rates, result.accelerations) for k in range(1, n + 1))
    return LagrangeSteps(tuple(links), derivatives, equations)
