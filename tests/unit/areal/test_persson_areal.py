"""Persson's areal theory against limits derived independently of its formulas."""
from __future__ import annotations

import math

import numpy as np
import pytest

from viscocontact.areal.surfaces import ExtrudedProfile, SelfAffineSurface, sample_statistics
from viscocontact.errors import ValidationError
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.theories import LineSpectrum, PerssonContact, PerssonFriction
from viscocontact.theories.persson_areal import (ArealSpectrum, PerssonArealContact,
                                                 PerssonArealFriction)

SLS = StandardLinearSolid(beta=10.0)
ZETAS = np.logspace(-6, 6, 25)


def surface(**kw):
    return SelfAffineSurface(**(dict(hurst=0.8, scales=24, rms=0.01, seed=1) | kw))


def test_spectrum_moments_are_the_surfaces():
    s = surface(aspect=1.5, anisotropy=2.0, orientation=0.3)
    spec = ArealSpectrum.from_surface(s)
    st = sample_statistics(s, 64, 96)
    assert spec.m0 == pytest.approx(st.m0, rel=1e-12)
    assert spec.gradient_variance == pytest.approx(st.m2x + st.m2y, rel=1e-12)
    # a surface without modes: the periodogram of its samples, same moments
    from viscocontact.areal.surfaces import SphericalCapLattice

    cap = SphericalCapLattice(radius=3.0, height=1.0)
    sampled = ArealSpectrum.from_surface(cap, 64, 64)
    st = sample_statistics(cap, 64, 64)
    assert sampled.m0 == pytest.approx(st.m0, rel=1e-12)
    assert sampled.gradient_variance == pytest.approx(st.m2x + st.m2y, rel=1e-12)


def test_elastic_area_is_linear_in_load_with_perssons_coefficient():
    c = PerssonArealContact.from_surface(surface())
    g = math.sqrt(c.spectrum.gradient_variance)
    p = 1e-6 * g
    # erf(x) = 2x/√π (1 - x²/3 + ...): relative error x²/3 ~ 1e-12 here
    assert c.area_fraction(p) / p == pytest.approx(math.sqrt(8 / math.pi) / g, rel=1e-10)
    assert c.small_load_slope == pytest.approx(math.sqrt(8 / math.pi) / g, rel=1e-15)
    assert c.pressure_at_area(float(c.area_fraction(0.3 * g))) == pytest.approx(0.3 * g, rel=1e-12)
    assert c.area_fraction(10 * g) == pytest.approx(1.0, abs=1e-12)
    assert float(c.area_fraction(0.3 * g, magnification=0.5)) == 1.0   # no roughness resolved


def test_isotropic_area_is_eq_3_45_of_its_profiles():
    s = surface()
    st = sample_statistics(s, 64, 64)
    c = PerssonArealContact(spectrum=ArealSpectrum.from_surface(s))
    # eq. 3.45 as printed, erf(p̄/(E*√m2)) with m2 the mean square slope of a profile cut
    # along x: the 1D module's isotropic reading; p̃Λ̃/2 = p̄/E* with Λ̃ = 1
    line = PerssonContact(spectrum=LineSpectrum(wavenumbers=[1.0], weights=[st.m2x],
                                                amplitude=1.0))
    p = np.array([1e-4, 3e-3, 1e-2, 3e-2])
    assert np.allclose(c.area_fraction(p), line.area_fraction_isotropic(2 * p), rtol=1e-12,
                       atol=0)


@pytest.mark.parametrize("zeta", [1e-3, 1.0, 1e3])
def test_extruded_profile_reduces_to_the_1d_theory(zeta):
    prof = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)
    areal = PerssonArealFriction(spectrum=ArealSpectrum.from_surface(ExtrudedProfile(profile=prof)),
                                 rheology=SLS)
    line = PerssonFriction.from_profile(prof, SLS)
    pt = 0.1
    p = pt * prof.amplitude / 2                     # p̄/E* = p̃Λ̃/2
    assert areal.coefficient(zeta, p) == pytest.approx(float(line.coefficient(zeta, pt)),
                                                       rel=1e-12)
    assert areal.area_fraction(zeta, p) == pytest.approx(float(line.area_fraction(zeta, pt)),
                                                         rel=1e-12)


