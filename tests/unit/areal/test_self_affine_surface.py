"""SelfAffineSurface: exact normalisation, real seeded fields, the PSD's slope, anisotropy."""
from __future__ import annotations

import math

import numpy as np
import pytest

from viscocontact.areal.surfaces import (SelfAffineSurface, fit_hurst, power_spectrum,
                                         sample_statistics)
from viscocontact.errors import ValidationError


def direct_sum(surface, nx, ny):
    """The Fourier series summed mode by mode on the grid (no FFT)."""
    x, y = surface.grid(nx, ny)
    m = surface.modes
    h = sum(a * np.cos(k * x + l * y / surface.aspect + p)
            for k, l, a, p in zip(m.kx, m.ky, m.amplitudes, m.phases))
    return h - h.mean()


@pytest.mark.parametrize("grid", [(32, 32), (33, 21), (12, 10)])
def test_heights_are_the_real_fourier_series_on_any_grid(grid):
    s = SelfAffineSurface(hurst=0.7, scales=8, rms=0.02, seed=4, aspect=1.5)
    h = s.heights(*grid)
    assert h.shape == grid[::-1] and h.dtype == float
    # rounding only: ~1e-16 per mode, a few hundred modes of amplitude <= rms
    assert np.max(np.abs(h - direct_sum(s, *grid))) < 1e-14


def test_rms_height_and_rms_gradient_are_exact():
    s = SelfAffineSurface(hurst=0.8, scales=16, rms=0.01, seed=1)
    assert abs(float(s.heights(64, 64).std()) - 0.01) < 1e-15
    g = SelfAffineSurface(hurst=0.8, scales=16, rms_slope=0.3, seed=1)
    stats = sample_statistics(g, 64, 64)
    assert abs(stats.rms_slope - 0.3) < 1e-13
    assert abs(g.gradient_variance - 0.09) < 1e-15
    # same shape of spectrum: the two differ by one factor
    ratio = g.heights(64, 64) / s.heights(64, 64)
    assert np.ptp(ratio) < 1e-9 * abs(ratio.mean())


def test_reproducible_by_seed_and_compared_by_value():
    a = SelfAffineSurface(hurst=0.8, scales=16, rms=0.01, seed=7)
    b = SelfAffineSurface(hurst=0.8, scales=16, rms=0.01, seed=7)
    assert a == b and hash(a) == hash(b)
    assert np.array_equal(a.heights(48, 48), b.heights(48, 48))
    c = SelfAffineSurface(hurst=0.8, scales=16, rms=0.01, seed=8)
    assert np.max(np.abs(a.heights(48, 48) - c.heights(48, 48))) > 1e-3


@pytest.mark.parametrize("hurst", [0.3, 0.8, 1.0])
def test_psd_slope_is_minus_two_one_plus_hurst(hurst):
    s = SelfAffineSurface(hurst=hurst, scales=48, rms=0.01, seed=2)
    # deterministic amplitudes: every bin lies on the power law
    assert abs(fit_hurst(s, 128, 128) - hurst) < 1e-10
    spec = power_spectrum(s, 128, 128)
    k = spec.wavenumbers
    use = (k >= 4) & (k <= 48)
    slope = np.polyfit(np.log(k[use]), np.log(spec.psd[use]), 1)[0]
    # averaging q^-2(1+H) over annuli of width 1 biases log C by about b(b+1)/(24k²) (b the
    # exponent): 0.04 at k = 4 falling to 0 at k = 48, a slope bias of about 0.01
    assert abs(slope + 2 * (1 + hurst)) < 0.012
    # the radial PSD integrates to m0 (annuli inside the Nyquist circle hold the whole band)
    assert abs(float(np.sum(spec.psd * spec.counts)) / s.aspect - s.m0) < 1e-12 * s.m0


def test_rolloff_flattens_the_psd_below_it():
    s = SelfAffineSurface(hurst=0.8, scales=32, rms=0.01, seed=2, rolloff=4.0)
    assert abs(fit_hurst(s, 128, 128, kmin=4.0) - 0.8) < 1e-10
    m = s.modes
    q = np.hypot(m.kx, m.ky)
    low = m.amplitudes[q <= 4.0]
    assert np.ptp(low) < 1e-14 * low.max()


def test_isotropic_surface_has_equal_directional_slopes():
    s = SelfAffineSurface(hurst=0.8, scales=32, rms=0.01, seed=3)
    st = s.statistics()
    # the square lattice's band is symmetric under (k, l) -> (-l, k): equal to rounding
    assert abs(st.m2x - st.m2y) < 1e-13 * st.m2x and abs(st.m2xy) < 1e-13 * st.m2x


