"""Pictures of DH chains: links, joints and the x/y/z triad of every frame, drawn with matplotlib.

Planar arms are drawn in their plane, spatial arms in 3D with equal axis scaling. The numeric
poses come from dhsym.plot.poses (core.numeric's forward kinematics); the package dhsym.plot
gathers what a notebook needs.

>>> from dhsym.io.library import load
>>> ax = draw(load("planar2r"), {"theta_1": "30deg"})
>>> ax.name
'rectilinear'
"""
from __future__ import annotations

import io
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path

import numpy as np
import sympy

from ..core.numbering import Numbering
from ..core.robot import Robot
from ..core.vectors import cross
from ..errors import UserError
from ..io.output import write_atomic
from .labels import Label, place_labels
from .poses import Skeleton, extent, planar_skeletons, resolve_values, skeleton

AXIS_COLOURS = ("#d62728", "#2ca02c", "#1f77b4")  # x red, y green, z blue, as in most textbooks
LINK_COLOUR = "#404040"
GROUND_COLOUR = "#a0a0a0"
CHAIN_COLOURS = ("#404040", "#8c564b", "#9467bd", "#e377c2")
TRIAD_FRACTION = 0.14  # triad length as a part of the arm's extent
STAGGER = 0.45  # frames sharing an origin get triads 1, 1.45, 1.9 ... times longer, so their tips differ
VIEW = {"elev": 25, "azim": -60}
FORMATS = ("png", "pdf", "svg")


# ---------------------------------------------------------------- pictures

def draw(robot: Robot, values=None, ax=None, planar=None, show_frames=True, triad_scale=None, title=None,
         frame_offset=None):
    """Draw one arm: links, joints (○ revolute, □ prismatic) and every frame's x/y/z triad.

    `ax` is an Axes to draw into (a 2D Axes gives the view from above), a Figure to add one
    to, or None for a new pyplot figure. `planar` None decides from the numbers; False forces
    3D. `show_frames`: True (every frame's triad), False (none), or the frames to draw, as
    printed (`[6]`, `["tool"]`, `[4, 5, 6]`: the tool frame alone shows the pose reached, the
    wrist's frames show how the wrist turns). `frame_offset` renumbers the frames in the
    picture: a wrist that a lecture numbers 3..6 is drawn with frame_offset=3 (default: the
    robot's own numbering, from its file's `first_frame`). Returns the Axes.

    >>> from dhsym.io.library import load
    >>> from matplotlib.figure import Figure
    >>> draw(load("planar3r"), {"theta_2": "30deg"}, ax=Figure()).name
    'rectilinear'
    >>> sorted(filter(None, (t.get_text() for t in draw(load("planar2r"), ax=Figure(), show_frames=[2]).texts)))
    ['$x_{2}$', '$y_{2}$']
    """
    if title is None and robot.name:
        title = robot.name + "\n" + _joint_line(robot, values)
    return draw_closed([(robot, values, LINK_COLOUR, None)], ax=ax, planar=planar, show_frames=show_frames,
                       triad_scale=triad_scale, title=title, frame_offset=frame_offset)


