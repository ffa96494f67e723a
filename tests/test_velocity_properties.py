"""Property tests: on random chains (both conventions, prismatic joints, offsets, symbolic
twists, base and tool steps) the Jacobian equals the definition on the raw product, in any
frame and for any point, and the velocity propagation ends in the same Jacobian."""
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from test_simplify_equals_raw import chains
from test_velocity import reference_jacobian

from dhsym.checking.verify import algebraically_equal, numeric_error
from dhsym.velocity import determinant, jacobian, propagated_jacobian

pytestmark = pytest.mark.slow  # property tests drawing many random chains: seconds to minutes per test

SETTINGS = settings(max_examples=40, deadline=None)


@SETTINGS
@given(chains(max_links=4), st.data())
def test_jacobian_equals_the_definition_on_the_raw_product(chain, data):
    frame, point = data.draw(st.sampled_from(chain.frames)), data.draw(st.sampled_from(chain.frames))
    assert numeric_error(jacobian(chain, frame, point), reference_jacobian(chain, frame, point), trials=4) < 1e-9


@SETTINGS
@given(chains(max_links=2), st.data())
def test_jacobian_equals_the_definition_by_algebra(chain, data):
    frame = data.draw(st.sampled_from(chain.frames))
    ours, reference = jacobian(chain, frame), reference_jacobian(chain, frame, chain.last_frame)
    assert all(algebraically_equal(x, y) for x, y in zip(ours, reference))


@SETTINGS
@given(chains(max_links=4))
def test_propagation_ends_in_the_jacobian_of_the_last_frame(chain):
    assert numeric_error(propagated_jacobian(chain), jacobian(chain, chain.last_frame), trials=4) < 1e-9


@SETTINGS
@given(chains(max_links=3))
def test_determinant_is_that_of_the_block_it_names(chain):
    result = determinant(chain)
    if result.value is None:
        assert result.note
        return
    rows = list(range(6)) if result.block == "J" else [
        ("vx", "vy", "vz", "ωx", "ωy", "ωz").index(r) for r in result.block[5:].split(", ")]
    block = jacobian(chain).extract(rows, list(range(chain.n)))
    assert numeric_error(result.value, block.det(method="berkowitz"), trials=4) < 1e-8
    assert sympy.Mul(*result.factors).free_symbols <= result.value.free_symbols
