"""`dhsym dynamics`: the equations of motion τ = M(q) q̈ + C(q, q̇) q̇ + g(q) as a textbook prints
them (Spong's d_ij, c_ijk and φ_k), their derivation (`--steps`), the regressor (`--regressor`),
JSON for programs, LaTeX, or a numpy module.

    dhsym dynamics spong_elbow
    dhsym dynamics spong_elbow --steps --method newton-euler
    dhsym dynamics puma560_akb --format json
    dhsym dynamics puma560 --format python > puma_dynamics.py
    dhsym dynamics puma560 --to 3

Whether the results are written out is decided from their size, counted before any of them is
(dhsym.dynamics.derive): a chain too large to print is refused at once, with what does fit.
"""
from __future__ import annotations

import json

from ..dynamics.derive import MAX_TERMS, TooLargeToPrint, derive, printed_terms
from ..dynamics.equations import links_to_frame
from ..errors import UserError
from .options import format_options, robot_options

FORMATS = ("text", "latex", "json", "python")
METHODS = ("lagrange", "newton-euler")


def add_parsers(commands) -> None:
    sub = commands.add_parser("dynamics", parents=[robot_options(), format_options()], conflict_handler="resolve",
                              help="print the equations of motion: M(q), the Christoffel symbols, C and g(q)",
                              description="Print the dynamics τ = M(q) q̈ + C(q, q̇) q̇ + g(q) from the DH table and "
                              "the links' masses, centres of mass and inertias (symbols where the robot file gives "
                              "none): M element by element, the Christoffel symbols that are not zero, C, the "
                              "gravity torques and one equation per joint, in c/s notation; as text, LaTeX, JSON, "
                              "or a standalone Python module (numpy only) with M, C, g, tau and qdd.")
    sub.add_argument("--format", choices=FORMATS, default="text",
                     help="output format (default text); python writes a module defining M, C, g, tau and qdd")
    sub.add_argument("--method", choices=METHODS, default="lagrange",
                     help="the derivation --steps shows: Lagrange's equations from the energies (Spong), or the "
                          "Newton-Euler recursion (Craig); both give the same equations")
    sub.add_argument("--steps", action="store_true", help="show the derivation link by link")
    sub.add_argument("--regressor", action="store_true",
                     help="also the regressor: tau = Y(q, qd, qdd) pi, and the base parameters")
    sub.add_argument("--to", dest="end", metavar="F",
                     help="only the links up to frame F, numbered as fk numbers it (the arm without its wrist: "
                          "--to 3)")
    sub.set_defaults(run=run)


def run(robot, args) -> str:
    robot = first_links(robot, args.end)
    if args.format == "python":
        from ..dynamics import dynamics_program, module_text

        program = dynamics_program(robot.chain, robot.filled_masses())
        return module_text(program, robot.name, robot.sample, command=_command(args))
    result = derived(robot, args)
    if args.format == "json":
        from ..printing.dynamics import json_dynamics

        return json.dumps(json_dynamics(robot, result), indent=2, ensure_ascii=False)
    if args.format == "latex":
        from ..latex.dynamics import snippet  # the LaTeX layout lives with the documents

        return snippet(robot, result, method=args.method, steps=args.steps, regressor=args.regressor)
    from ..dynamics.equations import textbook_layout
    from ..printing.dynamics import MotionTextPrinter, text_dynamics

    printer = MotionTextPrinter(robot, result, ascii=args.ascii)
    steps = derivation(robot, result, args.method) if args.steps else None
    regressor = identified(robot) if args.regressor else None
    return text_dynamics(robot, textbook_layout(result), printer, args.width, args.method, steps, regressor)


def identified(robot):
    """The base parameters and the base regressor, numbered as the robot prints its joints."""
    from ..dynamics.identification import identification

    return identification(robot.chain, robot.filled_masses(), robot.numbering.first_joint)


def derivation(robot, result, method: str):
    """The records of the derivation by `method` (each refuses a chain too large to show)."""
    if method == "lagrange":
        from ..dynamics.lagrange_steps import lagrange_steps

        return lagrange_steps(robot.chain, robot.filled_masses(), result)
    from ..dynamics.craig_steps import newton_euler_steps

    return newton_euler_steps(robot.chain, robot.filled_masses())


def first_links(robot, end):
    """The robot with the links up to its frame `end` (as printed: the robot's first_frame is the
    number of the chain's frame 0) only; all of it when None."""
    if end is None:
        return robot
    return links_to_frame(robot, _whole_number(end), lambda first, last: "--to names the last frame whose link "
                          f"moves, one of {first}..{last}; not {end}")


def _whole_number(text: str) -> int:
    try:
        return int(text.strip())
    except ValueError:
        raise UserError(f"--to names a frame by its number, not {text!r}") from None


def derived(robot, args):
    """derive, or a refusal that says what fits instead."""
    try:
        return derive(robot.chain, robot.filled_masses())
    except TooLargeToPrint as error:
        raise refusal(robot, error) from None


def refusal(robot, error: TooLargeToPrint, command: str = "") -> UserError:
    """What to ask for instead of dynamics too large to print: the links up to the last frame that
    fits (the first links' sizes are counted, from the base out), numbers, or code. `command`: the
    `dhsym dynamics` command line that takes those options, when it is not the command at hand."""
    fits = None
    for k in range(1, robot.chain.n):
        part = first_links(robot, str(robot.numbering.frame(k)))
        if printed_terms(part.chain, part.filled_masses())[2] > MAX_TERMS:
            break
        fits = robot.numbering.frame(k)
    prefix = f"{command} " if command else ""
    advice = [f"{prefix}--to {fits} (the links up to frame {fits})"] if fits is not None else []
    advice += ["numbers for the links' masses, centres of mass and inertias in the robot file (mass:, com:, "
               "inertia:)", f"{prefix}--format python, which needs no printing"]
    return UserError(f"{robot.path}: M, C and g would have about {error.terms:,} terms multiplied out, more than "
                     f"the {MAX_TERMS:,} dhsym writes out; ask for " + ", or ".join(advice))


def _command(args) -> str:
    """The command that made a module, for its docstring."""
    return f"dhsym dynamics {args.robot}{f' --to {args.end}' if args.end else ''} --format python"
