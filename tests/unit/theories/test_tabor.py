"""Tabor parameter (thesis eq. 1.48), crest radius (eq. 4.55) and the Lennard-Jones law (eq. 1.20)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate
from scipy.optimize import minimize_scalar

from viscocontact import groups
from viscocontact.theories import LennardJones, equivalent_crest_radius, tabor_parameter

SETTINGS = settings(max_examples=40, deadline=None)
logs = st.floats(-3.0, 3.0).map(lambda e: 10.0**e)


def test_thesis_numbers():
    # §4.6: λ0 = 6.28 mm, r_rms = 10 µm -> R ≈ 0.1 m (eq. 4.55)
    radius = equivalent_crest_radius(wavelength=6.28e-3, rms=10e-6)
    assert radius == pytest.approx(0.0999, rel=1e-3)
    # E0 = 10 MPa, ν = 0.5, Δγ = 0.01 J/m², Z0 = 1 nm. With E* = E0/(1-ν²) as eq. 1.48 asks:
    mu = tabor_parameter(radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7 / 0.75)
    assert mu == pytest.approx(383.2, abs=0.05)
    # the thesis's "μ_T ≈ 460" is the same formula with E0 in place of E* (docs/thesis-notes.md §2)
    assert tabor_parameter(radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7) == pytest.approx(
        464.2, abs=0.05)
    # as printed (E* to the first power) it is not dimensionless: in SI it would be ~9e4
    printed = (0.01**2 * 0.1 / (1e7 / 0.75 * 1e-27)) ** (1 / 3)
    assert printed > 100 * mu


@SETTINGS
@given(radius=logs, gamma=logs, modulus=logs, z0=logs)
def test_same_value_as_groups_and_scaling(radius, gamma, modulus, z0):
    mu = tabor_parameter(radius=radius, work_of_adhesion=gamma, reduced_modulus=modulus,
                         equilibrium_distance=z0)
    assert mu == groups.tabor_parameter(radius=radius, work_of_adhesion=gamma,
                                        reduced_modulus=modulus, equilibrium_distance=z0)
    assert mu == pytest.approx((radius * gamma**2 / (modulus**2 * z0**3)) ** (1 / 3), rel=1e-12)
    # dimensionless: invariant when every length is scaled by s (Δγ/E* is a length)
    s = 7.0
    assert tabor_parameter(radius=s * radius, work_of_adhesion=s * gamma, reduced_modulus=modulus,
                           equilibrium_distance=s * z0) == pytest.approx(mu, rel=1e-12)


@SETTINGS
@given(gamma=logs, eps=logs)
def test_lennard_jones_law(gamma, eps):
    lj = LennardJones(work_of_adhesion=gamma, equilibrium_distance=eps)
    assert float(lj.traction(eps)) == 0.0
    # the work of separation is Δγ (eq. 1.19)
    work = integrate.quad(lambda g: float(lj.traction(g)), eps, math.inf, epsabs=0, epsrel=1e-12)[0]
    assert work == pytest.approx(gamma, rel=1e-10)
    assert float(lj.potential(eps)) == pytest.approx(gamma, rel=1e-14)
    # potential' = -traction
    g, h = 1.7 * eps, 1e-5 * eps
    dphi = (float(lj.potential(g + h)) - float(lj.potential(g - h))) / (2 * h)
    assert dphi == pytest.approx(-float(lj.traction(g)), rel=1e-8)
    # largest tension 16Δγ/(9√3 ε) at g = 3^(1/6) ε
    res = minimize_scalar(lambda g: -float(lj.traction(g)), bounds=(eps, 3 * eps), method="bounded",
                          options={"xatol": 1e-12 * eps})
    assert -res.fun == pytest.approx(lj.max_traction, rel=1e-12)
    assert res.x == pytest.approx(lj.gap_at_max_traction, rel=1e-5)
    assert lj.max_traction * eps / gamma == pytest.approx(1.0264, abs=1e-4)
    # repulsive below ε
    assert float(lj.traction(0.9 * eps)) < 0


def test_lennard_jones_tabor_uses_epsilon():
    lj = LennardJones(work_of_adhesion=0.01, equilibrium_distance=1e-9)
    assert lj.tabor_parameter(radius=0.1, reduced_modulus=1e7 / 0.75) == tabor_parameter(
        radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7 / 0.75, equilibrium_distance=1e-9)
