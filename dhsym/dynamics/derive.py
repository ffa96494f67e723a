"""The equations of motion τ = M(q) q̈ + C(q, q̇) q̇ + g(q) of a chain, element by element.

`derive` runs the program (`dhsym.dynamics.program`) and writes each element of M, C and g and
each Christoffel symbol that is not zero in textbook form (`dhsym.dynamics.textbook`). Before any
element is written out, their size multiplied out is counted on the program's names, and a chain
whose elements would be too large to print (the fully symbolic PUMA 560) is refused at once, with
what to do instead.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> arm = dhsym.load("planar2r").chain
>>> result = derive(arm, MassModel().filled(2))
>>> result.M[1, 1]
I_zz2 + m_2*(a_2**2 + 2*a_2*x_c2 + x_c2**2 + y_c2**2)
>>> sorted(result.christoffel)
[(1, 1, 2), (1, 2, 1), (2, 1, 1), (2, 2, 1)]
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel
from ..errors import UserError
from .coriolis import christoffel_symbols
from .lagrange import gravity_vector
from .program import Program, dynamics_program
from .textbook import MAX_TERMS, compact, expanded_terms


@dataclass(frozen=True)
class Dynamics:
    """M (d_ij), C, g (Spong's φ_k, from the potential energy) and the Christoffel symbols
    {(i, j, k): c_ijk} that are not zero (joints counted from 1), in textbook form; `program`
    computes the same as code."""

    program: Program
    M: sympy.Matrix
    C: sympy.Matrix
    g: sympy.Matrix
    christoffel: dict

    @property
    def variables(self) -> tuple:
        return self.program.variables

    @property
    def rates(self) -> tuple:
        return self.program.rates

    @property
    def accelerations(self) -> tuple:
        return self.program.accelerations

    @property
    def tau(self) -> sympy.Matrix:
        """The equations of motion, one per joint: M q̈ + C q̇ + g."""
        return self.M * sympy.Matrix(self.accelerations) + self.C * sympy.Matrix(self.rates) + self.g


def derive(chain: Chain, masses: MassModel) -> Dynamics:
    """The dynamics of `chain` with the filled `masses`, in textbook form."""
    program = dynamics_program(chain, masses)
    tape = program.tape
    christoffel = christoffel_symbols(tape, program.model, program.outputs["M"])
    values = [*program.outputs["M"], *program.outputs["C"], *program.outputs["g"], *christoffel.values()]
    size = expanded_terms(tape, values)
    if size > MAX_TERMS:
        raise UserError(f"the elements of M, C and g would have about {size:,} terms multiplied out, more than the "
                        f"{MAX_TERMS:,} dhsym writes out; give the links' masses, centres of mass and inertias as "
                        "numbers, take fewer links, or generate code with --format python, which needs no printing")
    masses_symbols = [link.mass for link in masses.links if isinstance(link.mass, sympy.Symbol)]
    memo: dict = {}
    formulas: dict = {}

    def written(value):
        return compact(tape.expanded(value, memo), masses_symbols, formulas)

    M = program.outputs["M"]
    n = M.rows
    upper = {(i, j): written(M[i, j]) for i in range(n) for j in range(i, n)}
    gravity = gravity_vector(chain, masses).applyfunc(lambda x: compact(x, masses_symbols, formulas))
    return Dynamics(program, sympy.Matrix(n, n, lambda i, j: upper[min(i, j), max(i, j)]),
                    program.outputs["C"].applyfunc(written), gravity,
                    {key: value for key, value in ((k, written(v)) for k, v in christoffel.items()) if value != 0})
