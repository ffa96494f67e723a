"""The `${…}` expressions of a .xacro file, checked and worked out by dhsym, never by eval.

xacro 2.1.1 evaluates them with Python's eval, its builtins emptied but `type`, `vars`,
`load_yaml` (which reads any file) and Python's whole math module left in reach, and no bound on
`9**9**9` or `'a' * 10**9`. So dhsym walks the expression's syntax tree itself: numbers, strings,
the names of properties, `pi`, `e` and a few math functions (sin cos tan asin acos atan atan2
sqrt radians degrees fabs floor ceil, also as `math.sin`; abs min max round float int str),
arithmetic `+ - * / // % **`, comparisons, `and`/`or`/`not`, `a if c else b`, and the data of
YAML files: `load_yaml('file.yaml')` or `xacro.load_yaml(…)` (read by the caller's loader, see
xacro.py), `dict(key=value, …)`, and subscripts `kin['shoulder']['x']`, `limits[0]` or dotted
keys `kin.shoulder` on that data. Anything else (other attributes, comprehensions, lambdas,
other calls, names with an underscore in front) is refused, and so are results that are not the
size of a robot: powers above 64, numbers beyond 1e15, strings longer than 1,000 characters,
`round` to more than 20 places either way. A `Work` counts the syntax-tree nodes evaluated over
a whole expansion and stops it past 100,000 (a macro that repeats `${p}` many times).

>>> evaluate("2 * pi / 4 + radians(90) - l", {"l": 1.0})
2.141592653589793
>>> evaluate("kin['shoulder']['x'] + kin.shoulder.z", {"kin": YamlMap(shoulder=YamlMap(x=0.5, z=0.25))})
0.75
>>> check_syntax("().__class__")
"'.__class__' is not allowed in a xacro expression; dhsym allows numbers, property names, arithmetic and math functions"
>>> evaluate("9 ** 9 ** 9", {})
Traceback (most recent call last):
dhsym.io.xacroexpr.Refused: a power of 387420489 is more than a robot file needs (at most 64)
"""
from __future__ import annotations

import ast
import functools
import math
import operator

MAX_NUMBER = 1e15
MAX_TEXT = 1_000
MAX_POWER = 64
MAX_EXPRESSION = 1_000
MAX_ROUND_DIGITS = 20
MAX_WORK = 100_000  # syntax-tree nodes of one expansion; a UR5e's takes 1,408
FUNCTIONS = {name: getattr(math, name) for name in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt",
                                                    "radians", "degrees", "fabs", "floor", "ceil")}
FUNCTIONS.update(abs=abs, min=min, max=max, round=round, float=float, int=int, str=str)
DATA_FUNCTIONS = ("dict", "load_yaml")
CONSTANTS = {"pi": math.pi, "e": math.e, "True": True, "False": False}
_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow}
_COMPARE = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
            ast.Gt: operator.gt, ast.GtE: operator.ge}
_ALLOWED = (ast.Expression, ast.Constant, ast.Name, ast.Load, ast.BinOp, ast.UnaryOp, ast.BoolOp, ast.Compare,
            ast.IfExp, ast.Call, ast.Attribute, ast.Subscript, ast.keyword, ast.USub, ast.UAdd, ast.Not, ast.And,
            ast.Or, *_BINARY, *_COMPARE)
_WHAT = "dhsym allows numbers, property names, arithmetic and math functions"


class Refused(Exception):
    """An expression dhsym will not work out; the message says why."""


class YamlMap(dict):
    """A mapping of YAML data (load_yaml, dict(…)): the only dictionaries an expression sees."""


class YamlList(list):
    """A sequence of YAML data."""


class Work:
    """The evaluation work of one expansion, and where `load_yaml` reads from."""

    def __init__(self, load_yaml=None, limit: int = MAX_WORK):
        self.load_yaml, self.limit, self.done = load_yaml, limit, 0

    def count(self) -> None:
        self.done += 1
        if self.done > self.limit:
            raise Refused(f"the expansion evaluates more than {self.limit:,} expression parts (a macro that repeats "
                          "an expression many times?)")


def check_syntax(text: str) -> str | None:
    """Why an expression is refused by its form alone, or None when its form is allowed."""
    if len(text) > MAX_EXPRESSION:
        return f"an expression of {len(text)} characters is longer than the {MAX_EXPRESSION} allowed"
    try:
        tree = _parsed(text.strip())
    except SyntaxError:
        return None  # xacro's own error ("invalid syntax") is clear enough, and nothing runs
    for node in ast.walk(tree):
        if not isinstance(node, _ALLOWED):
            return f"{type(node).__name__.lower()} is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Name) and node.id.startswith("_"):
            return f"the name {node.id!r} is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Attribute) and node.attr.startswith("_"):
            return f"'.{node.attr}' is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Call):
            name = _function_name(node.func)
            if name not in FUNCTIONS and name not in DATA_FUNCTIONS or (node.keywords and name != "dict"):
                return f"calling {ast.unparse(node.func)!r} is not allowed in a xacro expression; {_WHAT}"
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and len(node.value) > MAX_TEXT:
            return f"a string longer than {MAX_TEXT:,} characters"
    return None


def evaluate(text: str, symbols, work: Work | None = None):
    """The value of an allowed expression; names are looked up in `symbols` (xacro's table)."""
    reason = check_syntax(text)
    if reason:
        raise Refused(reason)
    return _Evaluator(symbols, work or Work()).value(_parsed(text.strip()).body)


