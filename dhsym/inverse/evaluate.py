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

COMPILED_KEPT = 64  # compiled solutions kept between calls
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
    function, parameters = _program(solution)
    arguments = [poses[:, r, c] for r, c in _positions()]
    for symbol in parameters:
        if str(symbol) not in names:
            from ..errors import UserError
            raise UserError(f"no value for {symbol}: give it in the constants (a --free joint variable needs one)")
        arguments.append(float(names[str(symbol)]))
    count, branches, joints = poses.shape[0], len(solution.branches), len(solution.joint_variables)
    revolute = [row.joint == "R" for row, v in zip(solution.chain.rows, solution.chain.joint_variables)
                if v in solution.joint_variables]
    with numpy.errstate(invalid="ignore", divide="ignore"):
        out = numpy.empty((count, branches * joints))
        for k, value in enumerate(function(*arguments)):
            out[:, k] = value  # a number (a joint the pose does not change) fills its column
        out = out.reshape((count, branches, joints))
        out[..., revolute] = (out[..., revolute] + numpy.pi) % (2 * numpy.pi) - numpy.pi
        out[numpy.isnan(out).any(axis=-1)] = numpy.nan  # half a branch is no branch
    return out[0] if single else out


def _positions():
    return [(r, c) for r in range(3) for c in range(4)]


_compiled: dict = {}
_KEPT = sympy.Function("kept")  # a named value put in as it is: no rewriting across it


def _identity(x):
    return x


def _program(solution):
    """One numpy function of the target elements and the robot's constants that gives every
    joint of every branch, flat, with the sub-expressions that branches share (θ1, D, √(1 − D²),
    c1 of the shoulder) computed once: each name is put in for its value, and common
    sub-expression elimination shares what the branches have in common. Kept per solution.
    A name is put in unevaluated: SymPy would turn sin(atan2(y, x)) into y/√(x² + y²), which is
    0/0 where atan2(0, 0) is a number (the shoulder on the axis, the wrist at s5 = 0)."""
    key = (solution.definitions, solution.branches, solution.joint_variables)
    if key not in _compiled:
        if len(_compiled) > COMPILED_KEPT:  # a long session solving many arms keeps only recent ones
            _compiled.clear()
        shared: dict = {}
        for name, value in solution.definitions:
            shared[name] = _KEPT(value.xreplace(shared))
        outputs = []
        for branch in solution.branches:
            known = dict(shared)
            for name, value in branch.assignments:
                known[name] = _KEPT(value.xreplace(known))
            outputs += [sympy.sympify(known.get(v, v)) for v in solution.joint_variables]
        inputs = list(target_symbols())
        parameters = sorted(set().union(*(e.free_symbols for e in outputs)) - set(inputs), key=str)
        function = sympy.lambdify(inputs + parameters, outputs, modules=[{"sqrt": _sqrt, "kept": _identity}, "numpy"],
                                   cse=True)
        _compiled[key] = function, parameters
    return _compiled[key]


def _sqrt(x):
    import numpy

    x = numpy.asarray(x, dtype=float)
    return numpy.sqrt(numpy.where((x < 0) & (x > -ROUNDING), 0.0, x))
