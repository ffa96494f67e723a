"""The equations of motion τ = M(q) q̈ + C(q, q̇) q̇ + g(q) of a chain, element by element.

`derive` runs the program (`dhsym.dynamics.program`: M by composite bodies, g by Newton–Euler with
no motion, the Christoffel symbols from the derivatives of M) and writes each element of M and g
and each Christoffel symbol that is not zero in textbook form (`dhsym.dynamics.textbook`); C is
Spong's C_kj = Σ_i c_ijk q̇_i of them. Before any element is written out, their size multiplied
out is counted on the program's names, and a chain whose elements would be too large to print (the
fully symbolic PUMA 560) is refused at once, with what to do instead. The Euler–Lagrange route in
the robot's own frames (`dhsym.dynamics.lagrange`: energies, g from the potential energy) gives
the same, as the tests prove.

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
from .polynomial import angle_sums, multiplied_out
from .program import Program, dynamics_program
from .textbook import MAX_TERMS, compact, expanded_terms


class TooLargeToPrint(UserError):
    """The elements of M, C and g would have about `terms` terms multiplied out, more than MAX_TERMS."""

    def __init__(self, terms: int):
        super().__init__(f"the elements of M, C and g would have about {terms:,} terms multiplied out, more than the "
                         f"{MAX_TERMS:,} dhsym writes out; give the links' masses, centres of mass and inertias as "
                         "numbers, take fewer links, or generate code with --format python, which needs no printing")
        self.terms = terms


@dataclass(frozen=True)
class Dynamics:
    """M (d_ij), C, g (Spong's φ_k) and the Christoffel symbols {(i, j, k): c_ijk} that are not
    zero (joints counted from 1), in textbook form; `program` computes M and g as code (with
    `dynamics_program`'s other parts, C and τ too)."""


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


def printed_terms(chain: Chain, masses: MassModel) -> tuple[Program, dict, int]:
    """The program of M and g, the Christoffel symbols as its names, and how many terms all of them
    would have multiplied out: what `derive` measures before it writes anything out."""
    program = dynamics_program(chain, masses, parts=("M", "g"))
    christoffel = christoffel_symbols(program.tape, program.model, program.outputs["M"])
    values = [*program.outputs["M"], *program.outputs["g"], *christoffel.values()]
    return program, christoffel, expanded_terms(program.tape, values)


def derive(chain: Chain, masses: MassModel) -> Dynamics:
    """The dynamics of `chain` with the filled `masses`, in textbook form."""
    program, christoffel, size = printed_terms(chain, masses)
    tape = program.tape
    if size > MAX_TERMS:
        raise TooLargeToPrint(size)
    masses_symbols = [link.mass for link in masses.links if isinstance(link.mass, sympy.Symbol)]
    M, g = program.outputs["M"], program.outputs["g"]
    n = M.rows
    cells = [(i, j) for i in range(n) for j in range(i, n)]
    written = [compact(x, masses_symbols, multiplied=True) for x in
               multiplied_out(tape, [*(M[i, j] for i, j in cells), *g, *christoffel.values()],
                              angle_sums(program.model.bodies[1:]))]
    upper = dict(zip(cells, written))
    symbols = {key: value for key, value in zip(christoffel, written[len(cells) + n:]) if value != 0}
    rates = program.rates
    C = sympy.Matrix(n, n, lambda k, j: sympy.Add(*[symbols[i + 1, j + 1, k + 1] * rates[i] for i in range(n)
                                                    if (i + 1, j + 1, k + 1) in symbols]))
    return Dynamics(program, sympy.Matrix(n, n, lambda i, j: upper[min(i, j), max(i, j)]), C,
                    sympy.Matrix(written[len(cells):len(cells) + n]), symbols)
