"""Straight-line code: every value that costs an operation is computed once and named.

The recursions of dynamics (Newton–Euler, the composite bodies) build their results from a few
thousand small pieces. Written out, the pieces multiply into expressions of tens of thousands of
terms; kept as named values, each costs a handful of operations, the way OpenSYMORO's customized
Newton–Euler and SymPyBotics' code work. A `Tape` names each value the first time it is asked for,
so that a value asked for twice (cos θ2, a product of the same two names) is one name;
`differentiate` carries derivatives through the names (forward mode), for the Christoffel form of
C and for the regressor; `expanded` writes a name out again, for small robots whose results are
printed element by element.

>>> x, y = sympy.symbols("x y", real=True)
>>> tape = Tape()
>>> a = tape.name(x * y + sympy.cos(x))
>>> b = tape.name(a**2)
>>> tape.expanded(b)
(x*y + cos(x))**2
>>> derivative = tape.expanded(differentiate(tape, [b], {x: 1})[0])
>>> sympy.expand(derivative - sympy.diff(tape.expanded(b), x))
0
>>> operations(tape, [b])
Operations(multiplications=2, additions=1, functions=1)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy


def is_trivial(expr: sympy.Expr) -> bool:
    """A value that costs nothing: a number, a symbol, or minus a symbol."""
    if expr.is_Atom:
        return True
    return expr.is_Mul and len(expr.args) == 2 and expr.args[0] == -1 and expr.args[1].is_Atom


def leads_negative(expr: sympy.Expr) -> bool:
    """Whether `expr` is written with a minus in front, decided the same way for −expr (so that a
    value and its negative share a name) and cheaply: a product by its coefficient, a sum by the
    coefficient of its first term in SymPy's structural order, its coefficient left out.

    >>> x, y = sympy.symbols("x y", real=True)
    >>> leads_negative(x - y), leads_negative(y - x), leads_negative(-2*x*y)
    (False, True, True)
    """
    if expr.is_Mul or expr.is_Number:
        return expr.as_coeff_Mul()[0].is_negative
    if not expr.is_Add:
        return False
    first = None
    for term in expr.args:
        coefficient, rest = term.as_coeff_Mul()
        if rest != 1 and (first is None or rest.compare(first[1]) < 0):
            first = (coefficient, rest)
    return first is not None and first[0].is_negative


class Tape:

    """Named values in the order they were made; each name is a Dummy, so that it never meets a
    symbol of the robot."""

    def __init__(self):
        self.definitions: dict[sympy.Dummy, sympy.Expr] = {}
        self._names: dict[sympy.Expr, sympy.Dummy] = {}
        self.leaves: dict[sympy.Symbol, frozenset] = {}  # name -> the robot's symbols it depends on

    def name(self, expr) -> sympy.Expr:
        """`expr` itself when it costs nothing, else its name (the one it already has, if any).
        A value with a leading minus is named without it: −x costs nothing."""
        expr = sympy.sympify(expr)
        if is_trivial(expr):
            return expr
        if leads_negative(expr):
            return -self.name(-expr)
        known = self._names.get(expr)
        if known is not None:
            return known
        symbol = sympy.Dummy(f"t{len(self.definitions)}", real=True)
        self.definitions[symbol] = expr
        self._names[expr] = symbol
        self.leaves[symbol] = self.depends_on(expr)
        return symbol

    def vector(self, values) -> tuple:
        return tuple(self.name(value) for value in values)

    def depends_on(self, expr: sympy.Expr) -> frozenset:
        """The robot's symbols (never names) that `expr` depends on, through the names it uses."""
        found: set = set()
        for symbol in expr.free_symbols:
            found |= self.leaves[symbol] if symbol in self.leaves else {symbol}
        return frozenset(found)

    def expanded(self, expr, memo: dict | None = None) -> sympy.Expr:
        """`expr` with every name written out (as the definitions say, without multiplying out)."""
        memo = {} if memo is None else memo
        expr = sympy.sympify(expr)
        names = [s for s in expr.free_symbols if s in self.definitions]
        for symbol in names:
            if symbol not in memo:
                memo[symbol] = self.expanded(self.definitions[symbol], memo)
        return expr.xreplace({s: memo[s] for s in names}) if names else expr

    def used(self, outputs) -> list:
        """The names that `outputs` need, in the order of the tape (what code must compute)."""
        needed, waiting = set(), [s for x in outputs for s in sympy.sympify(x).free_symbols]
        while waiting:
            symbol = waiting.pop()
            if symbol in self.definitions and symbol not in needed:
                needed.add(symbol)
                waiting.extend(self.definitions[symbol].free_symbols)
        return [s for s in self.definitions if s in needed]


