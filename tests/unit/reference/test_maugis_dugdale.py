"""The Maugis–Dugdale wavy contact oracle against independent checks and its exact limits."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy import integrate

from viscocontact.errors import ValidationError
from viscocontact.groups import tabor_parameter
from viscocontact.reference import (
    JohnsonWavy,
    MaugisDugdaleWavy,
    westergaard_penetration,
    westergaard_pressure,
)


def _quad(f, lo, hi, points=()):
    cuts = [lo] + sorted(p for p in points if lo < p < hi) + [hi]
    return sum(integrate.quad(f, u, v, epsabs=1e-13, epsrel=1e-12, limit=200)[0]
               for u, v in itertools.pairwise(cuts))


def _displacement(md, st, x):
    """``ũ(x̃) = (1/πβ)∫ log|2 sin((x̃-t)/2)| σ̃(t) dt`` by direct quadrature of the kernel."""
    a, c = st.area / 2, st.outer / 2
    f = lambda t: math.log(abs(2 * math.sin((x - t) / 2))) * md.stress([t], st.area, st.outer)[0]
    return _quad(f, -math.pi, math.pi, (-c, -a, a, c, x)) / (math.pi * md.modulus_ratio)


def test_units_from_dimensional_values():
    """σ0 = Δγ/h0 in SI, scaled by eq. 4.17, gives σ̃0 = 2πΓ̃/η; λ and μ_T from their SI forms."""
    E0, nu, dgamma, h0, wavelength, amp = 10e6, 0.5, 0.01, 2e-9, 1e-4, 1e-6
    q0, estar = 2 * math.pi / wavelength, E0 / (1 - nu**2)
    gamma = (1 - nu**2) * q0 * dgamma / (math.pi * E0)                      # eq. 4.17
    md = MaugisDugdaleWavy.from_groups(gamma=gamma, h0=q0 * h0, amplitude=q0 * amp)
    sigma0 = dgamma / h0
    assert sigma0 / estar == pytest.approx(math.pi * gamma / (q0 * h0), rel=1e-12)
    assert md.cohesive_stress == pytest.approx(2 * sigma0 / (estar * q0 * amp), rel=1e-12)
    radius = 1 / (q0**2 * amp)
    lam = 2 * sigma0 * (radius / (math.pi * estar**2 * dgamma)) ** (1 / 3)
    assert md.transition_parameter == pytest.approx(lam, rel=1e-12)
    z0 = 16 * h0 / (9 * math.sqrt(3))       # σ0 = the Lennard-Jones maximum 16Δγ/(9√3 Z0)
    mu = tabor_parameter(radius=radius, work_of_adhesion=dgamma, reduced_modulus=estar,
                         equilibrium_distance=z0)
    assert md.tabor == pytest.approx(mu, rel=1e-12)
    assert md.johnson_parameter ** 2 == pytest.approx(
        2 * wavelength * dgamma / (math.pi**2 * estar * amp**2), rel=1e-12)  # Johnson's α²


@pytest.mark.parametrize("Gamma,eta,beta,area", [(0.05, 0.2, 1.0, 1.2), (0.02, 0.05, 3.0, 3.5),
                                                 (0.1, 0.5, 1.0, 2.5)])
def test_field_equations_by_direct_quadrature(Gamma, eta, beta, area):
    """With the log kernel integrated directly on the stress field: the contact follows the
    profile, the gap at the zone's end is η, the mean stress is -p̃∞, the stress is continuous
    at the contact edge (no singularity)."""
    md = MaugisDugdaleWavy(Gamma=Gamma, h0=eta, modulus_ratio=beta)
    st = md.state(area)
    assert not st.saturated
    a, c = st.area / 2, st.outer / 2
    for x in (0.0, 0.4 * a, 0.9 * a):
        assert _displacement(md, st, x) == pytest.approx(
            math.cos(x) - 1 + st.penetration, abs=1e-12)
    gap_c = _displacement(md, st, c) - (math.cos(c) - 1 + st.penetration)
    assert gap_c == pytest.approx(eta, rel=1e-12)
    assert md.gap([c], st.area, st.outer)[0] == pytest.approx(eta, rel=1e-11)
    mean = _quad(lambda t: md.stress([t], st.area, st.outer)[0], -math.pi, math.pi, (-c, -a, a, c))
    assert -mean / (2 * math.pi) == pytest.approx(st.mean_pressure, abs=1e-13)
    edge = md.stress([a * (1 - 1e-10)], st.area, st.outer)[0]
    assert edge == pytest.approx(md.cohesive_stress, rel=1e-4)


def _energy(md, st):
    """Elastic energy -½∫σ̃ũ plus the Dugdale potential -σ̃0(η - g̃) (contact: -σ̃0η)."""
    a, c, D, s0 = st.area / 2, st.outer / 2, st.penetration, md.cohesive_stress
    gap = lambda x: md.gap([x], st.area, st.outer)[0]
    contact = 2 * _quad(lambda x: md.stress([x], st.area, st.outer)[0]
                        * (math.cos(x) - 1 + D), 0, a)
    zone = 2 * _quad(lambda x: s0 * (gap(x) + math.cos(x) - 1 + D), a, c)
    gaps = 2 * _quad(gap, a, c)
    return -0.5 * (contact + zone) - s0 * md.h0 * 2 * c + s0 * gaps


@pytest.mark.parametrize("Gamma,eta,beta,area", [(0.05, 0.2, 1.0, 0.8), (0.05, 0.02, 1.0, 3.5),
                                                 (0.02, 1.0, 3.0, 2.0)])
def test_energy_release_is_the_work_of_adhesion(Gamma, eta, beta, area):
    """Along the equilibria, the total energy (elastic + cohesive, Δγ̃ = σ̃0η released per unit
    separated length) changes with Δ̃ at the rate 2πp̃∞: the zones release exactly Δγ."""
    md = MaugisDugdaleWavy(Gamma=Gamma, h0=eta, modulus_ratio=beta)
    h = 1e-3
    up, down = md.state(area + h), md.state(area - h)
    slope = (_energy(md, up) - _energy(md, down)) / (up.penetration - down.penetration)
    assert slope == pytest.approx(2 * math.pi * md.state(area).mean_pressure, rel=2e-6)


@pytest.mark.parametrize("beta", [1.0, 3.0])
def test_jkr_limit_at_fixed_area(beta):
    """η → 0 at fixed Γ̃: Johnson's p̃∞ and Δ̃ with error O(η²); the zone tends to Dugdale's
    d = πK²/(8σ0²) = βη²/(4Γ̃) (Irwin: G = K²/(2E) on a rigid-elastic interface), and the
    error is an edge shift of 2d/3 (Dugdale's field ahead, (2σ0/π)arctan√(d/x), matched to a
    K-field): Johnson at Ã + 4d/3 is reached to O(η⁴)."""
    G = 0.05
    jw = JohnsonWavy(Gamma=G, modulus_ratio=beta)

    def johnson(area):
        return np.array([float(jw.mean_pressure(area)), float(jw.penetration(area))])

    for area in (1.0, 2.0, 4.0):
        errs, shifted, zone = [], [], []
        for eta in (0.01, 0.005):
            st = MaugisDugdaleWavy(Gamma=G, h0=eta, modulus_ratio=beta).state(area)
            got = np.array([st.mean_pressure, st.penetration])
            d = beta * eta**2 / (4 * G)
            errs.append(np.abs(got - johnson(area)))
            shifted.append(np.abs(got - johnson(area + 4 * d / 3)))
            zone.append(abs(st.zone_width / d - 1))
        orders = np.log2(errs[0] / errs[1])
        assert np.all((orders > 1.9) & (orders < 2.1)), orders
        assert errs[1].max() < 3e-4
        assert shifted[1].max() < 2e-3 * errs[1].max()
        assert np.all(np.log2(shifted[0] / shifted[1]) > 3.8)
        assert zone[1] < 1e-3 and math.log2(zone[0] / zone[1]) > 1.9


def test_jkr_limit_of_the_pull_off():
    """The pull-off tends to Johnson's, with error O(η⁴): the O(η²) edge shift moves the area of
    the minimum, not its value."""
    G = 0.05
    _, p_j, _ = JohnsonWavy(Gamma=G).pull_off("load")
    errs = [MaugisDugdaleWavy(Gamma=G, h0=eta).pull_off().mean_pressure - p_j
            for eta in (0.04, 0.02)]
    assert 0 < errs[1] < 1e-7                    # less tensile than Johnson's
    assert math.log2(errs[0] / errs[1]) > 3.8


def test_westergaard_limit():
    """Γ̃ = 0 is Westergaard exactly; Γ̃ → 0 at fixed η approaches it at O(Γ̃)."""
    for area in (0.5, 2.0, 5.0):
        st = MaugisDugdaleWavy(Gamma=0.0, h0=0.3).state(area)
        assert st.mean_pressure == pytest.approx(float(westergaard_pressure(area)), abs=1e-15)
        assert st.penetration == pytest.approx(float(westergaard_penetration(area)), abs=1e-13)
        errs = [MaugisDugdaleWavy(Gamma=g, h0=0.3).state(area).mean_pressure
                - float(westergaard_pressure(area)) for g in (1e-4, 1e-5)]
        assert errs[0] < 0 and errs[0] / errs[1] == pytest.approx(10, rel=0.02)


def _westergaard_trough_gap(area):
    """Westergaard's gap at x̃ = π, by direct quadrature of its pressure with the log kernel."""
    a, s = area / 2, math.sin(area / 4)
    p = lambda t: 2 * math.cos(t / 2) * math.sqrt(max(s**2 - math.sin(t / 2) ** 2, 0.0))
    u = lambda x: -_quad(lambda t: math.log(abs(2 * math.sin((x - t) / 2))) * p(t),
                         -a, a, (x,)) / math.pi
    return u(math.pi) - u(0.0) + 2                  # g = u - (cos x - 1 + Δ), Δ = u(0)


