"""The `dhsym` command line: `main` parses and dispatches; each command is a module here with
NAME, add_parser(commands) and run(robot, args)."""
from .app import main

__all__ = ["main"]
