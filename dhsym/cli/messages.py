"""Warnings that a command finds on its own (a second robot file, a URDF), printed the way the
dispatcher prints those of the robot it reads: `dhsym: warning: ...`, one line each."""
from __future__ import annotations

import sys


def warn(messages) -> None:
    from .app import printable  # app imports the command modules; this runs only after

    for message in messages:
        print(f"dhsym: warning: {printable(message)}", file=sys.stderr)
