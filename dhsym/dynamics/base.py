"""The base inertial parameters: the combinations of π that τ = Y π can identify.

Some columns of Y are zero (a parameter that moves no joint: link 1's mass when its axis is
vertical) and others are combinations of the rest (link j's YY_j next to its XX_j and the link
before it). Keeping the independent columns, Y_b, gives τ = Y_b π_b with each base parameter
π_b,k = π_k + Σ_d β_dk π_d, where column d = Σ_k β_dk · column k (Gautier and Khalil; SymPyBotics
and OpenSYMORO give the same).

Which columns are independent is decided with numbers: Y is evaluated at random states (and
random values of the robot's lengths) and the columns are taken in a fixed order, each kept when
it is not a combination of those kept before it; a link's XX, XY, XZ, YZ, ZZ, MX, MY come before
its YY, MZ and mass, so that the latter are the ones grouped, as Khalil groups them, and the links
are taken from the base out. The coefficients β are then found exactly: each is a polynomial of
degree at most two in the robot's lengths (inertia is quadratic in distance), so it is fitted over
the lengths, each numeric length standing as a symbol, rounded to small fractions, checked at new
random points, and the numbers put back. Twists must be multiples of π/2 for this.

>>> import dhsym
>>> from dhsym.core.inertia import MassModel
>>> result = base_parameters(dhsym.load("planar2r").chain, MassModel().filled(2))
>>> for name, value in zip(result.names, result.values):
...     print(name, "=", value)
ZZR_1 = 2*MX_1*a_1 + ZZ_1 + a_1**2*m_1 + a_1**2*m_2
ZZR_2 = ZZ_2 - a_2**2*m_2
MXR_2 = MX_2 + a_2*m_2
MY_2 = MY_2
>>> len(result.unidentifiable)   # a planar arm moves no parameter out of its plane
13
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from fractions import Fraction

import sympy

from ..core.chain import Chain, DHRow
from ..core.inertia import MassModel
from ..errors import UserError
from .codegen import tape_function
from .regressor import ORDER, Regressor, regressor

PREFERENCE = ("XX", "XY", "XZ", "YZ", "ZZ", "MX", "MY", "YY", "MZ", "m")  # the last ones are grouped first
TOLERANCE = 1e-8  # relative size of what is left of a column after the kept ones are taken out
DENOMINATOR = 100  # the largest denominator of a coefficient of β


@dataclass(frozen=True)
class BaseParameters:
    """The kept standard parameters (their columns form Y_b), the base parameter each stands for
    (π_k plus the grouped ones), and the parameters that move no joint."""

    regressor: Regressor
    kept: tuple
    values: tuple
    unidentifiable: tuple

    @property
    def names(self) -> tuple:
        """Khalil's names: ZZR_1 for a parameter with others grouped into it, else its own name."""
        return tuple(k.name.replace("_", "R_", 1) if value != k else k.name for k, value in zip(self.kept, self.values))

    @property
    def Y(self) -> sympy.Matrix:
        columns = [self.regressor.parameters.index(p) for p in self.kept]
        return self.regressor.Y.extract(list(range(self.regressor.Y.rows)), columns)


def base_parameters(chain: Chain, masses: MassModel, first_joint: int = 1, seed: int = 0) -> BaseParameters:
    """The base parameters of `chain` with gravity as in the filled `masses`."""
    lengths, placeholders = _as_symbols(chain)
    result = regressor(placeholders, masses, first_joint)
    constants = sorted(set().union(*(result.tape.depends_on(x) for x in result.Y))
                       - set(result.variables) - set(result.rates) - set(result.accelerations) - set(result.parameters),
                       key=lambda s: s.name)
    evaluate = _evaluator(result, constants)
    rng = _numpy().random.default_rng(seed)
    kept, unidentifiable = _independent(evaluate(_point(rng, constants)), result.parameters)
    coefficients = _coefficients(evaluate, rng, constants, result.parameters, kept)
    values = []
    for k in kept:
        grouped = sum((beta[k] * d for d, beta in coefficients.items() if beta.get(k, 0) != 0), sympy.Integer(0))
        values.append(sympy.expand((k + grouped).xreplace(lengths)))
    final = regressor(chain, masses, first_joint)
    return BaseParameters(final, tuple(kept), tuple(values), tuple(unidentifiable))


