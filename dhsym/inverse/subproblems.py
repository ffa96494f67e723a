"""The sub-problems a course teaches, each recognised from one equation (or a pair) in one
unknown, and its closed-form solution.

An equation is an expression that must be zero. A revolute unknown θ must enter it linearly
in cos θ and sin θ (``a cos θ + b sin θ = c``); a prismatic unknown d as a polynomial of degree
one or two. A sign symbol σ (+1 or −1) marks the choice between two roots: one symbol per
branching step, so one derivation serves every branch.

>>> x, y, t = sympy.symbols("x y theta", real=True)
>>> form = trig_linear(x*sympy.cos(t) + y*sympy.sin(t) - 1, t)
>>> form
(x, y, 1)
>>> sigma = sympy.Symbol("sigma")
>>> one_equation(*form, sigma)
atan2(y, x) + atan2(sigma*sqrt(x**2 + y**2 - 1), 1)
>>> pair((1, 0, x), (0, 1, y))
atan2(y, x)
"""
from __future__ import annotations

import math

import sympy

from ..core.size import length, operations
from . import algebra
from .sentences import LinedUp, Undetermined
from .turned import turned_pair


def expand_around(expr: sympy.Expr, variable: sympy.Symbol) -> sympy.Expr | None:
    """cos/sin of sums that hold `variable` (with coefficient ±1) written with cos/sin of the
    variable alone: c23 → c2 c3 − s2 s3 for θ2. None when the variable enters otherwise
    (2θ, or outside cos/sin for an angle)."""
    replacements = {}
    for function in expr.atoms(sympy.cos, sympy.sin):
        argument = function.args[0]
        if variable not in argument.free_symbols or argument == variable:
            continue
        coefficient = argument.coeff(variable)
        rest = algebra.expand(argument - coefficient * variable)
        if coefficient not in (1, -1) or variable in rest.free_symbols:
            return None
        c, s = sympy.cos(variable), coefficient * sympy.sin(variable)
        cr, sr = sympy.cos(rest), sympy.sin(rest)
        replacements[function] = c * cr - s * sr if function.func == sympy.cos else s * cr + c * sr
    return expr.xreplace(replacements)


def trig_linear(expr: sympy.Expr, variable: sympy.Symbol, constants=frozenset()):
    """(a, b, c) with expr = 0 ⇔ a cos θ + b sin θ = c, or None when the equation is not of that form.
    A factor that a and b share is divided out when it is made of `constants` (the robot's
    lengths, never zero); a factor that can vanish (s5) stays, so that its zero stays visible."""
    expanded = expand_around(expr, variable)
    if expanded is None:
        return None
    c_, s_ = sympy.Dummy("c"), sympy.Dummy("s")
    plain = expanded.xreplace({sympy.cos(variable): c_, sympy.sin(variable): s_})
    if variable in plain.free_symbols:
        return None
    # Only the terms that hold cos θ or sin θ are expanded: the rest is c, as written.
    terms = sympy.Add.make_args(plain)
    rest = sympy.Add(*[t for t in terms if not t.has(c_, s_)])
    bearing = algebra.expand(sympy.Add(*[t for t in terms if t.has(c_, s_)]))
    parts = sympy.collect(bearing, [c_, s_], evaluate=False)
    if set(parts) - {c_, s_, sympy.S.One}:
        parts = sympy.collect(algebra.expand(bearing.subs(s_ ** 2, 1 - c_ ** 2)), [c_, s_], evaluate=False)
        if set(parts) - {c_, s_, sympy.S.One}:  # sin² = 1 − cos² did not make it linear
            return None
    a, b = parts.get(c_, sympy.Integer(0)), parts.get(s_, sympy.Integer(0))
    if a.has(c_, s_) or b.has(c_, s_) or (a == 0 and b == 0):
        return None
    factor = _common_constant(a, b, constants)  # from the expanded terms, before they are factored
    a, b = algebra.factor_terms(a), algebra.factor_terms(b)
    c = -(rest + parts.get(sympy.S.One, sympy.Integer(0)))
    if (b == 0 or a == 0) and factor in (a + b, -a - b):  # cos θ = D, sin θ = D
        return sympy.Integer(b == 0), sympy.Integer(a == 0), _divided(c, a if b == 0 else b)
    return tuple(_divided(x, factor) for x in (a, b, c))


def _divided(value, factor):
    """value / factor over one denominator ((K − a2²)/(2 a2), not K/(2 a2) − a2/2)."""
    if factor in (1, -1):
        return factor * value
    return algebra.over_one_denominator(value / factor)


