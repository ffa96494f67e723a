"""A URDF (or a .xacro file) to a DH chain, as `dhsym import` does it, for Python users.

>>> from pathlib import Path
>>> imported = import_urdf(Path(__file__).parents[2] / "tests" / "data" / "panda.urdf", convention="modified")
>>> imported.chain.n, imported.chain.convention, imported.chain.rows[0].d
(7, 'modified', 333/1000)
>>> imported.robot.notes[:61]
'Derived by dhsym import; joint variables: q_1 = panda_joint1,'

Joint i is the i-th revolute, continuous or prismatic joint from base to tip; its variable
equals the joint's value: q_i, or with `variables="urdf"` the joint's own name where that is
a name a robot file can hold (`right_s0`; `joint-1` becomes `joint_1`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import sympy

from ..core.inertia import GRAVITY_SYMBOL
from ..core.numbers import table_numbers
from ..core.robot import Robot
from ..errors import UserError
from ..geometry.frames import assign_frames
from ..geometry.rounding import joined
from .expr import parse_expression
from .urdfinertia import G_SAMPLE, in_dh_frames, inertia_note

_NAME_START = re.compile(r"^[A-Za-z]")


@dataclass(frozen=True)
class Imported:
    """What an import gives: the robot (its notes name the URDF joint of each variable, its
    warnings are the URDF reader's) and the URDF joint of each row."""

    robot: Robot
    joint_names: list = field(default_factory=list)

    @property
    def chain(self):
        return self.robot.chain

    @property
    def warnings(self) -> tuple:
        return self.robot.warnings


def import_urdf(path: str | Path, base: str | None = None, tip: str | None = None, convention: str = "standard",
                variables: str = "q", xacro_args: dict | None = None, package_paths=()) -> Imported:
    """The DH chain of a URDF's base → tip path; a `.xacro` file, or any file that holds xacro
    elements, is expanded first with the xacro arguments `xacro_args` (NAME → VALUE) and ROS
    packages found in `package_paths` too (see io.xacro, io.packages)."""
    if variables not in ("q", "urdf"):
        raise UserError(f"unknown variable style {variables!r}; use q or urdf")
    urdf, expansion_warnings = read_chain(path, base, tip, xacro_args, package_paths)
    symbols = joint_symbols(urdf.joint_names, variables)
    notes = "Derived by dhsym import; joint variables: " + ", ".join(
        f"{v} = {name}" for v, name in zip(symbols, urdf.joint_names))
    assignment = assign_frames(urdf.axes, urdf.tool, convention, symbols)
    masses, rounded, odd = in_dh_frames(urdf.bodies, [frame.pose for frame in assignment.frames[1:]])
    robot = assignment.robot(
        numbers=table_numbers(chain_numbers(assignment.chain())),  # decimals, as its robot file writes them
        name=urdf.name, source=f"{Path(path).name}, links {urdf.base} → {urdf.tip}",
        notes=joined(notes, inertia_note(urdf.bodies, rounded)), masses=masses,
        sample={GRAVITY_SYMBOL: G_SAMPLE} if masses.given else {}, joint_limits=urdf.limits,
        warnings=[*expansion_warnings, *urdf.warnings, *odd])

    return Imported(robot, list(urdf.joint_names))


def chain_numbers(chain) -> list:
    """The numbers a chain's table writes as numbers: each term's coefficient in d, a, θ, α and
    the base's and tool's steps, but a multiple of π's (pi/2 is written so)."""
    values = [value for row in chain.rows for value in (row.d, row.a, row.theta, row.alpha)]
    values += [step.value for step in (*chain.base, *chain.tool)]
    coefficients = [term.as_coeff_Mul() for value in values for term in sympy.Add.make_args(sympy.sympify(value))]
    return [number for number, rest in coefficients if not rest.has(sympy.pi)]


def read_chain(path, base, tip, xacro_args=None, package_paths=()):
    """(the URDF's base → tip chain, the warnings of its expansion): a file is expanded by xacro
    when it is named .xacro or holds xacro elements (with one warning then)."""
    from .urdf import read_urdf_text  # lxml only when a URDF is read
    from .xmlsource import read_regular_file, xacro_element

    warnings = []
    data = read_regular_file(path)
    used = None if str(path).lower().endswith(".xacro") else xacro_element(data, str(path))
    if not str(path).lower().endswith(".xacro") and used is None:
        if xacro_args:
            warnings.append(f"{path}: --xacro-arg is ignored: the file is a URDF, not a xacro file")
        return read_urdf_text(data, str(path), base, tip), warnings
    from .xacro import expand_xacro

    if used is not None:
        warnings.append(f"{used[0]}: <{used[1]}> is a xacro element, so the file is expanded by xacro although it is "
                        f"named {Path(path).suffix or 'without .xacro'}")
    expanded = expand_xacro(path, warnings, xacro_args, package_paths)
    return read_urdf_text(expanded, f"{path} (expanded by xacro)", base, tip), warnings


def joint_symbols(names: list[str], style: str) -> list[sympy.Symbol]:
    """q_1..q_n, or the URDF names made into symbols ('joint-1' → joint_1); q_i where that fails
    (a name that is not a name in a robot file, such as pi or sin, or one taken already), never
    a name that another joint has.

    >>> joint_symbols(["shoulder pan", "2nd", "pi"], "urdf")
    [shoulder_pan, q_2, q_3]
    >>> joint_symbols(["q_2", "elbow", "sin"], "urdf")
    [q_2, elbow, q_3]
    >>> joint_symbols(["a", "q_1", "sin"], "urdf")
    [a, q_1, q_3]
    >>> joint_symbols(["q_2", "sin"], "urdf")
    [q_2, q_2_2]
    """
    if style != "urdf":
        return [sympy.Symbol(f"q_{number}", real=True) for number in range(1, len(names) + 1)]
    made = [re.sub(r"\W+", "_", name).strip("_") for name in names]
    usable = [bool(_NAME_START.match(name)) and _reads_back(name) and made.count(name) == 1 for name in made]
    taken = {name for name, ok in zip(made, usable) if ok}
    symbols = []
    for number, (name, ok) in enumerate(zip(made, usable), 1):
        if not ok:
            name, extra = f"q_{number}", 1
            while name in taken:
                extra += 1
                name = f"q_{number}_{extra}"
            taken.add(name)
        symbols.append(sympy.Symbol(name, real=True))
    return symbols


def _reads_back(name: str) -> bool:
    try:
        return parse_expression(name) == sympy.Symbol(name, real=True)
    except UserError:
        return False
