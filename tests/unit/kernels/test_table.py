"""The combined kernel table (``viscocontact.kernels.table``) against the sum of its pieces."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact.kernels import ConfinedLayer, FreeLayer, HalfPlane
from viscocontact.kernels.prepared import element_integrals
from viscocontact.rheology import Elastic, PronySeries, StandardLinearSolid
from viscocontact.testing.strategies_rheology import log_uniform, prony_series

SLS = StandardLinearSolid(beta=10.0)
KERNELS = [HalfPlane(), ConfinedLayer(thickness=0.3, poisson=0.3), FreeLayer(thickness=2.0)]


def _points(rng):
    """Points over two periods, log-spaced down to 1e-15 on both sides of 0, and ±π."""
    tiny = 10.0 ** rng.uniform(-15, 0.5, 400) * rng.choice([-1.0, 1.0], 400)
    return np.concatenate([rng.uniform(-2 * np.pi, 2 * np.pi, 600), tiny,
                           [np.pi, -np.pi, 1e-300, -1e-300]])


def _scale(pk):
    return pk.instantaneous + float(np.sum(pk.weights)) + (pk.correction is not None)


def _assert_matches_terms(pk, x):
    """Values to rounding (1e-13 of the kernel's scale), slopes to 1e-10 of it (the smooth part
    of the Clausen function is interpolated there, its slope differentiated from the cubic).
    Slopes are compared off ``|x| < 1e-200``, where the pieces' interpolation index rounds
    ``±x`` onto the same side of the node 0 (the table finds the side exactly)."""
    scale = _scale(pk)
    assert np.max(np.abs(pk.antiderivative(x) - pk.antiderivative_terms(x))) < 1e-13 * scale
    assert np.max(np.abs(pk.even_antiderivative(x) - pk.even_antiderivative_terms(x))) \
        < 1e-13 * scale
    assert np.max(np.abs(pk.antiderivative_pair(x) - pk.antiderivative_pair_terms(x))) \
        < 1e-13 * scale
    x = x[np.abs(x) > 1e-200]
    ref = pk.slope_pair_terms(x)
    tol = 1e-10 * (scale + np.abs(ref))
    assert np.all(np.abs(pk.slope_pair(x) - ref) < tol)
    assert np.all(np.abs(pk.antiderivative_slope(x) - ref[0]) < tol[0])


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("zeta", [1e-8, 1e-6, 1e-2, 1.0, 1e3, 1e8])
def test_table_equals_the_sum_of_its_pieces(kernel, zeta):
    pk = kernel.prepare(SLS, zeta)
    assert pk.table is not None
    _assert_matches_terms(pk, _points(np.random.default_rng(0)))


@settings(max_examples=25, deadline=None)
@given(rheology=prony_series(max_terms=4), zeta=log_uniform(-8.0, 8.0),
       kernel=st.sampled_from(KERNELS), seed=st.integers(0, 2**16))
def test_table_equals_the_sum_of_its_pieces_for_any_prony_series(rheology, zeta, kernel, seed):
    pk = kernel.prepare(rheology, zeta)
    if pk.table is None:            # every branch relaxed or frozen on a half-plane: Clausen only
        assert isinstance(kernel, HalfPlane) and len(pk.weights) == 0
        return
    _assert_matches_terms(pk, _points(np.random.default_rng(seed)))


def test_a_multi_branch_table_holds_every_branch_grid():
    """Three active branches: the union grid holds each branch's nodes, is symmetric about 0
    and has 0 as a node."""
    rheology = PronySeries(moduli=[3.0, 20.0, 5.0], times=[0.01, 1.0, 50.0])
    pk = HalfPlane().prepare(rheology, 0.1)
    nodes = pk.table.nodes
    assert len(pk.tables) == 3
    for tab in pk.tables:
        assert np.all(np.isin(tab.nodes, nodes))
    assert np.array_equal(nodes, -nodes[::-1]) and 0.0 in nodes
    _assert_matches_terms(pk, _points(np.random.default_rng(3)))


def test_elastic_half_plane_keeps_the_closed_form():
    pk = HalfPlane().prepare(Elastic(), 0.0)
    assert pk.table is None
    x = _points(np.random.default_rng(1))
    assert np.array_equal(pk.antiderivative(x), pk.antiderivative_terms(x))


def test_an_elastic_layer_tabulates_its_correction():
    pk = ConfinedLayer(thickness=0.5).prepare(Elastic(), 0.0)
    assert pk.table is not None and len(pk.weights) == 0
    _assert_matches_terms(pk, _points(np.random.default_rng(2)))


@pytest.mark.parametrize("zeta", [1e-6, 1e-2, 1.0])
def test_slopes_are_the_derivative_of_the_table(zeta):
    pk = ConfinedLayer(thickness=0.7).prepare(SLS, zeta)
    x = np.random.default_rng(4).uniform(-3.0, 3.0, 50)
    x = x[np.abs(x) > 1e-3]
    h = 1e-6
    for f, df in ((pk.antiderivative, pk.antiderivative_slope),
                  (pk.even_antiderivative, lambda s: pk.slope_pair(s)[1])):
        central = (f(x + h) - f(x - h)) / (2 * h)
        assert np.max(np.abs(df(x) - central)) < 1e-6 * (1 + np.max(np.abs(central)))


def test_shapes_and_scalars():
    pk = HalfPlane().prepare(SLS, 0.1)
    x = np.linspace(-4, 4, 12).reshape(3, 4)
    assert pk.antiderivative(x).shape == (3, 4)
    assert pk.antiderivative_pair(x).shape == (2, 3, 4)
    assert pk.slope_pair(x).shape == (2, 3, 4)
    assert np.ndim(pk.antiderivative(np.pi)) == 0
    assert abs(pk.antiderivative(np.pi) - pk.antiderivative(-np.pi)) < 1e-13


def test_influence_of_tiny_elements_keeps_its_relative_accuracy():
    """A 1e-9 element next to large ones, against the pieces' antiderivative: its own
    coefficient (``F`` small near 0) to 1e-12 relative, every coefficient to the rounding of
    ``F`` (1e-15 absolute; the same in both)."""
    pk = HalfPlane().prepare(SLS, 1e-2)
    a = np.array([-1.0, 0.0, 1e-9, 0.3])
    b = np.array([0.0, 1e-9, 0.3, 1.2])
    xi = 0.5 * (a + b)
    B = pk.influence(xi, a, b)
    ref = element_integrals(pk.antiderivative_terms, xi, a, b) + pk.mean * (b - a)
    assert np.max(np.abs(B - ref)) < 1e-15
    assert abs(B[1, 1] - ref[1, 1]) < 1e-12 * abs(ref[1, 1])


@pytest.mark.parametrize("block", [1, 7, 64, 1 << 40])
def test_row_blocks_do_not_change_the_integrals(block):
    pk = HalfPlane().prepare(SLS, 1e-2)
    rng = np.random.default_rng(5)
    z = np.sort(rng.uniform(-3, 3, 41))
    a, b = z[:-1], z[1:]
    xi = np.concatenate([0.5 * (a + b), rng.uniform(-3, 3, 9)])   # one reduction of ξ - a
    ref = element_integrals(pk.antiderivative_pair, xi, a, b, block=1 << 40)
    assert np.array_equal(element_integrals(pk.antiderivative_pair, xi, a, b, block=block), ref)
    lone = element_integrals(pk.antiderivative, xi, a[::3], b[::3], block=block)
    assert np.array_equal(lone, element_integrals(pk.antiderivative, xi, a[::3], b[::3]))
