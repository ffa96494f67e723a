"""`dhsym import`: a URDF (or an `axes:` robot file) in, a DH robot file out.

    dhsym import ur5.urdf --tip tool0 --convention modified -o ur5.yaml

Joint i of the table is the i-th revolute, continuous or prismatic URDF joint from base to tip;
its variable q_i (or, with --variables urdf, the URDF joint's name made into a symbol) equals
the joint's value: θi = q_i + offset, or d_i = q_i + offset.
"""
from __future__ import annotations

import re
from pathlib import Path

import sympy

from ..errors import UserError
from ..geometry.convert import to_convention
from ..geometry.frames import assign_frames
from ..io.expr import parse_expression
from ..io.output import write_atomic
from ..io.robotfile import load_robot_file
from ..io.robotwriter import robot_yaml
from .messages import warn

_NAME_START = re.compile(r"^[A-Za-z]")


def add_parsers(commands) -> None:
    sub = commands.add_parser("import", help="derive a DH robot file from a URDF (or an axes: robot file)",
                              description="Read the serial chain from --base to --tip of a URDF file, assign DH "
                              "frames and write the robot file. Joint i is the i-th movable joint from base to tip; "
                              "its variable equals the joint value. Fixed joints fold into the constants; meshes "
                              "are not read. A robot file with axes: is converted to joints: instead.")
    sub.add_argument("file", metavar="FILE", help="a .urdf file, or a robot .yaml file written with axes:")
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
        chain, notes = to_convention(loaded.chain, args.convention or loaded.chain.convention), None
    else:
        from ..geometry.urdf import read_urdf  # lxml only when a URDF is read

        urdf = read_urdf(args.file, args.base, args.tip)
        warn(urdf.warnings)
        variables = joint_symbols(urdf.joint_names, args.variables)
        chain = assign_frames(urdf.axes, urdf.tool, args.convention or "standard", variables).chain(
            name=urdf.name, source=f"{Path(urdf.path).name}, links {urdf.base} → {urdf.tip}")
        notes = "Derived by dhsym import; joint variables: " + ", ".join(
            f"{v} = {name}" for v, name in zip(variables, urdf.joint_names))
    text = robot_yaml(chain, notes)
    if args.output is None:
        return text
    write_atomic(args.output, text, inputs=[args.file])
    return None


def joint_symbols(names: list[str], style: str) -> list[sympy.Symbol]:
    """q_1..q_n, or the URDF names made into symbols ('joint-1' → joint_1); q_i where that fails
    (a name that is not a name in a robot file, such as pi or sin, or one taken already).

    >>> joint_symbols(["shoulder pan", "2nd", "pi"], "urdf")
    [shoulder_pan, q_2, q_3]
    """
    symbols = []
    for number, name in enumerate(names, 1):
        made = re.sub(r"\W+", "_", name).strip("_") if style == "urdf" else ""
        symbol = sympy.Symbol(made or "_", real=True)
        if not _NAME_START.match(made) or symbol in symbols or not _reads_back(made, symbol):
            symbol = sympy.Symbol(f"q_{number}", real=True)
        symbols.append(symbol)
    return symbols


def _reads_back(name: str, symbol: sympy.Symbol) -> bool:
    try:
        return parse_expression(name) == symbol
    except UserError:
        return False
