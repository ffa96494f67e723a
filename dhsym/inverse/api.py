"""`chain.ik(free=...)`: a closed-form inverse-kinematics solution for notebooks and programs,
with its branches, numeric evaluation of every branch, the derivation in LaTeX (Jupyter renders
it) and the standalone numpy module of `dhsym ik --format python`.

    puma = dhsym.load("puma560")
    ik = puma.ik()
    [branch.name for branch in ik.branches]         # eight named configurations
    ik.evaluate(T)                                  # (8, 6) joint values, NaN where none
    ik.latex()                                      # the derivation, rendered by Jupyter
    print(ik.code())                                # ik(T, **constants), numpy only

The free joint variables are named by symbol or by name; a name the chain lacks is one clear
error:

>>> import dhsym
>>> free_variables(dhsym.load("planar2r"), ["theta_2"])
(theta_2,)
>>> free_variables(dhsym.load("planar2r"), ["theta_3"])  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
dhsym.errors.UserError: --free theta_3: Planar ... has no joint variable theta_3; its joint variables are ...
"""
from __future__ import annotations

from ..core.robot import as_robot
from ..errors import UserError
from .bounds import redundancy, redundant_message, refuse_unbounded
from .codegen import module_text
from .evaluate import Program
from .naming import checked_names
from .redundant import working_free
from .solve import solve
from .written import as_written, with_written_symbols


def free_variables(chain, names, option: str = "--free") -> tuple:
    """The joint variables `names` (symbols or their names) in joint order, each checked."""
    chain = as_robot(chain)  # its name, for the messages
    variables = {v.name: v for v in chain.joint_variables}
    chosen = []
    for name in names:
        text = getattr(name, "name", str(name))
        if text not in variables:
            raise UserError(f"{option} {text}: {chain.name or 'the robot'} has no joint variable {text}; its joint "
                            f"variables are {', '.join(variables)}")
        chosen.append(variables[text])
    return tuple(v for v in chain.joint_variables if v in chosen)


def inverse_kinematics(chain, free=()) -> "InverseKinematics":
    """The solution of `chain` (a Robot, or a plain Chain) with the joint variables `free` kept as
    parameters, its decimals as the robot file wrote them (solved as symbols, see
    dhsym.inverse.written); its messages and titles use the robot's name and frame numbers."""
    robot = as_robot(chain)
    variables = free_variables(robot, free)
    redundant = redundancy(robot, variables)
    if redundant:  # a closed form needs other or more parameters: which ones, checked by deriving with them
        refuse_unbounded(robot)  # else no choice could be derived
        kept, count = ((), redundant.needed) if redundant.lost else (variables, redundant.extra)
        example, tried = working_free(robot, kept, count) if count else ((), 0)
        raise UserError(redundant_message(robot, variables, redundant, example, tried))
    numbers = robot.numbers  # how the file wrote its numbers: the one place this reads it
    solving, written = with_written_symbols(robot, numbers)
    solution = solve(solving, free=variables)
    solution = as_written(solution, robot, numbers) if written else solution
    return InverseKinematics(checked_names(solution))


class InverseKinematics:
    """A closed-form solution (`solution`, see dhsym.inverse.solution) and what a user does with it.
    It pickles and deep-copies (the solution's expressions as they are); the compiled module that
    `evaluate` keeps is compiled again where it is needed."""

    def __init__(self, solution):
        self.solution = solution
        self._program = None  # the generated module, compiled on first use (dhsym.inverse.evaluate)

    def __getstate__(self) -> dict:
        return {"solution": self.solution}

    def __setstate__(self, state: dict) -> None:
        self.__init__(state["solution"])

    def _compiled(self) -> Program:
        if self._program is None:
            self._program = Program(self.solution)
        return self._program

    def __repr__(self) -> str:
        count = len(self.branches)
        names = "; ".join(branch.name for branch in self.branches)
        return f"InverseKinematics({self.solution.chain.name!r}, {count} branch{'es' if count != 1 else ''}: {names})"

    @property
    def branches(self):
        return self.solution.branches

    @property
    def definitions(self):
        return self.solution.definitions

    @property
    def joint_variables(self):
        return self.solution.joint_variables

    def evaluate(self, T, **constants):
        """Every branch's joint values for the pose T (4×4) or poses (N×4×4), NaN where a branch
        does not exist; constants default to the robot file's sample values; a name the robot
        does not have is an error that names those it has."""
        return self._compiled()(T, constants)

    def code(self, command: str = "") -> str:
        """The standalone numpy module (`dhsym ik --format python`)."""
        return module_text(self.solution, command)

    def function(self):
        """`ik(T, **constants)` of the generated module, ready to call."""
        return self._compiled().function

    def latex(self):
        """The derivation and every branch as LaTeX that Jupyter renders (`print()` shows the source)."""
        from ..latex.ik import notebook_display  # the layout lives with the documents

        return notebook_display(self.solution)

    def _repr_latex_(self) -> str:
        return self.latex()._repr_latex_()

    def text(self, width: int = 100, ascii: bool = False) -> str:
        """What `dhsym ik` prints."""
        from ..printing.ik import text_solution  # printing sits above the math

        return text_solution(self.solution, width, ascii)

    def json(self) -> dict:
        """What `dhsym ik --format json` prints, as a dict."""
        from ..printing.ik import json_solution

        return json_solution(self.solution)
