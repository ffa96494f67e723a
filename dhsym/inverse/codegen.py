"""`dhsym ik --format python`: a closed-form solution as a standalone Python module that needs
numpy only, what a course hands to the lab after the derivation.

The module defines `ik(T, **constants)`: T is one pose (4, 4) or many (N, 4, 4); it returns every
branch's joint values, shaped (B, n) or (N, B, n), branches in the order of `BRANCHES` (the
JSON's), joints in the order of `JOINTS`, revolute angles in [−π, π), NaN where a branch does not
exist. The robot's constants are keyword arguments whose defaults are the robot file's sample
values; a joint made a parameter with `--free` is a keyword argument without a default. The
intermediate values of a quartic's roots by radicals (dhsym.inverse.quartic) are computed in complex
numbers; an angle from them is NaN where its root is not real.

>>> import sympy
>>> from dhsym.core.chain import Chain, DHRow
>>> from dhsym.inverse.solution import Branch, Solution
>>> t, l = sympy.symbols("theta_1 l_1", real=True)
>>> arm = Chain([DHRow.revolute(t, a=l)], "standard")
>>> px, py = sympy.symbols("px py", real=True)
>>> solution = Solution(arm, "one angle", (t,), (), (Branch("only", ((t, sympy.atan2(py, px)),)),),
...                     sample={l: sympy.Rational(1, 2)})
>>> code = module_text(solution, "pendulum")
>>> namespace = {}
>>> exec(compile(code, "pendulum_ik.py", "exec"), namespace)
>>> namespace["ik"]([[0, -1, 0, 0], [1, 0, 0, 0.5], [0, 0, 1, 0], [0, 0, 0, 1]]).round(4).tolist()
[[1.5708]]
"""
from __future__ import annotations

import builtins
import keyword

import sympy
from sympy.printing.numpy import NumPyPrinter

from ..core.numbers import decimal_text
from .consistency import off_the_arm
from .fresh import PRIME
from .onepose import HELPERS, REAL_ANGLE, MathCode, Spelling, function_text, statement_lines
from .statements import comment_text, computation, members

ROUNDING = 1e-10  # a square root of −1e-16 at the edge of the workspace is a root of 0, not a missing branch
IMAGINARY = 1e-5  # a quartic's root found through complex numbers is real when its imaginary part is this small
# |sin θ5| below this: the wrist's axes line up and θ6 is taken through θ4 (the degenerate case's member),
# since the books' atan2(σ r32, −σ r31) is atan2 of rounding noise there; above it that form loses < 1e-9 rad
LINED_UP = 1e-6

_INTERNAL = {"T", "numpy", "ik", "BRANCHES", "JOINTS", "REVOLUTE", "ROUNDING", "root", "poses", "result",
             "angles", "elements", "missing", "k", "real_angle", "IMAGINARY", "math", "cmath", "one_pose",
             "root_one", "real_angle_one", "absent", "NUMBER", "off", "tolerance", "off_the_arm",
             "Q", "LINED_UP", "lined_up", "outside", "wrap_one", "angle",
             "many_poses", "CHUNK", "step", "start", "value"}  # the module's own names
_BUILTINS = frozenset(dir(builtins))  # len, float, abs, ...: a keyword argument of that name would hide them


class NumpyCode(Spelling, NumPyPrinter):
    """numpy.cos, numpy.sqrt, …; names made safe for Python (`names`: symbol name → Python name),
    a Dummy is a variable of the module's own, named already; decimals as the robot file wrote them."""

    CHOICE = ("lined_up = abs({guard}) < LINED_UP  # poses whose wrist's axes line up: {name} as its member",
              "if lined_up.any():",
              "    {name} = numpy.where(lined_up, {member}, {name})")

    def __init__(self, names: dict, numbers):
        super().__init__({"fully_qualified_modules": True})
        self.names, self.numbers = names, numbers


