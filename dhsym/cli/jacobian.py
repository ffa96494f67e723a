"""`dhsym jacobian`: the geometric Jacobian in any frame, its factored determinant and the
singular configurations, and (`--steps`) Craig's velocity propagation link by link.

    dhsym jacobian puma560 --frame 3
    dhsym jacobian planar3r --steps
    dhsym jacobian stanford --format json
"""
from __future__ import annotations

import json

from ..core.robot import Robot
from ..printing import jacobian as show
from ..printing.printers import chain_settings
from ..printing.render import convention_note, text_legend
from ..velocity import propagate, rate_symbols
from .limits import (
    LATEX_MAX_NODES,
    MAX_NODES,
    refuse_jacobian_if_too_large,
    refuse_long_entries,
    refuse_steps_if_too_large,
)
from .options import chosen_frame, format_options, robot_options


def add_parsers(commands) -> None:
    sub = commands.add_parser("jacobian", parents=[robot_options(), format_options()],
                              help="print the Jacobian, its determinant and the singular configurations",
                              description="Print the geometric Jacobian (rows vx vy vz ωx ωy ωz) of the origin of "
                              "the last frame, expressed in frame F, its factored determinant and the factors whose "
                              "vanishing makes it singular, each with its meaning.")
    sub.add_argument("--frame", metavar="F", help="the frame J is expressed in, numbered as fk numbers it "
                     "(default: base, else the first)")
    sub.add_argument("--point", metavar="P", help="the frame whose origin moves (default: tool, else the last)")
    sub.add_argument("--steps", action="store_true",
                     help="derive it by Craig's outward velocity propagation, link by link")
    sub.set_defaults(run=run)


def run(robot: Robot, args) -> str:
    chain = robot.chain
    frame = chosen_frame(robot, args.frame, "--frame", chain.frames[0])  # the chain's frames 0..n from here on
    point = chosen_frame(robot, args.point, "--point", chain.frames[-1])
    refuse_long_entries(robot)
    refuse_jacobian_if_too_large(robot, frame, point, LATEX_MAX_NODES if args.format == "latex" else MAX_NODES)
    if args.steps:
        refuse_steps_if_too_large(robot)
    if args.format == "latex":
        from ..latex.velocity import snippet  # the LaTeX layout lives with the documents

        return snippet(robot, frame, point, args.steps)
    velocity = show.velocity_of(robot, frame, point)
    if args.format == "json":
        return json.dumps(show.json_jacobian(robot, velocity), indent=2, ensure_ascii=False)
    steps = propagate(chain) if args.steps else None
    return _text(robot, velocity, steps, args)


def _text(robot: Robot, velocity: show.Velocity, steps, args) -> str:
    """The Jacobian, the propagation `steps` (or None), the determinant and the singularities, as text."""
    chain, numbering = robot.chain, robot.numbering
    frame, point = numbering.frame(velocity.frame), numbering.frame(velocity.point)  # as printed
    style = "ascii" if args.ascii else "unicode"
    printer = show.RateTextPrinter(chain.joint_variables, rate_symbols(chain), ascii=args.ascii,
                                   settings=chain_settings(robot))
    title = (f"{robot.name}: Jacobian {show.jacobian_title(frame, point, style)} of the {show.point_words(point)}, "
             f"in frame {frame}  ({chain.convention} DH)")
    blocks = [title, "rows vx vy vz ωx ωy ωz; " + convention_note(chain.convention, args.ascii)]
    if steps:
        blocks.append("Velocity propagation (Craig): ω and v of each frame in that frame, from the rates "
                      + ", ".join(printer.doprint(r) for r in rate_symbols(chain)) + "\n"
                      + show.text_steps(steps, printer, args.width, numbering))
        blocks.append("The rates' coefficients in the last step are the columns of J in frame "
                      f"{numbering.frame(steps[-1].frame)}.")
    blocks.append(show.text_grid(velocity.matrix, printer, args.width))
    blocks.append(show.text_determinant(velocity.determinant, velocity.singularities, printer, args.width))
    legend = text_legend(printer, args.width)
    text = "\n\n".join(blocks) + ("\n\n" + legend if legend else "")
    if args.ascii:
        text = text.replace("ω", "w").replace("−", "-").replace("×", "x").replace("–", "-").replace("·", "*")
    return text