def test_sliding_along_ridges_has_no_friction():
    prof = SelfAffineProfile(hurst=0.8, scales=20, rms=0.01)
    f = PerssonArealFriction(spectrum=ArealSpectrum.from_surface(ExtrudedProfile(profile=prof)),
                             rheology=SLS, direction=math.pi / 2)
    # q̃_V = k cos(π/2) is ~6e-17 k, not 0: the friction is of that order
    assert np.all(np.abs(f.coefficient(ZETAS, 1e-3)) < 1e-14)


def test_friction_is_positive_and_vanishes_in_the_elastic_limits():
    f = PerssonArealFriction.from_surface(surface(), SLS)
    assert f == PerssonArealFriction(spectrum=ArealSpectrum.from_surface(surface()), rheology=SLS)
    mu = f.coefficient(ZETAS, 0.01)
    assert np.all(mu > 0)
    peak = mu.max()
    # SLS: E'' ∝ ωτ at small ζ and ∝ 1/(ωτ) at large ζ
    assert mu[0] < 1e-4 * peak and mu[-1] < 1e-4 * peak
    assert f.coefficient(ZETAS[:2], 0.01)[1] / mu[0] == pytest.approx(ZETAS[1] / ZETAS[0],
                                                                        rel=1e-3)
    elastic = PerssonArealFriction(spectrum=f.spectrum, rheology=Elastic())
    assert np.all(elastic.coefficient(ZETAS, 0.01) == 0.0)
    # a correction S = γ + (1-γ)P² <= 1 can only lower it
    corrected = PerssonArealFriction(spectrum=f.spectrum, rheology=SLS, contact_correction=0.5)
    assert np.all(corrected.coefficient(ZETAS, 0.01) <= mu)


def test_viscoelastic_area_tends_to_the_elastic_areas_of_e0_and_einf():
    spec = ArealSpectrum.from_surface(surface())
    f = PerssonArealFriction(spectrum=spec, rheology=SLS)
    c = PerssonArealContact(spectrum=spec)
    p = 0.004
    # |E(ω)|/E0 - 1 = O(ωτ) and E∞/|E| - 1 = O(1/(ωτ)): ζ = 1e-9, 1e9 leave ~1e-8·k_max
    assert f.area_fraction(1e-9, p) == pytest.approx(float(c.area_fraction(p)), rel=1e-6)
    # fast sliding: every mode that varies along the sliding direction sees E∞ = 10 E0; the
    # modes q̃_x = 0 (ridges along it) are not deformed in time and keep E0
    g2 = (spec.qx**2 + spec.qy**2) * spec.weights
    fast = float(np.sum(np.where(spec.qx != 0, 100.0, 1.0) * g2))
    assert f.area_fraction(1e9, p) == pytest.approx(math.erf(math.sqrt(2) * p / math.sqrt(fast)),
                                                    rel=1e-6)
    assert fast < 100 * spec.gradient_variance


@pytest.mark.parametrize("zeta", [0.03, 1.0, 30.0])
def test_full_contact_friction_is_the_power_fed_into_the_half_space(zeta):
    """The power fed into the half-space by a surface h(x - Vt) in full contact, on a grid.

    The solid's surface follows ``u = h(x - Vt)``: a mode ``exp(iq·x)`` oscillates as
    ``exp(-i q_x V t)``, at ``ω = -q_x V``, and needs the pressure ``|q|E(ω)/(2(1-ν²))`` times its
    amplitude. The power per unit area is ``<p ∂u/∂t> = -V<p ∂h/∂x>``, the friction stress times V.
    """
    s = surface(aspect=1.25, anisotropy=1.5, orientation=1.0)
    n = 64
    h = s.heights(n, 80)
    kx = np.fft.fftfreq(n, 1.0 / n)[None, :]
    ky = (np.fft.fftfreq(80, 1.0 / 80) / s.aspect)[:, None]
    omega = np.abs(kx) * zeta / SLS.reference_time
    e = SLS.complex_modulus(omega) / SLS.relaxed_modulus
    e = np.where(kx > 0, np.conj(e), e)                             # E(-q_x ζ)
    H = np.fft.fft2(h)
    pressure = np.fft.ifft2(0.5 * np.hypot(kx, ky) * e * H)        # in units of E*
    slope = np.fft.ifft2(1j * kx * H).real
    assert np.max(np.abs(pressure.imag)) < 1e-15
    power = -float(np.mean(pressure.real * slope))
    f = PerssonArealFriction(spectrum=ArealSpectrum.from_surface(s), rheology=SLS)
    assert power > 0
    assert float(f.full_contact_stress(zeta)) == pytest.approx(power, rel=1e-12)
    # and the coefficient tends to it at a pressure that closes the contact at every scale
    p = 100 * math.sqrt(f.spectrum.gradient_variance)               # erf(141) = 1
    assert float(f.coefficient(zeta, p)) * p == pytest.approx(power, rel=1e-12)


