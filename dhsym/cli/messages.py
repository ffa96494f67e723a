"""How the command line speaks to the user on stderr: every message one line (`printable`), and
warnings as `dhsym: warning: ...`, both for the robot the dispatcher reads and for those a command
reads on its own (a second robot file, a URDF).

>>> printable("name\\x1b[31m")  # a terminal escape in a robot's name cannot colour the terminal
'name\\\\x1b[31m'
"""
from __future__ import annotations

import sys


def warn(messages) -> None:
    """Each message as one `dhsym: warning:` line on stderr."""
    for message in messages:
        print(f"dhsym: warning: {printable(message)}", file=sys.stderr)


def printable(message: str) -> str:
    """One line whatever the message quotes: line breaks and control characters are escaped.

    >>> printable("bad\\nname")
    'bad\\\\nname'
    """
    return "".join(ch if ch.isprintable() else ascii(ch)[1:-1] for ch in message)
