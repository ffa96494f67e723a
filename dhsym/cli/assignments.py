"""Values typed on the command line, read safely: `--q theta_1=30deg`, `--set l_1=0.5`, and target
elements `--pose "px=0.5, r33=1"` / `--ik "px=0.5"`. One reader, so every option words its
mistakes the same way.

>>> target_elements("px = 0.5, r33=1", "--pose")
{'px': 1/2, 'r33': 1}
"""
from __future__ import annotations

import re

from ..core.robot import Robot
from ..errors import UserError
from ..io.expr import parse_expression

_ASSIGNMENT = re.compile(r"\s*([^\W\d]\w*)\s*=(.*)\Z", re.DOTALL)
_ELEMENT = re.compile(r"\s*(r[123][123]|p[xyz])\s*=(.*)\Z", re.DOTALL)


def _number(option: str, text: str, expression: str):
    """The exact value of EXPR in `option text`; a symbol left inside is a mistake."""
    try:
        value = parse_expression(expression)
    except UserError as error:
        raise UserError(f"{option} {text!r}: {error.message}") from None
    if value.free_symbols:
        raise UserError(f"{option} {text!r}: the value must be a number, not an expression in "
                        f"{', '.join(sorted(map(str, value.free_symbols)))}")
    if not value.is_real:
        raise UserError(f"{option} {text!r}: the value must be a real number")
    return value


def target_elements(text, option: str) -> dict:
    """`"px=0.5, pz=0.3"`: elements of the target pose (r11 … r33, px, py, pz) to exact numbers.

    >>> target_elements("px = 0.5, py=1/5", "--ik")
    {'px': 1/2, 'py': 1/5}
    """
    values = {}
    for part in filter(str.strip, (text or "").split(",")):
        part = part.strip()
        match = _ELEMENT.match(part)
        if not match:
            raise UserError(f"{option} {part!r}: expected ELEMENT=NUMBER, the element one of r11 … r33, px, py, pz")
        values[match.group(1)] = _number(option, part, match.group(2))
    return values


def parse_assignments(robot: Robot, texts, option: str) -> dict:
    """`NAME=EXPR` texts to {name: exact value}; --q takes joint variables, --set constants.

    >>> from dhsym.io.library import load
    >>> parse_assignments(load("planar2r"), ["theta_1=30deg"], "--q")
    {'theta_1': pi/6}
    """
    symbols = sorted(s.name for s in robot.chain.symbols)
    variables = {v.name for v in robot.chain.joint_variables}
    values = {}
    for text in texts:
        match = _ASSIGNMENT.match(text)
        if not match:
            raise UserError(f"{option} {text!r}: expected NAME=EXPR, e.g. {option} "
                            f"{'theta_1=30deg' if option == '--q' else 'l_1=0.5'}")
        name = match.group(1)
        if name not in symbols:
            raise UserError(f"{option} {text!r}: {robot.name} has no symbol {name}; its symbols are "
                            f"{', '.join(symbols)}")
        if (name in variables) != (option == "--q"):
            kind = "a joint variable; use --q" if name in variables else "a constant; use --set"
            raise UserError(f"{option} {text!r}: {name} is {kind}")
        values[name] = _number(option, text, match.group(2))
    return values
