"""`robot.ik(free=...)`: a closed-form inverse-kinematics solution for notebooks and programs,
with its branches, numeric evaluation of every branch, the derivation in LaTeX (Jupyter renders
it), the text of `dhsym ik` and the standalone numpy module of `dhsym ik --format python`.

    puma = dhsym.load("puma560")
    ik = puma.ik()
    [branch.name for branch in ik.branches]         # eight named configurations
    ik.evaluate(T)                                  # (8, 6) joint values, NaN where none
    ik.evaluate(T, within_limits=True)              # NaN too where a joint is outside its limits
    ik.nearest(ik.evaluate(T), q_now)               # the branch nearest the joint values q_now
    ik.latex()                                      # the derivation, rendered by Jupyter
    print(ik.code())                                # ik(T, **constants), numpy only

Here, above every layer it calls, a robot's file meets the solver: `inverse_kinematics` hands
dhsym.inverse.solve the plain chain (frames 0..n) with the file's sample values, numbers and name,
and the printers number the frames as the file does.

>>> import dhsym
>>> inverse_kinematics(dhsym.load("spherical_wrist")).text().splitlines()[2]
'Target ³T₆, the pose to reach (what `dhsym fk` prints):'
"""
from __future__ import annotations

from ..core.chain import Chain
from ..core.robot import Robot
from ..inverse import solve
from ..inverse.codegen import module_text
from ..inverse.codegen_limits import joint_limit_lists, limits_section
from ..inverse.evaluate import Program
from ..latex.ik import notebook_display
from ..printing.ik_solution import json_solution, text_solution


def inverse_kinematics(robot, free=()) -> "InverseKinematics":
    """The solution of `robot` (a Robot, or a plain Chain: a robot without a file) with the joint
    variables `free` (symbols or names) kept as parameters, its decimals as the robot file wrote
    them; its messages and titles use the robot's name and frame numbers."""
    robot = Robot(robot) if isinstance(robot, Chain) else robot
    solution = solve(robot.chain, free, sample=robot.sample, numbers=robot.numbers, name=robot.name,
                     path=robot.path)
    return InverseKinematics(robot, solution)


def numeric_inverse_kinematics(robot, free=(), constants=None):
    """The numeric inverse kinematics (dhsym.inverse.numeric, numpy) of `robot` (a Robot, or a plain
    Chain) with the joint variables `free` given; `constants` (symbols or names to numbers) take
    precedence over the robot file's sample values."""
    from ..inverse.numeric.solver import numeric_inverse  # numpy, only when numbers are asked for

    robot = Robot(robot) if isinstance(robot, Chain) else robot
    return numeric_inverse(robot.chain, free, constants, sample=robot.sample, name=robot.name)


class InverseKinematics:
    """A closed-form solution (`solution`, see dhsym.inverse.solution) of a `robot` and what a user
    does with it. It pickles and deep-copies (the solution's expressions as they are); the
    compiled module that `evaluate` keeps is compiled again where it is needed."""

    def __init__(self, robot, solution):
        self.robot, self.solution = robot, solution
        self._program = None  # the generated module, compiled on first use (dhsym.inverse.evaluate)

    def __getstate__(self) -> dict:
        return {"robot": self.robot, "solution": self.solution}

    def __setstate__(self, state: dict) -> None:
        self.__init__(state["robot"], state["solution"])

    def _compiled(self) -> Program:
        if self._program is None:
            self._program = Program(self.solution, self.robot.name, getattr(self.robot, "sample", {}))
        return self._program

    def __repr__(self) -> str:
        count = len(self.branches)
        names = "; ".join(branch.name for branch in self.branches)
        return f"InverseKinematics({self.robot.name!r}, {count} branch{'es' if count != 1 else ''}: {names})"

    @property
    def branches(self):
        return self.solution.branches

    @property
    def definitions(self):
        return self.solution.definitions

    @property
    def joint_variables(self):
        return self.solution.joint_variables

    def evaluate(self, T, within_limits: bool = False, **constants):
        """Every branch's joint values for the pose T (4×4) or poses (N×4×4), NaN where a branch
        does not exist; constants default to the robot file's sample values; a name the robot
        does not have is an error that names those it has. `within_limits`: NaN also for each
        branch with a joint outside the robot's joint limits, revolute angles moved by whole turns
        into their limits (dhsym.inverse.joint_limits); a robot without limits keeps every branch."""
        values = self._compiled()(T, constants)
        if not within_limits:
            return values
        from ..inverse.joint_limits import within_joint_limits  # numpy, as evaluate is

        return within_joint_limits(values, *self._limits())

    def nearest(self, solutions, q_current):
        """The branch of `solutions` (what `evaluate` gives, (B, n) or (N, B, n)) nearest the joint
        values `q_current` (n,), in the order of `joint_variables`: the least sum of squared
        differences, revolute angles compared modulo 2π; NaN where no branch exists."""
        from ..inverse.joint_limits import nearest_branch

        return nearest_branch(solutions, q_current, self._limits()[2])

    def _limits(self) -> tuple:
        """(lower, upper, revolute), numpy arrays in the order of `joint_variables`."""
        import numpy

        robot = self.robot
        lists = joint_limit_lists(robot.chain, getattr(robot, "joint_limits", ()), self.joint_variables)
        return tuple(numpy.array(values) for values in lists)

    def code(self, command: str = "") -> str:
        """The standalone numpy module (`dhsym ik --format python`); for a robot with joint limits
        its `ik(T, within_limits=True)` drops the branches outside them, and `nearest(Q, q)` picks one."""
        text = module_text(self.solution, self.robot.name, command)
        if not getattr(self.robot, "joint_limits", ()):
            return text
        return text.rstrip("\n") + "\n" + limits_section(*joint_limit_lists(
            self.robot.chain, self.robot.joint_limits, self.joint_variables))

    def function(self):
        """`ik(T, **constants)` of the generated module, ready to call."""
        return self._compiled().function

    def latex(self):
        """The derivation and every branch as LaTeX that Jupyter renders (`print()` shows the source)."""
        return notebook_display(self.solution, self.robot)

    def _repr_latex_(self) -> str:
        return self.latex()._repr_latex_()

    def text(self, width: int = 100, ascii: bool = False) -> str:
        """What `dhsym ik` prints."""
        return text_solution(self.solution, self.robot, width, ascii)

    def json(self) -> dict:
        """What `dhsym ik --format json` prints, as a dict."""
        return json_solution(self.solution, self.robot)
