"""A whole inverse-kinematics solution for people and programs: the text of `dhsym ik` (title,
target, method, the `where` list, every branch, when branches exist, the degenerate poses, the
legend) and the JSON contract (full cos/sin/atan2 with the robot file's names, readable by
sympy.sympify; the sentences as plain strings).

>>> import dhsym
>>> from dhsym.inverse import solve
>>> arm = dhsym.load("planar2r")
>>> solution = solve(arm.chain, sample=arm.sample)
>>> json_solution(solution, arm)["degenerate"]
['px = 0 and py = 0: theta_1 is not determined (the end point on axis 1; only where a_1**2 = a_2**2)']
>>> json_solution(solve(dhsym.load("puma560").chain), dhsym.load("puma560"))["angles_solved_as_one"]
[['theta_23', 'theta_2 + theta_3']]
>>> print(text_solution(solution, arm).split("Degenerate:")[1].strip().splitlines()[0])
px = 0 and py = 0: θ1 is not determined (the end point on axis 1; only where a1² = a2²)
"""
from __future__ import annotations

import sympy

from . import render
from .ik import (
    IKExactPrinter,
    IKTextPrinter,
    angle_meanings,
    ik_settings,
    solution_printer,
    target_name,
    target_names,
    target_title,
    variable_list,
)
from .ik_limits import limits_json, limits_sentence
from .ik_lines import assignments_text
from .ik_sentences import PlainSentences, wrap_sentence
from .names import GREEK_NAMES, display_name


def text_solution(solution, robot, width: int = 100, ascii: bool = False) -> str:
    """The whole solution of `robot` (its name, its numbering) as text that fits `width`: title,
    target, method, definitions, each branch, when branches exist, the degenerate poses, and the
    legend of c/s abbreviations."""
    chain = solution.chain
    targets = target_names(solution)
    printer = solution_printer(solution, robot.numbering, IKTextPrinter, ascii)
    style = "ascii" if ascii else "unicode"
    title = f"{robot.name}: inverse kinematics  ({chain.convention}\u00a0DH)"  # "(modified DH)" kept whole
    blocks = [render.wrap(title, width, "  ").replace("\u00a0", " ")]
    target = [[target_name(targets[4 * r + c], style) for c in range(4)] for r in range(3)] + [["0", "0", "0", "1"]]
    title = f"Target {target_title(chain, robot.numbering, style)}, the pose to reach (what `dhsym fk` prints):"
    blocks.append(render.wrap(title, width, "  ") + "\n" + render.aligned_matrix(target, ascii))
    about = [f"Method: {printer.sentence(solution.method)}."]
    if solution.free:
        about.append(f"Free (parameters): {variable_list(solution.free, printer)}.")
    count = len(solution.branches)
    about.append(f"{count} branch{'es' if count != 1 else ''}.")
    blocks.append(render.wrap(" ".join(about), width, "  "))
    if solution.definitions:
        blocks.append("where\n" + assignments_text(solution.definitions, printer, width))
    for number, branch in enumerate(solution.branches, 1):
        heading = render.wrap(f"Branch {number}: {branch.name}", width, "  ")
        blocks.append(heading + "\n" + assignments_text(branch.assignments, printer, width))
    limits = limits_sentence(robot, printer.doprint, solution.joint_variables)  # which hold depends on the target
    blocks += [wrap_sentence(limits, width, "  ").replace("\u00a0", " ")] if limits else []
    for title, lines in (("Exists when", solution.conditions), ("Degenerate", solution.degenerate)):
        if lines:
            blocks.append(f"{title}:\n" + "\n".join(wrap_sentence("  " + printer.sentence(line), width, "    ")
                                                      for line in lines))
    meanings = angle_meanings(solution)
    if meanings:
        said = ", ".join(f"{printer.doprint(name)} = {printer.doprint(value)}" for name, value in meanings)
        blocks.append(wrap_sentence(f"Angles solved as one: {said}", width, "  "))
    atan2 = [render.wrap(ATAN2_LEGEND["unicode"], width, "  ")] if uses_atan2(solution) else []
    named = render.wrap(named_numbers(solution.numbers, "unicode"), width, "  ")
    legend = "\n".join(filter(None, [named, render.text_legend(printer, width), *atan2]))
    text = "\n\n".join(blocks + ([legend] if legend else []))
    return ascii_text(text) if ascii else text


ATAN2_LEGEND = {  # the order of atan2's arguments, said once where a solution uses it
    "unicode": "atan2(y, x) is the angle of the point (x, y), y (the sine) first; Spong (2006) writes Atan2(x, y).",
    "latex": "$\\mathrm{atan2}(y, x)$ is the angle of the point $(x, y)$, $y$ (the sine) first; Spong (2006) writes "
             "$\\mathrm{Atan2}(x, y)$.",
}


