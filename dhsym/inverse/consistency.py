"""What the target of an arm of fewer than six joints must satisfy besides the elements that are
the same in every pose: a coordinate of the position along one of the tool's axes that no joint
changes. A waist and three pitch joints keep the tool's point in the arm's plane, whose normal is
the tool's z: px r13 + py r23 + pz r33 = 0 in every pose. The generated module (`--format python`)
gives NaN for a target that breaks one, rather than joint values that miss it.

>>> import dhsym
>>> arm = dhsym.load("cylindrical_rpp").chain
>>> tool_relations(arm, ())
((px*r11 + py*r21 + pz*r31, 0),)
"""
from __future__ import annotations

import sympy

from ..core.chain import Chain
from ..core.verify import trig_canonical
from .fresh import reserved
from .sentences import Consistent
from .solution import target_matrix

POSE_JOINTS = 4  # from this many unknown joints on, ik() answers the whole pose (dhsym.inverse.reach)
OFF = 1e-6  # how far a relation may miss, relative to the pose's size (its elements are of order one)


def tool_relations(chain: Chain, fixed) -> tuple:
    """(px r1k + py r2k + pz r3k, value) for each tool axis k along which the position's coordinate
    is the same in every pose, the `fixed` elements [(element, value)] put in; none that they imply."""
    fk, target = chain.fk(), target_matrix(reserved(chain))
    moving, known = set(chain.joint_variables), dict(fixed)
    relations = []
    for k in range(3):
        value = trig_canonical(sum(fk[r, k] * fk[r, 3] for r in range(3)))
        side = sympy.expand(sum(target[r, k] * target[r, 3] for r in range(3)).xreplace(known))
        if not value.free_symbols & moving and side.free_symbols and (side, value) not in relations:
            relations.append((side, value))
    return tuple(relations)


def off_the_arm(solution, printer) -> list[str]:
    """The generated module's function `off_the_arm(elements)`: for the poses' elements (16, N), True
    where a pose breaks one of the arm's relations (an arm of POSE_JOINTS to five unknown joints), so
    that ik() gives NaN there; [] for any other arm. `printer` writes numpy code."""
    said = [c for c in solution.conditions if isinstance(c, Consistent)]
    kept = said[0].fixed + said[0].relations if said else ()
    if not kept or not POSE_JOINTS <= len(solution.joint_variables) < 6:
        return []
    elements = {t: sympy.Dummy(f"elements[{k}]") for k, t in enumerate(solution.target_symbols)}
    lines = ["def off_the_arm(elements):",
             '    """For the poses\' elements (16, N): True where the arm cannot take the pose."""',
             "    off = numpy.zeros(elements.shape[1], dtype=bool)",
             f"    tolerance = {OFF!r} * (1 + abs(elements[3]) + abs(elements[7]) + abs(elements[11]))"]
    for side, value in kept:
        lines.append(f"    off |= abs({printer.doprint((side - value).xreplace(elements))}) > tolerance")
    return lines + ["    return off", "", ""]
