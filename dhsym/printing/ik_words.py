"""What the words of a branch's name mean (dhsym.inverse.naming measures which word holds), as the
method line defines them, with this arm's points and axes put in.

>>> from dhsym.inverse.sentences import Point
>>> point_name(Point("meeting", (5, 6)), lambda joint: joint + 1)
'wrist (where axes 6 and 7 meet)'
"""
from __future__ import annotations

ROOT_DEFINITION = "+√/−√: the sign chosen in that joint's formula, where no word about the arm holds at every pose"
DEFINITIONS = {
    "right": "shoulder right/left: seen from above (axis {one} up), the arm's plane lies right/left of the line "
             "from axis {one} to the {wrist}",
    "front": "shoulder front/back: the {wrist} on the side of axis {one} where axis {two} is, or on the other",
    "ahead": "shoulder front/back: the {wrist} on the side of axis {one} that frame {one}'s x axis points to, or "
             "over the back",
    "ahead_end": "shoulder front/back: the end point (the target's origin) on the side of axis {one} that frame "
                 "{one}'s x axis points to, or over the back",
    "up": "elbow up/down: the elbow above/below the line from the shoulder to the {elbow_wrist}",
    "up_out": "elbow up/down: drawn in the arm's plane with axis {one} up and the {elbow_wrist} right of it, the "
              "elbow left/right of the line from the shoulder to the {elbow_wrist} (above/below it where the "
              "{elbow_wrist} is further out than the shoulder)",
    "turned": "elbow up/down: drawn in the arm's plane with axis {one} up and frame {one}'s x axis to the right, the "
              "elbow left/right of the line from the shoulder to the {elbow_wrist} (above/below it where the "
              "point lies ahead of the shoulder)",
    "planar": "elbow up/down: seen from +z{zero} (x{zero} right, y{zero} up), the elbow left/right of the line from "
              "joint {one} to the {planar_wrist} (Spong's +√ of the elbow is down)",
    "lefty": "righty/lefty: seen from above (axis {one} up), the elbow right/left of the line from axis {one} to the "
             "{planar_wrist}",
    "slide": "slide forward/back: along the slide (axis {slide}), the {slide_wrist} on the side of its crossing with "
             "axis {slide_from} that the axis points to, or behind",
    "slide_signed": "slide forward/back: along the slide (axis {slide}), the {slide_wrist} on the side of its crossing "
                    "with axis {slide_from} that the axis points to, or behind, where the slide runs backwards (its "
                    "joint variable < 0: an arm whose slide only extends has the forward branches only)",
    "flip": "wrist not flipped/flipped: seen from the tip of axis {b}'s direction u{b}, axis {c} is turned from "
            "axis {a} counter-clockwise/clockwise (u{a} × u{c} along +u{b}/−u{b})",
}

POINTS = {"wrist centre": "wrist centre", "end point": "end point", "target origin": "end point (the target's origin)",
          "meeting": "wrist (where axes {} and {} meet)", "axis point": "point of axis {} in the arm's plane",
          "wrist point": "wrist point (axis {})"}


def point_name(point, joint) -> str:
    """A Point in words, its axes numbered by `joint` (the chain's joint 1..n -> the number printed)."""
    axes = [joint(axis) for axis in point.axes]
    return POINTS[point.kind].format(*axes)


def meaning_text(meaning, joint, frame) -> str:
    """A Meaning in words; `joint` and `frame` number the chain's joints and frames as printed."""
    if meaning.key == "root":
        return ROOT_DEFINITION
    names = {role: joint(number) for role, number in meaning.joints}
    names |= {role: point_name(point, joint) for role, point in meaning.points}
    return DEFINITIONS[meaning.key].format(zero=frame(0), **names)
