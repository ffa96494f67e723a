"""The dynamics as a standalone Python module that needs numpy only (`--format python`).

The module defines M(q), C(q, qd), g(q), tau(q, qd, qdd) (inverse dynamics, by the Newton–Euler
recursion) and qdd(q, qd, tau) (forward dynamics: M q̈ = τ − C q̇ − g, solved). Each takes one
state, arrays of shape (n,), or many at once, (N, n), and returns the same number of states.
The robot's constants are keyword arguments whose defaults are the robot file's sample values (a
constant without one must be given). Every value the program names is computed once, in the
order of the program, so that common sub-expressions are shared as they were found.

>>> import dhsym
>>> from dhsym.core.chain import Chain, DHRow
>>> from dhsym.core.inertia import LinkInertia, MassModel
>>> from dhsym.dynamics.program import dynamics_program
>>> q, l, m, g = sympy.symbols("q l m g", real=True)
>>> pendulum = Chain([DHRow.revolute(q)], "modified")
>>> masses = MassModel((LinkInertia(m, (l, 0, 0), (0,) * 6),), gravity=(0, -g, 0))
>>> code = module_text(dynamics_program(pendulum, masses), "pendulum", {l: 1, m: 2, g: sympy.Rational("9.81")})
>>> namespace = {}
>>> exec(compile(code, "pendulum_dynamics.py", "exec"), namespace)
>>> namespace["tau"]([0.0], [0.0], [1.0]).round(4).tolist(), namespace["g"]([[0.0], [1.5707963]]).round(4).tolist()
([21.62], [[19.62], [0.0]])
>>> namespace["__all__"]
['JOINTS', 'M', 'C', 'g', 'tau', 'qdd']
"""
from __future__ import annotations

import sympy

from ..inverse.codegen import NumpyCode, comment_text, default_text, python_names
from .program import Program

INTERNAL = {"numpy", "q", "qd", "qdd", "tau", "_tau", "result", "single", "_states", "bias", "JOINTS", "M"}  # in bodies
PUBLIC = ("JOINTS", "M", "C", "g", "tau", "qdd")  # the module's __all__; its helpers start with _
SIGNATURES = {"M": ("q",), "C": ("q", "qd"), "g": ("q",), "tau": ("q", "qd", "qdd")}
WHAT = {"M": "the mass matrix M(q), shaped (n, n) or (N, n, n)",
        "C": "the Coriolis and centrifugal matrix C(q, qd) (Christoffel form), shaped (n, n) or (N, n, n)",
        "g": "the gravity torques g(q), shaped (n,) or (N, n)",
        "tau": "the joint torques (forces of prismatic joints) M qdd + C qd + g by Newton-Euler, shaped (n,) or (N, n)"}


def keyword_names(program: Program) -> dict:
    """{name of a constant: its keyword argument in the module's functions} (`g` stays `g`,
    a constant named `M` or `lambda` gets a trailing underscore)."""
    names = _names(program)
    return {s.name: names[s.name] for s in program.constants()}


def _names(program: Program) -> dict:
    """{symbol name: Python name}, none of them a name the module uses itself."""
    names = python_names([s.name for s in [*program.variables, *program.rates, *program.accelerations,
                                           *program.constants()]])
    taken = set(names.values())
    for name, safe in names.items():
        if safe in INTERNAL:
            while safe in INTERNAL or safe in taken:
                safe += "_"
            names[name] = safe
            taken.add(safe)
    return names



def module_text(program: Program, name: str, sample: dict, numbers=None, command: str = "") -> str:
    """The text of the standalone module of `program` (see the module's docstring)."""
    constants = program.constants()
    names = _names(program)

    code = NumpyCode(names, numbers)
    values = {s.name: v for s, v in sample.items()}
    keywords = [f"{names[s.name]}={default_text(values[s.name])}" for s in constants if s.name in values]
    keywords += [names[s.name] for s in constants if s.name not in values]
    renamed = _variable_names(program.tape, set(names.values()))
    n = len(program.variables)
    made = f"Made by `{comment_text(command)}`." if command else "Made by dhsym."
    lines = [f'"""Dynamics of {comment_text(name)}: M, C, g, tau and qdd. {made}\n',
             "Each function takes one state, arrays of shape (n,), or many, shaped (N, n); joints in the order",
             "of JOINTS (their values as the robot file's joint variables: theta_i or d_i, offsets included), SI",
             'units as the robot file gives them. The constants are keyword arguments. Needs numpy only.\n"""',
             "import numpy", "", f"__all__ = {list(PUBLIC)!r}", "",
             f"JOINTS = {tuple(v.name for v in program.variables)!r}", "", "",
             "def _states(x):", "    x = numpy.asarray(x, dtype=float)",
             f"    if x.shape[-1:] != ({n},) or x.ndim > 2:",
             f'        raise ValueError(f"expected states of shape ({n},) or (N, {n}), not {{x.shape}}")',
             f"    return x.reshape(-1, {n}), x.ndim == 1", ""]
    signature = ", ".join(keywords)
    for function in ("M", "C", "g", "tau"):
        lines += ["", *_function(program, function, names, renamed, code, signature)]
    forwarded = "".join(f", {names[s.name]}={names[s.name]}" for s in constants)
    lines += ["", "", f"def qdd(q, qd, tau{', *, ' + signature if signature else ''}):",
              '    """The joint accelerations that the torques tau give (forward dynamics), shaped like tau."""',
              "    q, single = _states(q)",
              "    qd, tau = _states(qd)[0], _states(tau)[0]",
              f"    bias = _tau(q, qd, numpy.zeros_like(q){forwarded})",
              f"    result = numpy.linalg.solve(M(q{forwarded}), (tau - bias)[..., None])[..., 0]",
              "    return result[0] if single else result", "", "", "_tau = tau  # qdd's argument tau hides it", ""]
    return "\n".join(lines)