def draw_closed(chains_with_values, ax=None, planar=None, show_frames=True, triad_scale=None, title=None,
                frame_offset=None):
    """Draw several robots' chains in one world frame, e.g. the two halves of a parallel mechanism.

    Each item is (robot, values, colour, label); colour and label may be left off or None.
    Every chain starts in the same world frame; its base steps place it. Where the last frames
    of two chains meet (the cut joint) a joint is drawn. With several chains, frame labels
    carry the first letter of the chain's label (x_L1, x_R1). `show_frames` as for `draw`.
    """
    items = [_item(item, k) for k, item in enumerate(chains_with_values)]
    show_frames = _frames_asked(show_frames, items, frame_offset)
    if not items:
        raise UserError("nothing to draw")
    skeletons = [skeleton(robot.chain, resolve_values(robot, values)) for robot, values, _, _ in items]
    points = np.array([p for s in skeletons for p in s.ground + s.links])
    size = extent(points) or 1.0
    ax = _axes(ax, planar if planar is not None else planar_skeletons(skeletons))
    flat = ax.name != "3d"
    for picture, (_, _, colour, label) in zip(skeletons, items, strict=True):
        _draw_links(ax, picture, colour, label, flat)
        _draw_joints(ax, picture.joints, colour, flat, size)
    cuts = _cut_points(skeletons, size)
    _draw_joints(ax, [("R", point) for point in cuts], "black", flat, size)
    _draw_ground(ax, _fixed_points(skeletons, size), flat)
    arrows = []
    if show_frames:
        triads = _Triads(triad_scale or TRIAD_FRACTION * size, size)
        for picture, prefix, (robot, *_) in zip(skeletons, _prefixes([label for *_, label in items]), items,
                                                strict=True):
            numbering = robot.numbering if frame_offset is None else Numbering(frame_offset)
            for frame, pose in picture.poses:
                if _wanted(numbering.frame(frame), show_frames):
                    triads.add(prefix + _frame_name(numbering.frame(frame)), pose)
        arrows = triads.draw(ax, flat)
    _set_limits(ax, np.vstack([points] + [[a.origin, a.tip] for a in arrows]), flat, size, skeletons)
    if title:
        ax.set_title(title, fontsize=10)
    _legend(ax, skeletons, items, bool(cuts), flat)
    segments = [pair for s in skeletons for line in (s.ground, s.links) for pair in pairwise(line)]
    place_labels(ax, [a.label() for a in arrows], [j[1] for s in skeletons for j in s.joints] + cuts,
                  segments + [(a.origin, a.tip) for a in arrows], flat)
    return ax


def save(fig_or_ax, path, inputs=()) -> None:
    """Write the picture (PNG, or PDF/SVG by the file's suffix) atomically; never over `inputs`."""
    figure = fig_or_ax if hasattr(fig_or_ax, "savefig") else fig_or_ax.figure
    buffer = io.BytesIO()
    figure.savefig(buffer, format=picture_format(path), dpi=150, bbox_inches="tight", facecolor="white")
    write_atomic(path, buffer.getvalue(), inputs=inputs)


def picture_format(path) -> str:
    """The picture format a file name asks for (png, pdf or svg), or a UserError.

    >>> picture_format("arm.svg")
    'svg'
    """
    suffix = Path(path).suffix.lower().lstrip(".") or "png"
    if suffix not in FORMATS:
        raise UserError(f"cannot write .{suffix} pictures; use one of {', '.join('.' + f for f in FORMATS)}")
    return suffix


def _item(item, number: int) -> tuple:
    chain, values, colour, label = (tuple(item) + (None, None))[:4]
    return chain, values, colour or CHAIN_COLOURS[number % len(CHAIN_COLOURS)], label


def _prefixes(labels: list) -> list[str]:
    if len(labels) == 1:
        return [""]
    initials = [(label or "")[:1].upper() for label in labels]
    if all(initials) and len(set(initials)) == len(initials):
        return initials
    return [chr(ord("a") + k) for k in range(len(labels))]


def _joint_line(robot: Robot, values) -> str:
    numbers = resolve_values(robot, values)
    parts = []
    for row in robot.chain.rows:
        value = numbers[row.variable]
        shown = f"{np.degrees(value):.4g}°" if row.joint == "R" else f"{value:.4g}"
        parts.append(f"${sympy.latex(row.variable)}$ = {shown.replace('-', '−')}")
    return ",  ".join(parts)


def _axes(ax, planar: bool):
    if ax is not None and hasattr(ax, "add_subplot"):  # a Figure
        return ax.add_subplot(111, **({} if planar else {"projection": "3d"}))
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt  # only here: library users in notebooks want pyplot's figures

    figure = plt.figure(figsize=(6.4, 5.6) if planar else (7.2, 6.8))
    return figure.add_subplot(111, **({} if planar else {"projection": "3d"}))


def _coordinates(points, flat: bool) -> list:
    points = np.asarray(points)
    return [points[:, 0], points[:, 1]] if flat else [points[:, 0], points[:, 1], points[:, 2]]


def _distinct(points, extent: float) -> list:
    kept = []
    for point in points:
        if all(np.linalg.norm(point - other) > 1e-6 * extent for other in kept):
            kept.append(point)
    return kept


def _cut_points(skeletons, extent: float) -> list:
    """Where the last frames of two chains meet: the joint a closed mechanism was cut at."""
    ends = [s.links[-1] for s in skeletons]
    return _distinct([e for k, e in enumerate(ends) if any(np.linalg.norm(e - o) < 1e-6 * extent
                                                           for o in ends[:k] + ends[k + 1:])], extent)


