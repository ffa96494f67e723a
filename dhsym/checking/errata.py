"""Checking what a lecture or book printed against the derived result, element by element.

Each element gets a verdict, *agrees* or *erratum*, and an erratum shows what was printed,
what is correct, and (when the caller knows) why they differ.

>>> import sympy
>>> t1, l1 = sympy.symbols("theta_1 l_1", real=True)
>>> printed = [["cos(theta_1)", "l_1*cos(theta_1)"], ["sin(theta_1)", "l_1*cos(theta_1)"]]
>>> derived = sympy.Matrix([[sympy.cos(t1), l1*sympy.cos(t1)], [sympy.sin(t1), l1*sympy.sin(t1)]])
>>> result = compare_printed(printed, derived, "slide 4")
>>> result.ok, [(e.row, e.column) for e in result.errata]
(False, [(2, 2)])
>>> print(result.report([t1]))
slide 4: 3 of 4 elements agree; 1 erratum
  erratum at (2,2): printed l1 c1, correct l1 s1

Only some elements printed? Pass them by position:

>>> compare_printed({(1, 2): "l_1*cos(theta_1)"}, derived, "spoken").ok
True
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from ..io.expr import parse_expression
from ..printing.printers import LatexPrinter, TextPrinter
from .verify import Verdict, check


@dataclass
class ElementCheck:
    """One printed element against its derived value (row and column count from 1)."""

    row: int
    column: int
    printed: sympy.Expr
    derived: sympy.Expr
    verdict: Verdict
    reason: str = ""

    @property
    def ok(self) -> bool:
        return bool(self.verdict)


@dataclass
class Comparison:
    """A printed matrix (or vector, or single expression) checked against a derivation."""

    title: str
    elements: list[ElementCheck] = field(default_factory=list)
    joint_variables: tuple = ()  # for the c/s notation of reports and tables
    fold: bool = False  # in a notebook, keep the table of a fully agreeing comparison folded

    @property
    def ok(self) -> bool:
        return all(e.ok for e in self.elements)

    @property
    def errata(self) -> list[ElementCheck]:
        return [e for e in self.elements if not e.ok]

    def summary(self) -> str:
        agree = len(self.elements) - len(self.errata)
        errata = len(self.errata)
        tail = "all agree" if not errata else f"{errata} errat{'um' if errata == 1 else 'a'}"
        return f"{self.title}: {agree} of {len(self.elements)} elements agree; {tail}"

    def report(self, joint_variables=None) -> str:
        """Plain-text verdict, one line per erratum, in the c/s notation."""
        printer = TextPrinter(self.joint_variables if joint_variables is None else joint_variables)
        lines = [self.summary()]
        for e in self.errata:
            line = (f"  erratum at ({e.row},{e.column}): printed {printer.doprint(e.printed)}, "
                    f"correct {printer.doprint(e.derived)}")
            lines.append(line + (f" — {e.reason}" if e.reason else ""))
        return "\n".join(lines)

    def markdown(self, joint_variables=None, fold: bool = False) -> str:
        """A table for notebooks: every element with its verdict; errata in bold.

        With `fold`, a comparison that fully agrees shows only its verdict line and keeps the
        table behind a click, so that the errata stand out in a long notebook.
        """
        printer = LatexPrinter(self.joint_variables if joint_variables is None else joint_variables)
        icon = "✅" if self.ok else "❌"
        table = ["| element | printed | derived | verdict |", "|---|---|---|---|"]
        for e in self.elements:
            verdict = "agrees" if e.ok else "**erratum**" + (f": {e.reason}" if e.reason else "")
            table.append(f"| ({e.row},{e.column}) | ${printer.doprint(e.printed)}$ | ${printer.doprint(e.derived)}$ "
                         f"| {verdict} |")
        headline = f"{icon} {self.summary()}"
        if fold and self.ok:
            return f"<details><summary>{headline}</summary>\n\n" + "\n".join(table) + "\n\n</details>"
        return "\n".join([f"**{headline}**", ""] + table)

    def _repr_markdown_(self) -> str:
        return self.markdown(fold=self.fold)


def compare_printed(printed, derived, title: str = "printed result", reasons=None, joint_variables=(),
                    fold: bool = False) -> Comparison:
    """Compare a transcription with the derived matrix, vector or expression.

    `printed` is a SymPy object or nested lists of strings/expressions of the derived shape,
    or a dict {(row, column): value} (counted from 1) when the lecture printed only some
    elements; strings are read with dhsym's safe parser. `reasons` maps (row, column), counted from 1,
    to a sentence explaining an expected erratum (slip, OCR error, disagreement).
    `joint_variables` (e.g. robot.chain.joint_variables) makes reports use c1, s23; with `fold`
    the notebook table of a fully agreeing comparison stays folded.
    """
    derived = sympy.Matrix(derived) if not isinstance(derived, sympy.Expr) else sympy.Matrix([[derived]])
    reasons = reasons or {}
    if isinstance(printed, dict):
        result = Comparison(title, joint_variables=tuple(joint_variables), fold=fold)
        for (r, c), value in sorted(printed.items()):
            expr = _read(value)
            result.elements.append(ElementCheck(r, c, expr, derived[r - 1, c - 1], check(expr, derived[r - 1, c - 1]),
                                                reasons.get((r, c), "")))
        return result
    printed = transcribe(printed)
    if printed.shape != derived.shape:
        if printed.shape == derived.T.shape and 1 in printed.shape:
            printed = printed.T
        else:
            raise ValueError(f"printed shape {printed.shape} differs from derived shape {derived.shape}")
    result = Comparison(title, joint_variables=tuple(joint_variables), fold=fold)
    for r in range(derived.rows):
        for c in range(derived.cols):
            verdict = check(printed[r, c], derived[r, c])
            result.elements.append(ElementCheck(r + 1, c + 1, printed[r, c], derived[r, c], verdict,
                                                reasons.get((r + 1, c + 1), "")))
    return result


def transcribe(printed) -> sympy.Matrix:
    """A printed matrix (nested lists of text or expressions) as SymPy, read by the safe parser,
    so that printed matrices can be multiplied as the lecture multiplies them.

    >>> transcribe([["cos(theta_1)", "0"], ["0", "1"]])
    Matrix([
    [cos(theta_1), 0],
    [           0, 1]])
    """
    if isinstance(printed, sympy.MatrixBase):
        return sympy.Matrix(printed)
    if isinstance(printed, (str, sympy.Expr, int)):
        printed = [[printed]]
    rows = [row if isinstance(row, (list, tuple)) else [row] for row in printed]
    return sympy.Matrix([[_read(x) for x in row] for row in rows])


def _read(value) -> sympy.Expr:
    if isinstance(value, str):
        return parse_expression(value)
    return sympy.sympify(value, strict=True)
