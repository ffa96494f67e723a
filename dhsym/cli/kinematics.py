"""`dhsym table`, `dhsym links` and `dhsym fk`: the DH table, the link matrices and any
transform, as text, LaTeX or JSON.

    dhsym table puma560
    dhsym links planar3r --ascii
    dhsym fk puma560 --from 3 --to 6 --format latex
    dhsym fk iiwa7 --format latex --text-width 469
"""
from __future__ import annotations

import argparse
import json

from ..core.robot import Robot
from ..latex.results import ARTICLE_TEXT_WIDTH_PT, results_latex, table_latex
from ..printing import render
from .limits import LATEX_MAX_NODES, MAX_NODES, refuse_if_too_large
from .options import chosen_frame, format_options, frame_options, robot_options


def add_parsers(commands) -> None:
    parents = [robot_options(), format_options()]
    table = commands.add_parser("table", parents=parents, help="print the DH table",
                                description="Print the robot's DH table in its convention's column order; "
                                "* marks the joint variables.")
    table.set_defaults(run=run_table)
    links = commands.add_parser("links", parents=parents, help="print every link matrix",
                                description="Print every link matrix {i-1}T_i, simplified.")
    links.add_argument("--raw", action="store_true", help="plain products, without simplification")
    text_width_option(links)
    links.set_defaults(run=run_links)
    fk = commands.add_parser("fk", parents=parents, help="print the transform between two frames "
                             "(default: whole chain)", description="Print {FROM}T_{TO}. Frames are 0..n (numbered "
                             "from the robot file's first_frame when it has one), plus base and tool when the robot "
                             "has them. FROM after TO gives the inverse transform.")
    frame_options(fk)
    fk.add_argument("--raw", action="store_true", help="the plain product, without simplification")
    text_width_option(fk)
    fk.set_defaults(run=run_fk)


def text_width_option(parser) -> None:
    parser.add_argument("--text-width", type=points, default=ARTICLE_TEXT_WIDTH_PT, metavar="PT",
                        help="with --format latex: the line width in pt (at 10 pt type) that matrices must fit; "
                             f"wider ones are written element by element (default {ARTICLE_TEXT_WIDTH_PT:g}, "
                             "a standard article)")


def points(text: str) -> float:
    """A line width in pt, for --text-width."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a width in pt") from None
    if not 100 <= value <= 2000:
        raise argparse.ArgumentTypeError("the text width must be between 100 and 2000 pt")
    return value


def run_table(robot: Robot, args) -> str:
    chain = robot.chain
    if args.format == "json":
        exact = render.exact_printer(robot)
        rows = [{"joint": r.joint, "number": number,
                 **{key: exact.doprint(getattr(r, key)) for key in ("theta", "d", "a", "alpha")},
                 "variable": r.variable.name} for number, r in zip(robot.numbering.joints(chain), chain.rows)]
        return json.dumps({"robot": robot.name, "convention": chain.convention, "first_frame": robot.frame_offset,
                           "rows": rows}, indent=2)
    if args.format == "latex":
        return table_latex(robot)
    note = render.wrap(render.convention_note(chain.convention, ascii=args.ascii) + "; * marks joint variables",
                       args.width, "  ")
    return _header(robot, "DH table", args.ascii) + "\n" + note + "\n\n" + \
        render.text_table(robot, ascii=args.ascii)


def run_links(robot: Robot, args) -> str:
    chain = robot.chain
    return _results(robot, [(i - 1, i, chain.link(i, raw=args.raw)) for i in range(1, chain.n + 1)], args)


def run_fk(robot: Robot, args) -> str:
    chain = robot.chain
    start = chosen_frame(robot, args.start, "--from", chain.frames[0])
    end = chosen_frame(robot, args.end, "--to", chain.frames[-1])
    refuse_if_too_large(robot, start, end, args.raw, LATEX_MAX_NODES if args.format == "latex" else MAX_NODES)
    with robot.numbering.printed():
        matrix = chain.transform(start, end, raw=args.raw)
    return _results(robot, [(start, end, matrix)], args)


def _header(robot: Robot, what: str, ascii: bool) -> str:
    title = f"{robot.name}: {what}  ({robot.chain.convention} DH)"
    return title.replace("−", "-") if ascii else title


def _results(robot: Robot, results, args) -> str:
    """(i, j, matrix) with i, j the chain's frames, titled with the robot's numbers."""
    if args.format == "json":
        data = [render.json_result(robot, i, j, m) for i, j, m in results]
        return json.dumps(data[0] if len(data) == 1 else data, indent=2, ensure_ascii=False)
    if args.format == "latex":
        return results_latex(robot, results, args.text_width)
    printer = render.text_printer(robot, ascii=args.ascii)
    style = "ascii" if args.ascii else "unicode"
    blocks = []
    for i, j, matrix in results:
        title = _header(robot, render.transform_title(robot.numbering.frame(i), robot.numbering.frame(j), style),
                        args.ascii)
        blocks.append(title + "\n\n" + render.text_matrix(matrix, printer, args.width))
    legend = render.text_legend(printer, args.width)
    return "\n\n".join(blocks) + ("\n\n" + legend if legend else "")
