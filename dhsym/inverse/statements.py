"""The statements the module `dhsym ik --format python` computes (dhsym.inverse.codegen prints them
with numpy, dhsym.inverse.onepose with math): every branch's values in order, a value two branches
share computed once, sub-expressions used more than once (cos θ1, √(1 − D²)) named and computed
once, and a lined-up wrist's member as a statement of its own, after the branch's value, that only
the poses which need it pay for.

>>> import sympy
>>> x = sympy.Symbol("x", real=True)
>>> choice(sympy.Piecewise((0, sympy.Abs(x) < 1), (x, True))), choice(sympy.atan2(x, 1))
(True, False)
>>> comment_text("shoulder left,   elbow up")
'shoulder left, elbow up'
"""
from __future__ import annotations

import sympy

from .quartic import Complex


def computation(solution, names: dict, code) -> tuple[list, list]:
    """The statements that compute every branch (see _shared_subexpressions) and each branch's
    values: the definitions, then each branch's assignments, a value that an earlier branch
    computed already (the same expression of the same earlier values) taken from it, and
    sub-expressions used more than once (cos θ1, √(1 − D²)) computed once."""
    taken = set(names.values())
    variable = {}  # the value's expression, in the variables computed before it -> its variable
    lines = []  # (comment, None, None) or (None, variable, expression)
    named: set = set()  # the variables' names so far
    statement = {}  # a variable -> the expression it holds

    def compute(name, value, known) -> sympy.Dummy:
        angles = [known[joint] for joint in solution.joint_variables if joint in known]
        key = value.xreplace(known).xreplace(on_the_unit_circle(angles, statement))
        if key not in variable:
            text = base = names[name.name]
            count = 1
            while text in named or (count > 1 and text in taken):
                count += 1
                text = f"{base}_{count}"
            taken.add(text)
            named.add(text)
            variable[key] = sympy.Dummy(text)
            statement[variable[key]] = key
            if isinstance(name, Complex):
                code.complex.add(variable[key])
            lines.extend(_statements(variable[key], key))
        return variable[key]

    shared = {}
    if solution.definitions:
        lines.append(("shared by every branch", None, None))
    for name, value in solution.definitions:
        shared[name] = compute(name, value, shared)
    columns = []
    lined_up = members(solution)
    for branch in solution.branches:
        lines.append((comment_text(branch.name), None, None))
        known = dict(shared)
        for name, value in branch.assignments:
            if name in lined_up:  # the degenerate case's member where its condition holds
                condition, member = lined_up[name]
                value = sympy.Piecewise((member, sympy.Abs(condition) < _LINED_UP), (value, True))
            known[name] = compute(name, value, known)
        columns.append([known.get(joint) if joint in known else (joint if joint in solution.free else None)
                        for joint in solution.joint_variables])
    return _shared_subexpressions(lines, taken, code), columns


def on_the_unit_circle(angles, statement: dict) -> dict:
    """{cos θ: x, sin θ: y} for each of the branch's `angles` θ = atan2(y, x) with y = ±√(1 − x²)
    (or x = ±√(1 − y²)), as the books write c3 = D, s3 = ±√(1 − D²): no round trip through atan2,
    cos and sin. Where the root is NaN, θ and so its branch are missing too.

    >>> d, t = sympy.symbols("D theta", real=True)
    >>> on_the_unit_circle([t], {t: sympy.atan2(-sympy.sqrt(1 - d**2), d)})
    {cos(theta): D, sin(theta): -sqrt(1 - D**2)}
    >>> on_the_unit_circle([t], {t: sympy.atan2(sympy.sqrt(2 - d**2), d)})
    {}
    """
    found = {}
    for angle in angles:
        value = statement.get(angle)
        if isinstance(value, sympy.atan2) and any(_root_of_one_minus(*pair) for pair in (value.args, value.args[::-1])):
            found[sympy.cos(angle)], found[sympy.sin(angle)] = value.args[1], value.args[0]
    return found


