"""Robot files: YAML in, a validated `Robot` out, with every mistake placed at FILE:LINE:COL.

The YAML is composed with the safe loader into nodes (which keep their line and column)
and read by hand: no Python objects are ever constructed from tags, and aliases are refused.

>>> robot = load_robot_text('''
... name: two-link arm
... convention: standard
... joints:
...   - {joint: R, alpha: 0, a: l_1, d: 0, theta: theta_1}
...   - {joint: R, alpha: 0, a: l_2, d: 0, theta: theta_2}
... ''', "arm.yaml")
>>> robot.chain.fk()[0, 3]
l_1*cos(theta_1) + l_2*cos(theta_1 + theta_2)
"""
from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from pathlib import Path

import sympy
import yaml

from .chain import Chain, DHRow
from .errors import Location, UserError
from .expr import parse_expression
from .transforms import CONVENTIONS, STEP_KINDS, Step

MAX_FILE_BYTES = 1 << 20
MAX_JOINTS = 24
TOP_KEYS = ("name", "source", "convention", "joints", "base", "tool", "sample", "notes")
ROW_KEYS = ("joint", "alpha", "a", "d", "theta", "var")
_JOINT_TYPES = {"r": "R", "revolute": "R", "p": "P", "prismatic": "P"}
_DEGREE_LOOKING = {15, 30, 45, 60, 90, 120, 135, 150, 180, 270, 360}


@dataclass
class Robot:
    """A robot as its file describes it."""

    name: str
    convention: str
    chain: Chain
    source: str = ""
    notes: str = ""
    sample: dict = field(default_factory=dict)  # constant symbol -> exact number, for pictures
    path: str = "<robot>"
    warnings: list = field(default_factory=list)  # strings "FILE:LINE:COL: message"


def load_robot_file(path: str | Path) -> Robot:
    """Read a robot file from disk, refusing huge or non-UTF-8 files."""
    path = Path(path)
    where = Location(str(path))
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise UserError(f"file is {size} bytes; robot files are limited to {MAX_FILE_BYTES}", where)
        with path.open("rb") as handle:
            data = handle.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise UserError(f"cannot read file: {exc.strerror or exc}", where) from None
    if len(data) > MAX_FILE_BYTES:
        raise UserError(f"file is larger than {MAX_FILE_BYTES} bytes", where)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise UserError(f"file is not UTF-8 text (bad byte at offset {exc.start})", where) from None
    return load_robot_text(text, str(path))


def load_robot_text(text: str, filename: str = "<robot>") -> Robot:
    return _Reader(filename).robot(_compose(text, filename))


def _compose(text: str, filename: str) -> yaml.Node:
    try:
        for event in yaml.parse(text, Loader=yaml.SafeLoader):
            if isinstance(event, yaml.AliasEvent):
                raise UserError("YAML aliases (*name) are not allowed in robot files", _mark(filename, event.start_mark))
        node = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        raise UserError(f"YAML syntax error: {exc.problem or exc.context}", _mark(filename, mark)) from None
    except yaml.YAMLError as exc:
        raise UserError(f"YAML error: {exc}", Location(filename)) from None
    if node is None:
        raise UserError("file is empty; expected a robot description", Location(filename, 1, 1))
    return node


def _mark(filename: str, mark) -> Location:
    return Location(filename, mark.line + 1, mark.column + 1) if mark else Location(filename)


