"""`dhsym screws`: the product-of-exponentials form of a DH robot, the space-frame screw
axes S_i = (ω_i, v_i) and the home pose M (Lynch and Park, Modern Robotics, section 4.1).

    dhsym screws ur5
"""
from __future__ import annotations

import json

from ..core.robot import Robot
from ..geometry.screws import screw_axes
from ..printing import render
from .limits import LATEX_MAX_NODES, MAX_NODES, refuse_long_entries, refuse_screws_if_too_large
from .options import format_options, robot_options


def add_parsers(commands) -> None:
    sub = commands.add_parser("screws", parents=[robot_options(), format_options()],
                              help="print the screw axes S_i and home pose M",
                              description="Print the space-frame screw axes S_i = (ω_i, v_i) of every joint and "
                              "the home pose M (base → tool with every joint variable zero), so that "
                              "T(q) = exp([S1] q1) ⋯ exp([Sn] qn) M.")
    sub.set_defaults(run=run)


def run(robot: Robot, args) -> str:
    chain, numbering = robot.chain, robot.numbering
    refuse_long_entries(robot)
    refuse_screws_if_too_large(robot, LATEX_MAX_NODES if args.format == "latex" else MAX_NODES)
    screws = screw_axes(chain)
    variables = chain.joint_variables
    first = numbering.frame(chain.first_frame)
    if args.format == "json":  # exact, with the decimals as the file wrote them, as every JSON output
        exact = render.exact_printer(robot).doprint
        return json.dumps({"robot": robot.name, "frame": str(first),
                           "screws": {v.name: [exact(x) for x in screws.matrix[:, i]] for i, v in enumerate(variables)},
                           "home": [[exact(x) for x in screws.home.row(r)] for r in range(4)]}, indent=2,
                          ensure_ascii=False)
    if args.format == "latex":
        printer = render.latex_printer(robot)
        return (f"\\[\nS = {render.latex_matrix(screws.matrix, printer)}\n\\]\n\n"
                f"\\[\nM = {render.latex_matrix(screws.home, printer)}\n\\]")
    printer = render.text_printer(robot, ascii=args.ascii)
    title = f"{robot.name}: screw axes in frame {first} at q = 0  (from {chain.convention} DH)"
    lines = [title, "S_i = (ωx, ωy, ωz; vx, vy, vz)", ""]
    for i, variable in enumerate(variables):
        column = [printer.doprint(x) for x in screws.matrix[:, i]]
        name = f"S{numbering.joint(i + 1)} ({printer.doprint(variable)})"  # numbered as the table numbers its rows
        lines += _screw_lines(name, column, args.width)
    lines += ["", "M =", render.text_matrix(screws.home, printer, args.width)]
    text = "\n".join(lines)
    return text.replace("ω", "w").replace("−", "-") if args.ascii else text


def _screw_lines(name: str, column: list[str], width: int) -> list[str]:
    """`S2 (θ2) = (ωx, ωy, ωz; vx, vy, vz)` on one line, or, when that is wider than `width`, one
    line per component, broken like a matrix element (a general chain's axes are long).

    >>> print(*_screw_lines("S2 (θ2)", ["0", "0", "1", "0", "−a1", "0"], 40), sep="\\n")
    S2 (θ2) = (0, 0, 1; 0, −a1, 0)
    >>> print(*_screw_lines("S2 (θ2)", ["0", "0", "1", "0", "−a1 c2 − a2 c23 − a3 c234 − a4 c2345", "0"], 40),
    ...       sep="\\n")
    S2 (θ2):
      ωx = 0
      ωy = 0
      ωz = 1
      vx = 0
      vy = −a1 c2 − a2 c23 − a3 c234
             − a4 c2345
      vz = 0
    """
    line = f"{name} = ({', '.join(column[:3])}; {', '.join(column[3:])})"
    if render.display_width(line) <= width:
        return [line]
    parts = zip(("ωx", "ωy", "ωz", "vx", "vy", "vz"), column)
    return [f"{name}:"] + [render.break_element(f"  {part} = ", text, width) for part, text in parts]
