"""`dhsym convert`: the same robot in the other DH convention, as a robot file.

    dhsym convert puma560 --to standard -o puma560_standard.yaml

Same joint variables, same base → tool for every joint value; symbols stay symbols.
"""
from __future__ import annotations

from ..core.robot import Robot
from ..geometry.convert import convert_robot
from ..io.output import write_atomic
from ..io.robotwriter import robot_yaml
from .options import robot_options


def add_parsers(commands) -> None:
    sub = commands.add_parser("convert", parents=[robot_options()], help="rewrite a robot in the other DH convention",
                              description="Write the robot file of the same robot in the standard or the modified "
                              "convention: the same joint variables and the same base → tool transform for every "
                              "joint value (base or tool steps are added where needed).")
    sub.add_argument("--to", required=True, choices=("standard", "modified"), help="the convention wanted")
    sub.add_argument("-o", "--output", metavar="OUT.yaml", help="write to OUT.yaml (atomically) instead of "
                     "standard output")
    sub.set_defaults(run=run)


def run(robot: Robot, args) -> str | None:
    text = robot_yaml(convert_robot(robot, args.to))  # keeps name, sample, first_frame...
    if args.output is None:
        return text
    write_atomic(args.output, text, inputs=[robot.path])
    return None