def _fixed_points(skeletons, extent: float) -> list:
    """The first frame and frame 0 of every chain: both are fixed to the ground."""
    return _distinct([p for s in skeletons for p in s.ground + s.links[:1]], extent)


def _draw_links(ax, skeleton: Skeleton, colour: str, label, flat: bool) -> None:
    if skeleton.ground:
        ax.plot(*_coordinates(skeleton.ground, flat), color=GROUND_COLOUR, lw=4, ls=(0, (2, 1.5)),
                zorder=1, gid="ground")
    ax.plot(*_coordinates(skeleton.links, flat), color=colour, lw=5, solid_capstyle="round",
            zorder=2, label=label, gid="links")


def _draw_ground(ax, points: list, flat: bool) -> None:
    from matplotlib.transforms import ScaledTranslation

    below = ax.transData + ScaledTranslation(0, -7 / 72, ax.figure.dpi_scale_trans)  # apex at the point
    for point in points:
        ax.plot(*_coordinates([point], flat), marker="^", ms=13, color=GROUND_COLOUR, mec="black", ls="none",
                zorder=2.5, transform=below, gid="fixed frame")


def _draw_joints(ax, joints: list, colour: str, flat: bool, extent: float) -> None:
    """Joints at one point are drawn as rings around each other, so each of them shows."""
    drawn = []
    for kind, point in joints:
        inside = sum(np.linalg.norm(point - other) < 1e-6 * extent for other in drawn)
        drawn.append(point)
        ax.plot(*_coordinates([point], flat), marker="o" if kind == "R" else "s", ms=12 + 7 * inside,
                mfc="white", mec=colour, mew=2, ls="none", zorder=3 - 0.1 * inside, gid=f"{kind} joint")


def _frames_asked(show_frames, items, frame_offset):
    """True, False, or the printed frames to draw (one name alone is a list of one), each checked."""
    if isinstance(show_frames, bool):
        return show_frames
    asked = [show_frames] if isinstance(show_frames, (str, int)) else list(show_frames)
    printed = []
    for robot, *_ in items:
        numbering = robot.numbering if frame_offset is None else Numbering(frame_offset)
        printed += [str(f) for f in numbering.frames(robot.chain) if str(f) not in printed]
    for frame in asked:
        if str(frame) not in printed:
            raise UserError(f"no frame {frame} to draw; the frames are {', '.join(printed)}")
    return asked


def _wanted(printed, show_frames) -> bool:
    """Whether the frame printed as `printed` gets a triad: `show_frames` is True or lists it."""
    if show_frames is True:
        return True
    return any(str(printed) == str(frame) for frame in show_frames)


def _frame_name(printed) -> str:
    """A frame's label in a picture: its printed number, B for the base, T for the tool."""
    return {"base": "B", "tool": "T"}.get(printed, str(printed))


@dataclass
class _Arrow:
    """One frame axis as drawn: several frames at one origin with one axis the same way share it."""

    letter: str
    origin: np.ndarray
    direction: np.ndarray
    length: float
    frames: list

    @property
    def tip(self) -> np.ndarray:
        return self.origin + self.length * self.direction

    @property
    def colour(self) -> str:
        return AXIS_COLOURS["xyz".index(self.letter)]

    def label(self) -> Label:
        return Label(f"${self.letter}_{{{','.join(self.frames)}}}$", self.tip, self.direction, self.colour)


