"""A URDF's `<limit lower upper>` carried into the joint limits of a DH table.

The frame assignment (dhsym.geometry.frames) points each DH z axis along the joint's positive
motion, so a DH variable equals the URDF joint's value (θi = qi + a constant, no sign flip): the
limits of qi are the URDF's, unchanged. A continuous joint has none; a revolute or prismatic joint
without `lower=` and `upper=` (a `<limit>` that gives only effort and velocity) has none either.
The numbers are exact, as written (2.8973 stays 2.8973, it is not snapped to a multiple of π/12).

>>> from dhsym.io.urdf import read_urdf_text
>>> chain = read_urdf_text(b'''<robot name="arm"><link name="a"/><link name="b"/><link name="c"/>
...   <joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
...     <limit lower="-2.8973" upper="2.8973" effort="87" velocity="2.175"/></joint>
...   <joint name="j2" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/></joint>
... </robot>''', "arm.urdf")
>>> chain.limits
[(-28973/10000, 28973/10000), None]
"""
from __future__ import annotations

BOUNDED = ("revolute", "prismatic")


def path_limits(reader, path: list) -> list:
    """The (lower, upper) limits of each moving joint of `path`, or None; `reader` is the URDF
    reader (its exact numbers, its warnings). Limits the wrong way round are a warning and dropped."""
    limits = []
    for joint in path:
        kind = joint.get("type", "").strip()
        if kind not in ("revolute", "continuous", "prismatic"):
            continue
        element = joint.find("limit")
        given = element is not None and (element.get("lower") is not None or element.get("upper") is not None)
        if kind not in BOUNDED or not given:
            limits.append(None)
            continue
        lower, upper = (reader.numbers(element, key, "0", count=1)[0] for key in ("lower", "upper"))
        if lower > upper:
            reader.warnings.append(f"{reader.where(element, 'lower')}: joint {joint.get('name', '').strip()!r}: "
                                   f"lower={element.get('lower')} is above upper={element.get('upper')}; its limits "
                                   "are left out")
            lower = None
        limits.append(None if lower is None else (lower, upper))
    return limits
