"""One generic pose in numbers: the joint values, the robot's constants and the target they give.
The search uses it to pass over equations that say nothing (0 = 0) once earlier results hold.

>>> import dhsym, sympy
>>> numbers = witness(dhsym.load("planar2r"))
>>> abs(numbers[sympy.Symbol("r33", real=True)] - 1) < 1e-12
True
"""
from __future__ import annotations

import math
import random

import sympy

from ..core.robot import as_chain, as_robot
from ..velocity.geometry import poses
from .solution import target_symbols

SEED = 20240516


def witness(chain, seed: int = SEED) -> dict:
    """Symbol -> Float for every joint variable, constant and target element at a random pose;
    constants from the robot's sample values where it has them."""
    sample, chain = as_robot(chain).sample, as_chain(chain)
    rng = random.Random(seed)
    values = {}
    for variable, row in zip(chain.joint_variables, chain.rows):
        values[variable] = rng.uniform(-math.pi, math.pi) if row.joint == "R" else rng.uniform(0.5, 1.5)
    for symbol in sorted(chain.symbols - set(chain.joint_variables), key=str):
        values[symbol] = float(sample[symbol]) if symbol in sample else rng.uniform(0.5, 1.5)
    rotation, origin = poses(chain, values)[chain.last_frame]
    elements = [x for r in range(3) for x in (*rotation[r], origin[r])]
    values.update(zip(target_symbols(), elements))
    return {symbol: sympy.Float(value, 17) for symbol, value in values.items()}