def _common_constant(a, b, constants) -> sympy.Expr:
    """The factor of constants that every term of a and b shares (2 a2 of 2 a2 a3 and −2 a2 d4).
    Read off the terms when they are monomials in symbols with rational coefficients (linear
    time); otherwise by factor_terms of the expanded sum."""
    shared = _monomial_gcd(sympy.Add.make_args(a) + sympy.Add.make_args(b), set(constants))
    if shared is not None:
        return shared
    x, y = sympy.Dummy("x"), sympy.Dummy("y")
    shared, _ = sympy.factor_terms(algebra.expand(a * x + b * y)).as_independent(x, y, as_Add=False)
    kept = [f for f in sympy.Mul.make_args(shared)
            if f.is_number and f != 0 or (f.free_symbols <= set(constants) and not f.atoms(sympy.Function))]
    shared = sympy.Mul(*kept)
    return -shared if shared.could_extract_minus_sign() else shared


def _monomial_gcd(terms, constants):
    """The positive rational gcd of the terms' coefficients times the lowest power of each constant
    that all of them hold; None when a term is not a product of a rational and powers of symbols.

    >>> a2, a3, d4 = sympy.symbols("a_2 a_3 d_4")
    >>> _monomial_gcd((2*a2*a3, -4*a2**2*d4), {a2, a3, d4})
    2*a_2
    """
    terms = [t for t in terms if t != 0]
    if not terms:
        return None
    numerator, denominator, powers = 0, 1, None
    for term in terms:
        coefficient, rest = term.as_coeff_Mul()
        if not coefficient.is_Rational:
            return None
        numerator = math.gcd(numerator, abs(coefficient.p))
        denominator = math.lcm(denominator, coefficient.q)
        held = {}
        for factor in sympy.Mul.make_args(rest):
            base, exponent = factor.as_base_exp()
            if not (base.is_Symbol and exponent.is_Integer):
                if base.is_number or base.free_symbols & constants:
                    return None
                continue  # cos θ, px**k: no constant of the robot in it
            if exponent < 0:
                return None
            held[base] = exponent
        held = {k: v for k, v in held.items() if k in constants}
        powers = held if powers is None else {k: min(v, held[k]) for k, v in powers.items() if k in held}
    return sympy.Rational(numerator, denominator) * sympy.Mul(*[k ** v for k, v in powers.items()])


def one_equation(a, b, c, sigma, shape: str = "A") -> sympy.Expr:
    """θ with a cos θ + b sin θ = c; the two roots differ by the sign σ of the square root.
    Shape "A" is atan2(b, a) + atan2(σ√(a² + b² − c²), c), shape "B" the same angle as
    atan2(a, −b) − atan2(c, σ√(a² + b² − c²)) (Craig's way of writing the PUMA's θ1).

    >>> x, sigma = sympy.symbols("x sigma", real=True)
    >>> one_equation(1, 0, x, sigma)          # cos θ = x: the law of cosines' form
    atan2(sigma*sqrt(1 - x**2), x)
    >>> one_equation(sympy.Symbol("y"), -x, 0, sigma)   # y cos θ − x sin θ = 0
    atan2(sigma*y, sigma*x)
    """
    if c == 0:  # (cos θ, sin θ) = ±(−b, a)/√(a² + b²)
        return sympy.atan2(sigma * a, -sigma * b)
    if b == 0:  # trig_linear makes a = 1 here
        return sympy.atan2(sigma * sympy.sqrt(1 - (c / a) ** 2), c / a)
    if a == 0:
        return sympy.atan2(c / b, sigma * sympy.sqrt(1 - (c / b) ** 2))
    root = sigma * sympy.sqrt(a ** 2 + b ** 2 - c ** 2)
    if shape == "B":
        return sympy.atan2(a, -b) - sympy.atan2(c, root)
    return sympy.atan2(b, a) + sympy.atan2(root, c)


def existence(a, b, c) -> sympy.Expr | None:
    """The argument of the square root of `one_equation`, which must be ≥ 0 (None: always real)."""
    if c == 0:
        return None
    if b == 0:
        return 1 - (c / a) ** 2
    if a == 0:
        return 1 - (c / b) ** 2
    return a ** 2 + b ** 2 - c ** 2


