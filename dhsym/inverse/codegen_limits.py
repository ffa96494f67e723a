"""Joint limits in the module `dhsym ik --format python` writes, for a robot with limits: the
limits in the order of the module's JOINTS, the code of dhsym.inverse.joint_limits, and `ik`
wrapped so that `ik(T, within_limits=True)` drops the branches outside them; `nearest(Q, q)`
picks the branch nearest a configuration. A robot without limits gets nothing (its module is
unchanged). The section is added after the module dhsym.inverse.codegen writes.

>>> import dhsym, sympy
>>> arm = dhsym.load("planar2r")
>>> limits = joint_limit_lists(arm.chain, [(-sympy.pi, 0), None], arm.chain.joint_variables)
>>> limits
([-3.141592653589793, -inf], [0.0, inf], [True, True])
>>> print(limits_section(*limits).splitlines()[3])
LIMITS_LOWER = numpy.array([-3.141592653589793, -numpy.inf])
"""
from __future__ import annotations

import ast
import math
from pathlib import Path

RUNTIME = Path(__file__).parent / "joint_limits.py"

WRAPPER = '''
_every_branch = ik


def ik(T, within_limits=False, **constants):
    """Every branch's joint values for the pose(s) T (see the module's docstring); with
    within_limits=True, NaN for each branch with a joint outside its limits (LIMITS_LOWER,
    LIMITS_UPPER), and revolute angles moved by whole turns into their limits."""
    Q = _every_branch(T, **constants)
    return within_joint_limits(Q, LIMITS_LOWER, LIMITS_UPPER, LIMITS_REVOLUTE) if within_limits else Q


def nearest(Q, q_current):
    """The branch of ik(T)'s result Q nearest the joint values q_current (in the order of JOINTS;
    revolute angles compared modulo 2 pi), NaN where no branch exists."""
    return nearest_branch(Q, q_current, LIMITS_REVOLUTE)
'''


def joint_limit_lists(chain, joint_limits, joint_variables) -> tuple:
    """(lower, upper, revolute) as lists of floats and booleans in the order of `joint_variables`
    (a solution's, without its --free joints): ±inf for a joint without limits."""
    rows = {row.variable: (row, joint_limits[k] if joint_limits else None) for k, row in enumerate(chain.rows)}
    lower, upper, revolute = [], [], []
    for variable in joint_variables:
        row, pair = rows[variable]
        lower.append(float(pair[0]) if pair else -math.inf)
        upper.append(float(pair[1]) if pair else math.inf)
        revolute.append(row.joint == "R")
    return lower, upper, revolute


def limits_section(lower, upper, revolute) -> str:
    """The text added to a generated module: the limits, the code that applies them, the wrapper."""
    head = ["", "", "# ---- joint limits, from the robot file, in the order of JOINTS; inf: none "
            "(dhsym.inverse.joint_limits) ----",
            f"LIMITS_LOWER = numpy.array({_floats(lower)})",
            f"LIMITS_UPPER = numpy.array({_floats(upper)})",
            f"LIMITS_REVOLUTE = numpy.array({revolute!r})", "", ""]
    return "\n".join(head) + _runtime_code() + "\n\n" + WRAPPER


def _floats(values) -> str:
    return "[" + ", ".join(("-numpy.inf" if v < 0 else "numpy.inf") if math.isinf(v) else repr(v)
                           for v in values) + "]"


def _runtime_code() -> str:
    """dhsym.inverse.joint_limits without its docstring and imports (the module imports numpy)."""
    text = RUNTIME.read_text(encoding="utf-8")
    lines = text.splitlines()
    kept = [("\n".join(lines[node.lineno - 1:node.end_lineno])) for node in ast.parse(text).body
            if not isinstance(node, (ast.Import, ast.ImportFrom, ast.Expr))]
    return "\n\n\n".join(kept) + "\n"
