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

from .codegen import keyword_names, module_text

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