@functools.lru_cache(maxsize=4096)
def _parsed(text: str) -> ast.Expression:
    return ast.parse(text, mode="eval")


def _function_name(node) -> str | None:
    """`sin`, `math.sin` → sin; `xacro.load_yaml` → load_yaml; anything else → None."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
        if node.value.id == "math" and node.attr in FUNCTIONS:
            return node.attr
        if node.value.id == "xacro" and node.attr == "load_yaml":
            return node.attr
    return None


class _Evaluator:
    def __init__(self, symbols, work: Work):
        self.symbols, self.work = symbols, work

    def value(self, node):
        self.work.count()
        kind = type(node).__name__
        method = getattr(self, f"v_{kind}", None)
        if method is None:
            raise Refused(f"{kind} is not allowed in a xacro expression")
        return method(node)

    def v_Constant(self, node):
        return _bounded(node.value)

    def v_Name(self, node):
        return _bounded(_lookup(node.id, self.symbols))

    def v_Attribute(self, node):
        if isinstance(node.value, ast.Name) and node.value.id in ("math", "xacro"):
            if node.value.id == "math" and node.attr in ("pi", "e"):
                return CONSTANTS[node.attr]
            raise Refused(f"{node.value.id}.{node.attr} is not a value; only math.pi, math.e and calls such as "
                          "math.sin(x) are allowed")
        return _item(self.value(node.value), node.attr)

    def v_Subscript(self, node):
        return _item(self.value(node.value), self.value(node.slice))

    def v_UnaryOp(self, node):
        operand = self.value(node.operand)
        if isinstance(node.op, ast.Not):
            return not operand
        _numbers(operand)
        return -operand if isinstance(node.op, ast.USub) else +operand

    def v_BinOp(self, node):
        return _binary(node.op, self.value(node.left), self.value(node.right))

    def v_BoolOp(self, node):
        result = self.value(node.values[0])
        for later in node.values[1:]:
            if bool(result) == isinstance(node.op, ast.Or):
                return result
            result = self.value(later)
        return result

    def v_Compare(self, node):
        left = self.value(node.left)
        for op, right_node in zip(node.ops, node.comparators):
            right = self.value(right_node)
            try:
                holds = _COMPARE[type(op)](left, right)
            except TypeError:
                raise Refused(f"{_short(left)} and {_short(right)} cannot be compared") from None
            if not holds:
                return False
            left = right
        return True

    def v_IfExp(self, node):
        return self.value(node.body if self.value(node.test) else node.orelse)

    def v_Call(self, node):
        name = _function_name(node.func)
        arguments = [self.value(argument) for argument in node.args]
        if name == "dict":
            return self.dictionary(node, arguments)
        if name == "load_yaml":
            if len(arguments) != 1 or not isinstance(arguments[0], str) or self.work.load_yaml is None:
                raise Refused("load_yaml takes one file name")
            return self.work.load_yaml(arguments[0])
        if len(arguments) > 3 or any(isinstance(a, str) and len(a) > 100 for a in arguments):
            raise Refused(f"too many or too long arguments to {name}")
        if name == "round" and len(arguments) == 2 and not (
                isinstance(arguments[1], int) and abs(arguments[1]) <= MAX_ROUND_DIGITS):
            raise Refused(f"round to {_short(arguments[1])} places: at most {MAX_ROUND_DIGITS} either way")
        try:
            return _bounded(FUNCTIONS[name](*arguments))
        except (TypeError, ValueError, OverflowError) as error:
            raise Refused(f"{name}: {error}") from None

    def dictionary(self, node, arguments):
        if arguments or any(keyword.arg is None for keyword in node.keywords):
            raise Refused("dict takes keywords only here, as in dict(x=1, y=2)")
        return YamlMap((keyword.arg, self.value(keyword.value)) for keyword in node.keywords)


def _item(container, key):
    """`container[key]` of YAML data (a dotted name is a key too, as xacro reads YAML)."""
    if isinstance(container, YamlMap):
        if key not in container:
            raise Refused(f"no key {_short(key)} in the YAML mapping (its keys: {_short(list(container))})")
        return container[key]
    if isinstance(container, YamlList):
        if isinstance(key, bool) or not isinstance(key, int) or not -len(container) <= key < len(container):
            raise Refused(f"index {_short(key)} of a YAML list of {len(container)} items")
        return container[key]
    raise Refused(f"{_short(container)} has no items; only YAML data (load_yaml, dict) is subscripted")


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _lookup(name: str, symbols):
    """A property's value; `pi` and `e` unless a property of that name hides them, as in xacro
    (ROS-Industrial's KR210 defines pi as 3.141592654).

    >>> _lookup("pi", {"pi": 3.141592654}), _lookup("pi", {})
    (3.141592654, 3.141592653589793)
    """
    if name in FUNCTIONS or name in DATA_FUNCTIONS:
        raise Refused(f"{name} is a function; call it, as in {name}(x)")
    try:
        value = symbols[name]
    except KeyError:
        if name in CONSTANTS:
            return CONSTANTS[name]
        raise Refused(f"name {name!r} is not defined (no xacro:property or macro parameter has it)") from None
    if name in CONSTANTS and not isinstance(value, (int, float)):
        return CONSTANTS[name]
    if value is not None and not isinstance(value, (int, float, str, bool, YamlMap, YamlList)):
        raise Refused(f"property {name!r} is a {type(value).__name__}, not a number, text or YAML data")
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
            raise Refused(f"arithmetic on {_short(value)}, which is not a number")


def _bounded(value):
    if isinstance(value, (bool, YamlMap, YamlList)) or value is None:
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
