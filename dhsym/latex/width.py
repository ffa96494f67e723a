r"""Printed widths of LaTeX math, estimated from Computer Modern glyph widths (within 2 % of
TeX's own measure for what dhsym's printers write), so that a layout can decide what fits a
line without running TeX.

Widths are in em of the body font. The reader knows the glyphs and commands the printers
use: italic letters, digits, Greek letters, sub- and superscripts (the wider of the two
counts), ``\frac``, ``\sqrt``, ``\cos``/``\sin``, spaces such as ``\,`` and ``\quad``,
and the spacing TeX puts around ``+``, ``-`` and ``=``.

>>> round(math_width("l_{1} c_{1} + l_{2} c_{12}"), 2)
4.88
>>> math_width("\\frac{a}{b}", display=True) > math_width("\\frac{a}{b}")  # script-size parts inline
True
"""
from __future__ import annotations

_ITALIC = dict(zip("abcdefghijklmnopqrstuvwxyz",
                   (.529, .429, .433, .520, .466, .490, .477, .576, .345, .412, .521, .298, .878,
                    .600, .485, .503, .446, .451, .469, .361, .572, .485, .716, .572, .490, .465), strict=True))
_GREEK_WIDTH = {"alpha": .640, "beta": .566, "gamma": .518, "delta": .444, "epsilon": .406, "varepsilon": .466,
                "zeta": .438, "eta": .497, "theta": .469, "vartheta": .592, "iota": .354, "kappa": .576,
                "lambda": .583, "mu": .603, "nu": .494, "xi": .438, "pi": .600, "varpi": .829, "rho": .517,
                "sigma": .571, "tau": .437, "upsilon": .540, "phi": .596, "varphi": .654, "chi": .626,
                "psi": .651, "omega": .622}
_OPERATOR_NAMES = {"cos": 1.338, "sin": 1.228, "tan": 1.339}
_SPACES = {",": .167, ";": .278, ":": .222, "!": -.167, "quad": 1.0, "qquad": 2.0}
_BINARY, _RELATION, _SCRIPT = .778 + 2 * .222, .778 + 2 * .278, 0.8  # + and = with their spaces


def math_width(tex: str, display: bool = False) -> float:
    """Estimated width in em of inline math `tex` (fractions in display style if `display`).

    >>> round(math_width("c_{1} + s_{23}"), 2), math_width("c_{1}") < math_width("c_{12}")
    (3.42, True)
    """
    return _Measure(tex).group(1.0, display)


def prefix_widths(tex: str, ends: list[int], display: bool = False) -> list[float]:
    """`[math_width(tex[:end]) for end in ends]` in one pass over `tex`, for ends in increasing
    order outside any {…} group (where a long element may break: a line's width is the width of
    the text up to there). An end that the reader steps over (inside a command) is measured alone.

    >>> prefix_widths("a + b + c", [1, 5]) == [math_width("a"), math_width("a + b")]
    True
    """
    measure = _Measure(tex, ends)
    measure.group(1.0, display)
    return [measure.at[end] if end in measure.at else math_width(tex[:end], display) for end in ends]


class _Measure:
    """A small reader of the LaTeX the printers write: glyphs, scripts, \\frac, \\sqrt, spaces;
    `ends`: positions outside any group where the width so far is noted in `at`."""

    def __init__(self, tex: str, ends=()):
        self.tex, self.i = tex, 0
        self.ends, self.at, self.depth = list(ends), {}, 0

    def group(self, scale: float, display: bool) -> float:
        """Width up to the closing brace of the current group, or the end."""
        total, operand, script = 0.0, False, None
        self.depth += 1
        while self.i < len(self.tex):
            if self.depth == 1 and self.ends and self.ends[0] <= self.i:
                if self.ends[0] == self.i:
                    self.at[self.i] = total
                self.ends.pop(0)
                continue
            ch = self.tex[self.i]
            self.i += 1
            if ch == "}":
                break
            if ch.isspace():
                continue
            if ch in "_^":  # a subscript and a superscript on one base stack: count the wider
                width = self.argument(scale * _SCRIPT)
                total += width + .05 * scale if script is None else max(0.0, width - script)
                script = width if script is None else max(script, width)
                continue
            script = None
            if ch == "{":
                total, operand = total + self.group(scale, display), True
            elif ch == "\\":
                width, operand = self.command(scale, display, operand)
                total += width
            elif ch in "+-=":  # spaced as a binary operator or relation, except in scripts
                spaced = _RELATION if ch == "=" else _BINARY if operand else .778
                total, operand = total + (spaced if scale == 1 else .778) * scale, False
            elif ch == ",":
                total, operand = total + .445 * scale, False
            else:
                total, operand = total + _glyph(ch) * scale, ch not in "(["
        self.depth -= 1
        if self.depth == 0 and self.ends and self.ends[0] == self.i:  # an end at the very end
            self.at[self.i] = total
        return total

    def argument(self, scale: float) -> float:
        while self.i < len(self.tex) and self.tex[self.i].isspace():
            self.i += 1
        if self.i >= len(self.tex):
            return 0.0
        ch = self.tex[self.i]
        self.i += 1
        if ch == "{":
            return self.group(scale, False)
        return self.command(scale, False, False)[0] if ch == "\\" else _glyph(ch) * scale

    def command(self, scale: float, display: bool, operand: bool) -> tuple[float, bool]:
        """(width, whether an operand ends here) of the command after a backslash."""
        start = self.i
        while self.i < len(self.tex) and self.tex[self.i].isalpha():
            self.i += 1
        self.i += self.i == start  # a one-character command such as \, or \{
        name = self.tex[start:self.i]
        if name.lower() in _GREEK_WIDTH:  # in a script, with a little of its italic correction
            return (_GREEK_WIDTH.get(name, .75) + (.04 if scale < 1 else 0.0)) * scale, True
        if name in _SPACES:
            return _SPACES[name] * scale, operand
        if name == "frac":
            inner = scale if display else scale * _SCRIPT
            return max(self.argument(inner), self.argument(inner)) + .24 * scale, True
        if name == "sqrt":
            return self.argument(scale) + .833 * scale, True
        if name in ("bar", "overline", "hat", "vec", "mathit", "mathbf"):
            return self.argument(scale), True
        if name in ("mathrm", "text", "operatorname"):
            before = self.i
            self.argument(scale)
            return .52 * sum(ch.isalnum() for ch in self.tex[before:self.i]) * scale, True
        if name in _OPERATOR_NAMES:
            return (_OPERATOR_NAMES[name] + 2 * .167) * scale, False
        if name in ("{", "}"):
            return .5 * scale, name == "}"
        if name in ("left", "right"):
            return 0.0, operand
        return 1.0 * scale, True


def _glyph(ch: str) -> float:
    if ch in _ITALIC:
        return _ITALIC[ch]
    if ch.isdigit():
        return .5
    return .8 if ch.isupper() else {"(": .389, ")": .389, "[": .278, "]": .278, "|": .278, "*": .5}.get(ch, .6)

