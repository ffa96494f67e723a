"""`dhsym latex`: beamer slides, an article or a snippet of math, written atomically.

    dhsym latex puma560 --document article --steps -o puma.tex
"""
from __future__ import annotations

from ..errors import UserError
from ..io.output import write_atomic
from ..latex.document import DOCUMENTS, document
from .limits import (
    LATEX_MAX_NODES,
    refuse_if_too_large,
    refuse_jacobian_if_too_large,
    refuse_long_entries,
    refuse_steps_if_too_large,
)
from .options import frame_options, robot_options


def add_parsers(commands) -> None:
    sub = commands.add_parser("latex", parents=[robot_options()],
                              help="write LaTeX: beamer slides, an article or a snippet",
                              description="Write the DH table, every link matrix and the result as LaTeX that "
                              "compiles with pdflatex: beamer slides (16:9), an article, or a snippet of math "
                              "for a document with amsmath. Matrices too wide for the page are written "
                              "element by element (r_11 ... p_z), never shrunk.")
    sub.add_argument("--document", choices=DOCUMENTS, default="slides", help="what to write (default slides)")
    sub.add_argument("--steps", action="store_true",
                     help="derive the result step by step: 0T2 = 0T1 1T2, then 0T3 = 0T2 2T3, ...")
    sub.add_argument("--jacobian", action="store_true", help="add the Jacobian, its determinant and singularities")
    sub.add_argument("--ik", action="store_true",
                     help="add the closed-form inverse kinematics: the decoupling, each equation with its "
                          "sub-problem, every branch")
    sub.add_argument("--free", metavar="VAR", nargs="+", action="extend", default=[],
                     help="with --ik: joint variables kept as parameters (a redundant arm needs them)")
    sub.add_argument("--dynamics", action="store_true",
                     help="add the equations of motion: M(q), the Christoffel symbols, C, g(q) and one equation per "
                          "joint (with --steps, their derivation by Lagrange's equations)")
    frame_options(sub)
    sub.add_argument("-o", "--output", metavar="FILE", help="write to FILE (atomically) instead of standard output")
    sub.set_defaults(run=run)


def _document(robot, args) -> str:
    from ..dynamics.derive import TooLargeToPrint

    try:
        return document(robot, args.document, steps=args.steps, start=args.start, end=args.end,
                        jacobian=args.jacobian, ik=args.ik, free=args.free, dynamics=args.dynamics)
    except TooLargeToPrint as error:
        from .dynamics import refusal  # says which --to of `dhsym dynamics` fits

        raise refusal(robot, error, f"dhsym dynamics {args.robot}") from None


def run(robot, args) -> str | None:
    chain = robot.chain
    try:
        start = chain.first_frame if args.start is None else robot.chain_frame(args.start)
        end = chain.last_frame if args.end is None else robot.chain_frame(args.end)
    except UserError:
        pass  # document() names the frame that is wrong, and the option
    else:
        refuse_if_too_large(robot, start, end, limit=LATEX_MAX_NODES, others=False)
    if args.free and not args.ik:
        raise UserError("--free names the parameters of the inverse kinematics; add --ik")
    if args.jacobian:
        refuse_long_entries(robot)
        refuse_jacobian_if_too_large(robot, chain.first_frame, chain.last_frame, LATEX_MAX_NODES, option="")
        if args.steps:
            refuse_steps_if_too_large(robot)
    text = _document(robot, args)
    if args.output is None:
        return text
    write_atomic(args.output, text, inputs=[robot.path])
    return None
