"""The numeric inverse kinematics (`dhsym ik --numeric`, or an arm with no closed form) for people
and programs: why it is numeric, the method, the arm's numbers, the target and every real
solution there, as text and as JSON.

>>> import dhsym
>>> from dhsym.inverse.numeric.answer import answer
>>> from dhsym.inverse.numeric.solver import numeric_inverse
>>> puma = dhsym.load("puma560")
>>> text = numeric_text(answer(numeric_inverse(puma.chain, sample=puma.sample, name=puma.name)))
>>> print(text.splitlines()[0])
PUMA 560: inverse kinematics in numbers  (modified DH)
"""
from __future__ import annotations

import numpy

from . import render
from .ik_limits import limits_json, limits_sentence, outside_limits
from .ik_solution import ascii_text
from .names import display_name

DIGITS = 6  # decimals of the printed joint values and target elements


def numeric_text(found, width: int = 100, ascii: bool = False, robot=None, refusal: str = "") -> str:
    """The answer as text: title, why numeric (`refusal`, the closed form's), method, arm, target, solutions."""
    inverse = found.inverse
    title = f"{inverse.arm.name}: inverse kinematics in numbers  ({inverse.arm.convention}\u00a0DH)"
    blocks = [render.wrap(title, width, "  ").replace("\u00a0", " ")]
    if refusal:
        blocks.append(render.wrap(f"{refusal[0].upper()}{refusal[1:]}.", width, "  "))
    blocks.append(render.wrap(f"Method: {method_sentence(inverse)}", width, "  "))
    if robot is not None:
        blocks.append(_arm_block(robot, inverse, ascii, width))
    blocks.append(_target_block(found, robot, ascii, width))
    blocks.append(_solutions_block(found, ascii, width, robot))
    text = "\n\n".join(blocks)
    return ascii_text(text.replace("←", "<-")) if ascii else text


def method_sentence(inverse) -> str:
    given = f" with {', '.join(_name(n) for n in inverse.free_variables)} given" if inverse.free else ""
    return (f"every real solution{given}, numerically: Raghavan and Roth's elimination turns the loop equation "
            f"into one polynomial in {_name(inverse.hidden_variable)} of degree at most 16, whose roots are the "
            "eigenvalues of a 24 × 24 matrix; Newton's method on the pose polishes each root, and a solution is "
            f"kept once, when it reaches the target within {_power(inverse.runtime()['tolerance'])}.")


def numeric_json(found, refusal: str = "", robot=None) -> dict:
    """The answer for programs: plain numbers, joint values in the order of `joint_variables`; for
    a `robot` with joint limits, the limits and the joints of each solution outside them."""
    inverse = found.inverse
    limits = {} if robot is None or not robot.joint_limits else {
        "joint_limits": limits_json(robot),
        "outside_limits": outside_limits(robot, inverse.joint_variables, found.solutions)}
    return {
        "robot": inverse.arm.name,
        "convention": inverse.arm.convention,
        "numeric": True,
        "closed_form": refusal or None,
        "method": method_sentence(inverse),
        "joint_variables": list(inverse.joint_variables),
        "free": list(inverse.free_variables),
        "constants": dict(sorted(inverse.arm.constants.items())),
        "joints": found.joints,
        "replaced": found.replaced,
        "target": found.target.tolist(),
        "tolerance": inverse.runtime()["tolerance"],
        "solutions": found.solutions.tolist(),
        "joints_among_solutions": found.among,
        "singular": found.singular,
        **limits,
    }


def _arm_block(robot, inverse, ascii, width) -> str:
    lines = ["The arm (what `dhsym table` prints):", render.text_table(robot, ascii)]
    printer = render.text_printer(robot, ascii)
    for label, steps in (("base", robot.chain.base), ("tool", robot.chain.tool)):
        if steps:
            lines.append(f"{label}: " + " ".join(f"{step.kind}({printer.doprint(step.value)})" for step in steps))
    if inverse.arm.constants:
        numbers = ", ".join(f"{_name(name)} = {_short(value)}" for name, value in sorted(inverse.arm.constants.items()))
        lines.append(render.wrap(f"with {numbers}", width, "  "))
    return "\n".join(lines)


