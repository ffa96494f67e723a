"""Do two robot files describe the same kinematics from base to tool, for every joint value?
If not, say what a student can fix: the first joint axis that differs (direction or position),
a joint whose zero (offset) differs, or only the base or the tool frame.

Tables in different conventions or with different but equivalent frame choices are the same
kinematics. Joints are matched by position (joint i with joint i); constants by name, each
given the reference's sample value, else the candidate's, else a random value shared by both.
"Same" is proven by algebra (sample values in exactly) and by numbers: base → tool at random
configurations, agreeing to 1e-9; the diagnosis of a difference is numeric.

>>> from dhsym.io.library import load
>>> from dhsym.geometry.convert import convert_robot
>>> compare(convert_robot(load("puma560"), "standard"), load("puma560")).same
True
>>> print(compare(load("spatial3r"), load("inline6")).message)
the tables have 3 and 6 joints; they cannot describe the same robot
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass

import sympy

from ..core.chain import Chain, plain
from ..core.estimate import estimated_size
from ..core.numbering import Numbering
from ..core.numeric import NumericChain
from ..core.robot import Robot
from ..core.size import expanded_terms, rough_count
from ..core.transforms import joint_axis_frame
from ..core.verify import algebraically_equal
from ..errors import UserError
from .screws import rate

TOLERANCE = 1e-9
TRIALS = 8
# The proof by algebra writes base → tool out in full (sums of angles expanded); it is tried only
# when that is estimated small enough, so the verdict is the same on every machine. Numbers
# (per link, in floats) work for any chain.
ALGEBRA_MAX_NODES = 20_000  # estimated nodes of either plain product base → tool (a general 6-link chain: 19,000)
ALGEBRA_MAX_TERMS = 20_000  # terms written out (expanded_terms); a general 5-link chain: 1,224 (0.5 s)


@dataclass(frozen=True)
class Comparison:
    """The verdict: `same`, a `kind` (same, joints, base, tool, offset, direction, position,
    different), the joint it concerns (1-based) and a message for the student."""

    same: bool
    kind: str
    joint: int | None
    message: str

    def __str__(self) -> str:
        return self.message


def compare(candidate: Robot, reference: Robot, seed: int = 0) -> Comparison:
    """Compare `candidate` against `reference`, joint i with joint i, constants by name with their
    sample values; joints and rows named as the candidate's table numbers them (a wrist's 4..6)."""
    chain, other = candidate.chain, reference.chain
    if chain.n != other.n:
        return Comparison(False, "joints", None, f"the tables have {chain.n} and {other.n} joints; "
                          "they cannot describe the same robot")
    numbering = candidate.numbering
    for number, mine, theirs in zip(numbering.joints(chain), chain.rows, other.rows):
        if mine.joint != theirs.joint:
            return Comparison(False, "joints", number, f"joint {number} is {_type(mine.joint)} in yours but "
                              f"{_type(theirs.joint)} in the reference")
    values = _constants(candidate, reference, seed)
    mine, theirs = _numeric_fk(candidate, values), _numeric_fk(reference, values)
    rng = random.Random(seed)
    configurations = [[rng.uniform(-math.pi, math.pi) for _ in range(chain.n)] for _ in range(TRIALS)]
    if all(_close(mine(q), theirs(q)) for q in configurations):
        algebra = _algebra_agrees(candidate, reference)
        if algebra is not False:
            how = "by algebra and" if algebra is True else ""
            unproven = "" if algebra is True else f"; not proven by algebra: {algebra}"
            return Comparison(True, "same", None, f"same kinematics: base → tool agrees {how} at {TRIALS} "
                              f"random configurations (to 1e-9){unproven}".replace("agrees  at", "agrees at"))
    note = _names_note(chain, other)
    for kind, side in (("tool", "right"), ("base", "left")):
        if _constant_difference(mine, theirs, configurations, side):
            return Comparison(False, kind, None, f"the joints agree; only the {kind} frame differs" + note)
    shifts = _zero_shifts(chain, other, values, mine, theirs, configurations)
    if shifts:
        first = numbering.joint(min(shifts) + 1)  # as the table numbers it
        return Comparison(False, "offset", first, _offset_message(chain, numbering, shifts) + note)
    return _first_axis_difference(chain, other, numbering, values, note)


def _algebra_agrees(candidate: Robot, reference: Robot) -> bool | str:
    """Whether base → tool is identical by algebra (joint i's variable renamed to the reference's,
    constants by name, sample values in exactly); a reason instead when it is too large to expand."""
    chain, other = candidate.chain, reference.chain
    size = max(estimated_size(c, c.first_frame, c.last_frame, raw=True) for c in (chain, other))
    if size > ALGEBRA_MAX_NODES:
        return (f"base → tool has {rough_count(size)} expression nodes, more than the {ALGEBRA_MAX_NODES:,} "
                "that are expanded")
    names = {s.name: s for s in other.symbols}
    renamed = dict(zip(chain.joint_variables, other.joint_variables))
    renamed.update({s: names[s.name] for s in chain.symbols - set(chain.joint_variables) if s.name in names})
    sample = {s.name: v for s, v in list(candidate.sample.items()) + list(reference.sample.items())}
    exact = {s: sample[s.name] for s in other.symbols | set(renamed.values()) if s.name in sample}
    mine = chain.fk(raw=True).xreplace(renamed).xreplace(exact)
    theirs = other.fk(raw=True).xreplace(exact)
    memo: dict = {}
    terms = sum(expanded_terms(a, True, memo) + expanded_terms(b, True, memo) for a, b in zip(mine, theirs))
    if terms > ALGEBRA_MAX_TERMS:
        return f"written out, base → tool would have {rough_count(terms)} terms, more than the " \
               f"{ALGEBRA_MAX_TERMS:,} that are expanded"
    return all(algebraically_equal(a, b) for a, b in zip(mine, theirs))


def _type(joint: str) -> str:
    return "revolute" if joint == "R" else "prismatic"


def _constants(candidate: Robot, reference: Robot, seed: int) -> dict:
    """A number for every constant symbol, by name, the same for both chains."""
    rng = random.Random(seed + 1)
    names = {}
    for chain in (reference.chain, candidate.chain):
        variables = set(chain.joint_variables)
        for symbol in sorted(chain.symbols - variables, key=str):
            if symbol.name not in names:
                sample = {s.name: v for s, v in list(reference.sample.items()) + list(candidate.sample.items())}
                names[symbol.name] = float(sample.get(symbol.name, rng.uniform(0.5, 1.5)))
    return names


def _numeric_fk(robot: Robot, constants: dict):
    """q ↦ base → tool as a flat list of 12 floats, the constants filled in (core.numeric, step by
    step in floats, so that its cost grows with the number of joints and not with the expressions)."""
    numeric = NumericChain(robot.chain, constants)

    def fk(q):
        flat = [x for row in numeric.end(q)[:3] for x in row]
        if not all(math.isfinite(x) for x in flat):
            raise UserError(f"{robot.name or 'the robot'}: base → tool overflows the floating-point numbers at a "
                            "random configuration (lengths too large), so it cannot be compared by numbers")
        return flat
    return fk


def _close(a, b) -> bool:
    return max(abs(x - y) for x, y in zip(a, b)) <= TOLERANCE


def _as_matrix(flat) -> sympy.Matrix:
    return sympy.Matrix(3, 4, flat).col_join(sympy.Matrix([[0, 0, 0, 1]]))


def _constant_difference(mine, theirs, configurations, side: str) -> bool:
    """Whether theirs⁻¹·mine (side right: a tool) or mine·theirs⁻¹ (left: a base) is the same everywhere."""
    differences = []
    for q in configurations[:4]:
        a, b = _as_matrix(mine(q)), _as_matrix(theirs(q))
        differences.append(list(b.inv() * a if side == "right" else a * b.inv()))
    return all(max(abs(float(x - y)) for x, y in zip(d, differences[0])) <= 1e-7 for d in differences)


def _offset(mine, theirs, configurations, k: int, joint: str):
    """The shift δ with mine(q) = theirs(q + δ·e_k) at every configuration, else None."""
    def moved(q, delta):
        return theirs(q[:k] + [q[k] + delta] + q[k + 1:])
    rows_b, rows_c, targets = [], [], []
    for q in configurations[:4]:
        base = moved(q, 0.0)
        if joint == "R":  # theirs is A + B cos δ + C sin δ in the shifted joint
            half = moved(q, math.pi)
            middle = [(x + y) / 2 for x, y in zip(base, half)]
            rows_b += [x - m for x, m in zip(base, middle)]
            rows_c += [y - m for y, m in zip(moved(q, math.pi / 2), middle)]
            targets += [t - m for t, m in zip(mine(q), middle)]
        else:  # theirs is A + D δ
            rows_b += [y - x for x, y in zip(base, moved(q, 1.0))]
            targets += [t - x for t, x in zip(mine(q), base)]
    if joint == "R":
        c, s = _least_squares(rows_b, rows_c, targets)
        if abs(c * c + s * s - 1) > 1e-6:
            return None
        delta = math.atan2(s, c)
    else:
        norm = sum(x * x for x in rows_b)
        delta = sum(x * t for x, t in zip(rows_b, targets)) / norm if norm else 0.0
    if abs(delta) < 1e-9 or not all(_close(mine(q), moved(q, delta)) for q in configurations):
        return None
    return delta


def _least_squares(b: list, c: list, t: list) -> tuple[float, float]:
    """The (x, y) minimising Σ (b x + c y − t)²."""
    bb, bc, cc = sum(x * x for x in b), sum(x * y for x, y in zip(b, c)), sum(y * y for y in c)
    bt, ct = sum(x * z for x, z in zip(b, t)), sum(y * z for y, z in zip(c, t))
    det = bb * cc - bc * bc
    if abs(det) < 1e-12:
        return 0.0, 0.0
    return (bt * cc - ct * bc) / det, (bb * ct - bc * bt) / det


def _offset_message(chain: Chain, numbering: Numbering, shifts: dict) -> str:
    """`shifts`: {row index 0..n−1: δ}; joints and rows named as the table numbers them."""
    joints = sorted(shifts)
    exact = {k: _exact_shift(shifts[k], chain.rows[k].joint) for k in joints}
    fixes = []
    for k in joints:
        row = chain.rows[k]
        moving, written = ("θ", row.theta) if row.joint == "R" else ("d", row.d)
        fixes.append(f"{moving} = {_show_exact(written - exact[k])} in row {numbering.joint(k + 1)} instead of "
                     f"{_show_exact(written)}")
    if len(joints) == 1:
        return f"the same axes, but joint {numbering.joint(joints[0] + 1)}'s zero differs by " \
            f"{_show_exact(exact[joints[0]])}: write " + fixes[0]
    numbers = " and ".join(str(numbering.joint(k + 1)) for k in joints)
    if len(joints) == 2 and joints[1] == joints[0] + 1 and all(abs(exact[k]) == sympy.pi for k in joints):
        # Rz(π) Tx(a) Rx(α) Rz(π) = Tx(−a) Rx(−α): two half-turn zeros are one flipped twist
        row = numbering.joint(joints[0] + (1 if chain.convention == "standard" else 2))
        return (f"the same axes, but the zeros of joints {numbers} both differ by π: the sign of α (and of a) in "
                f"row {row} is flipped; flip it back, or write " + " and ".join(fixes))
    amounts = " and ".join(_show_exact(exact[k]) for k in joints)
    return f"the same axes, but the zeros of joints {numbers} differ by {amounts}: write " + "; ".join(fixes)


def _zero_shifts(candidate: Chain, reference: Chain, values: dict, mine, theirs, configurations) -> dict | None:
    """{joint index: δ} with mine(q) = theirs(q + δ) everywhere, found axis by axis: where the axis of
    joint j first differs, a turn (or slide) of an earlier joint that carries the reference's axis
    onto the candidate's is a shifted zero. None when no such shifts explain the difference."""
    n = candidate.n
    wanted = _axes_at(candidate, values)([0.0] * n)
    placed = _axes_at(reference, values)
    shift = [0.0] * n
    for j in range(1, n):
        if _same(placed(shift)[j], wanted[j]):
            continue
        for k in range(j - 1, -1, -1):
            delta = _carry(placed, shift, k, j, wanted[j], reference.rows[k].joint)
            if delta is not None and all(_same(a, b) for a, b in zip(placed(_moved(shift, k, delta))[:j + 1],
                                                                    wanted[:j + 1])):
                shift = _moved(shift, k, delta)
                break
        else:
            return None
    def shifted(q):
        return theirs([a + b for a, b in zip(q, shift)])
    if not all(_close(mine(q), shifted(q)) for q in configurations):
        for k in range(n - 1, -1, -1):  # a joint whose shift shows only in the tool (the last one, as a rule)
            delta = _offset(mine, shifted, configurations, k, candidate.rows[k].joint)
            if delta is not None:
                shift = _moved(shift, k, delta)
                break
        else:
            return None
    found = {k: _wrapped(d, candidate.rows[k].joint) for k, d in enumerate(shift) if abs(d) > 1e-9}
    return {k: d for k, d in found.items() if abs(d) > 1e-9} or None