def test_anisotropy_stretches_the_features_along_the_orientation():
    gamma = 3.0
    band = dict(hurst=0.8, scales=64, lowest=8.0, rms=0.01, anisotropy=gamma)
    along_x = SelfAffineSurface(**band).statistics()
    # a stretched isotropic field h(x/γ, y): <h_x²> = <h_y²>/γ². The lattice samples the band
    # with a spacing γ along e1 in the isotropic coordinates; with q_L = 8-16 its sums differ from
    # the integrals by 0.1-1.1 % (with q_L = 1 by 30 %: the lattice cannot hold the stretch)
    assert along_x.m2y / along_x.m2x == pytest.approx(gamma**2, rel=0.03)
    along_y = SelfAffineSurface(**band, orientation=math.pi / 2).statistics()
    # a quarter turn is a symmetry of the square lattice: the moments swap exactly
    assert along_y.m2x == pytest.approx(along_x.m2y, rel=1e-12)
    theta = 0.6
    tilted = SelfAffineSurface(**band, orientation=theta).statistics()
    tensor = np.array([[tilted.m2x, tilted.m2xy], [tilted.m2xy, tilted.m2y]])
    w, v = np.linalg.eigh(tensor)
    long_axis = v[:, 0]                      # smallest slope: along the features
    angle = math.atan2(long_axis[1], long_axis[0]) % math.pi
    # lattice anisotropy of the band's edge only: a few hundredths of a radian
    assert angle == pytest.approx(theta, abs=0.03)


def test_rectangular_cell_wavevectors():
    s = SelfAffineSurface(hurst=0.8, scales=6, rms=0.01, aspect=2.0)
    m = s.modes
    q = np.hypot(m.kx, m.ky / 2.0)
    assert q.min() >= 1.0 - 1e-12 and q.max() <= 6.0 + 1e-12
    assert m.ky.max() == 12 and s.heights(16, 32).shape == (32, 16)


@pytest.mark.parametrize("kwargs, field", [
    (dict(rms=0.01, rms_slope=0.1), "rms/rms_slope"),
    (dict(), "rms/rms_slope"),
    (dict(rms=-1.0), "rms"),
    (dict(rms=0.01, hurst=1.5), "hurst"),
    (dict(rms=0.01, rolloff=20.0), "rolloff"),
    (dict(rms=0.01, orientation=math.pi), "orientation"),
    (dict(rms=0.01, anisotropy=0.0), "anisotropy"),
    (dict(rms=0.01, lowest=9.0), "lowest"),
    # γ = 3 along x, a thin cell: (1, 0) has q̃_e = 3, (0, 1) has 5; nothing in [1, 2]
    (dict(rms=0.01, scales=2, anisotropy=3.0, aspect=0.2), "scales"),
    (dict(rms=0.01, seed=-1), "seed"),
])
def test_bad_input_names_the_field(kwargs, field):
    args = dict(hurst=0.8, scales=8) | kwargs
    with pytest.raises(ValidationError, match=f"SelfAffineSurface.{field}"):
        SelfAffineSurface(**args)


def test_bad_grid_is_refused():
    s = SelfAffineSurface(hurst=0.8, scales=8, rms=0.01)
    with pytest.raises(ValidationError, match="nx"):
        s.heights(1, 8)


def test_gradient_is_the_derivative_of_the_series():
    s = SelfAffineSurface(hurst=0.7, scales=8, rms=0.02, seed=4, aspect=1.5, anisotropy=1.5)
    x, y = s.grid(20, 30)
    m = s.modes
    arg = [k * x + l * y / s.aspect + p for k, l, p in zip(m.kx, m.ky, m.phases)]
    hx = -sum(a * k * np.sin(t) for k, a, t in zip(m.kx, m.amplitudes, arg))
    hy = -sum(a * l / s.aspect * np.sin(t) for l, a, t in zip(m.ky, m.amplitudes, arg))
    gx, gy = s.gradient(20, 30)
    scale = float(np.max(np.abs(hx)))
    assert np.max(np.abs(gx - hx)) < 1e-13 * scale and np.max(np.abs(gy - hy)) < 1e-13 * scale
    st = s.statistics()
    fine_x, fine_y = s.gradient(64, 64)
    assert float(np.mean(fine_x**2)) == pytest.approx(st.m2x, rel=1e-12)
    assert float(np.mean(fine_y**2)) == pytest.approx(st.m2y, rel=1e-12)


def test_an_empty_band_is_refused_exactly_when_the_lattice_has_no_mode_in_it():
    import itertools

    refused = 0
    for scales, lowest, gamma, theta, aspect in itertools.product(
            [1, 2, 3, 5], [1.0, 2.0, 2.9, 3.0, 5.0], [0.3, 1.0, 3.0], [0.0, math.pi / 2, 2.5],
            [0.2, 1.0, 2.3]):
        if lowest > scales:
            continue
        c, s = math.cos(theta), math.sin(theta)
        reach = scales / min(1.0, gamma)
        kmax, lmax = int(reach) + 1, int(reach * aspect) + 1
        # brute force over the box: the effective wavenumber of every mode of the half plane
        found = any(lowest * (1 - 1e-12)
                    <= math.hypot(gamma * (k * c + l / aspect * s), -k * s + l / aspect * c)
                    <= scales * (1 + 1e-12)
                    for l in range(lmax + 1) for k in range(-kmax, kmax + 1) if l > 0 or k > 0)
        kw = dict(hurst=0.8, scales=scales, lowest=lowest, anisotropy=gamma, orientation=theta,
                  aspect=aspect, rms=0.01)
        if found:
            assert SelfAffineSurface(**kw).modes.kx.size > 0
        else:
            refused += 1
            with pytest.raises(ValidationError, match="SelfAffineSurface.scales"):
                SelfAffineSurface(**kw)
    assert refused > 10                               # the check is exercised both ways
