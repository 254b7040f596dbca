"""Hertz sphere and cylinder (thesis eqs. 1.4, 1.7-1.15, 3.24)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

from viscocontact.theories import (HertzCylinder, HertzSphere, combined_radius, reduced_modulus,
                                   westergaard_pressure)

SETTINGS = settings(max_examples=40, deadline=None)
logs = st.floats(-3.0, 3.0).map(lambda e: 10.0**e)


@SETTINGS
@given(radius=logs, modulus=logs, load=logs)
def test_load_and_radius_are_inverse_and_match_eq_3_24(radius, modulus, load):
    h = HertzSphere(radius=radius, reduced_modulus=modulus)
    a = h.contact_radius(load)
    assert h.load(a) == pytest.approx(load, rel=1e-13)
    # P = (4/3) E* √R δ^{3/2} with δ = a²/R (eq. 3.24 against eq. 1.15)
    assert h.load_at_penetration(h.penetration(a)) == pytest.approx(load, rel=1e-13)
    # p0 = 1.5 times the mean pressure P/(πa²) (text after eq. 1.8)
    assert h.max_pressure(a) == pytest.approx(1.5 * load / (math.pi * a * a), rel=1e-13)


@SETTINGS
@given(radius=logs, modulus=logs, a=logs)
def test_pressure_integrates_to_the_load_eq_1_14(radius, modulus, a):
    h = HertzSphere(radius=radius, reduced_modulus=modulus)
    total = integrate.quad(lambda r: 2 * math.pi * r * h.pressure(r, a), 0, a,
                           epsabs=0, epsrel=1e-12)[0]
    assert total == pytest.approx(float(h.load(a)), rel=1e-10)


@SETTINGS
@given(radius=logs, modulus=logs, a=logs, frac=st.floats(0.0, 1.0))
def test_displacement_mates_the_sphere_inside_the_contact_eq_1_5(radius, modulus, a, frac):
    h = HertzSphere(radius=radius, reduced_modulus=modulus)
    r = frac * a
    # u(r) = δ - h(r) with h = r²/(2R) (eqs. 1.3, 1.5, 1.12)
    assert h.displacement(r, a) == pytest.approx(h.penetration(a) - r * r / (2 * radius),
                                                 rel=1e-12, abs=1e-14 * h.penetration(a))


def test_reduced_modulus_and_combined_radius():
    assert reduced_modulus(10e6, 0.5) == pytest.approx(10e6 / 0.75, rel=1e-15)
    assert reduced_modulus(1.0, 0.3, 2.0, 0.2) == pytest.approx(reduced_modulus(2.0, 0.2, 1.0, 0.3))
    assert reduced_modulus(1.0, 0.0, 1.0, 0.0) == pytest.approx(0.5)
    assert combined_radius(2.0) == 2.0
    assert combined_radius(2.0, 2.0) == pytest.approx(1.0)


@SETTINGS
@given(radius=logs, modulus=logs, load=logs)
def test_cylinder_load_width_pressure(radius, modulus, load):
    c = HertzCylinder(radius=radius, reduced_modulus=modulus)
    a = c.half_width(load)
    assert c.load(a) == pytest.approx(load, rel=1e-13)
    total = integrate.quad(lambda x: c.pressure(x, a), -a, a, epsabs=0, epsrel=1e-12)[0]
    assert total == pytest.approx(load, rel=1e-10)
    assert c.max_pressure(a) == pytest.approx(2 * load / (math.pi * a), rel=1e-13)


@pytest.mark.parametrize("area", [1e-1, 1e-2, 1e-3])
def test_cylinder_is_the_small_contact_limit_of_westergaard(area):
    # Λ̃ cos x̃ has crest radius 1/Λ̃ (q0 units); p̃∞ = 2P'/(λ0 E* Λ̃) with λ0 = 2π; E* = 1.
    amp = 0.37
    c = HertzCylinder(radius=1.0 / amp, reduced_modulus=1.0)
    p_hertz = 2.0 * float(c.load(area / 2.0)) / (2 * math.pi * amp)
    p_west = float(westergaard_pressure(area))
    # sin²(Ã/4) = (Ã/4)²(1 - Ã²/48 + ...): the relative difference is Ã²/48 to leading order
    assert (p_hertz / p_west - 1.0) / (area**2 / 48.0) == pytest.approx(1.0, abs=area**2 / 10)