def test_lattice_spectrum_against_the_continuous_isotropic_one():
    kw = dict(hurst=0.8, scales=64, lowest=8.0, rms=0.01)
    lattice = PerssonArealFriction(spectrum=ArealSpectrum.from_surface(SelfAffineSurface(**kw)),
                                   rheology=SLS)
    smooth = PerssonArealFriction(spectrum=ArealSpectrum.isotropic_power_law(**kw), rheology=SLS)
    assert smooth.spectrum.m0 == pytest.approx(1e-4, rel=1e-12)
    z = np.logspace(-3, 3, 7)
    # the lattice's sums differ from the integrals by its spacing against the band: the strip
    # |q̃_x| < 1/2 that holds no mode is ~2.5 % of the band's mean |q̃_x| ≈ 20 (measured: 1-2.6 %)
    assert np.allclose(lattice.coefficient(z, 0.01), smooth.coefficient(z, 0.01), rtol=0.04)
    assert np.allclose(lattice.area_fraction(z, 0.01), smooth.area_fraction(z, 0.01), rtol=0.04)


def test_bad_input_names_the_argument():
    f = PerssonArealFriction(spectrum=ArealSpectrum.from_surface(surface()), rheology=SLS)
    with pytest.raises(ValidationError, match="pressure"):
        f.coefficient(1.0, 0.0)
    with pytest.raises(ValidationError, match="zeta"):
        f.coefficient(-1.0, 0.01)
    with pytest.raises(ValidationError, match="direction"):
        PerssonArealFriction(spectrum=f.spectrum, rheology=SLS, direction=7.0)
    with pytest.raises(ValidationError, match="ArealSpectrum.weights"):
        ArealSpectrum(qx=[1.0], qy=[0.0], weights=[-1.0])
    with pytest.raises(ValidationError, match="qx/qy"):
        ArealSpectrum(qx=[0.0], qy=[0.0], weights=[1.0])
    with pytest.raises(ValidationError, match="lowest"):
        ArealSpectrum.isotropic_power_law(hurst=0.8, scales=8, rms=0.01, lowest=9.0)


@pytest.mark.parametrize("rolloff", [None, 4.0])
def test_isotropic_power_law_quadrature_is_exact_for_the_moments(rolloff):
    h, n = 0.8, 50.0
    spec = ArealSpectrum.isotropic_power_law(hurst=h, scales=n, rms=0.01, rolloff=rolloff)
    kr = 1.0 if rolloff is None else rolloff
    b = 2 * (1 + h)

    def integral(p):                     # ∫ q^p C̃(q) 2πq dq on [1, N], C̃ ∝ max(q, kr)^-b
        flat = kr**-b * (kr ** (p + 2) - 1.0) / (p + 2)
        return flat + (n ** (p + 2 - b) - kr ** (p + 2 - b)) / (p + 2 - b)

    # Gauss-Legendre in u = log q: e^{su} is entire, 48 nodes over 1.7 decades reach rounding
    ratio = spec.gradient_variance / spec.m0
    assert ratio == pytest.approx(integral(2) / integral(0), rel=1e-12)
    # equally spaced directions: <q_x²> = <q_y²> = |q|²/2 exactly
    assert float(np.sum(spec.qx**2 * spec.weights)) == pytest.approx(spec.gradient_variance / 2,
                                                                     rel=1e-12)
