"""Pictures of DH chains: links, joints and the x/y/z triad of every frame, drawn with matplotlib.

Planar arms are drawn in their plane, spatial arms in 3D with equal axis scaling. The
numbers come from the same DH steps the algebra uses, so a picture is the formula evaluated.

>>> from dhsym.library import load
>>> poses = frame_poses(load("planar2r"), {"theta_1": 0, "theta_2": sympy.pi / 2})
>>> [(frame, pose[:2, 3].round(3).tolist()) for frame, pose in poses]
[(0, [0.0, 0.0]), (1, [0.5, 0.0]), (2, [0.5, 0.4])]
"""
from __future__ import annotations

import io
import re
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path

import numpy as np
import sympy

from .chain import Chain
from .errors import UserError
from .expr import parse_expression
from .output import write_atomic
from .robotfile import Robot

AXIS_COLOURS = ("#d62728", "#2ca02c", "#1f77b4")  # x red, y green, z blue, as in most textbooks
LINK_COLOUR = "#404040"
GROUND_COLOUR = "#a0a0a0"
CHAIN_COLOURS = ("#404040", "#8c564b", "#9467bd", "#e377c2")
TRIAD_FRACTION = 0.14  # triad length as a part of the arm's extent
STAGGER = 0.45  # frames sharing an origin get triads 1, 1.45, 1.9 ... times longer, so their tips differ
VIEW = {"elev": 25, "azim": -60}
FORMATS = ("png", "pdf", "svg")


# ---------------------------------------------------------------- numbers

def frame_poses(robot_or_chain, values=None) -> list[tuple]:
    """The numeric 4×4 pose of every frame (base, 0..n, tool as present) in the first frame.

    `values` maps symbols or their names to numbers (or to expression text such as "30deg").
    Missing constants come from the robot file's `sample`, missing joint variables are 0.

    >>> from dhsym.library import load
    >>> [f for f, _ in frame_poses(load("fourbar_right"), {"phi_1": 0})]
    ['base', 0, 1, 'tool']
    """
    return _skeleton(robot_or_chain, values).poses


def resolve_values(robot_or_chain, values=None) -> dict:
    """Every symbol of the chain mapped to a float: given, else sample (constants) or 0 (joints).

    >>> from dhsym.library import load
    >>> sorted((s.name, v) for s, v in resolve_values(load("planar2r"), {"theta_1": "90deg"}).items())
    [('a_1', 0.5), ('a_2', 0.4), ('theta_1', 1.5707963267948966), ('theta_2', 0.0)]
    """
    chain, sample = _chain_and_sample(robot_or_chain)
    symbols = {s.name: s for s in _symbols(chain)}
    given = {}
    for key, value in (values or {}).items():
        name = key.name if isinstance(key, sympy.Symbol) else str(key)
        if name not in symbols:
            raise UserError(f"{name} is not a symbol of this robot; its symbols are {', '.join(sorted(symbols))}")
        given[name] = _number(value, name)
    sample = {str(symbol): value for symbol, value in sample.items()}
    variables = {v.name for v in chain.joint_variables}
    resolved, missing = {}, []
    for name, symbol in symbols.items():
        if name in given:
            resolved[symbol] = given[name]
        elif name in variables:
            resolved[symbol] = 0.0
        elif name in sample:
            resolved[symbol] = _number(sample[name], name)
        else:
            missing.append(name)
    if missing:
        raise UserError(f"no value for {', '.join(sorted(missing))}; give a number for each "
                        "(the robot file's sample does not have one)")
    return resolved


