"""Writing a robot as a robot file that dhsym reads back to the same robot: the same rows, base,
tool, name, source, notes, sample values and first frame, its numbers written as its file wrote them.

Numbers are written as decimals where they end (17/40 → 0.425), else as fractions; π and
square roots by name; a denominator the chain's file wrote as a fraction stays one (l_1/2).
A value the robot-file parser cannot read (atan(4/3), a fraction of 60 digits) or that is too
long for it is rounded to a decimal by dhsym.geometry.rounding, and the notes say which value
and what it was exactly. What cannot be written at all (a symbolic atan2, an expression over the
200-character limit, more than 24 joints, a file over 1 MiB) is a UserError naming the limit,
and nothing is written. Every file is read back through the robot-file parser before the text
is returned, so a file that would not read back the same is never written.

>>> from dhsym.io.library import load
>>> print(robot_yaml(load("planar2r")))  # doctest: +ELLIPSIS
name: "Planar elbow manipulator (2R)"
source: "..."
convention: standard
joints:
  - {joint: R, theta: theta_1, d: 0, a: a_1, alpha: 0}
  - {joint: R, theta: theta_2, d: 0, a: a_2, alpha: 0}
sample: {a_1: 0.5, a_2: 0.4}
...
>>> expression_text(sympy.Symbol("q_1") + sympy.pi / 2), expression_text(sympy.Rational(17, 40))
('q_1 + pi/2', '0.425')
"""
from __future__ import annotations

import json
import re

import sympy

from ..core.chain import Chain, DHRow
from ..core.inertia import LinkInertia, MassModel
from ..core.numbers import WrittenNumbers
from ..core.robot import Robot
from ..core.transforms import Step
from ..errors import UserError
from ..geometry.rounding import Rounding, dh_label, fit, joined, rounding_note, written_text
from .expr import MAX_LENGTH, parse_expression
from .robotfile import MAX_JOINTS, load_robot_text
from .suspicious import misplaced_variable
from .yamlsafe import MAX_FILE_BYTES

COLUMNS = {"standard": ("theta", "d", "a", "alpha"), "modified": ("alpha", "a", "d", "theta")}
_PLAIN = re.compile(r"^[\w.+\-*/() ]+$")


def expression_text(value, numbers: WrittenNumbers | None = None) -> str:
    return written_text(value, numbers)


def _moving_text(variable, constant, numbers) -> str | None:
    """θ or d as a person writes it, the variable first: q_2 + 1.5707, q_6 - pi/2."""
    if constant == 0 or variable in constant.free_symbols:
        return None
    text = expression_text(constant, numbers)
    return f"{variable.name} - {text[1:]}" if text.startswith("-") else f"{variable.name} + {text}"


def _yaml_value(text: str) -> str:
    plain = _PLAIN.match(text) and (not text.startswith(("-", "*")) or re.match(r"^-[\w.(]", text))
    return text if plain else json.dumps(text)  # a YAML plain scalar where it reads back as written


def _string(text: str) -> str:
    """A YAML double-quoted string; characters YAML refuses in a file (C1 controls, U+2028) escaped."""
    return "".join(c if c.isprintable() or c == " " else _escape(c) for c in json.dumps(text, ensure_ascii=False))


def _escape(character: str) -> str:
    code = ord(character)
    return f"\\u{code:04x}" if code <= 0xFFFF else f"\\U{code:08x}"


class _Values:
    """Each value's text, checked to read back; what had to be rounded, for the notes."""

    def __init__(self, robot: Robot):
        self.numbers = robot.numbers
        self.roundings: list[Rounding] = []
        self.limits: list = []  # each row's joint limits as they will read back

    def written(self, value, label: str, place: str, length: bool = False):
        """(value as it will read back, its text) for a value of the table at `place`; a
        `length` holds no π (a robot file refuses it there)."""
        value = sympy.sympify(value)
        text = expression_text(value, self.numbers)
        if self.reads_back(text, value) and not (length and value.has(sympy.pi)):
            return value, text
        rounded = fit(value, length=length)
        if rounded is not value:
            rounded_text = expression_text(rounded, self.numbers)
            if self.reads_back(rounded_text, rounded):
                self.roundings.append(Rounding(label, rounded, value))
                return rounded, rounded_text
            text = rounded_text
        hint = ""
        if value.free_symbols and any(not isinstance(f, (sympy.sin, sympy.cos)) for f in value.atoms(sympy.Function)):
            names = ", ".join(sorted(map(str, value.free_symbols)))
            hint = f"; the angle depends on {names}, so it has no exact decimal: give those lengths as numbers"
        raise UserError(f"cannot write {place} as a robot file: {self.why_not(text)}{hint}; nothing was written")

    @staticmethod
    def reads_back(text: str, value) -> bool:
        if len(text) > MAX_LENGTH:
            return False
        try:
            return parse_expression(text) == value
        except UserError:
            return False

    @staticmethod
    def why_not(text: str) -> str:
        shown = text if len(text) <= 60 else text[:57] + "..."
        if len(text) > MAX_LENGTH:
            return f"its value is {len(text)} characters long; a robot file holds at most {MAX_LENGTH} per expression"
        try:
            parse_expression(text)
        except UserError as error:
            return f"{shown} does not read back ({error.message})"
        return f"{shown} does not read back as the same value"


