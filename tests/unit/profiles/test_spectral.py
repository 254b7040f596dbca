"""SpectralProfile: exact evaluation, grid sampling, moments, statistics and peak."""
from __future__ import annotations

import attrs
import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from viscocontact import ValidationError
from viscocontact.profiles import Modes, SelfAffineProfile, SpectralProfile
from viscocontact.testing.strategies_profiles import profiles, self_affine_profiles

TWO_PI = 2 * np.pi
SETTINGS = settings(max_examples=50, deadline=None)


@attrs.frozen(kw_only=True)
class Series(SpectralProfile):
    """A spectral profile with arbitrary (possibly sparse) modes, for the tests."""

    k: tuple
    a: tuple
    phi: tuple

    @property
    def modes(self) -> Modes:
        return Modes(wavenumbers=self.k, amplitudes=self.a, phases=self.phi)


def naive(modes: Modes, x: np.ndarray, d: int = 0) -> np.ndarray:
    k, a, phi = modes.wavenumbers, modes.amplitudes, modes.phases
    arg = np.multiply.outer(x, k) + phi + d * np.pi / 2
    return np.sum(a * k.astype(float) ** d * np.cos(arg), axis=-1)


def scale(p) -> float:
    """``Σ|a|`` with derivative weights, a natural error scale."""
    return float(np.sum(np.abs(p.modes.amplitudes)))


# -- Modes ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, field", [
    (dict(wavenumbers=[2, 1], amplitudes=[1, 1], phases=[0, 0]), "Modes.wavenumbers"),
    (dict(wavenumbers=[0, 1], amplitudes=[1, 1], phases=[0, 0]), "Modes.wavenumbers"),
    (dict(wavenumbers=[1.5], amplitudes=[1], phases=[0]), "Modes.wavenumbers"),
    (dict(wavenumbers=[], amplitudes=[], phases=[]), "Modes.wavenumbers"),
    (dict(wavenumbers=[1, 2], amplitudes=[1], phases=[0, 0]), "Modes.amplitudes"),
    (dict(wavenumbers=[1, 2], amplitudes=[1, np.nan], phases=[0, 0]), "Modes.amplitudes"),
    (dict(wavenumbers=[1, 2], amplitudes=[1, 1], phases=[0]), "Modes.phases"),
])
def test_modes_validation_names_field(kwargs, field):
    with pytest.raises(ValidationError) as err:
        Modes(**kwargs)
    assert err.value.field == field
    assert field in str(err.value)


def test_modes_are_read_only_values():
    m = Modes(wavenumbers=[1, 3], amplitudes=[0.5, 0.1], phases=[0.0, 1.0])
    assert m == Modes(wavenumbers=[1, 3], amplitudes=[0.5, 0.1], phases=[0.0, 1.0])
    assert m != Modes(wavenumbers=[1, 3], amplitudes=[0.5, 0.2], phases=[0.0, 1.0])
    with pytest.raises(ValueError):
        m.amplitudes[0] = 2.0
    assert m.moment(2) == pytest.approx((0.25 + 9 * 0.01) / 2, rel=1e-15)


# -- evaluation ----------------------------------------------------------------------------------

@SETTINGS
@given(p=profiles(), x=st.lists(st.floats(-20.0, 20.0), min_size=1, max_size=20))
def test_heights_slopes_curvatures_match_naive_sum(p, x):
    x = np.array(x)
    tol = 1e-12 * scale(p)
    kmax = float(p.modes.wavenumbers[-1])
    np.testing.assert_allclose(p.heights(x), naive(p.modes, x), rtol=0, atol=tol)
    np.testing.assert_allclose(p.slopes(x), naive(p.modes, x, 1), rtol=0, atol=tol * kmax)
    np.testing.assert_allclose(p.curvatures(x), naive(p.modes, x, 2), rtol=0, atol=tol * kmax**2)


def test_sparse_and_high_wavenumbers_and_shapes():
    p = Series(k=(3, 100, 1001), a=(0.2, 0.01, 1e-3), phi=(0.5, -1.0, 2.0))
    x = np.linspace(-7, 7, 60).reshape(3, 4, 5)
    r = p.heights(x)
    assert r.shape == (3, 4, 5)
    np.testing.assert_allclose(r, naive(p.modes, x), rtol=0, atol=1e-14)
    assert np.ndim(p.heights(0.3)) == 0
    assert float(p.heights(0.3)) == pytest.approx(float(naive(p.modes, np.array(0.3))), abs=1e-15)


