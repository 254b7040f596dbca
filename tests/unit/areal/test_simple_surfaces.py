"""The 2D sinusoid, the spherical-cap lattice and the extruded profile against closed forms."""
from __future__ import annotations

import math

import numpy as np
import pytest

from viscocontact.areal.surfaces import (ExtrudedProfile, SinusoidSurface, SphericalCapLattice,
                                         sample_statistics)
from viscocontact.errors import ValidationError
from viscocontact.methods.spectral.grid import uniform_heights
from viscocontact.profiles import SelfAffineProfile, Sinusoid


# -- sinusoid ------------------------------------------------------------------------------------
@pytest.mark.parametrize("kx, ky, aspect", [(1, 1, 1.0), (2, 3, 0.5), (3, 0, 2.0)])
def test_sinusoid_heights_and_moments(kx, ky, aspect):
    s = SinusoidSurface(amplitude=0.3, kx=kx, ky=ky, aspect=aspect)
    x, y = s.grid(24, 20)
    exact = 0.3 * np.cos(kx * x) * np.cos(ky * y / aspect)
    # rounding of cos at arguments up to 6π: a few ulp of 20 times Λ̃
    assert np.max(np.abs(s.heights(24, 20) - exact)) < 1e-14
    # the FFT of the modes gives the same samples as the closed form
    fft = super(SinusoidSurface, s).heights(24, 20)
    assert np.max(np.abs(fft - exact)) < 1e-14
    m0 = 0.3**2 / (4 if ky else 2)
    g2 = m0 * (kx**2 + (ky / aspect) ** 2)
    st = sample_statistics(s, 24, 20)
    assert st.m0 == pytest.approx(m0, rel=1e-13) and s.m0 == pytest.approx(m0, rel=1e-13)
    assert st.m2x + st.m2y == pytest.approx(g2, rel=1e-13)
    assert s.gradient_variance == pytest.approx(g2, rel=1e-13)
    # the rms curvature: ∇²h = -|q̃|²h, so <(∇²h)²> = |q̃|⁴ m0
    assert st.m4 == pytest.approx((kx**2 + (ky / aspect) ** 2) ** 2 * m0, rel=1e-12)
    assert st.amplitude == pytest.approx(0.3, rel=1e-15)


def test_sinusoid_refuses_a_flat_surface():
    with pytest.raises(ValidationError, match="kx/ky"):
        SinusoidSurface(amplitude=0.1, kx=0, ky=0)
    with pytest.raises(ValidationError, match="SinusoidSurface.amplitude"):
        SinusoidSurface(amplitude=0.0)


# -- spherical caps ------------------------------------------------------------------------------
def test_cap_top_and_paraboloid_near_it():
    s = SphericalCapLattice(radius=20.0, height=0.2)
    n = 256
    h = s.heights(n, n)
    assert h.max() - h.min() == pytest.approx(0.2, abs=1e-14)
    x, y = s.grid(n, n)
    rho2 = (x - math.pi) ** 2 + (y - math.pi) ** 2
    near = rho2 < 0.5**2
    parabola = h.max() - rho2[near] / (2 * 20.0)
    # √(R² - ρ²) = R - ρ²/2R - ρ⁴/8R³ - ...: the paraboloid's error is below ρ⁴/(8R³)(1 + ε)
    assert np.all(np.abs(h[near] - parabola) <= 1.01 * rho2[near] ** 2 / (8 * 20.0**3) + 1e-15)


def test_cap_mean_converges_to_the_volume_over_the_area():
    s = SphericalCapLattice(radius=2.0, height=1.0, aspect=1.2)
    errors = [abs(-float(s.heights(n, n).min()) - s.mean_height) for n in (64, 128, 256)]
    # outside the cap the samples are -mean; the cell sum converges at least linearly (the rim
    # of a cap that is not a hemisphere is a kink, not a jump)
    assert errors[2] < errors[0] / 4 and errors[2] < 2e-4 * s.mean_height


def test_cap_statistics_converge_to_the_closed_forms():
    s = SphericalCapLattice(radius=2.0, height=1.0, aspect=1.2)
    coarse, fine = (sample_statistics(s, n, n) for n in (128, 256))
    # heights are continuous: the cell sums converge fast (measured 6e-8 and 2e-6)
    assert fine.m0 == pytest.approx(s.m0, rel=1e-5)
    # the slope jumps at the rim: the power of ∇h beyond the grid's Nyquist circle falls as 1/n,
    # so the periodogram misses a first-order share (1.5 % at 128², 0.85 % at 256²)
    errors = [abs((st.m2x + st.m2y) / s.gradient_variance - 1.0) for st in (coarse, fine)]
    assert errors[1] < 0.02 and errors[1] < 0.65 * errors[0]
    assert SphericalCapLattice(radius=2.0, height=2.0).gradient_variance == math.inf


@pytest.mark.parametrize("kwargs, field", [
    (dict(radius=1.0, height=2.0), "height"),
    (dict(radius=10.0, height=5.0), "height"),      # base radius 8.7 > π
    (dict(radius=1.0, height=1.0, aspect=0.2), "height"),   # base 1 > 0.2π
    (dict(radius=-1.0, height=0.5), "radius"),
])
def test_cap_bad_input(kwargs, field):
    with pytest.raises(ValidationError, match=f"SphericalCapLattice.{field}"):
        SphericalCapLattice(**kwargs)


# -- extruded profile ----------------------------------------------------------------------------
@pytest.mark.parametrize("profile", [Sinusoid(amplitude=0.1),
                                     SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=2)])
@pytest.mark.parametrize("nx", [128, 64])        # 64 < 2·50: the profile's own aliased samples
def test_extrusion_repeats_the_profiles_samples_in_every_row(profile, nx):
    s = ExtrudedProfile(profile=profile, aspect=0.25)
    h = s.heights(nx, 6)
    row = uniform_heights(profile, 0.0, nx)
    assert np.max(np.abs(h - (row - row.mean()))) == 0.0
    assert abs(row.mean()) < 1e-16 * nx
    st = sample_statistics(s, 256, 4)
    assert st.m2y == 0.0 and st.m2x == pytest.approx(profile.m2, rel=1e-12)


def test_extrusion_from_a_scene_table():
    s = ExtrudedProfile(profile={"kind": "sinusoid", "amplitude": 0.2})
    assert s == ExtrudedProfile(profile=Sinusoid(amplitude=0.2))
    with pytest.raises(ValidationError, match="ExtrudedProfile.profile"):
        ExtrudedProfile(profile=3.0)