def robot_yaml(robot: Robot, notes: str | None = None) -> str:
    """The robot file of `robot`; it reads back to the same rows, base, tool, name, source, sample
    and first frame. `notes` goes before the robot's own notes, then a sentence on any value rounded."""
    chain = robot.chain
    if chain.n > MAX_JOINTS:
        raise UserError(f"{chain.n} joints; a robot file holds at most {MAX_JOINTS}, so none was written")
    values = _Values(robot)
    lines = [f"name: {_string(robot.name)}", f"source: {_string(robot.source)}", f"convention: {chain.convention}"]
    if robot.frame_offset:
        lines.append(f"first_frame: {robot.frame_offset}")
    rows, links = _joint_lines(robot, values, lines)
    gravity = None
    if robot.masses.gravity is not None:
        gravity = tuple(values.written(g, "gravity", "gravity")[0] for g in robot.masses.gravity)
    steps = _step_lines(chain, values, lines)
    if gravity is not None:
        lines.append(f"gravity: {_list(gravity, values.numbers)}")
    sample = _sample_lines(robot, values, lines)
    all_notes = joined(notes or "", robot.notes, rounding_note(values.roundings))
    if all_notes:
        lines.append(f"notes: {_string(all_notes)}")
    text = "\n".join(lines) + "\n"
    size = len(text.encode("utf-8"))
    if size > MAX_FILE_BYTES:
        raise UserError(f"the robot file would be {size} bytes; robot files are limited to {MAX_FILE_BYTES >> 20} "
                        "MiB, so none was written")
    masses = MassModel(tuple(links) if robot.masses.links else (), gravity)
    written = robot.replace(chain=Chain(rows, chain.convention, steps["base"], steps["tool"]), notes=all_notes,
                            sample=sample, masses=masses, joint_limits=values.limits)
    _check_reads_back(text, written)
    return text


def _joint_lines(robot: Robot, values: _Values, lines: list) -> tuple[list[DHRow], list[LinkInertia]]:
    """`joints:` and a line per row added to `lines`; the rows and the links' inertias as they will read back."""
    chain = robot.chain
    lines.append("joints:")
    rows, links = [], []
    for number, row in enumerate(chain.rows, 1):
        moving = "theta" if row.joint == "R" else "d"
        written, fields = {}, [f"joint: {row.joint}"]
        for key in COLUMNS[chain.convention]:
            value = getattr(row, key)
            constant = value - row.variable if key == moving else value
            label = dh_label(chain.convention, number, key, robot.numbering, moving=key == moving)
            constant, _ = values.written(constant, label, f"joint row {number} {key}", key in ("a", "d"))
            written[key] = constant + row.variable if key == moving else constant
            text = _moving_text(row.variable, constant, values.numbers) if key == moving else None
            text = text or expression_text(written[key], values.numbers)
            if len(text) > MAX_LENGTH:  # the constant fitted, but not with the variable added
                raise UserError(f"cannot write joint row {number} {key} as a robot file: {values.why_not(text)}; "
                                "nothing was written")
            fields.append(f"{key}: {_yaml_value(text)}")
        if len(written[moving].free_symbols) > 1 or _looks_misplaced(row.joint, written):
            fields.append(f"var: {row.variable.name}")
        pair = robot.joint_limits[number - 1] if robot.joint_limits else None
        fields += _limits_field(pair, row.joint, values, f"joint row {number} limits")
        fields += _inertia_fields(robot.masses.link(number), values, f"joint row {number}", links)
        lines.append("  - {" + ", ".join(fields) + "}")
        rows.append(DHRow(row.joint, written["theta"], written["d"], written["a"], written["alpha"], row.variable))
    return rows, links


