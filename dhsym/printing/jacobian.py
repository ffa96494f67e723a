"""Jacobians for people: 6×n matrices in the c/s notation, their determinant and singular
configurations, the velocity propagation step by step, and JSON.

Same layout rule as `dhsym fk`: a matrix that fits the width is printed as a matrix; otherwise
the matrix of names J11 … J6n is printed, then the elements column by column, and an element
wider than the line breaks before a + or − (`render.text_grid`).

>>> import dhsym
>>> from dhsym.printing.render import text_printer
>>> arm = dhsym.load("planar2r")
>>> print(text_grid(velocity_of(arm, 2, 2).matrix, text_printer(arm)))
⎡ a1 s2        0  ⎤
⎢ a2 + a1 c2   a2 ⎥
⎢ 0            0  ⎥
⎢ 0            0  ⎥
⎢ 0            0  ⎥
⎣ 1            1  ⎦
"""
from __future__ import annotations

import textwrap
from dataclasses import dataclass

import sympy
from sympy.printing.conventions import split_super_sub

from ..core.chain import Frame
from ..core.numbering import PLAIN, Numbering
from ..core.robot import Robot
from ..velocity import Determinant, Singularity, determinant, jacobian, singularities
from . import render
from .names import display_name, subscript, superscript
from .printers import ExactPrinter, LatexPrinter, TextPrinter, chain_settings


@dataclass(frozen=True)
class Velocity:
    """A robot's Jacobian of the origin of `point` in `frame` (the chain's frames), its determinant
    and the singular configurations, worked out with what its file says (decimals, sample values,
    numbering)."""

    frame: Frame
    point: Frame
    matrix: sympy.Matrix
    determinant: Determinant
    singularities: list[Singularity]


def velocity_of(robot: Robot, frame: Frame, point: Frame) -> Velocity:
    """ᵏJ of `robot` for the chain's frames `frame` and `point`, with its determinant and singularities;
    a transform refused as too large is named by the printed frames."""
    chain, numbering = robot.chain, robot.numbering
    with numbering.printed():
        matrix = jacobian(chain, frame, point)
        result = determinant(chain, frame, point, numbers=robot.numbers, sample=robot.sample, numbering=numbering)
    found = singularities(chain, result, point, sample=robot.sample, numbering=numbering)
    return Velocity(frame, point, matrix, result, found)


class _Rates:
    """Prints the joint rates θ̇1, ḋ3 (LaTeX \\dot{\\theta}_{1}; ASCII theta1dot)."""

    def _print_Symbol(self, expr):
        variable = self.rates.get(expr)
        if variable is None:
            return super()._print_Symbol(expr)
        if self.style == "latex":
            base, _, subs = split_super_sub(variable.name)
            return f"\\dot{{{display_name(base, 'latex')}}}" + "".join(f"_{{{s}}}" for s in subs[:1])
        name = display_name(variable.name, self.style)
        return name + "dot" if self.style == "ascii" else _dotted(name)


def _dotted(name: str) -> str:
    """θ1 -> θ̇1: a combining dot over the letters before the index."""
    letters = len(name.rstrip("0123456789₀₁₂₃₄₅₆₇₈₉"))
    return name[:letters] + "\u0307" + name[letters:]


class RateTextPrinter(_Rates, TextPrinter):
    def __init__(self, joint_variables, rates, ascii=False, settings=None):
        TextPrinter.__init__(self, joint_variables, settings, ascii=ascii)
        self.rates = dict(zip(rates, joint_variables))


class RateLatexPrinter(_Rates, LatexPrinter):
    def __init__(self, joint_variables, rates, settings=None):
        LatexPrinter.__init__(self, joint_variables, settings)
        self.rates = dict(zip(rates, joint_variables))


def jacobian_title(frame, point, style: str = "unicode") -> str:
    """⁰J (unicode), 0J (ascii), {}^{0}J (latex) for the Jacobian in `frame`; the point is
    said in words by the caller."""
    if style == "latex":
        name = f"\\mathrm{{{frame}}}" if isinstance(frame, str) else str(frame)
        return f"{{}}^{{{name}}}J"
    if style == "unicode" and isinstance(frame, int):
        return f"{superscript(str(frame))}J"
    return f"{frame}J" if isinstance(frame, int) else f"J({frame})"


def point_words(point) -> str:
    """'origin of frame 6', 'origin of the tool frame'."""
    return f"origin of frame {point}" if isinstance(point, int) else f"origin of the {point} frame"


def element_name(row: int, column: int, n: int, style: str) -> str:
    """J11 … J6n; J_{1,10} once a column number has two digits."""
    index = f"{row + 1}{',' if n > 9 else ''}{column + 1}"
    if style == "latex":
        return f"J_{{{index}}}"
    return f"J{index}" if style == "ascii" else f"J{subscript(index)}"


