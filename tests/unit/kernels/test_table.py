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


def test_an_elastic_half_plane_tabulates_the_clausen_function():
    """Its grid is the uniform one of the smooth part's bound alone (no memory, no layer), and
    the table gives the closed form to rounding."""
    from viscocontact.kernels.table import LONGEST_INTERVAL

    pk = HalfPlane().prepare(Elastic(), 0.0)
    nodes = pk.table.nodes
    assert len(pk.weights) == 0 and np.max(np.diff(nodes)) <= LONGEST_INTERVAL
    assert np.array_equal(nodes, -nodes[::-1]) and 0.0 in nodes
    _assert_matches_terms(pk, _points(np.random.default_rng(1)))


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
    """The numpy loop (any function: here the table's look-ups behind a lambda, which the
    compiled loop does not take) over blocks of rows."""
    pk = HalfPlane().prepare(SLS, 1e-2)
    pair, single = (lambda x: pk.table.pair(x)), (lambda x: pk.table.antiderivative(x))
    rng = np.random.default_rng(5)
    z = np.sort(rng.uniform(-3, 3, 41))
    a, b = z[:-1], z[1:]
    xi = np.concatenate([0.5 * (a + b), rng.uniform(-3, 3, 9)])   # one reduction of ξ - a
    ref = element_integrals(pair, xi, a, b, block=1 << 40)
    assert np.array_equal(element_integrals(pair, xi, a, b, block=block), ref)
    lone = element_integrals(single, xi, a[::3], b[::3], block=block)
    assert np.array_equal(lone, element_integrals(single, xi, a[::3], b[::3]))


#: Prony series, ζ, kernels and clustered meshes for the compiled loops' hypothesis tests
MESHES = dict(rheology=prony_series(max_terms=3), zeta=log_uniform(-8.0, 8.0),
              kernel=st.sampled_from(KERNELS), seed=st.integers(0, 2**16),
              contacts=st.integers(1, 6), elements=st.integers(1, 40))


def _contacts(rng, count, elements):
    """Edge-clustered chains of elements (contacts) and a few lone elements, as a mesh has."""
    edges = np.sort(rng.uniform(-np.pi, np.pi, 2 * count))
    s = np.sin(np.linspace(-0.5 * np.pi, 0.5 * np.pi, elements + 1)) ** 3
    nodes = [0.5 * (lo + hi) + 0.5 * (hi - lo) * s for lo, hi in zip(edges[::2], edges[1::2])]
    a = np.concatenate([n[:-1] for n in nodes] + [rng.uniform(-4.0, 4.0, 3)])
    b = np.concatenate([n[1:] for n in nodes] + [a[-3:] + 10.0 ** rng.uniform(-9, 0, 3)])
    return a, b


@settings(max_examples=30, deadline=None)
@given(**MESHES)
def test_the_compiled_loop_gives_the_integrals_of_the_pieces(rheology, zeta, kernel, seed,
                                                             contacts, elements):
    """The compiled loop (the table-backed antiderivatives of a prepared kernel) against the
    kernel's pieces summed one by one, on meshes of clustered contacts with points on the
    element ends, the midpoints and anywhere in two periods: to 1e-13 of the kernel's scale,
    as the table's look-ups."""
    pk = kernel.prepare(rheology, zeta)
    rng = np.random.default_rng(seed)
    a, b = _contacts(rng, contacts, elements)
    xi = np.concatenate([0.5 * (a + b), a[::2], rng.uniform(-2 * np.pi, 2 * np.pi, 7)])
    tol = 1e-13 * _scale(pk)
    pair = element_integrals(pk.antiderivative_pair, xi, a, b)
    assert pair.shape == (2, xi.size, a.size)
    assert np.max(np.abs(pair - element_integrals(pk.antiderivative_pair_terms, xi, a, b))) < tol
    assert np.max(np.abs(element_integrals(pk.antiderivative, xi, a, b)
                         - element_integrals(pk.antiderivative_terms, xi, a, b))) < tol
    assert np.max(np.abs(element_integrals(pk.even_antiderivative, xi, a, b)
                         - element_integrals(pk.even_antiderivative_terms, xi, a, b))) < tol


def test_the_compiled_loop_wraps_any_argument_and_passes_nan():
    """Differences beyond ``[-3π, 3π)`` take the general reduction, as :func:`wrap` does; a NaN
    point gives NaN coefficients in its row only."""
    pk = HalfPlane().prepare(SLS, 1e-2)
    a, b = np.array([-0.3, 0.1]), np.array([0.1, 0.5])
    xi = np.array([0.2, 0.2 + 6 * np.pi, 0.2 - 10 * np.pi, np.nan])
    B = element_integrals(pk.antiderivative_pair, xi, a, b)
    assert np.max(np.abs(B[:, 1:3] - B[:, :1])) < 1e-12
    assert np.all(np.isnan(B[:, 3])) and np.all(np.isfinite(B[:, :3]))