def close_loop(first, second, known: dict, unknowns, guess=None, tolerance=1e-10) -> tuple[dict, dict]:
    """Values of `unknowns` that bring the last frame origins of two chains together.

    A closed mechanism cut at a revolute joint gives two chains from one fixed frame (their base
    steps place them); closing the loop means both cut ends meet. Solved by Gauss-Newton from
    `guess` (default 0.5 for every unknown; another guess finds another assembly branch).
    Returns the full values of each chain, ready for `draw_closed`.

    >>> from dhsym.library import load
    >>> left, right = close_loop(load("fourbar_left"), load("fourbar_right"), {"phi_1": sympy.pi / 2},
    ...                          ["theta_1", "phi_2"])
    >>> round(float(np.degrees(left[sympy.Symbol("theta_1", real=True)])), 1)  # the other branch: 59.9
    11.1
    """
    names = [u.name if isinstance(u, sympy.Symbol) else str(u) for u in unknowns]
    guess = {(k.name if isinstance(k, sympy.Symbol) else str(k)): _number(v, str(k)) for k, v in (guess or {}).items()}
    known = {(k.name if isinstance(k, sympy.Symbol) else str(k)): v for k, v in known.items()}
    own = [{s.name for s in _symbols(_chain_and_sample(c)[0])} for c in (first, second)]
    strangers = [n for n in list(known) + names if not any(n in symbols for symbols in own)]
    if strangers:
        raise UserError(f"{', '.join(strangers)} belong to neither chain")
    unknown_values = np.array([guess.get(n, 0.5) for n in names], dtype=float)

    def gap(x):
        given = {**known, **dict(zip(names, x, strict=True))}
        ends = [frame_poses(chain, {n: v for n, v in given.items() if n in symbols})[-1][1][:3, 3]
                for chain, symbols in zip((first, second), own, strict=True)]
        return ends[0] - ends[1]

    for _ in range(60):
        residual = gap(unknown_values)
        if np.linalg.norm(residual) < tolerance:
            break
        step = 1e-7
        jacobian = np.column_stack([(gap(unknown_values + step * e) - gap(unknown_values - step * e)) / (2 * step)
                                    for e in np.eye(len(names))])
        unknown_values = unknown_values + np.linalg.lstsq(jacobian, -residual, rcond=None)[0]
    if np.linalg.norm(gap(unknown_values)) > 1e3 * tolerance:
        raise UserError(f"the loop does not close for these values (gap {np.linalg.norm(gap(unknown_values)):.3g}); "
                        "the mechanism cannot be assembled there, or try another guess")
    solved = {**known, **dict(zip(names, unknown_values.tolist(), strict=True))}
    return tuple(resolve_values(chain, {n: v for n, v in solved.items() if n in symbols})
                 for chain, symbols in zip((first, second), own, strict=True))


def _chain_and_sample(robot_or_chain) -> tuple[Chain, dict]:
    if isinstance(robot_or_chain, Robot):
        return robot_or_chain.chain, robot_or_chain.sample
    if isinstance(robot_or_chain, Chain):
        return robot_or_chain, {}
    raise TypeError(f"expected a Robot or a Chain, not {type(robot_or_chain).__name__}")


def _symbols(chain: Chain) -> set:
    fields = [e for row in chain.rows for e in (row.theta, row.d, row.a, row.alpha)]
    fields += [step.value for step in chain.base + chain.tool]
    return set().union(*(sympy.sympify(e).free_symbols for e in fields)) | set(chain.joint_variables)


def _number(value, name: str) -> float:
    if isinstance(value, str):
        value = parse_expression(value)
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise UserError(f"value of {name} must be a number, not {value}") from None
    if not np.isfinite(number):
        raise UserError(f"value of {name} must be a finite number")
    return number


def _step_matrix(kind: str, value: float) -> np.ndarray:
    matrix = np.eye(4)
    axis = "xyz".index(kind[1])
    if kind[0] == "T":
        matrix[axis, 3] = value
        return matrix
    i, j = ((1, 2), (2, 0), (0, 1))[axis]  # the plane turned by a rotation about x, y, z
    c, s = np.cos(value), np.sin(value)
    matrix[i, i], matrix[i, j], matrix[j, i], matrix[j, j] = c, -s, s, c
    return matrix


@dataclass
class _Skeleton:
    """What a picture needs: frame poses, the link polyline and where the joints are."""

    poses: list  # (frame, 4×4 pose)
    ground: list  # points from the first frame to frame 0 (the fixed base steps)
    links: list  # points from frame 0 to the last frame, through the corner between d and a
    joints: list  # (kind "R" or "P", point)


def _skeleton(robot_or_chain, values) -> _Skeleton:
    chain, _ = _chain_and_sample(robot_or_chain)
    numbers = resolve_values(robot_or_chain, values)
    pose = np.eye(4)

    def move(steps) -> list:
        nonlocal pose
        points = []
        for step in steps:
            pose = pose @ _step_matrix(step.kind, float(sympy.sympify(step.value).xreplace(numbers)))
            points.append(pose[:3, 3].copy())
        return points

    poses, ground, links, joints = [], [pose[:3, 3].copy()], [], []
    if chain.base:
        poses.append(("base", pose.copy()))
        move(chain.base)
        ground.append(pose[:3, 3].copy())
    poses.append((0, pose.copy()))
    links.append(pose[:3, 3].copy())
    for number, row in enumerate(chain.rows, 1):
        if chain.convention == "standard":  # joint i turns about z_{i-1}
            joints.append((row.joint, pose[:3, 3].copy()))
        # the corner after Tz(d) (standard) or Tx(a) (modified): a row with both d and a bends there
        corner = move(row.steps(chain.convention))[1]
        links.extend([corner, pose[:3, 3].copy()])
        if chain.convention == "modified":  # joint i turns about z_i
            joints.append((row.joint, pose[:3, 3].copy()))
        poses.append((number, pose.copy()))
    if chain.tool:
        move(chain.tool)
        links.append(pose[:3, 3].copy())
        poses.append(("tool", pose.copy()))
    return _Skeleton(poses, ground if chain.base else [], _without_repeats(links), joints)


