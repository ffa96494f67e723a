"""A solution pickled (and deep-copied) with its expressions exactly as the solver built them.

SymPy pickles an expression as its class and arguments and builds it again by calling the class,
which evaluates: a minus kept before a bracket, −(pz(a3 + a2 c3) + …), comes back multiplied in,
so that the copy is not equal to the solution and prints otherwise. Here each expression travels
as its tree and is rebuilt node by node with evaluate=False (a keyword SymPy's cache keys on, so
nothing evaluated elsewhere gets the unevaluated form from the cache); names and numbers pickle
as they are.

>>> import pickle, sympy
>>> x, y = sympy.symbols("x y", real=True)
>>> kept = sympy.Mul(-1, x + y, evaluate=False)
>>> pickle.loads(pickle.dumps(kept)) == kept, thawed(pickle.loads(pickle.dumps(frozen(kept)))) == kept
(False, True)
"""
from __future__ import annotations

from dataclasses import dataclass, fields

import sympy


@dataclass(frozen=True)
class Tree:
    """An expression that is not a name or a number: its class and its arguments (frozen)."""

    kind: type
    args: tuple


@dataclass(frozen=True)
class Grid:
    """A matrix: its shape and elements (frozen)."""

    rows: int
    columns: int
    elements: tuple


def frozen(value):
    """`value` with every expression in it (in tuples, lists and matrices) as a `Tree`."""
    if isinstance(value, sympy.MatrixBase):
        return Grid(value.rows, value.cols, tuple(frozen(element) for element in value))
    if isinstance(value, sympy.Basic) and value.args and not value.is_Atom:
        return Tree(type(value), tuple(frozen(argument) for argument in value.args))
    if isinstance(value, (tuple, list)):
        return type(value)(frozen(item) for item in value)
    return value


def thawed(value):
    """The inverse of `frozen`: each `Tree` built again as it was, unevaluated."""
    if isinstance(value, Grid):
        return sympy.Matrix(value.rows, value.columns, [thawed(element) for element in value.elements])
    if isinstance(value, Tree):
        return value.kind(*(thawed(argument) for argument in value.args), evaluate=False)
    if isinstance(value, (tuple, list)):
        return type(value)(thawed(item) for item in value)
    return value


class KeepsForm:
    """A dataclass that pickles and deep-copies its expressions as they are (see the module)."""

    def __reduce__(self):
        return _rebuilt, (type(self), {field.name: frozen(getattr(self, field.name)) for field in fields(self)
                                       if field.init})


def _rebuilt(kind, values: dict):
    return kind(**{name: thawed(value) for name, value in values.items()})
