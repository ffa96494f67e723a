"""How the command line speaks to the user on stderr: every message one line (`printable`), and
warnings as `dhsym: warning: ...`, both for the robot the dispatcher reads and for those a command
reads on its own (a second robot file, a URDF).

>>> printable("name\\x1b[31m")  # a terminal escape in a robot's name cannot colour the terminal
'name\\\\x1b[31m'
"""
from __future__ import annotations

import sys

# The optional packages, by the module a command imports: what needs it, and the extra that installs it.
EXTRAS = {"matplotlib": ("dhsym plot draws with it", "plot"),
          "numpy": ("dhsym plot, ik --numeric and ik(...).evaluate compute with it", "plot"),
          "lxml": ("dhsym import reads URDF files with it", "urdf"),
          "xacro": ("dhsym import expands .xacro files with it", "xacro")}


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


def missing_extra(error: ImportError) -> str | None:
    """The one line to say when an optional package is not installed, or None when the missing
    module is no optional package (then it is a bug).

    >>> print(missing_extra(ModuleNotFoundError("No module named 'matplotlib'", name="matplotlib.figure")))
    matplotlib is not installed (dhsym plot draws with it); install it with: pip install 'dhsym[plot]'
    >>> missing_extra(ModuleNotFoundError("No module named 'sympy'", name="sympy")) is None
    True
    """
    missing = (error.name or "").partition(".")[0]
    if missing not in EXTRAS:
        return None
    what, extra = EXTRAS[missing]
    return f"{missing} is not installed ({what}); install it with: pip install 'dhsym[{extra}]'"
