"""Random arms that satisfy Pieper's condition (a spherical wrist on an elbow, Stanford or
cylindrical arm), in either convention, with prismatic joints, joint offsets, base and tool steps,
lengths as symbols or as decimals: every real branch reaches the pose and one branch is q."""
import random

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from ik_checks import derived as solve
from ik_checks import said
from strategies import length_drawer
from test_inverse_robots import check_round_trip

from dhsym import Chain, DHRow, Step
from dhsym.core.robot import Robot
from dhsym.geometry.convert import convert_robot

pytestmark = pytest.mark.slow  # random arms solved in closed form: seconds to minutes per test

HALF = sympy.pi / 2


@st.composite
def pieper_arms(draw):
    length, sample = length_drawer(draw)

    sign = lambda: draw(st.sampled_from([1, -1]))  # noqa: E731
    offset = lambda: draw(st.sampled_from([0, 0, HALF, -sympy.pi / 6]))  # noqa: E731
    q = sympy.symbols("q_1:7", real=True)
    d = sympy.symbols("d_1:7", real=True)
    family = draw(st.sampled_from(["elbow", "stanford", "cylindrical"]))
    if family == "elbow":
        arm = [DHRow.revolute(q[0] + offset(), d=length(), a=length(), alpha=sign() * HALF, variable=q[0]),
               DHRow.revolute(q[1] + offset(), d=length(), a=length(False), variable=q[1]),
               DHRow.revolute(q[2] + offset(), a=length(), alpha=sign() * HALF, variable=q[2])]
    elif family == "stanford":
        arm = [DHRow.revolute(q[0] + offset(), d=length(), alpha=sign() * HALF, variable=q[0]),
               DHRow.revolute(q[1] + offset(), d=length(), alpha=sign() * HALF, variable=q[1]),
               DHRow.prismatic(d[2] + length(), variable=d[2])]
    else:
        arm = [DHRow.revolute(q[0] + offset(), d=length(), variable=q[0]),
               DHRow.prismatic(d[1] + length(), alpha=sign() * HALF, variable=d[1]),
               DHRow.prismatic(d[2], variable=d[2])]
    # the wrist centre off the elbow's axis (else θ3 would not move it): d4 ≠ 0 on an elbow arm
    wrist = [DHRow.revolute(q[3] + offset(), d=length(family != "elbow"), alpha=sign() * HALF, variable=q[3]),
             DHRow.revolute(q[4] + offset(), alpha=sign() * HALF, variable=q[4]),
             DHRow.revolute(q[5] + offset(), d=length(), a=length(), alpha=draw(st.sampled_from([0, HALF])),
                            variable=q[5])]
    base = draw(st.sampled_from([[], [Step("Tz", sympy.Rational(1, 4))], [Step("Rz", HALF), Step("Tx", length())]]))
    tool = draw(st.sampled_from([[], [Step("Tz", length())],
                                 [Step("Rx", sympy.pi), Step("Tz", sympy.Rational(1, 10))]]))
    plain = Chain(arm + wrist, "standard", base=base, tool=tool)
    used = {symbol: value for symbol, value in sample.items() if symbol in plain.symbols}  # drawn, maybe not chosen
    chain = Robot(plain, name=f"random {family} arm", sample=used)
    return convert_robot(chain, draw(st.sampled_from(["standard", "modified"])))


@settings(max_examples=6)
@given(pieper_arms(), st.integers(0, 10 ** 6))
def test_random_pieper_arms_round_trip(chain, seed):
    solution = solve(chain)
    assert said(solution.method).startswith("kinematic decoupling")
    check_round_trip(chain, solution, random.Random(seed), trials=2)


@settings(max_examples=2)
@given(st.sampled_from(["standard", "modified"]), st.integers(0, 10 ** 6))
def test_a_wrist_at_the_start_is_decoupled_too(convention, seed):
    q = sympy.symbols("q_1:7", real=True)
    lengths = sympy.symbols("L_1:7", real=True)
    rows = [DHRow.revolute(q[0], d=lengths[0], alpha=-HALF), DHRow.revolute(q[1], alpha=HALF),
            DHRow.revolute(q[2], d=lengths[1], a=lengths[2], alpha=HALF), DHRow.revolute(q[3], a=lengths[3]),
            DHRow.revolute(q[4], a=lengths[4], alpha=HALF), DHRow.revolute(q[5], d=lengths[5])]
    sample = {symbol: sympy.Rational(k + 3, 10) for k, symbol in enumerate(lengths)}
    chain = convert_robot(Robot(Chain(rows, "standard"), name="wrist first", sample=sample), convention)
    solution = solve(chain)
    assert "joints 1, 2 and 3 meet at a point fixed in the base" in said(solution.method)
    check_round_trip(chain, solution, random.Random(seed), trials=2)