def test_a_subclass_that_overrides_the_antiderivative_keeps_it():
    """The compiled loop stands in for the table's look-ups only: a kernel whose prepared
    object overrides ``antiderivative`` gets its own function integrated."""
    import attrs

    from viscocontact.kernels.prepared import PreparedKernel

    @attrs.frozen(kw_only=True, eq=False)
    class Doubled(PreparedKernel):
        def antiderivative(self, x):
            return 2.0 * super().antiderivative(x)

    pk = HalfPlane().prepare(SLS, 1e-2)
    doubled = Doubled(**{f.name: getattr(pk, f.name) for f in attrs.fields(PreparedKernel)
                         if f.init})
    a, b = np.array([-0.3, 0.1]), np.array([0.1, 0.5])
    xi = 0.5 * (a + b)
    assert np.allclose(element_integrals(doubled.antiderivative, xi, a, b),
                       2.0 * element_integrals(pk.antiderivative, xi, a, b), rtol=1e-14, atol=0)


@settings(max_examples=30, deadline=None)
@given(**MESHES)
def test_the_compiled_slopes_are_the_slopes_of_the_pieces(rheology, zeta, kernel, seed,
                                                          contacts, elements):
    """``pairwise`` of the table-backed slopes (the compiled loop) against the kernel's pieces,
    at collocation points minus mesh nodes as the edge Jacobian takes them, to the tolerance of
    the table's own slopes (1e-10 of the kernel's scale plus the value); a point on a node gives
    the table's value there (the infinite slope of ``x log|x|`` at 0)."""
    from viscocontact.kernels.prepared import pairwise

    pk = kernel.prepare(rheology, zeta)
    rng = np.random.default_rng(seed)
    a, b = _contacts(rng, contacts, elements)
    nodes = np.unique(np.concatenate([a, b]))
    xi = np.concatenate([0.5 * (a + b), rng.uniform(-2 * np.pi, 2 * np.pi, 7)])
    got = pairwise(pk.slope_pair, xi, nodes)
    assert got.shape == (2, xi.size, nodes.size)
    x = xi[:, None] - nodes[None, :]
    far = np.abs(np.mod(x + np.pi, 2 * np.pi) - np.pi) > 1e-200
    ref = pk.slope_pair_terms(x)
    tol = 1e-10 * (_scale(pk) + np.abs(ref))
    with np.errstate(invalid="ignore"):         # inf - inf on a node, not compared
        error = np.abs(got - ref)
    assert np.all(error[:, far] < tol[:, far])
    single = pairwise(pk.antiderivative_slope, xi, nodes)
    assert np.array_equal(single, got[0])
    on_node = pairwise(pk.slope_pair, nodes[:3], nodes)
    table = pk.table.slope_pair(nodes[:3, None] - nodes[None, :])
    finite = np.isfinite(table)
    assert np.array_equal(on_node[~finite], table[~finite])
    assert np.all(np.abs(on_node[finite] - table[finite])
                  < 1e-10 * (_scale(pk) + np.abs(table[finite])))


@pytest.mark.parametrize("count", [1, 2, 3])
def test_threads_change_no_bit_of_the_compiled_loops(count):
    """Rows split between threads (``viscocontact._threads``) give the one-thread result bit
    for bit, for the integrals and the slopes, on a call large enough to be split."""
    from viscocontact._threads import SPLIT_MIN, set_threads
    from viscocontact.kernels.prepared import pairwise

    pk = HalfPlane().prepare(SLS, 1e-2)
    a, b = _contacts(np.random.default_rng(7), 6, 60)
    xi = 0.5 * (a + b)
    xi2 = np.concatenate([xi, xi + 1e-3])
    assert xi2.size * a.size >= SPLIT_MIN            # the calls below are split
    try:
        set_threads(1)
        ref = (element_integrals(pk.antiderivative_pair, xi2, a, b),
               pairwise(pk.slope_pair, xi2, np.concatenate([a, b])))
        set_threads(count)
        got = (element_integrals(pk.antiderivative_pair, xi2, a, b),
               pairwise(pk.slope_pair, xi2, np.concatenate([a, b])))
    finally:
        set_threads(None)
    assert all(np.array_equal(r, g) for r, g in zip(ref, got))
