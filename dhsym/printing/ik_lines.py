"""The lines of the IK text: each assignment `θ1 = …` on its own line, a long one broken before a
+ or − or between the arguments of atan2, at the outermost bracket level that leaves a full line.

>>> print(break_value("θ = ", "atan2(a1 s1 + a2 s12, a1 c1 + a2 c12)", 26))
θ = atan2(a1 s1 + a2 s12,
      a1 c1 + a2 c12)
"""
from __future__ import annotations

from . import render


def assignments_text(assignments, printer, width: int) -> str:
    """`  θ1 = …` one to a line, a long one broken before a + or − to fit `width`."""
    names = [printer.doprint(name) for name, _ in assignments]
    label = max(map(render.display_width, names))
    lines = []
    for name, (_, value) in zip(names, assignments, strict=True):
        prefix = "  " + name + " " * (label - render.display_width(name)) + " = "
        lines.append(break_value(prefix, printer.doprint(value), width))
    return "\n".join(lines)


def break_value(prefix: str, text: str, width: int) -> str:
    """`prefix + text` in lines of at most `width` columns where possible: broken before a + or −,
    or after the comma between the arguments of atan2, at the outermost bracket level that leaves
    the rest on one line, else the line at least half full; continuation lines are indented past
    the prefix.

    >>> print(break_value("θ = ", "atan2(a1 s1 + a2 s12, a1 c1 + a2 c12)", 26))
    θ = atan2(a1 s1 + a2 s12,
          a1 c1 + a2 c12)
    """
    indent = " " * (render.display_width(prefix) + 2)
    lines, line, rest = [], prefix, text
    while render.display_width(line + rest) > width:
        room = width - render.display_width(line)
        points = _break_points(rest)
        fitting = [p for p in points if render.display_width(rest[:p[0]]) <= room and p[0] > 0]
        if not fitting:
            if not points:
                break  # one term wider than the line: nothing left to break
            fitting = points[:1]
        last = [p for p in fitting if len(indent) + render.display_width(rest[p[0]:].lstrip()) <= width]
        half = last or [p for p in fitting if render.display_width(rest[:p[0]]) >= room / 2] or fitting
        outermost = min(depth for _, depth in half)
        cut = max(position for position, depth in half if depth == outermost)
        lines.append(line + rest[:cut].rstrip())
        line, rest = indent, rest[cut:].lstrip()
    return "\n".join(lines + [line + rest])


def _break_points(text: str) -> list[tuple[int, float]]:
    """(position, bracket depth) where a line may break: before a binary + or −, after a comma."""
    found, depth = [], 0
    for position, ch in enumerate(text):
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == " " and text[position + 1:position + 3] in ("+ ", "− ", "- "):
            found.append((position, depth))
        elif ch == "," and text[position + 1:position + 2] == " ":
            found.append((position + 1, depth - 0.5))  # between arguments: before a sign inside one
    return found