def test_saturated_zone_is_westergaard_under_uniform_tension():
    """When Westergaard's trough gap is ≤ η, the zone may fill the gap region: a uniform
    tension deforms nothing, so p̃∞ = β sin²(Ã/4) - σ̃0 and Δ̃ is Westergaard's; unloading from
    full contact ends where that trough gap equals η."""
    md = MaugisDugdaleWavy(Gamma=0.02, h0=1.0, modulus_ratio=3.0)
    area = 3.5
    assert _westergaard_trough_gap(area) < md.h0
    sat = [s for s in md.states(area) if s.saturated]
    assert len(sat) == 1 and sat[0].outer == 2 * math.pi
    assert sat[0].mean_pressure == pytest.approx(
        3.0 * float(westergaard_pressure(area)) - md.cohesive_stress, abs=1e-14)
    assert sat[0].penetration == pytest.approx(float(westergaard_penetration(area)), abs=1e-12)
    x = np.linspace(-area / 2, area / 2, 41)[1:-1]
    westergaard = -6.0 * np.cos(x / 2) * np.sqrt(np.sin(area / 4) ** 2 - np.sin(x / 2) ** 2)
    assert md.stress(x, area, 2 * math.pi) == pytest.approx(westergaard + md.cohesive_stress,
                                                            abs=1e-12)
    assert md.mean_pressure(area, 2 * math.pi) == sat[0].mean_pressure
    full = md.pull_off("full")
    assert _westergaard_trough_gap(full.area) == pytest.approx(md.h0, rel=1e-9)
    assert full.mean_pressure == pytest.approx(
        3.0 * float(westergaard_pressure(full.area)) - md.cohesive_stress, abs=1e-14)
    wide = MaugisDugdaleWavy(Gamma=0.02, h0=2.5)      # η ≥ 2 = the largest gap
    assert wide.pull_off("full").mean_pressure == -wide.cohesive_stress


