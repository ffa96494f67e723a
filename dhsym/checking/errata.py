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

Say what kind of error each erratum is (see `kinds`) and give the element as the transcript prints
it; dhsym's reading of it is shown beside it:

>>> slip = compare_printed({(2, 2): "l_1*cos(theta_1)"}, derived, "slide 4",
...                        reasons={(2, 2): spoken("cos for sin", lines=(87,))}, verbatim={(2, 2): "l1 C1"})
>>> print(slip.report([t1]))
slide 4: 0 of 1 elements agree; 1 erratum (1 spoken slip)
  spoken slip at (2,2) (l.87): printed "l1 C1" (read as l1 c1), correct l1 s1 — cos for sin
>>> print(tally([result, slip]))
genuine errors of the lecture: 1 (1 spoken slip), in 1 element; unsure: 0; unclassified: 1 element

In a notebook a comparison shows itself as markdown: one line when all agree, and for each erratum
the element as printed, dhsym's value in the printed term order with the differing terms boxed,
and the difference:

>>> print(compare_printed({(1, 2): "l_1*cos(theta_1)"}, derived, "slide 4", joint_variables=[t1]).markdown())
✅ slide 4: the printed element agrees
>>> print(slip.markdown([t1]))
❌ **slide 4: 0 of 1 elements agree; 1 erratum (1 spoken slip)**
<BLANKLINE>
- **(2,2)** spoken slip (l.87): cos for sin
    - printed: `l1 C1`
    - dhsym, in the printed order: $\\boxed{l_{1} s_{1}}$
    - printed − dhsym: $l_{1}(c_{1} - s_{1})$
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import sympy

from ..core.verify import Verdict, check
from ..io.expr import parse_expression
from ..printing.printers import LatexPrinter, TextPrinter

# the kinds are re-exported, so that a notebook imports one module to classify its errata
from .kinds import Cause, Kind, counted, hypothetical, inconsistency, ocr, slide, spoken  # noqa: F401
from .kinds import corrected as corrected  # noqa: F401
from .kinds import printed_differences as printed_differences  # noqa: F401
from .kinds import tally as tally_causes
from .regroup import difference, printed_terms, regroup


@dataclass
class ElementCheck:
    """One printed element against its derived value (row and column count from 1)."""

    row: int
    column: int
    printed: sympy.Expr
    derived: sympy.Expr
    verdict: Verdict
    cause: Cause | None = None  # why it differs, when the caller knows
    verbatim: str = ""  # the element as the transcript prints it
    source: str = ""  # the printed element as given to compare_printed, in the lecture's term order

    @property
    def ok(self) -> bool:
        return bool(self.verdict)

    @property
    def kind(self) -> Kind | None:
        return self.cause.kind if self.cause else None

    @property
    def reason(self) -> str:
        return self.cause.why if self.cause else ""

    def label(self) -> str:
        """'spoken slip', 'transcription damage', or plain 'erratum' when unclassified."""
        return self.kind.value if self.kind else "erratum"

    def where(self) -> str:
        return f" ({self.cause.where()})" if self.cause and self.cause.where() else ""


