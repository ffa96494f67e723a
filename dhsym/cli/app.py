"""The `dhsym` command: parse, load the robot, run the command, report every failure in one line.

    dhsym list
    dhsym table puma560
    dhsym fk puma560 --from 3 --to 6 --format latex
    dhsym fk - < arm.yaml

Each command lives in its own module (listing, kinematics, latex, plot, ...) with
`add_parsers(commands)`, which registers its subcommands and their `run(robot, args)`. Only the
module of the command being run is imported (COMMANDS), so that `dhsym fk` does not pay for the
Jacobian, the documents or the URDF reader; `dhsym --help` and a mistyped command import them all.

Exit status: 0, with warnings (if any) on stderr; 2 after one `dhsym: error:` line (a mistake in
the input or the command line, or output that cannot be written: a full disk, a closed standard
output, an unwritable file); 141, the status of a tool stopped by a closed pipe, after one
`dhsym: error:` line when the reader of a pipe leaves before the output is written (`| head -0`);
130 on Ctrl-C, and 143 or 129 on SIGTERM or SIGHUP to the `dhsym` process, as a shell reports a tool
stopped by them (a file being written with -o is removed first, as on Ctrl-C); 70 for a bug in dhsym itself.

Whether a result is worked out is decided from estimates made before the work (dhsym.core.estimate,
cli.limits), so the answer is the same on any machine. `--timeout` is only a safety net, far above
any normal case, for an input that no estimate foresaw.
"""
from __future__ import annotations

import json
import os
import signal
import sys
from importlib import import_module

from ..core.budget import CommandTooSlow, time_budget
from ..errors import Location, UserError
from ..io import library
from ..io.robotfile import load_robot_text
from ..io.yamlsafe import MAX_FILE_BYTES, decode_utf8
from .messages import missing_extra, printable, warn
from .options import Parser, VersionAction, default_limit, safety_net, text_width

# Each command and the module (in dhsym.cli) that registers it, in the order `dhsym --help` lists them.
COMMANDS = {"list": "listing", "table": "kinematics", "links": "kinematics", "fk": "kinematics", "latex": "latex",
            "plot": "plot", "jacobian": "jacobian", "ik": "ik", "dynamics": "dynamics", "import": "urdf_import",
            "convert": "convert", "check": "check", "screws": "screws"}

EXIT_USER_ERROR = 2
EXIT_INTERNAL_ERROR = 70
EXIT_BROKEN_PIPE = 141  # what a shell reports for a tool stopped by SIGPIPE
ISSUE_URL = "the dhsym issue tracker"
STOP_SIGNALS = {name: getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name)}


class Stopped(BaseException):
    """SIGTERM or SIGHUP, raised where the process is (a BaseException, as KeyboardInterrupt is, so
    that what is being written is removed on the way out: io.output.write_atomic)."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


def stop_cleanly_on_signals() -> None:
    """Turn SIGTERM and SIGHUP into Stopped, for the `dhsym` process (cli/__main__.py) only: the
    default action ends the process at once and leaves a half-written -o file's temporary beside it."""
    for number in STOP_SIGNALS.values():
        signal.signal(number, _stop)


def _stop(signum, frame):
    for number in STOP_SIGNALS.values():  # a second signal must not cut the clean-up short
        signal.signal(number, signal.SIG_IGN)
    raise Stopped(signum)


def build_parser(argv=None) -> Parser:
    """The parser for `argv`: with the command's own module only, when argv starts with a known command.

    >>> build_parser(["fk", "puma560"]).parse_args(["fk", "puma560", "--to", "3"]).end
    '3'
    """
    parser = Parser(prog="dhsym", description="Denavit–Hartenberg tables to textbook-form kinematics: "
                    "link matrices, products iTj and 0Tn in c1/s23/c123 notation, as text, LaTeX or JSON.",
                    epilog="ROBOT is a built-in name (see 'dhsym list') or a path to a robot YAML file.")
    parser.add_argument("--version", action=VersionAction)
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    commands.required = True
    for module in command_modules(argv):
        import_module(f".{module}", __package__).add_parsers(commands)
    return parser


def command_modules(argv=None) -> list[str]:
    """The modules to import for `argv`: the command's, none for --version, else (help, no command, a
    typo) all of them.

    >>> command_modules(["fk", "puma560"]), command_modules(["--version"]), len(command_modules(["--help"]))
    (['kinematics'], [], 11)
    """
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] in COMMANDS:
        return [COMMANDS[argv[0]]]
    if argv == ["--version"]:
        return []
    return list(dict.fromkeys(COMMANDS.values()))


