"""Standard ↔ modified DH, exactly and symbolically: the same joint variables and the same
base → tool transform for every joint value.

The two conventions use the same four kinds of step; only the grouping differs. Since Tx(a)
and Rx(α) commute, a standard chain Rz(θ1)Tz(d1)·[Tx(a1)Rx(α1)]·Rz(θ2)Tz(d2)·[Tx(a2)Rx(α2)]⋯
regroups into modified rows [Rx(αi−1)Tx(ai−1)Rz(θi)Tz(di)], with α0 = a0 = 0 and the last
Tx(an)Rx(αn) moved into the tool. The frames on the joint axes stay where they were.

>>> from dhsym.io.library import load
>>> modified = to_convention(load("planar2r").chain, "modified")
>>> [(r.alpha, r.a, r.d, r.theta) for r in modified.rows]
[(0, 0, 0, theta_1), (0, a_1, 0, theta_2)]
>>> [str(s) for s in modified.tool]
['Tx(a_2)']
>>> [(r.theta, r.d, r.a, r.alpha) for r in to_convention(modified, "standard").rows]
[(theta_1, 0, a_1, 0), (theta_2, 0, a_2, 0)]

`convert_robot` converts a `Robot` to one that keeps everything its file said (name, source, notes,
sample values, the number of its first frame — the frames on the joint axes are the same ones —,
how it wrote its numbers, the file, the warnings), its links' inertias moved into the new frames.

>>> convert_robot(load("planar2r"), "modified").name
'Planar elbow manipulator (2R)'
"""
from __future__ import annotations

import sympy

from ..core.chain import Chain, DHRow, plain
from ..core.inertia import MassModel
from ..core.robot import Robot
from ..core.transforms import CONVENTIONS, Step, rotation
from ..errors import UserError


def convert_robot(robot: Robot, convention: str) -> Robot:
    """The same robot in `convention`, with everything its file said."""
    chain = to_convention(robot.chain, convention)
    return robot.replace(chain=chain, masses=_moved_masses(robot.masses, robot.chain, chain))


def to_convention(chain: Chain, convention: str) -> Chain:
    """The same chain in `convention` (a copy when it already is in it)."""
    plain(chain)
    if convention not in CONVENTIONS:
        raise UserError(f"unknown convention {convention!r}; use standard or modified")
    if convention == chain.convention:
        return _copy(chain, convention, chain.rows, chain.base, chain.tool)
    if convention == "modified":
        return _standard_to_modified(chain)
    return _modified_to_standard(chain)


def _standard_to_modified(chain: Chain) -> Chain:
    """Each row takes the twist and length of the row before; the last pair goes to the tool.
    A base ending in Tx/Rx steps gives row 1 its α0, a0."""
    twist, length, kept = _x_steps(list(reversed(chain.base)))
    base, rows = list(reversed(kept)), []
    for row in chain.rows:
        rows.append(DHRow(row.joint, row.theta, row.d, length, twist, row.variable))
        twist, length = row.alpha, row.a
    tool = _nonzero([Step("Tx", length), Step("Rx", twist)]) + list(chain.tool)
    return _copy(chain, "modified", rows, base, tool)


def _modified_to_standard(chain: Chain) -> Chain:
    """Each row takes the twist and length of the row after; the first pair goes to the base.
    A tool starting with Tx/Rx steps gives the last row its a, α."""
    first = chain.rows[0]
    base = list(chain.base) + _nonzero([Step("Rx", first.alpha), Step("Tx", first.a)])
    last_twist, last_length, tool = _x_steps(list(chain.tool))
    rows = []
    for row, following in zip(chain.rows, list(chain.rows[1:]) + [None]):
        twist, length = (following.alpha, following.a) if following else (last_twist, last_length)
        rows.append(DHRow(row.joint, row.theta, row.d, length, twist, row.variable))
    return _copy(chain, "standard", rows, base, tool)


def _x_steps(steps: list) -> tuple:
    """At most one Rx and one Tx from the front of `steps` (they commute): (twist, length, the rest)."""
    taken = {}
    while steps and steps[0].kind in ("Rx", "Tx") and steps[0].kind not in taken:
        step = steps.pop(0)
        taken[step.kind] = step.value
    return taken.get("Rx", sympy.Integer(0)), taken.get("Tx", sympy.Integer(0)), steps


def _moved_masses(masses: MassModel, before: Chain, after: Chain) -> MassModel:
    """The links' parameters in the frames of the other convention. Spong's frame i is Craig's frame
    i moved by Tx(a_i) Rx(α_i) of the standard row i, and both move with link i; gravity stays in the
    first frame, which the regrouping keeps."""
    if not masses.links or before.convention == after.convention:
        return masses
    standard = before if before.convention == "standard" else after
    links = []
    for link, row in zip(masses.links, standard.rows):
        turn = rotation(0, row.alpha)[:3, :3]
        if before.convention == "standard":
            links.append(link.moved(turn, (row.a, 0, 0)))
        else:
            links.append(link.moved(turn.T, (-row.a, 0, 0)))
    return MassModel(tuple(links), masses.gravity, masses.numbers)


def _nonzero(steps) -> list[Step]:
    return [step for step in steps if step.value != 0]


def _copy(chain: Chain, convention: str, rows, base, tool) -> Chain:
    return Chain(rows, convention, base, tool, chain.simplifier)
