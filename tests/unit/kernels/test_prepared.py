"""Invariants of the prepared periodic viscoelastic kernels (eqs. 4.2, 4.19, 4.32)."""
import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from viscocontact.kernels import ConfinedLayer, FreeLayer, HalfPlane
from viscocontact.kernels.clausen import cl2
from viscocontact.rheology.elastic import Elastic
from viscocontact.rheology.prony import PronySeries
from viscocontact.rheology.sls import StandardLinearSolid

SLS = StandardLinearSolid(beta=10.0)


def _mesh(rng, n_intervals=3, n_el=12, graded=True):
    """Random union of disjoint intervals inside one period, with edge-clustered elements."""
    cuts = np.sort(rng.uniform(-np.pi, np.pi, 2 * n_intervals))
    left, right = [], []
    for a, b in zip(cuts[::2], cuts[1::2]):
        s = np.linspace(0, 1, n_el + 1)
        if graded:
            s = 0.5 - 0.5 * np.cos(np.pi * s)    # clusters nodes at both ends
        z = a + (b - a) * s
        left.append(z[:-1])
        right.append(z[1:])
    return np.concatenate(left), np.concatenate(right)


def _fourier_influence(pk, xi, a, b, modes=200_000):
    """B from the Fourier series; the instantaneous log part is summed in closed form (Cl2, tested
    in test_clausen) so that the series left over decays like 1/m³ and 2e5 modes suffice."""
    m = np.arange(1, modes + 1, dtype=float)
    mult = (pk.multiplier(m) - pk.instantaneous) / m
    out = np.empty((len(xi), len(a)))
    for q in range(len(a)):
        ee = (np.exp(-1j * m * a[q]) - np.exp(-1j * m * b[q])) / (1j * m) * mult
        for l, x in enumerate(xi):
            out[l, q] = -np.sum((np.exp(1j * m * x) * ee).real) / np.pi
    inst = pk.instantaneous * (-cl2(xi[:, None] - a[None, :]) + cl2(xi[:, None] - b[None, :])) / np.pi
    return out + inst + pk.mean * (b - a)[None, :]


@settings(max_examples=8, deadline=None)
@given(st.integers(0, 10_000), st.sampled_from([0.0, 1e-3, 0.3, 30.0]),
       st.sampled_from(["half", "confined", "free"]))
def test_real_and_fourier_space_agree(seed, zeta, geometry):
    kernel = {"half": HalfPlane(), "confined": ConfinedLayer(thickness=0.7, poisson=0.3),
              "free": FreeLayer(thickness=3.0, poisson=0.4)}[geometry]
    pk = kernel.prepare(SLS, zeta)
    rng = np.random.default_rng(seed)
    a, b = _mesh(rng, 2, 3)
    xi = 0.5 * (a + b)
    assert np.max(np.abs(pk.influence(xi, a, b) - _fourier_influence(pk, xi, a, b))) < 2e-9


@settings(max_examples=30, deadline=None)
@given(st.floats(-np.pi, np.pi))
def test_elastic_kernel_is_even(x):
    pk = HalfPlane().prepare(Elastic(), 0.0)
    assume(abs(x) > 1e-6)
    assert abs(pk.values(x) - pk.values(-x)) < 1e-13
    assert abs(pk.antiderivative(x) + pk.antiderivative(-x)) < 1e-13


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 10_000), st.integers(1, 4), st.integers(4, 30))
def test_elastic_influence_symmetric_positive_definite(seed, n_intervals, n_el):
    """Equal elements on a union of intervals shorter than the period: B symmetric, -B PD."""
    rng = np.random.default_rng(seed)
    h = rng.uniform(0.2, 1.0) * 2 * np.pi / (n_intervals * n_el + 1)
    starts = np.sort(rng.choice(np.arange(n_intervals * n_el + n_intervals), n_intervals * n_el,
                                replace=False))
    a = -np.pi + starts * h
    b = a + h
    xi = 0.5 * (a + b)
    B = HalfPlane().prepare(Elastic(), 0.0).influence(xi, a, b)
    assert np.max(np.abs(B - B.T)) < 1e-13
    assert np.linalg.eigvalsh(-0.5 * (B + B.T)).min() > 0


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 10_000), st.sampled_from(["half", "confined", "free"]))
def test_elastic_limits_of_viscoelastic_kernel(seed, geometry):
    kernel = {"half": HalfPlane(), "confined": ConfinedLayer(thickness=0.7, poisson=0.3),
              "free": FreeLayer(thickness=3.0, poisson=0.5)}[geometry]
    rng = np.random.default_rng(seed)
    a, b = _mesh(rng)
    xi = 0.5 * (a + b)
    relaxed = kernel.prepare(Elastic(modulus=1.0), 0.0).influence(xi, a, b)
    slow = kernel.prepare(SLS, 1e-9).influence(xi, a, b)
    fast = kernel.prepare(SLS, 1e9).influence(xi, a, b)
    c0 = kernel.mean_compliance() * (b - a)[None, :]
    scale = np.abs(relaxed).max()
    assert np.max(np.abs(slow - relaxed)) < 1e-7 * scale          # ζ→0: modulus E0
    # ζ→∞: the oscillating part responds with E∞ = 10 E0; the mean (ω = 0) stays relaxed
    assert np.max(np.abs(fast - ((relaxed - c0) / 10.0 + c0))) < 1e-7 * scale


