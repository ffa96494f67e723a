"""Refusing, within a second, a result too large to print, with advice on what to ask for instead.

The estimate (dhsym.core.estimate) is made before any simplification or printing, so a general
24-link chain is refused at once instead of running for minutes. A Jacobian is about as large as
the transform from its frame to its point plus those to each joint axis (a general 8-link
chain: 203,000 nodes estimated, 200,000 built).
"""
from __future__ import annotations

from ..core.estimate import estimated_size
from ..errors import UserError
from ..printing.render import transform_title
from ..velocity.jacobian import axis_frame

MAX_NODES = 200_000  # about 400,000 printed characters, a few seconds of printing
CHARACTERS_PER_NODE = 2  # measured: 1 (textbook robots) to 1.9 (general chains)


def refuse_if_too_large(robot, start, end, raw: bool = False) -> None:
    """A UserError saying what to do instead when {start}T{end} would be too large to print."""
    chain = robot.chain
    size = estimated_size(chain, start, end, raw)
    if size <= MAX_NODES:
        return
    frames = chain.frames
    first, last = sorted((frames.index(start), frames.index(end)))
    reach = first + 1
    while reach + 1 <= last and estimated_size(chain, frames[first], frames[reach + 1]) <= MAX_NODES:
        reach += 1
    advice = (f"ask for part of the chain with --from/--to (--from {frames[first]} --to {frames[reach]} fits), "
              f"or print the link matrices with 'dhsym links'")
    if not raw and estimated_size(chain, start, end, raw=True) <= MAX_NODES:
        advice += ", or the unsimplified product with --raw"
    characters = _round(size * CHARACTERS_PER_NODE)
    raise UserError(f"{robot.path}: {transform_title(start, end, 'ascii')} would take about {characters} "
                    f"characters, too large to print or read; {advice}")


def _round(number: int) -> str:
    """A rough count in words people read at a glance: 600,000 or 2.4 billion."""
    for size, word in ((10**12, "trillion"), (10**9, "billion"), (10**6, "million")):
        if number >= size:
            return f"{number / size:.1f} {word}"
    return f"{round(number, -4):,}"


def refuse_jacobian_if_too_large(robot, frame, point) -> None:
    """A UserError when ᵏJ of `point` would be too large to print, naming a frame where it fits."""
    chain = robot.chain
    size = jacobian_size(chain, frame, point)
    if size <= MAX_NODES:
        return
    fitting = [f for f in chain.frames if jacobian_size(chain, f, point) <= MAX_NODES]
    if fitting:
        nearest = min(fitting, key=lambda f: abs(chain.frames.index(f) - chain.frames.index(frame)))
        advice = f"express it in a frame nearer the point with --frame (--frame {nearest} fits)"
    else:
        advice = "ask for the velocity of a frame nearer the base with --point"
    raise UserError(f"{robot.path}: the Jacobian of frame {point} in frame {frame} would take about "
                    f"{_round(size * CHARACTERS_PER_NODE)} characters, too large to print or read; {advice}")


def jacobian_size(chain, frame, point) -> int:
    """Estimated nodes of ᵏJ: the transform to the point, plus one to each joint's axis."""
    axes = (axis_frame(chain, joint) for joint in range(1, chain.n + 1))
    return estimated_size(chain, frame, point) + sum(estimated_size(chain, frame, axis) for axis in axes)