def _moved(shift: list, k: int, delta: float) -> list:
    return shift[:k] + [shift[k] + delta] + shift[k + 1:]


def _wrapped(delta: float, joint: str) -> float:
    """An angle in (−π, π]; a length as it is."""
    if joint != "R":
        return delta
    wrapped = math.remainder(delta, 2 * math.pi)
    return math.pi if abs(wrapped + math.pi) < 1e-9 else wrapped


def _carry(placed, shift, k: int, j: int, target, joint: str):
    """The δ of joint k that puts the reference's axis j (point and direction) onto `target`."""
    def axis_j(delta):
        point, direction = placed(_moved(shift, k, delta))[j]
        return list(point) + list(direction)
    goal = list(target[0]) + list(target[1])
    if joint == "R":  # a turn about axis k: A + B cos δ + C sin δ
        zero, half, quarter = axis_j(0.0), axis_j(math.pi), axis_j(math.pi / 2)
        middle = [(a + b) / 2 for a, b in zip(zero, half)]
        c, s = _least_squares([a - m for a, m in zip(zero, middle)], [q - m for q, m in zip(quarter, middle)],
                              [g - m for g, m in zip(goal, middle)])
        return math.atan2(s, c) if abs(c * c + s * s - 1) < 1e-6 else None
    slope = [b - a for a, b in zip(axis_j(0.0), axis_j(1.0))]
    norm = sum(x * x for x in slope)
    return sum(x * (g - a) for x, g, a in zip(slope, goal, axis_j(0.0))) / norm if norm else None


