"""The `dhsym plot` command: read NAME=EXPR values safely and write the picture atomically.

    dhsym plot planar3r --q theta_1=30deg theta_2=45deg -o arm.png
"""
from __future__ import annotations

from pathlib import Path

from ..api.robot import notebook_robot
from ..core.robot import Robot
from ..errors import UserError
from .assignments import parse_assignments, target_elements
from .options import robot_options


def add_parsers(commands) -> None:
    sub = commands.add_parser("plot", parents=[robot_options()], help="draw the arm (links, joints, frames) as a PNG",
                              description="Draw the arm with every DH frame as an x/y/z triad (x red, y green, "
                              "z blue). Constants default to the robot file's sample values, joint variables to 0. "
                              "Planar arms are drawn in their plane, others in 3D.")
    sub.add_argument("--set", dest="constants", metavar="NAME=EXPR", nargs="+", action="extend", default=[],
                     help="value of a constant, e.g. --set l_1=0.5 l_2=1/3")
    sub.add_argument("--q", dest="joints", metavar="NAME=EXPR", nargs="+", action="extend", default=[],
                     help="value of a joint variable, e.g. --q theta_1=30deg d_3=0.2 (default 0)")
    sub.add_argument("-o", "--output", metavar="FILE", help="picture to write (.png, .pdf or .svg; default ROBOT.png)")
    sub.add_argument("--no-frames", action="store_true", help="draw links and joints only")
    sub.add_argument("--3d", dest="three_d", action="store_true", help="3D even when the arm is planar")
    sub.add_argument("--ik", nargs="?", const="", metavar="TARGET",
                     help="draw every inverse-kinematics branch that reaches the pose of --q, side by side; "
                          "TARGET replaces elements of that pose, e.g. --ik \"px=0.5, py=0.2\"")
    sub.add_argument("--free", metavar="VAR", nargs="+", action="extend", default=[],
                     help="with --ik: joint variables kept as parameters (their --q values are used)")
    sub.set_defaults(run=run)


def run(robot: Robot, args) -> str:
    from matplotlib.backends.backend_agg import FigureCanvasAgg  # here: other commands need no matplotlib
    from matplotlib.figure import Figure

    from ..plot import draw, is_planar, picture_format, save

    values = {**parse_assignments(robot, args.constants, "--set"),
              **parse_assignments(robot, args.joints, "--q")}
    stem = Path(args.robot).stem if args.robot != "-" else "robot"
    path = args.output or f"{stem}{'_ik' if args.ik is not None else ''}.png"
    picture_format(path)  # a wrong suffix is found before any drawing
    if args.ik is not None:
        return _branches(robot, args, values, path)
    if args.free:
        raise UserError("--free names the parameters of the inverse kinematics; add --ik")
    planar = False if args.three_d else None
    figure = Figure(figsize=(6.4, 5.6) if (planar is None and is_planar(robot, values)) else (7.2, 6.8))
    FigureCanvasAgg(figure)
    draw(robot, values, ax=figure, planar=planar, show_frames=not args.no_frames)
    save(figure, path, inputs=[robot.path])
    return str(path)


def _branches(robot: Robot, args, values, path) -> str:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from ..plot import save
    from ..plot.branches import draw_branches

    figure = Figure()
    FigureCanvasAgg(figure)
    constants = parse_assignments(robot, args.constants, "--set")
    draw_branches(notebook_robot(robot), values, target_elements(args.ik, "--ik"), constants, args.free, figure=figure,
                  show_frames=not args.no_frames)
    save(figure, path, inputs=[robot.path])
    return str(path)


