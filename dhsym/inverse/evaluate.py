"""Numbers from a closed-form solution: every branch at once, for one pose or many, vectorised
with numpy (imported here only, on first use: the symbolic commands never load it).

>>> import numpy, dhsym
>>> from dhsym.inverse.solve import solve
>>> arm = dhsym.load("planar2r")
>>> solution = solve(arm.chain, sample=arm.sample)
>>> pose = numpy.eye(4); pose[:2, 3] = [0.5, 0.4]        # a_1 = 0.5, a_2 = 0.4: θ = (0, π/2)
>>> numpy.round(evaluate(solution, pose), 6)
array([[ 0.      ,  1.570796],
       [ 1.349482, -1.570796]])

A constant the robot does not have is an error, not a value quietly left out:

>>> evaluate(solution, pose, {"a_3": 1.0}, name=arm.name)
Traceback (most recent call last):
...
dhsym.errors.UserError: Planar elbow manipulator (2R) has no constant a_3; its constants are a_1, a_2
"""
from __future__ import annotations

from ..errors import UserError
from .codegen import keyword_names, module_text


def evaluate(solution, T, constants=None, name: str = ""):
    """Joint values of every branch for the pose T (4×4 → (B, n)) or poses (N×4×4 → (N, B, n)):
    branches in solution order, joints in `solution.joint_variables` order, NaN where a branch
    does not exist. `constants` maps the robot's symbols (and --free joint variables), or their
    names, to numbers; the robot's sample values are the defaults. The numbers come from the
    module `dhsym ik --format python` writes (dhsym.inverse.codegen): one generator for the
    printed module and for this. A `Program` compiles it once for many calls; `name`: the robot's,
    for the messages."""
    return Program(solution, name)(T, constants)


class Program:
    """The generated module's `ik` for one solution, compiled once, and the names of its keyword
    arguments: what `robot.ik().evaluate()` keeps between calls (each solution its own). `others`:
    names of the robot file's values for other chapters (g, masses), accepted and left out."""

    def __init__(self, solution, name: str = "", others=()):
        namespace: dict = {}
        exec(compile(module_text(solution, name), f"<ik of {name}>", "exec"), namespace)  # our own text
        self.function = namespace["ik"]
        self.keywords = keyword_names(solution)  # constant or --free joint name -> keyword of ik()
        sample = {str(symbol) for symbol in solution.sample}
        self.required = [known for known in self.keywords if known not in sample]
        self.unused = set(map(str, others)) - set(self.keywords)  # the file's other values (g, masses): not needed
        self.free = {symbol.name for symbol in solution.free}
        self.robot = name or "the robot"

    def __call__(self, T, constants=None):
        given = {getattr(k, "name", str(k)): v for k, v in (constants or {}).items()}
        given = {name: value for name, value in given.items() if name not in self.unused}
        for name in given:
            if name not in self.keywords:
                raise UserError(self._unknown(name))
        for name in self.required:
            if name not in given:
                raise UserError(f"no value for {name}: give it in the constants (a --free joint variable needs one)")
        return self.function(T, **{self.keywords[name]: float(value) for name, value in given.items()})

    def _unknown(self, name: str) -> str:
        """The message for a constant the robot does not have, naming those it has."""
        constants = [known for known in self.keywords if known not in self.free]
        said = f"its constants are {', '.join(constants)}" if constants else "it has no constants"
        if self.free:
            said += f", its --free joint variables {', '.join(known for known in self.keywords if known in self.free)}"
        return f"{self.robot} has no constant {name}; {said}"
