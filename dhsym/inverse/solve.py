"""Closed-form inverse kinematics of a chain: the method chosen from its axes, the equations
searched for sub-problems, every branch named.

>>> import dhsym
>>> solution = solve(dhsym.load("planar2r"))
>>> solution.method
'position problem by sub-problems (target elements used: px, py)'
>>> [branch.name for branch in solution.branches]
['elbow down', 'elbow up']
>>> solution.definitions
((D, (-a_1**2 - a_2**2 + px**2 + py**2)/(2*a_1*a_2)),)
>>> solution.branches[0].values()[solution.joint_variables[1]]
atan2(sqrt(1 - D**2), D)
"""
from __future__ import annotations

from itertools import product

import sympy

from ..core.robot import as_robot
from ..errors import UserError
from .bounds import redundancy, redundant_message, refuse_unbounded
from .branches import branch_name
from .equations import point_equations, transform_equations
from .fresh import fresh_symbol, reserved
from .pieper import pieper
from .quartic import root_number
from .reach import wrong_root
from .scan import Derivation, scan
from .singular import say_lined_up, tie_to_jacobian
from .solution import Branch, Solution, target_matrix, target_symbols
from .structure import analyse
from .witness import witness
from .wrist import centre, centre_at_start


def solve(chain, free=()) -> Solution:
    """The closed-form solution of `chain` for the target that `dhsym fk` prints; `free` names
    joint variables (symbols or their names) that are given parameters instead of unknowns.
    `chain` is a Robot (or a plain Chain): the math runs on its chain (frames 0..n), the robot
    names the frames and gives the sample values, and is the solution's `chain`."""
    robot = as_robot(chain)
    chain = robot.chain
    free = free_variables(chain, free)
    redundant = redundancy(robot, free)  # before any algebra: the motions the unknowns make, the axes, the work
    if redundant:
        raise UserError(redundant_message(robot, free, redundant))
    structure = analyse(robot, free)
    refuse_unbounded(robot)
    unknowns = [chain.joint_variables[j - 1] for j in structure.unknowns]
    prismatic = {v for v, row in zip(chain.joint_variables, chain.rows) if row.joint == "P"} & set(unknowns)
    target, fixed = _target(chain, len(unknowns))  # its names primed where the robot uses them (dhsym.inverse.fresh)
    unique: set = set()  # joints whose two roots were found not both to reach the pose
    while True:
        try:
            derivation, definitions, wrist_joints, method = _derive(robot, structure, unknowns, prismatic, target,
                                                                    frozenset(unique))
        except UserError as refusal:
            if not unique:
                raise
            joints = sorted(unique, key=unknowns.index)
            raise UserError(f"{refusal}; where {_names(joints)} came from an equation with two roots, one root "
                            f"missed the target (an arm of {len(unknowns)} unknown joints cannot reach every "
                            f"pose), and no equation gives {'it' if len(joints) == 1 else 'them'} with one root"
                            ) from None
        wrong = wrong_root(robot, definitions, derivation, unknowns)
        if wrong is None or wrong in unique:
            break
        unique.add(wrong)
    assignments = derivation.assignments
    definitions, assignments = _shared_first(definitions, assignments, chain.joint_variables, derivation.signs)
    conditions = list(derivation.conditions)
    used = _used_elements(definitions, assignments, chain)
    if len(unknowns) < 6:
        method += f" (target elements used: {', '.join(used)})"
        joints = f"{len(unknowns)} unknown joint{'s' if len(unknowns) != 1 else ''}"
        conditions.append(f"the arm has {joints}: only {', '.join(used)} are used, "
                          "and the other elements of the target must be consistent with them"
                          + (f" (in every pose of this arm {fixed})" if fixed else ""))
    say_lined_up(chain, derivation)
    if structure.wrist and len(unknowns) == 6 and chain.n == 6:
        tie_to_jacobian(chain, derivation, robot.sample, robot.numbers)
    branches = _branches(assignments, derivation.signs, unknowns[0], wrist_joints)
    return Solution(robot, method, tuple(unknowns), tuple(definitions), tuple(branches), tuple(free),
                    tuple(dict.fromkeys(conditions)), tuple(dict.fromkeys(derivation.degenerate)),
                    tuple(derivation.steps))


