"""Velocity kinematics, built on the contracted frames of `dhsym.core`: the geometric
Jacobian in any frame (`jacobian`), its factored determinant and singular configurations
(`determinant`, `singularities`), and Craig's outward velocity propagation (`propagate`).
They take a plain chain, frames 0..n; a notebook's robot has them in its printed numbers
(`robot.jacobian()`, `robot.determinant()`, `robot.singularities()`, `robot.propagate()`).

>>> import dhsym
>>> from dhsym.velocity import determinant
>>> determinant(dhsym.load("planar2r").chain).value
a_1*a_2*sin(theta_2)
"""
from .determinant import Determinant, determinant
from .jacobian import ROWS, jacobian
from .propagation import propagate, propagated_jacobian, rate_symbols
from .singularities import Singularity, singularities

__all__ = ["ROWS", "Determinant", "Singularity", "determinant", "jacobian", "propagate", "propagated_jacobian",
           "rate_symbols", "singularities"]
