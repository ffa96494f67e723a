"""The arm as an SVG picture in pure Python, for the page (no numpy, no matplotlib): the links
through the corners of each DH row, the joints (○ revolute, □ prismatic), the fixed base (▲) and
every frame's x/y/z triad (x red, y green, z blue, as `dhsym plot` draws them), at joint values
set by the page's sliders. The numbers come from core.numeric, the forward kinematics every
picture of dhsym uses; constants take the robot file's `sample` values.

A planar arm is seen from +z0 (x0 right, y0 up), any other from the side and above.

>>> import dhsym
>>> picture = arm_svg(dhsym.load("planar2r"), {"theta_2": 1.5708})
>>> picture.startswith("<svg") and picture.count('class="joint revolute"')
2
>>> [slider["label"] for slider in sliders(dhsym.load("stanford"))][:3]
['θ1', 'θ2', 'd3']
"""
from __future__ import annotations

import math
from html import escape

from ..core.numeric import NumericChain, origin
from ..core.robot import Robot
from ..errors import UserError
from ..printing.notation import display_name

COLOURS = {"x": "#d62728", "y": "#2ca02c", "z": "#1f77b4"}  # as dhsym plot: x red, y green, z blue
VIEWS = {"top": ((1, 0, 0), (0, 1, 0)), "front": ((1, 0, 0), (0, 0, 1)), "side": ((0, 1, 0), (0, 0, 1))}
ELEVATION, AZIMUTH = 25.0, -60.0  # degrees: the 3D view of dhsym plot
TRIAD_FRACTION, STAGGER = 0.14, 0.45  # triad length as a part of the arm's size; frames at one origin differ


def sliders(robot: Robot) -> list[dict]:
    """One slider per joint variable: degrees for a revolute joint, the arm's size either way
    for a prismatic one; each starts at the robot file's sample value, else 0."""
    size = _size_of_constants(robot)
    out = []
    for row, variable in zip(robot.chain.rows, robot.chain.joint_variables):
        start = float(robot.sample.get(variable, 0))
        if row.joint == "R":
            out.append({"name": variable.name, "label": display_name(variable.name, "unicode"), "unit": "°",
                        "min": -180, "max": 180, "step": 1, "value": round(math.degrees(start))})
        else:
            out.append({"name": variable.name, "label": display_name(variable.name, "unicode"), "unit": "",
                        "min": -size, "max": size, "step": size / 100, "value": start})
    return out


def arm_svg(robot: Robot, values: dict, view: str = "auto") -> str:
    """The picture at `values` (joint variable name → radians or length; missing ones are 0)."""
    chain = robot.chain
    numeric = NumericChain(chain, _constants(robot))
    q = [float(values.get(v.name, 0.0)) for v in chain.joint_variables]
    walk = numeric.walk(q)
    zero = 1 if chain.base else 0
    points = [origin(after[-1]) for _, after in walk]
    links = [points[zero]]
    for _, after in walk[zero + 1:zero + 1 + chain.n]:  # through the corner between d and a, as dhsym plot
        links += [origin(after[1] if len(after) > 1 else after[-1]), origin(after[-1])]
    if chain.tool:
        links.append(points[-1])
    poses = [(robot.numbering.frame(frame), after[-1]) for frame, after in walk]
    joints = [(row.joint, point) for row, (point, _) in zip(chain.rows, numeric.axes(q))]
    right, up = _view(view, poses, links, joints)
    return _Picture(right, up, _extent(points + links)).svg(points[:zero + 1], links, joints, poses,
                                                          robot.name)


def _constants(robot: Robot) -> dict:
    constants = set(robot.chain.symbols) - set(robot.chain.joint_variables)
    missing = sorted(s.name for s in constants if s not in robot.sample)
    if missing:
        raise UserError(f"to draw the arm, give a number for {', '.join(missing)} in the robot file's sample, "
                        f"e.g. sample: {{{missing[0]}: 0.5}}")
    return {s: robot.sample[s] for s in constants}


def _size_of_constants(robot: Robot) -> float:
    lengths = [abs(float(value)) for value in robot.sample.values()]
    return round(sum(lengths), 3) or 1.0


def _view(view: str, poses, links, joints) -> tuple:
    if view == "auto":
        flat = all(abs(abs(pose[2][2]) - 1) < 1e-9 for _, pose in poses) and \
            all(abs(p[2]) < 1e-9 * max(1.0, _extent(links)) for p in links) and all(k == "R" for k, _ in joints)
        view = "top" if flat else "3d"
    if view in VIEWS:
        return VIEWS[view]
    if view != "3d":
        raise UserError(f"unknown view {view!r}; views are auto, top, front, side, 3d")
    elevation, azimuth = math.radians(ELEVATION), math.radians(AZIMUTH)
    right = (-math.sin(azimuth), math.cos(azimuth), 0.0)
    up = (-math.sin(elevation) * math.cos(azimuth), -math.sin(elevation) * math.sin(azimuth), math.cos(elevation))
    return right, up


