"""Persson's contact area for a 1D profile (thesis eqs. 3.34-3.45, derived for line roughness)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate, special

from viscocontact.profiles import PowerLawPSD, SelfAffineProfile, Sinusoid
from viscocontact.reference import westergaard_pressure
from viscocontact.testing.strategies_profiles import self_affine_profiles
from viscocontact.theories import LineSpectrum, PerssonContact

SETTINGS = settings(max_examples=25, deadline=None)
THESIS = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)


def test_full_contact_pressure_variance_is_e_star_squared_m2_over_4():
    # the variance V = E*² m2/4 behind Persson's diffusion, in p̃ units m2/Λ̃², checked on
    # Westergaard's sinusoid at the onset of full contact (p̃∞ = 1, p̃(x) = 1 + cos x)
    amp = 0.3
    x = np.linspace(-math.pi, math.pi, 4096, endpoint=False)
    s = math.sin(math.pi / 2)
    p = 2 * np.cos(x / 2) * np.sqrt(np.clip(s**2 - np.sin(x / 2) ** 2, 0, None))
    assert float(westergaard_pressure(2 * math.pi)) == pytest.approx(np.mean(p), rel=1e-12)
    spectrum = LineSpectrum.from_profile(Sinusoid(amplitude=amp))
    assert np.var(p) == pytest.approx(spectrum.moment(2) / amp**2, rel=1e-12)


@SETTINGS
@given(profile=self_affine_profiles(max_scales=64), p=st.floats(1e-4, 3.0))
def test_area_formula_and_its_isotropic_counterpart(profile, p):
    c = PerssonContact(spectrum=LineSpectrum.from_profile(profile))
    lam, m2 = profile.amplitude, profile.m2
    # A/A0 = erf(√2 p̄/(E*√m2)) with p̄/E* = p̃Λ̃/2
    assert float(c.area_fraction(p)) == pytest.approx(special.erf(math.sqrt(2) * (p * lam / 2)
                                                                  / math.sqrt(m2)), rel=1e-13)
    # eq. 3.45 (isotropic surface): the same with p̄ → p̄/√2
    assert float(c.area_fraction_isotropic(p)) == pytest.approx(float(c.area_fraction(p / math.sqrt(2))),
                                                                rel=1e-13)
    assert c.mean_pressure_at_area(float(c.area_fraction(p))) == pytest.approx(p, rel=1e-9)


@SETTINGS
@given(profile=self_affine_profiles(max_scales=64), p=st.floats(1e-6, 1e-3))
def test_area_is_linear_in_load_at_small_load(profile, p):
    c = PerssonContact(spectrum=LineSpectrum.from_profile(profile))
    x = p * profile.amplitude / math.sqrt(2 * profile.m2)           # erf argument
    ratio = float(c.area_fraction(p)) / (c.small_load_slope * p)
    # erf(x)/(2x/√π) = 1 - x²/3 + x⁴/10 - ...; κ = √(8/π) against p̄/(E*√m2)
    assert ratio == pytest.approx(1.0 - x * x / 3.0, abs=x**4 / 10 + 2e-15)   # + a few ulp of rounding
    assert c.small_load_slope * 2 * math.sqrt(profile.m2) / profile.amplitude == pytest.approx(
        math.sqrt(8 / math.pi), rel=1e-14)


@SETTINGS
@given(profile=self_affine_profiles(max_scales=64), p=st.floats(0.01, 2.0))
def test_pressure_distribution_carries_area_and_load(profile, p):
    c = PerssonContact(spectrum=LineSpectrum.from_profile(profile))
    sd = math.sqrt(profile.m2) / profile.amplitude
    hi = p + 12 * sd
    area = integrate.quad(lambda s: float(c.pressure_distribution(s, p)), 0, hi, epsabs=0,
                          epsrel=1e-11, limit=200)[0]
    load = integrate.quad(lambda s: s * float(c.pressure_distribution(s, p)), 0, hi, epsabs=0,
                          epsrel=1e-11, limit=200)[0]
    assert area == pytest.approx(float(c.area_fraction(p)), rel=1e-9)
    assert load == pytest.approx(p, rel=1e-9)      # the mean pressure is borne by the contact
    assert float(c.pressure_distribution(0.0, p)) == 0.0                  # eq. 3.42
    assert float(c.pressure_distribution(-0.1, p)) == 0.0


def test_pressure_distribution_solves_the_diffusion_equation():
    # ∂P/∂ζ = f ∂²P/∂σ² (eq. 3.34) with f = dV/(2dζ): in the variance V itself, ∂P/∂V = ½ ∂²P/∂σ²
    c = PerssonContact(spectrum=LineSpectrum.from_profile(THESIS))
    lam = THESIS.amplitude
    k = 20.0
    v1, v2 = c.slope_variance(k) / lam**2, c.slope_variance(k + 1) / lam**2
    sig = np.linspace(0.05, 1.5, 30)
    p = 0.4
    dp_dv = (c.pressure_distribution(sig, p, k + 1) - c.pressure_distribution(sig, p, k)) / (v2 - v1)
    vm = 0.5 * (v1 + v2)
    g = lambda s, v: (np.exp(-(s - p) ** 2 / (2 * v)) - np.exp(-(s + p) ** 2 / (2 * v))) / math.sqrt(  # noqa: E731
        2 * math.pi * v)
    h = 1e-4
    d2 = (g(sig + h, vm) - 2 * g(sig, vm) + g(sig - h, vm)) / h**2
    np.testing.assert_allclose(dp_dv, 0.5 * d2, rtol=2e-3, atol=2e-3 * np.max(np.abs(d2)))


def test_magnification():
    c = PerssonContact(spectrum=LineSpectrum.from_profile(THESIS))
    areas = [float(c.area_fraction(0.2, z)) for z in (1, 2, 5, 10, 20, 50)]
    assert all(b < a for a, b in zip(areas, areas[1:]))
    assert areas[-1] == float(c.area_fraction(0.2))
    assert float(c.area_fraction(0.2, 0.5 + 1)) == float(c.area_fraction(0.2, 1))


def test_continuous_psd_quadrature():
    psd = PowerLawPSD.normalised(hurst=0.8, scales=50, rms=0.01, rolloff=4.0)
    s = LineSpectrum.from_psd(psd, amplitude=0.03)
    assert s.moment(0) == pytest.approx(psd.moment(0), rel=1e-12)
    assert s.moment(2) == pytest.approx(psd.moment(2), rel=1e-12)
    s2 = LineSpectrum.from_psd(psd, amplitude=0.03, two_sided=True)
    assert s2.moment(2) == pytest.approx(psd.moment(2, two_sided=True), rel=1e-12)


def test_thesis_profile_numbers():
    # q0 r_rms = 0.01, H = 0.8, N_q = 50, seed 0: m2 = 7.705e-4 (docs/profiles.md)
    c = PerssonContact(spectrum=LineSpectrum.from_profile(THESIS))
    assert c.slope_variance() == pytest.approx(7.7049e-4, rel=1e-4)
    # Ã = 2π A/A0 at p̃∞ = 0.1 and the small-load slope
    assert 2 * math.pi * float(c.area_fraction(0.1)) == pytest.approx(
        2 * math.pi * special.erf(0.1 * THESIS.amplitude / math.sqrt(2 * THESIS.m2)), rel=1e-14)
