"""`dhsym import`: a URDF, a .xacro file or an `axes:` robot file in, a DH robot file out.

    dhsym import ur5.urdf --tip tool0 --convention modified -o ur5.yaml

Joint i of the table is the i-th revolute, continuous or prismatic URDF joint from base to tip;
its variable q_i (or, with --variables urdf, the URDF joint's name made into a symbol) equals
the joint's value: θi = q_i + offset, or d_i = q_i + offset. The work is `io.urdfimport.import_urdf`.
"""
from __future__ import annotations

from pathlib import Path

from ..geometry.convert import to_convention
from ..io.output import write_atomic
from ..io.robotfile import load_robot_file
from ..io.robotwriter import robot_yaml
from ..io.urdfimport import import_urdf
from .messages import warn


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
    sub.add_argument("-o", "--output", metavar="OUT.yaml", help="write to OUT.yaml (atomically) instead of "
                     "standard output")
    sub.set_defaults(run=run)


def run(robot, args) -> str | None:
    if Path(args.file).suffix.lower() in (".yaml", ".yml"):
        loaded = load_robot_file(args.file)
        warn(loaded.warnings)
        robot = to_convention(loaded, args.convention or loaded.convention)
    else:
        robot = import_urdf(args.file, args.base, args.tip, args.convention or "standard", args.variables).robot
        warn(robot.warnings)
    text = robot_yaml(robot)
    if args.output is None:
        return text
    write_atomic(args.output, text, inputs=[args.file])
    return None
