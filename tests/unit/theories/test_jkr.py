"""JKR sphere and cylinder (thesis eqs. 1.39-1.47) and its limits."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate
from scipy.optimize import minimize_scalar

from viscocontact.theories import JKRCylinder, JKRSphere, johnson_pull_off_load
from viscocontact.theories.jkr import largest_quartic_root

SETTINGS = settings(max_examples=40, deadline=None)
logs = st.floats(-2.0, 2.0).map(lambda e: 10.0**e)
adhesion = st.floats(-6.0, -1.0).map(lambda e: 10.0**e)


def _sphere(radius, modulus, ratio):
    """A sphere whose Δγ/(E*R) is ``ratio``."""
    return JKRSphere(radius=radius, reduced_modulus=modulus, work_of_adhesion=ratio * modulus * radius)


@SETTINGS
@given(radius=logs, modulus=logs, ratio=adhesion)
def test_load_controlled_pull_off_is_the_minimum_load_eq_1_46(radius, modulus, ratio):
    j = _sphere(radius, modulus, ratio)
    po = j.pull_off_load_control()
    assert po.load == pytest.approx(-1.5 * math.pi * j.work_of_adhesion * radius, rel=1e-14)
    res = minimize_scalar(lambda a: float(j.load(a)), bounds=(1e-6 * po.contact_radius,
                          10 * po.contact_radius), method="bounded", options={"xatol": 1e-12 * radius})
    assert res.fun == pytest.approx(po.load, rel=1e-10)
    assert res.x == pytest.approx(po.contact_radius, rel=1e-4)    # flat minimum: a to √(1e-10)
    assert float(j.penetration(po.contact_radius)) == pytest.approx(po.penetration, rel=1e-12)
    assert float(j.contact_radius(po.load)) == pytest.approx(po.contact_radius, rel=1e-7)


@SETTINGS
@given(radius=logs, modulus=logs, ratio=adhesion)
def test_displacement_controlled_pull_off_is_the_minimum_penetration_eq_1_47(radius, modulus, ratio):
    j = _sphere(radius, modulus, ratio)
    po = j.pull_off_displacement_control()
    assert po.load == pytest.approx(-5.0 / 6.0 * math.pi * j.work_of_adhesion * radius, rel=1e-14)
    res = minimize_scalar(lambda a: float(j.penetration(a)), bounds=(1e-6 * po.contact_radius,
                          10 * po.contact_radius), method="bounded", options={"xatol": 1e-12 * radius})
    assert res.fun == pytest.approx(po.penetration, rel=1e-10)
    assert float(j.load(po.contact_radius)) == pytest.approx(po.load, rel=1e-12)
    assert float(j.penetration_derivative(po.contact_radius)) == pytest.approx(
        0.0, abs=1e-12 * abs(po.penetration) / po.contact_radius)


@SETTINGS
@given(radius=logs, modulus=logs, ratio=adhesion, x=st.floats(0.2, 20.0))
def test_griffith_balance_on_the_equilibrium_curve(radius, modulus, ratio, x):
    j = _sphere(radius, modulus, ratio)
    a = x * j.pull_off_load_control().contact_radius
    d = float(j.penetration(a))
    g = j.work_of_adhesion
    assert j.energy_release_rate(a, d) == pytest.approx(g, rel=1e-9)           # G = Δγ (1.35)
    assert j.stress_intensity(a) ** 2 / (2 * modulus) == pytest.approx(g, rel=1e-12)
    # P = ∂U_el/∂δ|_a: U_el is quadratic in δ, so the central difference is exact
    h = 1e-3 * (abs(d) + a * a / radius)
    du = (j.elastic_energy(a, d + h) - j.elastic_energy(a, d - h)) / (2 * h)
    assert du == pytest.approx(float(j.load(a)), rel=1e-8, abs=1e-8 * modulus * a * a * a / radius)
    # ∂U_el/∂a|_δ = 2πaΔγ (eq. 1.43 with U_S = -πa²Δγ)
    ha = 1e-5 * a
    dua = (j.elastic_energy(a + ha, d) - j.elastic_energy(a - ha, d)) / (2 * ha)
    assert dua == pytest.approx(2 * math.pi * a * g, rel=1e-6)


@SETTINGS
@given(radius=logs, modulus=logs, ratio=adhesion, x=st.floats(0.2, 20.0))
def test_pressure_integrates_to_the_load_eq_1_11(radius, modulus, ratio, x):
    j = _sphere(radius, modulus, ratio)
    a = x * j.pull_off_load_control().contact_radius
    # r = a sin θ removes the edge singularity of the flat-punch term
    total = integrate.quad(lambda th: 2 * math.pi * a * math.sin(th) * float(
        j.pressure(a * math.sin(th), a)) * a * math.cos(th), 0, math.pi / 2, epsabs=0,
        epsrel=1e-11)[0]
    scale = 4 * modulus * a**3 / (3 * radius)
    assert total == pytest.approx(float(j.load(a)), rel=1e-9, abs=1e-9 * scale)
    assert float(j.edge_coefficient(a)) == pytest.approx(
        modulus / math.pi * (float(j.penetration(a)) / a - a / radius), rel=1e-10)   # eq. 1.39


@SETTINGS
@given(radius=logs, modulus=logs, ratio=adhesion, x=st.floats(0.01, 30.0))
def test_stable_branches_invert_load_and_penetration(radius, modulus, ratio, x):
    j = _sphere(radius, modulus, ratio)
    pl = j.pull_off_load_control()
    p = pl.load + x * abs(pl.load)
    a = float(j.contact_radius(p))
    assert float(j.load(a)) == pytest.approx(p, rel=1e-9, abs=1e-10 * abs(pl.load))
    assert a >= pl.contact_radius * (1 - 1e-9)
    pd = j.pull_off_displacement_control()
    d = pd.penetration + x * abs(pd.penetration)
    a = float(j.contact_radius_at_penetration(d))
    assert float(j.penetration(a)) == pytest.approx(d, rel=1e-9, abs=1e-10 * abs(pd.penetration))
    assert a >= pd.contact_radius * (1 - 1e-7)


@pytest.mark.parametrize("radius,modulus", [(1.0, 1.0), (1e-3, 1e7), (0.1, 1e6 / 0.75)])
def test_jkr_tends_to_hertz_as_adhesion_vanishes(radius, modulus):
    load = modulus * radius**2 * 1e-3
    hertz = JKRSphere(radius=radius, reduced_modulus=modulus, work_of_adhesion=0.0)
    a_h = float(hertz.hertz.contact_radius(load))
    assert float(hertz.contact_radius(load)) == pytest.approx(a_h, rel=1e-15)
    assert float(hertz.contact_radius_at_penetration(a_h * a_h / radius)) == pytest.approx(a_h, rel=1e-14)
    # a³_JKR/a³_H - 1 = √(6πΔγR/P) + 3πΔγR/P + ...: the leading coefficient is recovered
    for ratio in (1e-8, 1e-10, 1e-12):
        j = _sphere(radius, modulus, ratio)
        eps = math.sqrt(6 * math.pi * j.work_of_adhesion * radius / load)
        rel = (float(j.contact_radius(load)) / a_h) ** 3 - 1.0
        assert rel / eps == pytest.approx(1.0, abs=2 * eps)


@pytest.mark.parametrize("ratio", [1e-6, 1e-3, 1e-1])
def test_inverses_at_the_pull_off_points(ratio):
    # at pull-off the stable and unstable branches meet in a double root, which floating point
    # resolves to about √ε relative
    j = _sphere(0.3, 2.0, ratio)
    pl, pd = j.pull_off_load_control(), j.pull_off_displacement_control()
    assert float(j.contact_radius(pl.load)) == pytest.approx(pl.contact_radius, rel=1e-7)
    assert float(j.contact_radius_at_penetration(pd.penetration)) == pytest.approx(
        pd.contact_radius, rel=1e-7)
    c = JKRCylinder(radius=0.3, reduced_modulus=2.0, work_of_adhesion=ratio * 0.6)
    pc = c.pull_off_load_control()
    assert float(c.half_width(pc.load)) == pytest.approx(pc.contact_radius, rel=1e-6)


def test_quartic_root():
    s = largest_quartic_root([0.0, 1.0, 2.0], [16.0, 0.0, -1.0])
    np.testing.assert_allclose(s**4 - np.array([0.0, 1.0, 2.0]) * s - [16.0, 0.0, -1.0], 0.0,
                               atol=1e-14)
    np.testing.assert_allclose(s[:2], [2.0, 1.0], rtol=1e-15)
    assert np.isnan(largest_quartic_root(4.0, -3.1))      # minimum of s⁴ - 4s is -3


@SETTINGS
@given(radius=logs, modulus=logs, ratio=adhesion, x=st.floats(0.01, 30.0))
def test_cylinder_pull_off_and_inverse(radius, modulus, ratio, x):
    c = JKRCylinder(radius=radius, reduced_modulus=modulus, work_of_adhesion=ratio * modulus * radius)
    po = c.pull_off_load_control()
    res = minimize_scalar(lambda a: float(c.load(a)), bounds=(1e-6 * po.contact_radius,
                          10 * po.contact_radius), method="bounded", options={"xatol": 1e-12 * radius})
    assert res.fun == pytest.approx(po.load, rel=1e-10)
    p = po.load + x * abs(po.load)
    a = float(c.half_width(p))
    assert float(c.load(a)) == pytest.approx(p, rel=1e-9, abs=1e-10 * abs(po.load))
    assert a >= po.contact_radius * (1 - 1e-7)


def test_cylinder_is_the_small_contact_limit_of_johnson():
    # Johnson's load-controlled pull-off tends to the JKR line contact's -(3/4)(4Γ̃²)^(1/3), with a
    # relative correction ã²/12, ã = (2Γ̃)^(1/3) the half-width at pull-off (measured: 0.083339 at
    # Γ̃ = 1e-6, 0.0833334 at 1e-10).
    for gamma in (1e-6, 1e-8, 1e-10):
        area, p_off, _ = johnson_pull_off_load(gamma)
        # the same number from JKRCylinder with R = 1/(q0Λ̃), Δγ/E* = πγ̃/q0, p̃ = 2P'/(λ0E*Λ̃)
        amp = 0.05
        c = JKRCylinder(radius=1.0 / amp, reduced_modulus=1.0,
                        work_of_adhesion=math.pi * gamma * amp**2)
        ref = 2.0 * c.pull_off_load_control().load / (2 * math.pi * amp)
        assert ref == pytest.approx(-0.75 * (4 * gamma**2) ** (1 / 3), rel=1e-13)
        a_half = (2 * gamma) ** (1 / 3)
        assert (p_off / ref - 1.0) / a_half**2 == pytest.approx(1.0 / 12.0, rel=2e-3)
    # the half-width too, with an O(ã²) relative correction (measured ã²/4 at Γ̃ = 1e-6; below,
    # the flat minimum limits JohnsonWavy's minimiser to about √ε in the area)
    area, _, _ = johnson_pull_off_load(1e-6)
    a_half = (2e-6) ** (1 / 3)
    assert abs(area / 2 / a_half - 1.0) < a_half**2 / 2


def test_johnson_pull_off_scales_with_the_modulus_ratio_like_the_cylinder():
    # with E = βE0 (γ̃ defined with E0) the line-contact pull-off is -(3/4)(4βΓ̃²)^(1/3)
    gamma = 1e-8
    for beta in (1.0, 10.0):
        _, p_off, _ = johnson_pull_off_load(gamma, beta)
        ref = -0.75 * (4 * beta * gamma**2) ** (1 / 3)
        a_half = (2 * gamma / beta) ** (1 / 3)          # ã³ = 2Γ̃/β
        assert (p_off / ref - 1.0) / a_half**2 == pytest.approx(1.0 / 12.0, rel=2e-3)