@dataclass
class Comparison:
    """A printed matrix (or vector, or single expression) checked against a derivation."""

    title: str
    elements: list[ElementCheck] = field(default_factory=list)
    joint_variables: tuple = ()  # for the c/s notation of reports and tables
    fold: bool = False  # kept for old callers: a fully agreeing comparison is always one line
    partial: bool = False  # only some elements of the matrix were printed, and so compared

    @property
    def ok(self) -> bool:
        return all(e.ok for e in self.elements)

    @property
    def errata(self) -> list[ElementCheck]:
        return [e for e in self.elements if not e.ok]

    def summary(self) -> str:
        agree = len(self.elements) - len(self.errata)
        if not self.errata:
            return f"{self.title}: {_all_agree(len(self.elements), self.partial)}"
        errata = len(self.errata)
        tail = f"{errata} errat{'um' if errata == 1 else 'a'}"
        kinds = Counter(e.kind for e in self.errata if e.kind)
        if kinds:
            tail += " (" + ", ".join(counted(n, kind.value) for kind, n in kinds.items()) + ")"
        return f"{self.title}: {agree} of {len(self.elements)} elements agree; {tail}"

    def report(self, joint_variables=None) -> str:
        """Plain-text verdict, one line per erratum, in the c/s notation."""
        printer = TextPrinter(self.joint_variables if joint_variables is None else joint_variables)
        lines = [self.summary()]
        for e in self.errata:
            printed = printer.doprint(e.printed)
            if e.verbatim:
                printed = f'"{e.verbatim}" (read as {printed})'
            line = (f"  {e.label()} at ({e.row},{e.column}){e.where()}: printed {printed}, "
                    f"correct {printer.doprint(e.derived)}")
            lines.append(line + (f" — {e.reason}" if e.reason else ""))
        return "\n".join(lines)

    def markdown(self, joint_variables=None, fold: bool = False) -> str:
        """The verdict for a notebook: one line when every element agrees; else the elements that
        agree on one line and, for each erratum, the element as printed, dhsym's value in the
        printed term order with the differing terms boxed, and printed − dhsym.

        Long expressions are written term by term, so that the page breaks them between terms
        instead of shrinking them. (`fold` is kept for old callers; agreement is always one line.)
        """
        printer = LatexPrinter(self.joint_variables if joint_variables is None else joint_variables)
        if self.ok:
            return f"✅ {self.summary()}"
        lines = [f"❌ **{self.summary()}**", ""]
        agreeing = [f"({e.row},{e.column})" for e in self.elements if e.ok]
        if agreeing:
            lines += ["agree: " + ", ".join(agreeing), ""]
        for group in _by_cause(self.errata):
            first = group[0]
            why = f": {first.reason}" if first.reason else ""
            places = ", ".join(f"({e.row},{e.column})" for e in group)
            lines.append(f"- **{places}** {first.label()}{first.where()}{why}")
            for e in group:  # one cause shared by several elements is said once, then each element shown
                indent = "    " if len(group) == 1 else "        "
                if len(group) > 1:
                    lines.append(f"    - **({e.row},{e.column})**")
                shown = _code_span(e.verbatim) if e.verbatim else _terms_latex(_printed_order(e), printer)
                lines.append(f"{indent}- printed: {shown}")
                lines.append(f"{indent}- dhsym, in the printed order: {_terms_latex(_regrouped(e), printer)}")
                lines.append(f"{indent}- printed − dhsym: ${printer.doprint(difference(e.printed, e.derived))}$")
        return "\n".join(lines)

    def _repr_markdown_(self) -> str:
        return self.markdown(fold=self.fold)


def compare_printed(printed, derived, title: str = "printed result", reasons=None, joint_variables=(),
                    fold: bool = False, verbatim=None) -> Comparison:
    """Compare a transcription with the derived matrix, vector or expression.

    `printed` is a SymPy object or nested lists of strings/expressions of the derived shape,
    or a dict {(row, column): value} (counted from 1) when the lecture printed only some
    elements; strings are read with dhsym's safe parser. `reasons` maps (row, column), counted from 1,
    to the `kinds.Cause` of an expected erratum (`spoken(...)`, `ocr(...)`, ...; a plain sentence
    leaves it unclassified). `verbatim` gives elements as the transcript prints them, as a dict
    {(row, column): text} or nested lists of text. `joint_variables` (e.g. robot.chain.joint_variables)
    makes reports use c1, s23; with `fold` the notebook table of a fully agreeing comparison stays folded.
    """
    derived = sympy.Matrix(derived) if not isinstance(derived, sympy.Expr) else sympy.Matrix([[derived]])
    causes = {place: _cause(reason) for place, reason in (reasons or {}).items()}
    texts = _by_position(verbatim)
    result = Comparison(title, joint_variables=tuple(joint_variables), fold=fold)

    def add(r, c, value):
        expr = _read(value)
        result.elements.append(ElementCheck(r, c, expr, derived[r - 1, c - 1], check(expr, derived[r - 1, c - 1]),
                                            causes.get((r, c)), texts.get((r, c), ""),
                                            value if isinstance(value, str) else ""))

    if isinstance(printed, dict):
        for (r, c), value in sorted(printed.items()):
            add(r, c, value)
        result.partial = len(printed) < len(derived)
        return result
    sources = {(1, 1): printed} if isinstance(printed, str) else \
        _by_position(printed) if not isinstance(printed, (sympy.MatrixBase, sympy.Expr, int)) else {}
    matrix = transcribe(printed)
    if matrix.shape != derived.shape:
        if matrix.shape == derived.T.shape and 1 in matrix.shape:
            matrix = matrix.T
            sources = {(c, r): text for (r, c), text in sources.items()}
        else:
            raise ValueError(f"printed shape {matrix.shape} differs from derived shape {derived.shape}")
    for r in range(derived.rows):
        for c in range(derived.cols):
            source = sources.get((r + 1, c + 1))
            add(r + 1, c + 1, source if isinstance(source, str) else matrix[r, c])
    return result


