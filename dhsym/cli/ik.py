"""`dhsym ik`: the closed-form inverse kinematics of a robot, every branch, as textbook text,
LaTeX, JSON or a standalone numpy module.

    dhsym ik planar2r
    dhsym ik puma560 --format json
    dhsym ik puma560 --format python > puma_ik.py
    dhsym ik iiwa7 --free theta_3
    dhsym ik hc10.yaml --numeric      # an arm with no closed form: every solution in numbers

The target is the transform `dhsym fk ROBOT` prints by default (base, else 0, to tool, else n),
written with the names of its elements r11 … r33, px, py, pz.
"""
from __future__ import annotations

import json

from . import ik_numeric
from .options import format_options, robot_options

FORMATS = ("text", "latex", "json", "python")


def add_parsers(commands) -> None:
    sub = commands.add_parser("ik", parents=[robot_options(), format_options()], conflict_handler="resolve",
                              help="print the closed-form inverse kinematics, every branch",
                              description="Solve the pose that `dhsym fk ROBOT` prints (its elements named r11 … "
                              "r33, px, py, pz) for the joint variables in closed form: the intermediate quantities "
                              "(wrist centre, D, ...) and every branch by name, as text, LaTeX, JSON, or a "
                              "standalone Python module (numpy only) defining ik(T, **constants).")
    sub.add_argument("--format", choices=FORMATS, default="text",
                     help="output format (default text); python writes a module defining ik(T, **constants)")
    sub.add_argument("--free", metavar="VAR", nargs="+", action="extend", default=[],
                     help="joint variables kept as parameters, e.g. --free theta_3 for a 7-joint arm")
    ik_numeric.add_arguments(sub)  # --numeric, --q, --pose, --set (dhsym.cli.ik_numeric)
    sub.set_defaults(run=run)


def run(robot, args) -> str:
    from ..api.ik import inverse_kinematics  # here: the other commands need no solver
    from ..errors import NoClosedForm

    if ik_numeric.wanted(args):
        return ik_numeric.run(robot, args)
    try:
        result = inverse_kinematics(robot, args.free)
    except NoClosedForm as refusal:  # the numeric module, or the command that answers numerically
        return ik_numeric.refused(robot, args, refusal)
    if args.format == "json":
        return json.dumps(result.json(), indent=2, ensure_ascii=False)
    if args.format == "python":
        return result.code(command=_command(args))
    if args.format == "latex":
        from ..latex.ik import snippet  # the LaTeX layout lives with the documents

        return snippet(result.solution, result.robot)
    return result.text(args.width, args.ascii)


def _command(args) -> str:
    """The command that made a module, for its docstring."""
    free = f" --free {' '.join(args.free)}" if args.free else ""
    return f"dhsym ik {args.robot}{free} --format python"