def _extent(points) -> float:
    if not points:
        return 0.0
    return max(max(p[k] for p in points) - min(p[k] for p in points) for k in range(3))


class _Picture:
    """Points projected onto the screen (`right`, `up`), drawn to the arm's size."""

    def __init__(self, right, up, extent: float):
        self.right, self.up = right, up
        self.size = extent or 1.0
        self.triad = TRIAD_FRACTION * self.size

    def at(self, point) -> tuple[float, float]:
        x = sum(a * b for a, b in zip(point, self.right))
        y = sum(a * b for a, b in zip(point, self.up))
        return x, -y  # SVG's y grows downwards

    def svg(self, fixed, links, joints, poses, name: str) -> str:
        body = [self._line(fixed, "ground", "#a0a0a0", ' stroke-dasharray="6 4"')] if len(fixed) > 1 else []
        body += [self._line(links, "link", "#404040")]
        body += [self._fixed(point) for point in fixed]
        body += self._joints(joints)
        body += self._triads(poses)
        shown = [self.at(p) for p in fixed + links + [p for _, p in joints]]
        shown += [self.at(self._tip(pose, axis, 1 + STAGGER * 2)) for _, pose in poses for axis in range(3)]
        pad = 0.08 * self.size
        left, right = min(x for x, _ in shown) - pad, max(x for x, _ in shown) + pad
        top, bottom = min(y for _, y in shown) - pad, max(y for _, y in shown) + pad
        box = f"{left:.4g} {top:.4g} {right - left:.4g} {bottom - top:.4g}"
        return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{box}" role="img" '
                f'font-size="{0.055 * self.size:.4g}" font-family="sans-serif">'
                f"<title>{escape(name)}: links, joints and frames</title>" + "".join(body) + "</svg>")

    def _line(self, points, kind: str, colour: str, dashes: str = "") -> str:
        path = " ".join(f"{x:.5g},{y:.5g}" for x, y in map(self.at, points))
        return (f'<polyline class="{kind}" points="{path}" fill="none" stroke="{colour}" stroke-width="5"{dashes} '
                'stroke-linecap="round" stroke-linejoin="round" vector-effect="non-scaling-stroke"/>')

    def _fixed(self, point) -> str:
        x, y = self.at(point)
        h = 0.05 * self.size
        return (f'<polygon class="fixed" points="{x:.5g},{y:.5g} {x - h:.5g},{y + 1.6 * h:.5g} '
                f'{x + h:.5g},{y + 1.6 * h:.5g}" fill="#a0a0a0" stroke="black" vector-effect="non-scaling-stroke"/>')

    def _joints(self, joints) -> list[str]:
        out, drawn = [], []
        for kind, point in joints:
            inside = sum(math.dist(point, other) < 1e-6 * self.size for other in drawn)  # rings around each other
            drawn.append(point)
            x, y = self.at(point)
            r = (0.025 + 0.015 * inside) * self.size
            shape = (f'<circle class="joint revolute" cx="{x:.5g}" cy="{y:.5g}" r="{r:.4g}"' if kind == "R" else
                     f'<rect class="joint prismatic" x="{x - r:.5g}" y="{y - r:.5g}" width="{2 * r:.4g}" '
                     f'height="{2 * r:.4g}"')
            out.insert(0, shape + ' fill="white" stroke="#404040" stroke-width="2" '
                       'vector-effect="non-scaling-stroke"/>')
        return out

    def _tip(self, pose, axis: int, scale: float) -> list[float]:
        return [pose[r][3] + scale * self.triad * pose[r][axis] for r in range(3)]

    def _triads(self, poses) -> list[str]:
        out, origins = [], []
        for frame, pose in poses:
            here = origin(pose)
            scale = 1 + STAGGER * sum(math.dist(here, other) < 1e-6 * self.size for other in origins)
            origins.append(here)
            x0, y0 = self.at(here)
            for axis, letter in enumerate("xyz"):
                x1, y1 = self.at(self._tip(pose, axis, scale))
                if math.hypot(x1 - x0, y1 - y0) < 1e-3 * self.size:  # seen end on: a dot
                    out.append(f'<circle class="axis {letter}" cx="{x0:.5g}" cy="{y0:.5g}" r="{0.008 * self.size:.4g}" '
                               f'fill="{COLOURS[letter]}"/>')
                    continue
                out.append(f'<line class="axis {letter}" x1="{x0:.5g}" y1="{y0:.5g}" x2="{x1:.5g}" y2="{y1:.5g}" '
                           f'stroke="{COLOURS[letter]}" stroke-width="2" vector-effect="non-scaling-stroke"/>')
                out.append(f'<text x="{x1:.5g}" y="{y1:.5g}" fill="{COLOURS[letter]}" dx="0.2em" dy="0.35em">'
                           f'{letter}<tspan font-size="70%" dy="0.3em">{escape(_frame_name(frame))}</tspan></text>')
        return out


def _frame_name(frame) -> str:
    return {"base": "B", "tool": "T"}.get(frame, str(frame))