def text_grid(matrix: sympy.Matrix, printer: TextPrinter, width: int = 100) -> str:
    """An aligned matrix, or the matrix of names J11 … J6n and the elements column by column
    (long ones broken) when too wide: `render.text_grid`, the rule of every surface."""
    cells = [[printer.doprint(matrix[r, c]) for c in range(matrix.cols)] for r in range(matrix.rows)]
    style = "ascii" if printer.style == "ascii" else "unicode"
    names = [[element_name(r, c, matrix.cols, style) for c in range(matrix.cols)] for r in range(matrix.rows)]
    return render.text_grid(cells, names, matrix.rows, printer.style == "ascii", width)


def text_determinant(result, found, printer: TextPrinter, width: int = 100) -> str:
    """'det J = …', what was computed, and one line per singular factor with its meaning."""
    label = "det J = " if result.block == "J" else f"det J[{result.block}] = "
    lines = []
    if result.value is not None:
        lines.extend(render.break_element(label, printer.doprint(result.value), width).splitlines())
    if result.note:
        lines.append(render.wrap(result.note, width))
    if found:
        lines.append("singular where")
        for singularity in found:
            lines += singular_lines(printer.doprint(singularity.factor), singularity.describe(joint_label(printer)),
                                    width)
    elif result.value is not None:
        lines.append("no factor with joint variables: never singular" if result.value != 0
                     else "identically zero: singular in every configuration")
    return "\n".join(lines)


def singular_lines(factor: str, meaning: str, width: int) -> list[str]:
    """`  factor = 0: meaning`, wrapped at `width` with every word whole: the meaning starts on the
    factor's line when its first word fits there, else on the next; a factor longer than the line
    breaks like a matrix element.

    >>> print(*singular_lines("s5", "wrist: axes 4 and 6 line up", 40), sep="\\n")
      s5 = 0: wrist: axes 4 and 6 line up
    >>> print(*singular_lines("1.596 s2 c3 c4 s5 + 6.86 s2 s3 s5 − 0.057 s23 c4² c5", "the joint velocities "
    ...                       "are dependent here", 40), sep="\\n")
      1.596 s2 c3 c4 s5 + 6.86 s2 s3 s5
        − 0.057 s23 c4² c5 = 0:
        the joint velocities are dependent
        here
    """
    head = f"  {factor} = 0:"
    first_word = meaning.split(" ", 1)[0]
    if render.display_width(head) + 1 + len(first_word) <= width:
        return _words(meaning, width, head + " ")
    return render.break_element("  ", f"{factor} = 0:", width).splitlines() + _words(meaning, width, "    ")


def _words(text: str, width: int, first: str) -> list[str]:
    """Prose wrapped at `width` after the `first` line's start, continuation lines indented four;
    never a word broken (a combining mark takes no column)."""
    room = width - render.display_width(first) + len(first)  # textwrap counts characters, the terminal columns
    return textwrap.wrap(text, room, initial_indent=first, subsequent_indent="    ", break_long_words=False,
                         break_on_hyphens=False)


def joint_label(printer):
    """Row number -> the joint's label in the notation (a wrist's rows 1..3 are joints 4..6)."""
    labels = list(printer.notation.label.values())
    return lambda row: str(labels[row - 1])


def text_steps(steps, printer: TextPrinter, width: int = 100, numbering: Numbering = PLAIN) -> str:
    """Craig's outward iteration: ¹ω₁ = (…), ¹v₁ = (…) for each frame, in that frame, numbered as printed."""
    lines = []
    for step in steps:
        for symbol, vector in (("ω", step.omega), ("v", step.velocity)):
            entries = ", ".join(printer.doprint(x) for x in vector)
            label = f"{vector_name(symbol, numbering.frame(step.frame), printer.style)} = "
            lines.extend(render.break_element(label, f"({entries})", width).splitlines())
    return "\n".join(lines)


def vector_name(symbol: str, frame, style: str) -> str:
    """¹ω₁ (unicode), 1w1 (ascii), ω(tool) for a named frame."""
    if style == "ascii":
        symbol = {"ω": "w"}.get(symbol, symbol)
        return f"{frame}{symbol}{frame}" if isinstance(frame, int) else f"{symbol}({frame})"
    if not isinstance(frame, int):
        return f"{symbol}({frame})"
    return f"{superscript(str(frame))}{symbol}{subscript(str(frame))}"


def json_jacobian(robot: Robot, velocity: Velocity) -> dict:
    """Full cos/sin strings with the robot file's symbol names, decimals and offsets as written;
    sympy.sympify reads them. Frames as printed."""
    sstr = ExactPrinter(chain_settings(robot)).doprint
    matrix, result = velocity.matrix, velocity.determinant
    return {
        "robot": robot.name,
        "convention": robot.chain.convention,
        "frame": robot.numbering.frame(velocity.frame),
        "point": robot.numbering.frame(velocity.point),
        "joint_variables": [s.name for s in robot.chain.joint_variables],
        "matrix": [[sstr(matrix[r, c]) for c in range(matrix.cols)] for r in range(matrix.rows)],
        "determinant": None if result.value is None else sstr(result.value),
        "singularities": [sstr(f) for f in result.factors],
    }
