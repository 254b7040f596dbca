"""Persson's mean-field viscoelastic friction for a 1D profile."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.testing.strategies_rheology import standard_linear_solids
from viscocontact.theories import LineSpectrum, PerssonContact, PerssonFriction

SETTINGS = settings(max_examples=25, deadline=None)
PROFILE = SelfAffineProfile(hurst=0.8, scales=20, rms=0.01, seed=1)
SPECTRUM = LineSpectrum.from_profile(PROFILE)


@SETTINGS
@given(rheology=standard_linear_solids(max_beta=1e3), p=st.floats(0.01, 5.0))
def test_friction_vanishes_in_both_elastic_limits_and_is_positive_between(rheology, p):
    f = PerssonFriction(spectrum=SPECTRUM, rheology=rheology)
    mid = np.logspace(-3, 1, 9)           # ζ around the loss peaks (kζ ~ 1..β for k = 1..20)
    mu = f.coefficient(mid, p)
    assert np.all(mu > 0)
    peak = float(np.max(mu))
    # E(kζ) → E0 (ζ → 0) and E∞ (ζ → ∞), both real
    assert float(f.coefficient(1e-14, p)) < 1e-8 * peak
    assert float(f.coefficient(1e16, p)) < 1e-8 * peak


@SETTINGS
@given(rheology=standard_linear_solids(max_beta=1e3), zeta=st.floats(-3.0, 3.0).map(lambda e: 10.0**e))
def test_friction_falls_and_area_grows_with_load(rheology, zeta):
    f = PerssonFriction(spectrum=SPECTRUM, rheology=rheology)
    p = np.array([0.01, 0.1, 0.5, 2.0, 10.0])
    mu = np.array([float(f.coefficient(zeta, q)) for q in p])
    area = np.array([float(f.area_fraction(zeta, q)) for q in p])
    assert np.all(np.diff(mu) < 0)
    assert np.all(np.diff(area) > 0) or np.all(area == 1.0)


def test_area_shrinks_as_the_solid_stiffens():
    f = PerssonFriction(spectrum=SPECTRUM, rheology=StandardLinearSolid(beta=10.0))
    zeta = np.logspace(-4, 4, 17)
    area = f.area_fraction(zeta, 0.2)
    assert np.all(np.diff(area) < 0)
    # elastic limits: Persson's elastic area with E0 (ζ → 0) and with E∞ = βE0 (p̃ → p̃/β)
    c = PerssonContact(spectrum=SPECTRUM)
    assert float(f.area_fraction(1e-12, 0.2)) == pytest.approx(float(c.area_fraction(0.2)), rel=1e-9)
    assert float(f.area_fraction(1e14, 0.2)) == pytest.approx(float(c.area_fraction(0.02)), rel=1e-9)


def test_elastic_solid_has_no_friction():
    f = PerssonFriction(spectrum=SPECTRUM, rheology=Elastic(modulus=3.0))
    assert np.all(f.coefficient(np.logspace(-3, 3, 7), 0.3) == 0.0)
    np.testing.assert_allclose(f.area_fraction(1.0, 0.3),
                               PerssonContact(spectrum=SPECTRUM).area_fraction(0.3), rtol=1e-14)


@pytest.mark.parametrize("zeta", [0.01, 0.3, 5.0])
def test_full_contact_friction_equals_the_exact_one_from_the_kernel(zeta):
    # In full contact the stress follows from the package's own kernel multiplier
    # (û_m = -(K(m)/m) σ̂_m, half-plane) and μ = -<p u'>/p∞; Persson's P(k) = 1 there.
    rheology = StandardLinearSolid(beta=10.0, tau=2.0, modulus=3.0)
    f = PerssonFriction(spectrum=SPECTRUM, rheology=rheology)
    lam = PROFILE.amplitude
    p_mean = 200.0
    assert float(f.area_fraction(zeta, p_mean)) == 1.0
    modes = PROFILE.modes
    m = modes.wavenumbers.astype(float)
    mult = HalfPlane().prepare(rheology, zeta).multiplier(m)
    x = 2 * np.pi * np.arange(2048) / 2048
    c = modes.coefficients / lam                                   # ũ = r/Λ (+ const)
    phase = np.exp(1j * np.multiply.outer(x, m))
    sigma = np.real(phase @ (-m * c / mult))
    du = np.real(phase @ (1j * m * c))
    exact = -np.mean((p_mean - sigma) * du) * lam / p_mean
    assert float(f.coefficient(zeta, p_mean)) == pytest.approx(exact, rel=1e-12)


def test_sinusoid_full_contact_closed_form_and_reduced_coefficient():
    # one mode: μ = Λ̃ Im(E(ζ)/E0)/(2p̃) in full contact (Hunter/Menga); eq. 4.59 divides by √m2
    amp, p, zeta = 0.05, 50.0, 1.0
    sls = StandardLinearSolid(beta=10.0)
    f = PerssonFriction(spectrum=LineSpectrum.from_profile(Sinusoid(amplitude=amp)), rheology=sls)
    e = complex(sls.complex_modulus(zeta))
    assert float(f.coefficient(zeta, p)) == pytest.approx(amp * e.imag / (2 * p), rel=1e-12)
    assert float(f.reduced_coefficient(zeta, p)) == pytest.approx(
        float(f.coefficient(zeta, p)) / (amp / math.sqrt(2)), rel=1e-14)


def test_contact_correction():
    sls = StandardLinearSolid(beta=10.0)
    plain = PerssonFriction(spectrum=SPECTRUM, rheology=sls)
    one = PerssonFriction(spectrum=SPECTRUM, rheology=sls, contact_correction=1.0)
    half = PerssonFriction(spectrum=SPECTRUM, rheology=sls, contact_correction=0.5)
    assert float(one.coefficient(1.0, 0.1)) == float(plain.coefficient(1.0, 0.1))
    # S = γ + (1-γ)P² < 1 in partial contact
    assert float(half.coefficient(1.0, 0.1)) < float(plain.coefficient(1.0, 0.1))
