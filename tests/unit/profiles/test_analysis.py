"""power_spectrum normalisation and fit_hurst."""
from __future__ import annotations

import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact import ValidationError
from viscocontact.profiles import (MeasuredProfile, Profile, SelfAffineProfile, Sinusoid,
                                   fit_hurst, power_spectrum)
from viscocontact.testing.strategies_profiles import profiles

TWO_PI = 2 * np.pi
SETTINGS = settings(max_examples=50, deadline=None)


@attrs.frozen(kw_only=True)
class Triangle(Profile):
    """A non-spectral profile (only heights and slopes), to exercise the generic path."""

    def heights(self, x):
        x = np.mod(np.asarray(x, dtype=float), TWO_PI)
        return np.abs(x - np.pi) - np.pi / 2

    def slopes(self, x):
        x = np.mod(np.asarray(x, dtype=float), TWO_PI)
        return np.sign(x - np.pi)


@SETTINGS
@given(p=profiles())
def test_periodogram_of_a_spectral_profile_is_half_the_squared_amplitudes(p):
    spec = power_spectrum(p)
    k = p.modes.wavenumbers
    np.testing.assert_allclose(spec.psd[k - 1], p.modes.amplitudes**2 / 2, rtol=1e-9,
                               atol=1e-14 * p.m0)
    assert spec.moment(0) == pytest.approx(p.m0, rel=1e-12)
    assert spec.moment(2) == pytest.approx(p.m2, rel=1e-12)
    assert spec.moment(4) == pytest.approx(p.m4, rel=1e-12)


@SETTINGS
@given(n=st.integers(4, 200), seed=st.integers(0, 10_000))
def test_parseval_for_samples(n, seed):
    r = np.random.default_rng(seed).normal(size=n) + 3.0
    spec = power_spectrum(r)
    assert spec.wavenumbers.tolist() == list(range(1, n // 2 + 1))
    assert spec.moment(0) == pytest.approx(np.var(r), rel=1e-12)


def test_generic_profile_and_explicit_n():
    spec = power_spectrum(Triangle(), n=1024)
    r = Triangle().heights(TWO_PI * np.arange(1024) / 1024)
    assert spec.moment(0) == pytest.approx(np.var(r), rel=1e-12)
    # a triangle wave has only odd harmonics with P_k ∝ k^-4
    assert spec.psd[1] < 1e-20
    assert spec.psd[2] / spec.psd[0] == pytest.approx(3.0**-4, rel=1e-2)
    s = power_spectrum(Sinusoid(amplitude=0.4), n=16)
    np.testing.assert_allclose(s.psd, [0.08] + [0.0] * 7, atol=1e-17)


def test_validation():
    with pytest.raises(ValidationError, match="power_spectrum.n"):
        power_spectrum(np.ones(16), n=16)
    with pytest.raises(ValidationError, match="power_spectrum.n"):
        power_spectrum(Sinusoid(amplitude=1.0), n=2)
    with pytest.raises(ValidationError, match="power_spectrum.heights"):
        power_spectrum(np.array([1.0, np.nan, 2.0, 3.0]))
    with pytest.raises(ValidationError, match="power_spectrum.heights"):
        power_spectrum(np.ones(3))
    with pytest.raises(ValidationError, match="fit_hurst"):
        fit_hurst(Sinusoid(amplitude=1.0))
    with pytest.raises(ValidationError, match="fit_hurst"):
        fit_hurst(SelfAffineProfile(hurst=0.5, scales=100, rms=0.1), kmin=50, kmax=50.5)


@pytest.mark.parametrize("hurst", [0.3, 0.5, 0.8])
def test_fit_hurst_is_exact_for_deterministic_amplitudes(hurst):
    p = SelfAffineProfile(hurst=hurst, scales=300, rms=0.1, seed=2)
    assert fit_hurst(p) == pytest.approx(hurst, abs=1e-10)
    assert fit_hurst(p, kmin=10, kmax=100) == pytest.approx(hurst, abs=1e-10)


@pytest.mark.parametrize("hurst, seed", [(0.3, 0), (0.5, 1), (0.8, 2), (0.95, 3)])
def test_fit_hurst_of_a_random_amplitude_measured_profile(hurst, seed):
    # Gaussian Fourier coefficients (Rayleigh amplitudes): the periodogram scatters by ~5.6 dB
    rng = np.random.default_rng(seed)
    k = np.arange(1, 2001)
    c = (rng.normal(size=k.size) + 1j * rng.normal(size=k.size)) * k ** -(hurst + 0.5)
    p = MeasuredProfile(amplitudes=np.abs(c), phases=np.angle(c), length=1e-2)
    assert fit_hurst(p) == pytest.approx(hurst, abs=0.05)
    # samples work as well as the profile
    assert fit_hurst(p.grid_values(8192)) == pytest.approx(fit_hurst(p), abs=1e-8)
