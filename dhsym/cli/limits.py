"""Refusing, within a second, a result too large to work out or print, with advice that the
command at hand accepts.

Every estimate (dhsym.core.estimate, dhsym.core.size) is made before any simplification or
printing, so whether a command works depends on the problem alone: a general 24-link chain is
refused at once, on any machine, instead of running for minutes. A Jacobian is about as large
as the transform from its frame to its point plus those to each joint axis (a general 8-link
chain: 203,000 nodes estimated, 200,000 built).
"""
from __future__ import annotations

from ..core.chain import Chain, Frame
from ..core.estimate import contracted_size, estimated_size
from ..core.robot import Robot
from ..core.size import expanded_terms, rough_count
from ..errors import UserError
from ..printing.render import transform_title

MAX_NODES = 200_000  # about 400,000 printed characters, a few seconds of printing
CHARACTERS_PER_NODE = 2  # measured: 1 (textbook robots) to 1.9 (general chains)
# LaTeX breaks a long element line by line, in time that grows with the square of its length:
# 0T5 of a general chain (6,900 nodes) takes seconds, 0T6 (18,000) a minute. The largest
# built-in result is the iiwa7's 0T7, 1,600 nodes; its Jacobian 3,300.
LATEX_MAX_NODES = 8_000
# Velocity propagation applies the sum formulas at every step: its size is the sum of the sizes of
# each frame's transforms to the axes before it. The iiwa7 has 6,700 (1.4 s), a planar 12R arm 7,900
# (4 s), a general 4-link chain 5,300 (8 s), a general 5-link chain 16,000 (minutes).
STEPS_MAX_NODES = 10_000
# A table entry that expands into many terms ((a + b)^16 nested: 17 terms and more per level) makes
# every determinant, screw axis and comparison expand it; textbook entries have one to three.
ENTRY_MAX_TERMS = 1_000


def refuse_if_too_large(robot: Robot, start: Frame, end: Frame, raw: bool = False, limit: int = MAX_NODES,
                        others: bool = True) -> None:
    """A UserError saying what to do instead when {start}T{end} (the chain's frames) would be
    larger than `limit` nodes, naming frames with the robot's numbers. `others`: also advise
    `dhsym links` and --raw (commands that print matrices)."""
    chain = robot.chain
    size = estimated_size(chain, start, end, raw)
    if size <= limit:
        return
    frames = chain.frames
    first, last = sorted((frames.index(start), frames.index(end)))
    reach = first + 1
    while reach + 1 <= last and estimated_size(chain, frames[first], frames[reach + 1]) <= limit:
        reach += 1
    shown = [robot.numbering.frame(frames[k]) for k in (first, reach)]
    advice = f"ask for part of the chain with --from/--to (--from {shown[0]} --to {shown[1]} fits)"
    if others:
        advice += ", or print the link matrices with 'dhsym links'"
        if not raw and estimated_size(chain, start, end, raw=True) <= limit:
            advice += ", or the unsimplified product with --raw"
    title = transform_title(robot.numbering.frame(start), robot.numbering.frame(end), "ascii")
    what = "too large to print or read" if limit == MAX_NODES else "too large to lay out as LaTeX"
    raise UserError(f"{robot.path}: {title} would take {rough_count(size * CHARACTERS_PER_NODE)} "
                    f"characters, {what}; {advice}")


def refuse_jacobian_if_too_large(robot: Robot, frame: Frame, point: Frame, limit: int = MAX_NODES,
                                 option: str = "--frame") -> None:
    """A UserError when ᵏJ of `point` would be larger than `limit` nodes, naming a frame where it
    fits (`option` is how the command names that frame), else advising another point."""
    from ..velocity.jacobian import jacobian_size  # the velocity layer only for the commands that use it

    chain = robot.chain
    size = jacobian_size(chain, frame, point)
    if size <= limit:
        return
    fitting = [f for f in chain.frames if jacobian_size(chain, f, point) <= limit]
    if fitting and option:
        nearest = min(fitting, key=lambda f: abs(chain.frames.index(f) - chain.frames.index(frame)))
        fits = robot.numbering.frame(nearest)
        advice = f"express it in a frame nearer the point with {option} ({option} {fits} fits)"
    elif option:
        advice = "ask for the velocity of a frame nearer the base with --point"
    else:
        advice = "leave out --jacobian, or print it with 'dhsym jacobian', which takes --frame and --point"
    what = "too large to print or read" if limit == MAX_NODES else "too large to lay out as LaTeX"
    raise UserError(f"{robot.path}: the Jacobian of frame {robot.numbering.frame(point)} in frame "
                    f"{robot.numbering.frame(frame)} would take {rough_count(size * CHARACTERS_PER_NODE)} "
                    f"characters, {what}; {advice}")


def refuse_steps_if_too_large(robot: Robot, option: str = "--steps") -> None:
    """A UserError when Craig's velocity propagation would be too large to work out."""
    size = propagation_size(robot.chain)
    if size > STEPS_MAX_NODES:
        raise UserError(f"{robot.path}: the velocity propagation (--steps) would take "
                        f"{rough_count(size * CHARACTERS_PER_NODE)} characters, too large to derive step by step; "
                        f"leave out {option} to get the Jacobian alone")


def propagation_size(chain: Chain) -> int:
    """Estimated nodes of every step of the propagation: frame k's ω and v depend on the axes before it."""
    from ..velocity.jacobian import axis_frame

    frames = chain.frames
    axes = [frames.index(axis_frame(chain, joint)) for joint in range(1, chain.n + 1)]
    return sum(estimated_size(chain, frames[k], frames[a]) for k in range(1, len(frames)) for a in axes if a < k)


def refuse_screws_if_too_large(robot: Robot, limit: int = MAX_NODES) -> None:
    """A UserError when the zero pose, contracted as `fk` contracts, is past what dhsym prints: the
    screw axes are its joint frames' z axes and origins (a cross product of two of its columns)."""
    from ..geometry.screws import zero_steps  # the geometry layer only for the command that uses it

    size = contracted_size(zero_steps(robot.chain))
    if size > limit:
        raise UserError(f"{robot.path}: the zero pose of this chain has {rough_count(size)} expression nodes, "
                        f"more than the {limit:,} that dhsym prints; print the link matrices with 'dhsym links' "
                        f"and set the joint variables to zero by hand")


def refuse_long_entries(robot: Robot) -> None:
    """A UserError when a table entry would expand to too many terms for the commands that expand."""
    chain = robot.chain
    fields = [(f"joint row {k} {key}", getattr(row, key)) for k, row in enumerate(chain.rows, 1)  # rows of the file
              for key in ("theta", "d", "a", "alpha")]
    fields += [(f"{side} step {k}", step.value) for side, steps in (("base", chain.base), ("tool", chain.tool))
               for k, step in enumerate(steps, 1)]
    for name, value in fields:
        terms = expanded_terms(value)
        if terms > ENTRY_MAX_TERMS:
            raise UserError(f"{robot.path}: {name} would expand to {rough_count(terms)} terms, more than the "
                            f"{ENTRY_MAX_TERMS:,} that dhsym expands; name it as a constant (a symbol such as l_1) "
                            "and give its value in the robot file's sample")