def _function(program: Program, function: str, names: dict, renamed: dict, code, signature: str) -> list:
    matrix = program.outputs[function]
    inputs = SIGNATURES[function]
    lines = [f"def {function}({', '.join(inputs)}{', *, ' + signature if signature else ''}):",
             f'    """{WHAT[function]}."""', "    q, single = _states(q)"]
    symbols = {"q": program.variables, "qd": program.rates, "qdd": program.accelerations}
    for argument in inputs:
        if argument != "q":
            lines.append(f"    {argument} = _states({argument})[0]")
        unpacked = ", ".join(names[s.name] for s in symbols[argument])
        lines.append(f"    {unpacked}{',' if len(symbols[argument]) == 1 else ''} = {argument}.T")
    square = function in ("M", "C")
    cells = [((i, j), matrix[i, j]) for i in range(matrix.rows) for j in range(matrix.cols)
             if not (function == "M" and j < i)] if square else [((i,), matrix[i]) for i in range(matrix.rows)]
    tape = program.tape
    for symbol in tape.used([value for _, value in cells]):
        lines.append(f"    {renamed[symbol].name} = {code.doprint(tape.definitions[symbol].xreplace(renamed))}")
    shape = f"(len(q), {matrix.rows}, {matrix.rows})" if square else f"(len(q), {matrix.rows})"
    lines.append(f"    result = numpy.zeros({shape})")
    for index, value in cells:
        if value != 0:
            target = ", ".join(map(str, index))
            lines.append(f"    result[:, {target}] = {code.doprint(sympy.sympify(value).xreplace(renamed))}")
            if function == "M" and index[0] != index[1]:
                lines.append(f"    result[:, {index[1]}, {index[0]}] = result[:, {target}]")
    lines.append("    return result[0] if single else result")
    return lines


def tape_function(tape, inputs: list, outputs: list):
    """A numpy function of the symbols `inputs` (each a number or an array of one shape, in that
    order) that returns the values of `outputs` (expressions on `tape`) as one array, outputs first:
    what the base-parameter search and the tests evaluate the tape with, at many points at once."""
    import numpy  # only to evaluate: writing a module needs no numpy

    names = python_names([s.name for s in inputs])
    code = NumpyCode(names, None)
    renamed = _variable_names(tape, set(names.values()) | {"numpy", "broadcast"})
    lines = [f"def evaluate({', '.join(names[s.name] for s in inputs)}):"]
    for symbol in tape.used(outputs):
        lines.append(f"    {renamed[symbol].name} = {code.doprint(tape.definitions[symbol].xreplace(renamed))}")
    values = ", ".join(code.doprint(sympy.sympify(x).xreplace(renamed)) for x in outputs)
    lines.append(f"    return numpy.array(numpy.broadcast_arrays({values}), dtype=float)")
    namespace = {"numpy": numpy}
    exec(compile("\n".join(lines), "<dhsym tape>", "exec"), namespace)
    return namespace["evaluate"]


def _variable_names(tape, taken: set) -> dict:
    """{name on the tape: a Dummy named for the module}: cos_theta_1 for cos θ1, v1, v2, … else."""
    renamed, count = {}, 0
    for symbol, value in tape.definitions.items():
        text = None
        if isinstance(value, (sympy.cos, sympy.sin)) and value.args[0].is_Symbol:
            text = f"{type(value).__name__}_{value.args[0].name}"
        while text is None or text in taken or not text.isidentifier():
            count += 1
            text = f"v{count}"
        taken.add(text)
        renamed[symbol] = sympy.Dummy(text)
    return renamed