def _without_repeats(points: list) -> list:
    kept = [points[0]]
    for point in points[1:]:
        if np.linalg.norm(point - kept[-1]) > 1e-12:
            kept.append(point)
    return kept


def is_planar(robot_or_chain, values=None) -> bool:
    """True when every z axis is parallel to the first frame's z, all points lie in one plane
    normal to it, and no joint is prismatic (a prismatic joint would leave the plane).

    >>> from dhsym.library import load
    >>> is_planar(load("planar3r")), is_planar(load("scara")), is_planar(load("puma560"))
    (True, False, False)
    """
    return _planar([_skeleton(robot_or_chain, values)])


def _planar(skeletons) -> bool:
    points = np.array([p for s in skeletons for p in s.ground + s.links])
    tolerance = 1e-9 * max(1.0, _extent(points))
    return all(
        abs(abs(pose[2, 2]) - 1) < 1e-9 for s in skeletons for _, pose in s.poses
    ) and np.ptp(points[:, 2]) < tolerance and all(kind == "R" for s in skeletons for kind, _ in s.joints)


def _extent(points: np.ndarray) -> float:
    return float(np.max(np.ptp(points, axis=0))) if len(points) else 0.0


# ---------------------------------------------------------------- pictures

@dataclass
class _Label:
    text: str
    anchor: np.ndarray  # a point in the world frame
    direction: np.ndarray  # where the label prefers to sit, as a world direction from the anchor
    colour: str


def draw(robot, values=None, ax=None, planar=None, show_frames=True, triad_scale=None, title=None):
    """Draw one arm: links, joints (○ revolute, □ prismatic) and every frame's x/y/z triad.

    `ax` is an Axes to draw into (a 2D Axes gives the view from above), a Figure to add one
    to, or None for a new pyplot figure. `planar` None decides from the numbers; False forces
    3D. Returns the Axes.

    >>> from dhsym.library import load
    >>> from matplotlib.figure import Figure
    >>> draw(load("planar3r"), {"theta_2": "30deg"}, ax=Figure()).name
    'rectilinear'
    """
    if title is None and isinstance(robot, Robot):
        title = robot.name + "\n" + _joint_line(robot, values)
    return draw_closed([(robot, values, LINK_COLOUR, None)], ax=ax, planar=planar,
                       show_frames=show_frames, triad_scale=triad_scale, title=title)


def draw_closed(chains_with_values, ax=None, planar=None, show_frames=True, triad_scale=None, title=None):
    """Draw several chains in one world frame, e.g. the two halves of a parallel mechanism.

    Each item is (robot, values, colour, label); colour and label may be left off or None.
    Every chain starts in the same world frame; its base steps place it. Where the last frames
    of two chains meet (the cut joint) a joint is drawn. With several chains, frame labels
    carry the first letter of the chain's label (x_L1, x_R1).
    """
    items = [_item(item, k) for k, item in enumerate(chains_with_values)]
    if not items:
        raise UserError("nothing to draw")
    skeletons = [_skeleton(robot, values) for robot, values, _, _ in items]
    points = np.array([p for s in skeletons for p in s.ground + s.links])
    extent = _extent(points) or 1.0
    ax = _axes(ax, planar if planar is not None else _planar(skeletons))
    flat = ax.name != "3d"
    for skeleton, (_, _, colour, label) in zip(skeletons, items, strict=True):
        _draw_links(ax, skeleton, colour, label, flat)
        _draw_joints(ax, skeleton.joints, colour, flat, extent)
    cuts = _cut_points(skeletons, extent)
    _draw_joints(ax, [("R", point) for point in cuts], "black", flat, extent)
    _draw_ground(ax, _fixed_points(skeletons, extent), flat)
    arrows = []
    if show_frames:
        triads = _Triads(triad_scale or TRIAD_FRACTION * extent, extent)
        for skeleton, prefix in zip(skeletons, _prefixes([label for _, _, _, label in items]), strict=True):
            for frame, pose in skeleton.poses:
                triads.add(prefix + _frame_name(frame), pose)
        arrows = triads.draw(ax, flat)
    _set_limits(ax, np.vstack([points] + [[a.origin, a.tip] for a in arrows]), flat, extent, skeletons)
    if title:
        ax.set_title(title, fontsize=10)
    _legend(ax, skeletons, items, bool(cuts), flat)
    segments = [pair for s in skeletons for line in (s.ground, s.links) for pair in pairwise(line)]
    _place_labels(ax, [a.label() for a in arrows], [j[1] for s in skeletons for j in s.joints] + cuts,
                  segments + [(a.origin, a.tip) for a in arrows], flat)
    return ax