class _NumpyCode(NumpyCode):
    """numpy.arctan2 of values found through complex numbers, square roots at the workspace's edge."""

    def __init__(self, names: dict, numbers):
        super().__init__(names, numbers)
        self.complex: set = set()  # the module's variables that hold complex values (a quartic's roots)
        self.casting = False  # printing a value that is computed in complex numbers (dhsym.inverse.quartic)

    def is_complex(self, expr) -> bool:
        """Whether `expr` holds a complex variable outside an atan2 (whose value is real or NaN)."""
        if isinstance(expr, sympy.atan2):
            return False
        return expr in self.complex or any(self.is_complex(a) for a in expr.args)

    def _print_atan2(self, expr):
        if any(self.is_complex(a) for a in expr.args):  # real, or NaN where the root is not real
            return f"real_angle({self._print(expr.args[0])}, {self._print(expr.args[1])})"
        return super()._print_atan2(expr)

    def _print_acos(self, expr):
        if self.casting:
            return f"numpy.arccos({self._print(expr.args[0])} + 0j)"
        return super()._print_acos(expr)

    def _print_Pow(self, expr, rational=False):
        if expr.exp == sympy.Rational(1, 2) and self.casting:  # complex on purpose: the root of a negative number
            return f"numpy.sqrt({self._print(expr.base)} + 0j)"
        if expr.exp == sympy.Rational(1, 2):  # a root of −1e-16 at the edge of the workspace is a root of 0
            return f"root({self._print(expr.base)})"
        return super()._print_Pow(expr, rational)


def python_names(names) -> dict:
    """{symbol name: a Python identifier for it}: a keyword, a built-in (len, float), a name the
    module uses itself or one taken already gets a trailing underscore; leading underscores move to
    the end, a derivation's prime is spelt out (Dʹ: D_prime), and a name Python cannot spell in
    ASCII gets a plain replacement.

    >>> python_names(["theta_1", "lambda", "T", "x-1"])
    {'theta_1': 'theta_1', 'lambda': 'lambda_', 'T': 'T_', 'x-1': 'symbol_3'}
    >>> python_names(["len", "_l", "Dʹ"])
    {'len': 'len_', '_l': 'l_', 'Dʹ': 'D_prime'}
    """
    out, taken = {}, set()
    for position, name in enumerate(names):
        spelt = name.replace(PRIME, "_prime")
        bare = spelt.lstrip("_")
        safe = bare + "_" * (len(spelt) - len(bare))
        if not bare or not safe.isidentifier() or not safe.isascii():
            safe = f"symbol_{position}"
        while keyword.iskeyword(safe) or safe in _INTERNAL or safe in _BUILTINS or safe in taken:
            safe += "_"
        out[name] = safe
        taken.add(safe)
    return out


def default_text(value) -> str:
    """A sample value as the file wrote it: 0.4318, not 2159/5000."""
    value = sympy.nsimplify(value) if not isinstance(value, sympy.Basic) else value
    if value.is_Rational and (10 ** 30) % value.q == 0:
        return decimal_text(value) if not value.is_Integer else f"{int(value)}.0"
    return repr(float(value))


def module_text(solution, name: str = "", command: str = "") -> str:
    """The text of the standalone module for `solution` (see the module docstring); `name`: the
    robot's, `command` the one that made it, for its docstring."""
    chain = solution.chain
    joints = list(solution.joint_variables)
    names, constants = _names(solution)
    code = _NumpyCode(names, solution.numbers)
    keywords = _keywords(solution, names, constants)
    kinds = {row.variable: row.joint for row in chain.rows}
    revolute = tuple(k for k, joint in enumerate(joints) if kinds.get(joint) == "R")
    statements, columns = computation(solution, names, code)
    targets = _targets(solution, names)
    parameters = [keyword.split("=")[0] for keyword in keywords]
    off = off_the_arm(solution, code)  # an arm of fewer than six joints: a pose off its set gives NaN
    one = function_text(statements, columns, revolute, parameters, MathCode(names, solution.numbers, code.complex),
                        targets)
    body = _body(solution, names, code, statements, columns, targets)
    lines = [
        *_docstring(name, command, chain.convention, bool(one)),
        *(["import cmath"] if one and code.complex else []), *(["import math"] if one else []), "import numpy", "",
        f"BRANCHES = {tuple(branch.name for branch in solution.branches)!r}",
        f"JOINTS = {tuple(j.name for j in joints)!r}",
        f"REVOLUTE = {revolute!r}  # the positions of the revolute joints in JOINTS",
        f"ROUNDING = {ROUNDING!r}  # a square root of a number this close below 0 is a root of 0",
        "CHUNK = 8192  # poses worked out at a time: their arrays stay in the processor's cache, which is faster",
        *([f"LINED_UP = {LINED_UP!r}  # |sin| of the wrist's middle angle below this: its axes line up"]
          if members(solution) else []),
        *(["NUMBER = (int, float)  # constants of these types let one pose take the plain-float path"] if one else []),
        "", "",
        "def root(x):",
        "    return numpy.sqrt(numpy.where((x < 0) & (x > -ROUNDING), 0.0, x))", "", "",
        *(HELPERS if one else []),
        *(_REAL_ANGLE if code.complex else []),
        *(REAL_ANGLE if one and code.complex else []),
        *off,
        *one,
        f"def ik(T, *, {', '.join(keywords)}):" if keywords else "def ik(T):",
        '    """Every branch\'s joint values for the pose(s) T; see the module\'s docstring."""',
        "    T = numpy.asarray(T, dtype=float)",
        *(_dispatch(parameters, bool(off)) if one else []),
        "    if T.ndim not in (2, 3) or T.shape[-2:] != (4, 4):",
        '        raise ValueError(f"T must be one pose (4, 4) or many (N, 4, 4), not an array of shape {T.shape}")',
        *_chunks(len(solution.branches), len(joints), parameters),
        "    elements = numpy.ascontiguousarray(poses.reshape(-1, 16).T)  # each element's values side by side: faster",
        *body,
        *(["    result[:, :, off_the_arm(elements)] = numpy.nan"] if off else []),
        *_FINISH,
    ]
    return "\n".join(lines)


