"""Safe parsing of the expressions users write in robot files and on the command line.

The parser walks Python's `ast` over a whitelist of node types and builds SymPy objects
directly; user text never reaches `eval`, `sympify` or `parse_expr`. Work is bounded: the
text, its nesting, its exponents and the size of every number it builds are limited.

>>> parse_expression("theta_2 - pi/2")
theta_2 - pi/2
>>> parse_expression("90deg"), parse_expression("0.25"), parse_expression("sqrt(3)/2")
(pi/2, 1/4, sqrt(3)/2)
>>> parse_expression("θ1 + 1.5"), parse_expression("θ₁")
(θ1 + 3/2, θ_1)

A `Reading` passed along collects what the value alone does not say: how the numbers were
written (decimal places, fraction denominators: see dhsym.core.numbers), where each name and
each angle unit (π, degrees) stands, and warnings about spellings that are probably slips.

>>> reading = Reading()
>>> parse_expression("Pi/3 + 0.25", reading=reading)
Pi/3 + 1/4
>>> reading.places, reading.fractions, [message for _, message in reading.warnings]
(2, {3}, ["'Pi' is a new symbol, not π; did you mean pi?"])
"""
from __future__ import annotations

import ast
import re
import warnings
from dataclasses import dataclass, field
from fractions import Fraction

import sympy

from ..core.numbers import WrittenNumbers
from ..errors import Location, UserError
from .suspicious import DECIMAL_COMMA, lookalike_letters, misspelt_pi, why_unreadable

MAX_LENGTH = 200  # characters of one expression
MAX_DEPTH = 24  # nesting of operators and calls
MAX_EXPONENT = 16  # largest |numerator| or denominator of a power's exponent
MAX_DIGITS = 120  # of any exact number built on the way (numerator or denominator)

FUNCTIONS = {"sqrt": sympy.sqrt, "sin": sympy.sin, "cos": sympy.cos}
CONSTANTS = {"pi": sympy.pi, "π": sympy.pi}
_DEGREE_MARK = "_deg"  # a user's own `_deg` is refused, so this name can only come from `90deg`

# A number standing on its own (not the digits at the end of a name such as `l90`), then a unit.
_NUMBER_WITH_DEGREES = re.compile(r"(?<![\w.])(\d+(?:\.\d*)?|\.\d+)(\s*)(deg(?:rees?)?\b|°)")
_USER_UNDERSCORE_NAME = re.compile(r"(?<![\w.])_\w*")
_DECIMAL = re.compile(r"(?P<whole>[\d_]*)(?:\.(?P<fraction>[\d_]*))?(?:[eE](?P<exponent>[+-]?[\d_]+))?")
_SPELLINGS = {"^": "**", "−": "-", "·": "*", "×": "*"}  # what people type for Python's operators
_BINARY = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow)
_SUBSCRIPTS = "₀₁₂₃₄₅₆₇₈₉"
_SUBSCRIPT_DIGITS = str.maketrans(_SUBSCRIPTS, "0123456789")


@dataclass
class Reading:
    """What parsing noticed besides the value; one Reading may collect over a whole file."""

    places: int = 0  # the most decimal places of any decimal literal read
    fractions: set = field(default_factory=set)  # denominators written as fractions (l_1/2, 1/3)
    values: set = field(default_factory=set)  # the values of the decimal literals
    names: list = field(default_factory=list)  # (name, Location) of every symbol, in reading order
    decimals: list = field(default_factory=list)  # (literal, Location) of every decimal literal
    units: list = field(default_factory=list)  # ("pi" or "degrees", Location, inside sin/cos?)
    warnings: list = field(default_factory=list)  # (Location, message)

    @property
    def numbers(self) -> WrittenNumbers:
        return WrittenNumbers(self.places, frozenset(self.fractions), frozenset(self.values))

    def absorb(self, other: "Reading") -> None:
        """Add what another reading (of one field) noticed to this one (of the file)."""
        self.places = max(self.places, other.places)
        self.fractions |= other.fractions
        self.values |= other.values
        self.names += other.names
        self.decimals += other.decimals
        self.units += other.units
        self.warnings += other.warnings


def real_symbol(name: str) -> sympy.Symbol:
    """The real SymPy symbol for a name in a robot file.

    >>> real_symbol("l_1").is_real
    True
    """
    return sympy.Symbol(name, real=True)


