"""A URDF's `<inertial>` elements carried into the links of a DH table.

Link i of the table is everything joint i moves and joint i+1 does not: the URDF link after
joint i, every link joined to it by fixed joints, and any branch that leaves it through a joint
off the base → tip path (a gripper's fingers), held at that joint's zero. The links of a group are
merged into one body at the zero configuration: their masses add, the centre of mass is the
weighted mean, and each inertia tensor is turned into common axes and moved to the common centre
(the parallel-axis theorem). The merged body is then seen from DH frame i at the zero
configuration (`in_dh_frames`). Numbers stay exact, as written; a value that no longer ends as a
decimal (a mean over several masses) is rounded to 15 significant digits and the notes say so.

The reading reuses the URDF reader's exact numbers and rotations (`dhsym.io.urdf`), so a place
in an error is the attribute's own: FILE:LINE:COL.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import sympy

from ..core.inertia import LinkInertia, MassModel, entries, tensor
from ..errors import UserError
from ..geometry.rounding import fit
from .inertia import measured_slip, physical_problem

INERTIA_ATTRIBUTES = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
MAX_MERGED_LINKS = 200  # links merged into the bodies of one table, as many as a path may hold
G_SAMPLE = sympy.Rational("9.81")  # the sample value of g an imported robot with masses gets


@dataclass(frozen=True)
class Body:
    """A merged body in base coordinates at the zero configuration: mass, centre of mass, inertia
    tensor about the centre of mass (3×3), and the URDF links in it."""

    mass: sympy.Expr
    com: sympy.Matrix
    inertia: sympy.Matrix
    held: tuple  # joints off the path whose links are in it, held at zero
    place: str = ""  # FILE:LINE:COL of the first <inertial> in it


def link_bodies(reader, path: list, poses: dict) -> list:
    """The merged body of each moving joint of `path` (None where no link of its group has an
    `<inertial>`); `reader` is the URDF reader, `poses` each path link's pose at zero."""
    moving = [joint for joint in path if joint.get("type", "").strip() in ("revolute", "continuous", "prismatic")]
    children = [joint.find("child").get("link").strip() for joint in moving]
    on_path = set(poses)
    bodies, count = [], 0
    for k, start in enumerate(children):
        stop = children[k + 1] if k + 1 < len(children) else None
        group = _group(reader, start, stop, poses[start], poses)
        count += len(group)
        if count > MAX_MERGED_LINKS:
            raise UserError(f"more than {MAX_MERGED_LINKS} links hang on the joints of this path; choose a nearer "
                            "tip or a later base")
        parts = [part for part in (_inertial(reader, name, pose) for name, pose in group) if part is not None]
        held = tuple(reader.joints[name].get("name", "").strip() for name, _ in group[1:]
                     if name not in on_path and reader.joints[name].get("type", "").strip() != "fixed")
        body = _merged(parts, held) if parts else None
        if body is not None:
            first = next(name for name, _ in group if reader.links[name].find("inertial") is not None)
            body = dataclasses.replace(body, place=str(reader.where(reader.links[first].find("inertial"))))
        bodies.append(body)
    return bodies


def _group(reader, start: str, stop: str | None, pose: sympy.Matrix, poses: dict) -> list:
    """(link, pose at zero) of every link below `start` but not below `stop`; `poses` holds the
    path's links and gets the others."""
    found, waiting = [], [(start, pose)]
    while waiting:
        name, pose = waiting.pop()
        found.append((name, pose))
        for child in reader.children.get(name, []):
            if child == stop:
                continue
            if child not in poses:  # a branch off the path, held at its joint's zero
                joint = reader.joints[child]
                poses[child] = (pose * reader.origin(joint, joint.get("name", "").strip())).applyfunc(sympy.expand)
            waiting.append((child, poses[child]))
    return found