def tally(comparisons) -> str:
    """The errata of several comparisons counted by kind: the lecture's errors apart from OCR damage."""
    return tally_causes(e.cause for comparison in comparisons for e in comparison.errata)


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


def _cause(reason) -> Cause | None:
    if isinstance(reason, Cause) or reason is None:
        return reason
    return Cause(None, str(reason)) if reason else None


def _by_position(verbatim) -> dict:
    """Transcript text by (row, column), from a dict or from nested lists (a vector as a flat list)."""
    if not verbatim:
        return {}
    if isinstance(verbatim, dict):
        return dict(verbatim)
    rows = [row if isinstance(row, (list, tuple)) else [row] for row in verbatim]
    return {(r + 1, c + 1): text for r, row in enumerate(rows) for c, text in enumerate(row) if text}


def _by_cause(errata: list[ElementCheck]) -> list[list[ElementCheck]]:
    """Errata grouped by their cause, in order of first appearance; unclassified ones stay alone."""
    groups: dict = {}
    for e in errata:
        groups.setdefault(e.cause if e.cause is not None else id(e), []).append(e)
    return list(groups.values())


def _all_agree(count: int, partial: bool) -> str:
    """'all 16 elements agree', 'all 3 printed elements agree', 'the element agrees'."""
    if count == 1:
        return "the printed element agrees" if partial else "the element agrees"
    return f"all {count} {'printed ' if partial else ''}elements agree"


def _printed_order(e: ElementCheck) -> list[tuple[sympy.Expr, bool]]:
    """The printed element's terms in the lecture's order (from its text when it was given as text)."""
    terms = printed_terms(e.source) if e.source else [e.printed]
    try:
        return [(_read(term), False) for term in terms]
    except Exception:  # a piece the parser cannot read alone: the whole element, in SymPy's order
        return [(e.printed, False)]


def _regrouped(e: ElementCheck) -> list[tuple[sympy.Expr, bool]]:
    return regroup([term for term, _ in _printed_order(e)], e.derived)


def _terms_latex(terms, printer) -> str:
    """Terms as separate inline formulas, '$a$ $+ \\boxed{b}$', so that a long sum breaks between
    terms; a term marked as differing is boxed."""
    pieces = []
    for position, (term, differs) in enumerate(terms):
        text = printer.doprint(term)
        negative = text.startswith("-")
        body = text[1:].strip() if negative else text
        body = f"\\boxed{{{body}}}" if differs else body
        sign = ("-" if negative else "") if position == 0 else ("- " if negative else "+ ")
        pieces.append(f"${sign}{body}$")
    return " ".join(pieces)


def _code_span(text: str) -> str:
    """Transcript text shown exactly as it is, in a table cell."""
    return "`" + text.replace("`", "'").replace("|", "\\|") + "`"


def _read(value) -> sympy.Expr:
    if isinstance(value, str):
        return parse_expression(value)
    return sympy.sympify(value, strict=True)
