"""Each sub-problem solver on its own, at random numbers: the angle (or slide) it returns
satisfies the equation it was given, and every root a student expects is among its roots."""
import math

import sympy
from hypothesis import example, given
from hypothesis import strategies as st

import dhsym
from dhsym.inverse import subproblems as sp
from dhsym.inverse.algebra import expand, pythagoras
from dhsym.inverse.singular import wrist_factors
from dhsym.inverse.witness import number_at
from dhsym.velocity.determinant import determinant

theta, d = sympy.symbols("theta d", real=True)
sigma = sympy.Symbol("sigma", real=True)
angles = st.floats(-math.pi, math.pi, allow_nan=False)
lengths = st.floats(0.1, 2.0, allow_nan=False)
signed = st.floats(-2.0, 2.0, allow_nan=False).filter(lambda x: abs(x) > 0.05)


X = sympy.Symbol("X", real=True)  # the number an equation is given, kept a symbol until the end


def _safe_sqrt(x):
    return math.sqrt(max(x, 0.0)) if x > -1e-9 else math.nan


def _value(expr, sign=1, x=0.0):
    """The number, with a root of −1e-15 (rounding at the edge of the workspace) taken as 0."""
    function = sympy.lambdify([sigma, X], sympy.sympify(expr), modules=[{"sqrt": _safe_sqrt}, "math"])
    return float(function(sign, x))


def _same_angle(x, y):
    return abs(math.remainder(x - y, 2 * math.pi)) < 1e-7


@given(signed, signed, angles)
def test_a_cos_plus_b_sin_gives_both_roots(a, b, truth):
    c = a * math.cos(truth) + b * math.sin(truth)
    form = sp.trig_linear(sympy.Rational(a) * sympy.cos(theta) + sympy.Rational(b) * sympy.sin(theta) - X, theta)
    roots = [_value(sp.one_equation(*form, sigma), s, c) for s in (1, -1)]
    for root in roots:
        assert abs(a * math.cos(root) + b * math.sin(root) - c) < 1e-7
    assert any(_same_angle(root, truth) for root in roots)


@given(lengths, lengths, angles)
@example(2.0, 0.1015625, 0.0)  # the arm stretched out: D = 1 up to rounding
def test_law_of_cosines_gives_elbow_up_and_down(l1, l2, truth):
    squared = l1 ** 2 + l2 ** 2 + 2 * l1 * l2 * math.cos(truth)
    exact1, exact2 = sympy.Rational(l1), sympy.Rational(l2)  # no 15-digit Floats inside the form
    form = sp.trig_linear(X - exact1 ** 2 - exact2 ** 2 - 2 * exact1 * exact2 * sympy.cos(theta), theta)
    assert form[1] == 0  # recognised as cos θ = D
    roots = [_value(sp.one_equation(*form, sigma), s, squared) for s in (1, -1)]
    assert any(_same_angle(root, truth) for root in roots) and any(_same_angle(-root, truth) for root in roots)


@given(signed, signed, angles, st.floats(0.2, 3.0))
def test_a_pair_gives_the_one_angle(a, b, truth, scale):
    # (a c − b s, b c + a s) = scale·(x, y): the rotation-like pair of a planar arm
    x = a * math.cos(truth) - b * math.sin(truth)
    y = b * math.cos(truth) + a * math.sin(truth)
    first = sp.trig_linear(a * sympy.cos(theta) - b * sympy.sin(theta) - x, theta)
    second = sp.trig_linear(b * sympy.cos(theta) + a * sympy.sin(theta) - y, theta)
    assert _same_angle(_value(sp.pair(first, second)), truth)


@given(signed, signed, angles)
def test_a_pair_with_symbolic_coefficients_keeps_the_sign(s5, k, truth):
    # −s5 cos θ = X, s5 sin θ = Y: the wrist's θ4, right for either sign of s5
    s = sympy.Symbol("s_5", real=True)
    first, second = (-s, 0, sympy.Symbol("X")), (0, s, sympy.Symbol("Y"))
    angle = sp.pair(first, second).xreplace({s: s5, sympy.Symbol("X"): -s5 * math.cos(truth),
                                            sympy.Symbol("Y"): s5 * math.sin(truth)})
    assert _same_angle(_value(angle), truth)


@given(st.floats(-2, 2), lengths, st.floats(-2, 2))
def test_prismatic_joint_from_a_distance(offset, scale, truth):
    # (d + offset)² · scale = value: the two roots, one of them the truth
    value = scale * (truth + offset) ** 2
    coefficients = sp.polynomial(scale * (d + offset) ** 2 - X, d)
    roots = [_value(sp.prismatic(coefficients, sigma), s, value) for s in (1, -1)]
    assert any(abs(root - truth) < 1e-6 for root in roots)


