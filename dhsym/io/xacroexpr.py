"""The `${…}` expressions of a .xacro file, checked and worked out by dhsym, never by eval.

xacro 2.1.1 evaluates them with Python's eval, its builtins emptied but `type`, `vars`,
`load_yaml` (which reads any file) and Python's whole math module left in reach, and no bound on
`9**9**9` or `'a' * 10**9`. So dhsym walks the expression's syntax tree itself: numbers, strings,
the names of properties, `pi`, `e` and a few math functions (sin cos tan asin acos atan atan2
sqrt radians degrees fabs floor ceil, also as `math.sin`), arithmetic `+ - * / // % **`,
comparisons, `and`/`or`/`not` and `a if c else b`. Anything else (attributes, subscripts,
comprehensions, lambdas, other calls, names with an underscore in front) is refused, and so are
results that are not the size of a robot: powers above 64, numbers beyond 1e15, strings longer
than 1,000 characters.

>>> evaluate("2 * pi / 4 + radians(90) - l", {"l": 1.0})
2.141592653589793
>>> check_syntax("().__class__")
"'.__class__' is not allowed in a xacro expression; dhsym allows numbers, property names, arithmetic and math functions"
>>> evaluate("9 ** 9 ** 9", {})
Traceback (most recent call last):
dhsym.io.xacroexpr.Refused: a power of 387420489 is more than a robot file needs (at most 64)
"""
from __future__ import annotations

import ast
import math
import operator

MAX_NUMBER = 1e15
MAX_TEXT = 1_000
MAX_POWER = 64
MAX_EXPRESSION = 1_000
FUNCTIONS = {name: getattr(math, name) for name in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt",
                                                    "radians", "degrees", "fabs", "floor", "ceil")}
FUNCTIONS.update(abs=abs, min=min, max=max, round=round, float=float, int=int, str=str)
CONSTANTS = {"pi": math.pi, "e": math.e, "True": True, "False": False}
_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow}
_COMPARE = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
            ast.Gt: operator.gt, ast.GtE: operator.ge}
_ALLOWED = (ast.Expression, ast.Constant, ast.Name, ast.Load, ast.BinOp, ast.UnaryOp, ast.BoolOp, ast.Compare,
            ast.IfExp, ast.Call, ast.Attribute, ast.USub, ast.UAdd, ast.Not, ast.And, ast.Or, *_BINARY, *_COMPARE)
_WHAT = "dhsym allows numbers, property names, arithmetic and math functions"


class Refused(Exception):
    """An expression dhsym will not work out; the message says why."""


def check_syntax(text: str) -> str | None:
    """Why an expression is refused by its form alone, or None when its form is allowed."""
    if len(text) > MAX_EXPRESSION:
        return f"an expression of {len(text)} characters is longer than the {MAX_EXPRESSION} allowed"
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError:
        return None  # xacro's own error ("invalid syntax") is clear enough, and nothing runs
    for node in ast.walk(tree):
        if not isinstance(node, _ALLOWED):
            return f"{type(node).__name__.lower()} is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Name) and node.id.startswith("_"):
            return f"the name {node.id!r} is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Attribute) and not _math_name(node):
            return f"'.{node.attr}' is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Call) and (node.keywords or _function_name(node.func) not in FUNCTIONS):
            return f"calling {ast.unparse(node.func)!r} is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and len(node.value) > MAX_TEXT:
            return f"a string longer than {MAX_TEXT:,} characters"
    return None


def evaluate(text: str, symbols):
    """The value of an allowed expression; names are looked up in `symbols` (xacro's table)."""
    reason = check_syntax(text)
    if reason:
        raise Refused(reason)
    return _value(ast.parse(text.strip(), mode="eval").body, symbols)


def _math_name(node) -> bool:
    return isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "math" \
        and (node.attr in FUNCTIONS or node.attr in ("pi", "e"))


def _function_name(node) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    return node.attr if _math_name(node) else None


