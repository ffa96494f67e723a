"""The one rule for a random pose of a chain, for every numeric question dhsym asks at a generic
configuration (do three axes meet, which equations say nothing, which word names a branch):
each symbol in the order of its name gets one number from the generator, so that the same seed
gives the same pose on every machine and adding a slide does not move the other values.

- a revolute joint's angle: uniform in (−π, π);
- a prismatic joint's length: uniform in (0.5, 1.5), as a slide extended (never negative, never 0);
- a constant: its value in `sample` (a robot file's), else uniform in (0.5, 1.5), as a length.

>>> import random, sympy
>>> from dhsym.core.chain import Chain, DHRow
>>> t, d, l = sympy.symbols("theta_1 d_2 l_1", real=True)
>>> arm = Chain([DHRow.revolute(t, a=l), DHRow.prismatic(d)], "standard")
>>> pose = random_pose(arm, random.Random(1), {l: sympy.Rational(1, 2)})
>>> pose[l], 0.5 < pose[d] < 1.5, -3.15 < pose[t] < 3.15
(0.5, True, True)
"""
from __future__ import annotations

import math
import random
from typing import Mapping

from .chain import Chain, plain

ANGLES = (-math.pi, math.pi)
LENGTHS = (0.5, 1.5)  # a slide extended, a constant length: of the order of the robots' metres


def random_pose(chain: Chain, rng: random.Random, sample: Mapping | None = None) -> dict:
    """{symbol: float} for every symbol of `chain` (joint variables and constants), by the rule above."""
    chain, sample = plain(chain), sample or {}
    revolute = {row.variable for row in chain.rows if row.joint == "R"}
    values = {}
    for symbol in sorted(chain.symbols, key=lambda s: s.name):
        if symbol in sample and symbol not in chain.joint_variables:
            values[symbol] = float(sample[symbol])
        else:
            values[symbol] = rng.uniform(*(ANGLES if symbol in revolute else LENGTHS))
    return values
