"""DH rows and chains: link matrices, products between any two frames, and their inverses.

>>> import sympy
>>> t1, t2, l1, l2 = sympy.symbols("theta_1 theta_2 l_1 l_2", real=True)
>>> arm = Chain([DHRow.revolute(t1, a=l1), DHRow.revolute(t2, a=l2)], "standard")
>>> arm.fk()[0, 3]
l_1*cos(theta_1) + l_2*cos(theta_1 + theta_2)
>>> arm.transform(2, 0)[0, 3]
-l_1*cos(theta_2) - l_2
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import sympy

from ..errors import UserError
from .estimate import contracted_size, span_size
from .simplify import contract
from .transforms import CONVENTIONS, Step, as_expr, inverse_transform, link_steps, product

Frame = int | str  # 0..n, or "base" / "tool"
Simplifier = Callable[[Sequence[Step], frozenset], sympy.Matrix]
MAX_WORK_NODES = 2_000_000  # estimated expression nodes: past this a transform is not built (a general 11-link chain)


@dataclass(frozen=True)
class DHRow:
    """One joint's row. In the `modified` convention `a` and `alpha` are a_{i-1}, α_{i-1}.

    >>> import dhsym
    >>> theta_1, l_1 = dhsym.real_symbol("theta_1"), dhsym.real_symbol("l_1")
    >>> dhsym.DHRow.revolute(theta_1, a=l_1).variable
    theta_1
    """

    joint: str  # "R" revolute or "P" prismatic
    theta: sympy.Expr
    d: sympy.Expr
    a: sympy.Expr
    alpha: sympy.Expr
    variable: sympy.Symbol

    @classmethod
    def revolute(cls, theta, d=0, a=0, alpha=0, variable=None) -> "DHRow":
        """A revolute row; the variable defaults to the one symbol in `theta`."""
        return cls._make("R", theta, d, a, alpha, variable, theta)

    @classmethod
    def prismatic(cls, d, theta=0, a=0, alpha=0, variable=None) -> "DHRow":
        """A prismatic row; the variable defaults to the one symbol in `d`."""
        return cls._make("P", theta, d, a, alpha, variable, d)

    @classmethod
    def _make(cls, joint, theta, d, a, alpha, variable, moving) -> "DHRow":
        theta, d, a, alpha, moving = (as_expr(x) for x in (theta, d, a, alpha, moving))
        if variable is None:
            free = sorted(moving.free_symbols, key=str)
            field_name = "theta" if joint == "R" else "d"
            if len(free) != 1:
                raise UserError(f"{field_name} {moving} must hold exactly one joint variable, "
                                f"found {len(free)}; name it with var")
            variable = free[0]
        return cls(joint, theta, d, a, alpha, variable)

    def steps(self, convention: str) -> list[Step]:
        return link_steps(convention, self.theta, self.d, self.a, self.alpha)


class TransformTooLarge(UserError):
    """A transform refused before it is built; `start`, `end` are the chain's frames (a robot's
    numbering renames them with the printed numbers: `Numbering.printed`)."""

    def __init__(self, start: Frame, end: Frame, size: int, message: str):
        super().__init__(message)
        self.start, self.end, self.size = start, end, size


def too_large_message(start: Frame, end: Frame, size: int) -> str:
    """What a too-large transform is told, with the frames as the user numbers them."""
    return (f"{start}T{end} would have about {size:,} expression nodes, more than the {MAX_WORK_NODES:,} that "
            "dhsym works out; ask for a shorter part of the chain")


def frame_named(text, frames: list, number=lambda frame: frame) -> Frame:
    """The frame of `frames` whose printed `number` is `text` ("3", " 03", "+3", "Tool"), else a
    UserError listing the frames by their printed numbers.

    >>> frame_named(" 04", [0, 1, 2], lambda f: f + 3), frame_named("Tool", ["base", 0, 1, "tool"])
    (1, 'tool')
    """
    wanted = str(text).strip().lower()
    if wanted.isascii() and wanted.lstrip("+").isdigit() and len(wanted) < 6:
        wanted = str(int(wanted))
    for frame in frames:
        if wanted == str(number(frame)):
            return frame
    shown = str(text) if len(str(text)) <= 20 else str(text)[:20] + "..."
    shown = shown if shown.lstrip("-").isascii() and shown.lstrip("-").isdigit() else repr(shown)
    listed = [number(f) for f in frames]
    listed = listed[:2] + ["..."] + listed[-2:] if len(listed) > 8 else listed
    raise UserError(f"no frame {shown} in this robot; frames are {', '.join(map(str, listed))}")


def plain(chain: "Chain") -> "Chain":
    """`chain` itself, when it is a plain Chain (frames 0..n); anything else, a Robot above all,
    is a TypeError at once: code inside dhsym never renumbers frames silently.

    >>> plain(object())
    Traceback (most recent call last):
    TypeError: a plain Chain (frames 0..n) is needed here, not object
    """
    if not isinstance(chain, Chain):
        hint = "; a robot's is robot.chain, its printed numbers robot.numbering" if hasattr(chain, "chain") else ""
        raise TypeError(f"a plain Chain (frames 0..n) is needed here, not {type(chain).__name__}{hint}")
    return chain


class Chain:
    """A serial chain: DH rows in one convention, with optional fixed base and tool steps. Plain
    math: what a robot file says about it (name, sample values, its frame numbering...) is kept
    by the `dhsym.core.robot.Robot` that holds it.

    Frames are numbered 0..n; "base" (before the base steps) and "tool" (after the tool
    steps) exist when the chain has such steps.

    >>> import sympy
    >>> Chain([DHRow.revolute(sympy.Symbol("theta_1", real=True), a=1)], "standard")
    Chain(standard DH, 1 joint: R)
    """

    def __init__(self, rows: Sequence[DHRow], convention: str, base: Sequence[Step] = (),
                 tool: Sequence[Step] = (), simplifier: Simplifier = contract):
        if convention not in CONVENTIONS:
            raise UserError(f"unknown convention {convention!r}; use standard or modified")
        if not rows:
            raise UserError("a chain needs at least one joint")
        self.rows, self.convention = tuple(rows), convention
        self.base, self.tool = tuple(base), tuple(tool)
        self.simplifier = simplifier
        self._cache: dict = {}

    def __repr__(self) -> str:
        joints = "".join(row.joint for row in self.rows)
        return f"Chain({self.convention} DH, {self.n} joint{'s' if self.n > 1 else ''}: {joints})"

    def __getstate__(self) -> dict:
        """Pickled and deep-copied without what it worked out (transforms, a solution), which a copy
        works out again when asked."""
        return {**self.__dict__, "_cache": {}}

    @property
    def n(self) -> int:
        return len(self.rows)

    @property
    def joint_variables(self) -> list[sympy.Symbol]:
        return [row.variable for row in self.rows]

    @property
    def symbols(self) -> set[sympy.Symbol]:
        """Every symbol of the rows and of the fixed steps: joint variables and constants."""
        values = [x for row in self.rows for x in (row.theta, row.d, row.a, row.alpha)]
        values += [step.value for step in self.base + self.tool]
        return set().union(*(value.free_symbols for value in values)) | set(self.joint_variables)

    @property
    def frames(self) -> list[Frame]:
        return (["base"] if self.base else []) + list(range(self.n + 1)) + (["tool"] if self.tool else [])

    @property
    def first_frame(self) -> Frame:
        return self.frames[0]

    @property
    def last_frame(self) -> Frame:
        return self.frames[-1]

    def frame(self, text: str) -> Frame:
        """The frame a user names: "3", "03" and "+3" are frame 3; "base"/"tool" where present.
        (A robot numbered from 3 names its frames with `robot.numbering.chain_frame`.)

        >>> import sympy
        >>> Chain([DHRow.revolute(sympy.Symbol("q", real=True))], "standard").frame(" 01")
        1
        """
        return frame_named(text, self.frames)

    def link(self, i: int, raw: bool = False) -> sympy.Matrix:
        """The link matrix {i-1}T_i."""
        return self.transform(i - 1, i, raw=raw)

    def links(self, raw: bool = False) -> list[sympy.Matrix]:
        return [self.link(i, raw=raw) for i in range(1, self.n + 1)]

    def fk(self, raw: bool = False) -> sympy.Matrix:
        """The whole chain, from base (else 0) to tool (else n)."""
        return self.transform(self.first_frame, self.last_frame, raw=raw)

    def transform(self, i: Frame, j: Frame, raw: bool = False) -> sympy.Matrix:
        """{i}T_{j}; for i after j this is the inverse, built in closed form."""
        key = (self._position(i), self._position(j), raw)
        if key not in self._cache:
            self._cache[key] = self._compute(*key)
        return self._cache[key].copy()

    def steps(self, i: Frame, j: Frame) -> list[Step]:
        """The elementary steps from frame i to frame j (inverted and reversed for i after j)."""
        start, end = self._position(i), self._position(j)
        if start > end:
            return [step.inverse() for step in reversed(self._steps()[end:start])]
        return self._steps()[start:end]

    def _compute(self, start: int, end: int, raw: bool) -> sympy.Matrix:
        """The transform between two step positions. Its size is estimated first, so that a
        transform too large to work out is refused at once, whatever the machine."""
        if start > end:
            if raw:
                return inverse_transform(self._compute(end, start, raw=True))
            steps = [step.inverse() for step in reversed(self._steps()[end:start])]
        else:
            steps = self._steps()[start:end]
        size = span_size(self, start, end, raw=True) if raw else \
            contracted_size(steps, self._cache.setdefault("block sizes", {}))
        if size > MAX_WORK_NODES:
            frames = self.frames
            first, last = (frames[self._bounds().index(p)] for p in (start, end))
            raise TransformTooLarge(first, last, size, too_large_message(first, last, size))
        if raw:
            return self._raw_links(start, end)
        return self.simplifier(steps, frozenset(self.joint_variables))

    def _raw_links(self, start: int, end: int) -> sympy.Matrix:
        """The plain product of whole link matrices (and base/tool matrices)."""
        bounds = self._bounds()
        result = sympy.eye(4)
        for lo, hi in zip(bounds, bounds[1:]):
            if start <= lo and hi <= end and hi > lo:
                result = result * product(self._steps()[lo:hi])
        return result

    def _steps(self) -> list[Step]:
        if "steps" not in self._cache:
            link = [s for row in self.rows for s in row.steps(self.convention)]
            self._cache["steps"] = list(self.base) + link + list(self.tool)
        return self._cache["steps"]

    def _bounds(self) -> list[int]:
        """Step index of each frame, in the order of `frames`."""
        bounds = [0] if self.base else []
        position = len(self.base)
        bounds.append(position)
        for _ in self.rows:
            position += 4
            bounds.append(position)
        if self.tool:
            bounds.append(position + len(self.tool))
        return bounds

    def _position(self, frame: Frame) -> int:
        frames = self.frames
        if isinstance(frame, str) and frame.isdigit():
            frame = int(frame)
        if frame not in frames:
            names = ", ".join(str(f) for f in (frames[:2] + ["..."] + frames[-2:] if len(frames) > 6 else frames))
            raise UserError(f"no frame {frame!r} in this robot; frames are {names}")
        return self._bounds()[frames.index(frame)]
