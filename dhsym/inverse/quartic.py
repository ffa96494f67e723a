"""The roots of a quartic in closed form, by radicals, as a textbook writes them: Descartes's way
of Ferrari's solution, each intermediate quantity named.

For A₄u⁴ + A₃u³ + A₂u² + A₁u + A₀ = 0 (A₄ ≠ 0), u = y − A₃/(4A₄) gives the depressed quartic
y⁴ + p y² + q y + r = 0. It splits into (y² + s y + t)(y² − s y + v), where z = s² is a root of
the resolvent cubic z³ + 2p z² + (p² − 4r) z − q² = 0. That cubic's root is taken by the
trigonometric formula (z = w − 2p/3, w = 2m cos(acos(−R/(2m³))/3), m² = −P/3 for the depressed
cubic w³ + P w + R), which is a root for every branch of the functions, so that no case is
singled out by a sign. The four roots are

    u = −A₃/(4A₄) + σa s/2 + σb √(−z − 2p − 2σa q/s)/2,   σa, σb = ±1.

Intermediate values may be complex (m, w, z, s) even where the four roots are real: `Complex`
marks the names that may hold a complex value (the generated code computes them in complex
numbers). A root is real up to rounding where it is real.

When q is zero for every pose (a quartic in u² alone), y² = (−p ± √(p² − 4r))/2 instead.

>>> definitions, roots = ferrari([1, -10, 35, -50, 24])            # (u − 1)(u − 2)(u − 3)(u − 4)
>>> sorted(round(complex(written_out(definitions, root(roots, a, b)).evalf(30)).real, 9)
...        for a in (1, -1) for b in (1, -1))
[1.0, 2.0, 3.0, 4.0]
"""
from __future__ import annotations

import sympy

SIGNS = (sympy.Symbol("sigma_a", real=True), sympy.Symbol("sigma_b", real=True))


class Complex(sympy.Symbol):
    """A name whose value may be complex although the coefficients are real (the resolvent cubic's
    root, its square root): the generated code computes it in complex numbers."""


def ferrari(coefficients, names=("A_4", "A_3", "A_2", "A_1", "A_0", "p", "q", "r", "m", "w", "z", "s"),
            signs=SIGNS):
    """(definitions [(name, value)], the root in the signs `signs` (σa, σb)) for the quartic with
    the `coefficients` A₄ … A₀ (expressions); `names` for the intermediate quantities, in the
    order A₄ … A₀, p, q, r, m, w, z, s."""
    a4, a3, a2, a1, a0, p, q, r, m, w, z, s = names = [
        (Complex if k >= 8 else sympy.Symbol)(str(name), **({} if k >= 8 else {"real": True}))
        for k, name in enumerate(names)]
    definitions = list(zip(names[:5], [sympy.sympify(c) for c in coefficients]))
    definitions += [(p, (8 * a4 * a2 - 3 * a3 ** 2) / (8 * a4 ** 2)),
                    (q, (a3 ** 3 - 4 * a4 * a3 * a2 + 8 * a4 ** 2 * a1) / (8 * a4 ** 3)),
                    (r, (-3 * a3 ** 4 + 256 * a4 ** 3 * a0 - 64 * a4 ** 2 * a3 * a1 + 16 * a4 * a3 ** 2 * a2)
                     / (256 * a4 ** 4))]
    shift = -a3 / (4 * a4)
    sa, sb = signs
    if biquadratic(coefficients):
        definitions += [(m, sympy.sqrt(p ** 2 - 4 * r))]
        return definitions, shift + sb * sympy.sqrt((-p + sa * m) / 2)
    definitions += [(m, sympy.sqrt(p ** 2 / 9 + 4 * r / 3)),
                    (w, 2 * m * sympy.cos(sympy.acos((p ** 3 / 27 - 4 * p * r / 3 + q ** 2 / 2) / m ** 3) / 3)),
                    (z, w - 2 * p / 3),
                    (s, sympy.sqrt(z))]
    return definitions, shift + sa * s / 2 + sb * sympy.sqrt(-z - 2 * p - 2 * sa * q / s) / 2


def biquadratic(coefficients) -> bool:
    """Whether the quartic is one in u² alone (A₃ = A₁ = 0 whatever the coefficients' symbols are):
    then q = 0, and the resolvent's root may be 0. (Expanding q itself costs more than the rest.)"""
    return all(sympy.expand(coefficients[k]) == 0 for k in (1, 3))


def root(expression, sigma_a: int, sigma_b: int, signs=SIGNS):
    """The root for one choice of the signs."""
    return expression.xreplace({signs[0]: sigma_a, signs[1]: sigma_b})


def written_out(definitions, expression):
    """`expression` with the named quantities of `definitions` put in, last first."""
    for name, value in reversed(definitions):
        expression = expression.xreplace({name: value})
    return expression


def root_number(sigma_a: int, sigma_b: int) -> int:
    """1 … 4 for (+, +), (+, −), (−, +), (−, −): the order in which the branches list them."""
    return 1 + (2 if sigma_a < 0 else 0) + (1 if sigma_b < 0 else 0)
