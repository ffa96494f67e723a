"""`dhsym ik --format python` for an arm solved numerically: a standalone module that needs numpy
only, with the interface of the closed-form module (dhsym.inverse.codegen): `ik(T, **given)` takes
one pose (4, 4) or many (N, 4, 4) and returns every real solution, shaped (16, n) or (N, 16, n),
each solution once, in order of its joint values, NaN after the last; a joint given with --free
is a keyword argument without a default. It also has `nearest(T, seed)`, the solution nearest a
configuration. The module holds the arm in numbers and the code of dhsym.inverse.numeric.runtime,
copied: it computes what `dhsym.inverse.numeric` computes.

>>> import dhsym, numpy
>>> from dhsym.inverse.numeric.solver import numeric_inverse
>>> puma = dhsym.load("puma560")
>>> ik = numeric_inverse(puma.chain, sample=puma.sample, name=puma.name)
>>> namespace = {}
>>> exec(compile(module_text(ik), "puma_ik.py", "exec"), namespace)
>>> T = ik.pose([0.3, -0.4, 0.5, -0.6, 0.7, -0.8])
>>> bool(numpy.array_equal(namespace["ik"](T), ik.solve(T), equal_nan=True))
True
"""
from __future__ import annotations

import ast
import keyword
from pathlib import Path

from .variants import SIZE

RUNTIME = Path(__file__).parent / "runtime"
PARTS = (("chain", "the chain in numbers: poses, Jacobian, Newton, damped least squares"),
         ("elimination", "every root of the loop: Raghavan and Roth's elimination"),
         ("solve", "every real solution: the roots polished, checked, each kept once"))
_RESERVED = {"T", "numpy", "ik", "nearest", "solve", "ARM", "JOINTS", "REVOLUTE", "SIZE", "TOLERANCE", "given",
             "poses", "result", "seed", "limits"}


def module_text(inverse, command: str = "") -> str:
    """The module's text for `inverse` (a dhsym.inverse.numeric.solver.NumericInverse)."""
    arm, data = inverse.arm, inverse.runtime()
    names = _python_names(inverse.free_variables)
    keywords = ", ".join(names[name] for name in inverse.free_variables)
    given = ", ".join(f"numpy.broadcast_to(numpy.asarray({names[n]}, dtype=float).reshape(-1), (len(poses),))"
                      for n in inverse.free_variables)
    lines = _docstring(arm, data, command)
    for part, what in PARTS:
        lines += [f"# ---- {what} (dhsym.inverse.numeric.runtime.{part}) ----", "", _code_of(part), ""]
    lines += [
        f"JOINTS = {arm.variables!r}",
        f"REVOLUTE = {tuple(k for k, kind in enumerate(arm.kinds) if kind == 'R')!r}  # positions in JOINTS",
        f"SIZE = {SIZE}  # the most solutions a six-joint arm has at a pose",
        "ARM = {",
        "    \"frames\": numpy.array([  # X0 … Xn: the constant transforms around the joints' motions",
        *(line for frame in data["frames"] for line in _rows(frame)),
        "    ]),",
        *(f"    {key!r}: {data[key]!r}," for key in ("kinds", "slopes", "free", "variants", "scale", "size",
                                                   "tolerance")),
        "}", "", "",
        f"def ik(T, *, {keywords}):" if keywords else "def ik(T):",
        '    """Every real solution at the pose(s) T; see the module\'s docstring."""',
        "    T = numpy.asarray(T, dtype=float)",
        "    if T.ndim not in (2, 3) or T.shape[-2:] != (4, 4):",
        '        raise ValueError(f"T must be one pose (4, 4) or many (N, 4, 4), not an array of shape {T.shape}")',
        "    poses = T.reshape(-1, 4, 4)",
        f"    given = numpy.stack([{given}], axis=1)" if given else "    given = numpy.zeros((len(poses), 0))",
        "    result = solve(ARM, poses, given)",
        "    return result[0] if T.ndim == 2 else result", "", "",
        "def nearest(T, seed, limits=None):",
        '    """The joint values nearest `seed` (n,) that reach the pose T (every joint moves, a given one too);',
        '    `limits` (n, 2), the lower and upper value of each joint, keeps them within. NaN where none is found."""',
        "    slopes = numpy.asarray(ARM[\"slopes\"])",
        "    bounds = None if limits is None else numpy.sort(numpy.asarray(limits, dtype=float) * slopes[:, None],",
        "                                                    axis=1)",
        "    amounts, missed = nearest_amounts(ARM[\"frames\"], ARM[\"kinds\"], numpy.asarray(T, dtype=float),",
        "                                      numpy.asarray(seed, dtype=float) * slopes, bounds)",
        "    values = wrapped(amounts / slopes, ARM[\"kinds\"])",
        "    return numpy.where(missed < ARM[\"tolerance\"], values, numpy.nan)", "",
    ]
    return "\n".join(lines)


