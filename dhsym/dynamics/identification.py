"""The regressor as a lecture on identification prints it: the base parameters (the combinations of
the standard inertial parameters that the torques identify, dhsym.dynamics.base) and the columns of
the base regressor Y_b, τ = Y_b(q, q̇, q̈) π_b, in textbook form.

The columns are written out only when they are small enough to read: their terms multiplied out
are counted on the regressor's names first, and past MAX_REGRESSOR_TERMS (the PUMA 560's 55,000)
only the base parameters are given.

>>> import dhsym
>>> arm = dhsym.load("planar2r")
>>> found = identification(arm.chain, arm.filled_masses())
>>> [(p.name, p.value) for p in found.base][:2]
[('ZZR_1', 2*MX_1*a_1 + ZZ_1 + a_1**2*m_1 + a_1**2*m_2), ('ZZR_2', ZZ_2 - a_2**2*m_2)]
>>> found.columns[0].values
(theta_1_ddot, 0)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel
from .base import base_parameters
from .polynomial import multiplied_out
from .textbook import compact, expanded_terms

MAX_REGRESSOR_TERMS = 5_000  # of the base regressor's columns multiplied out: a SCARA has 200, the PUMA 55,000


@dataclass(frozen=True)
class BaseParameter:
    """One identifiable combination: its name (Khalil's, ZZR_1 for a grouped one) and value."""

    name: str
    value: sympy.Expr

    @property
    def symbol(self) -> sympy.Symbol:
        return sympy.Symbol(self.name, real=True)


@dataclass(frozen=True)
class RegressorColumn:
    """∂τ/∂π_b for one base parameter: the column of Y_b, one entry per joint."""

    parameter: BaseParameter
    values: tuple


@dataclass(frozen=True)
class Identification:
    """The base parameters, the columns of Y_b (empty when too large: `terms` says how large), the
    standard parameters that move no joint, and the motion symbols (q, q̇, q̈)."""

    base: tuple
    columns: tuple
    unidentifiable: tuple
    terms: int
    variables: tuple
    rates: tuple
    accelerations: tuple


def identification(chain: Chain, masses: MassModel, first_joint: int = 1) -> Identification:
    """The base parameters of `chain` (gravity as in the filled `masses`) and Y_b's columns; the
    standard parameters are numbered from `first_joint`."""
    found = base_parameters(chain, masses, first_joint)
    base = tuple(BaseParameter(name, value) for name, value in zip(found.names, found.values))
    Y = found.Y
    tape = found.regressor.tape
    terms = expanded_terms(tape, list(Y))
    columns = ()
    if terms <= MAX_REGRESSOR_TERMS:
        written = iter(compact(x, multiplied=True) for x in multiplied_out(tape, list(Y.T)))
        columns = tuple(RegressorColumn(p, tuple(next(written) for _ in range(Y.rows))) for p in base)
    result = found.regressor
    return Identification(base, columns, tuple(found.unidentifiable), terms, result.variables, result.rates,
                          result.accelerations)