@given(signed, st.floats(-2, 2))
def test_prismatic_joint_from_a_coordinate(scale, truth):
    coefficients = sp.polynomial(scale * d - sympy.Float(scale * truth), d)
    assert abs(_value(sp.prismatic(coefficients, sigma)) - truth) < 1e-9


def test_an_equation_not_of_a_known_form_is_not_recognised():
    assert sp.trig_linear(sympy.cos(2 * theta) - 1, theta) is None
    assert sp.trig_linear(sympy.cos(theta) * sympy.sin(theta) - 1, theta) is None
    assert sp.polynomial(d ** 3 - 1, d) is None


def test_no_root_outside_the_workspace():
    form = sp.trig_linear(sympy.cos(theta) - X, theta)
    assert sp.existence(*form) == 1 - X ** 2  # the condition: cos θ = X needs 1 − X² ≥ 0
    assert math.isnan(_value(sp.one_equation(*form, sigma), 1, 2.0))


# The speed-ups of the derivation: each must give what the slower SymPy route gives.

_a, _b, _t = sympy.symbols("a_2 b_3 theta_1", real=True)
_atoms = [_a, _b, sympy.cos(_t), sympy.sin(_t), sympy.cos(_t + _a), sympy.Integer(2), sympy.Rational(-1, 3)]


@st.composite
def _polynomials(draw, depth=3):
    """Random sums and products of symbols, cos/sin terms and rationals, sometimes over a monomial."""
    if depth == 0 or draw(st.booleans()):
        return draw(st.sampled_from(_atoms))
    parts = draw(st.lists(_polynomials(depth - 1), min_size=2, max_size=3))
    expr = sympy.Add(*parts) if draw(st.booleans()) else sympy.Mul(*parts)
    return expr / (2 * _a) if draw(st.integers(0, 4)) == 0 else expr


@given(_polynomials())
@example(sympy.sqrt(2) * (_a + 1) ** 2)  # not over the rationals: SymPy expands it
@example(_a / (_b * (_a + 1)))  # a quotient by a sum: SymPy expands it
def test_ring_expansion_is_sympys_expansion(expr):
    assert expand(expr) == sympy.expand(expr)


def test_pythagoras_shortens_without_double_angles_as_a_book_does():
    t3, t4 = sympy.symbols("theta_3 theta_4", real=True)
    d3, d5 = sympy.symbols("d_3 d_5", real=True)
    s3, c3, s4, c4 = sympy.sin(t3), sympy.cos(t3), sympy.sin(t4), sympy.cos(t4)
    # the iiwa's determinant with θ3 free: what trigsimp wrote, at a hundredth of the cost
    det = d3**2 + 2*d3*d5*c4 + d5**2*s4**2*c3**2 + d5**2*c4**2
    assert pythagoras(det) == d3**2 + 2*d3*d5*c4 - d5**2*s3**2*s4**2 + d5**2
    # nothing shorter: left as it is (trigsimp would write sin(2θ1), which a book does not)
    px, py, t1 = sympy.symbols("px py theta_1", real=True)
    kept = px**2*sympy.cos(t1)**2 + 2*px*py*sympy.sin(t1)*sympy.cos(t1) + py**2*sympy.sin(t1)**2
    assert pythagoras(kept) is kept


def test_wrist_singularity_is_a_factor_of_the_whole_determinant():
    for name in ("puma560", "stanford", "inline6", "cylindrical_wrist"):
        chain = dhsym.load(name)
        found = wrist_factors(chain.chain, chain.numbers, chain.sample)
        assert found and all(f in determinant(chain).factors for f in found), name


@given(angles, lengths)
def test_the_witness_value_is_sympys(angle, length):
    x, y = sympy.symbols("x y", real=True)
    expr = sympy.atan2(y * sympy.sin(x), sympy.sqrt(1 + y**2) - sympy.cos(x)) / (2 * y) + sympy.pi * y**3
    numbers = {x: sympy.Float(angle, 17), y: sympy.Float(length, 17)}
    assert math.isclose(number_at(expr, numbers), float(expr.xreplace(numbers).evalf(15)), rel_tol=1e-12,
                        abs_tol=1e-14)
    assert number_at(sympy.sqrt(x - 10), numbers) is None  # complex: no value, as SymPy's float() says
