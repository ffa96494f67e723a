"""`dhsym import`: a URDF, a .xacro file or an `axes:` robot file in, a DH robot file out.

    dhsym import ur5.urdf --tip tool0 --convention modified -o ur5.yaml
    dhsym import ur_description/urdf/ur.urdf.xacro --xacro-arg ur_type:=ur5e --xacro-arg name:=ur

Joint i of the table is the i-th revolute, continuous or prismatic URDF joint from base to tip;
its variable q_i (or, with --variables urdf, the URDF joint's name made into a symbol) equals
the joint's value: θi = q_i + offset, or d_i = q_i + offset. The work is `io.urdfimport.import_urdf`.
"""
from __future__ import annotations

import re
from pathlib import Path

from ..errors import UserError
from ..geometry.convert import convert_robot
from ..io.output import write_atomic
from ..io.robotfile import load_robot_file
from ..io.robotwriter import robot_yaml
from ..io.urdfimport import import_urdf
from .messages import warn

MAX_ARGUMENT_TEXT = 1_000
_ARGUMENT = re.compile(r"([^\s:=]+):=(.*)", re.DOTALL)


def add_parsers(commands) -> None:
    sub = commands.add_parser("import", help="derive a DH robot file from a URDF or .xacro file (or an axes: "
                              "robot file)",
                              description="Read the serial chain from --base to --tip of a URDF file (a .xacro "
                              "file is expanded first), assign DH frames and write the robot file. Joint i is the "
                              "i-th movable joint from base to tip; its variable equals the joint value. Fixed joints "
                              "fold into the constants; meshes are not read. A robot file with axes: is converted to "
                              "joints: instead.")
    sub.add_argument("file", metavar="FILE", help="a .urdf or .xacro file, or a robot .yaml file written with axes:")
    sub.add_argument("--base", metavar="LINK", help="the base link (default: the URDF's root link)")
    sub.add_argument("--tip", metavar="LINK", help="the tip link (default: the only leaf below the base)")
    sub.add_argument("--convention", choices=("standard", "modified"),
                     help="the DH convention of the table (default: standard for a URDF, the file's own for axes:)")
    sub.add_argument("--variables", choices=("q", "urdf"), default="q",
                     help="joint variables q_1..q_n (default), or the URDF joint names made into symbols")
    sub.add_argument("--xacro-arg", metavar="NAME:=VALUE", action="append", default=[],
                     help="a xacro argument, as `xacro FILE NAME:=VALUE` takes it (repeatable); it overrides the "
                     "file's <xacro:arg> default")
    sub.add_argument("--package-path", metavar="DIR", action="append", default=[],
                     help="a folder to search for the ROS packages that $(find PKG) names, after the package that "
                     "holds the file and its workspace (repeatable); nothing outside these folders is read")
    sub.add_argument("-o", "--output", metavar="OUT.yaml", help="write to OUT.yaml (atomically) instead of "
                     "standard output")
    sub.set_defaults(run=run)


def run(robot: None, args) -> str | None:
    if Path(args.file).suffix.lower() in (".yaml", ".yml"):
        loaded = load_robot_file(args.file)
        warn(loaded.warnings)
        robot = convert_robot(loaded, args.convention or loaded.chain.convention)
    else:
        robot = import_urdf(args.file, args.base, args.tip, args.convention or "standard", args.variables,
                            xacro_arguments(args.xacro_arg), args.package_path).robot
        warn(robot.warnings)
    text = robot_yaml(robot)
    if args.output is None:
        return text
    write_atomic(args.output, text, inputs=[args.file])
    return None


def xacro_arguments(pairs: list[str]) -> dict:
    """NAME → VALUE of each `--xacro-arg NAME:=VALUE` (the last of a name wins, as in xacro).

    >>> xacro_arguments(["ur_type:=ur5e", "prefix:="])
    {'ur_type': 'ur5e', 'prefix': ''}
    >>> xacro_arguments(["ur_type=ur5e"])
    Traceback (most recent call last):
    dhsym.errors.UserError: --xacro-arg ur_type=ur5e: write NAME:=VALUE, as xacro takes it (ur_type:=ur5e)
    """
    arguments = {}
    for pair in pairs:
        match = _ARGUMENT.fullmatch(pair)
        if match is None:
            example = pair.replace("=", ":=", 1) if "=" in pair and ":=" not in pair else "name:=ur"
            raise UserError(f"--xacro-arg {pair[:60]}: write NAME:=VALUE, as xacro takes it ({example[:60]})")
        if len(match.group(2)) > MAX_ARGUMENT_TEXT:
            raise UserError(f"--xacro-arg {match.group(1)}: a value longer than {MAX_ARGUMENT_TEXT:,} characters")
        arguments[match.group(1)] = match.group(2)
    return arguments