def _chunks(branches: int, joints: int, parameters) -> list[str]:
    """ik()'s batch path, many_poses() on CHUNK poses at a time, whose arrays stay in the processor's
    cache (where a constant holds a value per pose, on all of them at once); then many_poses()'s head."""
    call = ", ".join(["poses[start:start + step]", *parameters])
    values = ", ".join(parameters) + ("," if len(parameters) == 1 else "")
    each = f"any(numpy.ndim(value) for value in ({values}))" if parameters else "False"
    return ["    poses = T.reshape(-1, 4, 4)",
            f"    result = numpy.empty((len(poses), {branches}, {joints}))",
            f"    step = max(1, len(poses)) if {each} else CHUNK  # a constant per pose: all poses at once",
            "    for start in range(0, len(poses), step):",
            f"        result[start:start + step] = many_poses({call})",
            "    return result[0] if T.ndim == 2 else result", "", "",
            f"def many_poses({', '.join(['poses', *parameters])}):",
            '    """ik() of many poses (N, 4, 4) with numpy, shaped (N, B, n)."""']


_FINISH = [  # many_poses()'s last lines: angles into [-pi, pi), a branch whole or NaN, shaped (N, B, n)
    "    for k in REVOLUTE:  # into [-pi, pi): a turn off or on (exact), the remainder only where one is not enough",
    "        angles = result[:, k]",
    "        numpy.subtract(angles, 2 * numpy.pi, out=angles, where=angles >= numpy.pi)",
    "        numpy.add(angles, 2 * numpy.pi, out=angles, where=angles < -numpy.pi)",
    "        outside = (angles < -numpy.pi) | (angles >= numpy.pi)",
    "        if outside.any():",
    "            angles[outside] = numpy.remainder(angles[outside] + numpy.pi, 2 * numpy.pi) - numpy.pi",
    "    missing = ~numpy.isfinite(result).all(axis=1)  # a branch exists whole or not at all",
    "    numpy.copyto(result, numpy.nan, where=missing[:, None, :])",
    "    return result.transpose(2, 0, 1)", "",
]


def _docstring(name: str, command: str, convention: str, one: bool) -> list[str]:
    """The generated module's docstring: what ik() takes and returns."""
    return [f'"""Closed-form inverse kinematics of {comment_text(name)} ({convention} DH).\n',
            (f"Made by `{comment_text(command)}`.\n" if command else "Made by dhsym.\n"),
            "ik(T, **constants): T is one pose (4, 4) or many (N, 4, 4), the transform `dhsym fk` prints by",
            "default; the result holds every branch's joint values, shaped (B, n) or (N, B, n): branches in",
            "the order of BRANCHES, joints in the order of JOINTS, revolute angles in [-pi, pi), NaN where a",
            "branch does not exist. Needs numpy only. A value that branches share is computed once and named",
            "in the first branch that needs it (theta_1, theta_1_2 for the other root, ...).",
            *(["One pose, with plain numbers for the constants, is worked out in plain floats (one_pose, with",
               "math: faster for one pose), many poses with numpy; both give the same values."] if one else []),
            '"""']


