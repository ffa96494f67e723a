"""The equations of motion for people and programs: printers that write the derivation's records
(`dhsym.dynamics.equations`) in the notation students write, and the JSON contract.

Names, text (LaTeX): d12 (d_{12}) for the elements of M, c121 (c_{121}) for the Christoffel
symbols, C12 for C's, φ1 (\\phi_{1}) for the gravity torques, τ1 (\\tau_{1}); rates and
accelerations dotted, θ̇1, q̈2, ḋ3 (\\dot{\\theta}_{1}, \\ddot{q}_{2}); ASCII theta1dot, q2ddot, phi1,
tau1. Indices are the joints as the robot prints them (`first_joint`), separated by commas once one
has two digits (d1,10). Each record has one `_print_<record>` method shared by the text and the
LaTeX printer: the two differ only in how a name and a symbol are written.

>>> import dhsym
>>> from dhsym.dynamics.derive import derive
>>> from dhsym.dynamics.equations import textbook_layout
>>> arm = dhsym.load("planar2r")
>>> result = derive(arm.chain, arm.filled_masses())
>>> layout = textbook_layout(result)
>>> printer = MotionTextPrinter(arm, result)
>>> printer.doprint(layout.inertia[2])
'd22 = Izz2 + m2(a2² + xc2² + yc2² + 2 a2 xc2)'
>>> printer.doprint(layout.motion[0])
'τ1 = d11 θ̈1 + d12 θ̈2 + 2 c121 θ̇1 θ̇2 + c221 θ̇2²'
>>> MotionLatexPrinter(arm, result).doprint(layout.christoffel[0])
'c_{121} = c_{211} = -a_{1} m_{2}[y_{c2} c_{2} + s_{2}(a_{2} + x_{c2})]'
"""
from __future__ import annotations

import sympy
from sympy.printing.conventions import split_super_sub

from ..core.numbers import WrittenNumbers
from ..dynamics.equations import CoriolisElement
from .dynamics_steps import MotionSteps, text_regressor, text_steps
from .names import display_name
from .printers import ExactPrinter, LatexPrinter, TextPrinter, chain_settings
from .render import break_element, text_legend, wrap

DOTS = {1: "\u0307", 2: "\u0308"}  # combining dot and diaeresis: θ̇1, θ̈1
LATEX_DOTS = {1: "\\dot", 2: "\\ddot"}
ASCII_DOTS = {1: "dot", 2: "ddot"}
GREEK = {"φ": ("phi", "\\phi"), "τ": ("tau", "\\tau")}


def motion_settings(robot) -> dict:
    """The printer settings of a robot for its dynamics: `chain_settings`, with the numbers of its
    masses written as its file wrote them. Products of masses and squared lengths have more decimal
    places than any number written, so a decimal ends within four times the places written."""
    settings = chain_settings(robot)
    mine, theirs = settings["numbers"] or WrittenNumbers(), robot.masses.numbers or WrittenNumbers()
    places = max(mine.places, theirs.places)
    settings["numbers"] = WrittenNumbers(2 * places, mine.fractions | theirs.fractions, mine.values | theirs.values)
    return settings


def dotted(name: str, order: int, style: str) -> str:
    """θ1 → θ̇1 (order 1) or θ̈1 (2): the mark over the letters before the index; ASCII theta1dot.

    >>> dotted("θ1", 2, "unicode"), dotted("theta1", 1, "ascii")
    ('θ̈1', 'theta1dot')
    """
    if style == "ascii":
        return name + ASCII_DOTS[order]
    letters = len(name.rstrip("0123456789₀₁₂₃₄₅₆₇₈₉′"))
    return name[:letters] + DOTS[order] + name[letters:]


