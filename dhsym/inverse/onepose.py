"""The one-pose path of the module `dhsym ik --format python` writes (dhsym.inverse.codegen): the
batch path's statements again, in plain floats with `math` (`cmath` for a quartic's complex
values), for a single (4, 4) pose, where numpy's cost per call would outweigh the arithmetic.
Where plain floats raise (a division by 0, math.cos of an infinity) ik() takes the batch path,
whose NaN and infinities then decide.

>>> import sympy
>>> x, y = sympy.symbols("x y", real=True)
>>> code = MathCode({}, None, set())
>>> code.doprint(sympy.atan2(y, sympy.sqrt(1 - x**2)))
'math.atan2(y, root_one(1 - x**2))'
"""
from __future__ import annotations

import sympy
from sympy.printing.pycode import PythonCodePrinter


class Spelling:
    """Names made safe for Python (`names`: symbol name → Python name), a Dummy is a variable of the
    module's own, named already; decimals as the robot file wrote them (`numbers`)."""

    names: dict
    numbers: object

    def _print_Symbol(self, expr):
        return self.names.get(expr.name, expr.name)

    def _print_Dummy(self, expr):
        return expr.name

    def _print_Rational(self, expr):
        decimal = self.numbers.decimal(expr, alone=True) if self.numbers else None
        return decimal if decimal else f"{expr.p}/{expr.q}"

    def _print_Written(self, expr):  # a number as the robot file wrote it (dhsym.inverse.written)
        return expr.name

    # how the printer writes a choice (a statement of its own): the member where the wrist lines up
    CHOICE = ("if abs({guard}) < LINED_UP:  # the wrist's axes line up: {name} as its member",
              "    {name} = {member}")

    def choice_lines(self, name: str, expr) -> list[str]:
        """The lines that set `name` to the lined-up wrist's member where |guard| < LINED_UP
        (dhsym.inverse.codegen.members: the only choice the module makes); `expr` is
        Piecewise((member, |guard| < LINED_UP), (name, True))."""
        (member, condition), _ = expr.args
        guard = next(a for a in condition.args if isinstance(a, sympy.Abs)).args[0]
        return [line.format(name=name, member=self._print(member), guard=self._print(guard)) for line in self.CHOICE]


class MathCode(Spelling, PythonCodePrinter):
    """math.cos, math.atan2, …; root_one for a square root at the workspace's edge, cmath for the
    variables in `complex` (a quartic's roots by radicals); a function math lacks raises
    PrintMethodNotImplementedError (strict), and the module then has no one-pose path."""

    def __init__(self, names: dict, numbers, complex_: set):
        super().__init__({"fully_qualified_modules": True, "strict": True})
        self.names, self.numbers, self.complex = names, numbers, complex_
        self.casting = False  # printing a value that is computed in complex numbers

    def is_complex(self, expr) -> bool:
        if isinstance(expr, sympy.atan2):
            return False
        return expr in self.complex or any(self.is_complex(a) for a in expr.args)

    def _print(self, expr, **settings):
        text = super()._print(expr, **settings)
        if text.startswith("math.") and isinstance(expr, sympy.Function) and self.is_complex(expr):
            return "c" + text  # cmath.cos of a complex value, as numpy.cos takes a complex array
        return text

    def _print_atan2(self, expr):
        if any(self.is_complex(a) for a in expr.args):  # real, or NaN where the root is not real
            return f"real_angle_one({self._print(expr.args[0])}, {self._print(expr.args[1])})"
        return super()._print_atan2(expr)

    def _print_acos(self, expr):
        if self.casting:
            return f"cmath.acos({self._print(expr.args[0])})"
        return super()._print_acos(expr)

    def _print_Pow(self, expr, rational=False):
        if expr.exp == sympy.Rational(1, 2):
            complex_ = self.casting or self.is_complex(expr.base)
            return f"{'cmath.sqrt' if complex_ else 'root_one'}({self._print(expr.base)})"
        return super()._print_Pow(expr, rational)


HELPERS = [
    "def root_one(x):",
    "    if x >= 0:",
    "        return math.sqrt(x)",
    "    return 0.0 if x > -ROUNDING else math.nan", "", "",
    "def wrap_one(angle):",
    '    """The angle in [-pi, pi): one turn off or on is exact and cheap, the remainder is for more."""',
    "    if angle >= math.pi:",
    "        angle -= math.tau",
    "    elif angle < -math.pi:",
    "        angle += math.tau",
    "    return angle if -math.pi <= angle < math.pi else (angle + math.pi) % math.tau - math.pi", "", ""]

REAL_ANGLE = [
    "def real_angle_one(y, x):",
    "    if abs(y.imag) <= IMAGINARY * (1 + abs(y)) and abs(x.imag) <= IMAGINARY * (1 + abs(x)):",
    "        return math.atan2(y.real, x.real)",
    "    return math.nan", "", ""]


def statement_lines(statements, code) -> list[str]:
    """`name = expression` for each statement (a comment line where it is one), printed by `code`
    (numpy for a batch, math for one pose), with the complex casting each statement asks for."""
    lines = []
    for comment, symbol, expression, casting in statements:
        if comment is not None:
            lines.append(f"# {comment}")
            continue
        code.casting = casting
        if isinstance(expression, sympy.Piecewise):  # the lined-up wrist's member (Spelling.choice_lines)
            lines += code.choice_lines(code.doprint(symbol), expression)
            continue
        lines.append(f"{code.doprint(symbol)} = {code.doprint(expression)}")
    code.casting = False
    return lines


def function_text(statements, columns, revolute, parameters, code: MathCode, targets) -> list[str]:
    """The lines of `one_pose(T, *parameters)`, or [] where math cannot spell a statement or a value
    is a revolute angle in one place and not in another. `statements`: (comment, symbol, expression,
    casting) as codegen orders them; `columns`: each branch's values (a variable, a --free joint's
    symbol or None); `targets`: (index into T's first 12 elements, Python name) of the elements read."""
    angles = {value for values in columns for k, value in enumerate(values) if k in revolute and value is not None}
    others = {value for values in columns for k, value in enumerate(values) if k not in revolute}
    if angles & others:
        return []
    read = dict(targets)
    unpacked = ", ".join("(" + ", ".join(read.get(4 * r + c, "_") for c in range(4)) + ")" for r in range(3))
    lines = [f"def one_pose(T, {', '.join(parameters)}):" if parameters else "def one_pose(T):",
             '    """ik() of one pose (4, 4) in plain floats (see the module\'s docstring)."""',
             f"    {unpacked} = T.tolist()[:3]"]
    try:
        lines += ["    " + line for line in statement_lines(statements, code)]
        wrapped = [code.doprint(angle) for angle in sorted(angles, key=str)]
        lines += [f"    {name} = wrap_one({name})" for name in wrapped]
        rows = [[("math.nan" if value is None else code.doprint(value)) for value in values] for values in columns]
    except NotImplementedError:  # PrintMethodNotImplementedError: a function math does not have
        code.casting = False
        return []
    lines.append(f"    absent = (math.nan,) * {len(columns[0])}  # a branch exists whole or not at all")
    lines.append("    return numpy.array((")
    for row in rows:
        check = " + ".join(f"{value} - {value}" for value in dict.fromkeys(row) if value != "math.nan") or "math.nan"
        lines.append(f"        ({', '.join(row)}{',' if len(row) == 1 else ''}) if {check} == 0 else absent,")
    lines += ["    ), dtype=float)", "", ""]
    return lines