def _as_symbols(chain: Chain) -> tuple:
    """The chain with each numeric length of its rows written as a symbol, and {symbol: number}."""
    lengths, rows = {}, []
    for k, row in enumerate(chain.rows, 1):
        if any(not (angle / (sympy.pi / 2)).is_Integer for angle in (row.alpha,)) or row.alpha.free_symbols:
            raise UserError(f"the base parameters need twists that are multiples of π/2; joint {k}'s is {row.alpha}")
        values = {}
        for key in ("a", "d"):
            value = getattr(row, key)
            constant = value - row.variable if key == "d" and row.joint == "P" else value
            if constant.is_number and constant != 0:
                symbol = sympy.Dummy(f"{key}{k}", real=True)
                lengths[symbol] = constant
                constant = symbol
            values[key] = constant + row.variable if key == "d" and row.joint == "P" else constant
        rows.append(DHRow(row.joint, row.theta, values["d"], values["a"], row.alpha, row.variable))
    return lengths, Chain(rows, chain.convention, chain.base, chain.tool)


def _evaluator(result: Regressor, constants: list):
    """Y at many states at once: (states, constants) → array (n × 10n, states)."""
    inputs = [*result.variables, *result.rates, *result.accelerations, *constants]
    function = tape_function(result.tape, inputs, list(result.Y))
    n, count = len(result.variables), len(result.parameters)

    def evaluate(point: dict, states: int = 0):
        numpy = _numpy()
        rng = numpy.random.default_rng(len(point))
        states = states or 4 * n + 4
        motion = [rng.uniform(-math.pi, math.pi, states) for _ in range(3 * n)]
        values = function(*motion, *[point[c] for c in constants])
        return values.reshape(n, count, states).transpose(2, 0, 1).reshape(states * n, count)

    return evaluate


def _point(rng, constants: list) -> dict:
    return {c: rng.uniform(0.5, 1.5) for c in constants}


def _independent(W, parameters: tuple) -> tuple:
    """(kept parameters, those with a zero column), taking the columns in the order of PREFERENCE."""
    numpy = _numpy()
    order = sorted(range(len(parameters)), key=lambda j: (j // len(ORDER), PREFERENCE.index(ORDER[j % len(ORDER)])))
    scale = numpy.abs(W).max() or 1.0
    basis, kept, zero = [], [], []
    for j in order:
        column = W[:, j].copy()
        if numpy.abs(column).max() <= TOLERANCE * scale:
            zero.append(parameters[j])
            continue
        for _ in range(2):  # Gram–Schmidt twice: stable enough for some sixty columns
            for vector in basis:
                column -= (vector @ column) * vector
        if numpy.linalg.norm(column) > TOLERANCE * scale * math.sqrt(len(column)):
            basis.append(column / numpy.linalg.norm(column))
            kept.append(parameters[j])
    kept.sort(key=parameters.index)
    return kept, [p for p in parameters if p in zero]


def _coefficients(evaluate, rng, constants: list, parameters: tuple, kept: list) -> dict:
    """{grouped parameter d: {kept parameter k: β_dk}}, exact, fitted over the constants."""
    numpy = _numpy()
    dropped = [p for p in parameters if p not in kept]
    kept_columns = [parameters.index(p) for p in kept]
    monomials = [m for degree in range(3) for m in itertools.combinations_with_replacement(constants, degree)]
    points = [_point(rng, constants) for _ in range(len(monomials) + 6)]
    betas = []
    for point in points:
        W = evaluate(point)
        solution = numpy.linalg.lstsq(W[:, kept_columns], W[:, [parameters.index(d) for d in dropped]], rcond=None)[0]
        betas.append(solution)
    design = numpy.array([[math.prod(point[c] for c in m) for m in monomials] for point in points])
    fitted = numpy.linalg.lstsq(design, numpy.array(betas).reshape(len(points), -1), rcond=None)[0]
    exact = [[_small_fraction(x) for x in row] for row in fitted]
    check = _point(rng, constants)
    W = evaluate(check)
    expected = numpy.linalg.lstsq(W[:, kept_columns], W[:, [parameters.index(d) for d in dropped]], rcond=None)[0]
    predicted = numpy.array([[float(sum(exact[i][r * len(dropped) + c] * math.prod(check[x] for x in m)
                                        for i, m in enumerate(monomials))) for c in range(len(dropped))]
                             for r in range(len(kept))])
    if not numpy.allclose(predicted, expected, atol=1e-7, rtol=1e-7):
        raise UserError("the base parameters of this robot are not polynomials of degree two in its lengths; "
                        "dhsym cannot write them exactly")
    out = {}
    for c, d in enumerate(dropped):
        out[d] = {}
        for r, k in enumerate(kept):
            value = sum(sympy.Rational(exact[i][r * len(dropped) + c]) * sympy.Mul(*m) for i, m in enumerate(monomials))
            if value != 0:
                out[d][k] = value
    return out


def _small_fraction(x: float) -> Fraction:
    fraction = Fraction(x).limit_denominator(DENOMINATOR)
    if abs(float(fraction) - x) > 1e-6 * max(1.0, abs(x)):
        raise UserError("the base parameters of this robot have coefficients dhsym cannot write exactly")
    return fraction


def _numpy():
    import numpy  # only where numbers are worked out: the other dynamics needs no numpy

    return numpy