class _Motion(MotionSteps):
    """What the text and the LaTeX printer of the dynamics share: the records and the rates."""

    def _motion_setup(self, robot, result) -> None:
        self.rates = dict(zip(result.rates, result.variables))
        self.accelerations = dict(zip(result.accelerations, result.variables))
        self.first = self._settings["first_joint"]
        self.masses = [link.mass for link in robot.filled_masses().links]

    def doprint(self, expr):
        if isinstance(expr, sympy.Basic):
            return super().doprint(expr)
        return self._print(expr)

    def _print_Symbol(self, expr):
        for order, table in ((1, self.rates), (2, self.accelerations)):
            variable = table.get(expr)
            if variable is not None:
                return self.rate(variable, order)
        return super()._print_Symbol(expr)

    def rate(self, variable, order: int) -> str:
        if self.style != "latex":
            return dotted(display_name(variable.name, self.style), order, self.style)
        base, _, subs = split_super_sub(variable.name)
        return f"{LATEX_DOTS[order]}{{{display_name(base, 'latex')}}}" + "".join(f"_{{{s}}}" for s in subs[:1])

    def name(self, letter: str, *joints: int) -> str:
        """d12, c121, φ1 (LaTeX d_{12}, \\phi_{1}): the joints numbered as printed."""
        numbers = [str(j + self.first - 1) for j in joints]
        index = ("," if any(len(x) > 1 for x in numbers) else "").join(numbers)
        ascii_name, latex_name = GREEK.get(letter, (letter, letter))
        if self.style == "latex":
            return f"{latex_name}_{{{index}}}"
        return (ascii_name if self.style == "ascii" else letter) + index

    def sides(self, record) -> tuple[str, str]:
        """(left side, right side) of a record's equation, for layouts that break the right side."""
        return getattr(self, f"_sides_{type(record).__name__}")(record)

    def _equation(self, record) -> str:
        left, right = self.sides(record)
        return f"{left} = {right}"

    _print_InertiaElement = _print_ChristoffelSymbol = _print_CoriolisElement = _equation
    _print_GravityTorque = _print_EquationOfMotion = _equation

    def _sides_InertiaElement(self, record):
        return self.name("d", record.i, record.j), self.doprint(record.value)

    def _sides_ChristoffelSymbol(self, record):
        names = [self.name("c", record.i, record.j, record.k)]
        if record.i != record.j:
            names.append(self.name("c", record.j, record.i, record.k))
        return " = ".join(names), self.doprint(record.value)

    def _sides_CoriolisElement(self, record):
        terms = " + ".join(f"{self.name('c', i, record.j, record.k)} {self.doprint(rate)}" for i, rate in record.terms)
        return self.name("C", record.k, record.j), terms

    def _sides_GravityTorque(self, record):
        return self.name("φ", record.k), self.doprint(record.value)

    def _sides_EquationOfMotion(self, record):
        terms = [f"{self.name('d', record.k, j)} {self.doprint(record.accelerations[j - 1])}" for j in record.inertia]
        for term in record.velocity:
            rates = (self.doprint(term.rates[0] ** 2) if term.i == term.j
                     else f"{self.doprint(term.rates[0])} {self.doprint(term.rates[1])}")
            terms.append(f"{'2 ' if term.times == 2 else ''}{self.name('c', term.i, term.j, term.k)} {rates}")
        if record.gravity:
            terms.append(self.name("φ", record.k))
        return self.name("τ", record.k), " + ".join(terms) or "0"


class MotionTextPrinter(_Motion, TextPrinter):
    """Text (Unicode, or ASCII with `ascii=True`) for a robot's derived dynamics `result`."""

    def __init__(self, robot, result, ascii: bool = False):
        TextPrinter.__init__(self, motion_settings(robot), ascii=ascii)
        self._motion_setup(robot, result)


class MotionLatexPrinter(_Motion, LatexPrinter):
    """LaTeX for a robot's derived dynamics `result`."""

    def __init__(self, robot, result):
        LatexPrinter.__init__(self, motion_settings(robot))
        self._motion_setup(robot, result)

    def _print_Pow(self, expr):
        """(q̇1 + q̇2)² in plain brackets, which a layout may break a line inside (\\left( may not be)."""
        if expr.base.is_Add and expr.exp.is_Integer and expr.exp > 1:
            return f"{self._factor(expr.base)}^{{{expr.exp}}}"
        return super()._print_Pow(expr)


def json_dynamics(robot, result) -> dict:
    """The contract programs read: M, C and g as SymPy-parsable strings with the robot file's names
    and decimals as written, the joint variables and their rates in joint order, every other name used
    (`parameters`), the accelerations' names and the Christoffel symbols that are not zero."""
    exact = ExactPrinter(motion_settings(robot)).doprint
    M, C, g = result.M, result.C, result.g
    motion = set(result.variables) | set(result.rates)
    used = set().union(*(sympy.sympify(x).free_symbols for x in [*M, *C, *g])) - motion
    first = chain_settings(robot)["first_joint"]
    return {
        "robot": robot.name,
        "convention": robot.chain.convention,
        "joint_variables": [s.name for s in result.variables],
        "velocities": [s.name for s in result.rates],
        "accelerations": [s.name for s in result.accelerations],
        "M": [[exact(M[i, j]) for j in range(M.cols)] for i in range(M.rows)],
        "C": [[exact(C[i, j]) for j in range(C.cols)] for i in range(C.rows)],
        "g": [exact(x) for x in g],
        "christoffel": [{"i": i + first - 1, "j": j + first - 1, "k": k + first - 1, "value": exact(value)}
                        for (i, j, k), value in sorted(result.christoffel.items(), key=lambda item: item[0][::-1])],
        "parameters": sorted(s.name for s in used),
    }


