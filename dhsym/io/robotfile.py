"""Robot files: YAML in, a validated `Robot` out, with every mistake placed at FILE:LINE:COL.

The YAML comes from dhsym.yamlsafe as nodes that keep their line and column, and is read
by hand: no Python object is ever built from a tag. Limits: 24 joints, 200 characters per
expression (see dhsym.expr) and those of dhsym.yamlsafe (1 MiB, nesting 10, 20,000 values).

>>> robot = load_robot_text('''
... name: two-link arm
... convention: standard
... joints:
...   - {joint: R, alpha: 0, a: l_1, d: 0, theta: theta_1}
...   - {joint: R, alpha: 0, a: l_2, d: 0, theta: theta_2}
... ''', "arm.yaml")
>>> robot.chain.fk()[0, 3], robot.name, robot.file
(l_1*cos(theta_1) + l_2*cos(theta_1 + theta_2), 'two-link arm', 'arm.yaml')
>>> load_robot_text("convention: standard\\njoints: [{joint: R, alpah: 0}]", "arm.yaml")
Traceback (most recent call last):
dhsym.errors.UserError: arm.yaml:2:21: unknown key 'alpah' in joint row 1; did you mean 'alpha'?
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import sympy
import yaml

from ..core.chain import Chain, DHRow
from ..core.grid import Snaps
from ..core.robot import Robot
from ..core.transforms import CONVENTIONS, STEP_KINDS, Step
from ..errors import Location, UserError
from .expr import Reading, parse_expression
from .inertia import ROW_KEYS as INERTIA_KEYS
from .inertia import read_masses
from .jointlimits import ROW_KEY as LIMITS_KEY
from .jointlimits import read_joint_limits
from .suspicious import decimal_angle, looks_like_degrees, misplaced_variable, misspelt_pi, printed_key, printed_text
from .yamlhints import glued_key, node_kind
from .yamlsafe import MAX_JOINTS, YAML_TAG, compose, mark_location, read_text_file

TOP_KEYS = ("name", "source", "convention", "joints", "axes", "base", "tool", "sample", "notes", "first_frame",
            "gravity")
ROW_KEYS = ("joint", "alpha", "a", "d", "theta", "var", LIMITS_KEY, *INERTIA_KEYS)
_JOINT_TYPES = {"r": "R", "revolute": "R", "p": "P", "prismatic": "P"}
LENGTHS = ("a", "d", "Tx", "Ty", "Tz")  # fields that hold distances; the others hold angles


def load_robot_file(path: str | Path) -> Robot:
    """Read a robot file from disk, refusing huge or non-UTF-8 files."""
    return load_robot_text(read_text_file(path), str(path))


def load_robot_text(text: str, filename: str = "<robot>") -> Robot:
    """The robot of a robot file's text; `filename` places errors and becomes `robot.file`.
    >>> load_robot_text('<?xml version="1.0"?>\\n<robot name="arm"/>', "arm.urdf")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    dhsym.errors.UserError: arm.urdf:1:1: this is XML (a URDF?), not a robot file: ... and use arm.yaml
    """
    if text.lstrip("\ufeff \t\r\n").startswith("<"):  # YAML would read it as one long string
        raise UserError(f"this is XML (a URDF?), not a robot file: make one with `dhsym import {filename} [--tip "
                        "LINK] -o arm.yaml` and use arm.yaml", Location(filename, 1, 1))
    return _Reader(filename).robot(compose(text, filename))


def _suggestion(key: str, allowed) -> str:
    """`; did you mean 'alpha'?` for a near miss, else the list of what is allowed."""
    import difflib  # only after a mistake: a command pays at start-up for what it uses

    allowed = list(allowed)
    same_but_case = [name for name in allowed if name.lower() == key.lower()]
    hint = same_but_case or difflib.get_close_matches(key, allowed, n=1)
    return f"; did you mean {hint[0]!r}?" if hint else f"; expected one of {', '.join(allowed)}"


class _Reader:
    """Walks the composed YAML nodes and builds the Robot, checking as it goes."""

    max_joints = MAX_JOINTS  # the axes: form (io/axesfile.py) reads its limit here

    def __init__(self, filename: str):
        self.filename = filename
        self.warnings: list[str] = []
        self.snaps = Snaps(lengths=False)  # angles read as multiples of π/12: one warning at the end
        self.reading = Reading()  # of the table's fields: how numbers were written, where names stand

    def where(self, node: yaml.Node) -> Location:
        location = mark_location(self.filename, node.start_mark)
        quoted = isinstance(node, yaml.ScalarNode) and node.style in ("'", '"')
        return location.shifted(1) if quoted else location

    def warn(self, node: yaml.Node, message: str) -> None:
        self.warnings.append(f"{self.where(node)}: {message}")

    def mapping(self, node: yaml.Node, what: str, allowed) -> dict:
        """A mapping's items as {key: (key node, value node)}, refusing unknown keys."""
        if not isinstance(node, yaml.MappingNode):
            glued = glued_key(node) if isinstance(node, yaml.ScalarNode) else ""
            raise UserError(f"{what} must be a mapping of keys to values, not {node_kind(node)}{glued}",
                            self.where(node))

        items, previous = {}, None
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise UserError(f"keys in {what} must be plain names, not {node_kind(key_node)}", self.where(key_node))
            key = key_node.value
            if key not in allowed and key.isdigit() and previous is not None and previous.strip().isdigit():
                raise UserError(f"unknown key {key!r} in {what}: inside {{...}} a comma separates entries; write "
                                f"decimals with a point, as in {previous.strip()}.{key}", self.where(key_node))
            if key not in allowed:
                hint = glued_key(key_node) or _suggestion(key, allowed)
                raise UserError(f"unknown key {key!r} in {what}{hint}", self.where(key_node))
            if key in items:
                raise UserError(f"key {key!r} appears twice in {what}", self.where(key_node))
            items[key] = (key_node, value_node)
            previous = value_node.value if isinstance(value_node, yaml.ScalarNode) else None
        return items

    def text(self, node: yaml.Node, what: str) -> str:
        if not isinstance(node, yaml.ScalarNode):
            raise UserError(f"{what} must be a single value, not {node_kind(node)}", self.where(node))
        return node.value

    def expression(self, node: yaml.Node, what: str, table: bool = True) -> sympy.Expr:
        """A field's value parsed as an expression; any mistake is reported with the field's name."""
        return self.read(node, what, table)[0]

    def read(self, node: yaml.Node, what: str, table: bool = True) -> tuple[sympy.Expr, Reading]:
        """A field's value and what its reading noticed. Fields of the table (rows, base, tool)
        also say how the file writes numbers; a length field refuses π and degrees."""
        value = self.text(node, what)
        if node.style is None and node.tag == YAML_TAG + "null":
            raise UserError(f"{what} has no value", self.where(node))
        if node.style is None and node.tag == YAML_TAG + "bool":
            raise UserError(f"{what}: {value!r} reads as a YAML true/false, not a number; quote it to "
                            f"use it as a name", self.where(node))
        reading = Reading()
        try:
            result = parse_expression(value, self.where(node), reading)
        except UserError as error:
            raise UserError(f"{what}: {error.message}", error.where) from None
        self.warnings += [f"{where}: {what}: {message}" for where, message in reading.warnings]
        if table:
            field_name = what.rsplit(" ", 1)[-1]
            if field_name in LENGTHS:
                self.refuse_angle_units(reading, what, field_name)
            self.reading.absorb(reading)
        return result, reading

    def refuse_angle_units(self, reading: Reading, what: str, field_name: str) -> None:
        """π and degrees make angles; outside a sin or cos they have no place in a length."""
        for unit, where, inside_trig in reading.units:
            if not inside_trig:
                angles = "alpha and theta" if field_name in ("a", "d") else "Rx, Ry and Rz"
                unit = "in degrees" if unit == "degrees" else "a multiple of π"
                raise UserError(f"{what}: {field_name} is a length and cannot be {unit}; angles go in {angles}",
                                where)

    def decimal_angle(self, value: sympy.Expr, reading: Reading, what: str) -> sympy.Expr:
        """`alpha: 1.5708` is not π/2, say so where the decimal stands; a double's π/2 is (io.suspicious)."""
        angle, message = decimal_angle(value, reading.decimals, reading.places, self.snaps)
        self.warnings += [f"{reading.decimals[0][1]}: {what}: {message}"] if message else []
        return angle

    def optional_text(self, top: dict, key: str, default: str) -> str:
        if key not in top:
            return default
        node = top[key][1]
        if isinstance(node, yaml.ScalarNode) and node.style is None and node.tag == YAML_TAG + "null":
            return default
        return self.text(node, key)

    def sequence(self, node: yaml.Node, what: str) -> list:
        if isinstance(node, yaml.ScalarNode) and node.tag == YAML_TAG + "null":
            return []
        if not isinstance(node, yaml.SequenceNode):
            raise UserError(f"{what} must be a list, not {node_kind(node)}", self.where(node))
        return node.value

    def robot(self, root: yaml.Node) -> Robot:
        if not isinstance(root, yaml.MappingNode):
            raise UserError(f"a robot file must be a mapping of keys (convention, joints, ...) to values, "
                            f"not {node_kind(root)}", self.where(root))
        top = self.mapping(root, "the robot file", TOP_KEYS)
        if "convention" not in top:
            raise UserError("missing key 'convention' (standard or modified)", self.where(root))
        if "joints" not in top and "axes" not in top:
            raise UserError("missing key 'joints' (the list of DH rows)", self.where(root))
        convention_node = top["convention"][1]
        convention = self.text(convention_node, "convention").strip().lower()
        if convention not in CONVENTIONS:
            raise UserError(f"unknown convention {self.text(convention_node, 'convention')!r}; use standard or "
                            f"modified", self.where(convention_node))
        notes = self.optional_text(top, "notes", "")
        if "axes" in top:  # the geometric form (io/axesfile.py): joint axes instead of DH rows
            from ..geometry.rounding import joined
            from .axesfile import axes_chain  # the geometry of frames, only for a file that needs it

            chain, rounded = axes_chain(self, top, convention)
            notes = joined(notes, rounded)
        else:
            chain = self.dh_chain(top, convention)
        masses = read_masses(self, top, chain.joint_variables)
        self.check_names()
        first_frame = self.first_frame(top["first_frame"][1]) if "first_frame" in top else 0
        weights = masses.symbols(chain.n, first_frame + 1)  # the generic m_4 … too; listed when the file has masses
        listed = {s.name for s in chain.symbols | (weights if masses.given else set())}
        sample = self.sample(top["sample"][1], {s.name: s for s in chain.symbols | weights}, listed) \
            if "sample" in top else {}
        return Robot(chain, name=self.optional_text(top, "name", Path(self.filename).stem), masses=masses,
                     source=self.optional_text(top, "source", ""), notes=notes, sample=sample,
                     numbers=self.reading.numbers,  # how the table's fields wrote numbers, for the printers
                     joint_limits=read_joint_limits(self, top, chain) if "axes" not in top else (),
                     frame_offset=first_frame, file=self.filename, warnings=self.warnings + self.snaps.warnings())

    def dh_chain(self, top: dict, convention: str) -> Chain:
        """The chain of a file that gives DH rows under `joints:`."""
        joints_node = top["joints"][1]
        row_nodes = self.sequence(joints_node, "joints")
        if not row_nodes:
            raise UserError("joints is empty; a robot needs at least one joint", self.where(joints_node))
        if len(row_nodes) > MAX_JOINTS:
            raise UserError(f"{len(row_nodes)} joints; dhsym handles at most {MAX_JOINTS}", self.where(joints_node))
        rows = [self.row(node, number) for number, node in enumerate(row_nodes, 1)]
        self.check_variables(rows)
        dh_rows = [row.dh for row in rows]
        variables = {row.variable for row in dh_rows}
        base = self.steps(top["base"][1], "base", variables) if "base" in top else []
        tool = self.steps(top["tool"][1], "tool", variables) if "tool" in top else []
        return Chain(dh_rows, convention, base, tool)

    def row(self, node: yaml.Node, number: int) -> "_Row":
        """One joint row, checked field by field."""
        what = f"joint row {number}"
        items = self.mapping(node, what, ROW_KEYS)
        for key in ("joint", "alpha", "a", "d", "theta"):
            if key not in items:
                raise UserError(f"{what} is missing {key!r}", self.where(node))
        nodes = {key: value_node for key, (_, value_node) in items.items()}
        kind = _JOINT_TYPES.get(self.text(nodes["joint"], f"{what} joint").strip().lower())
        if kind is None:
            raise UserError(f"{what} joint: must be R (revolute) or P (prismatic), not "
                            f"{nodes['joint'].value!r}", self.where(nodes["joint"]))
        values, readings = {}, {}
        for key in ("alpha", "a", "d", "theta"):
            values[key], readings[key] = self.read(nodes[key], f"{what} {key}")
        moving = "theta" if kind == "R" else "d"
        variable = self.joint_variable(what, kind, values, nodes)
        self.refuse_nonlinear(values[moving], variable, f"{what} {moving}", readings[moving], nodes[moving])
        for key in ("theta", "d"):  # a variable in the other column, or named for it: joint: P with theta_1
            for name, place in readings[key].names:
                slip = (key != moving or name == variable.name) and misplaced_variable(kind, key, name, "var" in nodes)
                if slip:
                    raise UserError(f"{what} {key}: {slip}", place)
        for key in ("alpha", "a", "theta" if kind == "P" else "d"):
            if variable in values[key].free_symbols:
                raise UserError(f"{what} {key}: joint variable {variable} also appears here; only {moving} "
                                f"may hold it", self.where(nodes[key]))
        self.warn_degrees(values["alpha"], nodes["alpha"], f"{what} alpha")
        values["alpha"] = self.decimal_angle(values["alpha"], readings["alpha"], f"{what} alpha")
        constant_angle = values["theta"] - variable if kind == "R" else values["theta"]
        self.warn_degrees(constant_angle, nodes["theta"], f"{what} theta", offset=kind == "R")
        values["theta"] += self.decimal_angle(constant_angle, readings["theta"], f"{what} theta") - constant_angle
        dh = DHRow(kind, values["theta"], values["d"], values["a"], values["alpha"], variable)
        return _Row(number, dh, nodes)

    def joint_variable(self, what: str, kind: str, values: dict, nodes: dict) -> sympy.Symbol:
        """The one symbol of theta (revolute) or d (prismatic), or the one named by `var`."""
        moving = "theta" if kind == "R" else "d"
        free = sorted(values[moving].free_symbols, key=str)
        if "var" in nodes:
            name = self.text(nodes["var"], f"{what} var").strip()
            match = [s for s in free if s.name == name]
            if not match:
                raise UserError(f"{what} var: {name!r} does not appear in {moving}", self.where(nodes["var"]))
            return match[0]
        if kind == "P" and values["theta"].free_symbols and not free:
            names = ", ".join(sorted(map(str, values["theta"].free_symbols)))
            raise UserError(f"{what} theta: holds {names}, but joint P (prismatic) moves along d, and d is "
                            f"constant; write joint: R, or put the variable in d", self.where(nodes["theta"]))
        if len(free) == 1:
            return free[0]
        if not free:
            joint = "revolute" if kind == "R" else "prismatic"
            other = sorted(map(str, values["d"].free_symbols)) if kind == "R" else []
            hint = f"; d holds {', '.join(other)}: write joint: P if this joint slides" if other else ""
            raise UserError(f"{what} {moving}: no joint variable; a {joint} joint needs a symbol in {moving}{hint}",
                            self.where(nodes[moving]))
        names = ", ".join(s.name for s in free)
        pi = [misspelt_pi(s.name) for s in free if misspelt_pi(s.name)]
        advice = pi[0] if pi else "name the joint variable with var"
        raise UserError(f"{what} {moving}: several symbols ({names}); {advice}", self.where(nodes[moving]))

    def refuse_nonlinear(self, value: sympy.Expr, variable: sympy.Symbol, what: str, reading: Reading,
                         node: yaml.Node) -> None:
        """A DH angle or offset is the variable times a constant plus a constant: theta_2 - pi/2."""
        slope = sympy.diff(value, variable)
        if variable not in slope.free_symbols:
            return
        inside = sorted({type(f).__name__ for f in value.atoms(sympy.Function) if variable in f.free_symbols})
        powers = [p for p in value.atoms(sympy.Pow) if variable in p.base.free_symbols]
        how = (f"inside {inside[0]}" if inside else "under a square root" if any(p.exp.q == 2 for p in powers)
               else "in a denominator" if any(p.exp.is_negative for p in powers)
               else "squared" if any(p.exp == 2 for p in powers) else "raised to a power" if powers
               else "non-linearly")
        where = next((place for name, place in reading.names if name == variable.name), self.where(node))
        field_name = what.rsplit(" ", 1)[-1]
        example = "theta_2 - pi/2" if field_name == "theta" else "d_3 + l_1"
        raise UserError(f"{what}: the joint variable {variable} enters {how}; a DH {field_name} is the variable "
                        f"plus a constant, as in {example}", where)

    def check_names(self) -> None:
        """Warn about two spellings of one printed name: l1 and l_1, theta_1 and θ1 are different symbols."""
        first: dict = {}
        warned = set()
        for name, where in self.reading.names:
            key = printed_key(name)
            seen = first.setdefault(key, name)
            if seen != name and (seen, name) not in warned:
                warned.add((seen, name))
                self.warnings.append(f"{where}: {name} and {seen} are two different symbols that both print as "
                                     f"{printed_text(name)}; write one spelling for both")

    def check_variables(self, rows: list["_Row"]) -> None:
        """Each joint variable belongs to one row and is no other row's constant."""
        owner: dict = {}
        for row in rows:
            moving = "theta" if row.dh.joint == "R" else "d"
            if row.dh.variable in owner:
                raise UserError(f"joint row {row.number} {moving}: joint variable {row.dh.variable} is already "
                                f"the variable of joint row {owner[row.dh.variable]}", self.where(row.nodes[moving]))
            owner[row.dh.variable] = row.number
        for row in rows:
            constants = ("alpha", "a", "d" if row.dh.joint == "R" else "theta")
            for key in constants:
                for symbol in sorted(getattr(row.dh, key).free_symbols, key=str):
                    if symbol in owner and owner[symbol] != row.number:
                        raise UserError(f"joint row {row.number} {key}: {symbol} is the joint variable of joint "
                                        f"row {owner[symbol]} and cannot be a constant here",
                                        self.where(row.nodes[key]))

    def warn_degrees(self, value: sympy.Expr, node: yaml.Node, what: str, offset: bool = False) -> None:
        """Warn about an angle such as 90 that was almost certainly meant in degrees."""
        constant = value.as_coeff_Add()[0] if value.is_Add else value
        if looks_like_degrees(constant):
            kind = "the offset " if offset or constant != value else ""
            self.warn(node, f"{what}: {kind}{constant} is taken as radians; write {constant}deg if you meant degrees")

    def steps(self, node: yaml.Node, what: str, variables: set) -> list[Step]:
        steps = []
        for number, step_node in enumerate(self.sequence(node, what), 1):
            step_what = f"{what} step {number}"
            items = self.mapping(step_node, step_what, STEP_KINDS)
            if len(items) != 1:
                raise UserError(f"{step_what} must have exactly one of {', '.join(STEP_KINDS)}, not "
                                f"{len(items)}", self.where(step_node))
            (kind, (_, value_node)), = items.items()
            value, reading = self.read(value_node, f"{step_what} {kind}")
            if value.free_symbols & variables:
                raise UserError(f"{step_what} {kind}: a fixed step cannot use a joint variable "
                                f"({', '.join(sorted(map(str, value.free_symbols & variables)))})",
                                self.where(value_node))
            if kind[0] == "R":
                self.warn_degrees(value, value_node, f"{step_what} {kind}")
                value = self.decimal_angle(value, reading, f"{step_what} {kind}")
            steps.append(Step(kind, value))
        return steps

    def first_frame(self, node: yaml.Node) -> int:
        """The number of the chain's first frame, as the lecture numbers it (a wrist: 3)."""
        text = self.text(node, "first_frame").strip()
        if not (text.isascii() and text.isdigit() and len(text) <= 3):
            raise UserError(f"first_frame must be a whole number such as 3 (the number of the chain's first "
                            f"frame), not {text!r}", self.where(node))
        return int(text)

    def sample(self, node: yaml.Node, symbols: dict, listed=None) -> dict:
        """Numbers for the robot's symbols; a name the robot does not use is a typo (the message lists `listed`)."""
        keys = [k.value for k, _ in node.value if isinstance(k, yaml.ScalarNode)] \
            if isinstance(node, yaml.MappingNode) else []
        values = {}
        for key, (key_node, value_node) in self.mapping(node, "sample", keys).items():
            if key.strip() not in symbols:
                hint = _suggestion(key, sorted(listed or symbols))
                raise UserError(f"sample {key}: the robot has no symbol {key!r}{hint}", self.where(key_node))

            value = self.expression(value_node, f"sample {key}", table=False)
            if not value.is_number:
                raise UserError(f"sample {key}: must be a number, not {value}", self.where(value_node))
            values[symbols[key.strip()]] = value
        return values


@dataclass
class _Row:
    number: int
    dh: DHRow
    nodes: dict  # field name -> YAML value node, for locating later errors