def test_several_equilibria_are_all_admissible():
    """Where the trough gap is below η but g̃(c) peaks above it, an area has three equilibria:
    each has g̃ < η in its zone and g̃ > η beyond (the Dugdale law holds everywhere)."""
    md = MaugisDugdaleWavy(Gamma=0.05, h0=0.4)
    states = md.states(4.0)
    assert len(states) == 3 and [s.saturated for s in states] == [False, False, True]
    assert states[0].outer < states[1].outer < states[2].outer
    assert states[0].mean_pressure > states[1].mean_pressure > states[2].mean_pressure
    for st in states:
        x = np.linspace(st.area / 2, math.pi, 60)[1:]
        g = md.gap(x, st.area, st.outer)
        assert np.all(np.diff(g) > 0)
        inside = (x < st.outer / 2) | st.saturated
        assert np.all(g[inside] <= md.h0 * (1 + 1e-12))
        assert np.all(g[~inside] >= md.h0 * (1 - 1e-12))
        if not st.saturated:
            assert md.zone_gap(st.area, st.outer) == pytest.approx(md.h0, rel=1e-12)


@pytest.mark.parametrize("eta", [0.5, 1.5])
def test_rigid_limit_of_the_pull_off(eta):
    """Γ̃ → 0 at fixed η (Bradley-like): the contact vanishes at pull-off and the tension acts
    where the undeformed gap 1 - cos x̃ is below η, p̃∞/σ̃0 → -arccos(1 - η)/π, error O(Γ̃)."""
    errs = []
    for G in (1e-3, 1e-4):
        md = MaugisDugdaleWavy(Gamma=G, h0=eta)
        off = md.pull_off()
        assert off.area < 1e-3
        errs.append(off.mean_pressure / md.cohesive_stress + math.acos(1 - eta) / math.pi)
    assert 0 < errs[1] < 5e-4 and errs[0] / errs[1] == pytest.approx(10, rel=0.05)


