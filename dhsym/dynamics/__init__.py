"""Dynamics, from the DH table and the links' masses: τ = M(q) q̈ + C(q, q̇) q̇ + g(q).

Everything here takes a plain `Chain` (frames 0..n) and a filled `MassModel`; a `Robot` gives
both (`robot.chain`, `robot.filled_masses()`, symbols numbered as its joints are printed):

- `derive`: M, C, g and the Christoffel symbols element by element, in textbook form;
- `dynamics_program`: the same and τ as straight-line code (Newton–Euler, composite bodies), with
  what it costs; `module_text` writes it as a numpy module;
- `regressor` and `base_parameters`: τ = Y π and the identifiable combinations of π.

>>> import dhsym
>>> from dhsym.dynamics import derive
>>> arm = dhsym.load("planar2r")
>>> derive(arm.chain, arm.filled_masses()).M[1, 1]
I_zz2 + m_2*(a_2**2 + 2*a_2*x_c2 + x_c2**2 + y_c2**2)
"""
from .base import BaseParameters, base_parameters
from .codegen import module_text
from .derive import Dynamics, derive
from .program import Program, dynamics_program
from .regressor import Regressor, regressor

__all__ = ["BaseParameters", "Dynamics", "Program", "Regressor", "base_parameters", "derive", "dynamics_program",
           "module_text", "regressor"]
