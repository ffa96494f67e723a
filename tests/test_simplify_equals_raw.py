"""The simplified result always equals the raw product: random chains, algebra and numbers."""
import pytest
import sympy
from hypothesis import given
from hypothesis import strategies as st

from dhsym import Chain, DHRow, Step
from dhsym.checking.verify import algebraically_equal, numeric_error

pytestmark = pytest.mark.slow  # property tests drawing many random chains: seconds to minutes per test

PI = sympy.pi
TWISTS = [0, PI / 2, -PI / 2, PI, PI / 3, -PI / 4, "symbol"]
OFFSETS = [0, PI / 2, -PI / 2, PI, PI / 6]


def _sym(name):
    return sympy.Symbol(name, real=True)


@st.composite
def chains(draw, max_links=5, conventions=("standard", "modified")):
    n = draw(st.integers(1, max_links))
    convention = draw(st.sampled_from(conventions))
    rows = []
    for i in range(1, n + 1):
        twist = draw(st.sampled_from(TWISTS))
        alpha = _sym(f"alpha_{i}") if twist == "symbol" else twist
        a = draw(st.sampled_from([0, _sym(f"a_{i}"), sympy.Rational(1, 2)]))
        if draw(st.booleans()):
            d = draw(st.sampled_from([0, _sym(f"d_{i}"), 2]))
            rows.append(DHRow.revolute(_sym(f"theta_{i}") + draw(st.sampled_from(OFFSETS)), d, a, alpha,
                                       variable=_sym(f"theta_{i}")))
        else:
            theta = draw(st.sampled_from([0, PI / 2, _sym(f"beta_{i}")]))
            rows.append(DHRow.prismatic(_sym(f"q_{i}") + draw(st.sampled_from([0, _sym(f"e_{i}")])), theta, a, alpha,
                                        variable=_sym(f"q_{i}")))
    fixed = st.lists(st.builds(Step, st.sampled_from(["Rx", "Ry", "Rz", "Tx", "Ty", "Tz"]),
                               st.sampled_from([PI / 2, -PI / 2, PI, _sym("h"), 1])), max_size=2)
    return Chain(rows, convention, base=draw(fixed), tool=draw(fixed))


def _frames(chain, draw):
    frames = chain.frames
    return draw(st.sampled_from(frames)), draw(st.sampled_from(frames))


@given(chains(), st.data())
def test_simplified_equals_raw_numerically(chain, data):
    i, j = _frames(chain, data.draw)
    assert numeric_error(chain.transform(i, j), chain.transform(i, j, raw=True)) < 1e-9


@given(chains(max_links=3), st.data())
def test_simplified_equals_raw_algebraically(chain, data):
    i, j = _frames(chain, data.draw)
    simplified, raw = chain.transform(i, j), chain.transform(i, j, raw=True)
    assert all(algebraically_equal(x, y) for x, y in zip(simplified, raw))


@pytest.mark.slow
@given(chains(max_links=3), st.data())
def test_transform_times_its_inverse_is_identity(chain, data):
    i, j = _frames(chain, data.draw)
    product = chain.transform(i, j) * chain.transform(j, i)
    assert all(algebraically_equal(x, y) for x, y in zip(product, sympy.eye(4)))


@given(chains(max_links=4, conventions=["standard"]))
def test_standard_chain_equals_its_modified_rewrite(chain):
    """A standard table read as a modified one (shifted a, α, plus a tool step) gives the same pose."""
    rows = chain.rows
    shifted = [DHRow(r.joint, r.theta, r.d, prev_a, prev_alpha, r.variable)
               for r, prev_a, prev_alpha in zip(rows, [0] + [r.a for r in rows], [0] + [r.alpha for r in rows])]
    tool = [Step("Tx", rows[-1].a), Step("Rx", rows[-1].alpha)] + list(chain.tool)
    modified = Chain(shifted, "modified", base=chain.base, tool=tool)
    assert numeric_error(chain.fk(), modified.transform(modified.first_frame, "tool")) < 1e-9


@given(chains(max_links=4, conventions=["modified"]))
def test_modified_chain_equals_its_standard_rewrite(chain):
    """A modified table read as a standard one (a, α shifted down, the first pair as base steps) gives the same pose."""
    rows = chain.rows
    shifted = [DHRow(r.joint, r.theta, r.d, next_a, next_alpha, r.variable)
               for r, next_a, next_alpha in zip(rows, [r.a for r in rows[1:]] + [0], [r.alpha for r in rows[1:]] + [0])]
    base = list(chain.base) + [Step("Rx", rows[0].alpha), Step("Tx", rows[0].a)]
    standard = Chain(shifted, "standard", base=base, tool=chain.tool)
    assert numeric_error(chain.fk(), standard.fk()) < 1e-9
