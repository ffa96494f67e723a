"""Safe parsing of the expressions users write in robot files and on the command line.

The parser walks Python's `ast` over a whitelist of node types and builds SymPy objects
directly; user text never reaches `eval`, `sympify` or `parse_expr`. Work is bounded: the
text, its nesting, its exponents and the size of every number it builds are limited.

>>> parse_expression("theta_2 - pi/2")
theta_2 - pi/2
>>> parse_expression("90deg"), parse_expression("0.25"), parse_expression("sqrt(3)/2")
(pi/2, 1/4, sqrt(3)/2)
>>> parse_expression("θ1 + 1.5")
θ1 + 3/2
"""
from __future__ import annotations

import ast
import re
import warnings
from fractions import Fraction

import sympy

from ..errors import Location, UserError

MAX_LENGTH = 200  # characters of one expression
MAX_DEPTH = 24  # nesting of operators and calls
MAX_EXPONENT = 16  # largest |numerator| or denominator of a power's exponent
MAX_DIGITS = 120  # of any exact number built on the way (numerator or denominator)

FUNCTIONS = {"sqrt": sympy.sqrt, "sin": sympy.sin, "cos": sympy.cos}
CONSTANTS = {"pi": sympy.pi, "π": sympy.pi}
_DEGREE_MARK = "_deg"  # a user's own `_deg` is refused, so this name can only come from `90deg`

# A number standing on its own (not the digits at the end of a name such as `l90`), then a unit.
_NUMBER_WITH_DEGREES = re.compile(r"(?<![\w.])(\d+(?:\.\d*)?|\.\d+)(\s*)(deg\b|°)")
_USER_UNDERSCORE_NAME = re.compile(r"(?<![\w.])_\w*")
_DECIMAL = re.compile(r"(?P<whole>[\d_]*)(?:\.(?P<fraction>[\d_]*))?(?:[eE](?P<exponent>[+-]?[\d_]+))?")
_SPELLINGS = {"^": "**", "−": "-", "·": "*", "×": "*"}  # what people type for Python's operators
_BINARY = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow)


def real_symbol(name: str) -> sympy.Symbol:
    """The real SymPy symbol for a name in a robot file.

    >>> real_symbol("l_1").is_real
    True
    """
    return sympy.Symbol(name, real=True)


def parse_expression(text: str, where: Location | None = None) -> sympy.Expr:
    """Parse one expression; raise UserError pointing at the offending column.

    >>> parse_expression("x.__class__")
    Traceback (most recent call last):
    dhsym.errors.UserError: <expression>:1:1: attribute access is not allowed in an expression
    """
    where = where or Location("<expression>", 1, 1)
    if not isinstance(text, str):
        raise UserError("expected an expression", where)
    if len(text) > MAX_LENGTH:
        raise UserError(f"expression is {len(text)} characters long; the limit is {MAX_LENGTH}", where)
    _refuse_odd_characters(text, where)
    if not text.strip():
        raise UserError("empty expression", where)
    bad_name = _USER_UNDERSCORE_NAME.search(text)
    if bad_name:
        raise UserError(f"name {bad_name.group(0)!r} may not start with '_'", where.shifted(bad_name.start()))
    source, columns, marks = _normalise(text)
    stray_degree = source.find("°")
    if stray_degree >= 0:
        raise UserError("° must follow a number, as in 90°", where.shifted(columns[stray_degree]))
    indent = len(source) - len(source.lstrip())  # Python reads leading blanks as an indent
    try:
        with warnings.catch_warnings():  # `1if`, `"\d"`: Python would warn on stderr about code we refuse anyway
            warnings.simplefilter("ignore")
            tree = ast.parse(source[indent:], mode="eval")
    except SyntaxError as exc:
        offset = indent + max((exc.offset or 1) - 1, 0)  # SyntaxError counts characters, not bytes
        column = columns[min(offset, len(columns) - 1)]
        raise UserError(f"cannot read expression {text!r}", where.shifted(column)) from None
    except (ValueError, RecursionError, MemoryError):
        raise UserError(f"cannot read expression {text!r}", where) from None
    return _Builder(source, indent, columns, marks, where).build(tree.body, 0)


