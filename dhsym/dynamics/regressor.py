"""The dynamics as linear in the inertial parameters: τ = Y(q, q̇, q̈) π.

π holds each link's ten standard inertial parameters, about the origin of the robot's own frame
i and along its axes (Khalil's names): the inertia XX_i, XY_i, XZ_i, YY_i, YZ_i, ZZ_i, the first
moments MX_i, MY_i, MZ_i (mass times the centre of mass) and the mass m_i. The Newton–Euler
recursion written with the first moment and the inertia about the origin (dhsym.dynamics.
newton_euler) is linear in them, so column j of Y is the derivative of τ by π_j, carried through
the program's names (`dhsym.dynamics.tape.differentiate`); a parameter of link j moves only
τ_1..τ_j.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> result = regressor(dhsym.load("planar2r").chain, MassModel().filled(2))
>>> [p.name for p in result.parameters[:10]]
['XX_1', 'XY_1', 'XZ_1', 'YY_1', 'YZ_1', 'ZZ_1', 'MX_1', 'MY_1', 'MZ_1', 'm_1']
>>> result.tape.expanded(result.Y[1, 15])      # ZZ_2 in τ2: θ̈1 + θ̈2
theta_1_ddot + theta_2_ddot
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel
from .model import rigid_model, standard_parameters
from .newton_euler import newton_euler, rate_symbols
from .tape import Tape, differentiate

ORDER = ("XX", "XY", "XZ", "YY", "YZ", "ZZ", "MX", "MY", "MZ", "m")  # each link's parameters in π


@dataclass(frozen=True)
class Regressor:
    """Y (n × 10n, entries names on `tape`) and π, the standard parameters, in the order of ORDER
    for link 1, then link 2 ...; the joint variables, their rates and accelerations."""

    tape: Tape
    Y: sympy.Matrix
    parameters: tuple
    variables: tuple
    rates: tuple
    accelerations: tuple


def parameter_symbols(number: int) -> tuple:
    """The ten standard parameters of link `number`, in the order of ORDER."""
    mass, moments, inertia = standard_parameters(number)
    xx, yy, zz, xy, xz, yz = inertia
    return (xx, xy, xz, yy, yz, zz, *moments, mass)


def regressor(chain: Chain, masses: MassModel, first_joint: int = 1) -> Regressor:
    """Y and π of `chain`, gravity as in the filled `masses`; parameters numbered from
    `first_joint` (a wrist whose joints are 4..6: XX_4 …)."""
    numbers = range(first_joint, first_joint + chain.n)
    model = rigid_model(chain, masses, [standard_parameters(k) for k in numbers])
    tape = Tape()
    variables = tuple(model.variables)
    rates, accelerations = tuple(rate_symbols(variables)), tuple(rate_symbols(variables, 2))
    torques = newton_euler(tape, model, rates, accelerations).torques
    parameters = tuple(p for k in numbers for p in parameter_symbols(k))
    columns = [differentiate(tape, torques, {p: 1}) for p in parameters]
    Y = sympy.Matrix(chain.n, len(parameters), lambda i, j: columns[j][i])
    return Regressor(tape, Y, parameters, variables, rates, accelerations)
