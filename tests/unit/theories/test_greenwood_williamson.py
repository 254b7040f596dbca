"""Greenwood-Williamson (thesis eqs. 3.20-3.27) and Fuller-Tabor (eq. 3.28)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

from viscocontact.theories import (FullerTabor, GreenwoodWilliamson, HertzSphere, JKRSphere,
                                   RoughnessMoments, gaussian_tail_moment)
from viscocontact.theories.greenwood_williamson import gw_integral

SETTINGS = settings(max_examples=15, deadline=None)
MOMENTS = RoughnessMoments(m0=1e-4, m2=7.7e-4, m4=5.0e-2, amplitude=0.02)   # α ≈ 8.4


@pytest.mark.parametrize("n", [0.0, 1.0, 1.5])
@pytest.mark.parametrize("h", [-45.0, -31.0, -10.0, -1.0, 0.0, 2.0, 8.0, 30.0])
def test_gaussian_tail_moment_against_quadrature(n, h):
    ref = integrate.quad(lambda w: w**n * math.exp(-(w + h) ** 2 / 2), max(0.0, -h - 40), -h + 60
                         if h < 0 else 60, epsabs=0, epsrel=1e-13, limit=400)[0]
    assert gaussian_tail_moment(n, h) == pytest.approx(ref, rel=1e-11)


def test_literature_values_of_the_gw_integrals():
    # F_0 = Gaussian tail, F_1(h) = φ(h) - h Q(h), F_{3/2}(0) = 2^(1/4) Γ(5/4)/√(2π) = 0.42996
    assert gw_integral(0.0, 1.0) == pytest.approx(0.15865525393145707, rel=1e-14)
    assert gw_integral(1.0, 0.0) == pytest.approx(1.0 / math.sqrt(2 * math.pi), rel=1e-14)
    assert gw_integral(1.5, 0.0) == pytest.approx(2**0.25 * math.gamma(1.25) / math.sqrt(2 * math.pi),
                                                  rel=1e-13)


@SETTINGS
@given(d=st.floats(-2.0, 4.0))
def test_gw_is_the_sum_of_hertz_contacts_eqs_3_21_to_3_24(d):
    gw = GreenwoodWilliamson.from_moments(MOMENTS)
    h = HertzSphere(radius=gw.summit_radius, reduced_modulus=1.0)
    sig = gw.summit_std
    phi = lambda z: math.exp(-0.5 * (z / sig) ** 2) / (sig * math.sqrt(2 * math.pi))  # noqa: E731
    lo = d * sig
    area = integrate.quad(lambda z: math.pi * gw.summit_radius * (z - lo) * phi(z), lo, 12 * sig,
                          epsabs=0, epsrel=1e-12)[0] * gw.summit_density
    load = integrate.quad(lambda z: float(h.load_at_penetration(z - lo)) * phi(z), lo, 12 * sig,
                          epsabs=0, epsrel=1e-12)[0] * gw.summit_density
    assert float(gw.area_fraction(d)) == pytest.approx(area, rel=1e-9)
    assert float(gw.pressure_over_modulus(d)) == pytest.approx(load, rel=1e-9)
    assert float(gw.mean_pressure(d)) == pytest.approx(2 * load / MOMENTS.amplitude, rel=1e-9)


def test_parameters_from_moments_and_archard():
    gw = GreenwoodWilliamson.from_moments(MOMENTS)
    a = MOMENTS.alpha
    assert gw.summit_density == pytest.approx(MOMENTS.m4 / (6 * math.pi * math.sqrt(3) * MOMENTS.m2))
    assert gw.summit_radius == pytest.approx(3 * math.sqrt(math.pi) / (8 * math.sqrt(MOMENTS.m4)))
    # Archard's product σ_s R D_s (eq. 3.27) = √(α - 0.8968)/(16√(3π)), here in 0.03-0.05 for α 3-7
    product = gw.summit_std * gw.summit_radius * gw.summit_density
    assert product == pytest.approx(math.sqrt(a - 0.896805756) / (16 * math.sqrt(3 * math.pi)), rel=1e-9)
    # Archard's empirical 0.03-0.05 is α between about 3.1 and 6.9
    for alpha in (3.1, 6.9):
        g = GreenwoodWilliamson.from_moments(RoughnessMoments(m0=1.0, m2=1.0, m4=alpha))
        assert 0.03 < g.summit_std * g.summit_radius * g.summit_density < 0.05


def test_area_to_load_ratio_at_small_load():
    # A/P = (3π/(4E*))√(R/σ_s) F1/F_{3/2}, and F1/F_{3/2} = (4/(3√π))√d*(1 + 11/(8d*²) + O(d*^-4)):
    # GW's area is proportional to load only up to √d* (the known asymptote A/P → √(πRd*/σ_s)/E*)
    gw = GreenwoodWilliamson.from_moments(MOMENTS)
    for d in (10.0, 20.0, 30.0):
        ratio = float(gw.area_fraction(d) / gw.pressure_over_modulus(d))
        asym = math.sqrt(math.pi * gw.summit_radius * d / gw.summit_std)
        assert (ratio / asym - 1.0) * d * d == pytest.approx(11.0 / 8.0, abs=20.0 / d**2)
    # and the contact spots: N/A0 = D_s F_0
    assert float(gw.contact_density(0.0)) == pytest.approx(gw.summit_density / 2, rel=1e-14)


def test_fuller_tabor_without_adhesion_is_gw():
    gw = GreenwoodWilliamson.from_moments(MOMENTS)
    ft = FullerTabor.from_moments(MOMENTS, gamma=0.0)
    d = np.array([-2.0, 0.0, 1.0, 3.0, 5.0])
    for unloading in (False, True):
        np.testing.assert_allclose(ft.area_fraction(d, unloading), gw.area_fraction(d), rtol=1e-10)
        np.testing.assert_allclose(ft.pressure_over_modulus(d, unloading),
                                   gw.pressure_over_modulus(d), rtol=1e-10)
    assert ft.critical_neck == 0.0 and ft.adhesion_parameter == math.inf


def test_fuller_tabor_tends_to_gw_as_adhesion_vanishes():
    gw = GreenwoodWilliamson.from_moments(MOMENTS)
    errs = []
    for gamma in (1e-6, 1e-8, 1e-10):
        ft = FullerTabor.from_moments(MOMENTS, gamma=gamma)
        errs.append(abs(float(ft.pressure_over_modulus(1.0)) / float(gw.pressure_over_modulus(1.0)) - 1))
    # the relative difference falls linearly with γ̃ (measured 3.1e-2, 2.9e-4, 2.9e-6)
    assert errs[1] / errs[0] == pytest.approx(0.01, rel=0.1)
    assert errs[2] / errs[1] == pytest.approx(0.01, rel=0.05)


@SETTINGS
@given(gamma=st.floats(-6.0, -1.0).map(lambda e: 10.0**e), d=st.floats(-1.5, 4.0))
def test_fuller_tabor_hysteresis(gamma, d):
    ft = FullerTabor.from_moments(MOMENTS, gamma=gamma)
    # on unloading summits stay attached down to d - δ_c: more area, less (more tensile) load
    assert ft.area_fraction(d, True) >= ft.area_fraction(d, False)
    assert ft.pressure_over_modulus(d, True) <= ft.pressure_over_modulus(d, False) + 1e-15
    # eq. 3.28 is the displacement-controlled JKR neck of eq. 1.47
    j = JKRSphere(radius=ft.summit_radius, reduced_modulus=1.0, work_of_adhesion=math.pi * gamma)
    assert ft.critical_neck == pytest.approx(
        (27 * math.pi**2 * (math.pi * gamma) ** 2 * ft.summit_radius / 64) ** (1 / 3), rel=1e-13)
    assert -ft.critical_neck == j.pull_off_displacement_control().penetration


def test_fuller_tabor_pull_off_grows_with_adhesion():
    m = RoughnessMoments(m0=1.0, m2=1.0, m4=10.0, amplitude=3.0)
    pulls = [FullerTabor.from_moments(m, gamma=g).pull_off()[1] for g in (0.01, 0.03, 0.1, 0.3)]
    assert all(b < a for a, b in zip(pulls, pulls[1:]))
    assert pulls[-1] < 0
    ft = FullerTabor.from_moments(m, gamma=0.1)
    d, p = ft.pull_off()
    assert float(ft.pressure_over_modulus(d, True)) == pytest.approx(p, rel=1e-12)
    assert float(ft.pressure_over_modulus(d - 0.2, True)) > p < float(ft.pressure_over_modulus(d + 0.2, True))


def test_fuller_tabor_on_the_thesis_profile_has_no_pull_off():
    # §4.6: γ̃ = 2.387e-7 on the H = 0.8, N_q = 50, q0 r_rms = 0.01 profile: θ ≈ 1280, and the
    # unloading load never turns tensile (roughness masks adhesion in the elastic 3D theory);
    # with γ̃ = 1e-4 (θ ≈ 3) it does
    from viscocontact.profiles import SelfAffineProfile

    moments = RoughnessMoments.from_profile(SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0))
    weak = FullerTabor.from_moments(moments, gamma=2.387e-7)
    assert weak.adhesion_parameter == pytest.approx(1280.3, rel=1e-4)
    assert weak.pull_off() == (math.inf, 0.0)
    strong = FullerTabor.from_moments(moments, gamma=1e-4)
    assert strong.adhesion_parameter == pytest.approx(3.056, rel=1e-3)
    assert strong.pull_off()[1] < 0
