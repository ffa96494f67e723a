"""The methods of a course, one function each, as the axes choose them (dhsym.inverse.structure):

- `decouple_at_wrist`: the last three axes meet at the wrist centre; its position gives the arm's
  joints (by the sub-problems, else by Pieper's quartic), the orientation the wrist's (Pieper,
  Craig §4.6; Spong's p − d6 R z);
- `decouple_at_base`: the first three axes meet at a point fixed in the base; that point seen from
  the last frame gives the joints after them, the orientation the first three;
- `euler_wrist`: a spherical wrist alone, its Euler angles from the orientation;
- `by_subproblems`: the search through Paul's equations (Hawkins's way for three parallel axes).

Each takes the `Problem` (what one derivation works with, made once per call) and the joints
that must be solved by a rule with one root, and returns what it `Found`: the derivation, the
definitions shared by every branch (the wrist centre's x_c, y_c, z_c), the wrist's joints (for
the branch names) and the method as a record (dhsym.inverse.sentences).

>>> import dhsym
>>> from dhsym.inverse.structure import analyse
>>> method_for(analyse(dhsym.load("puma560").chain)).__name__
'decouple_at_wrist'
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from ..core.chain import Chain
from ..core.numbers import WrittenNumbers
from ..errors import UserError
from .equations import point_equations, transform_equations
from .fresh import fresh_symbol
from .pieper import pieper
from .scan import Derivation, scan
from .sentences import BySubproblems, Decoupled, EulerWrist, Method
from .structure import Structure
from .wrist import centre, centre_at_start


@dataclass
class Problem:
    """What one derivation works with, worked out once per call: the chain (frames 0..n) and its
    structure, the robot file's `sample` and `numbers`, the unknowns (the slides among them), the
    target matrix, the robot's own names (which the derivation's never take), its constants, and
    the numbers of one generic pose (`witness`, copied by each attempt)."""

    chain: Chain
    structure: Structure
    sample: dict
    numbers: WrittenNumbers
    unknowns: list
    prismatic: set
    target: sympy.Matrix
    names: frozenset
    constants: frozenset
    witness: dict = field(repr=False)
    fixed: tuple = ()  # (element, value) of the target the same in every pose (an arm of fewer than six joints)


@dataclass
class Found:
    """What a method found: the derivation, the definitions shared by every branch, the wrist's
    joints (for the branches' names) and the method."""

    derivation: Derivation
    definitions: list
    wrist_joints: list
    method: Method


def method_for(structure: Structure):
    """The method the axes choose."""
    if structure.wrist and len(structure.unknowns) > 3:
        return decouple_at_wrist
    if structure.first_wrist:
        return decouple_at_base
    if structure.spherical:
        return euler_wrist
    return by_subproblems


def decouple_at_wrist(problem: Problem, unique) -> Found:
    """Kinematic decoupling at the wrist centre p_c = p + R·c (c the centre in the last frame)."""
    chain, target, joints = problem.chain, problem.target, problem.structure.wrist
    witness, definitions = dict(problem.witness), []
    wrist = [chain.joint_variables[j - 1] for j in joints]
    holder, local, in_last = centre(chain, joints)
    point = target[:3, :3] * in_last + target[:3, 3]
    if any(x != 0 for x in in_last):
        point = _centre_named(point, problem.names, definitions, witness)
    arm = [v for v in problem.unknowns if v not in wrist]
    equations = point_equations(chain, point, sum(x ** 2 for x in point), local, holder)
    derivation, witness, quartic = position_of_centre(
        problem, equations, arm, witness, unique,
        lambda fresh: pieper(chain, problem.numbers, point, local, holder, arm, fresh,
                             taken=[n for n, _ in definitions]))
    scan(transform_equations(chain, target, position=False, start=holder), wrist, problem.prismatic, derivation,
         prefer=("orientation",), constants=problem.constants, witness=witness, unique=unique, first=wrist[1::-1],
         last=wrist[2:])
    return Found(derivation, definitions, wrist,
                 Decoupled(wrist=joints, arm=tuple(arm), oriented=tuple(wrist), quartic=quartic))


def decouple_at_base(problem: Problem, unique) -> Found:
    """Kinematic decoupling at a point fixed in the base where the first three axes meet: seen from
    the last frame it is Rᵀ(c − p), and gives the joints after the three, counted from the end."""
    chain, target, joints = problem.chain, problem.target, problem.structure.first_wrist
    witness, definitions = dict(problem.witness), []
    wrist = [chain.joint_variables[j - 1] for j in joints]
    holder, local, in_first = centre_at_start(chain, joints)
    point = _centre_named(target[:3, :3].T * (in_first - target[:3, 3]), problem.names, definitions, witness)
    arm = [v for v in problem.unknowns if v not in wrist]
    equations = point_equations(chain, point, sum(x ** 2 for x in point), local, holder, known_in=chain.last_frame)
    derivation, witness, quartic = position_of_centre(
        problem, equations, arm, witness, unique,
        lambda fresh: pieper(chain, problem.numbers, point, local, holder, arm[::-1], fresh,
                             taken=[n for n, _ in definitions], known_in=chain.last_frame))
    scan(transform_equations(chain, target, position=False, end=holder), wrist, problem.prismatic, derivation,
         prefer=("orientation",), constants=problem.constants, witness=witness, unique=unique)
    return Found(derivation, definitions, wrist,
                 Decoupled(wrist=joints, arm=tuple(arm), oriented=tuple(wrist), at_start=True, quartic=quartic))


def euler_wrist(problem: Problem, unique) -> Found:
    """A spherical wrist on its own: the orientation gives the Euler angles."""
    derivation = Derivation(reserved=problem.names)
    middle = problem.unknowns[1::-1] if len(problem.unknowns) == 3 else ()  # the books' θ5, then θ4, then θ6
    scan(transform_equations(problem.chain, problem.target, position=False), problem.unknowns, problem.prismatic,
         derivation, prefer=("orientation",), constants=problem.constants, witness=dict(problem.witness),
         unique=unique, first=middle, last=problem.unknowns[2:] if middle else ())
    return Found(derivation, [], list(problem.unknowns), EulerWrist(joints=problem.structure.unknowns))


def by_subproblems(problem: Problem, unique) -> Found:
    """The sub-problems of Paul's equations; for six joints with three parallel axes (Hawkins's
    way) the joints after the parallel ones turn the tool, and are named as a wrist's."""
    chain, structure = problem.chain, problem.structure
    derivation = Derivation(reserved=problem.names)
    scan(transform_equations(chain, problem.target, position=True), problem.unknowns, problem.prismatic, derivation,
         constants=problem.constants, witness=dict(problem.witness), unique=unique)
    parallel = bool(structure.parallel) and len(problem.unknowns) == 6
    wrist = [chain.joint_variables[j - 1] for j in structure.unknowns if j > structure.parallel[-1]] if parallel else []
    return Found(derivation, [], wrist, BySubproblems(parallel=parallel))


def position_of_centre(problem: Problem, equations, arm, witness: dict, unique, by_pieper):
    """(derivation, witness numbers, the joint (1..n) of Pieper's quartic or None) for the position
    of a wrist centre: the sub-problems, else `by_pieper(fresh derivation)`, else the
    sub-problems' refusal."""
    derivation, kept = Derivation(reserved=problem.names), dict(witness)
    try:
        scan(equations, arm, problem.prismatic, derivation, constants=problem.constants, witness=witness,
             unique=unique)
        return derivation, witness, None
    except UserError as refusal:  # no sub-problem: Pieper's elimination, a quartic in tan(θ3/2)
        derivation = Derivation(reserved=problem.names)
        try:
            by_pieper(derivation)
        except UserError:
            raise refusal from None
        joint = next(j for _, j, rule in derivation.signs if rule == "quartic")
        return derivation, kept, problem.chain.joint_variables.index(joint) + 1


def _centre_named(point, names, definitions: list, witness: dict) -> sympy.Matrix:
    """The wrist centre's coordinates named x_c, y_c, z_c (primed where the robot uses those
    names), added to the definitions and to the witness numbers."""
    named = [fresh_symbol(name, names) for name in ("x_c", "y_c", "z_c")]
    definitions += list(zip(named, point))
    witness.update({n: p.xreplace(witness) for n, p in zip(named, point)})
    return sympy.Matrix(named)