def _same(axis, other) -> bool:
    """Two axes (point, direction) are the same directed line."""
    (p, u), (p_ref, u_ref) = axis, other
    if _distance(u, u_ref) > 1e-7:
        return False
    along = [a - b for a, b in zip(p, p_ref)]
    dot = sum(a * b for a, b in zip(along, u_ref))
    return math.sqrt(sum((a - dot * b) ** 2 for a, b in zip(along, u_ref))) <= 1e-7


def _axes_at(chain: Chain, values: dict):
    """q ↦ every joint axis (point, direction) in the base frame at configuration q, each direction
    along the joint's positive motion (d = −d3 moves along −z)."""
    numeric = NumericChain(plain(chain), values)
    fixed = {s: values[s.name] for s in chain.symbols if s.name in values}
    signs = [float(rate(row).xreplace(fixed)) for row in chain.rows]

    def axes(q):
        return [(point, [sign * x for x in direction]) for (point, direction), sign in zip(numeric.axes(q), signs)]
    return axes


def _exact_shift(delta: float, joint: str) -> sympy.Expr:
    """δ as a multiple of π/12 (revolute) or a short decimal (prismatic) when it is one."""
    if joint == "R":
        steps = round(delta / (math.pi / 12))
        if abs(delta - steps * math.pi / 12) < 1e-7:
            return steps * sympy.pi / 12
    return sympy.Rational(f"{delta:.6g}")