def _docstring(arm, data: dict, command: str) -> list[str]:
    """The module's docstring and its import: what ik() and nearest() give, the arm's constants."""
    constants = ", ".join(f"{name} = {value!r}" for name, value in sorted(arm.constants.items())) or "none"
    return [
        f'"""Every solution of the inverse kinematics of {_comment(arm.name)} ({arm.convention} DH), numerically.\n',
        (f"Made by `{_comment(command)}`." if command else "Made by dhsym.") + " No closed form is used: the loop",
        "equation is reduced to one polynomial (Raghavan and Roth's elimination), whose roots are the",
        "eigenvalues of a 24 x 24 matrix; each root is polished by Newton's method on the pose and kept",
        f"when it reaches the pose within {data['tolerance']:.3g}.\n",
        "ik(T): T is one pose (4, 4) or many (N, 4, 4), the transform `dhsym fk` prints by default; the result",
        f"holds every real solution, shaped ({SIZE}, n) or (N, {SIZE}, n): each solution once, in order of its",
        "joint values, joints in the order of JOINTS, revolute angles in [-pi, pi), NaN after the last solution.",
        "nearest(T, seed): the one solution nearest the joint values `seed`, by damped least squares.",
        f"The arm's constants: {_comment(constants)}. Needs numpy only.",
        '"""',
        "import numpy", "", "",
    ]


def _code_of(part: str) -> str:
    """A runtime file's code without its docstring and its imports (the module imports numpy once)."""
    text = (RUNTIME / f"{part}.py").read_text(encoding="utf-8")
    tree = ast.parse(text)
    body = tree.body[1:] if isinstance(tree.body[0], ast.Expr) else tree.body
    lines = text.splitlines()
    kept = []
    for node in body:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            continue
        kept.append("\n".join(lines[node.lineno - 1 - _decorators(node):node.end_lineno]))
    return "\n\n\n".join(kept)


def _decorators(node) -> int:
    return len(getattr(node, "decorator_list", ()))


def _rows(matrix) -> list[str]:
    """A 4 × 4 transform as lines of the module: its rows, floats that read back exactly."""
    rows = [repr([float(x) for x in row]) for row in matrix[:3]] + ["[0.0, 0.0, 0.0, 1.0]"]
    return [f"        [{rows[0]},", *(f"         {row}," for row in rows[1:3]), f"         {rows[3]}],"]


def _python_names(names) -> dict:
    """{joint variable name: the keyword argument for it}: safe from Python's keywords and the module's names."""
    out = {}
    for position, name in enumerate(names):
        safe = name if name.isidentifier() and name.isascii() else f"joint_{position}"
        while keyword.iskeyword(safe) or safe in _RESERVED or safe in out.values():
            safe += "_"
        out[name] = safe
    return out


def _comment(text: str) -> str:
    """Text from a robot file, safe inside a docstring: one line, no quotes to end it."""
    return " ".join(str(text).split()).replace("\\", "/").replace('"""', "'''")