def save(fig_or_ax, path, inputs=()) -> None:
    """Write the picture (PNG, or PDF/SVG by the file's suffix) atomically; never over `inputs`."""
    figure = fig_or_ax if hasattr(fig_or_ax, "savefig") else fig_or_ax.figure
    buffer = io.BytesIO()
    figure.savefig(buffer, format=_format(path), dpi=150, bbox_inches="tight", facecolor="white")
    write_atomic(path, buffer.getvalue(), inputs=inputs)


def _format(path) -> str:
    suffix = Path(path).suffix.lower().lstrip(".") or "png"
    if suffix not in FORMATS:
        raise UserError(f"cannot write .{suffix} pictures; use one of {', '.join('.' + f for f in FORMATS)}")
    return suffix


def _item(item, number: int) -> tuple:
    robot, values, colour, label = (tuple(item) + (None, None))[:4]
    return robot, values, colour or CHAIN_COLOURS[number % len(CHAIN_COLOURS)], label


def _prefixes(labels: list) -> list[str]:
    if len(labels) == 1:
        return [""]
    initials = [(label or "")[:1].upper() for label in labels]
    if all(initials) and len(set(initials)) == len(initials):
        return initials
    return [chr(ord("a") + k) for k in range(len(labels))]


def _joint_line(robot, values) -> str:
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


def _draw_links(ax, skeleton: _Skeleton, colour: str, label, flat: bool) -> None:
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


def _frame_name(frame) -> str:
    return {"base": "B", "tool": "T"}.get(frame, str(frame))


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

    def label(self) -> _Label:
        return _Label(f"${self.letter}_{{{','.join(self.frames)}}}$", self.tip, self.direction, self.colour)


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
        return sum(np.linalg.norm(np.cross(b - a, view)) for a, b in segments)

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


def _place_labels(ax, labels: list[_Label], points: list, segments: list, flat: bool) -> None:
    """Put each axis label beside its tip where it covers the fewest labels, joints and lines."""
    if not labels:
        return
    from matplotlib.transforms import ScaledTranslation

    figure = ax.figure
    figure.draw_without_rendering()  # fixes the 3D projection and the axes' place on the figure
    to_display = _projector(ax, flat)
    pixel = figure.dpi / 72  # display pixels per point
    taken = [(_box(to_display(p), 6 * pixel, 6 * pixel), 1.0) for p in points]
    for start, end in segments:
        a, b = to_display(start), to_display(end)
        for t in np.linspace(0, 1, max(2, int(np.linalg.norm(b - a) / (4 * pixel)))):
            taken.append((_box(a + t * (b - a), 2.5 * pixel, 2.5 * pixel), 0.3))
    for label in labels:
        text = ax.text(*(label.anchor[:2] if flat else label.anchor), label.text, color=label.colour, fontsize=9,
                       ha="center", va="center", zorder=7,
                       bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
        size = text.get_window_extent()
        half = np.array([size.width, size.height]) / 2 + pixel
        anchor = to_display(label.anchor)
        heading = to_display(label.anchor + 1e-3 * label.direction) - anchor
        heading = heading / np.linalg.norm(heading) if np.linalg.norm(heading) > 1e-12 else np.array([0.7, 0.7])
        best, best_cost = None, np.inf
        for gap in (2, 6, 11, 17):
            for turn in (0, 35, -35, 70, -70, 110, -110, 145, -145, 180):
                angle = np.radians(turn)
                way = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]) @ heading
                reach = min(half[0] / max(abs(way[0]), 1e-9), half[1] / max(abs(way[1]), 1e-9))
                centre = anchor + way * (reach + gap * pixel)
                box = _box(centre, *half)
                cost = sum(weight * _overlap(box, other) for other, weight in taken) + 0.5 * abs(turn) + 3 * gap
                if cost < best_cost:
                    best, best_cost = (centre, box), cost
        centre, box = best
        taken.append((box, 1.0))
        shift = (centre - anchor) / figure.dpi
        text.set_transform(ax.transData + ScaledTranslation(shift[0], shift[1], figure.dpi_scale_trans))


