"""A closed-form derivation of a plain chain, as a book lays it out: the structure of its axes
chooses the method (dhsym.inverse.methods), the method searches the equations for sub-problems,
a root that misses the pose is ruled out and the search run again, and every branch is named by
the signs it chose.

>>> import dhsym
>>> solution = derive(dhsym.load("planar2r").chain)
>>> solution.method
BySubproblems(used=(px, py), words=(), parallel=False)
>>> [branch.name for branch in solution.branches]
['elbow down', 'elbow up']
>>> solution.definitions
((D, (-a_1**2 - a_2**2 + px**2 + py**2)/(2*a_1*a_2)),)
>>> solution.branches[0].values()[solution.joint_variables[1]]
atan2(sqrt(1 - D**2), D)
"""
from __future__ import annotations

from dataclasses import replace
from itertools import product

import sympy

from ..core.chain import Chain, plain
from ..core.numbers import WrittenNumbers
from ..errors import UserError
from .bounds import redundancy, redundant_message, refuse_unbounded
from .branches import branch_name
from .consistency import tool_relations
from .fresh import reserved
from .methods import Problem, method_for
from .quartic import root_number
from .reach import wrong_root
from .sentences import Consistent
from .singular import explain_cases
from .solution import Branch, Solution, target_matrix, target_symbols
from .structure import analyse
from .witness import witness


def derive(chain: Chain, free=(), *, sample=None, numbers: WrittenNumbers | None = None, name: str = "",
           path: str = "<robot>") -> Solution:
    """The closed-form solution of `chain` (frames 0..n) for the target that `dhsym fk` prints,
    the joint variables `free` (symbols) kept as parameters; `sample` and `numbers` are the robot
    file's (numbers for its constants, how it wrote them), `name` and `path` name it in messages."""
    chain, numbers = plain(chain), numbers or WrittenNumbers()
    sample = {symbol: value for symbol, value in (sample or {}).items() if symbol in chain.symbols}  # not masses
    redundant = redundancy(chain, free, sample)  # before any algebra: the motions the unknowns make, the axes, the work
    if redundant:
        raise UserError(redundant_message(name, free, redundant))
    problem = _problem(chain, free, sample, numbers, path)
    found = _without_wrong_roots(problem)
    derivation, unknowns = found.derivation, problem.unknowns
    definitions, assignments = _shared_first(found.definitions, derivation.assignments, chain.joint_variables,
                                             derivation.signs)
    nonzero = {c for c in problem.constants if sample.get(c, 1) != 0}
    explain_cases(chain, derivation, found.definitions, sample, numbers, nonzero,
                  tie=len(unknowns) == 6 and chain.n == 6)
    conditions, method = list(derivation.conditions), found.method
    if len(unknowns) < 6:
        used = _used_elements(definitions, assignments, chain)
        method = replace(method, used=used)
        conditions.append(Consistent(len(unknowns), used, problem.fixed, tool_relations(chain, problem.fixed)))
    branches = _branches(assignments, derivation.signs, unknowns[0], found.wrist_joints)
    return Solution(chain, method, tuple(unknowns), tuple(definitions), tuple(branches), tuple(free),
                    tuple(dict.fromkeys(conditions)), tuple(dict.fromkeys(derivation.degenerate)),
                    tuple(derivation.steps), sample=sample, numbers=numbers)


def _problem(chain: Chain, free, sample: dict, numbers: WrittenNumbers, path: str) -> Problem:
    """What the derivation works with, checked and bounded before any algebra."""
    structure = analyse(chain, free, sample)
    refuse_unbounded(chain, path)
    unknowns = [chain.joint_variables[j - 1] for j in structure.unknowns]
    prismatic = {v for v, row in zip(chain.joint_variables, chain.rows) if row.joint == "P"} & set(unknowns)
    target, fixed = _target(chain, len(unknowns))  # its names primed where the robot uses them (dhsym.inverse.fresh)
    return Problem(chain, structure, sample, numbers, unknowns, prismatic, target, reserved(chain),
                   frozenset(chain.symbols - set(chain.joint_variables)), witness(chain, sample), fixed)


def _without_wrong_roots(problem: Problem):
    """What the method finds, found again with a one-root rule for each joint whose two roots were
    found not both to reach the pose (dhsym.inverse.reach) until none is left."""
    unique: set = set()
    method = method_for(problem.structure)
    while True:
        try:
            found = method(problem, frozenset(unique))
        except UserError as refusal:
            if not unique:
                raise
            joints = sorted(unique, key=problem.unknowns.index)
            raise type(refusal)(f"{refusal}; where {_names(joints)} came from an equation with two roots, one root "
                            f"missed the target (an arm of {len(problem.unknowns)} unknown joints cannot reach every "
                            f"pose), and no equation gives {'it' if len(joints) == 1 else 'them'} with one root"
                            ) from None
        wrong = wrong_root(problem.chain, problem.sample, found.definitions, found.derivation, problem.unknowns)
        if wrong is None or wrong in unique:
            return found
        unique.add(wrong)


def _target(chain: Chain, unknowns: int) -> tuple[sympy.Matrix, tuple]:
    """The target matrix; for an arm of fewer than six joints, the elements that are the same in
    every pose (a planar arm's r33 = 1, pz = 0) are put in as those numbers, and listed."""
    target = target_matrix(reserved(chain))
    if unknowns >= 6:
        return target, ()
    fk = chain.fk()
    moving = set(chain.joint_variables)
    fixed = {}
    for r in range(3):
        for c in range(4):
            if not fk[r, c].free_symbols & moving:
                fixed[target[r, c]] = fk[r, c]
    return target.xreplace(fixed), tuple(fixed.items())


def _names(variables) -> str:
    return ", ".join(map(str, variables))


def _shared_first(definitions, assignments, joints, signs):
    """Assignments that hold no joint variable and no sign move to the shared definitions."""
    branchy = set(joints) | {s for s, _, _ in signs}
    shared, rest = list(definitions), []
    for name, value in assignments:
        if name not in joints and not (value.free_symbols & (branchy | {n for n, _ in rest})):
            shared.append((name, value))
        else:
            rest.append((name, value))
    return shared, rest


def _used_elements(definitions, assignments, chain: Chain) -> tuple:
    """The target's elements the solution reads, in the target's order."""
    symbols = set().union(*(v.free_symbols for _, v in list(definitions) + list(assignments)))
    return tuple(t for t in target_symbols(reserved(chain)) if t in symbols)


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