def _value(node, symbols):
    if isinstance(node, ast.Constant):
        return _bounded(node.value)
    if isinstance(node, ast.Name):
        return _bounded(_lookup(node.id, symbols))
    if isinstance(node, ast.Attribute):
        return CONSTANTS[node.attr]
    if isinstance(node, ast.UnaryOp):
        operand = _value(node.operand, symbols)
        if isinstance(node.op, ast.Not):
            return not operand
        _numbers(operand)
        return -operand if isinstance(node.op, ast.USub) else +operand
    if isinstance(node, ast.BinOp):
        return _binary(node.op, _value(node.left, symbols), _value(node.right, symbols))
    if isinstance(node, ast.BoolOp):
        result = _value(node.values[0], symbols)
        for later in node.values[1:]:
            if bool(result) == isinstance(node.op, ast.Or):
                return result
            result = _value(later, symbols)
        return result
    if isinstance(node, ast.Compare):
        left = _value(node.left, symbols)
        for op, right_node in zip(node.ops, node.comparators):
            right = _value(right_node, symbols)
            try:
                holds = _COMPARE[type(op)](left, right)
            except TypeError:
                raise Refused(f"{left!r} and {right!r} cannot be compared") from None
            if not holds:
                return False
            left = right
        return True
    if isinstance(node, ast.IfExp):
        return _value(node.body if _value(node.test, symbols) else node.orelse, symbols)
    if isinstance(node, ast.Call):
        arguments = [_value(argument, symbols) for argument in node.args]
        if len(arguments) > 3 or any(isinstance(a, str) and len(a) > 100 for a in arguments):
            raise Refused(f"too many or too long arguments to {_function_name(node.func)}")
        try:
            return _bounded(FUNCTIONS[_function_name(node.func)](*arguments))
        except (TypeError, ValueError, OverflowError) as error:
            raise Refused(f"{_function_name(node.func)}: {error}") from None
    raise Refused(f"{type(node).__name__} is not allowed in a xacro expression")


def _lookup(name: str, symbols):
    """A property's value; `pi` and `e` unless a property of that name hides them, as in xacro
    (ROS-Industrial's KR210 defines pi as 3.141592654).

    >>> _lookup("pi", {"pi": 3.141592654}), _lookup("pi", {})
    (3.141592654, 3.141592653589793)
    """
    if name in FUNCTIONS:
        raise Refused(f"{name} is a function; call it, as in {name}(x)")
    try:
        value = symbols[name]
    except KeyError:
        if name in CONSTANTS:
            return CONSTANTS[name]
        raise Refused(f"name {name!r} is not defined (no xacro:property or macro parameter has it)") from None
    if name in CONSTANTS and not isinstance(value, (int, float)):
        return CONSTANTS[name]
    if not isinstance(value, (int, float, str, bool)):
        raise Refused(f"property {name!r} is a {type(value).__name__}, not a number or text")
    return value


def _binary(op, left, right):
    if isinstance(op, ast.Add) and isinstance(left, str) and isinstance(right, str):
        return _bounded(left + right)
    _numbers(left, right)
    if isinstance(op, ast.Pow) and (abs(right) > MAX_POWER or abs(left) > MAX_NUMBER):
        raise Refused(f"a power of {right} is more than a robot file needs (at most {MAX_POWER})")
    try:
        return _bounded(_BINARY[type(op)](left, right))
    except ZeroDivisionError:
        raise Refused("division by zero") from None
    except (OverflowError, ValueError, TypeError) as error:
        raise Refused(str(error)) from None


def _numbers(*values) -> None:
    for value in values:
        if isinstance(value, str) or not isinstance(value, (int, float)):
            raise Refused(f"arithmetic on {value!r}, which is not a number")


def _bounded(value):
    if isinstance(value, bool) or value is None:
        return value
    if isinstance(value, str):
        if len(value) > MAX_TEXT:
            raise Refused(f"a text longer than {MAX_TEXT:,} characters")
        return value
    if isinstance(value, int) and abs(value) <= MAX_NUMBER:
        return value
    if isinstance(value, float) and math.isfinite(value) and abs(value) <= MAX_NUMBER:
        return value
    if isinstance(value, (int, float)):
        raise Refused(f"the number {float(min(abs(value), 10 ** 300)):.3g} is not of a robot's size")
    raise Refused(f"a {type(value).__name__} is not a number or text")
