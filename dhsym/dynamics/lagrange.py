"""The Euler–Lagrange route, as Spong derives it: each link's energies from its centre-of-mass
Jacobian, in the first frame.

For link i, with r_ci its centre of mass in the first frame (the contracted ⁰T_i applied to the
com the robot file gives in frame i), Jv_ci = ∂r_ci/∂q, Jω_i the axes of joints 1..i (revolute
ones) and R_i the orientation of frame i:

    K_i = ½ m_i q̇ᵀ Jv_ciᵀ Jv_ci q̇ + ½ q̇ᵀ Jω_iᵀ R_i I_i R_iᵀ Jω_i q̇,   P_i = −m_i gᵀ r_ci,

so that M = Σ m_i Jv_ciᵀ Jv_ci + Jω_iᵀ R_i I_i R_iᵀ Jω_i and φ_k = ∂P/∂q_k. The links' parameters
are used in the robot's own frames, with no change of frame: this route checks the joint-frame
recursions (dhsym.dynamics.composite, newton_euler) independently, and its records are the steps
a lecture shows. The potential energy, written with the contracted transforms, gives g in
textbook form directly: Spong's φ1 = (m1 lc1 + m2 l1) g c1 + m2 lc2 g c12.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> arm = dhsym.load("planar2r").chain
>>> energies = link_energies(arm, MassModel().filled(2))
>>> energies[0].com[0]
-y_c1*sin(theta_1) + (a_1 + x_c1)*cos(theta_1)
>>> gravity_vector(arm, MassModel().filled(2), energies).T
Matrix([[0, 0]])
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel, tensor
from ..core.simplify import collect_by_trig
from ..velocity.jacobian import axis, derivative, gain


@dataclass(frozen=True)
class LinkEnergy:
    """Link i's part of the Lagrangian, in the first frame: its centre of mass r_ci, Jv_ci
    (3×n), Jω_i (3×n), the orientation R_i of frame i, and its potential energy P_i."""

    link: int
    com: tuple
    linear: sympy.Matrix
    angular: sympy.Matrix
    rotation: sympy.Matrix
    potential: sympy.Expr

    def kinetic(self, mass, inertia, rates) -> sympy.Expr:
        """K_i for the joint rates q̇ (symbols), linear and angular parts added."""
        qd = sympy.Matrix(rates)
        v, w = self.linear * qd, self.rotation.T * self.angular * qd
        return (mass * (v.T * v)[0] + (w.T * tensor(inertia) * w)[0]) / 2


def link_energies(chain: Chain, masses: MassModel) -> list[LinkEnergy]:
    """The energy records of links 1..n with the filled `masses`."""
    first = chain.frames[0]
    variables = chain.joint_variables
    atoms = frozenset(variables)
    gravity = sympy.Matrix(masses.gravity)
    out = []
    for i, link in enumerate(masses.links, 1):
        pose = chain.transform(first, i)
        com = [collect_by_trig(x, atoms) for x in pose[:3, :3] * sympy.Matrix(link.com) + pose[:3, 3]]
        linear = sympy.Matrix([[collect_by_trig(derivative(x, v), atoms) if k < i else 0
                                for k, v in enumerate(variables)] for x in com])
        columns = [[gain(chain, k) * x for x in axis(chain, first, k)] if k <= i and chain.rows[k - 1].joint == "R"
                   else [0, 0, 0] for k in range(1, chain.n + 1)]
        angular = sympy.Matrix(columns).T

        potential = -link.mass * (gravity.T * sympy.Matrix(com))[0]
        out.append(LinkEnergy(i, tuple(com), linear, angular, pose[:3, :3], potential))
    return out


def mass_matrix(chain: Chain, masses: MassModel, energies: list[LinkEnergy] | None = None) -> sympy.Matrix:
    """M = Σ m_i Jv_ciᵀ Jv_ci + Jω_iᵀ R_i I_i R_iᵀ Jω_i, as the products give it (not simplified)."""
    energies = link_energies(chain, masses) if energies is None else energies
    total = sympy.zeros(chain.n, chain.n)
    for energy, link in zip(energies, masses.links):
        body = energy.rotation.T * energy.angular
        total += link.mass * energy.linear.T * energy.linear + body.T * tensor(link.inertia) * body
    return total


def gravity_vector(chain: Chain, masses: MassModel, energies: list[LinkEnergy] | None = None) -> sympy.Matrix:
    """φ_k = ∂P/∂q_k, P the total potential energy, each entry collected by cos/sin."""
    energies = link_energies(chain, masses) if energies is None else energies
    potential = sympy.Add(*[energy.potential for energy in energies])
    atoms = frozenset(chain.joint_variables)
    return sympy.Matrix([collect_by_trig(sympy.expand(derivative(potential, v)), atoms) for v in chain.joint_variables])