def _step_lines(chain: Chain, values: _Values, lines: list) -> dict:
    """`base:` and `tool:` added to `lines` where the chain has such steps; the steps as they will read back."""
    steps = {}
    for key, chain_steps in (("base", chain.base), ("tool", chain.tool)):
        steps[key] = [Step(s.kind, values.written(s.value, f"{key} {s.kind}", f"{key} step {n} {s.kind}",
                                                  s.kind[0] == "T")[0]) for n, s in enumerate(chain_steps, 1)]
        if steps[key]:
            texts = (f"{{{s.kind}: {_yaml_value(expression_text(s.value, values.numbers))}}}" for s in steps[key])
            lines.append(f"{key}: [" + ", ".join(texts) + "]")
    return steps


def _sample_lines(robot: Robot, values: _Values, lines: list) -> dict:
    """`sample:` added to `lines` where the robot has sample values; the values as they will read back."""
    sample = {}
    if robot.sample:
        for s, v in sorted(robot.sample.items(), key=lambda i: i[0].name):
            sample[s] = values.written(v, s.name, f"sample {s.name}")
        lines.append("sample: {" + ", ".join(f"{s.name}: {_yaml_value(text)}" for s, (_, text) in sample.items()) + "}")
    return {s: value for s, (value, _) in sample.items()}


def _check_reads_back(text: str, robot: Robot) -> None:
    """The written file must give the robot back exactly; anything else is a bug in this writer,
    reported as an error (nothing is written) rather than a crash."""
    try:
        again = load_robot_text(text, "<written>")
    except UserError as error:
        raise UserError(f"the robot file dhsym would write does not read back ({error}); nothing was written") \
            from None
    same = [(r.joint, r.theta, r.d, r.a, r.alpha, r.variable) for r in again.chain.rows] == \
        [(r.joint, r.theta, r.d, r.a, r.alpha, r.variable) for r in robot.chain.rows]
    details = ("name", "source", "notes", "sample", "frame_offset", "masses", "joint_limits")
    same_details = [getattr(again, key) for key in details] == [getattr(robot, key) for key in details]
    fixed = [list(again.chain.base), list(again.chain.tool)] == [list(robot.chain.base), list(robot.chain.tool)]
    if not (same and same_details and fixed):
        raise UserError("the robot file dhsym would write reads back as a different chain; nothing was written")


def _inertia_fields(link: LinkInertia, values: _Values, place: str, links: list) -> list[str]:
    """`mass: …`, `com: [...]`, `inertia: [...]` of a row, for what the robot gives; the link as it
    will read back is added to `links`."""
    fields, written = [], {}
    for key in ("mass", "com", "inertia"):
        value = getattr(link, key)
        if value is None:
            continue
        if key == "mass":
            written[key] = values.written(value, f"{place} mass", f"{place} mass")[0]
            fields.append(f"mass: {_yaml_value(expression_text(written[key], values.numbers))}")
        else:
            written[key] = tuple(values.written(x, f"{place} {key}", f"{place} {key}")[0] for x in value)
            fields.append(f"{key}: {_list(written[key], values.numbers)}")
    links.append(LinkInertia(**written))
    return fields


def _limits_field(pair, joint: str, values: _Values, place: str) -> list[str]:
    """`limits: [-160deg, 160deg]` of a row that has limits: a revolute joint's in whole degrees
    where they are, as datasheets give them (they read back exactly: 160deg is 8π/9).

    >>> from dhsym.io.library import load
    >>> _limits_field((-sympy.pi / 2, sympy.Rational(3, 10)), "R", _Values(load("planar2r")), "joint row 1 limits")
    ['limits: [-90deg, 0.3]']
    """
    if pair is None:
        values.limits.append(None)
        return []
    texts, written = [], []
    for value in pair:
        degrees = value * 180 / sympy.pi
        if joint == "R" and value != 0 and degrees.is_Integer:
            written.append(value)
            texts.append(f"{degrees}deg")
        else:
            value, text = values.written(value, place, place)
            written.append(value)
            texts.append(_yaml_value(text))
    values.limits.append(tuple(written))
    return [f"limits: [{', '.join(texts)}]"]


def _list(entries, numbers) -> str:
    """A YAML flow list of expressions: [0.1, -l_1/2, 0]."""
    return "[" + ", ".join(_yaml_value(expression_text(x, numbers)) for x in entries) + "]"


def _looks_misplaced(joint: str, written: dict) -> bool:

    """Would the reader take a name in theta or d for a joint variable in the wrong column (a URDF
    joint named d_1 that turns)? Then `var:` says which symbol moves.

    >>> _looks_misplaced("R", {"theta": sympy.Symbol("d_1"), "d": sympy.Integer(0)})
    True
    """
    return any(misplaced_variable(joint, column, symbol.name, False)
               for column in ("theta", "d") for symbol in written[column].free_symbols)
