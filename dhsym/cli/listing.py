"""`dhsym list`: the built-in robots with their joints, convention and source."""
from __future__ import annotations

from ..io.library import builtin_names, load


def add_parsers(commands) -> None:
    sub = commands.add_parser("list", help="list the built-in robots and their sources",
                              description="List the built-in robots with their joints, convention and source.")
    sub.set_defaults(run=run)


def run(robot: None, args) -> str:
    names = builtin_names()
    width = max(len(name) for name in names)
    lines = []
    for name in names:
        robot = load(name)
        lines.append(f"{name:<{width}}  {robot.chain.n} joints  {robot.chain.convention:<8}  {robot.name}")
        lines.append(f"{'':<{width}}  source: {robot.source}")
    return "\n".join(lines)
