"""Options shared by the commands, as argparse parent parsers, and the parser class that turns
a usage mistake into one line on stderr.

>>> parser = Parser(prog="demo", parents=[robot_options()])
>>> parser.parse_args(["puma560", "--timeout", "5"]).timeout
5.0
"""
from __future__ import annotations

import argparse
import shutil

from ..core.chain import Frame
from ..core.robot import Robot
from ..errors import UserError
from ..printing.render import MIN_WIDTH

SAFETY_NET_SECONDS = 600.0  # --timeout's default: far above any normal case (the slowest built-in takes seconds)
DEFAULT_WIDTH = 100  # when neither COLUMNS nor the terminal says


class Parser(argparse.ArgumentParser):
    """argparse, but a usage mistake is a UserError: one line on stderr and exit status 2."""

    def error(self, message):
        raise UserError(f"{message} (see '{self.prog} --help')")


class VersionAction(argparse.Action):
    """--version: `dhsym 0.1.0`, from the installed package's metadata (looked up only when asked)."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS, nargs=0,
                         help="print dhsym's version and exit")

    def __call__(self, parser, namespace, values, option_string=None):
        from importlib.metadata import PackageNotFoundError, version

        try:
            number = version("dhsym")
        except PackageNotFoundError:  # run from a source folder that was never installed
            number = "(not installed: no version)"
        print(f"dhsym {number}")
        parser.exit()


def robot_options() -> argparse.ArgumentParser:
    """ROBOT and --timeout: every command that reads a robot takes them."""
    parent = argparse.ArgumentParser(add_help=False)
    parent.add_argument("robot", metavar="ROBOT", help="built-in robot name or path to a robot YAML file")
    parent.add_argument("--timeout", type=seconds, default=None, metavar="SECONDS",
                        help="a safety net only: stop with an error after this long (default "
                             f"{SAFETY_NET_SECONDS:g}). What is worked out is decided from size estimates made "
                             "before the work, never from the clock, so no normal input comes near it")
    return parent


def safety_net(args) -> float | None:
    """The seconds a command may run: --timeout as given, else SAFETY_NET_SECONDS for a command that
    reads a robot, else no limit.

    >>> safety_net(argparse.Namespace(timeout=None)), safety_net(argparse.Namespace())
    (600.0, None)
    """
    if not hasattr(args, "timeout"):
        return None
    return args.timeout or default_limit()


def default_limit() -> float:
    """--timeout's default (read when asked, so that a test can lower it)."""
    return SAFETY_NET_SECONDS


def format_options() -> argparse.ArgumentParser:
    """--format, --ascii and --width: the commands that print matrices or tables."""
    parent = argparse.ArgumentParser(add_help=False)
    parent.add_argument("--format", choices=("text", "latex", "json"), default="text",
                        help="output format (default text)")
    parent.add_argument("--ascii", action="store_true", help="plain ASCII text instead of Unicode")
    parent.add_argument("--width", type=columns, default=None, metavar="N",
                        help="text width in columns, at least 40; wider matrices are printed element by element "
                             "and long elements are broken (default: $COLUMNS, else the terminal's, else 100)")
    return parent


def text_width(requested: int | None = None) -> int:
    """--width if given, else $COLUMNS, else the terminal's width, else 100; never below MIN_WIDTH.

    >>> text_width(72)
    72
    """
    if requested:
        return requested
    return max(MIN_WIDTH, shutil.get_terminal_size((DEFAULT_WIDTH, 24)).columns)


def columns(text: str) -> int:
    """A text width for --width: a whole number of columns, at least MIN_WIDTH."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of columns") from None
    if value < MIN_WIDTH:
        raise argparse.ArgumentTypeError(f"the width must be at least {MIN_WIDTH} columns, not {value}")
    return value


def frame_options(parser: argparse.ArgumentParser) -> None:
    """--from and --to: the two frames of a transform."""
    parser.add_argument("--from", dest="start", metavar="F", help="start frame (default: base, else the first)")
    parser.add_argument("--to", dest="end", metavar="T", help="end frame (default: tool, else the last)")


def chosen_frame(robot: Robot, text, option: str, default: Frame | None) -> Frame | None:
    """The chain's frame that `option` names by its printed number (`default` when not given); a
    frame the robot does not have is an error that names the option.

    >>> from dhsym.io.library import load
    >>> chosen_frame(load("spherical_wrist"), "4", "--from", 0)
    1
    >>> chosen_frame(load("spherical_wrist"), "0", "--from", 0)
    Traceback (most recent call last):
    dhsym.errors.UserError: --from: no frame 0 in this robot; frames are 3, 4, 5, 6
    """
    if text is None:
        return default
    try:
        return robot.numbering.chain_frame(text, robot.chain)
    except UserError as error:
        raise UserError(f"{option}: {error.message}") from None


def seconds(text: str) -> float:
    """A positive number of seconds, for --timeout."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None
    if not 0 < value < 1e6:
        raise argparse.ArgumentTypeError("the timeout must be a positive number of seconds")
    return value
