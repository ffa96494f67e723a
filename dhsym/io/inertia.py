"""Inertial parameters in robot files: each joint row's `mass`, `com` and `inertia`, and the
file's `gravity`, read with the safe parser and checked where they stand.

    joints:
      - {joint: R, theta: q_1, d: 0, a: l_1, alpha: 0,
         mass: m_1, com: [lc_1 - l_1, 0, 0], inertia: [0, 0, I_1, 0, 0, 0]}
    gravity: [0, -g, 0]

`com` is the link's centre of mass in the frame its row ends in; `inertia` the six entries
[Ixx, Iyy, Izz, Ixy, Ixz, Iyz] of its inertia tensor about the centre of mass, axes parallel to
that frame; `gravity` the acceleration of gravity in the first frame (the base frame when there
is one), [0, 0, -g] when not given. A row without them is fully symbolic (see dhsym.core.inertia).
A numeric mass must be positive, and a numeric tensor one that a body can have: its principal
moments are not negative and each is at most the sum of the other two.

>>> from dhsym.io.robotfile import load_robot_text
>>> robot = load_robot_text('''convention: standard
... joints: [{joint: R, theta: q_1, d: 0, a: 1, alpha: 0, mass: 2.5, com: [-0.5, 0, 0]}]
... gravity: [0, -9.81, 0]''', "arm.yaml")
>>> robot.masses.links[0].mass, robot.masses.links[0].com, robot.masses.gravity
(5/2, (-1/2, 0, 0), (0, -981/100, 0))
>>> load_robot_text('''convention: standard
... joints: [{joint: R, theta: q_1, d: 0, a: 1, alpha: 0, inertia: [1, 1, 3, 0, 0, 0]}]''', "arm.yaml")
... # doctest: +ELLIPSIS
Traceback (most recent call last):
dhsym.errors.UserError: arm.yaml:2:64: joint row 1 inertia: Ixx + Iyy ≥ Izz fails (1 + 1 < 3): no body has ...
"""
from __future__ import annotations

import sympy
import yaml

from ..core.inertia import INERTIA_ENTRIES, LinkInertia, MassModel, tensor
from ..errors import UserError
from .expr import Reading

ROW_KEYS = ("mass", "com", "inertia")
COM_FORM = "[x, y, z] (the centre of mass in the frame this row ends in)"
INERTIA_FORM = "[Ixx, Iyy, Izz, Ixy, Ixz, Iyz] (the tensor's entries about the centre of mass)"


def read_masses(reader, top: dict, variables) -> MassModel:
    """The mass model of a robot file: its rows' `mass`, `com`, `inertia` and its `gravity`;
    `reader` is the robot-file reader (dhsym.io.robotfile), `variables` the joint variables."""
    reading = Reading()  # how these numbers were written, apart from the table's
    links = []
    row_nodes = reader.sequence(top["joints"][1], "joints") if "joints" in top else []
    for number, node in enumerate(row_nodes, 1):
        items = {key.value: value for key, value in node.value if key.value in ROW_KEYS}
        links.append(_link(reader, items, f"joint row {number}", variables, reading))
    gravity = None
    if "gravity" in top:
        gravity = _vector(reader, top["gravity"][1], "gravity", 3, "[gx, gy, gz] (in the first frame)", variables,
                          reading, "gravity is one constant vector, given in the first frame")
    given = tuple(links) if any(link.given for link in links) else ()
    return MassModel(given, gravity, reading.numbers)


def _link(reader, items: dict, what: str, variables, reading: Reading) -> LinkInertia:
    mass = com = inertia = None
    if "mass" in items:
        mass = _value(reader, items["mass"], f"{what} mass", variables, reading)
        if mass.is_number and not mass.is_positive:
            raise UserError(f"{what} mass: must be more than 0, not {_shown(mass)}; give the link's mass in "
                            "kilograms (or a name such as m_1)", reader.where(items["mass"]))
    if "com" in items:
        com = _vector(reader, items["com"], f"{what} com", 3, COM_FORM, variables, reading)
    if "inertia" in items:
        inertia = _vector(reader, items["inertia"], f"{what} inertia", 6, INERTIA_FORM, variables, reading)
        problem = physical_problem(inertia)
        if problem:
            raise UserError(f"{what} inertia: {problem}", reader.where(items["inertia"]))
        slip = measured_slip(inertia)
        if slip:
            reader.warn(items["inertia"], f"{what} inertia: {slip}")
    return LinkInertia(mass, com, inertia)


def _vector(reader, node: yaml.Node, what: str, size: int, form: str, variables, reading: Reading,
            why: str = "") -> tuple:
    if not isinstance(node, yaml.SequenceNode):
        raise UserError(f"{what} must be a list of {size} values {form}, not a single value", reader.where(node))
    if len(node.value) != size:
        raise UserError(f"{what} must be a list of {size} values {form}, not {len(node.value)}", reader.where(node))
    return tuple(_value(reader, element, what, variables, reading, why) for element in node.value)


def _value(reader, node: yaml.Node, what: str, variables, reading: Reading, why: str = "") -> sympy.Expr:
    value, read = reader.read(node, what, table=False)
    reading.absorb(read)
    reader.reading.names += read.names  # two spellings of one printed name are warned about with the table's
    moving = sorted(value.free_symbols & set(variables), key=str)
    if moving:
        why = why or "a link's mass, centre of mass and inertia are constants, given in the link's own frame"
        raise UserError(f"{what}: {moving[0]} is a joint variable; {why}", reader.where(node))
    return value


MEASURED_SLIP = sympy.Rational(1, 10)  # of the moment: how far a measured table may miss the triangle inequality


