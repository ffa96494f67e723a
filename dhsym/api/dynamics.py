"""A robot's equations of motion for notebooks and programs: what `dhsym.equations_of_motion(robot)`
returns, and `robot.dynamics()` of the notebook Robot.

    elbow = dhsym.equations_of_motion(dhsym.load("spong_elbow"))
    elbow.M, elbow.C, elbow.g               # SymPy matrices in textbook form (d_ij, Spong's φ_k)
    elbow.christoffel[1, 2, 1]              # c_121, joints numbered as the robot prints them
    elbow.tau()                             # M q̈ + C q̇ + g, symbolic
    elbow.tau(q, qd, qdd)                   # numbers (numpy), one state or (N, n), the sample's constants
    elbow.regressor()                       # the base parameters and the columns of Y_b
    elbow.latex(steps=True)                 # the derivation, rendered by Jupyter
    elbow.show("d11", "phi1")               # some elements, by their names
    print(elbow.text()); print(elbow.code())

>>> import dhsym
>>> elbow = robot_dynamics(dhsym.load("spong_elbow"))
>>> elbow.g[1], elbow.christoffel[1, 1, 2]
(g*l_c2*m_2*cos(q_1 + q_2), l_1*l_c2*m_2*sin(q_2))
>>> elbow.tau([0.0, 0.0], [0.0, 0.0], [0.0, 0.0]).round(4).tolist()   # holding the arm out level
[19.62, 4.905]
"""
from __future__ import annotations

import json

import sympy

from ..dynamics.derive import derive
from ..dynamics.equations import links_to_frame, textbook_layout
from ..latex.display import Latex
from ..printing.dynamics import MotionTextPrinter, json_dynamics, text_dynamics


def robot_dynamics(robot, to: int | None = None) -> "RobotDynamics":
    """The equations of motion of `robot` (a robot file's robot: its masses, or the generic symbols
    where it gives none), in textbook form, of its links up to frame `to` (numbered as the robot
    prints its frames; all of them by default); a robot too large to print is refused at once."""
    if to is not None:
        robot = links_to_frame(robot, to, lambda first, last: f"to={to}: the last frame whose link moves is one "
                               f"of {first}..{last}")
    return RobotDynamics(robot, derive(robot.chain, robot.filled_masses()))


class RobotDynamics:
    """M, C, g and the Christoffel symbols of a robot, and what a user does with them."""

    def __init__(self, robot, result):
        self.robot, self.result = robot, result
        self._module = None  # the generated numpy module, compiled on first numeric use

    def __repr__(self) -> str:
        return f"<equations of motion of {self.robot.name or 'a robot'}: {self.result.M.rows} joints>"

    @property
    def M(self) -> sympy.Matrix:
        return self.result.M

    @property
    def C(self) -> sympy.Matrix:
        return self.result.C

    @property
    def g(self) -> sympy.Matrix:
        return self.result.g

    @property
    def christoffel(self) -> dict:
        """{(i, j, k): c_ijk} that are not zero, joints numbered as the robot prints them."""
        joint = self.robot.numbering.joint
        return {(joint(i), joint(j), joint(k)): value for (i, j, k), value in self.result.christoffel.items()}

    @property
    def variables(self) -> tuple:
        return self.result.variables

    @property
    def rates(self) -> tuple:
        return self.result.rates

    @property
    def accelerations(self) -> tuple:
        return self.result.accelerations

    def tau(self, q=None, qd=None, qdd=None, **constants):
        """M q̈ + C q̇ + g: symbolic with no state; else numbers for the joint values `q`, rates `qd`
        and accelerations `qdd` (one state, shape (n,), or many, (N, n)), the robot's sample values
        for its constants unless given by name (m_1=2.0)."""
        if q is None:
            return self.result.tau
        return self.numeric()["tau"](q, qd, qdd, **constants)

    def numeric(self) -> dict:
        """The generated module's functions M, C, g, tau and qdd (numpy), by name."""
        if self._module is None:
            namespace: dict = {}
            exec(compile(self.code(), f"{self.robot.name or 'robot'}_dynamics.py", "exec"), namespace)
            self._module = {name: namespace[name] for name in ("M", "C", "g", "tau", "qdd")}
        return self._module

    def regressor(self):
        """The base parameters and the columns of the base regressor (dhsym.dynamics.identification)."""
        from ..dynamics.identification import identification

        return identification(self.robot.chain, self.robot.filled_masses(), self.robot.numbering.first_joint)

    def steps(self, method: str = "lagrange"):
        """The derivation's records: Lagrange's (dhsym.dynamics.lagrange_steps) or Craig's Newton–Euler
        passes (method="newton-euler", dhsym.dynamics.craig_steps)."""
        if method == "lagrange":
            from ..dynamics.lagrange_steps import lagrange_steps

            return lagrange_steps(self.robot.chain, self.robot.filled_masses(), self.result)
        from ..dynamics.craig_steps import newton_euler_steps

        return newton_euler_steps(self.robot.chain, self.robot.filled_masses())

    def text(self, width: int = 100, ascii: bool = False, steps: bool = False, method: str = "lagrange",
             regressor: bool = False) -> str:
        """What `dhsym dynamics` prints."""
        printer = MotionTextPrinter(self.robot, self.result, ascii=ascii)
        return text_dynamics(self.robot, textbook_layout(self.result), printer, width, method,
                             self.steps(method) if steps else None, self.regressor() if regressor else None)

    def latex(self, steps: bool = False, method: str = "lagrange", regressor: bool = False) -> Latex:
        """The derivation as one display for Jupyter (print() shows its source)."""
        from ..latex.dynamics import notebook_display

        return notebook_display(self.robot, self.result, method, steps, regressor)

    def show(self, *names: str) -> Latex:
        """Some elements by name, laid out for the notebook: show("d22", "c121", "phi2", "tau1")."""
        from ..latex.dynamics import notebook_elements

        return notebook_elements(self.robot, self.result, names)

    def matrix(self, value, name: str = "") -> Latex:
        """Any matrix of these equations (Ṁ − 2C, a Jacobian) as the notebook shows it, rates dotted."""
        from ..latex.dynamics import notebook_matrix

        return notebook_matrix(self.robot, self.result, value, name)

    def _repr_latex_(self) -> str:
        return self.latex()._repr_latex_()

    def json(self) -> dict:
        """What `dhsym dynamics --format json` writes."""
        return json.loads(json.dumps(json_dynamics(self.robot, self.result)))

    def code(self) -> str:
        """The standalone numpy module of `dhsym dynamics --format python`."""
        from ..dynamics import dynamics_program, module_text

        program = dynamics_program(self.robot.chain, self.robot.filled_masses())
        return module_text(program, self.robot.name, self.robot.sample)