def test_long_evaluation_is_chunked_and_exact():
    p = SelfAffineProfile(hurst=0.7, scales=50, rms=0.05, seed=11)
    x = np.random.default_rng(0).uniform(0, TWO_PI, 100_000)
    r = p.heights(x)
    idx = np.arange(0, x.size, 997)
    np.testing.assert_allclose(r[idx], naive(p.modes, x[idx]), rtol=0, atol=1e-15)


@SETTINGS
@given(p=profiles(), x=st.floats(-10.0, 10.0))
def test_slopes_are_the_derivative_of_heights(p, x):
    kmax = float(p.modes.wavenumbers[-1])
    h = 1e-3 / kmax
    xs = x + h * np.array([-2.0, -1.0, 1.0, 2.0])
    w = np.array([1.0, -8.0, 8.0, -1.0]) / (12 * h)
    fd_slope = float(w @ p.heights(xs))
    fd_curv = float(w @ p.slopes(xs))
    assert fd_slope == pytest.approx(float(p.slopes(x)), abs=1e-8 * kmax * scale(p) + 1e-300)
    assert fd_curv == pytest.approx(float(p.curvatures(x)), abs=1e-8 * kmax**2 * scale(p) + 1e-300)


@SETTINGS
@given(p=profiles(), n=st.integers(1, 300), d=st.integers(0, 2))
def test_grid_values_equal_pointwise_values_including_aliasing(p, n, d):
    x = TWO_PI * np.arange(n) / n
    kmax = float(p.modes.wavenumbers[-1])
    np.testing.assert_allclose(p.grid_values(n, d), naive(p.modes, x, d), rtol=0,
                               atol=1e-12 * scale(p) * kmax**d)


# -- moments and statistics ---------------------------------------------------------------------

@SETTINGS
@given(p=profiles())
def test_exact_moments_agree_with_dense_samples(p):
    n = 4 * int(p.modes.wavenumbers[-1]) + 16
    r, s, c = p.grid_values(n), p.grid_values(n, 1), p.grid_values(n, 2)
    assert p.m0 == pytest.approx(np.mean(r**2), rel=1e-10)
    assert p.m2 == pytest.approx(np.mean(s**2), rel=1e-10)
    assert p.m4 == pytest.approx(np.mean(c**2), rel=1e-10)
    assert abs(np.mean(r)) <= 1e-13 * scale(p)


def test_statistics_match_dense_sampling():
    p = SelfAffineProfile(hurst=0.6, scales=40, rms=0.2, seed=5)
    st_ = p.statistics()
    x = np.linspace(0, TWO_PI, 1 << 18, endpoint=False)
    r = p.heights(x)
    sd = np.sqrt(np.mean(r**2))
    assert st_.rms == pytest.approx(0.2, rel=1e-12)
    assert st_.m0 == pytest.approx(sd**2, rel=1e-10)
    assert st_.m2 == pytest.approx(np.mean(p.slopes(x) ** 2), rel=1e-10)
    assert st_.skewness == pytest.approx(np.mean(r**3) / sd**3, rel=1e-9, abs=1e-12)
    assert st_.kurtosis == pytest.approx(np.mean(r**4) / sd**4, rel=1e-9)
    assert st_.ra == pytest.approx(np.mean(np.abs(r)), rel=1e-6)
    assert st_.amplitude == p.peak()[1]


# -- peak ----------------------------------------------------------------------------------------

@settings(max_examples=15, deadline=None)
@given(p=profiles())
def test_peak_is_the_true_maximum(p):
    xp, top = p.peak()
    assert 0.0 <= xp < TWO_PI
    assert float(p.heights(xp)) == pytest.approx(top, abs=1e-15 * scale(p))
    k = p.modes.wavenumbers.astype(float)
    a = np.abs(p.modes.amplitudes)
    assert abs(float(p.slopes(xp))) <= 1e-10 * float(np.sum(k * a))
    x = np.linspace(0, TWO_PI, 1_000_000, endpoint=False)
    sampled = float(p.grid_values(x.size).max())
    h = x[1]
    assert sampled <= top + 1e-14 * scale(p)
    # the sampled maximum is within the sampling error h²/8·max|r''| of the true one
    assert top - sampled <= h * h / 8 * float(np.sum(k * k * a)) + 1e-14 * scale(p)


def test_peak_picks_the_higher_of_two_nearly_equal_maxima():
    for eps, expected in ((1e-9, 0.0), (-1e-9, np.pi)):
        p = Series(k=(1, 2), a=(abs(eps), 1.0), phi=(0.0 if eps > 0 else np.pi, 0.0))
        xp, top = p.peak()
        assert xp == pytest.approx(expected, abs=1e-6)
        assert top == pytest.approx(1.0 + abs(eps), abs=1e-15)


