"""Hypothesis strategies for robots as robot files write them: a first frame other than 0,
numbers written as decimals, joint offsets, fixed base and tool steps, sample values. The
frame bugs live there (a wrist numbered 3..6, a table of decimals), so every property about
numbering or round trips draws from these.

>>> from hypothesis import find
>>> find(robots(), lambda robot: robot.frame_offset > 0 and robot.base).frames[:2]
['base', 1]
"""
from __future__ import annotations

import sympy
from hypothesis import strategies as st

from dhsym import Robot
from dhsym.core.chain import Chain, DHRow
from dhsym.core.inertia import LinkInertia, MassModel
from dhsym.core.numbers import WrittenNumbers
from dhsym.core.transforms import Step

DECIMALS = [sympy.Rational(text) for text in ("0.1", "0.25", "0.425", "0.39225", "0.0892", "1.5")]
ANGLES = [sympy.Integer(0), sympy.pi / 2, -sympy.pi / 2, sympy.pi, sympy.pi / 6]


def real(name: str) -> sympy.Symbol:
    return sympy.Symbol(name, real=True)


@st.composite
def lengths(draw, name: str, decimals: bool):
    """0, a named constant (l_3), or a number: a decimal when the file writes decimals."""
    kind = draw(st.sampled_from(["zero", "symbol", "number"]))
    if kind == "zero":
        return sympy.Integer(0)
    if kind == "symbol":
        return real(name)
    return draw(st.sampled_from(DECIMALS)) if decimals else sympy.Integer(draw(st.integers(1, 3)))


def length_drawer(draw) -> tuple:
    """(length, sample) for a hypothesis test that builds arms: `length(may_be_zero=True)` draws 0,
    a decimal in 0.15..0.90, or a new symbol L_k whose value it puts in `sample`."""
    sample, count = {}, iter(range(1, 100))

    def length(may_be_zero=True):
        kind = draw(st.sampled_from((["zero"] if may_be_zero else []) + ["symbol", "decimal"]))
        value = sympy.Rational(draw(st.integers(15, 90)), 100)
        if kind == "zero":
            return sympy.Integer(0)
        if kind == "decimal":
            return value
        symbol = sympy.Symbol(f"L_{next(count)}", real=True)
        sample[symbol] = value
        return symbol
    return length, sample


@st.composite
def robots(draw, max_joints: int = 4, conventions=("standard", "modified")):
    """A Robot as read from a file: first_frame 0..5, decimals or not, offsets, base and tool
    steps, sample values for some constants."""
    offset = draw(st.integers(0, 5))
    decimals = draw(st.booleans())
    convention = draw(st.sampled_from(conventions))
    rows = []
    for k in range(1, draw(st.integers(1, max_joints)) + 1):
        number = offset + k  # variables named as the lecture numbers the joints: theta_4 for a wrist's first
        alpha = draw(st.sampled_from(ANGLES))
        a, d = draw(lengths(f"a_{number}", decimals)), draw(lengths(f"d_{number}", decimals))
        joint_offset = draw(st.sampled_from([0, 0, sympy.pi / 2, -sympy.pi / 2]))
        if draw(st.booleans()):
            rows.append(DHRow.revolute(real(f"theta_{number}") + joint_offset, d, a, alpha,
                                       variable=real(f"theta_{number}")))
        else:
            rows.append(DHRow.prismatic(real(f"q_{number}") + a, joint_offset, 0, alpha, variable=real(f"q_{number}")))
    fixed = st.lists(st.one_of(st.sampled_from(["Rx", "Ry", "Rz"]).map(lambda kind: Step(kind, sympy.pi / 2)),
                               st.sampled_from(["Tx", "Ty", "Tz"]).map(
                                   lambda kind: Step(kind, DECIMALS[2] if decimals else sympy.Integer(1)))),
                     max_size=2)
    chain = Chain(rows, convention, draw(fixed), draw(fixed))
    constants = sorted(chain.symbols - set(chain.joint_variables), key=str)
    sample = {s: draw(st.sampled_from(DECIMALS if decimals else [sympy.Integer(1), sympy.Integer(2)]))
              for s in constants if draw(st.booleans())}
    numbers = WrittenNumbers(places=5) if decimals else WrittenNumbers()
    return Robot(chain, name=draw(st.sampled_from(["arm", "wrist", "Ärm “3”"])), source="drawn by hypothesis",
                 notes=draw(st.sampled_from(["", "a note"])), sample=sample, numbers=numbers, frame_offset=offset)


@st.composite
def link_inertias(draw, number: int, decimals: bool):
    """What a robot file may say about link `number`: nothing (the generic symbols), numbers (a
    tensor some body has: about its centre, the moments of a box), names, or a mix."""
    kind = draw(st.sampled_from(["none", "numbers", "names", "mass only", "com only"]))
    if kind == "none":
        return LinkInertia()
    value = (lambda: draw(st.sampled_from(DECIMALS))) if decimals else (lambda: sympy.Integer(draw(st.integers(1, 3))))
    if kind == "names":
        return LinkInertia(real(f"m_{number}"), (real(f"lc_{number}"), 0, 0), (0, 0, real(f"I_{number}"), 0, 0, 0))
    mass = value()
    com = tuple(draw(st.sampled_from([sympy.Integer(0), value(), -value()])) for _ in range(3))
    if kind == "mass only":
        return LinkInertia(mass=mass)
    if kind == "com only":
        return LinkInertia(com=com)
    x, y, z = value(), value(), value()  # a box of sides x, y, z: moments m(y² + z²)/12 ...
    box = [mass * (y**2 + z**2) / 12, mass * (x**2 + z**2) / 12, mass * (x**2 + y**2) / 12]
    return LinkInertia(mass, com, (*box, 0, 0, 0))


@st.composite
def robots_with_masses(draw, max_joints: int = 4, conventions=("standard", "modified")):
    """A robot of `robots` with masses on some links and, perhaps, gravity of its own."""
    robot = draw(robots(max_joints, conventions))
    decimals = robot.numbers.places > 0
    links = tuple(draw(link_inertias(robot.frame_offset + k, decimals)) for k in range(1, robot.n + 1))
    gravity = draw(st.sampled_from([None, (0, 0, -sympy.Rational("9.81")), (0, -real("g"), 0)]))
    masses = MassModel(links if any(link.given for link in links) else (), gravity)
    return robot.replace(masses=masses)
