"""Checks every inverse-kinematics surface must pass, whoever made the solution: the JSON
contract (readable, consistent), the generated module (importable, right shapes, its branches
reach the pose, the original joint values among them)."""
import importlib.util
import json
import re

import numpy as np
import sympy

from dhsym.inverse.derive import derive
from dhsym.inverse.solution import TARGET_NAMES
from dhsym.inverse.solve import free_variables
from dhsym.printing.ik_sentences import PlainSentences

JSON_KEYS = {"robot", "convention", "joint_variables", "free", "method", "target", "definitions", "solutions",
             "conditions", "degenerate", "angles_solved_as_one"}
ALLOWED_FUNCTIONS = {sympy.atan2, sympy.sqrt, sympy.cos, sympy.sin, sympy.acos, sympy.asin, sympy.Abs, sympy.sign}


def check_json(text: str, chain) -> dict:
    """The documented keys; every expression read back by sympify; every joint assigned in every
    branch; each assignment uses only the target, the constants, the definitions and the names
    assigned before it; the target's names and the derivation's are never the robot's own (a
    robot's D or px stays its own; the derivation's get a prime, ʹ)."""
    data = json.loads(text)
    limited = bool(getattr(chain, "joint_limits", ()))  # a robot with joint limits has them in its JSON too
    assert set(data) == JSON_KEYS | ({"joint_limits"} if limited else set())
    robot = {s.name for s in chain.symbols}
    assert [name.rstrip("ʹ") for name in data["target"]] == list(TARGET_NAMES)
    assert not set(data["target"]) & robot
    assert data["joint_variables"] == [v.name for v in chain.joint_variables]
    constants = robot - set(data["joint_variables"]) | set(data["free"])
    known = set(data["target"]) | constants
    for name, expression in data["definitions"]:
        assert _names(expression) <= known, (name, expression)
        assert name not in robot, name
        known.add(name)
    assert data["solutions"], "no branch"
    for branch in data["solutions"]:
        assert set(branch) == {"name", "assignments"} and branch["name"]
        seen = set(known)
        for name, expression in branch["assignments"]:
            assert _names(expression) <= seen, (branch["name"], name, expression)
            assert name not in robot or name in data["joint_variables"], name
            seen.add(name)
        assert set(data["joint_variables"]) - set(data["free"]) <= {name for name, _ in branch["assignments"]}
    assert all(isinstance(text, str) for text in data["conditions"] + data["degenerate"])
    assigned = {name for branch in data["solutions"] for name, _ in branch["assignments"]}
    assigned |= {name for name, _ in data["definitions"]}
    for name, joints in data["angles_solved_as_one"]:  # a name the solution assigns, as a sum of joints
        assert name in assigned and _names(joints) <= set(data["joint_variables"]), (name, joints)
    return data


def used_target(data: dict) -> list:
    """The target's elements a solution reads (JSON), in the target's order, by their plain names
    (px, also where the solution calls it pxʹ)."""
    expressions = [e for _, e in data["definitions"]] + [e for b in data["solutions"] for _, e in b["assignments"]]
    used = set().union(*(_names(e) for e in expressions))
    return [plain for plain, name in zip(TARGET_NAMES, data["target"]) if name in used]


def _names(expression: str) -> set:
    """The names an expression uses, read with every name that is not called as a symbol: a robot's
    `len` or `E` is its constant, not Python's len() or Euler's number."""
    names = {name for name, call in re.findall(r"(?<![\w.])([^\W\d]\w*)(\s*\()?", expression) if not call} - {"pi"}
    value = sympy.sympify(expression, locals={name: sympy.Symbol(name) for name in names})
    functions = {type(f) for f in value.atoms(sympy.Function)}
    assert functions <= ALLOWED_FUNCTIONS, (expression, functions)
    return {s.name for s in value.free_symbols}


def derived(robot, free=()):
    """The derivation of a robot file's chain with its sample and numbers, as the solver makes it
    (dhsym.inverse.derive: its decimals not made symbols, its branches named by the signs)."""
    return derive(robot.chain, free_variables(robot.chain, free), sample=robot.sample, numbers=robot.numbers,
                  name=robot.name, path=robot.path)


def said(record, robot=None) -> str:
    """A sentence of the solver (its method, a condition, a degenerate case) as the JSON gives it."""
    return PlainSentences({"frame_offset": robot.numbering.offset if robot else 0}).sentence(record)


def import_module(path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def numeric_fk(chain, constants: dict):
    """q (n,) -> the 4×4 pose `dhsym fk` prints, with the constants given."""
    matrix = chain.fk().subs({s: constants[s.name] for s in chain.symbols if s.name in constants})
    return sympy.lambdify(chain.joint_variables, matrix, "numpy")


def sample_constants(chain) -> dict:
    return {str(symbol): float(value) for symbol, value in chain.sample.items()}


def random_joints(chain, rng, count: int) -> np.ndarray:
    """Joint values away from the singular edges: angles in ±(0.2 … 2.9), lengths in 0.1 … 0.5."""
    values = rng.uniform(0.2, 2.9, (count, chain.n)) * rng.choice([-1, 1], (count, chain.n))
    for k, row in enumerate(chain.rows):
        if row.joint == "P":
            values[:, k] = rng.uniform(0.1, 0.5, count)
    return values


def check_branches_reach(ik, chain, constants: dict, joints: np.ndarray, free=(), compare=TARGET_NAMES) -> None:
    """For every q: T = FK(q); every branch that exists reaches T (the elements `compare`: an arm
    with fewer than six joints reaches a part of the pose), and q is one of them. The joints
    named in `free` are given to `ik` as keyword arguments; its columns are the other joints."""
    wanted = [TARGET_NAMES.index(name) for name in compare]
    names = [v.name for v in chain.joint_variables]
    unknown = [k for k, name in enumerate(names) if name not in free]
    fk = numeric_fk(chain, constants)
    poses = np.array([np.array(fk(*q), dtype=float) for q in joints])
    found = np.array([ik(pose, **{name: q[names.index(name)] for name in free}) for q, pose in zip(joints, poses)])
    revolute = [k for k, row in enumerate(chain.rows) if row.joint == "R" and k in unknown]
    for pose, q, branches in zip(poses, joints, found, strict=True):
        existing = branches[np.isfinite(branches).all(axis=1)]
        assert len(existing), f"no branch reaches FK({q})"
        full = np.tile(q, (len(existing), 1))
        full[:, unknown] = existing
        for values in full:
            reached = np.array(fk(*values), dtype=float)[:3].reshape(12)[wanted]
            assert np.allclose(reached, pose[:3].reshape(12)[wanted], atol=1e-7), (q, values)
        difference = full - q
        difference[:, revolute] = (difference[:, revolute] + np.pi) % (2 * np.pi) - np.pi
        assert np.abs(difference).max(axis=1).min() < 1e-6, f"{q} is not among the branches {full}"
