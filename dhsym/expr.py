"""Safe parsing of the expressions users write in robot files and on the command line.

The parser walks Python's `ast` over a whitelist of node types and builds SymPy objects
directly; user text never reaches `eval`, `sympify` or `parse_expr`.

>>> parse_expression("theta_2 - pi/2")
theta_2 - pi/2
>>> parse_expression("90deg"), parse_expression("0.25"), parse_expression("sqrt(3)/2")
(pi/2, 1/4, sqrt(3)/2)
"""
from __future__ import annotations

import ast
import re

import sympy

from .errors import Location, UserError

MAX_LENGTH = 200  # characters of one expression
MAX_DEPTH = 24  # nesting of operators and calls
MAX_EXPONENT = 16  # largest |numerator| or denominator of a power's exponent

FUNCTIONS = {"sqrt": sympy.sqrt, "sin": sympy.sin, "cos": sympy.cos}
CONSTANTS = {"pi": sympy.pi, "π": sympy.pi}
_DEGREE_MARK = "_deg"  # users cannot write names starting with '_', so this one is ours

_NUMBER_WITH_DEGREES = re.compile(r"(\d+(?:\.\d*)?|\.\d+)(\s*)(deg\b|°)")
_USER_UNDERSCORE_NAME = re.compile(r"(?<![\w.])_\w*")
_BINARY = {ast.Add: sympy.Add, ast.Sub: None, ast.Mult: sympy.Mul, ast.Div: None, ast.Pow: None}


def real_symbol(name: str) -> sympy.Symbol:
    """The real SymPy symbol for a name in a robot file.

    >>> real_symbol("l_1").is_real
    True
    """
    return sympy.Symbol(name, real=True)


def parse_expression(text: str, where: Location | None = None) -> sympy.Expr:
    """Parse one expression; raise UserError pointing at the offending column."""
    where = where or Location("<expression>", 1, 1)
    if not isinstance(text, str):
        raise UserError("expected an expression", where)
    if len(text) > MAX_LENGTH:
        raise UserError(f"expression longer than {MAX_LENGTH} characters", where)
    if not text.strip():
        raise UserError("empty expression", where)
    bad_name = _USER_UNDERSCORE_NAME.search(text)
    if bad_name:
        raise UserError(f"name {bad_name.group(0)!r} may not start with '_'", where.shifted(bad_name.start()))
    source, columns = _normalise(text)
    try:
        tree = ast.parse(source.strip() and source, mode="eval")
    except SyntaxError as exc:
        column = columns[min(max((exc.offset or 1) - 1, 0), len(columns) - 1)]
        raise UserError(f"cannot read expression {text!r}", where.shifted(column)) from None
    except (ValueError, RecursionError, MemoryError):
        raise UserError(f"cannot read expression {text!r}", where) from None
    return _Builder(source, columns, where).build(tree.body, 0)


def _normalise(text: str) -> tuple[str, list[int]]:
    """Rewrite `^`, `−`, `90deg`, `90°` into Python syntax; map new columns back to old ones."""
    pieces: list[tuple[str, int]] = []  # (new text, original column it came from)
    position = 0
    for match in _NUMBER_WITH_DEGREES.finditer(text):
        pieces.extend((ch, position + i) for i, ch in enumerate(text[position:match.start()]))
        number = match.group(1)
        pieces.extend((ch, match.start() + i) for i, ch in enumerate(number))
        pieces.extend((ch, match.start(3)) for ch in "*" + _DEGREE_MARK)
        position = match.end()
    pieces.extend((ch, position + i) for i, ch in enumerate(text[position:]))
    out, columns = [], []
    for ch, column in pieces:
        replacement = {"^": "**", "−": "-", "·": "*", "×": "*"}.get(ch, ch)
        out.append(replacement)
        columns.extend([column] * len(replacement))
    columns.append(len(text))
    return "".join(out), columns


class _Builder:
    """Turns a whitelisted AST into SymPy, one node type at a time."""

    def __init__(self, source: str, columns: list[int], where: Location):
        self.source, self.columns, self.where = source, columns, where

    def fail(self, node: ast.AST, message: str) -> UserError:
        offset = getattr(node, "col_offset", 0)
        return UserError(message, self.where.shifted(self.columns[min(offset, len(self.columns) - 1)]))

    def build(self, node: ast.AST, depth: int) -> sympy.Expr:
        if depth > MAX_DEPTH:
            raise self.fail(node, f"expression nested deeper than {MAX_DEPTH} levels")
        handler = getattr(self, "_" + type(node).__name__, None)
        if handler is None:
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        result = handler(node, depth + 1)
        if result.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
            raise self.fail(node, "expression is undefined (division by zero?)")
        return result

    def _Constant(self, node: ast.Constant, depth: int) -> sympy.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        if isinstance(value, int):
            return sympy.Integer(value)
        literal = self.source[node.col_offset:node.end_col_offset].replace("_", "")
        return sympy.Rational(literal)  # exact: 0.1 stays 1/10

    def _Name(self, node: ast.Name, depth: int) -> sympy.Expr:
        name = node.id
        if name == _DEGREE_MARK:
            return sympy.pi / 180
        if name in CONSTANTS:
            return CONSTANTS[name]
        if name in FUNCTIONS:
            raise self.fail(node, f"{name!r} is a function and cannot be used as a name")
        return real_symbol(name)

    def _UnaryOp(self, node: ast.UnaryOp, depth: int) -> sympy.Expr:
        operand = self.build(node.operand, depth)
        if isinstance(node.op, ast.USub):
            return -operand
        if isinstance(node.op, ast.UAdd):
            return operand
        raise self.fail(node, f"operator {type(node.op).__name__} is not allowed")

    def _BinOp(self, node: ast.BinOp, depth: int) -> sympy.Expr:
        if type(node.op) not in _BINARY:
            raise self.fail(node, "only + - * / ** and ^ are allowed as operators")
        left = self.build(node.left, depth)
        right = self.build(node.right, depth)
        if isinstance(node.op, ast.Add):
            return left + right
        if isinstance(node.op, ast.Sub):
            return left - right
        if isinstance(node.op, ast.Mult):
            return left * right
        if isinstance(node.op, ast.Div):
            if right == 0:
                raise self.fail(node, "division by zero")
            return left / right
        if not (right.is_Rational and abs(right.p) <= MAX_EXPONENT and right.q <= MAX_EXPONENT):
            raise self.fail(node, f"exponent must be a small number (at most {MAX_EXPONENT})")
        if left == 0 and right.is_negative:
            raise self.fail(node, "division by zero")
        return left**right

    def _Call(self, node: ast.Call, depth: int) -> sympy.Expr:
        name = node.func.id if isinstance(node.func, ast.Name) else None
        if name not in FUNCTIONS:
            raise self.fail(node, "only sqrt, sin and cos may be called")
        if node.keywords or len(node.args) != 1:
            raise self.fail(node, f"{name} takes exactly one argument")
        return FUNCTIONS[name](self.build(node.args[0], depth))


def _describe(node: ast.AST) -> str:
    if isinstance(node, ast.Constant):
        return "a string" if isinstance(node.value, str) else f"the constant {node.value!r}"
    return {
        "Attribute": "attribute access", "Subscript": "a subscript", "Lambda": "a lambda",
        "ListComp": "a comprehension", "GeneratorExp": "a comprehension", "Compare": "a comparison",
        "BoolOp": "a boolean operator", "JoinedStr": "a string", "Tuple": "a tuple", "List": "a list",
    }.get(type(node).__name__, f"{type(node).__name__} syntax")
