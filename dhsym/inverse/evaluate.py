"""Numbers from a closed-form solution: every branch at once, for one pose or many, vectorised
with numpy (imported here only, on first use: the symbolic commands never load it).

>>> import numpy, dhsym
>>> from dhsym.inverse.solve import solve
>>> arm = dhsym.load("planar2r")
>>> pose = numpy.eye(4); pose[:2, 3] = [0.5, 0.4]        # a_1 = 0.5, a_2 = 0.4: θ = (0, π/2)
>>> numpy.round(evaluate(solve(arm), pose), 6)
array([[ 0.      ,  1.570796],
       [ 1.349482, -1.570796]])
"""
from __future__ import annotations

import sympy

from .solution import target_symbols

COMPILED_KEPT = 2000  # compiled expressions kept between calls
ROUNDING = 1e-10  # a square root of −1e-16 at the edge of the workspace is a root of 0, not a missing branch


def evaluate(solution, T, constants=None):
    """Joint values of every branch for the pose T (4×4 → (B, n)) or poses (N×4×4 → (N, B, n)):
    branches in solution order, joints in `solution.joint_variables` order, NaN where a branch
    does not exist. `constants` maps the robot's symbols (and --free joint variables) to numbers;
    it defaults to the robot's sample values."""
    import numpy

    poses = numpy.asarray(T, dtype=float)
    single = poses.ndim == 2
    poses = poses.reshape((-1, 4, 4))
    values = dict(solution.chain.sample)
    values.update(constants or {})
    names = {str(k): v for k, v in values.items()}
    inputs = {symbol: poses[:, r, c] for symbol, (r, c) in zip(target_symbols(), _positions())}
    out = numpy.full((poses.shape[0], len(solution.branches), len(solution.joint_variables)), numpy.nan)
    revolute = [row.joint == "R" for row, v in zip(solution.chain.rows, solution.chain.joint_variables)
                if v in solution.joint_variables]
    with numpy.errstate(invalid="ignore", divide="ignore"):
        shared = dict(inputs)
        for name, value in solution.definitions:
            shared[name] = _compute(value, shared, names)
        done: dict = {}  # branches share their first steps (θ1 of the shoulder): each is computed once
        for b, branch in enumerate(solution.branches):
            known = dict(shared)
            for k, (name, value) in enumerate(branch.assignments):
                prefix = branch.assignments[:k + 1]
                if prefix not in done:
                    done[prefix] = _compute(value, known, names)
                known[name] = done[prefix]
            result = numpy.stack([numpy.broadcast_to(numpy.asarray(known[v], dtype=float), (poses.shape[0],))
                                  for v in solution.joint_variables], axis=-1)
            result[:, revolute] = (result[:, revolute] + numpy.pi) % (2 * numpy.pi) - numpy.pi
            result[numpy.isnan(result).any(axis=-1)] = numpy.nan  # half a branch is no branch
            out[:, b] = result
    return out[0] if single else out


def _positions():
    return [(r, c) for r in range(3) for c in range(4)]


_compiled: dict = {}


def _compute(expr: sympy.Expr, known: dict, constants: dict):
    """The value of `expr` from arrays of the names it uses (and numbers for the constants)."""
    import numpy

    symbols = sorted(expr.free_symbols, key=str)
    key = (expr, tuple(symbols))
    if key not in _compiled:
        if len(_compiled) > COMPILED_KEPT:  # a long session solving many arms keeps only recent ones
            _compiled.clear()
        _compiled[key] = sympy.lambdify(symbols, expr, modules=[{"sqrt": _sqrt}, "numpy"])
    arguments = []
    for symbol in symbols:
        if symbol in known:
            arguments.append(known[symbol])
        elif str(symbol) in constants:
            arguments.append(float(constants[str(symbol)]))
        else:
            from ..errors import UserError
            raise UserError(f"no value for {symbol}: give it in the constants (a --free joint variable needs one)")
    return numpy.asarray(_compiled[key](*arguments), dtype=float)


def _sqrt(x):
    import numpy

    x = numpy.asarray(x, dtype=float)
    return numpy.sqrt(numpy.where((x < 0) & (x > -ROUNDING), 0.0, x))
