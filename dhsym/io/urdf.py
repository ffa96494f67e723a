"""URDF files in: the serial chain from a base link to a tip link, as exact joint axes at the
zero configuration and the tip's pose, ready for the frame-assignment algorithm.

The file is decoded, checked and parsed by `xmlsource` (no DOCTYPE, no entities, nothing left for
xacro; see there). Meshes are never opened. Numbers are read exactly as written; an angle that
stands for a multiple of π/12 (1.571, 1.5708: the rule is core.grid's) is read as it, and
directions within 1e-5 of an exact unit vector are snapped to it, with one warning each per file;
numbers below 1e-9 (CAD noise such as -2.67276e-51) become 0, with one warning per file. Angles
that look like degrees (90) or like a cut-off π (3.1415) are kept as written, with the warning a
robot file gets. Only joints on the base → tip path matter: a mimic finger or a floating base
elsewhere in the file is not read.

>>> robot = read_urdf_text(b'''<robot name="arm">
...   <link name="base"/><link name="upper"/><link name="tip"/>
...   <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
...     <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/></joint>
...   <joint name="wrist" type="fixed"><parent link="upper"/><child link="tip"/>
...     <origin xyz="0.25 0 0" rpy="0 1.5708 0"/></joint>
... </robot>''', "arm.urdf")
>>> robot.axes[0].point.T, robot.tool[:3, 3].T
(Matrix([[0, 0, 1/10]]), Matrix([[1/4, 0, 1/10]]))
>>> robot.warnings
['arm.urdf:6:35: angles snapped to the multiples of π/12 they were rounded from: 1.5708 → π/2; this turns any \
frame by at most 3.7e-06 rad']
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import sympy

from ..core.grid import ANGLE_STEP, Snaps, exact_number, snap_angle
from ..core.transforms import rotation
from ..errors import Location, UserError
from ..geometry.exact import LENGTH_NOISE, rational_turn, snap_direction, tidy_vector, vector
from ..geometry.lines import JointAxis
from .suspicious import looks_like_degrees, near_multiple_of_pi
from .urdfinertia import link_bodies
from .urdflimits import path_limits
from .xmlsource import MAX_XML_BYTES, parse_xml_text, read_regular_file

MAX_URDF_BYTES = MAX_XML_BYTES
MAX_MOVING_JOINTS = 24  # as in a robot file
MAX_PATH_JOINTS = 200  # fixed ones included; a humanoid's hand is some 20 joints from its pelvis
MAX_OFF_GRID_TURNS = 64  # rotations through rational cosines on the path: each one lengthens every number
MOVING = {"revolute": "R", "continuous": "R", "prismatic": "P"}
UNSUPPORTED = {"floating": "a floating joint has 6 degrees of freedom", "planar": "a planar joint has 3"}
# What dhsym never reads: a leftover $(find …) in a mesh path or a Gazebo plugin changes nothing.
IGNORED = ("visual", "collision", "inertial", "gazebo", "transmission", "material", "sensor", "ros2_control")
_DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


@dataclass
class UrdfChain:
    """The base→tip chain of a URDF: joint axes (base link coordinates, zero configuration),
    the tip link's pose, the moving joints' names, and the warnings of the reading."""

    name: str
    path: str
    base: str
    tip: str
    axes: list
    tool: sympy.Matrix
    joint_names: list
    warnings: list = field(default_factory=list)
    bodies: list = field(default_factory=list)  # each moving joint's link, merged (io.urdfinertia), or None
    limits: list = field(default_factory=list)  # each moving joint's (lower, upper) or None (io.urdflimits)


def read_urdf(path: str | Path, base: str | None = None, tip: str | None = None) -> UrdfChain:
    """Read a URDF file from disk: a regular file of at most 2 MiB."""
    return read_urdf_text(read_regular_file(path), str(path), base, tip)


def read_urdf_text(data: bytes, filename: str = "<urdf>", base: str | None = None,
                   tip: str | None = None) -> UrdfChain:
    source = parse_xml_text(data, filename)
    source.refuse_substitutions(IGNORED)
    if source.root.tag != "robot":
        raise UserError(f"a URDF file has <robot> at its top, not <{source.root.tag}>", source.place(source.root))
    return _Reader(source).chain(base, tip)


class _Reader:
    """Reads links and joints, checks that they form a tree, and walks the base→tip path."""

    def __init__(self, source):
        self.source, self.root, self.filename = source, source.root, source.filename
        self.warnings: list[str] = []
        self.snaps = Snaps()  # angles read as multiples of π/12 (core.grid)
        self.reach = 0.0  # metres beyond the origin being read: how far a changed angle there moves the tip
        self.free_angles: dict = {}
        self.snapped_directions: list = []
        self.noise: list = []  # (text, place) of numbers below 1e-9 read as 0
        self.first_direction = None
        self.links = {}
        for link in self.root.findall("link"):
            name = self.attribute(link, "name")
            if name in self.links:
                raise UserError(f"link {name!r} is defined twice", self.where(link))
            self.links[name] = link
        if not self.links:
            raise UserError("the URDF has no links", self.where(self.root))
        self.joints = {}  # child link -> joint element
        self.children = {}  # parent link -> child links
        for joint in self.root.findall("joint"):
            self.add_joint(joint)

    def where(self, element, attribute: str | None = None, word: int | None = None) -> Location:
        return self.source.place(element, attribute, word)

    def attribute(self, element, key: str) -> str:
        value = element.get(key)
        if value is None or not value.strip():
            raise UserError(f"<{element.tag}> needs a {key}= attribute", self.where(element))
        return value.strip()

    def link_of(self, joint, role: str) -> str:
        element = joint.find(role)
        if element is None:
            raise UserError(f"joint {joint.get('name')!r} has no <{role}>", self.where(joint))
        name = self.attribute(element, "link")
        if name not in self.links:
            raise UserError(f"joint {joint.get('name')!r}: {role} link {name!r} is not defined",
                            self.where(element, "link"))
        return name

    def add_joint(self, joint) -> None:
        self.attribute(joint, "name")
        parent, child = self.link_of(joint, "parent"), self.link_of(joint, "child")
        if child in self.joints:
            raise UserError(f"link {child!r} is the child of two joints ({self.joints[child].get('name')!r} and "
                            f"{joint.get('name')!r}): a closed loop; dhsym reads serial chains only",
                            self.where(joint))
        self.joints[child] = joint
        self.children.setdefault(parent, []).append(child)

    def chain(self, base: str | None, tip: str | None) -> UrdfChain:
        roots = [name for name in self.links if name not in self.joints]
        if not roots:
            raise UserError("every link has a parent: the joints form a closed loop", self.where(self.root))
        self.check_tree(roots)
        base = base or self.only(roots, "root links", "--base")
        if base not in self.links:
            raise UserError(f"no link {base!r}; the links are {_listed(self.links)}")
        tip = tip or self.only(self.leaves_below(base), f"leaf links below {base!r}", "--tip")
        if tip not in self.links:
            raise UserError(f"no link {tip!r}; the links are {_listed(self.links)}")
        path = self.path(base, tip)
        self.check_size(base, tip, path)
        return self.walk(base, tip, path)

    def check_tree(self, roots: list) -> None:
        """Refuse links that no root reaches: their joints close a loop (urdfdom refuses it too)."""
        reached, waiting = set(roots), list(roots)
        while waiting:
            for child in self.children.get(waiting.pop(), []):
                if child not in reached:
                    reached.add(child)
                    waiting.append(child)
        if len(reached) == len(self.links):
            return
        loop, link = [], next(name for name in self.links if name not in reached)
        while link not in loop:
            loop.append(link)
            link = self.joints[link].find("parent").get("link").strip()
        loop = loop[loop.index(link):]
        loop = [loop[0], *reversed(loop[1:])]  # parent to child, from the first link of the file
        edges = [*loop[1:], loop[0]]
        joints = ", ".join(repr(self.joints[name].get("name")) for name in edges)
        raise UserError(f"joints {joints} close a loop of links ({' → '.join([*loop, loop[0]])}) that no root link "
                        "reaches; the links of a URDF form one tree", self.where(self.joints[edges[0]]))

    def only(self, choices: list, what: str, option: str) -> str:
        if len(choices) == 1:
            return choices[0]
        raise UserError(f"the URDF has {len(choices)} {what} ({_listed(choices)}); choose one with {option}")

    def below(self, link: str) -> list:
        found, seen, waiting = [], set(), [link]
        while waiting:
            current = waiting.pop()
            if current in seen:
                raise UserError(f"link {current!r} is reached twice: a closed loop", self.where(self.links[current]))
            seen.add(current)
            found.append(current)
            waiting.extend(self.children.get(current, []))
        return found

    def leaves_below(self, link: str) -> list:
        return [name for name in self.below(link) if not self.children.get(name)]

    def path(self, base: str, tip: str) -> list:
        """The joints from base to tip."""
        joints, current, seen = [], tip, set()
        while current != base:
            if current not in self.joints or current in seen:
                raise UserError(f"link {tip!r} is not below link {base!r}; choose a tip among "
                                f"{_listed(self.leaves_below(base))}")
            seen.add(current)
            joint = self.joints[current]
            joints.append(joint)
            current = joint.find("parent").get("link").strip()
        return list(reversed(joints))

    def check_size(self, base: str, tip: str, path: list) -> None:
        """Refuse, before any arithmetic, a path with more joints than a table holds or more
        off-grid rotations than exact numbers can carry; name a nearer tip that fits."""
        if len(path) > MAX_PATH_JOINTS:
            nearer = path[MAX_PATH_JOINTS - 1].find("child").get("link").strip()
            raise UserError(f"the path {base} → {tip} has {len(path)} joints, more than the {MAX_PATH_JOINTS} dhsym "
                            f"reads on one path; choose a nearer tip (--tip {nearer})")
        moving = [joint for joint in path if joint.get("type", "").strip() in MOVING]
        if len(moving) > MAX_MOVING_JOINTS:
            nearer = moving[MAX_MOVING_JOINTS - 1].find("child").get("link").strip()
            raise UserError(f"the path {base} → {tip} has {len(moving)} movable joints, more than the "
                            f"{MAX_MOVING_JOINTS} a DH table of dhsym holds; choose a nearer tip (--tip {nearer}) "
                            "or a later base (--base)")
        turns = 0
        for number, joint in enumerate(path):
            origin = joint.find("origin")
            words = (origin.get("rpy") or "").split() if origin is not None else []
            turns += sum(1 for word in words if not _on_grid(word))
            if turns > MAX_OFF_GRID_TURNS:
                nearer = path[max(number - 1, 0)].find("child").get("link").strip()
                raise UserError(f"the path {base} → {tip} turns through more than {MAX_OFF_GRID_TURNS} angles off "
                                f"the π/12 grid, too many to keep exact; choose a nearer tip (--tip {nearer})",
                                self.where(origin, "rpy"))

    def walk(self, base: str, tip: str, path: list) -> UrdfChain:
        pose, axes, names, poses = sympy.eye(4), [], [], {}
        for joint, self.reach in zip(path, _reaches(path)):
            name, kind = joint.get("name").strip(), self.attribute(joint, "type")
            if kind in UNSUPPORTED:
                raise UserError(f"joint {name!r} is {kind}: {UNSUPPORTED[kind]}; dhsym handles revolute, continuous, "
                                "prismatic and fixed joints; choose a --base after it", self.where(joint, "type"))
            if kind not in MOVING and kind != "fixed":
                raise UserError(f"joint {name!r} has unknown type {kind!r}", self.where(joint, "type"))
            mimic = joint.find("mimic")
            if kind != "fixed" and mimic is not None:
                raise UserError(f"joint {name!r} mimics joint {mimic.get('joint')!r} (its value follows that "
                                "joint's), so it has no variable of its own; dhsym needs independent joints on the "
                                "path: choose a --tip before it", self.where(mimic))
            pose = (pose * self.origin(joint, name)).applyfunc(sympy.expand)
            poses[joint.find("child").get("link").strip()] = pose
            if kind == "fixed":
                continue
            direction = tidy_vector(pose[:3, :3] * self.axis(joint))
            axes.append(JointAxis(MOVING[kind], pose[:3, 3], direction, name))
            names.append(name)
        if not axes:
            raise UserError(f"no revolute, continuous or prismatic joint between {base!r} and {tip!r}")
        bodies, limits = link_bodies(self, path, poses), path_limits(self, path)
        self.report()
        robot_name = self.root.get("name") or Path(self.filename).stem
        return UrdfChain(robot_name, self.filename, base, tip, axes, pose, names, self.warnings, bodies, limits)

    def numbers(self, element, key: str, default: str, count: int = 3) -> list:
        """The written numbers of an attribute, exact; noise below 1e-9 is 0 (and remembered)."""
        text = element.get(key, default) if element is not None else default
        values = []
        for word, part in enumerate(text.split()):
            if _DECIMAL.fullmatch(part) and abs(float(part)) < LENGTH_NOISE:
                values.append(sympy.Integer(0))
                if float(part) != 0:
                    self.noise.append((part, self.where(element, key, word)))
                continue
            try:
                values.append(exact_number(part))
            except ValueError as error:
                raise UserError(f"{key}={text!r}: {error}", self.where(element, key, word)) from None
        if len(values) != count:
            raise UserError(f"{key}={text!r} must be {count} numbers, not {len(values)}",
                            self.where(element, key) if element is not None else None)
        return values

    def origin(self, joint, name: str) -> sympy.Matrix:
        """Txyz · Rz(yaw) Ry(pitch) Rx(roll), the URDF origin, exact."""
        element = joint.find("origin")
        xyz = self.numbers(element, "xyz", "0 0 0")
        angles = self.numbers(element, "rpy", "0 0 0")
        words = element.get("rpy").split() if element is not None and element.get("rpy") else ["0"] * 3
        turns = []
        for axis, (value, text) in enumerate(zip(angles, words)):
            turns.append(self.turn(axis, value, text, element))
            if value != 0:
                self.warn_slips(value, text, self.where(element, "rpy", axis), name)
        roll, pitch, yaw = turns
        result = yaw * pitch * roll
        result[:3, 3] = vector(*xyz)
        return result

    def turn(self, axis: int, written: sympy.Rational, text: str, element) -> sympy.Matrix:
        """The rotation by a written angle: exact on the π/12 grid (read as a multiple of π/12 by
        the rule of core.grid), else through a rational cosine and sine (see exact.rational_turn)."""
        value, moved = snap_angle(text) if written != 0 else (written, False)
        if moved:
            self.snaps.add(text, value, self.where(element, "rpy", axis), self.reach)
        if (value / ANGLE_STEP).is_integer:
            return rotation(axis, value)
        self.free_angles.setdefault(text, self.where(element, "rpy", axis))
        cosine, sine = rational_turn(value)
        angle = sympy.Dummy("angle", real=True)
        return rotation(axis, angle).xreplace({sympy.cos(angle): cosine, sympy.sin(angle): sine})

    def warn_slips(self, value: sympy.Rational, text: str, where: Location, name: str) -> None:
        """Degrees (90) and rounded multiples of π (1.57) get the warnings a robot file gets."""
        if looks_like_degrees(value):
            self.warnings.append(f"{where}: joint {name!r} rpy: {text} is taken as radians (URDF angles are in "
                                 f"radians); write {float(sympy.rad(value))!r} if you meant {text}°")
            return
        places = len(text.split(".")[1]) if "." in text and "e" not in text.lower() else 0
        message = near_multiple_of_pi(value, places)
        if message and not snap_angle(text)[1]:
            self.warnings.append(f"{where}: joint {name!r} rpy: {message}")

    def axis(self, joint) -> sympy.Matrix:
        element = joint.find("axis")
        values = self.numbers(element, "xyz", "1 0 0")
        try:
            direction, moved = snap_direction(values)
        except ValueError:
            raise UserError(f"joint {joint.get('name')!r}: the axis has zero length",
                            self.where(element, "xyz") if element is not None else self.where(joint)) from None
        if moved:
            self.snapped_directions.append(" ".join(element.get("xyz").split()))
            self.first_direction = self.first_direction or self.where(element, "xyz")
        return direction

    def report(self) -> None:
        self.warnings[:0] = self.snaps.warnings()
        if self.noise:
            shown = ", ".join(dict.fromkeys(text for text, _ in self.noise[:3]))
            more = f" and {len(self.noise) - 3} more" if len(self.noise) > 3 else ""
            self.warnings.append(f"{self.noise[0][1]}: {shown}{more} taken as 0 (rounding noise below 1e-9)")
        if self.free_angles:
            angles, first = ", ".join(self.free_angles), next(iter(self.free_angles.values()))
            self.warnings.append(f"{first}: angles off the π/12 grid ({angles}) are turned "
                                 "through rational cosines and sines (within 1e-20 rad); table values that depend on "
                                 "them are rounded to 15 significant digits")
        if self.snapped_directions:
            self.warnings.append(f"{self.first_direction}: axis directions snapped to exact unit vectors: "
                                 f"{', '.join(self.snapped_directions)}")


def _on_grid(word: str) -> bool:
    """Whether a written angle is 0 or stands for a multiple of π/12 (core.grid)."""
    try:
        return abs(float(word)) < LENGTH_NOISE or (value := snap_angle(word)[0]) == 0 or (value / ANGLE_STEP).is_integer
    except ValueError:
        return True  # reported with its place when the origin is read


def _reaches(path: list) -> list[float]:
    """For each joint of the path, how far the tip can be from its origin (metres): the lengths
    of the later origins and the travel of this and later prismatic joints (their limits)."""
    reaches, total = [], 0.0
    for joint in reversed(path):
        if joint.get("type", "").strip() == "prismatic":
            total += max((abs(_float(joint.find("limit"), key)) for key in ("lower", "upper")), default=0.0)
        reaches.append(total)
        total += math.hypot(*(_float(joint.find("origin"), "xyz", axis) for axis in range(3)))
    return reaches[::-1]


def _float(element, key: str, word: int = 0) -> float:
    """A number of an attribute as a float, 0 where there is none (errors are reported where the
    number is read exactly)."""
    try:
        value = float((element.get(key) or "").split()[word]) if element is not None else 0.0
    except (ValueError, IndexError):
        return 0.0
    return value if math.isfinite(value) else 0.0


def _listed(names, shown: int = 12) -> str:
    """Names joined by commas, the first `shown` of them and how many more."""
    names = list(names)
    more = f" and {len(names) - shown} more" if len(names) > shown else ""
    return ", ".join(names[:shown]) + more
