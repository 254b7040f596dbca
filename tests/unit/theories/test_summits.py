"""Nayak's summit statistics (thesis eqs. 3.33, 3.48, 3.49) and RoughnessMoments."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate, special

from viscocontact import ValidationError
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.theories import (RoughnessMoments, summit_height_density, summit_joint_density,
                                   summit_mean_curvature)
from viscocontact.theories.summits import SUMMIT_VARIANCE_CONSTANT

SETTINGS = settings(max_examples=15, deadline=None)
alphas = st.floats(0.2, 3.0).map(lambda e: 1.5 + 10.0**e)   # α in (1.5 + 1.6, 1.5 + 1000)


def thesis_p_sum(xi, alpha):
    """Eq. 3.49 as printed, except the last exponent (printed exp(-α/(2(α-1)ξ²)))."""
    c1 = alpha / (2 * alpha - 3)
    erf = special.erf
    return (3 * xi / (2 * math.pi * math.sqrt(c1 * alpha)) * np.exp(-c1 * xi**2)
            + 3 * math.sqrt(3) / (2 * alpha * math.sqrt(2 * math.pi)) * (xi**2 - 1)
            * np.exp(-xi**2 / 2) * (1 + erf(math.sqrt(3 * c1 / (2 * alpha)) * xi))
            + math.sqrt(alpha / (2 * math.pi * (alpha - 1)))
            * np.exp(-alpha * xi**2 / (2 * (alpha - 1))) * (1 + erf(math.sqrt(c1 / (2 * (alpha - 1))) * xi)))


def thesis_kbar(xi, alpha):
    """Eq. 3.48 exactly as printed (with p_sum of eq. 3.49)."""
    c1 = alpha / (2 * alpha - 3)
    erf = special.erf
    brace = (-2 / (3 * math.sqrt(6 * math.pi)) / (c1 * math.sqrt(c1) * (1 + c1))
             * np.exp(-3 * c1 * xi**2 / (2 * alpha))
             - xi / (3 * c1 * math.sqrt(alpha)) * (1 + erf(math.sqrt(3 * c1 / (2 * alpha)) * xi))
             + xi * math.sqrt(c1) / (3 * math.sqrt(alpha) * (1 + c1) ** 3)
             * (1 + erf(math.sqrt(c1 / (2 * (alpha - 1))) * xi)) * np.exp(-xi**2 / (2 * (alpha - 1))))
    return (-xi / math.sqrt(alpha) + 3 * math.sqrt(3) / math.sqrt(2 * math.pi)
            * np.exp(xi**2 / 2) * brace / thesis_p_sum(xi, alpha))


@SETTINGS
@given(alpha=alphas)
def test_summit_height_density_moments(alpha):
    norm = integrate.quad(lambda x: summit_height_density(x, alpha), -30, 30, epsabs=0, epsrel=1e-12,
                          limit=200)[0]
    mean = integrate.quad(lambda x: x * summit_height_density(x, alpha), -30, 30, epsabs=0,
                          epsrel=1e-12, limit=200)[0]
    msq = integrate.quad(lambda x: x * x * summit_height_density(x, alpha), -30, 30, epsabs=0,
                         epsrel=1e-12, limit=200)[0]
    assert norm == pytest.approx(1.0, abs=1e-10)
    # Nayak / McCool: mean summit height 4/√(πα), variance 1 - 0.8968/α
    assert mean == pytest.approx(4.0 / math.sqrt(math.pi * alpha), rel=1e-9)
    assert msq - mean**2 == pytest.approx(1.0 - SUMMIT_VARIANCE_CONSTANT / alpha, rel=1e-9)
    assert SUMMIT_VARIANCE_CONSTANT == pytest.approx(0.8968, abs=1e-4)
    # mean summit curvature over all summits (8/3)/√π in √m4 units
    kappa = integrate.quad(lambda x: -summit_mean_curvature(x, alpha) * summit_height_density(x, alpha),
                           -30, 30, epsabs=0, epsrel=1e-12, limit=200)[0]
    assert kappa == pytest.approx(8.0 / (3.0 * math.sqrt(math.pi)), rel=1e-9)


@SETTINGS
@given(alpha=alphas, xi=st.floats(-3.0, 6.0))
def test_density_equals_eq_3_49_with_the_corrected_exponent(alpha, xi):
    assert summit_height_density(xi, alpha) == pytest.approx(thesis_p_sum(xi, alpha), rel=1e-10,
                                                            abs=1e-300)


def test_eq_3_49_as_printed_is_not_a_density():
    alpha = 5.0

    def printed(x):   # the last exponential as printed: exp(-α/(2(α-1)ξ²))
        c1 = alpha / (2 * alpha - 3)
        return (thesis_p_sum(x, alpha) - math.sqrt(alpha / (2 * math.pi * (alpha - 1)))
                * (math.exp(-alpha * x**2 / (2 * (alpha - 1))) - math.exp(-alpha / (2 * (alpha - 1) * x**2)))
                * (1 + special.erf(math.sqrt(c1 / (2 * (alpha - 1))) * x)))
    total = integrate.quad(printed, -30, 30, points=[0.0], limit=200)[0]
    assert total > 2.0     # does not decay: not normalisable to 1


def _gl(lo, hi, panels, n=48):
    x, w = np.polynomial.legendre.leggauss(n)
    e = np.linspace(lo, hi, panels + 1)
    return (np.concatenate([0.5 * (b + a) + 0.5 * (b - a) * x for a, b in zip(e[:-1], e[1:])]),
            np.concatenate([0.5 * (b - a) * w for a, b in zip(e[:-1], e[1:])]))


def _ordered_quadrature(xi, alpha, kmax=9.0):
    """∫∫ over k1 < k2 < 0 of (1, (k1+k2)/2)·Υ* at each ξ, by tensor Gauss-Legendre
    (independent of the closed forms)."""
    xi = np.atleast_1d(np.asarray(xi, dtype=float))[:, None]
    k1, w1 = _gl(-kmax, 0.0, 6)
    x, w = np.polynomial.legendre.leggauss(48)
    tot = np.zeros((2, xi.shape[0]))
    for a, wa in zip(k1, w1):                     # k2 from k1 to 0
        k2 = (0.5 * a - 0.5 * a * x)[None, :]
        w2 = (-0.5 * a * w)[None, :]
        y = summit_joint_density(xi, a, k2, alpha)
        tot += wa * np.array([np.sum(w2 * y, axis=1), np.sum(w2 * y * (a + k2) / 2, axis=1)])
    return tot


@pytest.mark.parametrize("alpha", [2.0, 20.0])
def test_joint_density_eq_3_33_gives_nayak_summit_density_for_ordered_curvatures(alpha):
    xis, wx = _gl(-12.0, 14.0, 8, 24)
    tot = float(np.sum(wx * _ordered_quadrature(xis, alpha)[0]))
    # D_s (m2/m4) = 1/(6π√3): the constant of eq. 3.33 is that of ordered principal curvatures;
    # over the whole quadrant K1, K2 < 0 the integral doubles
    assert tot == pytest.approx(1.0 / (6 * math.pi * math.sqrt(3)), rel=1e-9)


@pytest.mark.parametrize("alpha,xi", [(2.0, -1.0), (2.0, 1.5), (5.0, 0.0), (5.0, 2.5), (50.0, 1.0)])
def test_mean_curvature_is_the_conditional_mean_of_eq_3_33(alpha, xi):
    dens, first = _ordered_quadrature(xi, alpha)[:, 0]
    ds = 1.0 / (6 * math.pi * math.sqrt(3))
    assert dens / ds == pytest.approx(summit_height_density(xi, alpha), rel=1e-7)
    assert first / dens == pytest.approx(summit_mean_curvature(xi, alpha), rel=1e-7)


def test_eq_3_48_as_printed_agrees_only_at_zero_height():
    # evidence for docs/theories.md: the printed K̄_A* matches the conditional mean at ξ = 0 only
    for alpha in (2.0, 5.0, 20.0):
        assert thesis_kbar(0.0, alpha) == pytest.approx(summit_mean_curvature(0.0, alpha), rel=1e-12)
        for xi in (1.0, 2.5):
            assert abs(thesis_kbar(xi, alpha) / summit_mean_curvature(xi, alpha) - 1) > 0.5


@SETTINGS
@given(alpha=alphas)
def test_high_summits_have_curvature_proportional_to_height(alpha):
    # K̄_A* → -ξ/√α (i.e. K̄ → -(m2/m0) z) for ξ → ∞, with a relative correction that decays
    r40 = summit_mean_curvature(40.0, alpha) * math.sqrt(alpha) / -40.0
    r80 = summit_mean_curvature(80.0, alpha) * math.sqrt(alpha) / -80.0
    assert abs(r80 - 1) < abs(r40 - 1) or abs(r80 - 1) < 1e-12
    assert np.isfinite(summit_mean_curvature(200.0, alpha))        # no 0/0 far in the tail


def test_many_scales_tend_to_gaussian_heights():
    xi = np.linspace(-3, 3, 13)
    gauss = np.exp(-xi**2 / 2) / math.sqrt(2 * math.pi)
    np.testing.assert_allclose(summit_height_density(xi, 1e8), gauss, atol=1e-4)


def test_moments_from_profiles():
    p = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)
    m = RoughnessMoments.from_profile(p)
    assert (m.m0, m.m2, m.m4) == (p.m0, p.m2, p.m4)
    assert m.amplitude == p.amplitude
    assert m.summit_density == pytest.approx(p.m4 / (6 * math.pi * math.sqrt(3) * p.m2))
    # a single sinusoid has α = 1: not an isotropic Gaussian surface
    s = RoughnessMoments.from_profile(Sinusoid(amplitude=0.1))
    assert s.alpha == pytest.approx(1.0)
    with pytest.raises(ValidationError, match="alpha"):
        s.summit_height_std
