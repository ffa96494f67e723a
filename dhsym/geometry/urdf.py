"""URDF files in: the serial chain from a base link to a tip link, as exact joint axes at the
zero configuration and the tip's pose, ready for the frame-assignment algorithm.

The XML is parsed by lxml with entity resolution, DTD loading and network access off, and a
file that declares a DOCTYPE or an entity is refused before parsing (libxml2 would still expand
entities inside attribute values). Meshes are never opened. Numbers are read exactly as written;
angles within 1e-5 rad of a multiple of π/12, and directions within 1e-5 of an exact unit
vector, are snapped to it with a warning; lengths below 1e-9 m are rounding noise and become 0.

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
['arm.urdf:6: angles snapped to exact multiples of π/12 (within 1e-05 rad): 1.5708 → π/2']
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import sympy
from lxml import etree

from ..core.transforms import rotation
from ..errors import Location, UserError
from .exact import (
    ANGLE_STEP,
    ANGLE_TOLERANCE,
    exact_number,
    rational_turn,
    snap_angle,
    snap_direction,
    snap_length,
    tidy_vector,
    vector,
)
from .lines import JointAxis

MAX_URDF_BYTES = 2 << 20
MOVING = {"revolute": "R", "continuous": "R", "prismatic": "P"}
UNSUPPORTED = {"floating": "a floating joint has 6 degrees of freedom", "planar": "a planar joint has 3"}


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


def read_urdf(path: str | Path, base: str | None = None, tip: str | None = None) -> UrdfChain:
    """Read a URDF file from disk, refusing files over 2 MiB."""
    path = Path(path)
    try:
        if path.is_dir():
            raise UserError("is a folder, not a URDF file", Location(str(path)))
        with path.open("rb") as handle:
            data = handle.read(MAX_URDF_BYTES + 1)
    except OSError as exc:
        raise UserError(f"cannot read file: {exc.strerror or exc}", Location(str(path))) from None
    if len(data) > MAX_URDF_BYTES:
        raise UserError(f"file is larger than {MAX_URDF_BYTES >> 20} MiB, the limit for URDF files",
                        Location(str(path), 1, 1))
    return read_urdf_text(data, str(path), base, tip)


def read_urdf_text(data: bytes, filename: str = "<urdf>", base: str | None = None,
                   tip: str | None = None) -> UrdfChain:
    root = _parse_xml(data, filename)
    return _Reader(root, filename).chain(base, tip)


def _parse_xml(data: bytes, filename: str):
    xacro = re.search(rb"xmlns:xacro|<xacro:", data)
    if filename.endswith(".xacro") or xacro:
        line = data[:xacro.start()].count(b"\n") + 1 if xacro else 1
        raise UserError("xacro files are not supported; expand it first (xacro FILE.xacro > FILE.urdf)",
                        Location(filename, line))
    declaration = re.search(rb"<!(DOCTYPE|ENTITY)", data, re.IGNORECASE)
    if declaration:
        line = data[:declaration.start()].count(b"\n") + 1
        column = declaration.start() - (data.rfind(b"\n", 0, declaration.start()) + 1) + 1
        raise UserError("DOCTYPE and entity declarations are not allowed in a URDF file (entities can expand "
                        "without bound)", Location(filename, line, column))
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False,
                             remove_comments=True, remove_pis=True)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as exc:
        line, column = exc.position if exc.position else (None, None)
        raise UserError(f"not well-formed XML: {exc.msg.split(', line')[0]}", Location(filename, line, column)) \
            from None
    if root.tag != "robot":
        raise UserError(f"a URDF file has <robot> at its top, not <{root.tag}>", _place(filename, root))
    return root


def _place(filename: str, element) -> Location:
    return Location(filename, element.sourceline)


class _Reader:
    """Reads links and joints, checks that they form a tree, and walks the base→tip path."""

    def __init__(self, root, filename: str):
        self.root, self.filename = root, filename
        self.warnings: list[str] = []
        self.snapped_angles: dict = {}
        self.free_angles: dict = {}
        self.snapped_directions: list = []
        self.first_snap = None
        self.links = {}
        for link in root.findall("link"):
            name = self.attribute(link, "name")
            if name in self.links:
                raise UserError(f"link {name!r} is defined twice", self.where(link))
            self.links[name] = link
        if not self.links:
            raise UserError("the URDF has no links", self.where(root))
        self.joints = {}  # child link -> joint element
        self.children = {}  # parent link -> child links
        for joint in root.findall("joint"):
            self.add_joint(joint)

    def where(self, element) -> Location:
        return _place(self.filename, element)

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
            raise UserError(f"joint {joint.get('name')!r}: {role} link {name!r} is not defined", self.where(element))
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
        base = base or self.only(roots, "root links", "--base")
        if base not in self.links:
            raise UserError(f"no link {base!r}; the links are {', '.join(self.links)}")
        tip = tip or self.only(self.leaves_below(base), f"leaf links below {base!r}", "--tip")
        if tip not in self.links:
            raise UserError(f"no link {tip!r}; the links are {', '.join(self.links)}")
        path = self.path(base, tip)
        skipped = len(self.below(base)) - len(path) - 1
        if skipped > 0:
            self.warnings.append(f"{self.filename}: ignored {skipped} link{'s' if skipped > 1 else ''} outside the "
                                 f"{base} → {tip} path")
        return self.walk(base, tip, path)

    def only(self, choices: list, what: str, option: str) -> str:
        if len(choices) == 1:
            return choices[0]
        raise UserError(f"the URDF has {len(choices)} {what} ({', '.join(choices)}); choose one with {option}")

    def below(self, link: str) -> list:
        found, waiting = [], [link]
        while waiting:
            current = waiting.pop()
            if current in found:
                raise UserError(f"link {current!r} is reached twice: a closed loop", self.where(self.links[current]))
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
                                f"{', '.join(self.leaves_below(base))}")
            seen.add(current)
            joint = self.joints[current]
            joints.append(joint)
            current = joint.find("parent").get("link").strip()
        return list(reversed(joints))

    def walk(self, base: str, tip: str, path: list) -> UrdfChain:
        pose, axes, names = sympy.eye(4), [], []
        for joint in path:
            name, kind = joint.get("name").strip(), self.attribute(joint, "type")
            if kind in UNSUPPORTED:
                raise UserError(f"joint {name!r} is {kind}: {UNSUPPORTED[kind]}; dhsym handles revolute, continuous, "
                                "prismatic and fixed joints", self.where(joint))
            if kind not in MOVING and kind != "fixed":
                raise UserError(f"joint {name!r} has unknown type {kind!r}", self.where(joint))
            if kind != "fixed" and joint.find("mimic") is not None:
                raise UserError(f"joint {name!r} mimics another joint; dhsym needs independent joint variables",
                                self.where(joint.find("mimic")))
            pose = (pose * self.origin(joint)).applyfunc(sympy.expand)
            if kind == "fixed":
                continue
            direction = tidy_vector(pose[:3, :3] * self.axis(joint))
            axes.append(JointAxis(MOVING[kind], pose[:3, 3], direction, name))
            names.append(name)
        if not axes:
            raise UserError(f"no revolute, continuous or prismatic joint between {base!r} and {tip!r}")
        self.report_snaps()
        robot_name = self.root.get("name") or Path(self.filename).stem
        return UrdfChain(robot_name, self.filename, base, tip, axes, pose, names, self.warnings)

    def numbers(self, element, key: str, default: str, count: int = 3) -> list:
        text = element.get(key, default) if element is not None else default
        parts = text.split()
        try:
            values = [exact_number(part) for part in parts]
        except ValueError as error:
            raise UserError(f"{key}={text!r}: {error}", self.where(element)) from None
        if len(values) != count:
            raise UserError(f"{key}={text!r} must be {count} numbers, not {len(values)}", self.where(element))
        return values

    def origin(self, joint) -> sympy.Matrix:
        """Txyz · Rz(yaw) Ry(pitch) Rx(roll), the URDF origin, exact."""
        element = joint.find("origin")
        self.numbers(element, "xyz", "0 0 0")  # checks the count and the numbers
        self.numbers(element, "rpy", "0 0 0")
        xyz_text, rpy_text = ((element.get(key, "0 0 0") if element is not None else "0 0 0").split()
                              for key in ("xyz", "rpy"))
        roll, pitch, yaw = (self.turn(axis, text, element) for axis, text in enumerate(rpy_text))
        result = yaw * pitch * roll
        result[:3, 3] = vector(*(self.length(text) for text in xyz_text))
        return result

    def turn(self, axis: int, text: str, element) -> sympy.Matrix:
        """The rotation by a written angle: exact on the π/12 grid (snapped there within 1e-5 rad),
        else through a rational cosine and sine (see exact.rational_turn)."""
        value, moved = snap_angle(text)
        if moved:
            self.snapped_angles.setdefault(text, value)
            self.first_snap = element if self.first_snap is None else self.first_snap
        if (value / ANGLE_STEP).is_integer:
            return rotation(axis, value)
        self.free_angles.setdefault(text, None)
        cosine, sine = rational_turn(value)
        angle = sympy.Dummy("angle", real=True)
        return rotation(axis, angle).xreplace({sympy.cos(angle): cosine, sympy.sin(angle): sine})

    def length(self, text: str) -> sympy.Expr:
        value = snap_length(text)
        if value == 0 and exact_number(text) != 0:
            self.warnings.append(f"{self.filename}: length {text} taken as 0 (rounding noise below 1e-9)")
        return value

    def axis(self, joint) -> sympy.Matrix:
        element = joint.find("axis")
        values = self.numbers(element, "xyz", "1 0 0")
        try:
            direction, moved = snap_direction(values)
        except ValueError:
            raise UserError(f"joint {joint.get('name')!r}: the axis has zero length",
                            self.where(element if element is not None else joint)) from None
        if moved:
            self.snapped_directions.append(" ".join(element.get("xyz").split()))
            self.first_snap = element if self.first_snap is None else self.first_snap
        return direction

    def report_snaps(self) -> None:
        where = self.where(self.first_snap) if self.first_snap is not None else Location(self.filename)
        if self.snapped_angles:
            shown = ", ".join(f"{text} → {str(value).replace('pi', 'π')}"
                              for text, value in self.snapped_angles.items())
            self.warnings.insert(0, f"{where}: angles snapped to exact multiples of π/12 (within {ANGLE_TOLERANCE:g} "
                                 f"rad): {shown}")
        if self.free_angles:
            angles = ", ".join(self.free_angles)
            self.warnings.append(f"{self.filename}: angles off the π/12 grid ({angles}) are turned "
                                 "through rational cosines and sines (within 1e-20 rad); table values that depend on "
                                 "them are rounded to 15 significant digits")
        if self.snapped_directions:
            self.warnings.append(f"{where}: axis directions snapped to exact unit vectors: "
                                 f"{', '.join(self.snapped_directions)}")
