"""The dynamics of a chain as straight-line code: M, C, g and τ from one tape of named values.

`dynamics_program` runs the recursions once: Newton–Euler for τ and for g (no motion), the
composite bodies for M, and the derivatives of M for C. What a program costs is counted by
`Program.operations`, what it needs as inputs by `Program.constants`; `dhsym.dynamics.codegen`
writes it as a numpy module, `dhsym.dynamics.textbook` writes its results out element by element.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> arm = dhsym.load("planar2r").chain
>>> program = dynamics_program(arm, MassModel().filled(2))
>>> sorted(program.outputs), program.operations("M")
(['C', 'M', 'g', 'tau'], Operations(multiplications=28, additions=14, functions=2))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..core.chain import Chain
from ..core.inertia import MassModel
from ..errors import UserError
from .composite import mass_matrix
from .coriolis import coriolis_matrix
from .model import RigidModel, rigid_model
from .newton_euler import NewtonEuler, newton_euler, rate_symbols
from .tape import Operations, Tape, operations

MAX_PROGRAM_JOINTS = 12  # C by derivatives grows as n³: 12 joints is some 20,000 operations


@dataclass(frozen=True)
class Program:
    """Named values (`tape`) and what they give: `outputs` M (n×n), C (n×n), g (n×1) and tau
    (n×1) (those asked for), functions of the joint variables, their rates (`rates`, q̇) and
    accelerations (q̈) and the robot's constants; `steps` are Newton–Euler's passes, link by link
    (when tau is asked for)."""

    tape: Tape
    model: RigidModel
    variables: tuple
    rates: tuple
    accelerations: tuple
    outputs: dict
    steps: NewtonEuler | None


    def operations(self, *names: str) -> Operations:
        """What computing the named outputs (all of them when none is named) costs."""
        names = names or tuple(self.outputs)
        return operations(self.tape, [x for name in names for x in _entries(self.outputs[name], name)])

    def constants(self, *names: str) -> list:
        """The symbols other than the joint variables, rates and accelerations that the named
        outputs need, sorted by name."""
        names = names or tuple(self.outputs)
        found = set().union(*(self.tape.depends_on(sympy.sympify(x)) for name in names for x in self.outputs[name]))
        motion = set(self.variables) | set(self.rates) | set(self.accelerations)
        return sorted(found - motion, key=lambda s: s.name)


def _entries(matrix: sympy.Matrix, name: str) -> list:
    """The entries that code computes: the upper triangle of the symmetric M."""
    if name == "M":
        return [matrix[i, j] for i in range(matrix.rows) for j in range(i, matrix.cols)]
    return list(matrix)


def dynamics_program(chain: Chain, masses: MassModel, parameters: list | None = None,
                     parts=("M", "C", "g", "tau")) -> Program:
    """The program of `chain` with the filled `masses` (see `dhsym.dynamics.model.rigid_model`
    for `parameters`), with the outputs named in `parts` (C needs M). A chain of more than
    MAX_PROGRAM_JOINTS joints is refused before any work."""
    if chain.n > MAX_PROGRAM_JOINTS:
        raise UserError(f"the dynamics of {chain.n} joints would be too long to work out (C grows as the cube of "
                        f"the number of joints); dhsym derives it for at most {MAX_PROGRAM_JOINTS}: take fewer links")
    tape = Tape()
    model = rigid_model(chain, masses, parameters)
    variables = tuple(model.variables)
    rates, accelerations = tuple(rate_symbols(variables)), tuple(rate_symbols(variables, 2))
    outputs: dict = {}
    steps = newton_euler(tape, model, rates, accelerations) if "tau" in parts else None
    if "g" in parts:
        zero = [sympy.Integer(0)] * model.n
        outputs["g"] = sympy.Matrix(newton_euler(tape, model, zero, zero).torques)
    if "M" in parts or "C" in parts:
        outputs["M"] = mass_matrix(tape, model)
    if "C" in parts:
        outputs["C"] = coriolis_matrix(tape, model, outputs["M"], rates)
    if steps is not None:
        outputs["tau"] = sympy.Matrix(steps.torques)
    return Program(tape, model, variables, rates, accelerations, outputs, steps)
