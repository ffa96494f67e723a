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

import math

from .codegen import ROUNDING, keyword_names, module_text
from .solution import TARGET_NAMES

COMPILED_KEPT = 64  # compiled solutions kept between calls


def evaluate(solution, T, constants=None):
    """Joint values of every branch for the pose T (4×4 → (B, n)) or poses (N×4×4 → (N, B, n)):
    branches in solution order, joints in `solution.joint_variables` order, NaN where a branch
    does not exist. `constants` maps the robot's symbols (and --free joint variables), or their
    names, to numbers; the robot's sample values are the defaults. The numbers come from the
    module `dhsym ik --format python` writes (dhsym.inverse.codegen), compiled once per solution:
    one generator for the printed module and for this."""
    function, keywords, required = _program(solution)
    given = {getattr(k, "name", str(k)): v for k, v in (constants or {}).items()}
    for name in required:
        if name not in given:
            from ..errors import UserError
            raise UserError(f"no value for {name}: give it in the constants (a --free joint variable needs one)")
    return function(T, **{keywords[name]: float(value) for name, value in given.items() if name in keywords})


def evaluate_few(solution, T, constants=None) -> list:
    """`evaluate` for a few poses T (N×4×4, nested lists), as nested lists of floats (N, B, n): the
    same numbers as the generated module's (its rounding of square roots at the edge of the
    workspace, angles in [−π, π), a branch missing whole), worked out in plain floats. For the
    dozen poses the branch names are checked at, compiling the module costs a hundred times more
    than this, and numpy is not loaded.

    >>> import dhsym
    >>> from dhsym.inverse.solve import solve
    >>> pose = [[1, 0, 0, 0.5], [0, 1, 0, 0.4], [0, 0, 1, 0], [0, 0, 0, 1]]
    >>> [[round(x, 6) for x in joints] for joints in evaluate_few(solve(dhsym.load("planar2r")), [pose])[0]]
    [[0.0, 1.570796], [1.349482, -1.570796]]
    """
    _, required = _constants(solution)
    given = {getattr(k, "name", str(k)): float(v) for k, v in (constants or {}).items()}
    for name in required:
        if name not in given:
            from ..errors import UserError
            raise UserError(f"no value for {name}: give it in the constants (a --free joint variable needs one)")
    chain = solution.chain
    settable = {s.name for s in chain.symbols - set(chain.joint_variables) | set(solution.free)}
    fixed = {symbol.name: float(value) for symbol, value in chain.sample.items()}
    fixed.update({name: value for name, value in given.items() if name in settable})
    joints = [joint.name for joint in solution.joint_variables]
    kinds = {row.variable.name: row.joint for row in chain.rows if row.variable is not None}
    revolute = [kinds.get(joint) == "R" for joint in joints]
    pose_level = {*fixed, *TARGET_NAMES, *(name.name for name, _ in solution.definitions)}
    out = []
    for pose in T:
        values = dict(fixed)
        values.update({name: float(pose[k // 4][k % 4]) for k, name in enumerate(TARGET_NAMES)})
        memo: dict = {}  # values of sub-expressions of the pose's names alone, shared by the branches
        for name, value in solution.definitions:
            values[name.name] = _number(value, values, memo)
        branches = []
        for branch in solution.branches:
            known = dict(values)
            for name, value in branch.assignments:
                shared = all(s.name in pose_level for s in value.free_symbols)
                known[name.name] = _number(value, known, memo if shared else {})
            joint_values = [known.get(joint, math.nan) for joint in joints]
            joint_values = [(x + math.pi) % (2 * math.pi) - math.pi if turning and math.isfinite(x) else x
                            for x, turning in zip(joint_values, revolute)]
            branches.append(joint_values if all(map(math.isfinite, joint_values)) else [math.nan] * len(joints))
        out.append(branches)
    return out


def _number(expr, values: dict, memo: dict) -> float:
    """The value of `expr`, NaN where numpy's would not be a finite number; `memo` keeps the
    values of sub-expressions that hold only names whose values are fixed for the pose."""
    if expr.is_Symbol:
        value = values.get(expr.name)
        if value is None:
            value = float(expr.value) if hasattr(expr, "value") else math.nan  # a written decimal
        return value
    key = id(expr)
    if key in memo:
        return memo[key][1]
    value = _apply(expr, [_number(a, values, memo) for a in expr.args])
    memo[key] = (expr, value)  # the expression is held: its id is not reused while the memo lives
    return value


def _apply(expr, args) -> float:
    try:
        if expr.is_Number:
            return float(expr)
        if expr.is_Add:
            return math.fsum(args)
        if expr.is_Mul:
            return math.prod(args)
        if expr.is_Pow:
            base, exponent = args
            if exponent == 0.5:
                return math.sqrt(0.0 if -ROUNDING < base < 0 else base)
            if base == 0 and exponent < 0:
                return math.inf
            result = base ** exponent
            return math.nan if isinstance(result, complex) else result
        if expr.is_NumberSymbol:
            return float(expr)
        function = _FUNCTIONS.get(expr.func.__name__)
        if function is None:  # what the module would print with numpy, SymPy evaluates
            return float(expr.func(*args).evalf())
        return function(*args)
    except (ValueError, OverflowError, ZeroDivisionError, TypeError):
        return math.nan


_FUNCTIONS = {"cos": math.cos, "sin": math.sin, "atan2": math.atan2, "acos": math.acos, "asin": math.asin,
              "atan": math.atan, "tan": math.tan, "Abs": abs}


_compiled: dict = {}


def _program(solution):
    """(the module's ik function, {constant name: keyword}, the names that have no default), kept per solution."""
    key = (id(solution.chain), solution.definitions, solution.branches, solution.joint_variables, solution.free)
    if key not in _compiled:
        if len(_compiled) > COMPILED_KEPT:  # a long session solving many arms keeps only recent ones
            _compiled.clear()
        namespace: dict = {}
        exec(compile(module_text(solution), f"<ik of {solution.chain.name}>", "exec"), namespace)  # our own text
        _compiled[key] = (namespace["ik"], *_constants(solution))
    return _compiled[key]


def _constants(solution):
    """({constant name: keyword of the module's ik()}, the names that have no default)."""
    keywords = keyword_names(solution)
    sample = {str(symbol) for symbol in solution.chain.sample}
    return keywords, [name for name in keywords if name not in sample]