def pair(first, second, sign: int | None | str = "unknown", constants=frozenset()) -> sympy.Expr:
    """θ from two equations a cos θ + b sin θ = c, solved as a linear system in (cos θ, sin θ):
    atan2 of the pair, one root. `first` and `second` are (a, b, c); `sign` is their
    determinant's, when the caller has worked it out already.

    >>> x, y, s5 = sympy.symbols("x y s_5", real=True)
    >>> pair((-s5, 0, x), (0, s5, y))          # −s5 cos θ = x, s5 sin θ = y
    atan2(s_5*y, -s_5*x)
    """
    (a1, b1, k1), (a2, b2, k2) = first, second
    cos_part, sin_part = k1 * b2 - b1 * k2, a1 * k2 - a2 * k1
    turned = turned_pair(first, second, constants, _tidy)
    sign = determinant_sign(first, second) if turned is None and sign == "unknown" else sign
    if turned is not None:
        single = sympy.atan2(_tidy(sin_part), _tidy(cos_part)) if algebra.expand(a1 * b2 - a2 * b1).is_positive \
            else None
        return min(filter(None, (turned, single)), key=operations)
    if sign is None:  # atan2(s·det², c·det²) = atan2(s, c): det² > 0 wherever det ≠ 0
        det = a1 * b2 - a2 * b1
        return sympy.atan2(_tidy(sin_part * det), _tidy(cos_part * det))
    return sympy.atan2(_tidy(sign * sin_part), _tidy(sign * cos_part))


def pair_is_defined(first, second) -> bool:
    """Whether the pair gives cos θ and sin θ that are not both identically zero."""
    (a1, b1, k1), (a2, b2, k2) = first, second
    return algebra.expand(k1 * b2 - b1 * k2) != 0 or algebra.expand(a1 * k2 - a2 * k1) != 0


def determinant(first, second, factored: bool = True) -> sympy.Expr:
    """The determinant of the pair's 2×2 system; where it is zero the angle is not determined."""
    det = algebra.expand(first[0] * second[1] - second[0] * first[1])
    return sympy.factor(det) if factored else det


def determinant_sign(first, second) -> int | None:
    """+1 or −1 when the pair's determinant keeps one sign wherever it is not zero, else None.
    [[α, −β], [β, α]] has α² + β² ≥ 0 and [[α, β], [β, −α]] has −(α² + β²) ≤ 0."""
    rotation = rotation_sign(first, second)
    if rotation is not None:
        return rotation
    (a1, b1, _), (a2, b2, _) = first, second
    det = algebra.expand(a1 * b2 - a2 * b1)
    if det.is_number:
        return 1 if det > 0 else -1 if det < 0 else None
    return 1 if det.is_nonnegative else -1 if det.is_nonpositive else None


def rotation_sign(first, second) -> int | None:
    """+1 for a pair [[α, −β], [β, α]] (determinant α² + β²), −1 for [[α, β], [β, −α]]
    (−(α² + β²)), else None."""
    (a1, b1, _), (a2, b2, _) = first, second
    zero = lambda e: algebra.expand(e) == 0  # noqa: E731
    if zero(a1 - b2) and zero(b1 + a2):
        return 1
    if zero(a1 + b2) and zero(b1 - a2):
        return -1
    return None


def _tidy(expr: sympy.Expr) -> sympy.Expr:
    """The shorter of the expression and its factored form."""
    candidates = [expr, algebra.factor_terms(expr), algebra.factor_terms(algebra.expand(expr))]
    return min(candidates, key=length)


def polynomial(expr: sympy.Expr, variable: sympy.Symbol):
    """The coefficients (highest first) of a prismatic unknown's equation, degree 1 or 2, else None.

    >>> d, x = sympy.symbols("d x", real=True)
    >>> polynomial(d**2 - x, d)
    [1, 0, -x]
    """
    try:
        poly = sympy.Poly(algebra.expand(expr), variable)
    except sympy.PolynomialError:
        return None
    if poly.degree() not in (1, 2) or any(variable in c.free_symbols for c in poly.all_coeffs()):
        return None
    return [sympy.factor_terms(c) for c in poly.all_coeffs()]


def prismatic(coefficients, sigma) -> sympy.Expr:
    """The root of a degree-1 or degree-2 polynomial; σ chooses between the two of a quadratic.

    >>> d, x, sigma = sympy.symbols("d x sigma", real=True)
    >>> prismatic([1, 0, -x], sigma), prismatic([2, -x], sigma)
    (sigma*sqrt(x), x/2)
    """
    if len(coefficients) == 2:
        return sympy.factor_terms(-coefficients[1] / coefficients[0])
    a, b, c = coefficients
    if b == 0:
        return sigma * sympy.sqrt(sympy.factor_terms(-c / a))
    return (-b + sigma * sympy.sqrt(b ** 2 - 4 * a * c)) / (2 * a)