def _refuse_odd_characters(text: str, where: Location) -> None:
    """Control characters, line breaks and comments have no place in one expression."""
    for index, ch in enumerate(text):
        if ch == "#":
            raise UserError("'#' is not allowed in an expression", where.shifted(index))
        if (ord(ch) < 32 and ch != "\t") or 0x7F <= ord(ch) < 0xA0 or ch in "\u2028\u2029":
            raise UserError(f"character U+{ord(ch):04X} is not allowed in an expression", where.shifted(index))


def _normalise(text: str) -> tuple[str, list[int], set[int]]:
    """Rewrite `^`, `−`, `90deg`, `90°` into Python syntax.

    Returns the new text, the original column of each of its characters (plus one past the
    end), and the positions in the new text where a degree mark was inserted.
    """
    pieces: list[tuple[str, int]] = []  # (new text, original column it came from)
    marks: set[int] = set()
    position = 0
    for match in _NUMBER_WITH_DEGREES.finditer(text):
        pieces.extend((ch, position + i) for i, ch in enumerate(text[position:match.start()]))
        pieces.append(("(", match.start()))  # the unit binds to its number: 2**90deg is 2**(pi/2)
        pieces.extend((ch, match.start() + i) for i, ch in enumerate(match.group(1)))
        pieces.append(("*", match.start(3)))
        marks.add(sum(len(piece) for piece, _ in pieces))
        pieces.extend((ch, match.start(3)) for ch in _DEGREE_MARK + ")")
        position = match.end()
    pieces.extend((ch, position + i) for i, ch in enumerate(text[position:]))
    out, columns = [], []
    for piece, column in pieces:
        replacement = _SPELLINGS.get(piece, piece)
        out.append(replacement)
        columns.extend([column] * len(replacement))
    columns.append(len(text))
    return "".join(out), columns, marks


def _char_index(line: str, byte_offset: int) -> int:
    """`ast` counts columns in UTF-8 bytes; this is the same place counted in characters."""
    return len(line.encode("utf-8")[:max(byte_offset, 0)].decode("utf-8", errors="ignore"))


def _exact_decimal(literal: str) -> sympy.Rational | None:
    """The exact value of a decimal literal such as `0.1` or `2.5e-3`, or None if it is huge."""
    match = _DECIMAL.fullmatch(literal.replace("_", ""))
    if not match:
        return None
    exponent = int(match.group("exponent") or 0) if len(match.group("exponent") or "") < 8 else None
    if exponent is None or abs(exponent) > 100:
        return None
    value = Fraction(match.group("whole") or "0") + Fraction(f"0.{match.group('fraction') or '0'}")
    value *= Fraction(10) ** exponent
    return sympy.Rational(value.numerator, value.denominator)


def _too_big(value: sympy.Expr) -> bool:
    """More than MAX_DIGITS digits above or below the fraction bar (bits first: str() of a huge int is slow)."""
    if not value.is_Rational:
        return False
    parts = (abs(value.p), value.q)
    return any(part.bit_length() > 4 * MAX_DIGITS or len(str(part)) > MAX_DIGITS for part in parts)


def _bits(value: sympy.Rational) -> int:
    return max(abs(value.p).bit_length(), value.q.bit_length())


