"""`dhsym list`: the built-in robots with their joints, convention and source."""
from __future__ import annotations

from ..io.library import builtin_names, load


def add_parsers(commands) -> None:
    sub = commands.add_parser("list", help="list the built-in robots and their sources",
                              description="List the built-in robots with their joints, convention and source.")
    sub.set_defaults(run=run)


def run(robot, args) -> str:
    names = builtin_names()
    width = max(len(name) for name in names)
    lines = []
    for name in names:
        chain = load(name)
        lines.append(f"{name:<{width}}  {chain.n} joints  {chain.convention:<8}  {chain.name}")
        lines.append(f"{'':<{width}}  source: {chain.source}")
    return "\n".join(lines)