def _root_of_one_minus(root, other) -> bool:
    """Whether `root` is ±√(1 − other²)."""
    bare = -root if root.could_extract_minus_sign() else root
    return bare.is_Pow and bare.exp == sympy.S.Half and sympy.expand(bare.base + other**2) == 1


def _statements(variable, value) -> list[tuple]:
    """The lines (None, variable, expression) that compute `variable`: a lined-up wrist's choice in
    two, the branch's value then its member where |guard| < LINED_UP (a Piecewise of its own, see choice)."""
    if not isinstance(value, sympy.Piecewise):
        return [(None, variable, value)]
    (member, condition), (value, _) = value.args
    return [(None, variable, value), (None, variable, sympy.Piecewise((member, condition), (variable, True)))]


_LINED_UP = sympy.Dummy("LINED_UP")  # the module's constant, by name


def members(solution) -> dict:
    """{joint: (condition, value)}: where `condition` is 0 (|sin θ5| < LINED_UP), the joint takes
    `value`, the member of the family its degenerate case names (dhsym.inverse.mirrored)."""
    return {joint: (case.condition[0], value) for case in solution.degenerate
            for joint, value in getattr(case, "member", ())}


def _shared_subexpressions(lines, taken: set, code) -> list[tuple]:
    """The lines as statements (comment, None, None, False) or (None, variable, expression, whether
    it is computed in complex numbers), each sub-expression used more than once computed once,
    just before the first line that needs it; cos and sin of a value are named after it (cos_theta_1)."""
    expressions = [expression for comment, _, expression in lines if comment is None and not choice(expression)]
    replacements, reduced = sympy.cse(expressions, symbols=_temporaries(taken), order="none")
    renamed = {}
    for symbol, value in replacements:
        if isinstance(value, (sympy.cos, sympy.sin)) and value.args[0].is_Symbol:
            text = f"{type(value).__name__}_{code.doprint(value.args[0])}"
            if text not in taken:
                taken.add(text)
                renamed[symbol] = sympy.Dummy(text)
    replacements = [(renamed.get(s, s), v.xreplace(renamed)) for s, v in replacements]
    reduced = iter(r.xreplace(renamed) for r in reduced)
    pending = dict(replacements)
    out = []

    def emit(expression):
        for symbol in sorted(expression.free_symbols & pending.keys(), key=str):
            if symbol in pending:
                value = pending.pop(symbol)
                emit(value)
                if code.is_complex(value):
                    code.complex.add(symbol)
                out.append((None, symbol, value, False))

    for comment, symbol, expression in lines:
        if comment is not None:
            out.append((comment, None, None, False))
            continue
        if choice(expression):  # seldom taken: kept out of the shared values, reusing those computed so far
            out.append((None, symbol, expression.xreplace(_computed(out, replacements)), False))
            continue
        expression = next(reduced)
        emit(expression)
        out.append((None, symbol, expression, symbol in code.complex))
    return out


def choice(expression) -> bool:
    """Whether `expression` is a lined-up wrist's choice, Piecewise((member, |guard| < LINED_UP), (variable, True))."""
    return isinstance(expression, sympy.Piecewise)


def _computed(out, replacements) -> dict:
    """{expression, in the module's variables: the shared value (cos_theta_1, ...) computed for it so far}."""
    done = {symbol for _, symbol, _, _ in out if symbol is not None}
    written, found = {}, {}
    for symbol, value in replacements:
        written[symbol] = value.xreplace(written)
        if symbol in done:
            found[written[symbol]] = symbol
    return found


def _temporaries(taken: set):
    number = 0
    while True:
        number += 1
        if f"common_{number}" not in taken:
            yield sympy.Dummy(f"common_{number}")


def comment_text(text: str) -> str:
    """Text from a robot file, safe inside a comment or a docstring: one line, no quotes to end it."""
    return " ".join(str(text).split()).replace("\\", "/").replace('"""', "'''")
