"""How frames and joints are printed: the one place where a chain's frames 0..n become the numbers
a lecture (a robot file's `first_frame`) gives them.

Inside dhsym every function works on a plain `Chain`, frames 0..n, joints 1..n. A wrist that follows
a 3R arm is printed with frames 3..6 and joints 4..6: its `Numbering(3)` says so. The public
surfaces (the `dhsym` functions, the notebook `Robot`, the command line, the web page) build one
from a robot (`robot.numbering`) and use it both ways: a number a user typed to the chain's frame,
and a chain's frame or joint to the number printed.

>>> import sympy
>>> from dhsym.core.chain import Chain, DHRow
>>> from dhsym.core.transforms import Step
>>> t4, t5, t6 = sympy.symbols("theta_4 theta_5 theta_6", real=True)
>>> wrist = Chain([DHRow.revolute(t) for t in (t4, t5, t6)], "modified", tool=[Step("Tz", 1)])
>>> numbering = Numbering(3)
>>> numbering.frames(wrist), numbering.joints(wrist)
([3, 4, 5, 6, 'tool'], [4, 5, 6])
>>> numbering.frame(1), numbering.joint(2), numbering.chain_frame(" 05", wrist), numbering.joint_index(6, wrist)
(4, 5, 2, 3)
>>> numbering.chain_frame("2", wrist)
Traceback (most recent call last):
dhsym.errors.UserError: no frame 2 in this robot; frames are 3, 4, 5, 6, tool
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass

from ..errors import UserError
from .chain import Chain, Frame, TransformTooLarge, frame_named, plain, too_large_message

MAX_FIRST_FRAME = 999  # a robot file writes first_frame with at most 3 digits


@dataclass(frozen=True)
class Numbering:
    """`offset`: the number printed for the chain's frame 0 (a robot file's `first_frame`); joint i
    of the chain (1..n) is printed i + offset, as it moves frame i. "base" and "tool" keep their names.

    >>> Numbering().frame(0), Numbering(3).frame("tool"), Numbering(3).first_joint
    (0, 'tool', 4)
    """

    offset: int = 0

    def __post_init__(self):
        offset = self.offset
        if isinstance(offset, bool) or not (isinstance(offset, int) and 0 <= offset <= MAX_FIRST_FRAME):
            raise UserError(f"first_frame must be a whole number from 0 to {MAX_FIRST_FRAME}, not {offset!r}")

    # ------------------------------------------------------------ chain -> printed

    def frame(self, frame: Frame) -> Frame:
        """The printed label of one of a chain's frames (0..n, "base", "tool")."""
        return frame + self.offset if isinstance(frame, int) else frame

    def joint(self, index: int) -> int:
        """The printed number of the chain's joint `index` (1..n)."""
        return index + self.offset

    @property
    def first_joint(self) -> int:
        """The number printed for the chain's joint 1."""
        return self.offset + 1

    def frames(self, chain: Chain) -> list[Frame]:
        """The chain's frames as printed: "base", the numbers, "tool"."""
        return [self.frame(f) for f in plain(chain).frames]

    def joints(self, chain: Chain) -> list[int]:
        """The chain's joints as printed: a wrist with frames 3..6 has joints 4..6."""
        return [self.joint(i) for i in range(1, plain(chain).n + 1)]

    # ------------------------------------------------------------ printed -> chain

    def chain_frame(self, frame: Frame, chain: Chain) -> Frame:
        """The chain's frame (0..n, "base", "tool") for a frame as printed: an int, or the text a user
        typed ("4", " 04", "+4", "Tool"); else a UserError listing the frames as printed."""
        if isinstance(frame, bool) or not isinstance(frame, (int, str)):
            raise UserError(f"a frame is a number or base/tool, not {frame!r}")
        return frame_named(frame, plain(chain).frames, self.frame)

    def chain_frames(self, chain: Chain, start: Frame | None, end: Frame | None) -> tuple[Frame, Frame]:
        """The chain's frames for two printed ones; None is the first frame and the last."""
        frames = plain(chain).frames
        return (frames[0] if start is None else self.chain_frame(start, chain),
                frames[-1] if end is None else self.chain_frame(end, chain))

    def joint_index(self, joint: int, chain: Chain) -> int:
        """The chain's joint (1..n) for a printed joint number (a wrist's joints 4..6 are 1..3)."""
        listed = self.joints(chain)
        if isinstance(joint, bool) or not (isinstance(joint, int) and joint in listed):
            raise UserError(f"no joint {joint!r} in this robot; joints are {listed[0]}..{listed[-1]}")
        return joint - self.offset

    # ------------------------------------------------------------ errors the chain raises

    @contextmanager
    def printed(self):
        """Inside it, a transform the chain refuses as too large is named by its printed frames.

        >>> from dhsym.core.chain import TransformTooLarge
        >>> with Numbering(3).printed():
        ...     raise TransformTooLarge(0, 2, 5_000_000, "0T2 is too large")
        Traceback (most recent call last):
        dhsym.core.chain.TransformTooLarge: 3T5 would have about 5,000,000 expression nodes, ...
        """
        try:
            yield
        except TransformTooLarge as error:
            shown = [self.frame(f) for f in (error.start, error.end)]
            raise TransformTooLarge(error.start, error.end, error.size, too_large_message(*shown, error.size)) \
                from None


PLAIN = Numbering()  # frames 0..n as the chain counts them