def _inertial(reader, name: str, pose: sympy.Matrix):
    """(mass, centre of mass, tensor about it) of one link in base coordinates, or None."""
    element = reader.links[name].find("inertial")
    if element is None:
        return None
    mass_element = element.find("mass")
    if mass_element is None:
        raise UserError(f"link {name!r}: <inertial> has no <mass>", reader.where(element))
    mass = reader.numbers(mass_element, "value", "", count=1)[0]
    if mass < 0:
        raise UserError(f"link {name!r}: the mass {mass_element.get('value')} is negative",
                        reader.where(mass_element, "value"))
    frame = (pose * reader.origin(element, f"{name} inertial")).applyfunc(sympy.expand)
    values = _tensor_values(reader, element, name)
    turn = frame[:3, :3]
    return mass, frame[:3, 3], (turn * tensor(values) * turn.T).applyfunc(sympy.expand)


def _tensor_values(reader, element, name: str) -> tuple:
    inertia = element.find("inertia")
    if inertia is None:
        raise UserError(f"link {name!r}: <inertial> has no <inertia>", reader.where(element))
    return tuple(reader.numbers(inertia, key, "0", count=1)[0] for key in INERTIA_ATTRIBUTES)


def _merged(parts: list, held: tuple) -> Body | None:
    """One body from (mass, com, tensor) parts: the parallel-axis theorem about the common centre."""
    mass = sympy.Add(*[m for m, _, _ in parts])
    if mass == 0:
        return None
    com = sum((m * c for m, c, _ in parts), sympy.zeros(3, 1)) / mass
    inertia = sympy.zeros(3, 3)
    for m, c, own in parts:
        d = c - com
        inertia += own + m * ((d.T * d)[0] * sympy.eye(3) - d * d.T)
    return Body(mass, com.applyfunc(sympy.expand), inertia.applyfunc(sympy.expand), held)


def in_dh_frames(bodies: list, frames: list) -> tuple:
    """(MassModel with each body seen from its DH frame i, whether a value was rounded, warnings):
    `frames` are the DH frames' poses at zero in base coordinates, frame i for body i (1..n). An
    inertia that no body can have (CAD exports have them) is left generic, with a warning, so that
    the robot file reads back."""
    links, rounded, warnings = [], False, []
    for number, (body, pose) in enumerate(zip(bodies, frames), 1):
        if body is None:
            links.append(LinkInertia())
            continue
        turn, origin = pose[:3, :3], pose[:3, 3]
        com = (turn.T * (body.com - origin)).applyfunc(sympy.expand)
        inertia = (turn.T * body.inertia * turn).applyfunc(sympy.expand)
        values = [body.mass, *com, *entries(inertia)]
        written = [fit(value) for value in values]
        rounded = rounded or any(w != v for w, v in zip(written, values))
        tensor_entries = tuple(written[4:])
        problem = physical_problem(tensor_entries)
        if problem:
            warnings.append(f"{body.place}: the inertia of DH link {number} is not one a body can have "
                            f"({problem.split(':')[0]}); it is left as the generic symbols I_xx{number} … I_yz{number}")

            tensor_entries = None
        elif measured_slip(tensor_entries):
            warnings.append(f"{body.place}: the inertia of DH link {number}: {measured_slip(tensor_entries)}")
        links.append(LinkInertia(written[0], tuple(written[1:4]), tensor_entries))
    given = tuple(links) if any(link.given for link in links) else ()
    return MassModel(given), rounded, warnings


def inertia_note(bodies: list, rounded: bool) -> str:
    """What the notes of an imported robot say about its masses ("" when the URDF gives none)."""
    if not any(bodies):
        return ""
    held = [name for body in bodies if body for name in body.held]
    return ("Masses, centres of mass and inertias from the URDF's <inertial> elements, seen from each DH frame i; "
            "links fixed to a moving link are merged into it"
            + (f"; links beyond joints off the path ({', '.join(held)}) are merged too, those joints at zero"
               if held else "")
            + ("; merged values that do not end as decimals are rounded to 15 significant digits" if rounded else ""))