def _ends(robot) -> tuple:
    """The first and last frames of the robot's chain, numbered as its file numbers them."""
    return robot.numbering.frame(robot.chain.first_frame), robot.numbering.frame(robot.chain.last_frame)


def _target_block(found, robot, ascii, width) -> str:
    frames = f"{render.transform_title(*_ends(robot), 'ascii' if ascii else 'unicode')} " \
        if robot is not None else ""
    at = ", ".join(f"{_name(name)} = {_short(value)}" for name, value in found.joints.items())
    said = f"Target {frames}at {at}"
    if found.replaced:
        said += f", with {', '.join(f'{name} = {_short(v)}' for name, v in found.replaced.items())} put in (--pose)"
    cells = [[_number(x) for x in row] for row in found.target[:3]] + [["0", "0", "0", "1"]]
    text = render.wrap(said + ":", width, "  ") + "\n" + render.aligned_matrix(cells, ascii)
    if found.singular:
        text += "\n" + render.wrap("These joints are a singular configuration (the Jacobian loses rank): solutions "
                                   "there are not isolated, and the list holds those the elimination meets.", width,
                                   "  ")
    return text


def _solutions_block(found, ascii, width, robot=None) -> str:
    inverse = found.inverse
    count = len(found.solutions)
    outside = outside_limits(robot, inverse.joint_variables, found.solutions) if robot is not None else []
    units = "angles in radians" + (", lengths in the file's units" if "P" in inverse.arm.kinds else "")
    head = (f"{count} solution{'s' if count != 1 else ''} (every real one, each once; {units})"
            if count else "No solution: the target is out of the arm's reach")
    if not count:
        return render.wrap(head + ".", width, "  ")
    header = ["#"] + [_name(name) for name in inverse.joint_variables]
    rows = [[str(k + 1)] + [_number(x) for x in solution] for k, solution in enumerate(found.solutions)]
    widths = [max(len(row[k]) for row in [header] + rows) for k in range(len(header))]
    lines = ["  ".join(cell.rjust(w) for cell, w in zip(row, widths)) for row in [header] + rows]
    for k, names in enumerate(outside):
        lines[k + 1] += f"   outside limits: {', '.join(_name(name) for name in names)}" if names else ""
    if found.among is not None:
        lines[found.among + 1] += "   ← the joints that made the target"
    elif not found.replaced:
        lines.append("(the joints that made the target are not among them: a singular configuration)")
    if robot is not None and robot.joint_limits:
        within = sum(not names for names in outside)
        lines.append(render.wrap(f"{within} of {count} within the joint limits. "
                                 + limits_sentence(robot, lambda symbol: _name(symbol.name)), width, "  ")
                     .replace("\u00a0", " "))
    return render.wrap(head + ":", width, "  ") + "\n" + "\n".join(lines)


def _name(name: str) -> str:
    return display_name(name, "unicode")


def _power(value: float) -> str:
    """1e-9, not 1e-09."""
    mantissa, exponent = f"{value:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def _short(value) -> str:
    """A given number as short as it reads back: 0.3, −0.4, 0.523599."""
    return f"{float(value):.6g}".replace("-", "−")


def _number(value) -> str:
    """A value with DIGITS decimals, −0 as 0, the minus sign a minus."""
    value = float(value)
    text = f"{value:.{DIGITS}f}" if abs(value) < 1e6 else f"{value:.{DIGITS}g}"
    text = "0." + "0" * DIGITS if numpy.isclose(value, 0, atol=0.5 * 10 ** -DIGITS) else text
    return text.replace("-", "−")
