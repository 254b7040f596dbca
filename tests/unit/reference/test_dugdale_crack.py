"""The Dugdale crack in a standard linear solid against direct quadrature of its mechanics."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy import integrate

from viscocontact.errors import ValidationError
from viscocontact.reference import MaugisDugdaleWavy
from viscocontact.reference.dugdale_crack import (
    creep_weight_tip,
    creep_weight_zone,
    speed_group,
    steady_crack,
    toughness,
    zone_length,
)

KAPPAS = [1e-3, 0.3, 3.0, 40.0]


def _q(f, lo, hi, points=None, rel=1e-12):
    return integrate.quad(f, lo, hi, points=points, epsabs=1e-14, epsrel=rel, limit=400)[0]


def _creep(t, beta):
    """``E0·J(t)`` of the standard linear solid, t in units of τ."""
    return 1 - (1 - 1 / beta) * math.exp(-t)


def _opening(r, traction, far_k, a):
    """Opening (E' = 1) at distance r behind the tip of a semi-infinite crack under the far-field
    K and the closing traction p(ρ) on 0 < ρ < a: ``(8K)√(r/2π) - (4/π)∫p log|(√ρ+√r)/(√ρ-√r)|``
    (the point-force Green function, e.g. Tada, Paris & Irwin)."""
    v = math.sqrt(r)                       # ρ = w²: the log singularity at w = v, split there
    green = lambda w: 2 * w * traction(w * w) * math.log(abs((w + v) / (w - v)))
    cuts = (0.0, v, math.sqrt(a)) if v < math.sqrt(a) else (0.0, math.sqrt(a))
    load = sum(_q(green, lo, hi) for lo, hi in itertools.pairwise(cuts))
    return 8 * far_k * math.sqrt(r / (2 * math.pi)) - 4 / math.pi * load


def _k(traction, a):
    """``K = √(2/π)∫ p(ρ)/√ρ dρ`` (ρ = w²)."""
    return math.sqrt(2 / math.pi) * 2 * _q(lambda w: traction(w * w), 0, math.sqrt(a))


@pytest.mark.parametrize("kappa", KAPPAS + [1e3])
def test_weights_are_their_defining_integrals(kappa):
    tip = _q(lambda w: 2 * w * math.atanh(w) * math.exp(-kappa * (1 - w * w)), 0, 1,
             [1 - 1 / kappa] if kappa > 1 else None)
    assert creep_weight_tip(kappa) == pytest.approx(tip, rel=1e-11)
    zone = _q(lambda w: math.exp(-kappa * (1 - w * w)), 0, 1)
    assert creep_weight_zone(kappa) == pytest.approx(zone, rel=1e-12)


@pytest.mark.parametrize("beta", [3.0, 100.0])
@pytest.mark.parametrize("kappa", KAPPAS)
def test_opening_crack_by_direct_quadrature(kappa, beta):
    """Stresses elastic (K = σ0√(8a/π) closes the tip smoothly); the opening at the crack tip is
    the creep integral of the elastic opening met along the material's path through the zone;
    G = K²/E0 and δ_tip = Δγ/σ0 give G/Δγ."""
    a, sigma0 = 1.0, 1.0
    k = _k(lambda rho: sigma0, a)
    assert k == pytest.approx(sigma0 * math.sqrt(8 * a / math.pi), rel=1e-12)
    elastic = lambda s: _opening(s, lambda rho: sigma0, k, a)   # s: distance from the tip
    r = 1e-6                                                    # closes smoothly at the tip:
    assert abs(elastic(r)) < 1e-3 * 8 * k * math.sqrt(r / (2 * math.pi))   # no K-field left
    vt = a / kappa
    # the point now at the zone's end entered it (a - s)/V ago at s = 0 and met D(s) on its way:
    # δ = ∫ c((a - s)/Vτ) dD = c(0)D(a) + ∫ D(s) d/ds[c((a - s)/Vτ)] ds  (by parts, D(0) = 0)
    creep = _q(lambda s: elastic(s) * (1 - 1 / beta) * math.exp(-(a - s) / vt) / vt, 0, a,
               rel=1e-10)               # the inner quadrature is exact to ~1e-13
    tip = elastic(a) / beta + creep
    assert toughness(kappa, beta, "opening") == pytest.approx(k**2 / (sigma0 * tip), rel=1e-11)


@pytest.mark.parametrize("beta", [3.0, 100.0])
@pytest.mark.parametrize("kappa", KAPPAS)
def test_closing_crack_by_direct_quadrature(kappa, beta):
    """Healing: the opening is elastic (compliance 1/E0) under the creep integral of the traction
    met along the path (σ0 c((a - ρ)/Vτ) at ρ behind the tip); K closes the tip smoothly and
    the zone's entry opens to Δγ/σ0."""
    a, sigma0 = 1.0, 1.0
    vt = a / kappa
    traction = lambda rho: sigma0 * _creep((a - rho) / vt, beta)
    k = _k(traction, a)
    entry = _opening(a, traction, k, a)
    assert toughness(kappa, beta, "closing") == pytest.approx(k**2 / (sigma0 * entry), rel=1e-11)
    assert zone_length(kappa, beta, "closing") == pytest.approx(
        toughness(kappa, beta, "closing") / (k / (sigma0 * math.sqrt(8 * a / math.pi))) ** 2,
        rel=1e-12)


@pytest.mark.parametrize("beta", [1.0, 2.0, 1e3])
def test_slow_and_fast_limits(beta):
    """Relaxed when slow (κ → ∞), glassy when fast: opening → β, closing → 1/β; elastic at β=1."""
    for crack, fast in (("opening", beta), ("closing", 1 / beta)):
        assert toughness(0.0, beta, crack) == pytest.approx(fast, rel=1e-15)
        assert toughness(1e-12, beta, crack) == pytest.approx(fast, rel=1e-8)
        assert toughness(1e9, beta, crack) == pytest.approx(1.0, abs=2e-8 * beta)
        assert steady_crack(1e-9, beta, crack).toughness == pytest.approx(1.0, abs=1e-7)
        # fast: κ ≈ a/(a0 v) and the relative error ≈ βκ/3, so v ≫ β²
        assert steady_crack(1e9 * beta**2, beta, crack).toughness == pytest.approx(fast, rel=1e-8)


@pytest.mark.parametrize("beta", [1.5, 10.0, 1e3])
def test_monotone_in_speed_and_self_consistent(beta):
    """Opening toughness rises and closing toughness falls with v = Vτ/a0; the zone is
    self-consistent (κ·v = a/a0; opening a/a0 = G/Δγ)."""
    speeds = np.logspace(-4, 4, 25)
    for crack in ("opening", "closing"):
        states = [steady_crack(v, beta, crack) for v in speeds]
        g = np.array([s.toughness for s in states])
        assert np.all(np.diff(g) > 0) if crack == "opening" else np.all(np.diff(g) < 0)
        assert np.all((g >= min(1, 1 / beta)) & (g <= max(1, beta)))
        for s in states:
            assert s.kappa * s.speed == pytest.approx(s.zone_length, rel=1e-12)
            assert s.toughness == pytest.approx(toughness(s.kappa, beta, crack), rel=1e-15)
            if crack == "opening":
                assert s.zone_length == pytest.approx(s.toughness, rel=1e-15)


def test_speed_group_and_the_wavy_dugdale_zone():
    """``v = Vτ/a0`` from SI values (a0 = πE*Δγ/(4σ0²), one deformable surface) equals 4ζγ̃/h̃0²,
    and a0 is the elastic Maugis–Dugdale wavy zone of the small-range limit."""
    E0, nu, dgamma, h0, wavelength, tau, speed = 5e6, 0.45, 0.05, 1e-8, 1e-3, 1e-3, 0.2
    q0, estar = 2 * math.pi / wavelength, E0 / (1 - nu**2)
    gamma = (1 - nu**2) * q0 * dgamma / (math.pi * E0)
    a0 = math.pi * estar * dgamma / (4 * (dgamma / h0) ** 2)
    zeta = q0 * speed * tau
    assert speed_group(zeta, gamma, q0 * h0) == pytest.approx(speed * tau / a0, rel=1e-12)
    amp = 1e-5
    md = MaugisDugdaleWavy.from_groups(gamma=gamma, h0=q0 * h0, amplitude=q0 * amp)
    assert md.state(2.0).zone_width == pytest.approx(q0 * a0, rel=1e-3)


def test_invalid_input_names_the_field():
    with pytest.raises(ValidationError, match="beta"):
        toughness(1.0, 0.5)
    with pytest.raises(ValidationError, match="crack"):
        toughness(1.0, 2.0, "healing")
    with pytest.raises(ValidationError, match="speed"):
        steady_crack(0.0, 2.0)
    with pytest.raises(ValidationError, match="kappa"):
        creep_weight_tip(-1.0)