def _show_exact(value) -> str:
    return str(sympy.sympify(value)).replace("pi", "π").replace("*", "·")


def _first_axis_difference(candidate: Chain, reference: Chain, numbering: Numbering, values: dict,
                           note: str) -> Comparison:
    """The first joint whose axis (at the zero configuration) is not where the reference has it."""
    zero = [0.0] * candidate.n
    mine, theirs = _axes_at(candidate, values)(zero), _axes_at(reference, values)(zero)
    for index, ((p, u), (p_ref, u_ref)) in enumerate(zip(mine, theirs), 1):
        number = numbering.joint(index)
        if _distance(u, u_ref) > 1e-7:
            reversed_axis = _distance(u, [-x for x in u_ref]) <= 1e-7
            what = ("is reversed: the joint moves the other way round" if reversed_axis else
                    f"points along {_show(u)} at the zero pose; the reference's points along {_show(u_ref)}")
            return Comparison(False, "direction", number, f"joint {number}'s axis {what}; "
                              + _where_to_look(candidate, numbering, index, "the twist α") + note)
        along = [a - b for a, b in zip(p, p_ref)]
        dot = sum(a * b for a, b in zip(along, u_ref))
        off = [a - dot * b for a, b in zip(along, u_ref)]
        if math.sqrt(sum(x * x for x in off)) > 1e-7:
            return Comparison(False, "position", number, f"joint {number}'s axis points the right way but is "
                              f"shifted by {_show(off)} from the reference's; "
                              + _where_to_look(candidate, numbering, index, "the lengths a and d") + note)
    return Comparison(False, "different", None, "the joint axes agree at the zero pose, but base → tool differs "
                      "in more than one fixed frame" + note)


def _where_to_look(chain: Chain, numbering: Numbering, joint: int, what: str) -> str:
    """The row that places the axis of `joint` (1..n): the row before in standard DH, its own row in
    modified; named as the table numbers its rows."""
    row = joint_axis_frame(chain.convention, joint)
    if row == 0:
        return "check the base steps"
    return f"check {what} in row {numbering.joint(row)}" + (" and the rows before it" if row > 1 else "")


def _distance(a, b) -> float:
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def _show(v) -> str:
    return "(" + ", ".join(f"{0.0 if abs(x) < 5e-10 else x:.4g}" for x in v) + ")"


def _names_note(candidate: Chain, reference: Chain) -> str:
    mine = {s.name for s in candidate.symbols - set(candidate.joint_variables)}
    theirs = {s.name for s in reference.symbols - set(reference.joint_variables)}
    if mine == theirs or not mine or not theirs:  # a numeric table takes the other's sample values
        return ""
    only_mine, only_theirs = sorted(mine - theirs), sorted(theirs - mine)
    return (f" (constants are matched by name: {', '.join(only_mine) or 'none'} only in yours, "
            f"{', '.join(only_theirs) or 'none'} only in the reference)")