def _projector(ax, flat: bool):
    if flat:
        return lambda point: ax.transData.transform(np.asarray(point)[:2])
    from mpl_toolkits.mplot3d import proj3d

    projection = ax.get_proj()

    def to_display(point):
        x, y, _ = proj3d.proj_transform(point[0], point[1], point[2], projection)
        return ax.transData.transform((x, y))

    return to_display


def _box(centre, half_width: float, half_height: float) -> tuple:
    return (centre[0] - half_width, centre[1] - half_height, centre[0] + half_width, centre[1] + half_height)


def _overlap(a: tuple, b: tuple) -> float:
    width = min(a[2], b[2]) - max(a[0], b[0])
    height = min(a[3], b[3]) - max(a[1], b[1])
    return width * height if width > 0 and height > 0 else 0.0


# ---------------------------------------------------------------- the `dhsym plot` command

NAME = "plot"
_ASSIGNMENT = re.compile(r"\s*([^\W\d]\w*)\s*=(.*)\Z", re.DOTALL)


def add_parser(commands) -> None:
    from . import cli  # cli imports this module, so not at the top

    sub = commands.add_parser(NAME, help="draw the arm (links, joints, frames) as a PNG",
                              description="Draw the arm with every DH frame as an x/y/z triad (x red, y green, "
                              "z blue). Constants default to the robot file's sample values, joint variables to 0. "
                              "Planar arms are drawn in their plane, others in 3D.")
    sub.add_argument("robot", metavar="ROBOT", help="built-in robot name or path to a robot YAML file")
    sub.add_argument("--set", dest="constants", metavar="NAME=EXPR", nargs="+", action="extend", default=[],
                     help="value of a constant, e.g. --set l_1=0.5 l_2=1/3")
    sub.add_argument("--q", dest="joints", metavar="NAME=EXPR", nargs="+", action="extend", default=[],
                     help="value of a joint variable, e.g. --q theta_1=30deg d_3=0.2 (default 0)")
    sub.add_argument("-o", "--output", metavar="FILE", help="picture to write (.png, .pdf or .svg; default ROBOT.png)")
    sub.add_argument("--no-frames", action="store_true", help="draw links and joints only")
    sub.add_argument("--3d", dest="three_d", action="store_true", help="3D even when the arm is planar")
    cli.add_common_options(sub)


def run(robot, args) -> str:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    values = {**parse_assignments(robot, args.constants, "--set"), **parse_assignments(robot, args.joints, "--q")}
    path = args.output or f"{Path(args.robot).stem}.png"
    _format(path)  # a wrong suffix is found before any drawing
    planar = False if args.three_d else None
    figure = Figure(figsize=(6.4, 5.6) if (planar is None and is_planar(robot, values)) else (7.2, 6.8))
    FigureCanvasAgg(figure)
    draw(robot, values, ax=figure, planar=planar, show_frames=not args.no_frames)
    save(figure, path, inputs=[robot.path])
    return str(path)


def parse_assignments(robot, texts, option: str) -> dict:
    """`NAME=EXPR` texts to {name: exact value}; --q takes joint variables, --set constants.

    >>> from dhsym.library import load
    >>> parse_assignments(load("planar2r"), ["theta_1=30deg"], "--q")
    {'theta_1': pi/6}
    """
    symbols = sorted(s.name for s in _symbols(robot.chain))
    variables = {v.name for v in robot.chain.joint_variables}
    values = {}
    for text in texts:
        match = _ASSIGNMENT.match(text)
        if not match:
            raise UserError(f"{option} {text!r}: expected NAME=EXPR, e.g. {option} "
                            f"{'theta_1=30deg' if option == '--q' else 'l_1=0.5'}")
        name, expression = match.group(1), match.group(2)
        if name not in symbols:
            raise UserError(f"{option} {text!r}: {robot.name} has no symbol {name}; its symbols are "
                            f"{', '.join(symbols)}")
        wanted = option == "--q"
        if (name in variables) != wanted:
            kind = "a joint variable; use --q" if name in variables else "a constant; use --set"
            raise UserError(f"{option} {text!r}: {name} is {kind}")
        try:
            value = parse_expression(expression)
        except UserError as error:
            raise UserError(f"{option} {text!r}: {error.message}") from None
        if value.free_symbols:
            raise UserError(f"{option} {text!r}: the value must be a number, not an expression in "
                            f"{', '.join(sorted(map(str, value.free_symbols)))}")
        values[name] = value
    return values
