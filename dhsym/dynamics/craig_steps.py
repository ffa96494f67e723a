"""The Newton–Euler recursion as Craig prints it (Introduction to Robotics, § 6.5), link by link in
the joint frames: outward, each link's ω, ω̇, the acceleration v̇ of its frame's origin and v̇_C of
its centre of mass, and the force F = m v̇_C and moment N = ᶜI ω̇ + ω × ᶜI ω that move it; inward,
the force f and moment n that the link before exerts on it, and the joint's τ (the z entry of n, or
of f for a prismatic joint). The base accelerates upward, v̇_0 = −g, so that gravity comes out of
the same sums.

The values are the recursion's (dhsym.dynamics.newton_euler) written out and multiplied out, in
textbook form; F and N about the centre of mass are Craig's, worked out from ω, ω̇ and v̇. How much
there is to write is counted on the recursion's names before anything is written out
(`steps_terms`), and a chain past MAX_STEP_TERMS is refused.

The joint frames are a modified-DH chain's own frames; a standard-DH chain's frame i sits at the far
end of link i, and the joint frame J_i of link i is on joint i's axis (dhsym.dynamics.model).

>>> import dhsym
>>> arm = dhsym.load("spong_elbow")
>>> steps = newton_euler_steps(arm.chain, arm.filled_masses())
>>> steps.outward[0].omega, steps.outward[0].com_acceleration[1]
((0, 0, q_1_dot), g*cos(q_1) + l_c1*q_1_ddot)
>>> steps.inward[1].torque.args[1]
l_c2*m_2*(g*cos(q_1 + q_2) + l_1*q_1_ddot*cos(q_2) + l_1*q_1_dot**2*sin(q_2) + l_c2*(q_1_ddot + q_2_ddot))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel, entries, tensor
from ..core.vectors import cross
from ..errors import UserError
from .polynomial import angle_sums, multiplied_out
from .program import dynamics_program
from .textbook import compact, expanded_terms

MAX_STEP_TERMS = 6_000  # of every vector of both passes multiplied out: a SCARA has 1,400, the PUMA 560 30,000


@dataclass(frozen=True)
class OutwardStep:
    """Link i in its joint frame: ω, ω̇, v̇ (its origin), v̇_C (its centre of mass), F and N."""

    link: int
    omega: tuple
    omega_dot: tuple
    acceleration: tuple
    com_acceleration: tuple
    force: tuple
    moment: tuple


@dataclass(frozen=True)
class InwardStep:
    """What link i−1 exerts on link i, in link i's joint frame: f, n (about its origin), and τ_i."""

    link: int
    force: tuple
    moment: tuple
    torque: sympy.Expr


@dataclass(frozen=True)
class NewtonEulerSteps:
    """Both passes; each link's centre of mass and inertia about it, in its joint frame; whether the
    joint frames are other than the robot's own frames (a standard-DH chain)."""

    outward: tuple
    inward: tuple
    centres: tuple
    inertias: tuple
    own_frames: bool


def steps_terms(chain: Chain, masses: MassModel) -> int:
    """How many terms both passes' vectors would have multiplied out (counted on the names)."""
    program = dynamics_program(chain, masses, parts=("tau",))
    return expanded_terms(program.tape, _names(program.steps))


def _names(steps) -> list:
    out = []
    for step in steps.outward:
        out += [*step.omega, *step.omega_dot, *step.acceleration, *step.force]
    for step in steps.inward:
        out += [*step.force, *step.moment, step.torque]
    return out


def newton_euler_steps(chain: Chain, masses: MassModel) -> NewtonEulerSteps:
    """The records of both passes for `chain` with the filled `masses` (see the module's docstring)."""
    program = dynamics_program(chain, masses, parts=("tau",))
    names = _names(program.steps)
    size = expanded_terms(program.tape, names)
    if size > MAX_STEP_TERMS:
        raise UserError(f"the Newton-Euler steps would have about {size:,} terms multiplied out, more than the "
                        f"{MAX_STEP_TERMS:,} dhsym shows; ask for fewer links (--to), or --method lagrange")
    bodies = program.model.bodies
    weights = [body.mass for body in bodies if isinstance(body.mass, sympy.Symbol)]
    written = iter(compact(x, weights, multiplied=True)
                   for x in multiplied_out(program.tape, names, angle_sums(bodies[1:])))
    centres, inertias, outward = [], [], []
    for step, body in zip(program.steps.outward, bodies):
        omega, omega_dot, acceleration, force = (tuple(next(written) for _ in range(3)) for _ in range(4))
        centre = tuple(sympy.cancel(h / body.mass) for h in body.first_moment)
        about = tensor(body.inertia) - body.mass * ((sympy.Matrix(centre).T * sympy.Matrix(centre))[0]
                                                     * sympy.eye(3) - sympy.Matrix(centre) * sympy.Matrix(centre).T)
        about = tensor([sympy.expand(x) for x in entries(about)])
        com = [a + b + c for a, b, c in zip(acceleration, cross(omega_dot, centre),
                                             cross(omega, cross(omega, centre)))]
        spin = about * sympy.Matrix(omega_dot) + sympy.Matrix(cross(omega, about * sympy.Matrix(omega)))
        outward.append(OutwardStep(step.link, omega, omega_dot, acceleration, tuple(compact(x, weights) for x in com),
                                   force, tuple(compact(x, weights) for x in spin)))
        centres.append(centre)
        inertias.append(entries(about))
    inward = [InwardStep(step.link, tuple(next(written) for _ in range(3)), tuple(next(written) for _ in range(3)),
                         next(written)) for step in program.steps.inward]
    return NewtonEulerSteps(tuple(outward), tuple(inward), tuple(centres), tuple(inertias),
                            chain.convention == "modified" and not chain.base)
