"""How a symbol's name is written: θ1 (Unicode), \\theta_{1} (LaTeX), theta1 (ASCII); a word
name such as a URDF joint's `right_s0` as it is; digits raised and lowered (⁰T₆).

>>> display_name("theta_1", "unicode"), display_name("theta_1", "latex"), display_name("l_13", "ascii")
('θ1', '\\\\theta_{1}', 'l13')
"""
from __future__ import annotations

from functools import lru_cache

from sympy.printing.conventions import split_super_sub
from sympy.printing.latex import translate
from sympy.printing.pretty.pretty_symbology import greek_unicode, sub, sup

PRIME = "\u02b9"  # ʹ, the letter dhsym.inverse.fresh primes a derivation's name with (printed ′ or ')
GREEK_NAMES = {letter: name for name, letter in greek_unicode.items()}  # 'θ' -> 'theta'


def is_word_name(name: str) -> bool:
    """Whether a name is a word with underscores, such as a URDF joint's `right_s0` or
    `shoulder_pan_joint`, rather than a letter with indices (`theta_1`, `l_23`): it prints as
    written (LaTeX `\\mathrm{right\\_s0}`), since `rights0` would be no one's name.

    >>> is_word_name("right_s0"), is_word_name("theta_1"), is_word_name("elbow_1"), is_word_name("ab_c")
    (True, False, False, False)
    """
    base, supers, subs = split_super_sub(name)
    numbered = not supers and len(subs) == 1 and subs[0].isdigit()  # elbow_1 stays elbow₁-like: elbow1
    return "_" in name and len(base) > 2 and base not in greek_unicode and base not in GREEK_NAMES and not numbered


@lru_cache(maxsize=4096)  # asked for every symbol printed: a large result prints a few names thousands of times
def display_name(name: str, style: str) -> str:
    """A symbol name as a textbook writes it: theta_1 -> θ1 (unicode), \\theta_{1} (LaTeX); a name
    the inverse kinematics primed (dhsym.inverse.fresh), phi_1ʹ, as φ1′ (unicode), \\phi_{1}' (LaTeX)."""
    bare = name.rstrip(PRIME)
    if bare != name and bare:
        return display_name(bare, style) + ("′" if style == "unicode" else "'") * (len(name) - len(bare))
    if is_word_name(name):
        return "\\mathrm{" + name.replace("_", "\\_") + "}" if style == "latex" else name
    base, supers, subs = split_super_sub(name)
    subs = [s.strip("{}") for s in subs]
    supers = [s.strip("{}") for s in supers]
    if style == "latex":
        base = _latex_base(base)
        text = base + "".join(f"_{{{s}}}" for s in subs[:1])
        if len(subs) > 1:
            text = base + "_{" + ",".join(subs) + "}"
        return text + "".join(f"^{{{s}}}" for s in supers)
    if style == "unicode":
        base = greek_unicode.get(base, base)
    else:
        base = GREEK_NAMES.get(base, base)
    return base + "".join(subs) + "".join("^" + s for s in supers)


def greek_latex(name: str) -> str | None:
    """The TeX for a Greek letter's name (SymPy's own translation), or None if it is no Greek letter.

    >>> greek_latex("theta"), greek_latex("lamda"), greek_latex("Alpha"), greek_latex("l")
    ('\\\\theta', '\\\\lambda', '\\\\mathrm{A}', None)
    """
    return translate(name) if name in greek_unicode else None


def _latex_base(base: str) -> str:
    name = GREEK_NAMES.get(base, base)
    greek = greek_latex(name)
    if greek:
        return greek
    return f"\\mathrm{{{name}}}" if len(name) > 1 else name


def superscript(text: str) -> str:
    """Digits and minus signs raised, as in ⁰T₆; SymPy's own table of Unicode superscripts.

    >>> superscript("-12") + subscript("3")
    '⁻¹²₃'
    """
    return "".join(sup.get(ch, ch) for ch in text)


def subscript(text: str) -> str:
    """Digits and minus signs lowered (₀₁₂…)."""
    return "".join(sub.get(ch, ch) for ch in text)
