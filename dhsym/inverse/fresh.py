"""The derivation's own names (the target's r11 … pz, the wrist centre x_c, D, K, C, θ23, φk, σk, Pieper's
quantities) never collide with the robot's: a name the robot uses for a length or a joint is the
robot's, and the derivation's name gets a prime. A robot whose first link is named D gets
D′ = (px² + py² − D² − a2²)/(2 D a2); an arm whose own joint is φ1 solves an angle with an offset,
θ1 + 1, as φ1′.

The prime is MODIFIER LETTER PRIME (ʹ, U+02B9), a letter that Python, SymPy and dhsym's own
parser read as part of a name: the JSON's expressions and the solver's sentences read back.
The printers write it as a prime: D′ in text, D' in LaTeX and ASCII.

>>> fresh("D", {"D", "a_2"}), fresh("D", {"D", "Dʹ"}), fresh("K", {"D"})
('Dʹ', 'Dʹʹ', 'K')
>>> [s.name for s in target_symbols({"px", "a_1"})][:4]
['r11', 'r12', 'r13', 'pxʹ']
"""
from __future__ import annotations

import sympy

PRIME = "ʹ"
TARGET_NAMES = ("r11", "r12", "r13", "px", "r21", "r22", "r23", "py", "r31", "r32", "r33", "pz")


def fresh(name: str, taken) -> str:
    """`name`, primed as often as it takes not to be one of the names `taken`."""
    while name in taken:
        name += PRIME
    return name


def fresh_symbol(name: str, taken, kind=sympy.Symbol, **assumptions) -> sympy.Symbol:
    """A symbol (real unless said otherwise) named `fresh(name, taken)`."""
    return kind(fresh(name, taken), **({"real": True} | assumptions))


def reserved(chain) -> frozenset:
    """The names a robot (or chain) uses itself: its joint variables and constants."""
    return frozenset(symbol.name for symbol in getattr(chain, "symbols", ()))


def target_symbols(taken=()) -> tuple:
    """The twelve names of the target's elements, row by row (r11 r12 r13 px r21 …), each fresh
    against the names `taken` (the robot's)."""
    return tuple(fresh_symbol(name, taken) for name in TARGET_NAMES)


def plain(name: str) -> tuple[str, int]:
    """(the name without its primes, how many it has): ('px', 1) for pxʹ."""
    stripped = name.rstrip(PRIME)
    return stripped, len(name) - len(stripped)