def _derive(robot, structure, unknowns, prismatic, target, unique):
    """(derivation, definitions, wrist joints, method line) by the method the axes choose; the
    joints in `unique` are solved only by a rule with one root."""
    chain = robot.chain
    names = reserved(chain)
    derivation = Derivation(reserved=names)
    constants = frozenset(chain.symbols - set(chain.joint_variables))
    numbers = witness(robot)
    definitions: list = []
    wrist_joints = []
    if structure.wrist and len(unknowns) > 3:
        wrist_joints = [chain.joint_variables[j - 1] for j in structure.wrist]
        holder, local, in_last = centre(chain, structure.wrist)
        point = target[:3, :3] * in_last + target[:3, 3]
        if any(x != 0 for x in in_last):
            point = _centre_named(point, names, definitions, numbers)
        arm = [v for v in unknowns if v not in wrist_joints]
        derivation, numbers, pieper_used = _arm(
            robot, point_equations(robot, point, sum(x ** 2 for x in point), local, holder), arm, prismatic,
            constants, numbers, unique, lambda fresh: pieper(robot, point, local, holder, arm, fresh,
                                                               taken=[n for n, _ in definitions]))
        scan(transform_equations(robot, target, position=False, start=holder), wrist_joints, prismatic, derivation,
             prefer=("orientation",), constants=constants, witness=numbers, unique=unique)
        method = (f"kinematic decoupling: the axes of joints {_joints(robot, structure.wrist)} meet at the wrist "
                  "centre; "
                  f"the position of the wrist centre gives {_names(arm)}"
                  + (_pieper_said(robot, derivation) if pieper_used else "")
                  + f", its orientation {_names(wrist_joints)}")
    elif structure.first_wrist:
        wrist_joints = [chain.joint_variables[j - 1] for j in structure.first_wrist]
        holder, local, in_first = centre_at_start(chain, structure.first_wrist)
        rotation_t = target[:3, :3].T
        point = rotation_t * (in_first - target[:3, 3])  # the centre seen from the last frame: Rᵀ(c − p)
        point = _centre_named(point, names, definitions, numbers)
        arm = [v for v in unknowns if v not in wrist_joints]
        derivation, numbers, pieper_used = _arm(  # as above, the arm counted from the end
            robot, point_equations(robot, point, sum(x ** 2 for x in point), local, holder, known_in=chain.last_frame),
            arm, prismatic, constants, numbers, unique,
            lambda fresh: pieper(robot, point, local, holder, arm[::-1], fresh, taken=[n for n, _ in definitions],
                                 known_in=chain.last_frame))
        scan(transform_equations(robot, target, position=False, end=holder), wrist_joints, prismatic, derivation,
             prefer=("orientation",), constants=constants, witness=numbers, unique=unique)
        method = (f"kinematic decoupling: the axes of joints {_joints(robot, structure.first_wrist)} meet at a "
                  f"point fixed in the base; that point seen from the last frame gives {_names(arm)}"
                  + (_pieper_said(robot, derivation) if pieper_used else "") + f", the orientation "
                  f"{_names(wrist_joints)}")
    elif structure.spherical:
        scan(transform_equations(robot, target, position=False), unknowns, prismatic, derivation,
             prefer=("orientation",), constants=constants, witness=numbers, unique=unique)
        wrist_joints = unknowns
        method = f"a spherical wrist: the axes of joints {_joints(robot, structure.unknowns)} meet in a point; " \
                 "the orientation gives the Euler angles"
    else:
        scan(transform_equations(robot, target, position=True), unknowns, prismatic, derivation,
             constants=constants, witness=numbers, unique=unique)
        method = "the sub-problems of the equations (Hawkins's way for three parallel axes)" \
            if structure.parallel and len(unknowns) == 6 else "position problem by sub-problems"
        if structure.parallel and len(unknowns) == 6:  # the joints after the parallel ones turn the tool
            wrist_joints = [chain.joint_variables[j - 1] for j in structure.unknowns if j > structure.parallel[-1]]
    return derivation, definitions, wrist_joints, method


def _arm(robot, equations, arm, prismatic, constants, numbers, unique, by_pieper):
    """(derivation, witness numbers, whether Pieper's quartic was used) for the position of a wrist
    centre: the sub-problems, else `by_pieper(fresh derivation)`, else the sub-problems' refusal."""
    names = reserved(robot.chain)
    derivation, kept = Derivation(reserved=names), dict(numbers)
    try:
        scan(equations, arm, prismatic, derivation, constants=constants, witness=numbers, unique=unique)
        return derivation, numbers, False
    except UserError as refusal:  # no sub-problem: Pieper's elimination, a quartic in tan(θ3/2)
        derivation = Derivation(reserved=names)
        try:
            by_pieper(derivation)
        except UserError:
            raise refusal from None
        return derivation, kept, True


