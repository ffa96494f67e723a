"""Branch names in words. Each sign choice σ = ±1 belongs to a joint; the joint's place in the
arm names it: the first joint is the shoulder, the rest of the arm the elbow, the wrist's
joints the wrist. The + root is called right / down / not flipped, the − root left / up /
flipped (the names of the planar elbow's +√ and −√ in Spong's book); a slide's roots are
"forward" and "back". These are the solver's names by sign; dhsym.inverse.naming replaces
each with the word the arm's geometry gives that root (which may be the other one, or another
pair: front/back, lefty/righty, forward/back), or with "+√" / "−√" where no word holds.

>>> import sympy
>>> t1, t3 = sympy.symbols("theta_1 theta_3")
>>> branch_name([(t1, "one", 1), (t3, "law", -1)], t1, [])
'shoulder right, elbow up'
>>> branch_name([], t1, [])
'the only solution'
"""
from __future__ import annotations

WORDS = {"shoulder": ("right", "left"), "elbow": ("down", "up"), "wrist": ("not flipped", "flipped"),
         "slide": ("forward", "back")}


def branch_name(choices, first_joint, wrist_joints) -> str:
    """`choices`: (joint variable, sub-problem rule, sign) per sign symbol, in order; `first_joint`
    the arm's first unknown (its shoulder)."""
    roles = []
    for joint, rule, sign in choices:
        if rule == "prismatic":
            role = "slide"
        elif joint in wrist_joints:
            role = "wrist"
        else:
            role = "shoulder" if joint == first_joint else "elbow"
        roles.append((role, joint, sign))
    counts = {role: sum(1 for r, _, _ in roles if r == role) for role, _, _ in roles}
    if not roles:
        return "the only solution"
    parts = []
    for role, joint, sign in roles:
        word = WORDS[role][0 if sign > 0 else 1]
        parts.append(f"{role} ({joint}) {word}" if counts[role] > 1 else f"{role} {word}")
    return ", ".join(parts)