def physical_problem(entries) -> str:
    """Why a numeric inertia tensor (six entries about the centre of mass) belongs to no body,
    else "": a negative principal moment, or one larger than the sum of the other two by more
    than MEASURED_SLIP of itself. Decided exactly: the tensor and ½·trace − tensor (the body's
    second moments) must both be positive semi-definite. Symbolic entries are not judged. A
    smaller excess is what a published, measured table can have (Armstrong, Khatib and Burdick's
    PUMA link 3, by 8.7 %): `measured_slip` words its warning.

    >>> physical_problem((1, 1, 1, 0, 0, 0)), physical_problem((1, 1, 1, 2, 0, 0))[:30]
    ('', 'not positive semi-definite: a ')
    >>> physical_problem([sympy.Rational(x) for x in ("0.066", "0.0125", "0.086", 0, 0, 0)])
    ''
    """
    if not all(sympy.sympify(x).is_number for x in entries):
        return ""
    matrix = tensor(entries)
    if not _semidefinite(matrix):
        return ("not positive semi-definite: a principal moment of inertia would be negative; give the entries of "
                "the tensor [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] as a URDF does")
    excess = _excess(matrix)
    if excess is None or excess[0] <= MEASURED_SLIP:
        return ""
    advice = "no body has these moments of inertia; each principal moment is at most the sum of the other two"
    slip = f"a measured table may miss it by up to {_percent(MEASURED_SLIP)} of the moment, not by " \
        f"{_percent(excess[0])}"
    broken = excess[1]
    if isinstance(broken, tuple):
        (i, j, k) = broken
        flat = "; a flat model that needs only one moment can give a thin disc's: the other two half of it" \
            if matrix[i, i] == matrix[j, j] == 0 else ""
        return f"{_inequality(matrix, broken)}: {advice} ({slip}{flat})"
    return f"the principal moments {broken} break the triangle inequality: {advice} ({slip})"


def measured_slip(entries) -> str:
    """The warning for a numeric inertia tensor whose largest moment exceeds the sum of the other
    two by at most MEASURED_SLIP of itself, as a published table of measured values can (its
    digits were measured, not derived); "" for any other tensor.

    >>> print(measured_slip([sympy.Rational(x) for x in ("0.066", "0.0125", "0.086", 0, 0, 0)]))
    Ixx + Iyy ≥ Izz fails by 0.0075 (0.066 + 0.0125 < 0.086), 8.7 % of Izz: no body has exactly these moments; \
used as written, as a measured table's may miss by up to 10 % (more is refused)
    """
    if not all(sympy.sympify(x).is_number for x in entries):
        return ""
    matrix = tensor(entries)
    excess = _excess(matrix) if _semidefinite(matrix) else None
    if excess is None or excess[0] > MEASURED_SLIP:
        return ""
    share, broken = excess
    if isinstance(broken, tuple):
        amount = matrix[broken[2], broken[2]] - matrix[broken[0], broken[0]] - matrix[broken[1], broken[1]]
        what = f"{_inequality(matrix, broken, amount)}, {_percent(share)} of I{INERTIA_ENTRIES[broken[2]]}"
    else:
        what = f"the principal moments {broken} break the triangle inequality by {_percent(share)} of the largest"
    return (f"{what}: no body has exactly these moments; used as written, as a measured table's may miss by up to "
            f"{_percent(MEASURED_SLIP)} (more is refused)")


def _excess(matrix: sympy.Matrix):
    """(how far the largest principal moment exceeds the sum of the other two, as a part of itself;
    the diagonal entries (i, j, k) that break Ixx + Iyy ≥ Izz, or the principal moments as text), or
    None when the triangle inequality holds."""
    if _semidefinite(matrix.trace() / 2 * sympy.eye(3) - matrix):
        return None
    if all(matrix[r, c] == 0 for r in range(3) for c in range(3) if r != c):
        for k in range(3):
            i, j = [m for m in range(3) if m != k]
            if matrix[i, i] + matrix[j, j] < matrix[k, k]:
                return (matrix[k, k] - matrix[i, i] - matrix[j, j]) / matrix[k, k], (i, j, k)
    moments = sorted(float(sympy.re(x)) for x in matrix.evalf(30).eigenvals(multiple=True))
    share = sympy.Rational(moments[2] - moments[0] - moments[1]) / sympy.Rational(moments[2])
    return share, ", ".join(f"{x:.4g}" for x in moments)


def _inequality(matrix: sympy.Matrix, broken: tuple, amount=None) -> str:
    """'Ixx + Iyy ≥ Izz fails (1 + 1 < 3)', with `amount`: 'fails by 1 (1 + 1 < 3)'."""
    names = [f"I{INERTIA_ENTRIES[m]}" for m in broken]
    values = [_shown(matrix[m, m]) for m in broken]
    by = f" by {_shown(amount)}" if amount is not None else ""
    return f"{names[0]} + {names[1]} ≥ {names[2]} fails{by} ({values[0]} + {values[1]} < {values[2]})"


def _percent(share) -> str:
    """0.087 → '8.7 %', 1 → '100 %': two significant digits, at least the whole number."""
    value = float(share) * 100
    return f"{value:.2g} %" if value < 10 else f"{value:.0f} %"


def _semidefinite(matrix: sympy.Matrix) -> bool:
    """Every principal minor is not negative."""
    minors = [matrix[k, k] for k in range(3)]
    minors += [matrix.extract([i, j], [i, j]).det() for i, j in ((0, 1), (0, 2), (1, 2))]
    minors.append(matrix.det())
    return not any(m.is_negative for m in minors)


def _shown(value) -> str:
    """A number as a robot file writes it (0.01, not 1/100), for a message."""
    from ..geometry.rounding import written_text  # only after a mistake: reading a file needs no geometry

    return written_text(value)