def _target(chain, unknowns: int) -> tuple[sympy.Matrix, str]:
    """The target matrix; for an arm of fewer than six joints, the elements that are the same in
    every pose (a planar arm's r33 = 1, pz = 0) are put in as those numbers, and said."""
    target = target_matrix(reserved(chain))
    if unknowns >= 6:
        return target, ""
    fk = chain.fk()
    moving = set(chain.joint_variables)
    fixed = {}
    for r in range(3):
        for c in range(4):
            if not fk[r, c].free_symbols & moving:
                fixed[target[r, c]] = fk[r, c]
    said = ", ".join(f"{name} = {value}" for name, value in fixed.items())
    return target.xreplace(fixed), said


def free_variables(chain, free) -> tuple[sympy.Symbol, ...]:
    """The joint variables named in `free` (symbols or names), checked."""
    by_name = {str(v): v for v in chain.joint_variables}
    result = []
    for item in free:
        name = str(item).strip()
        if name not in by_name:
            raise UserError(f"--free {name}: no joint variable of that name; "
                            f"the joint variables are {', '.join(by_name)}")
        result.append(by_name[name])
    return tuple(dict.fromkeys(result))


def _joints(robot, numbers) -> str:
    """Joints 1..n as the robot numbers them (a wrist's 4..6)."""
    shown = [str(number + robot.frame_offset) for number in numbers]
    return ", ".join(shown[:-1]) + " and " + shown[-1]


def _pieper_said(robot, derivation) -> str:
    """How the method line says that Pieper's quartic gave the arm's joints."""
    joint = next(j for _, j, rule in derivation.signs if rule == "quartic")
    number = robot.chain.joint_variables.index(joint) + 1 + robot.frame_offset
    return f" as Pieper solved them: a quartic in tan(θ{number}/2), its roots by radicals (Ferrari)"


def _names(variables) -> str:
    return ", ".join(map(str, variables))


def _shared_first(definitions, assignments, joints, signs):
    """Assignments that hold no joint variable and no sign move to the shared definitions."""
    branchy = set(joints) | {s for s, _, _ in signs}
    shared, rest, moved = list(definitions), [], set()
    for name, value in assignments:
        if name not in joints and not (value.free_symbols & (branchy | {n for n, _ in rest})):
            shared.append((name, value))
            moved.add(name)
        else:
            rest.append((name, value))
    return shared, rest


def _used_elements(definitions, assignments, chain) -> list[str]:
    symbols = set().union(*(v.free_symbols for _, v in list(definitions) + list(assignments)))
    return [str(t) for t in target_symbols(reserved(chain)) if t in symbols]


def _centre_named(point, names, definitions: list, numbers: dict) -> sympy.Matrix:
    """The wrist centre's coordinates named x_c, y_c, z_c (primed where the robot uses those
    names), added to the definitions and to the witness numbers."""
    named = [fresh_symbol(name, names) for name in ("x_c", "y_c", "z_c")]
    definitions += list(zip(named, point))
    numbers.update({n: p.xreplace(numbers) for n, p in zip(named, point)})
    return sympy.Matrix(named)


def _branches(assignments, signs, first_joint, wrist_joints) -> list[Branch]:
    """One branch per choice of the signs, named in words."""
    branches, made = [], {}  # an assignment with the same signs in it is worked out once, not per branch
    held = [(n, v, tuple(s for s, _, _ in signs if s in v.free_symbols)) for n, v in assignments]
    for choice in product((1, -1), repeat=len(signs)):
        values = {s: c for (s, _, _), c in zip(signs, choice)}
        name = branch_name([(joint, rule, c) for (_, joint, rule), c in zip(signs, choice) if rule != "quartic"],
                           first_joint, wrist_joints)
        roots = [(joint, c) for (_, joint, rule), c in zip(signs, choice) if rule == "quartic"]
        if roots:  # the quartic's two signs choose one of its four roots
            said = f"quartic root {root_number(roots[0][1], roots[1][1])}"
            name = said if name == "the only solution" else f"{said}, {name}"
        for n, v, mine in held:
            key = (n, v, tuple(values[s] for s in mine))
            if key not in made:
                made[key] = v.xreplace({s: values[s] for s in mine})
        branches.append(Branch(name, tuple((n, made[(n, v, tuple(values[s] for s in mine))]) for n, v, mine in held)))
    return branches
