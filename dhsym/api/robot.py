"""The notebook's `Robot`: the robot record of dhsym.core.robot with the conveniences a notebook
uses, every frame and joint numbered as the robot file prints them.

A wrist that follows a 3R arm has frames 3..6 (its file's `first_frame: 3`): `transform(3, 6)`,
`frames`, `link(4)`, `jacobian(frame=3)` take and give those numbers; `robot.chain` is the plain
math, frames 0..n, and `robot.numbering` translates between the two (the one place that does).
`dhsym.load`, `dhsym.convert`, `dhsym.import_urdf(...).robot` and `dhsym.Robot(...)` give one.

>>> import sympy
>>> from dhsym.core.chain import Chain, DHRow
>>> t4, t5 = sympy.symbols("theta_4 theta_5", real=True)
>>> wrist = Robot(Chain([DHRow.revolute(t4, alpha=-sympy.pi / 2), DHRow.revolute(t5)], "standard"),
...               name="wrist", frame_offset=3)
>>> wrist
Robot('wrist', standard DH, 2 joints: RR, frames 3..5)
>>> wrist.frames, wrist.transform(3, 5) == wrist.chain.transform(0, 2), wrist.link(4) == wrist.chain.link(1)
([3, 4, 5], True, True)
>>> wrist.transform(0, 5)
Traceback (most recent call last):
dhsym.errors.UserError: no frame 0 in this robot; frames are 3, 4, 5
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import sympy

from ..core import robot as record
from ..core.chain import Chain, Frame

# The layers each convenience hands over to are imported when it is first used, so that a command
# that only reads a robot loads neither the velocity layer nor the printers.


@dataclass(frozen=True, repr=False)
class Robot(record.Robot):
    """A robot record (chain, name, sample values, numbering …) with its kinematics in printed
    numbers and its Jupyter display (the DH table). Immutable; what it works out (a solution per
    choice of free variables) is kept with it.

    >>> import dhsym
    >>> puma = dhsym.load("puma560")
    >>> puma.transform(3, 6)[:3, 2].T
    Matrix([[-sin(theta_5)*cos(theta_4), cos(theta_5), sin(theta_4)*sin(theta_5)]])
    """

    _solved: dict = field(default_factory=dict, init=False, repr=False, compare=False, hash=False)

    @classmethod
    def of(cls, robot: record.Robot) -> "Robot":
        """The notebook robot of a robot record (itself when it is one)."""
        if isinstance(robot, cls):
            return robot
        return cls(**{f.name: getattr(robot, f.name) for f in dataclasses.fields(record.Robot) if f.init})

    def _repr_latex_(self) -> str:
        """Jupyter shows a robot as its DH table, rows numbered as its joints."""
        from ..printing.render import latex_table

        return f"$$\n{latex_table(self)}\n$$"

    # ------------------------------------------------------------ the chain's, numbering aside

    @property
    def n(self) -> int:
        return self.chain.n

    @property
    def rows(self) -> tuple:
        return self.chain.rows

    @property
    def convention(self) -> str:
        return self.chain.convention

    @property
    def base(self) -> tuple:
        return self.chain.base

    @property
    def tool(self) -> tuple:
        return self.chain.tool

    @property
    def joint_variables(self) -> list[sympy.Symbol]:
        return self.chain.joint_variables

    @property
    def symbols(self) -> set[sympy.Symbol]:
        return self.chain.symbols

    # ------------------------------------------------------------ frames and joints as printed

    @property
    def frames(self) -> list[Frame]:
        """The frames as printed: [3, 4, 5, 6] for a wrist numbered from 3; "base"/"tool" where present."""
        return self.numbering.frames(self.chain)

    @property
    def first_frame(self) -> Frame:
        """The first frame as printed: "base" where there is one, else the number of frame 0."""
        return self.frames[0]

    @property
    def last_frame(self) -> Frame:
        return self.frames[-1]

    @property
    def joints(self) -> list[int]:
        """The joint numbers as printed: joint i moves frame i, so a wrist with frames 3..6 has joints 4..6."""
        return self.numbering.joints(self.chain)

    # ------------------------------------------------------------ the math, in printed numbers

    def transform(self, i: Frame, j: Frame, raw: bool = False) -> sympy.Matrix:
        """{i}T_{j} between frames as printed (an int, or text: "3", "tool"); for i after j the
        inverse, built in closed form."""
        start, end = (self.numbering.chain_frame(f, self.chain) for f in (i, j))
        with self.numbering.printed():
            return self.chain.transform(start, end, raw=raw)

    def fk(self, raw: bool = False) -> sympy.Matrix:
        """The whole chain, from base (else the first frame) to tool (else the last)."""
        with self.numbering.printed():
            return self.chain.fk(raw=raw)

    def link(self, i: int, raw: bool = False) -> sympy.Matrix:
        """The link matrix {i-1}T_i of joint i as printed (a wrist numbered 3..6: link(4) is ³T₄)."""
        index = self.numbering.joint_index(i, self.chain)
        with self.numbering.printed():
            return self.chain.link(index, raw=raw)

    def links(self, raw: bool = False) -> list[sympy.Matrix]:
        return [self.link(i, raw=raw) for i in self.joints]

    def steps(self, i: Frame, j: Frame) -> list:
        """The elementary steps (Rz, Tz, Tx, Rx, base and tool steps) from frame i to frame j, as
        printed; inverted and reversed for i after j."""
        return self.chain.steps(*(self.numbering.chain_frame(f, self.chain) for f in (i, j)))

    def jacobian(self, frame: Frame | None = None, point: Frame | None = None) -> sympy.Matrix:
        """The geometric Jacobian (rows vx vy vz ωx ωy ωz) of the origin of frame `point` (default:
        the last), expressed in frame `frame` (default: the first); frames as printed."""
        from ..velocity.jacobian import jacobian

        frame, point = self.numbering.chain_frames(self.chain, frame, point)
        with self.numbering.printed():
            return jacobian(self.chain, frame, point)

    def determinant(self, frame: Frame | None = None, point: Frame | None = None):
        """det J factored (a dhsym.velocity.Determinant), its notes with the printed frame numbers and
        the file's decimals; frames as printed."""
        from ..velocity import determinant

        frame, point = self.numbering.chain_frames(self.chain, frame, point)
        with self.numbering.printed():
            return determinant(self.chain, frame, point, numbers=self.numbers, sample=self.sample,
                               numbering=self.numbering)

    def singularities(self, result=None, point: Frame | None = None) -> list:
        """What each factor of det J (`result`, default: `determinant()`) means, joints numbered as
        printed (`.meaning`; dhsym.velocity.Singularity)."""
        from ..velocity import singularities

        result = self.determinant(point=point) if result is None else result
        point = self.numbering.chain_frames(self.chain, None, point)[1]
        return singularities(self.chain, result, point, sample=self.sample, numbering=self.numbering)

    def propagate(self) -> list:
        """Craig's outward velocity propagation, each step's frame as printed (dhsym.velocity.propagation)."""
        from ..velocity import propagate

        return [dataclasses.replace(step, frame=self.numbering.frame(step.frame)) for step in propagate(self.chain)]

    def ik(self, free=()):
        """The closed-form inverse kinematics, with the joint variables `free` (symbols or names)
        kept as parameters: its branches, `.evaluate(T)`, `.latex()` and `.code()`; see
        dhsym.inverse. Solved once per choice of `free`."""
        from .ik import inverse_kinematics  # the solver only when it is asked for

        key = frozenset(getattr(v, "name", str(v)) for v in free)
        if key not in self._solved:
            self._solved[key] = inverse_kinematics(self, free)
        return self._solved[key]

    def dynamics(self, to: Frame | None = None):
        """The equations of motion τ = M q̈ + C q̇ + g (dhsym.api.dynamics): `.M`, `.C`, `.g`,
        `.tau(...)`, `.latex()` …; of the links up to frame `to` (as printed) only.

        >>> import dhsym
        >>> dhsym.load("spong_elbow").dynamics().M[1, 1]
        I_2 + l_c2**2*m_2
        """
        from .dynamics import robot_dynamics

        return robot_dynamics(self, to)


def notebook_robot(value) -> Robot:
    """The notebook robot of what a user hands a `dhsym` function: a robot, what `import_urdf` gives
    (its `.robot`), or a plain `Chain` (a robot without a file, frames 0..n)."""
    value = getattr(value, "robot", value)
    if isinstance(value, Chain):
        return Robot(value)
    if isinstance(value, record.Robot):
        return Robot.of(value)
    raise TypeError(f"a robot or a chain is needed here, not {type(value).__name__}")