@pytest.mark.parametrize("make", [lambda d: ConfinedLayer(thickness=d, poisson=0.5),
                                  lambda d: FreeLayer(thickness=d, poisson=0.5)])
def test_layers_tend_to_half_plane(make):
    rng = np.random.default_rng(3)
    a, b = _mesh(rng)
    xi = 0.5 * (a + b)
    half = HalfPlane().prepare(SLS, 0.1).influence(xi, a, b)
    errs = [np.max(np.abs(make(d).prepare(SLS, 0.1).influence(xi, a, b) - half)) for d in (2, 8, 30)]
    assert errs[0] > errs[1] > errs[2]
    assert errs[2] < 1e-12


def test_layer_factors_limits():
    m = np.arange(1, 50)
    assert np.all(ConfinedLayer(thickness=0.01, poisson=0.5).geometry_factors(m[:5]) < 1e-3)   # stiff
    assert np.all(FreeLayer(thickness=0.01, poisson=0.5).geometry_factors(m[:5]) > 1e3)        # soft
    assert np.allclose(FreeLayer(thickness=40.0).geometry_factors(m), 1.0, atol=1e-15)
    assert FreeLayer(thickness=1.0, poisson=0.5).mean_compliance() == 0.0
    assert ConfinedLayer(thickness=1.0, poisson=0.3).mean_compliance() < 0  # compressive σ → u > 0


rheologies = st.sampled_from([SLS, StandardLinearSolid(beta=1e3, tau=2.0),
                              PronySeries(moduli=[3.0, 20.0, 5.0], times=[0.01, 1.0, 50.0])])


@settings(max_examples=20, deadline=None)
@given(st.integers(0, 10_000), rheologies, st.floats(-6, 6))
def test_sliding_feeds_non_negative_energy(seed, rheology, log_zeta):
    """Power fed into the solid, V∫σ u' dx, is >= 0 for any stress.

    In the profile's frame the material moves towards -x (eq. 4.2: the displacement at x feels the
    stress that acted at x + Vt a time t ago), so a surface point's normal velocity is -V u' and the
    power of the pressure p = -σ is -V∫p u' dx = V∫σ u' dx; it is >= 0 because Im K(m) >= 0.
    """
    pk = HalfPlane().prepare(rheology, 10.0**log_zeta)
    rng = np.random.default_rng(seed)
    a, b = _mesh(rng, 2, 10)
    F = pk.antiderivative
    # P[l, q] = ∫_{e_l} dx ∫_{e_q} dη G'(x - η) = [∫_{e_q} G(x - η) dη]_{x=a_l}^{b_l}
    def Bx(x):
        return F(x[:, None] - a[None, :]) - F(x[:, None] - b[None, :])
    P = Bx(b) - Bx(a)
    sigma = rng.normal(size=len(a))
    power = sigma @ P @ sigma
    assert power >= -1e-10 * np.abs(P).max() * np.sum(sigma**2)
    sym = 0.5 * (P + P.T)
    assert np.linalg.eigvalsh(sym).min() > -1e-9 * np.abs(P).max()


def test_elastic_kernel_feeds_no_energy():
    pk = HalfPlane().prepare(Elastic(), 0.0)
    a, b = _mesh(np.random.default_rng(1))
    F = pk.antiderivative
    Bx = lambda x: F(x[:, None] - a[None, :]) - F(x[:, None] - b[None, :])
    P = Bx(b) - Bx(a)
    assert np.max(np.abs(P + P.T)) < 1e-12


def test_tiny_element_next_to_large_one():
    """A 1e-9 element next to a unit one: coefficients match the log-kernel integral in closed form."""
    pk = HalfPlane().prepare(Elastic(), 0.0)
    a = np.array([0.0, 1.0])
    b = np.array([1.0, 1.0 + 1e-9])
    xi = 0.5 * (a + b)
    B = pk.influence(xi, a, b)
    # tiny element seen from its own midpoint: ∫ log|2 sin(s/2)| over |s| < h/2 ≈ h(log(h/2) - 1)
    h = 1e-9
    assert B[1, 1] == pytest.approx(h * (np.log(h / 2) - 1) / np.pi, rel=1e-9)
    # tiny element seen from far away: h g(d)/π
    d = xi[0] - xi[1]
    assert B[0, 1] == pytest.approx(h * np.log(abs(2 * np.sin(d / 2))) / np.pi, rel=1e-6)


def test_kernel_zero_mean_and_periodicity():
    for zeta in [0.0, 0.01, 1.0, 100.0]:
        pk = HalfPlane().prepare(SLS, zeta)
        assert abs(pk.antiderivative(np.pi) - pk.antiderivative(-np.pi)) < 1e-10   # ∫ over period = 0
        x = np.linspace(-3, 3, 7)
        assert np.max(np.abs(pk.antiderivative(x + 2 * np.pi) - pk.antiderivative(x))) < 1e-10
