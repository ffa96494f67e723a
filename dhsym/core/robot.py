"""A robot: its plain-math `Chain` and what its file says about it.

A `Chain` counts its frames 0..n (plus "base" and "tool"). A lecture often does not: a wrist
that follows a 3R arm has frames 3..6 (a robot file's `first_frame: 3`). A `Robot` is a record:
the chain, with frames 0..n, and what its file says, its numbering among it (`robot.numbering`,
dhsym.core.numbering, the one translation between the two). It has no transforms of its own and
takes no frame numbers: code inside dhsym works on `robot.chain` and prints with
`robot.numbering`; the notebook `Robot` (`dhsym.Robot`, dhsym.api.robot) adds `transform(3, 6)`,
`fk()`, `jacobian()`, `ik()` in printed numbers.

A robot is immutable; `with_chain` and `replace` give a changed copy that keeps everything
else (a conversion to the other convention keeps the name, the sample values, the numbering...).

>>> import sympy
>>> from dhsym.core.chain import Chain, DHRow
>>> t4, t5 = sympy.symbols("theta_4 theta_5", real=True)
>>> wrist = Robot(Chain([DHRow.revolute(t4, alpha=-sympy.pi / 2), DHRow.revolute(t5)], "standard"),
...               name="wrist", frame_offset=3)
>>> wrist
Robot('wrist', standard DH, 2 joints: RR, frames 3..5)
>>> wrist.numbering.frames(wrist.chain), wrist.chain.frames
([3, 4, 5], [0, 1, 2])
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import sympy

from ..errors import UserError
from .chain import Chain, plain
from .inertia import MassModel
from .numbering import Numbering
from .numbers import WrittenNumbers


@dataclass(frozen=True)
class Robot:
    """A chain and what its robot file says: `name`, `source`, `notes`, `sample` (numbers for its
    constants, for pictures and numeric checks), `numbers` (how the file wrote its numbers, so
    that printers write them back the same way), `frame_offset` (the number printed for the
    chain's frame 0: a robot file's `first_frame`), `file` (the file it was read from) and
    `warnings` (what its reading noticed: "FILE:LINE:COL: message"), `masses` (its links'
    inertial parameters and gravity, dhsym.core.inertia) and `joint_limits` (empty, or for each
    joint None or its (lower, upper) exact numbers, in the joint variable's units: radians, lengths).

    >>> import sympy
    >>> from dhsym.core.chain import DHRow
    >>> wrist = Robot(Chain([DHRow.revolute(sympy.Symbol("theta_4", real=True))], "standard"),
    ...               name="one wrist joint", frame_offset=3)
    >>> wrist.numbering.joints(wrist.chain), wrist.path
    ([4], 'one wrist joint')
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
    joint_limits: tuple = ()

    def __post_init__(self):
        if not isinstance(self.chain, Chain):
            raise TypeError(f"a Robot is made of a Chain, not {type(self.chain).__name__}")
        numbering = Numbering(self.frame_offset)  # checks it
        if self.masses.links and len(self.masses.links) != self.chain.n:
            raise ValueError(f"{len(self.masses.links)} links' masses for {self.chain.n} joints")
        unknown = [s for s in self.sample if s not in self.chain.symbols]
        weights = self.masses.symbols(self.chain.n, numbering.first_joint) if unknown else set()
        unknown = sorted(str(s) for s in unknown if s not in weights)

        if unknown:
            raise UserError(f"sample: the robot has no symbol {unknown[0]!r}")
        object.__setattr__(self, "sample", MappingProxyType(dict(self.sample)))
        object.__setattr__(self, "warnings", tuple(self.warnings))
        object.__setattr__(self, "numbers", self.numbers or WrittenNumbers())
        limits = tuple(None if pair is None else tuple(map(sympy.sympify, pair)) for pair in self.joint_limits)
        if limits and len(limits) != self.chain.n:
            raise ValueError(f"{len(limits)} joints' limits for {self.chain.n} joints")
        object.__setattr__(self, "joint_limits", limits if any(limits) else ())

    def __reduce__(self):
        """Pickled and deep-copied as the fields it was made from (its sample a plain dict: a
        read-only view cannot be pickled).

        >>> import copy, pickle, sympy
        >>> from dhsym.core.chain import DHRow
        >>> l = sympy.Symbol("l", real=True)
        >>> arm = Robot(Chain([DHRow.revolute(sympy.Symbol("q", real=True), a=l)], "standard"), sample={l: 1})
        >>> copy.deepcopy(arm).chain.fk() == arm.chain.fk() == pickle.loads(pickle.dumps(arm)).chain.fk()
        True
        >>> pickle.loads(pickle.dumps(arm)).sample
        mappingproxy({l: 1})
        """
        fields = {f.name: getattr(self, f.name) for f in dataclasses.fields(self) if f.init}
        return type(self), tuple({**fields, "sample": dict(self.sample)}.values())

    def __repr__(self) -> str:
        chain, numbering = self.chain, self.numbering
        joints = "".join(row.joint for row in chain.rows)
        plural = "s" if chain.n > 1 else ""
        return (f"{type(self).__name__}({self.name!r}, {chain.convention} DH, {chain.n} joint{plural}: {joints}, "
                f"frames {numbering.frame(0)}..{numbering.frame(chain.n)})")

    # ------------------------------------------------------------ copies

    def with_chain(self, chain: Chain) -> "Robot":
        """The same robot (name, numbering, sample...) with another chain, as a conversion gives."""
        return dataclasses.replace(self, chain=plain(chain))

    def replace(self, **changes) -> "Robot":
        """A copy with some fields changed: `robot.replace(frame_offset=0)`."""
        return dataclasses.replace(self, **changes)

    # ------------------------------------------------------------ what the file says

    @property
    def numbering(self) -> Numbering:
        """How its frames and joints are printed (dhsym.core.numbering): the one translation between
        the chain's frames 0..n and the robot file's numbers."""
        return Numbering(self.frame_offset)

    @property
    def path(self) -> str:
        """Where the robot comes from, for messages: its file, else its name."""
        return self.file or self.name or "<robot>"

    def filled_masses(self) -> MassModel:
        """Every link's mass, centre of mass and inertia, and gravity: the generic symbols
        (m_4, x_c4, I_xx4 …, numbered as the joints are printed) where the file gives none."""
        return self.masses.filled(self.chain.n, self.numbering.first_joint)