def named_numbers(numbers, style: str) -> str:
    """The sentence that says which of the table's long decimals the formulas write by a name,
    and what each is, to 6 digits ('' when none); `style` is unicode or latex.

    >>> from dhsym.core.numbers import WrittenNumbers
    >>> named = WrittenNumbers(named=(("1.23412150740817", "beta", (("theta", 2, True),)),))
    >>> print(named_numbers(named, "unicode")[:58])
    Named numbers: β ≈ 1.23412 (the θ offset −β of row 2); the
    >>> named_numbers(named, "unicode")[58:]
    ' table gives it to 15 digits, the formulas use it as given.'

    """
    if not numbers.named:
        return ""
    math = (lambda text: f"${text}$") if style == "latex" else (lambda text: text)  # noqa: E731
    entries, digits = [], 0
    for decimal, name, places in numbers.named:
        label, parameter = display_name(name, style), places[0][0]
        if parameter == "theta":
            theta, minus = ("$\\theta$", "-") if style == "latex" else ("θ", "−")
            signs = [(minus, [p for _, p, negative in places if negative]),
                     ("+" if any(n for *_, n in places) else "", [p for _, p, negative in places if not negative])]
            what = f"the {theta} offset " + " and ".join(f"{math(sign + label)} of {_rows(rows, 'row')}"
                                                         for sign, rows in signs if rows)
        else:
            kind = {"b": "the base's translation", "t": "the tool's translation"}.get(
                parameter, f"the {math(parameter)}")
            what = f"{kind} of {_rows([p for _, p, _ in places], 'axis' if parameter in ('b', 't') else 'row')}"
        approx = " \\approx " if style == "latex" else " ≈ "
        entries.append(f"{math(label + approx + format(float(decimal), '.6g'))} ({what})")
        digits = max(digits, len(decimal.replace(".", "").lstrip("0")))
    them = "them" if len(entries) > 1 else "it"
    return (f"Named numbers: {'; '.join(entries)}; the table gives {them} to {digits} digits, the formulas use "
            f"{them} as given.")


def _rows(places, kind: str) -> str:
    """'row 2', 'rows 2 and 3', 'rows 1, 2 and 4'."""
    named = [str(place) for place in places]
    listed = " and ".join([", ".join(named[:-1]), named[-1]]) if len(named) > 1 else named[0]
    return f"{kind}{'s' if len(named) > 1 else ''} {listed}"


def uses_atan2(solution) -> bool:
    """Whether a formula of the solution (a definition or a branch's assignment) holds atan2."""
    pairs = list(solution.definitions) + [pair for branch in solution.branches for pair in branch.assignments]
    return any(sympy.sympify(value).has(sympy.atan2) for _, value in pairs)


_ASCII = {"−": "-", "–": "-", "≥": ">=", "≤": "<=", "≠": "!=", "·": "*", "×": "x", "√": "sqrt", "±": "+-",
          "→": "->", "…": "...", "²": "^2", "³": "^3", "⁻": "^-", "¹": "^1", "₀": "0", "′": "'", "ʹ": "'",
          "∈": "in", "°": "deg", "’": "'"}


def ascii_text(text: str) -> str:
    """Text for --ascii: the solver's sentences may hold Greek letters, squares and signs.

    >>> ascii_text("s5 = 0: only θ4 + θ6 is determined; D² ≤ 1")
    's5 = 0: only theta4 + theta6 is determined; D^2 <= 1'
    """
    out = []
    for ch in text:
        if ch.isascii():
            out.append(ch)
        else:
            out.append(_ASCII.get(ch) or GREEK_NAMES.get(ch) or "?")
    return "".join(out)


def json_solution(solution, robot) -> dict:
    """The JSON contract: full forms with the robot file's names and decimals as written;
    `sympy.sympify` reads every expression back. `robot` gives the name and the numbering."""
    chain = solution.chain
    settings = ik_settings(chain, solution.numbers, robot.numbering)
    exact = IKExactPrinter({key: settings[key] for key in ("joint_variables", "offsets", "numbers", "first_joint")})
    plain = PlainSentences({"frame_offset": robot.numbering.offset})
    pairs = lambda items: [[name.name, exact.doprint(value)] for name, value in items]  # noqa: E731
    return {
        "robot": robot.name,
        "convention": chain.convention,
        "joint_variables": [symbol.name for symbol in solution.joint_variables],
        "free": [symbol.name for symbol in solution.free],
        "method": plain.sentence(solution.method),
        "target": list(target_names(solution)),
        "definitions": pairs(solution.definitions),
        "solutions": [{"name": branch.name, "assignments": pairs(branch.assignments)}
                      for branch in solution.branches],
        "conditions": [plain.sentence(said) for said in solution.conditions],
        "degenerate": [plain.sentence(said) for said in solution.degenerate],
        "angles_solved_as_one": pairs(angle_meanings(solution)),
        **({"joint_limits": limits_json(robot, solution.joint_variables)} if robot.joint_limits else {}),
    }
