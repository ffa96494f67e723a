"""A few values of every branch at a few poses, in plain Python floats: what naming a branch
needs (dhsym.inverse.naming measures the arm at twelve poses). Each distinct expression is printed
once as a Python expression on `math` and compiled: for a dozen poses that is several times
cheaper than compiling the numpy module of `dhsym ik --format python` (dhsym.inverse.evaluate),
whose work is in sharing sub-expressions across branches for many poses at once.

>>> import dhsym, math
>>> from dhsym.inverse.derive import derive
>>> arm = dhsym.load("planar2r").chain
>>> a_1, a_2 = sorted((s for s in arm.symbols if s not in arm.joint_variables), key=str)
>>> values = BranchValues(derive(arm), arm.joint_variables)
>>> pose = [[1, 0, 0, 0.5], [0, 1, 0, 0.4], [0, 0, 1, 0], [0, 0, 0, 1]]   # θ = (0, π/2)
>>> [[round(x, 6) for x in branch.values()] for branch in values(pose, {a_1: 0.5, a_2: 0.4})]
[[1.570796, 0.0], [-1.570796, 1.349482]]
"""
from __future__ import annotations

import math

import sympy
from sympy.printing.pycode import PythonCodePrinter

from .codegen import ROUNDING
from .written import Written


class BranchValues:
    """`BranchValues(solution, wanted)(target, constants)`: per branch {symbol: value} for the
    joint variables `wanted` (and what they are computed from), in the order computed; None for a
    branch that does not exist at that pose (a root of a negative number, acos beyond ±1).
    `target` is the 4×4 pose as nested lists; `constants` maps the robot's symbols to numbers."""

    def __init__(self, solution, wanted):
        self._slots: dict = {}  # symbol -> its place in the list of values
        printer = _MathCode(self._slots)
        for symbol in solution.target_symbols:
            printer.slot(symbol)
        compiled: dict = {}  # expression -> function, each distinct one compiled once

        def function(value):
            if value not in compiled:
                text = printer.doprint(value)
                compiled[value] = eval(compile(f"lambda v: {text}", "<branch values>", "eval"),  # our own text
                                       {"math": math, "root": _root})
            return compiled[value]

        self._branches = []
        for branch in solution.branches:
            kept = set(wanted)
            for name, value in reversed(branch.assignments):  # a kept value keeps what it is computed from
                if name in kept:
                    kept |= value.free_symbols
            steps = [(printer.slot(name), function(value)) for name, value in branch.assignments if name in kept]
            self._branches.append(([name for name, _ in branch.assignments if name in kept], steps))
        self._shared = [(printer.slot(name), function(value)) for name, value in solution.definitions]
        targets = set(solution.target_symbols)
        self._constants = [s for s in self._slots if s not in targets]

    def __call__(self, target, constants: dict) -> list:
        values = [math.nan] * len(self._slots)
        for slot, number in enumerate(x for row in target[:3] for x in row):
            values[slot] = float(number)
        for symbol in self._constants:
            if symbol in constants:
                values[self._slots[symbol]] = float(constants[symbol])
            elif isinstance(symbol, Written):
                values[self._slots[symbol]] = float(symbol.value)
        for slot, function in self._shared:
            values[slot] = _value(function, values)
        found = []
        for names, steps in self._branches:
            mine = list(values)
            for slot, function in steps:
                mine[slot] = _value(function, mine)
            numbers = {name: mine[self._slots[name]] for name in names}
            found.append(None if any(math.isnan(x) for x in numbers.values()) else numbers)
        return found


class _MathCode(PythonCodePrinter):
    """math.atan2, math.cos, …; each symbol a place in the list `v`; square roots by `root`."""

    def __init__(self, slots: dict):
        super().__init__({"fully_qualified_modules": True})
        self.slots = slots

    def slot(self, symbol) -> int:
        return self.slots.setdefault(symbol, len(self.slots))

    def _print_Symbol(self, expr):
        return f"v[{self.slot(expr)}]"

    _print_Dummy = _print_Symbol

    def _print_Pow(self, expr, rational=False):
        if expr.exp == sympy.S.Half:
            return f"root({self._print(expr.base)})"
        if expr.exp == -sympy.S.Half:
            return f"(1/root({self._print(expr.base)}))"
        return super()._print_Pow(expr, rational=rational)


def _root(x: float) -> float:
    """√x, a number this close below 0 taken as 0 (the edge of the workspace), as the module does."""
    if x < -ROUNDING:
        raise ValueError("no real root")
    return math.sqrt(max(x, 0.0))


def _value(function, values: list) -> float:
    try:
        return float(function(values))
    except (ValueError, ZeroDivisionError, OverflowError):
        return math.nan  # this branch has no value here