def _keywords(solution, names: dict, constants) -> list[str]:
    """ik()'s keyword arguments: the constants with the file's sample values as defaults, then those
    without, then the --free joint variables."""
    sample = {str(symbol): value for symbol, value in solution.sample.items()}
    keywords = [f"{names[s.name]}={default_text(sample[s.name])}" for s in constants if s.name in sample]
    keywords += [names[s.name] for s in constants if s.name not in sample]
    return keywords + [names[s.name] for s in solution.free]


def _targets(solution, names: dict) -> list[tuple[int, str]]:
    """(index among the pose's elements, Python name) of each target element the solution reads."""
    used = set().union(*(value.free_symbols for _, value in solution.definitions),
                       *(value.free_symbols for branch in solution.branches for _, value in branch.assignments),
                       *(value.free_symbols for _, value in members(solution).values()))
    held = {symbol.name for symbol in used}
    return [(k, names[element.name]) for k, element in enumerate(solution.target_symbols) if element.name in held]


def _dispatch(parameters, checked: bool) -> list[str]:
    """ik()'s first lines: one pose of plain numbers goes to one_pose(), unless plain floats raise;
    where the arm has relations (`checked`), a pose that breaks one gives NaN there too."""
    numbers = "".join(f" and isinstance({name}, NUMBER)" for name in parameters)
    call = ", ".join(["T", *parameters])
    answer = (f"            Q = one_pose({call})\n"
              "            return numpy.full_like(Q, numpy.nan) if off_the_arm(T.reshape(16, 1))[0] else Q") \
        if checked else f"            return one_pose({call})"
    return [f"    if T.shape == (4, 4){numbers}:",
            "        try:",
            answer,
            "        except (ArithmeticError, ValueError, TypeError):  # a division by 0, ...: numpy's NaN below",
            "            pass"]


def _body(solution, names: dict, code, statements, columns, targets) -> list[str]:
    """many_poses()'s middle: the target's elements it reads, the result array, every branch's values."""
    body = [f"    {name} = elements[{k}]" for k, name in targets]
    body.append(f"    result = numpy.empty(({len(solution.branches)}, {len(solution.joint_variables)}, len(poses)))"
                "  # each value's poses side by side: faster")
    body.append('    with numpy.errstate(invalid="ignore", divide="ignore", over="ignore"):')
    return body + ["        " + line for line in _numpy_lines(statements, columns, code)]


def _numpy_lines(statements, columns, code) -> list[str]:
    """The batch path's computation: each statement in numpy, then each branch's values put in result."""
    out = statement_lines(statements, code)
    for number, values in enumerate(columns):
        for k, value in enumerate(values):
            text = "numpy.nan" if value is None else code.doprint(value)
            out.append(f"result[{number}, {k}] = {text}")
    return out


_REAL_ANGLE = [
    f"IMAGINARY = {IMAGINARY!r}  # a value found through complex numbers is real when its imaginary part is this small",
    "", "",
    "def real_angle(y, x):",
    '    """atan2 of values found through complex numbers (a quartic\'s roots): NaN where they are not real."""',
    "    real = (abs(numpy.imag(y)) <= IMAGINARY * (1 + abs(y))) & (abs(numpy.imag(x)) <= IMAGINARY * (1 + abs(x)))",
    "    return numpy.where(real, numpy.arctan2(numpy.real(y), numpy.real(x)), numpy.nan)", "", ""]


def keyword_names(solution) -> dict:
    """{name of a constant or --free joint variable: its keyword argument in the module's ik()}."""
    names, constants = _names(solution)
    return {s.name: names[s.name] for s in list(constants) + list(solution.free)}


def _names(solution) -> tuple[dict, list]:
    """(symbol name -> Python name for every name the module uses, the robot's constants in order)."""
    chain = solution.chain
    joints = list(solution.joint_variables)
    constants = sorted((s for s in chain.symbols if s not in chain.joint_variables), key=lambda s: s.name)
    definitions = [name for name, _ in solution.definitions]
    assigned = {name for branch in solution.branches for name, _ in branch.assignments}
    names = python_names([s.name for s in joints + constants + list(solution.free) + definitions]
                         + [s.name for s in solution.target_symbols]
                         + sorted({s.name for s in assigned} - {s.name for s in joints}))
    return names, constants