HEADINGS = {
    "unicode": {
        "M": "Inertia matrix M(q) = [dij], symmetric (dji = dij):",
        "christoffel": "Christoffel symbols cijk = ½(∂dkj/∂qi + ∂dki/∂qj − ∂dij/∂qk) that are not zero, "
                       "by the equation k they enter (cjik = cijk):",
        "no christoffel": "Christoffel symbols cijk = ½(∂dkj/∂qi + ∂dki/∂qj − ∂dij/∂qk): all zero, so C = 0",
        "C": "Coriolis and centrifugal matrix C(q, q̇), Ckj = Σi cijk q̇i (the elements that are not zero):",
        "g": "Gravity vector g(q) = ∂P/∂q, φk = ∂P/∂qk:",
        "tau": "Equations of motion τk = Σj dkj q̈j + Σij cijk q̇i q̇j + φk:",
    },
    "ascii": {
        "M": "Inertia matrix M(q) = [dij], symmetric (dji = dij):",
        "christoffel": "Christoffel symbols cijk = 1/2 (d dkj/dqi + d dki/dqj - d dij/dqk) that are not zero, "
                       "by the equation k they enter (cjik = cijk):",
        "no christoffel": "Christoffel symbols cijk = 1/2 (d dkj/dqi + d dki/dqj - d dij/dqk): all zero, so C = 0",
        "C": "Coriolis and centrifugal matrix C(q, qdot), Ckj = sum over i of cijk qidot (the elements that are "
             "not zero):",
        "g": "Gravity vector g(q) = dP/dq, phik = dP/dqk:",
        "tau": "Equations of motion tauk = sum over j of dkj qjddot + sum over i, j of cijk qidot qjdot + phik:",
    },
}
METHODS = {"lagrange": "by Lagrange's equations (Spong)", "newton-euler": "by the Newton–Euler recursion (Craig)"}
C_VALUES_UP_TO = 3  # joints: C's elements are written out too (a larger arm's are sums of the symbols above)


def text_dynamics(robot, layout, printer: TextPrinter, width: int = 100, method: str = "lagrange",
                  steps=None, regressor=None) -> str:
    """The derivation's results as a book prints them (see the module's docstring), lines broken
    at `width`, after the derivation's `steps` (records of dhsym.dynamics.lagrange_steps or
    craig_steps) when given, and before the `regressor` (dhsym.dynamics.identification) when
    given; the legend of the c/s abbreviations last."""
    style = "ascii" if printer.style == "ascii" else "unicode"
    headings = HEADINGS[style]

    def lines(records) -> str:
        out = []
        for record in records:
            left, right = printer.sides(record)
            if isinstance(record, CoriolisElement) and layout.n <= C_VALUES_UP_TO:
                right += " = " + printer.doprint(record.value)
            out.append(break_element(f"{left} = ", right, width))
        return "\n".join(out)

    title = f"{robot.name}: equations of motion  ({robot.chain.convention} DH)"
    blocks = [wrap(title, width) + "\n" + wrap(f"τ = M(q) q̈ + C(q, q̇) q̇ + g(q), {METHODS[method]}", width)]
    if steps is not None:
        blocks += text_steps(steps, printer, width, method)
    blocks.append(wrap(headings["M"], width) + "\n" + lines(layout.inertia))
    if layout.christoffel:
        blocks.append(wrap(headings["christoffel"], width) + "\n" + lines(layout.christoffel))
        blocks.append(wrap(headings["C"], width) + "\n" + lines(layout.coriolis))
    else:
        blocks.append(wrap(headings["no christoffel"], width))
    blocks.append(wrap(headings["g"], width) + "\n" + lines(layout.gravity))
    blocks.append(wrap(headings["tau"], width) + "\n" + lines(layout.motion))
    if regressor is not None:
        blocks += text_regressor(regressor, printer, width)
    legend = text_legend(printer, width)
    text = "\n\n".join(blocks) + ("\n\n" + legend if legend else "")
    return to_ascii(text) if style == "ascii" else text


ASCII = (("ω̇", "wdot"), ("ω", "w"), ("v̇", "vdot"), ("q̈", "qddot"), ("q̇", "qdot"), ("ᶜI", "cI"), ("τ", "tau"),
         ("φ", "phi"), ("Σ", "sum "), ("ᵀ", "^T"), ("∂", "d"), ("×", "x"), ("−", "-"), ("–", "-"), ("½", "1/2"),
         ("≥", ">="), ("πb", "pi_b"), ("π", "pi"))


def to_ascii(text: str) -> str:
    """What the ASCII printer leaves in Unicode (titles, headings) in plain letters; the printed
    expressions are ASCII already.

    >>> to_ascii("τ = M(q) q̈, ½ ωᵀ ᶜI ω")
    'tau = M(q) qddot, 1/2 w^T cI w'
    """
    for unicode, plain in ASCII:
        text = text.replace(unicode, plain)
    return text