class _Derivative:
    """d/dε of named values when each symbol x moves as `seed[x]`·ε: ∂/∂q_k for seed {q_k: 1},
    the time derivative for {q_k: q̇_k}. Each derivative is named on the tape as it is found."""

    def __init__(self, tape: Tape, seed: dict):
        self.tape, self.seed = tape, {k: sympy.sympify(v) for k, v in seed.items() if v != 0}
        self.moving = frozenset(self.seed)
        self.memo: dict = {}

    def of(self, expr: sympy.Expr) -> sympy.Expr:
        if expr in self.seed:
            return self.seed[expr]
        if expr.is_Atom:
            return self.of_name(expr) if expr in self.tape.definitions else sympy.Integer(0)
        if not (self.tape.depends_on(expr) & self.moving):
            return sympy.Integer(0)
        if expr.is_Add:
            return sympy.Add(*[self.of(term) for term in expr.args])
        if expr.is_Mul:
            factors = expr.args
            parts = []
            for k, factor in enumerate(factors):
                change = self.tape.name(self.of(factor))  # a product of a sum is slow to build: name the sum
                if change != 0:

                    parts.append(sympy.Mul(*factors[:k], change, *factors[k + 1:]))
            return sympy.Add(*parts)
        if expr.is_Pow and expr.exp.is_Integer:
            return expr.exp * expr.base ** (expr.exp - 1) * self.of(expr.base)
        if isinstance(expr, sympy.cos):
            return -self.tape.name(sympy.sin(expr.args[0])) * self.of(expr.args[0])
        if isinstance(expr, sympy.sin):
            return self.tape.name(sympy.cos(expr.args[0])) * self.of(expr.args[0])
        raise ValueError(f"no derivative rule for {type(expr).__name__}")  # the recursions make none other

    def of_name(self, symbol: sympy.Dummy) -> sympy.Expr:
        if symbol not in self.memo:
            if not (self.tape.leaves[symbol] & self.moving):
                self.memo[symbol] = sympy.Integer(0)
            else:
                self.memo[symbol] = self.tape.name(self.of(self.tape.definitions[symbol]))
        return self.memo[symbol]


def differentiate(tape: Tape, values, seed: dict) -> list:
    """The derivatives of `values` (expressions in names and symbols) when each symbol x of
    `seed` moves at the rate seed[x], named on `tape`."""
    derivative = _Derivative(tape, seed)
    return [tape.name(derivative.of(sympy.sympify(value))) for value in values]


@dataclass(frozen=True)
class Operations:
    """What straight-line code costs: multiplications (divisions included), additions
    (subtractions included), and calls of cos and sin. A change of sign costs nothing."""

    multiplications: int = 0
    additions: int = 0
    functions: int = 0

    def __add__(self, other: "Operations") -> "Operations":
        return Operations(self.multiplications + other.multiplications, self.additions + other.additions,
                          self.functions + other.functions)

    @property
    def total(self) -> int:
        return self.multiplications + self.additions + self.functions


def cost(expr: sympy.Expr) -> Operations:
    """The operations of one expression, written as code writes it.

    >>> x, y = sympy.symbols("x y", real=True)
    >>> cost(2*x*y - x**2/y + sympy.cos(x))
    Operations(multiplications=4, additions=2, functions=1)
    """
    if expr.is_Atom:
        return Operations()
    inner = sum((cost(arg) for arg in _operands(expr)), Operations())
    if expr.is_Add:
        return inner + Operations(additions=len(expr.args) - 1)
    if expr.is_Mul:
        coefficient, factors = expr.as_coeff_mul()
        count = len(factors) - 1 + (0 if abs(coefficient) == 1 else 1)
        return inner + Operations(multiplications=count)
    if expr.is_Pow:
        power = abs(int(expr.exp)) if expr.exp.is_Integer else 1
        return inner + Operations(multiplications=max(power - 1, 0) + (1 if expr.exp.is_negative else 0))
    return inner + Operations(functions=1)


def operation_count(expr: sympy.Expr, memo: dict | None = None) -> int:
    """`cost(expr).total`, counted faster (plain integers, a subtree met again is looked up in
    `memo`): what choosing the shortest of several forms compares, many times over.

    >>> x, y = sympy.symbols("x y", real=True)
    >>> operation_count(2*x*y - x**2/y + sympy.cos(x))
    7
    """
    memo = {} if memo is None else memo
    known = memo.get(expr)
    if known is not None:
        return known
    if expr.is_Atom:
        return 0
    if expr.is_Add:
        count = len(expr.args) - 1 + sum(operation_count(arg, memo) for arg in expr.args)
    elif expr.is_Mul:
        coefficient, factors = expr.as_coeff_mul()
        count = len(factors) - (1 if abs(coefficient) == 1 else 0) + sum(_divisor_count(f, memo) for f in factors)
    elif expr.is_Pow:
        power = abs(int(expr.exp)) if expr.exp.is_Integer else 1
        count = operation_count(expr.base, memo) + max(power - 1, 0) + (1 if expr.exp.is_negative else 0)
    else:
        count = 1 + sum(operation_count(arg, memo) for arg in expr.args)
    memo[expr] = count
    return count


def _divisor_count(factor: sympy.Expr, memo: dict) -> int:
    """A factor's own operations as `_operands` counts them: of y only, for a factor 1/y."""
    if not (factor.is_Pow and factor.exp.is_negative):
        return operation_count(factor, memo)
    if factor.base.is_Number or not (-factor.exp).is_Integer:
        return operation_count(factor.base ** -factor.exp, memo)
    return operation_count(factor.base, memo) + max(int(-factor.exp) - 1, 0)


def _operands(expr: sympy.Expr) -> tuple:
    """The parts of `expr` whose own cost adds to it: a factor 1/y of a product is the division
    the product counts, so only y."""
    if expr.is_Mul:
        return tuple(f.base ** -f.exp if f.is_Pow and f.exp.is_negative else f for f in expr.as_coeff_mul()[1])
    if expr.is_Pow:
        return (expr.base,)
    return expr.args


def operations(tape: Tape, outputs) -> Operations:
    """What computing `outputs` from the robot's symbols costs: every name they need once, then
    the outputs themselves."""
    total = sum((cost(tape.definitions[s]) for s in tape.used(outputs)), Operations())
    return total + sum((cost(sympy.sympify(x)) for x in outputs), Operations())