class _Reader:
    """Walks the composed YAML nodes and builds the Robot, checking as it goes."""

    def __init__(self, filename: str):
        self.filename = filename
        self.warnings: list[str] = []

    def where(self, node: yaml.Node) -> Location:
        location = _mark(self.filename, node.start_mark)
        quoted = isinstance(node, yaml.ScalarNode) and node.style in ("'", '"')
        return location.shifted(1) if quoted else location

    def mapping(self, node: yaml.Node, what: str, allowed: tuple) -> dict:
        """A mapping's items as {key: (key node, value node)}, refusing unknown keys."""
        if not isinstance(node, yaml.MappingNode):
            raise UserError(f"{what} must be a mapping of keys to values", self.where(node))
        items = {}
        for key_node, value_node in node.value:
            key = key_node.value if isinstance(key_node, yaml.ScalarNode) else None
            if key not in allowed:
                hint = difflib.get_close_matches(str(key), allowed, n=1)
                suggestion = f"; did you mean {hint[0]!r}?" if hint else f"; expected one of {', '.join(allowed)}"
                raise UserError(f"unknown key {key!r} in {what}{suggestion}", self.where(key_node))
            if key in items:
                raise UserError(f"key {key!r} appears twice in {what}", self.where(key_node))
            items[key] = (key_node, value_node)
        return items

    def text(self, node: yaml.Node, what: str) -> str:
        if not isinstance(node, yaml.ScalarNode):
            raise UserError(f"{what} must be a single value, not a list or mapping", self.where(node))
        return node.value

    def expression(self, node: yaml.Node, what: str) -> sympy.Expr:
        return parse_expression(self.text(node, what), self.where(node))

    def sequence(self, node: yaml.Node, what: str) -> list:
        if isinstance(node, yaml.ScalarNode) and node.tag.endswith(":null"):
            return []
        if not isinstance(node, yaml.SequenceNode):
            raise UserError(f"{what} must be a list", self.where(node))
        return node.value

    def robot(self, root: yaml.Node) -> Robot:
        top = self.mapping(root, "the robot file", TOP_KEYS)
        for required in ("convention", "joints"):
            if required not in top:
                raise UserError(f"missing key {required!r} (standard or modified)" if required == "convention"
                                else f"missing key {required!r}", self.where(root))
        convention_node = top["convention"][1]
        convention = self.text(convention_node, "convention").strip().lower()
        if convention not in CONVENTIONS:
            raise UserError(f"unknown convention {convention!r}; use standard or modified", self.where(convention_node))
        joints_node = top["joints"][1]
        row_nodes = self.sequence(joints_node, "joints")
        if not row_nodes:
            raise UserError("joints is empty; a robot needs at least one joint", self.where(joints_node))
        if len(row_nodes) > MAX_JOINTS:
            raise UserError(f"{len(row_nodes)} joints; dhsym handles at most {MAX_JOINTS}", self.where(joints_node))
        parsed = [self.row(node, number) for number, node in enumerate(row_nodes, 1)]
        rows = [row for row, _ in parsed]
        self.check_variables(rows, [moving for _, moving in parsed], row_nodes)
        variables = {row.variable for row in rows}
        base = self.steps(top["base"][1], "base", variables) if "base" in top else []
        tool = self.steps(top["tool"][1], "tool", variables) if "tool" in top else []
        name = self.text(top["name"][1], "name") if "name" in top else Path(self.filename).stem
        return Robot(
            name=name, convention=convention, chain=Chain(rows, convention, base, tool),
            source=self.text(top["source"][1], "source") if "source" in top else "",
            notes=self.text(top["notes"][1], "notes") if "notes" in top else "",
            sample=self.sample(top["sample"][1], variables) if "sample" in top else {},
            path=self.filename, warnings=self.warnings,
        )

    def row(self, node: yaml.Node, number: int) -> tuple[DHRow, yaml.Node]:
        """One joint row, and the node of the field that holds its variable."""
        what = f"joint row {number}"
        items = self.mapping(node, what, ROW_KEYS)
        for key in ("joint", "alpha", "a", "d", "theta"):
            if key not in items:
                raise UserError(f"{what} is missing {key!r}", self.where(node))
        kind_node = items["joint"][1]
        kind = _JOINT_TYPES.get(self.text(kind_node, "joint").strip().lower())
        if kind is None:
            raise UserError(f"{what}: joint must be R (revolute) or P (prismatic)", self.where(kind_node))
        values = {key: self.expression(items[key][1], f"{what} {key}") for key in ("alpha", "a", "d", "theta")}
        self.warn_degrees(values["alpha"], items["alpha"][1], "alpha")
        if kind == "R":
            self.warn_degrees(values["theta"], items["theta"][1], "theta")
        moving_key = "theta" if kind == "R" else "d"
        moving_node = items[moving_key][1]
        free = sorted(values[moving_key].free_symbols, key=str)
        if "var" in items:
            var_node = items["var"][1]
            name = self.text(var_node, "var").strip()
            match = [s for s in free if s.name == name]
            if not match:
                raise UserError(f"{what}: var {name!r} does not appear in {moving_key}", self.where(var_node))
            variable = match[0]
        elif len(free) == 1:
            variable = free[0]
        elif not free:
            raise UserError(f"{what}: no joint variable; a {'revolute' if kind == 'R' else 'prismatic'} "
                            f"joint needs a symbol in {moving_key}", self.where(moving_node))
        else:
            names = ", ".join(s.name for s in free)
            raise UserError(f"{what}: {moving_key} has several symbols ({names}); name the joint variable "
                            f"with var", self.where(moving_node))
        if kind == "P" and values["theta"].free_symbols and "var" not in items:
            raise UserError(f"{what}: a prismatic joint moves along d, but theta holds a variable "
                            f"({values['theta']}); use joint: R or a constant theta", self.where(items["theta"][1]))
        for key in ("alpha", "a", "theta" if kind == "P" else "d"):
            if variable in values[key].free_symbols:
                raise UserError(f"{what}: joint variable {variable} also appears in {key}", self.where(items[key][1]))
        return DHRow(kind, values["theta"], values["d"], values["a"], values["alpha"], variable), moving_node

    def check_variables(self, rows: list[DHRow], moving_nodes: list, row_nodes: list) -> None:
        """Each joint variable belongs to one row and is no other row's constant."""
        seen: dict = {}
        for number, row in enumerate(rows, 1):
            if row.variable in seen:
                raise UserError(f"joint row {number}: joint variable {row.variable} is already the variable "
                                f"of row {seen[row.variable]}", self.where(moving_nodes[number - 1]))
            seen[row.variable] = number
        variables = set(seen)
        for number, row in enumerate(rows, 1):
            constants = (row.a, row.alpha, row.d if row.joint == "R" else row.theta)
            for value in constants:
                clash = value.free_symbols & (variables - {row.variable})
                if clash:
                    raise UserError(f"joint row {number}: {sorted(map(str, clash))[0]} is another row's joint "
                                    f"variable and cannot be a constant here", self.where(row_nodes[number - 1]))

    def warn_degrees(self, value: sympy.Expr, node: yaml.Node, key: str) -> None:
        if value.is_Integer and abs(int(value)) in _DEGREE_LOOKING:
            self.warnings.append(f"{self.where(node)}: {key} {value} is taken as radians; "
                                 f"write {value}deg if you meant degrees")

    def steps(self, node: yaml.Node, what: str, variables: set) -> list[Step]:
        steps = []
        for number, step_node in enumerate(self.sequence(node, what), 1):
            items = self.mapping(step_node, f"{what} step {number}", STEP_KINDS)
            if len(items) != 1:
                raise UserError(f"{what} step {number} must have exactly one of {', '.join(STEP_KINDS)}",
                                self.where(step_node))
            (kind, (_, value_node)), = items.items()
            value = self.expression(value_node, f"{what} step {number}")
            if value.free_symbols & variables:
                raise UserError(f"{what} step {number} is fixed and cannot use a joint variable", self.where(value_node))
            if kind[0] == "R":
                self.warn_degrees(value, value_node, kind)
            steps.append(Step(kind, value))
        return steps

    def sample(self, node: yaml.Node, variables: set) -> dict:
        values = {}
        for key, (key_node, value_node) in self.mapping(node, "sample", tuple(_keys(node))).items():
            value = self.expression(value_node, f"sample {key}")
            if not value.is_number:
                raise UserError(f"sample {key} must be a number", self.where(value_node))
            values[parse_expression(key, self.where(key_node))] = value
        return values


def _keys(node: yaml.Node) -> list:
    if not isinstance(node, yaml.MappingNode):
        return []
    return [k.value for k, _ in node.value if isinstance(k, yaml.ScalarNode)]
