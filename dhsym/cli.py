"""The `dhsym` command: argument parsing and dispatch only.

    dhsym list
    dhsym table puma560
    dhsym links planar3r --ascii
    dhsym fk puma560 --from 3 --to 6 --format latex
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import warnings

from . import latexdoc, plot_cli, render
from .budget import CommandTooSlow, SimplificationTimeout, time_budget
from .errors import UserError
from .library import builtin_names, load
from .printing import LatexPrinter

# Subcommands that live in their own modules: each has NAME, add_parser(commands) and
# run(robot, args) -> str | None (None when it wrote its own output file).
EXTENSIONS: tuple = (plot_cli, latexdoc)

EXIT_USER_ERROR = 2
EXIT_INTERNAL_ERROR = 70
COMMAND_BUDGET_FACTOR = 5  # times --timeout, for everything a command does (printing too)
EXIT_BROKEN_PIPE = 141  # what a shell reports for a tool stopped by SIGPIPE
ISSUE_URL = "the dhsym issue tracker"


class _Parser(argparse.ArgumentParser):
    """argparse, but a usage mistake is one line on stderr and exit status 2."""

    def error(self, message):
        raise UserError(f"{message} (see '{self.prog} --help')")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="dhsym", description="Denavit–Hartenberg tables to textbook-form kinematics: "
                     "link matrices, products iTj and 0Tn in c1/s23/c123 notation, as text, LaTeX or JSON.",
                     epilog="ROBOT is a built-in name (see 'dhsym list') or a path to a robot YAML file.")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    commands.required = True
    commands.add_parser("list", help="list the built-in robots and their sources",
                        description="List the built-in robots with their joints, convention and source.")

    def robot_command(name, help_text, description):
        sub = commands.add_parser(name, help=help_text, description=description)
        sub.add_argument("robot", metavar="ROBOT", help="built-in robot name or path to a robot YAML file")
        sub.add_argument("--format", choices=("text", "latex", "json"), default="text",
                         help="output format (default text)")
        sub.add_argument("--ascii", action="store_true", help="plain ASCII text instead of Unicode")
        sub.add_argument("--width", type=int, default=100, metavar="N",
                         help="text width; wider matrices are printed element by element (default 100)")
        add_common_options(sub)
        return sub

    robot_command("table", "print the DH table", "Print the robot's DH table in its convention's column order; "
                  "* marks the joint variables.")
    links = robot_command("links", "print every link matrix", "Print every link matrix {i-1}T_i, simplified.")
    links.add_argument("--raw", action="store_true", help="plain products, without simplification")
    fk = robot_command("fk", "print the transform between two frames (default: whole chain)",
                       "Print {FROM}T_{TO}. Frames are 0..n, plus base and tool when the robot has them. "
                       "FROM after TO gives the inverse transform.")
    fk.add_argument("--from", dest="start", metavar="F", help="start frame (default: base, else 0)")
    fk.add_argument("--to", dest="end", metavar="T", help="end frame (default: tool, else n)")
    fk.add_argument("--raw", action="store_true", help="the plain product, without simplification")
    for extension in EXTENSIONS:
        extension.add_parser(commands)
    return parser


def add_common_options(sub: argparse.ArgumentParser) -> None:
    """Options every command that reads a robot shares."""
    sub.add_argument("--timeout", type=_seconds, default=60.0, metavar="SECONDS",
                     help="simplification budget per result; past it the raw product is printed (default 60). "
                          f"A whole command stops with an error after {COMMAND_BUDGET_FACTOR} times this")


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None
    if not 0 < value < 1e6:
        raise argparse.ArgumentTypeError("the timeout must be a positive number of seconds")
    return value


def main(argv=None) -> int:
    try:
        args = build_parser().parse_args(argv)
        with warnings.catch_warnings(record=True) as caught, time_budget(_command_budget(args), CommandTooSlow):
            warnings.simplefilter("always", SimplificationTimeout)
            status = _dispatch(args)
        for warning in caught:
            if issubclass(warning.category, SimplificationTimeout):
                print(f"dhsym: warning: {_printable(str(warning.message))}", file=sys.stderr)
        return status
    except UserError as error:
        print(f"dhsym: error: {_printable(str(error))}", file=sys.stderr)
        return EXIT_USER_ERROR
    except CommandTooSlow:
        print(f"dhsym: error: {_printable(args.robot)}: gave up after {_command_budget(args):g} s; the result is "
              f"too large to work out and print (ask for part of the chain with --from/--to, or raise --timeout)",
              file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt:
        print("dhsym: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # `dhsym fk puma560 | head`: the reader left; stop quietly, like a shell tool
        _silence_stdout()
        return EXIT_BROKEN_PIPE
    except UnicodeEncodeError as error:
        print(f"dhsym: error: the output cannot be written as {error.encoding}; use --ascii, or set "
              f"PYTHONIOENCODING=utf-8", file=sys.stderr)
        return EXIT_USER_ERROR
    except Exception as error:  # a bug in dhsym, not the user's fault
        print(f"dhsym: internal error: {type(error).__name__}: {_printable(str(error))[:300]}\n"
              f"This is a bug in dhsym, not a mistake in your input. Please report it on {ISSUE_URL} "
              f"with the command you ran and the robot file.", file=sys.stderr)
        return EXIT_INTERNAL_ERROR


def _command_budget(args) -> float | None:
    """A whole command may take this long; simplification alone gets --timeout per result."""
    timeout = getattr(args, "timeout", None)
    return COMMAND_BUDGET_FACTOR * timeout if timeout else None


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that Python's final flush does not complain about the pipe again."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError):  # stdout without a file descriptor (tests, notebooks): nothing to do
        pass


def _printable(message: str) -> str:
    """One line whatever the message quotes: line breaks and control characters are escaped."""
    return "".join(ch if ch.isprintable() else ascii(ch)[1:-1] for ch in message)


def _dispatch(args) -> int:
    if args.command == "list":
        _print_list()
        return 0
    robot = load(args.robot)
    robot.chain.timeout = args.timeout
    for warning in robot.warnings:
        print(f"dhsym: warning: {_printable(warning)}", file=sys.stderr)
    commands = {"table": _table, "links": _links, "fk": _fk}
    commands.update({extension.NAME: extension.run for extension in EXTENSIONS})
    output = commands[args.command](robot, args)
    if output is not None:
        sys.stdout.write(output if output.endswith("\n") else output + "\n")
    return 0


def _print_list() -> None:
    robots = [load(name) for name in builtin_names()]
    width = max(len(name) for name in builtin_names())
    for name, robot in zip(builtin_names(), robots):
        print(f"{name:<{width}}  {robot.chain.n} joints  {robot.chain.convention:<8}  {robot.name}")
        print(f"{'':<{width}}  source: {robot.source}")


def _frame(text, chain, default):
    """The frame a --from/--to value names (0..n, base, tool), or a UserError listing the frames."""
    return default if text is None else chain.frame(text)


def _header(robot, what: str, ascii: bool) -> str:
    title = f"{robot.name}: {what}  ({robot.chain.convention} DH)"
    return title.replace("−", "-") if ascii else title


def _table(robot, args) -> str:
    if args.format == "json":
        rows = [{"joint": r.joint, "theta": str(r.theta), "d": str(r.d), "a": str(r.a), "alpha": str(r.alpha),
                 "variable": r.variable.name} for r in robot.chain.rows]
        return json.dumps({"robot": robot.name, "convention": robot.chain.convention, "rows": rows}, indent=2)
    if args.format == "latex":
        return "\\[\n" + render.latex_table(robot) + "\n\\]"
    note = render.convention_note(robot.chain.convention, ascii=args.ascii) + "; * marks joint variables"
    return _header(robot, "DH table", args.ascii) + "\n" + note \
        + "\n\n" + render.text_table(robot, ascii=args.ascii)


def _links(robot, args) -> str:
    results = [(i - 1, i, robot.chain.link(i, raw=args.raw)) for i in range(1, robot.chain.n + 1)]
    return _results(robot, results, args)


def _fk(robot, args) -> str:
    chain = robot.chain
    start, end = _frame(args.start, chain, chain.first_frame), _frame(args.end, chain, chain.last_frame)
    return _results(robot, [(start, end, chain.transform(start, end, raw=args.raw))], args)


def _results(robot, results, args) -> str:
    if args.format == "json":
        data = [render.json_result(robot, i, j, m) for i, j, m in results]
        return json.dumps(data[0] if len(data) == 1 else data, indent=2, ensure_ascii=False)
    if args.format == "latex":
        printer = LatexPrinter(robot.chain.joint_variables)
        blocks = [f"{render.transform_title(i, j, 'latex')} =\n{render.latex_matrix(m, printer)}"
                  for i, j, m in results]
        legend = render.latex_legend(printer)
        return "\n\n".join(f"\\[\n{b}\n\\]" for b in blocks) + (f"\n\nwhere ${legend}$" if legend else "")
    printer = render.text_printer(robot, ascii=args.ascii)
    style = "ascii" if args.ascii else "unicode"
    blocks = []
    for i, j, matrix in results:
        title = _header(robot, render.transform_title(i, j, style), args.ascii)
        blocks.append(title + "\n\n" + render.text_matrix(matrix, printer, args.width))
    legend = render.text_legend(printer, args.width)
    return "\n\n".join(blocks) + ("\n\n" + legend if legend else "")


if __name__ == "__main__":
    sys.exit(main())