def factor_bases(expr) -> set:
    """The factors of a product that are not numbers, a power by its base: −2 sin(θ5)² → {sin(θ5)}."""
    return {f.base if f.is_Pow else f for f in sympy.Mul.make_args(expr) if not f.is_number}


def lined_up_angle(det):
    """θk, or θk plus a number (a row's offset, θ5 + 1), where a pair's determinant is a power of
    the sine of that alone (the wrist's s5), else None.

    >>> t, x = sympy.symbols("theta_5 x", real=True)
    >>> lined_up_angle(-sympy.sin(t)**2), lined_up_angle(sympy.sin(t + 1)), lined_up_angle(x * sympy.sin(t))
    (theta_5, theta_5 + 1, None)
    """
    bases = factor_bases(det)
    if len(bases) == 1:
        (base,) = bases
        if isinstance(base, sympy.sin) and angle_symbol(base.args[0]) is not None:
            return base.args[0]
    return None


def angle_symbol(angle):
    """The symbol θ of an angle θ or θ + c (c a number), else None.

    >>> t = sympy.Symbol("theta_5", real=True)
    >>> angle_symbol(t), angle_symbol(t - sympy.pi / 7), angle_symbol(2 * t)
    (theta_5, theta_5, None)
    """
    symbols = angle.free_symbols
    if len(symbols) != 1:
        return None
    (symbol,) = symbols
    return symbol if (angle - symbol).is_number else None


def degenerate_pair(det, shown, forms) -> Undetermined:
    """Where a pair's determinant vanishes. When that is sin θk = 0 of a joint already solved
    (the wrist's s5), the axes on either side of joint k line up: a one-parameter family (which
    sum or difference is left, dhsym.inverse.singular measures). A pair [[α, −β], [β, α]] has
    α² + β² for its determinant, zero where both are: said so.

    >>> x, y, t = sympy.symbols("x y t", real=True)
    >>> degenerate_pair(x**2 + y**2, t, ((x, -y, 1), (y, x, 2))).condition
    (x, y)
    """
    angle = lined_up_angle(det)
    if angle is not None:
        return Undetermined((sympy.sin(angle),), shown, LinedUp(angle))
    a1, b1, _ = forms[0]
    # α = 0 and β = 0 where that is shorter than α² + β² expanded (pz² + (px c1 + py s1)²)
    if rotation_sign(*forms) is not None and length(a1) + length(b1) < length(det):
        return Undetermined(tuple(sorted((unsigned(a1), unsigned(b1)), key=str)), shown)
    return Undetermined((unsigned(det),), shown)


def unsigned(expr):
    return -expr if expr.could_extract_minus_sign() else expr


def root_argument(form, slide: bool = False) -> sympy.Expr | None:
    """The argument of the square root of a two-root form: a² + b² − c² (or 1 − (c/a)²) for
    a cos θ + b sin θ = c, b² − 4ac for a slide's a d² + b d + c = 0; None where there is none.

    >>> a, b, c = sympy.symbols("a b c", real=True)
    >>> root_argument((a, b, c)), root_argument((a, b, c), slide=True)
    (a**2 + b**2 - c**2, -4*a*c + b**2)
    """
    if slide:
        a, b, c = form
        return b ** 2 - 4 * a * c
    return existence(*form)


def double_root(a, b, c) -> sympy.Expr:
    """The one root of a cos θ + b sin θ = c where a² + b² = c²: (cos θ, sin θ) = c (a, b)/(a² + b²).

    >>> x, y = sympy.symbols("x y", real=True)
    >>> double_root(x, y, -sympy.sqrt(x**2 + y**2))   # θ points against (x, y)
    atan2(-y*sqrt(x**2 + y**2), -x*sqrt(x**2 + y**2))
    """
    return sympy.atan2(b * c, a * c)


def book_variants(a, b, c, sigma):
    """(a, b, c, shape, the angle with c as a placeholder) for both signs of the equation and both
    atan2 identities: Craig writes θ1 = atan2(py, px) − atan2(d3, ±√(px² + py² − d3²))."""
    placeholder = sympy.Dummy("c")
    for sign in (1, -1):
        sa, sb, sc = (x if sign == 1 else algebra.over_one_denominator(-x) for x in (a, b, c))
        for shape in ("A", "B"):
            yield sa, sb, sc, shape, one_equation(sa, sb, placeholder, sigma, shape)