class _Builder:
    """Turns a whitelisted AST into SymPy, one node type at a time."""

    def __init__(self, source: str, indent: int, columns: list[int], marks: set[int], where: Location):
        self.source, self.indent, self.columns, self.marks, self.where = source, indent, columns, marks, where
        self.parsed = source[indent:]  # the text `ast` saw

    def start(self, node: ast.AST) -> int:
        """Where `node` starts in the normalised text, in characters."""
        return self.indent + _char_index(self.parsed, getattr(node, "col_offset", 0))

    def end(self, node: ast.AST) -> int:
        return self.indent + _char_index(self.parsed, getattr(node, "end_col_offset", 0) or 0)

    def fail(self, node: ast.AST, message: str) -> UserError:
        return UserError(message, self.where.shifted(self.columns[min(self.start(node), len(self.columns) - 1)]))

    def build(self, node: ast.AST, depth: int) -> sympy.Expr:
        if depth > MAX_DEPTH:
            raise self.fail(node, f"expression nested deeper than {MAX_DEPTH} levels")
        handler = getattr(self, "_" + type(node).__name__, None)
        if handler is None:
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        result = handler(node, depth + 1)
        if result.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
            raise self.fail(node, "expression is undefined (division by zero?)")
        if _too_big(result):
            raise self.fail(node, f"number too large (more than {MAX_DIGITS} digits)")
        if result.is_real is False:
            raise self.fail(node, "expression is not a real number")
        return result

    def _Constant(self, node: ast.Constant, depth: int) -> sympy.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        if isinstance(value, int):
            return sympy.Integer(value)  # at most MAX_LENGTH digits; build() checks the size
        exact = _exact_decimal(self.source[self.start(node):self.end(node)])
        if exact is None:
            raise self.fail(node, "number too large or too small")
        return exact  # exact: 0.1 stays 1/10

    def _Name(self, node: ast.Name, depth: int) -> sympy.Expr:
        name = node.id  # already NFKC-normalised by Python, so `ｓｉｎ` arrives as `sin`
        if name == _DEGREE_MARK and self.start(node) in self.marks:
            return sympy.pi / 180
        if name.startswith("_"):
            raise self.fail(node, f"name {name!r} may not start with '_'")
        if name in CONSTANTS:
            return CONSTANTS[name]
        if name in FUNCTIONS:
            raise self.fail(node, f"{name!r} is a function and cannot be used as a name")
        return real_symbol(name)

    def _UnaryOp(self, node: ast.UnaryOp, depth: int) -> sympy.Expr:
        if not isinstance(node.op, (ast.USub, ast.UAdd)):
            raise self.fail(node, f"operator {_OPERATORS.get(type(node.op).__name__, '?')} is not allowed")
        operand = self.build(node.operand, depth)
        return -operand if isinstance(node.op, ast.USub) else operand

    def _BinOp(self, node: ast.BinOp, depth: int) -> sympy.Expr:
        if not isinstance(node.op, _BINARY):
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
        if left.is_Rational and _bits(left) * abs(right.p) > 4 * MAX_DIGITS * right.q:
            raise self.fail(node, f"number too large (more than {MAX_DIGITS} digits)")  # refused before computing
        return left**right

    def _Call(self, node: ast.Call, depth: int) -> sympy.Expr:
        name = node.func.id if isinstance(node.func, ast.Name) else None
        if name not in FUNCTIONS:
            raise self.fail(node, "only sqrt, sin and cos may be called")
        if node.keywords or len(node.args) != 1 or isinstance(node.args[0], ast.Starred):
            raise self.fail(node, f"{name} takes exactly one argument")
        return FUNCTIONS[name](self.build(node.args[0], depth))


_OPERATORS = {"Invert": "~", "Not": "not"}


def _describe(node: ast.AST) -> str:
    if isinstance(node, ast.Constant):
        return "a string" if isinstance(node.value, (str, bytes)) else f"the constant {node.value!r}"
    return {
        "Attribute": "attribute access", "Subscript": "a subscript", "Lambda": "a lambda",
        "ListComp": "a comprehension", "SetComp": "a comprehension", "DictComp": "a comprehension",
        "GeneratorExp": "a comprehension", "Compare": "a comparison", "BoolOp": "a boolean operator",
        "JoinedStr": "a string", "Tuple": "a tuple", "List": "a list", "Set": "a set", "Dict": "a dict",
        "IfExp": "an if-expression", "NamedExpr": "an assignment", "Await": "await", "Starred": "a starred name",
    }.get(type(node).__name__, f"{type(node).__name__} syntax")