def test_peak_of_a_long_self_affine_profile_is_exact_to_1e_12():
    p = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)
    xp, top = p.peak()
    x = np.linspace(xp - 1e-4, xp + 1e-4, 20001)
    assert top >= p.heights(x).max() - 1e-18
    assert abs(float(p.slopes(xp))) < 1e-14
    assert float(p.curvatures(xp)) < 0
    assert p.amplitude == top


def test_grid_values_rejects_bad_n():
    p = Series(k=(1,), a=(1.0,), phi=(0.0,))
    with pytest.raises(ValidationError, match="grid_values.n"):
        p.grid_values(0)


# ---- local maxima (where contacts are born) ----------------------------------------------------
@settings(max_examples=40, deadline=None)
@given(p=self_affine_profiles(max_scales=128))
@example(p=SelfAffineProfile(hurst=0.484375, scales=95, rms=1.0, seed=95, rolloff=31.5625))
def test_local_maxima_are_maxima_and_include_the_peak(p):
    """Every reported maximum has zero slope to sampling accuracy and negative curvature or a
    flat top; the global peak is among them; sorted in [0, 2π)."""
    from viscocontact.profiles.base import TWO_PI

    m = p.local_maxima()
    assert np.all(np.diff(m) > 0) and m[0] >= 0 and m[-1] < TWO_PI
    kmax = p.modes.wavenumbers[-1]
    n = 1 << max(13, int(np.ceil(np.log2(16 * kmax))))
    h = TWO_PI / n
    # within a sample of a true maximum: the exact slope falls from + to - somewhere in m ± h
    # (not necessarily across m ± h themselves: a shoulder can hold a minimum-maximum pair
    # closer than one sample, seen with seed 95)
    x = m[:, None] + h * np.linspace(-1.0, 1.0, 65)
    s = p.slopes(x)
    floor = 1e-12 * np.abs(s).max()
    assert np.all(np.any((s[:, :-1] > -floor) & (s[:, 1:] <= floor), axis=1))
    xp, lam = p.peak()
    d = np.abs(np.angle(np.exp(1j * (m - xp))))
    assert d.min() <= h
    # and no maximum is missed: every fall of the sampled slope from + to - has a reported
    # maximum within a sample (the counts themselves may differ by sub-sample shoulders)
    s = p.grid_values(n, derivative=1)
    falls = h * (np.flatnonzero((s > 0) & (np.roll(s, -1) <= 0)) + 0.5)
    gap = np.abs(np.angle(np.exp(1j * (falls[:, None] - m[None, :])))).min(axis=1)
    assert np.all(gap <= 1.5 * h)


@pytest.mark.parametrize("k", [1, 7, 128])
def test_local_maxima_of_a_cosine(k):
    from viscocontact.profiles import MeasuredProfile

    amp = np.zeros(k)
    amp[-1] = 1.0
    p = MeasuredProfile(amplitudes=amp, phases=np.zeros(k), length=1.0)
    np.testing.assert_allclose(p.local_maxima(), 2 * np.pi * np.arange(k) / k, atol=1e-12)


# ---- shortest wavelength (sizes the elements inside a contact) ------------------------------------
@SETTINGS
@given(k=st.lists(st.integers(1, 300), min_size=1, max_size=6, unique=True),
       zero_last=st.booleans())
def test_shortest_wavelength_is_that_of_the_highest_mode_with_amplitude(k, zero_last):
    """``2π/k_max`` over the modes with a non-zero amplitude: a trailing zero mode does not count,
    and the heights are unchanged by dropping it."""
    k = sorted(k)
    a = [1.0] * len(k)
    if zero_last and len(k) > 1:
        a[-1] = 0.0
    p = Series(k=tuple(k), a=tuple(a), phi=(0.3,) * len(k))
    m = len(k) - (a[-1] == 0.0)
    assert p.shortest_wavelength == pytest.approx(TWO_PI / k[m - 1], rel=1e-15)
    # the modes up to k_max reproduce the heights exactly
    kept = Series(k=tuple(k[:m]), a=tuple(a[:m]), phi=(0.3,) * m)
    x = np.linspace(0, TWO_PI, 64)
    np.testing.assert_allclose(p.heights(x), kept.heights(x), atol=1e-12)


def test_profiles_without_a_spectrum_do_not_report_a_wavelength():
    """The base class does not know the wavelengths of arbitrary heights: the solver then keeps
    the elements per contact as given."""
    from viscocontact.profiles.base import Profile

    class Bump(Profile):
        def heights(self, x):
            return np.exp(np.cos(x))

        def slopes(self, x):
            return -np.sin(x) * np.exp(np.cos(x))

    assert Bump().shortest_wavelength is None