def main(argv=None, read=library.read) -> int:
    """Run one command; `read` turns ROBOT into a Robot (tests pass their own)."""
    args = None
    try:
        args = build_parser(argv).parse_args(argv)
        with time_budget(safety_net(args), CommandTooSlow):
            return _dispatch(args, read)
    except BrokenPipeError:  # `dhsym fk iiwa7 | head -0`: the reader left; say so, the output is cut short
        _silence_stdout()
        print("dhsym: error: standard output was closed by its reader before all of the output was written "
              "(a pipe into head?); the output is incomplete", file=sys.stderr)
        return EXIT_BROKEN_PIPE
    except UserError as error:
        print(f"dhsym: error: {printable(str(error))}", file=sys.stderr)
        return EXIT_USER_ERROR
    except CommandTooSlow:
        print(f"dhsym: error: {printable(args.robot)}: {_stopped(args.timeout, safety_net(args))}", file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt:
        print("dhsym: interrupted", file=sys.stderr)
        return 130
    except Stopped as stop:
        name = signal.Signals(stop.signum).name
        try:  # after a hangup the terminal may be gone
            print(f"dhsym: stopped by {name}", file=sys.stderr)
        except (OSError, ValueError):
            pass
        return 128 + stop.signum
    except UnicodeEncodeError as error:
        print(f"dhsym: error: the output cannot be written as {error.encoding}; use --ascii, or set "
              f"PYTHONIOENCODING=utf-8", file=sys.stderr)
        return EXIT_USER_ERROR
    except ImportError as error:  # an optional package (dhsym[plot], [urdf], [xacro]) that is not installed
        missing = missing_extra(error)
        if missing is None:
            return _internal_error(error)
        print(f"dhsym: error: {missing}", file=sys.stderr)
        return EXIT_USER_ERROR
    except Exception as error:  # a bug in dhsym, not the user's fault
        return _internal_error(error)


def _internal_error(error: Exception) -> int:
    print(f"dhsym: internal error: {type(error).__name__}: {printable(str(error))[:300]} (a bug in dhsym, "
          f"not a mistake in your input; please report it on {ISSUE_URL} with the command and the robot file)",
          file=sys.stderr)
    return EXIT_INTERNAL_ERROR


def _stopped(given: float | None, limit: float) -> str:
    """Why a command stopped on the clock: the limit the user `given` (too short for this work), or
    the default safety net, which no normal input reaches (then dhsym's estimates missed something).

    >>> _stopped(1e-07, 1e-07)[:70]
    'stopped after 1e-07 s, the limit set with --timeout, before the work w'
    """
    if given is not None:
        return (f"stopped after {given:g} s, the limit set with --timeout, before the work was done; that limit is "
                f"too short for this command: give a longer one, or leave --timeout out (the default, "
                f"{default_limit():g} s, is a safety net far above any normal case)")
    return (f"stopped by the safety net after {limit:g} s (--timeout); no normal input takes this long, and the "
            f"size estimates did not foresee it; please report the robot file on {ISSUE_URL}")


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that Python's final flush does not complain about the pipe again."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError):  # stdout without a file descriptor (tests, notebooks): nothing to do
        pass


def _without_control_characters(text: str, json_format: bool) -> str:
    """The output with every control character escaped (a robot name with terminal escape
    sequences, a right-to-left override in a note), line breaks and tabs kept: as \\u escapes
    in JSON, as Python-style escapes like the error messages' in text. LaTeX has none left.

    >>> _without_control_characters("arm\\x1b[31m\\n", False), _without_control_characters('"a\\x7f"', True)
    ('arm\\\\x1b[31m\\n', '"a\\\\u007f"')
    """
    if text.replace("\n", "").replace("\t", "").isprintable():
        return text
    return "".join(ch if ch.isprintable() or ch in "\n\t" else
                   json.dumps(ch)[1:-1] if json_format else ascii(ch)[1:-1] for ch in text)


def _dispatch(args, read) -> int:
    robot = None
    if hasattr(args, "robot"):
        robot = read_standard_input() if args.robot == "-" else read(args.robot)
        warn(robot.warnings)
    if hasattr(args, "width"):
        args.width = text_width(args.width)  # --width, else $COLUMNS, else the terminal's, else 100
    output = args.run(robot, args)
    if output is not None:
        output = _without_control_characters(output, getattr(args, "format", "text") == "json")
        if sys.stdout is None:  # started with standard output closed (`dhsym fk puma560 >&-`)
            raise UserError("standard output is closed; there is nowhere to write the result")
        try:
            sys.stdout.write(output if output.endswith("\n") else output + "\n")
            sys.stdout.flush()  # a full disk is found here, while a clear message can still be given
        except BrokenPipeError:
            raise
        except OSError as error:  # a full disk, a device that refuses the bytes
            _silence_stdout()
            raise UserError(f"cannot write the output: {error.strerror or error}") from None
    return getattr(output, "exit_status", 0)  # `dhsym check` says 1 for "different"


def read_standard_input():
    """`dhsym fk -`: the robot file from standard input, with a robot file's limits."""
    if sys.stdin is None:
        raise UserError("standard input is closed; give a robot file or a built-in name instead of -")
    stream = getattr(sys.stdin, "buffer", None)
    data = stream.read(MAX_FILE_BYTES + 1) if stream else sys.stdin.read(MAX_FILE_BYTES + 1).encode("utf-8")
    if len(data) > MAX_FILE_BYTES:
        raise UserError(f"file is larger than {MAX_FILE_BYTES // (1 << 20)} MiB, the limit for robot files",
                        Location(STDIN_NAME, 1, 1))
    return load_robot_text(decode_utf8(data, STDIN_NAME), STDIN_NAME)


STDIN_NAME = "<stdin>"


if __name__ == "__main__":
    sys.exit(main())