def test_pull_off_between_the_limits():
    """At fixed Γ̃ the pull-off grows with the transition parameter λ towards Johnson's."""
    G = 0.05
    _, p_j, _ = JohnsonWavy(Gamma=G).pull_off("load")
    p = [MaugisDugdaleWavy.from_transition(Gamma=G, transition=lam).pull_off().mean_pressure
         for lam in (0.3, 1.0, 3.0, 10.0)]
    assert np.all(np.diff(p) < 0) and p_j < p[-1] < p_j + 1e-5


def test_area_at_pressure_inverts_the_branch():
    md = MaugisDugdaleWavy(Gamma=0.05, h0=0.05)
    off = md.pull_off()
    assert md.area_at_pressure(off.mean_pressure - 1e-3) is None
    for p in (off.mean_pressure + 0.01, 0.0, 0.1):
        area = md.area_at_pressure(p)
        assert area > off.area
        assert md.state(area).mean_pressure == pytest.approx(p, abs=1e-12)
        assert md.state_at_pressure(p).area == area
        assert area == pytest.approx(JohnsonWavy(Gamma=0.05).area_at_pressure(p), rel=2e-2)


def test_narrow_zones_by_their_angle():
    """A state's exact zone angle gives the same fields as its outer length, and keeps the
    equilibrium to round-off where the zone is too narrow for C̃ - Ã to carry the digits."""
    md = MaugisDugdaleWavy(Gamma=0.05, h0=0.1)
    st = md.state(2.0)
    x = np.linspace(-math.pi, math.pi, 13)
    assert md.stress(x, 2.0, zone_angle=st.zone_angle) == pytest.approx(
        md.stress(x, 2.0, st.outer), abs=1e-12)
    assert md.penetration(2.0, zone_angle=st.zone_angle) == pytest.approx(st.penetration,
                                                                          abs=1e-15)
    narrow = MaugisDugdaleWavy(Gamma=5.0, h0=2e-4, modulus_ratio=2.0)
    st = narrow.state(0.4)
    assert st.zone_width < 1e-7
    assert narrow.zone_gap(0.4, zone_angle=st.zone_angle) == pytest.approx(2e-4, rel=1e-10)
    assert narrow.mean_pressure(0.4, zone_angle=st.zone_angle) == st.mean_pressure


def test_invalid_input_names_the_field():
    md = MaugisDugdaleWavy(Gamma=0.05, h0=0.1)
    with pytest.raises(ValidationError, match="outer"):
        md.penetration(2.0)
    with pytest.raises(ValidationError, match="zone_angle"):
        md.gap([1.0], 2.0, zone_angle=2.0)
    with pytest.raises(ValidationError, match="area"):
        md.state(7.0)
    with pytest.raises(ValidationError, match="outer"):
        md.mean_pressure(2.0, 1.0)
    with pytest.raises(ValidationError, match="branch"):
        md.pull_off("both")
    with pytest.raises(ValidationError, match="h0"):
        MaugisDugdaleWavy(Gamma=0.05, h0=0.0)
    with pytest.raises(ValidationError, match="Gamma"):
        MaugisDugdaleWavy(Gamma=-1.0, h0=0.1)