def parse_expression(text: str, where: Location | None = None, reading: Reading | None = None) -> sympy.Expr:
    """Parse one expression; raise UserError pointing at the offending column. `reading`, if
    given, collects how numbers were written, where names and angle units stand, and warnings.

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
        slip = why_unreadable(text)
        if slip:
            raise UserError(slip[0], where.shifted(slip[1])) from None
        raise UserError(f"cannot read expression {text!r}", where.shifted(column)) from None
    except (ValueError, RecursionError, MemoryError):
        raise UserError(f"cannot read expression {text!r}", where) from None
    builder = _Builder(source, indent, columns, marks, where)
    value = builder.build(tree.body, 0)
    if reading is not None:
        reading.absorb(builder.reading)
    return value


def _refuse_odd_characters(text: str, where: Location) -> None:
    """Control characters, line breaks and comments have no place in one expression."""
    for index, ch in enumerate(text):
        if ch == "#":
            raise UserError("'#' is not allowed in an expression", where.shifted(index))
        if (ord(ch) < 32 and ch != "\t") or 0x7F <= ord(ch) < 0xA0 or ch in "\u2028\u2029":
            raise UserError(f"character U+{ord(ch):04X} is not allowed in an expression", where.shifted(index))


def _normalise(text: str) -> tuple[str, list[int], dict[int, int]]:
    """Rewrite `^`, `−`, `90deg`, `90°` and `θ₁` (as θ_1) into Python syntax.

    Returns the new text, the original column of each of its characters (plus one past the
    end), and the positions in the new text where a degree mark was inserted, each with the
    original column of its number.
    """
    pieces: list[tuple[str, int]] = []  # (new text, original column it came from)
    marks: dict[int, int] = {}
    position = 0
    for match in _NUMBER_WITH_DEGREES.finditer(text):
        pieces.extend((ch, position + i) for i, ch in enumerate(text[position:match.start()]))
        pieces.append(("(", match.start()))  # the unit binds to its number: 2**90deg is 2**(pi/2)
        pieces.extend((ch, match.start() + i) for i, ch in enumerate(match.group(1)))
        pieces.append(("*", match.start(3)))
        marks[sum(len(piece) for piece, _ in pieces)] = match.start()
        pieces.extend((ch, match.start(3)) for ch in _DEGREE_MARK + ")")
        position = match.end()
    pieces.extend((ch, position + i) for i, ch in enumerate(text[position:]))
    pieces = _subscripts_as_underscores(pieces)
    out, columns = [], []
    for piece, column in pieces:
        replacement = _SPELLINGS.get(piece, piece)
        out.append(replacement)
        columns.extend([column] * len(replacement))
    columns.append(len(text))
    return "".join(out), columns, marks


def _subscripts_as_underscores(pieces: list) -> list:
    """θ₁ is θ_1 and l₁₂ is l_12: subscript digits that end a name become an underscore subscript."""
    out: list = []
    subscripted = False  # the previous piece was a subscript digit
    for ch, column in pieces:
        if ch in _SUBSCRIPTS and (subscripted or _ends_a_name(out)):
            if not subscripted and out[-1][0] != "_":
                out.append(("_", column))
            out.append((ch.translate(_SUBSCRIPT_DIGITS), column))
            subscripted = True
            continue
        subscripted = False
        out.append((ch, column))
    return out


def _ends_a_name(pieces: list) -> bool:
    """Whether the text so far ends with a name (a letter or _, then letters, digits or _)."""
    start = len(pieces)
    while start and (pieces[start - 1][0].isalnum() or pieces[start - 1][0] == "_"):
        start -= 1
    return start < len(pieces) and not pieces[start][0].isdigit()


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


def _places(literal: str) -> int:
    """Decimal places a literal was written with: 0.425 has 3, 2.5e-3 has 4, 1e3 has 0."""
    match = _DECIMAL.fullmatch(literal.replace("_", ""))
    if not match:
        return 0
    exponent = match.group("exponent") or "0"
    exponent = int(exponent) if len(exponent) < 8 else 0
    return max(0, len(match.group("fraction") or "") - exponent)


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

    def __init__(self, source: str, indent: int, columns: list[int], marks: dict[int, int], where: Location):
        self.source, self.indent, self.columns, self.marks, self.where = source, indent, columns, marks, where
        self.parsed = source[indent:]  # the text `ast` saw
        self.reading = Reading()
        self.inside_trig = 0  # how many sin/cos calls enclose the node being built

    def start(self, node: ast.AST) -> int:
        """Where `node` starts in the normalised text, in characters."""
        return self.indent + _char_index(self.parsed, getattr(node, "col_offset", 0))

    def end(self, node: ast.AST) -> int:
        return self.indent + _char_index(self.parsed, getattr(node, "end_col_offset", 0) or 0)

    def place(self, node: ast.AST) -> Location:
        """Where `node` starts in the user's text."""
        return self.where.shifted(self.columns[min(self.start(node), len(self.columns) - 1)])

    def fail(self, node: ast.AST, message: str) -> UserError:
        return UserError(message, self.place(node))

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
        if result.is_real is False or result.has(sympy.I):  # sqrt(-(x*x)) is I*|x|: real only at 0
            raise self.fail(node, "expression is not a real number")
        return result

    def _Constant(self, node: ast.Constant, depth: int) -> sympy.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        if isinstance(value, int):
            return sympy.Integer(value)  # at most MAX_LENGTH digits; build() checks the size
        literal = self.source[self.start(node):self.end(node)]
        exact = _exact_decimal(literal)
        if exact is None:
            raise self.fail(node, "number too large or too small")
        self.reading.places = max(self.reading.places, _places(literal))
        self.reading.decimals.append((literal, self.place(node)))
        self.reading.values.add(exact)
        return exact  # exact: 0.1 stays 1/10, and the reading remembers it was written as a decimal

    def _Name(self, node: ast.Name, depth: int) -> sympy.Expr:
        name = node.id  # already NFKC-normalised by Python, so `ｓｉｎ` arrives as `sin`
        if name == _DEGREE_MARK and self.start(node) in self.marks:
            number = self.marks[self.start(node)]  # the column where the number of `90deg` starts
            self.reading.units.append(("degrees", self.where.shifted(number), self.inside_trig > 0))
            return sympy.pi / 180
        if name.startswith("_"):
            raise self.fail(node, f"name {name!r} may not start with '_'")
        if name in CONSTANTS:
            self.reading.units.append(("pi", self.place(node), self.inside_trig > 0))
            return CONSTANTS[name]
        if name in FUNCTIONS:
            raise self.fail(node, f"{name!r} is a function and cannot be used as a name")
        self.reading.names.append((name, self.place(node)))
        for check in (misspelt_pi, lookalike_letters):
            message = check(name)
            if message:
                self.reading.warnings.append((self.place(node), message))
        return real_symbol(name)

    def _UnaryOp(self, node: ast.UnaryOp, depth: int) -> sympy.Expr:
        if not isinstance(node.op, (ast.USub, ast.UAdd)):
            raise self.fail(node, f"operator {_OPERATORS.get(type(node.op).__name__, '?')} is not allowed")
        operand = self.build(node.operand, depth)
        return -operand if isinstance(node.op, ast.USub) else operand

    def _BinOp(self, node: ast.BinOp, depth: int) -> sympy.Expr:
        if not isinstance(node.op, _BINARY):
            raise self.fail(node, "only + - * / ** and ^ are allowed as operators")
        before = len(self.reading.units)
        left = self.build(node.left, depth)
        middle = len(self.reading.units)
        right = self.build(node.right, depth)
        if isinstance(node.op, (ast.Mult, ast.Div)):
            self._refuse_pi_times_degrees(node, self.reading.units[before:middle], self.reading.units[middle:])
        if isinstance(node.op, ast.Div) and right.is_Integer and abs(right) > 1 and not left.has(sympy.pi):
            self.reading.fractions.add(abs(int(right)))  # l_1/2 and 1/3 are fractions; pi/2 is an angle
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
        trig = name in ("sin", "cos")
        self.inside_trig += trig
        try:
            return FUNCTIONS[name](self.build(node.args[0], depth))
        finally:
            self.inside_trig -= trig

    def _Tuple(self, node: ast.Tuple, depth: int) -> sympy.Expr:
        text = self.source[self.start(node):self.end(node)]
        if DECIMAL_COMMA.fullmatch(text):
            raise self.fail(node, f"write decimals with a point: {text.strip().replace(',', '.')}, not "
                                  f"{text.strip()}")
        raise self.fail(node, "a tuple is not allowed in an expression")

    def _refuse_pi_times_degrees(self, node: ast.BinOp, left: list, right: list) -> None:
        """`pi/2deg` is π/(π/90) = 90 radians: a product of π and degrees is never what was meant."""
        kinds = {kind for kind, _, _ in left}, {kind for kind, _, _ in right}
        if ("pi" in kinds[0] and "degrees" in kinds[1]) or ("degrees" in kinds[0] and "pi" in kinds[1]):
            raise self.fail(node, "π and degrees in one product; write an angle either as pi/2 or as 90deg")


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