class _Triads:
    """The x/y/z axes of every frame, merged where frames share an origin and an axis."""

    def __init__(self, scale: float, extent: float):
        self.scale, self.extent = scale, extent
        self.arrows: list[_Arrow] = []

    def add(self, frame: str, pose: np.ndarray) -> None:
        origin = pose[:3, 3]
        for axis, letter in enumerate("xyz"):
            direction = pose[:3, axis]
            here = [a for a in self.arrows if np.linalg.norm(a.origin - origin) < 1e-6 * self.extent
                    and np.dot(a.direction, direction) > 1 - 1e-9]
            same = [a for a in here if a.letter == letter]
            if same:
                same[0].frames.append(frame)
            else:  # another letter along the same line: longer, so both colours show
                self.arrows.append(_Arrow(letter, origin, direction, self.scale * (1 + STAGGER * len(here)), [frame]))

    def draw(self, ax, flat: bool) -> list[_Arrow]:
        drawn = []
        for arrow in self.arrows:
            gid = f"{arrow.letter} axis of frame {','.join(arrow.frames)}"
            origin, direction = arrow.origin, arrow.direction
            if flat and np.linalg.norm(direction[:2]) < 0.2:  # along ±z: seen end-on, ⊙ or ⊗
                toward = direction[2] > 0
                ax.plot(origin[0], origin[1], marker="o", ms=8, color=arrow.colour, mfc="white", mew=1.5,
                        zorder=5, gid=gid)
                ax.plot(origin[0], origin[1], marker="." if toward else "x", ms=6 if toward else 5,
                        color=arrow.colour, mew=1.5, zorder=5.5, gid=gid)
                continue
            if flat and arrow.letter == "z":
                continue  # a tilted z seen from above: x and y already fix the frame
            if flat:
                ax.annotate("", xy=arrow.tip[:2], xytext=origin[:2], zorder=4, gid=gid,
                            arrowprops={"arrowstyle": "-|>,head_length=0.5,head_width=0.22", "color": arrow.colour,
                                        "lw": 1.6, "shrinkA": 0, "shrinkB": 0})
            else:
                ax.quiver(*origin, *(arrow.length * direction), color=arrow.colour, lw=1.6,
                          arrow_length_ratio=0.22 * self.scale / arrow.length, zorder=4, gid=gid)
            drawn.append(arrow)
        return drawn


def _set_limits(ax, points: np.ndarray, flat: bool, extent: float, skeletons) -> None:
    low, high = points.min(axis=0), points.max(axis=0)
    centre = (low + high) / 2
    if flat:
        spans = (high - low)[:2] / 2 + 0.1 * extent
        ax.set_xlim(centre[0] - spans[0], centre[0] + spans[0])
        ax.set_ylim(centre[1] - spans[1], centre[1] + spans[1])
        ax.set_aspect("equal", adjustable="box")
        ax.grid(True, color="#e6e6e6", lw=0.8, zorder=0)
        ax.set_axisbelow(True)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        return
    half = np.max(high - low) / 2 + 0.05 * extent
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.computed_zorder = False  # keep frames drawn over links whatever the depth
    segments = [(a, b) for s in skeletons for line in (s.ground, s.links) for a, b in pairwise(line)]
    ax.view_init(elev=VIEW["elev"], azim=_best_azimuth(segments))
    for name in "xyz":
        getattr(ax, f"set_{name}label")(name)
    ax.tick_params(labelsize=7)


def _best_azimuth(segments) -> float:
    """The azimuth from which the links look longest, preferring the usual -60° on near ties."""
    def seen_length(azimuth: float) -> float:
        elevation, azimuth = np.radians(VIEW["elev"]), np.radians(azimuth)
        view = np.array([np.cos(elevation) * np.cos(azimuth), np.cos(elevation) * np.sin(azimuth), np.sin(elevation)])
        return sum(np.linalg.norm(cross(b - a, view)) for a, b in segments)

    candidates = range(-120, -29, 15)  # from the front right: x toward the viewer, y to the right, z up
    best = max(seen_length(a) for a in candidates)
    good = [a for a in candidates if seen_length(a) >= 0.9 * best]
    return float(min(good, key=lambda a: abs(a - VIEW["azim"])))


def _legend(ax, skeletons, items, cut: bool, flat: bool) -> None:
    from matplotlib.lines import Line2D

    handles = list(ax.get_legend_handles_labels()[0])
    kinds = {kind for s in skeletons for kind, _ in s.joints}
    for kind, marker, text in (("R", "o", "revolute joint"), ("P", "s", "prismatic joint")):
        if kind in kinds:
            handles.append(Line2D([], [], marker=marker, ms=9, mfc="white", mec=LINK_COLOUR, mew=2, ls="none",
                                  label=text))
    if cut:
        handles.append(Line2D([], [], marker="o", ms=9, mfc="white", mec="black", mew=2, ls="none",
                              label="cut joint (loop closes)"))
    handles.append(Line2D([], [], marker="^", ms=9, color=GROUND_COLOUR, mec="black", ls="none", label="fixed"))
    place = {"loc": "upper left"} if not flat else {"loc": "upper left", "bbox_to_anchor": (1.02, 1)}
    ax.legend(handles=handles, fontsize=8, framealpha=0.85, **place)
