"""The Newton–Euler recursion (Craig, Introduction to Robotics, § 6.5), link by link in the joint
frames, on a tape: the joint torques τ(q, q̇, q̈) in a few hundred operations.

Outward, for link i+1 (a revolute joint; a prismatic one adds q̇, q̈ to the linear terms instead):

    ω_{i+1} = R ω_i + q̇ ẑ,   ω̇_{i+1} = R ω̇_i + R ω_i × q̇ ẑ + q̈ ẑ,
    v̇_{i+1} = R (v̇_i + ω̇_i × P + ω_i × (ω_i × P)),

with R the rotation from J_i into J_{i+1} and P the origin of J_{i+1} in J_i; the base starts at
rest with v̇_0 = −g, so that gravity comes out of the same sums. Each link's force and moment
about its frame's origin are written with the first moment h = m·c and the inertia about the
origin (Khalil's form, linear in the inertial parameters):

    F = m v̇ + ω̇ × h + ω × (ω × h),   N = I_o ω̇ + ω × I_o ω + h × v̇.

Inward: f_i = F_i + R f_{i+1}, n_i = N_i + R n_{i+1} + P × R f_{i+1}, and τ_i is the z entry of n_i
(revolute) or of f_i (prismatic).

>>> from dhsym.core.chain import Chain, DHRow
>>> from dhsym.core.inertia import LinkInertia, MassModel
>>> from dhsym.dynamics.model import rigid_model
>>> from dhsym.dynamics.tape import Tape
>>> q, l, m, g = sympy.symbols("q l m g", real=True)
>>> pendulum = Chain([DHRow.revolute(q)], "modified")   # a point mass m at (l, 0, 0), gravity along −y
>>> masses = MassModel((LinkInertia(m, (l, 0, 0), (0,) * 6),), gravity=(0, -g, 0))
>>> tape = Tape()
>>> steps = newton_euler(tape, rigid_model(pendulum, masses))
>>> sympy.expand(tape.expanded(steps.torques[0]))
g*l*m*cos(q) + l**2*m*q_ddot
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from .frames import add, cross, into_next, into_previous, position, scale, times_tensor
from .model import RigidModel
from .tape import Tape

ZERO = (sympy.Integer(0),) * 3


def rate_symbols(variables, order: int = 1) -> list:
    """q̇ (order 1) or q̈ (order 2) of each joint variable: `theta_1_dot`, `theta_1_ddot`."""
    suffix = "_dot" if order == 1 else "_ddot"
    return [sympy.Symbol(f"{v.name}{suffix}", real=True) for v in variables]


@dataclass(frozen=True)
class Outward:
    """Link i's motion in J_i: angular velocity and acceleration, the acceleration of the origin,
    and the force F and moment N that move it."""

    link: int
    omega: tuple
    omega_dot: tuple
    acceleration: tuple
    force: tuple
    moment: tuple


@dataclass(frozen=True)
class Inward:
    """What link i−1 exerts on link i, in J_i, and the joint's torque (or force)."""

    link: int
    force: tuple
    moment: tuple
    torque: sympy.Expr


@dataclass(frozen=True)
class NewtonEuler:
    """Both passes, link by link (names on the tape), and τ."""

    outward: tuple
    inward: tuple

    @property
    def torques(self) -> list:
        return [step.torque for step in self.inward]


def newton_euler(tape: Tape, model: RigidModel, rates=None, accelerations=None, gravity: bool = True) -> NewtonEuler:
    """τ of `model` for joint rates and accelerations (symbols named after the joint variables
    unless given; zeros give the gravity torques alone); without `gravity` the base does not
    accelerate."""
    rates = rate_symbols(model.variables) if rates is None else rates
    accelerations = rate_symbols(model.variables, 2) if accelerations is None else accelerations
    omega = omega_dot = ZERO
    acceleration = tape.vector(-x for x in model.gravity) if gravity else ZERO
    outward = []
    for k, body in enumerate(model.bodies):
        reach = position(tape, body)
        acceleration = add(tape, acceleration, cross(tape, omega_dot, reach),
                           cross(tape, omega, cross(tape, omega, reach)))
        acceleration = into_next(tape, body, acceleration)
        turned, omega_dot = into_next(tape, body, omega), into_next(tape, body, omega_dot)
        rate, change = body.gain * rates[k], body.gain * accelerations[k]
        if body.joint == "R":
            omega = add(tape, turned, (0, 0, rate))
            omega_dot = add(tape, omega_dot, (rate * turned[1], -rate * turned[0], change))
        else:
            omega = turned
            acceleration = add(tape, acceleration, cross(tape, omega, (0, 0, 2 * rate)), (0, 0, change))
        outward.append(_loads(tape, k + 1, body, omega, omega_dot, acceleration))
    return NewtonEuler(tuple(outward), tuple(_inward(tape, model, outward)))


def _loads(tape: Tape, link: int, body, omega, omega_dot, acceleration) -> Outward:
    h = body.first_moment
    force = add(tape, scale(tape, body.mass, acceleration), cross(tape, omega_dot, h),
                cross(tape, omega, cross(tape, omega, h)))
    moment = add(tape, times_tensor(tape, body.inertia, omega_dot),
                 cross(tape, omega, times_tensor(tape, body.inertia, omega)), cross(tape, h, acceleration))
    return Outward(link, omega, omega_dot, acceleration, force, moment)


def _inward(tape: Tape, model: RigidModel, outward: list) -> list:
    force, moment = ZERO, ZERO
    steps = []
    for k in range(model.n - 1, -1, -1):
        if k + 1 < model.n:
            after = model.bodies[k + 1]
            pushed = into_previous(tape, after, force)
            moment = add(tape, into_previous(tape, after, moment), cross(tape, position(tape, after), pushed))
            force = pushed
        force = add(tape, force, outward[k].force)
        moment = add(tape, moment, outward[k].moment)
        torque = tape.name(model.bodies[k].gain * (moment[2] if model.bodies[k].joint == "R" else force[2]))

        steps.append(Inward(k + 1, force, moment, torque))
    return steps[::-1]
