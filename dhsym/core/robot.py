"""A robot: its plain-math `Chain` and what its file says about it, with its frames numbered as
the lecture numbers them.

A `Chain` counts its frames 0..n (plus "base" and "tool"). A lecture often does not: a wrist
that follows a 3R arm has frames 3..6 (a robot file's `first_frame: 3`). A `Robot` takes and
returns frame and joint numbers as they are printed, everywhere: `transform(3, 6)`, `frames`,
`link(4)`, `jacobian(frame=3)`. `robot.chain` is the math with frames 0..n; `chain_frame` and
`frame_number` translate between the two numberings for code built on the chain.

A robot is immutable; `with_chain` and `replace` give a changed copy that keeps everything
else (a conversion to the other convention keeps the name, the sample values, the numbering...).

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
from contextlib import contextmanager
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import sympy

from ..errors import UserError
from .chain import Chain, Frame, TransformTooLarge, frame_named, too_large_message
from .inertia import MassModel
from .numbering import Numbering
from .numbers import WrittenNumbers


@dataclass(frozen=True)
class Robot:
    """A chain and what its robot file says: `name`, `source`, `notes`, `sample` (numbers for its
    constants, for pictures and numeric checks), `numbers` (how the file wrote its numbers, so
    that printers write them back the same way), `frame_offset` (the number printed for the
    chain's frame 0: a robot file's `first_frame`), `file` (the file it was read from) and
    `warnings` (what its reading noticed: "FILE:LINE:COL: message") and `masses` (its links'
    inertial parameters and gravity, dhsym.core.inertia). Frames are numbered as printed.

    >>> import sympy
    >>> from dhsym.core.chain import DHRow
    >>> wrist = Robot(Chain([DHRow.revolute(sympy.Symbol("theta_4", real=True))], "standard"),
    ...               name="one wrist joint", frame_offset=3)
    >>> wrist.frames, wrist.link(4) == wrist.chain.link(1)
    ([3, 4], True)
    """

    chain: Chain
    name: str = ""
    source: str = ""
    notes: str = ""
    sample: Mapping = field(default_factory=dict, hash=False)  # symbol -> exact number
    numbers: WrittenNumbers = WrittenNumbers()
    frame_offset: int = 0
    file: str = ""
    warnings: tuple = ()
    masses: MassModel = MassModel()
    _cache: dict = field(default_factory=dict, init=False, repr=False, compare=False, hash=False)

    def __post_init__(self):
        if not isinstance(self.chain, Chain):
            raise TypeError(f"a Robot is made of a Chain, not {type(self.chain).__name__}")
        Numbering(self.frame_offset)  # checks it
        if self.masses.links and len(self.masses.links) != self.chain.n:
            raise ValueError(f"{len(self.masses.links)} links' masses for {self.chain.n} joints")
        unknown = [s for s in self.sample if s not in self.chain.symbols]
        weights = self.masses.symbols(self.n, self.frame_offset + 1) if unknown else set()
        unknown = sorted(str(s) for s in unknown if s not in weights)

        if unknown:
            raise UserError(f"sample: the robot has no symbol {unknown[0]!r}")
        object.__setattr__(self, "sample", MappingProxyType(dict(self.sample)))
        object.__setattr__(self, "warnings", tuple(self.warnings))
        object.__setattr__(self, "numbers", self.numbers or WrittenNumbers())

    def __reduce__(self):
        """Pickled and deep-copied as the fields it was made from (its sample a plain dict: a
        read-only view cannot be pickled); what it worked out is worked out again.

        >>> import copy, pickle, sympy
        >>> from dhsym.core.chain import DHRow
        >>> l = sympy.Symbol("l", real=True)
        >>> arm = Robot(Chain([DHRow.revolute(sympy.Symbol("q", real=True), a=l)], "standard"), sample={l: 1})
        >>> copy.deepcopy(arm).fk() == arm.fk() == pickle.loads(pickle.dumps(arm)).fk()
        True
        >>> pickle.loads(pickle.dumps(arm)).sample
        mappingproxy({l: 1})
        """
        fields = {f.name: getattr(self, f.name) for f in dataclasses.fields(self) if f.init}
        return type(self), tuple({**fields, "sample": dict(self.sample)}.values())

    def __repr__(self) -> str:
        joints = "".join(row.joint for row in self.rows)
        numbers = [f for f in self.frames if isinstance(f, int)]
        return (f"Robot({self.name!r}, {self.convention} DH, {self.n} joint{'s' if self.n > 1 else ''}: {joints}, "
                f"frames {numbers[0]}..{numbers[-1]})")

    def _repr_latex_(self) -> str:
        """Jupyter shows a robot as its DH table, rows numbered as its joints."""
        from ..printing.render import latex_table  # printing sits above the math; only this display needs it

        return f"$$\n{latex_table(self)}\n$$"

    # ------------------------------------------------------------ copies

    def with_chain(self, chain: Chain) -> "Robot":
        """The same robot (name, numbering, sample...) with another chain, as a conversion gives."""
        return dataclasses.replace(self, chain=chain)

    def replace(self, **changes) -> "Robot":
        """A copy with some fields changed: `robot.replace(frame_offset=0)`."""
        return dataclasses.replace(self, **changes)

    # ------------------------------------------------------------ what does not depend on numbering

    def filled_masses(self) -> MassModel:
        """Every link's mass, centre of mass and inertia, and gravity: the generic symbols
        (m_4, x_c4, I_xx4 …, numbered as the joints are printed) where the file gives none."""
        return self.masses.filled(self.n, self.frame_offset + 1)

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

    @property
    def path(self) -> str:
        """Where the robot comes from, for messages: its file, else its name."""
        return self.file or self.name or "<robot>"

    # ------------------------------------------------------------ frame numbers

    @property
    def numbering(self) -> Numbering:
        """How its frames and joints are printed (dhsym.core.numbering): the one translation between
        the chain's frames 0..n and the robot file's numbers."""
        return Numbering(self.frame_offset)

    @property
    def frames(self) -> list[Frame]:
        """The frames as printed: [3, 4, 5, 6] for a wrist numbered from 3; "base"/"tool" where present."""
        return [self.frame_number(f) for f in self.chain.frames]

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
        return list(range(self.frame_offset + 1, self.frame_offset + self.n + 1))

    def frame_number(self, frame: Frame) -> Frame:
        """The printed number of one of the chain's frames (0..n, "base", "tool").

        >>> from dhsym.io.library import load
        >>> load("spherical_wrist").frame_number(0), load("spherical_wrist").frame_number("tool")
        (3, 'tool')
        """
        return frame + self.frame_offset if isinstance(frame, int) else frame

    def chain_frame(self, frame: Frame) -> Frame:
        """The chain's frame (0..n, "base", "tool") for a frame as printed: an int, or text a
        user typed ("4", " 04", "+4", "Tool").

        >>> from dhsym.io.library import load
        >>> wrist = load("spherical_wrist")
        >>> wrist.chain_frame(4), wrist.chain_frame(" 06")
        (1, 3)
        >>> wrist.chain_frame("0")
        Traceback (most recent call last):
        dhsym.errors.UserError: no frame 0 in this robot; frames are 3, 4, 5, 6
        """
        if isinstance(frame, bool) or not isinstance(frame, (int, str)):
            raise UserError(f"a frame is a number or base/tool, not {frame!r}")
        return frame_named(frame, self.chain.frames, self.frame_number)

    def joint_index(self, joint: int) -> int:
        """The chain's joint (1..n) for a printed joint number (a wrist's joints 4..6 are 1..3)."""
        if not (isinstance(joint, int) and joint in self.joints):
            listed = self.joints
            raise UserError(f"no joint {joint!r} in this robot; joints are {listed[0]}..{listed[-1]}")
        return joint - self.frame_offset

    # ------------------------------------------------------------ the math, in printed numbers

    def transform(self, i: Frame, j: Frame, raw: bool = False) -> sympy.Matrix:
        """{i}T_{j} between frames as printed; for i after j the inverse, built in closed form."""
        start, end = self.chain_frame(i), self.chain_frame(j)
        with self.numbered():
            return self.chain.transform(start, end, raw=raw)

    def fk(self, raw: bool = False) -> sympy.Matrix:
        """The whole chain, from base (else the first frame) to tool (else the last)."""
        with self.numbered():
            return self.chain.fk(raw=raw)

    def link(self, i: int, raw: bool = False) -> sympy.Matrix:
        """The link matrix {i-1}T_i of joint i as printed (a wrist numbered 3..6: link(4) is ³T₄)."""
        with self.numbered():
            return self.chain.link(self.joint_index(i), raw=raw)

    def links(self, raw: bool = False) -> list[sympy.Matrix]:
        return [self.link(i, raw=raw) for i in self.joints]

    def steps(self, i: Frame, j: Frame) -> list:
        """The elementary steps (Rz, Tz, Tx, Rx, base and tool steps) from frame i to frame j, as
        printed; inverted and reversed for i after j."""
        return self.chain.steps(self.chain_frame(i), self.chain_frame(j))

    def jacobian(self, frame: Frame | None = None, point: Frame | None = None) -> sympy.Matrix:
        """The geometric Jacobian (rows vx vy vz ωx ωy ωz) of the origin of frame `point` (default:
        the last), expressed in frame `frame` (default: the first); frames as printed."""
        from ..velocity.jacobian import jacobian  # velocity is built on core, not the other way

        frame = self.chain.frames[0] if frame is None else self.chain_frame(frame)
        point = self.chain.frames[-1] if point is None else self.chain_frame(point)
        with self.numbered():
            return jacobian(self.chain, frame, point)

    def ik(self, free=()):
        """The closed-form inverse kinematics, with the joint variables `free` (symbols or names)
        kept as parameters: its branches, `.evaluate(T)`, `.latex()` and `.code()`; see
        dhsym.inverse. Solved once per choice of `free`."""
        from ..api.ik import inverse_kinematics  # the facade stands above every layer

        key = frozenset(getattr(v, "name", str(v)) for v in free)
        if key not in self._cache:
            self._cache[key] = inverse_kinematics(self, free)
        return self._cache[key]

    @contextmanager
    def numbered(self):
        """Inside it, a transform refused as too large is named with the printed frame numbers."""
        try:
            yield
        except TransformTooLarge as error:
            shown = [self.frame_number(f) for f in (error.start, error.end)]
            raise TransformTooLarge(error.start, error.end, error.size, too_large_message(*shown, error.size)) \
                from None


def as_robot(chain_or_robot) -> Robot:
    """A Robot as it is, or a plain Chain as a robot without a file (frames 0..n), for code that
    takes either.

    >>> from dhsym.io.library import load
    >>> as_robot(load("planar2r").chain).frames, as_robot(load("spherical_wrist")).frames
    ([0, 1, 2], [3, 4, 5, 6])
    """
    if isinstance(chain_or_robot, Robot):
        return chain_or_robot
    return Robot(chain_or_robot)


def as_chain(chain_or_robot) -> Chain:
    """The plain chain (frames 0..n) of a Robot, or a Chain as it is."""
    return chain_or_robot.chain if isinstance(chain_or_robot, Robot) else chain_or_robot
