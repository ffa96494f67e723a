"""`dhsym check`: do two robot files describe the same kinematics, base to tool, for every
joint value? Exit status 0 when they do, 1 when they do not (with what to fix), 2 when a file
cannot be read.

    dhsym check homework.yaml --against inline6
"""
from __future__ import annotations

from ..core.robot import Robot
from ..geometry.compare import compare
from ..io import library
from .limits import refuse_long_entries
from .messages import warn
from .options import robot_options

EXIT_DIFFERENT = 1


class Outcome(str):
    """The printed verdict, carrying the exit status for the dispatcher."""

    exit_status = 0


class Different(Outcome):
    exit_status = EXIT_DIFFERENT


def add_parsers(commands) -> None:
    sub = commands.add_parser("check", parents=[robot_options()], help="check a DH table against a reference",
                              description="Check that CANDIDATE (ROBOT) describes the same kinematics as REFERENCE "
                              "from base to tool, for every joint value, whatever the convention or frame choice. "
                              "Exit status 0: same; 1: different, with the first joint axis that differs, a joint "
                              "zero (offset) that differs, or a base/tool frame that differs; 2: unreadable input.")
    sub.add_argument("--against", required=True, metavar="REFERENCE", help="built-in robot name or robot file")
    sub.set_defaults(run=run)


def run(robot: Robot, args) -> str:
    reference = library.read(args.against)
    warn(reference.warnings)
    refuse_long_entries(robot)
    refuse_long_entries(reference)
    verdict = compare(robot, reference)
    return (Outcome if verdict.same else Different)(f"{args.robot}: {verdict.message}")
