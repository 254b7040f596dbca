"""The areal spectral method against independent references: an elastic FFT contact solver
written here (the elastic limits of a viscoelastic solid), Hertz's sphere, and the dissipated
power."""
import numpy as np
import pytest

from viscocontact.areal.method import ArealSpectral
from viscocontact.areal.problem import ArealProblem
from viscocontact.areal.results import area_fraction
from viscocontact.rheology import Elastic, StandardLinearSolid

TWO_PI = 2 * np.pi
BETA = 10.0
SLS = StandardLinearSolid(beta=BETA)


def _self_affine(n, hurst=0.8, q_max=8, seed=0):
    """An isotropic self-affine height field: PSD ``∝ q^{-2(1+H)}`` for ``1 <= |q| <= q_max``,
    random phases, rms slope 0.1."""
    rng = np.random.default_rng(seed)
    qx = np.fft.rfftfreq(n, 1 / n)[None, :]
    qy = np.fft.fftfreq(n, 1 / n)[:, None]
    q = np.hypot(qx, qy)
    amp = np.where((q >= 1) & (q <= q_max), np.maximum(q, 1.0) ** (-(1 + hurst)), 0.0)
    spec = amp * np.exp(2j * np.pi * rng.random(amp.shape))
    h = np.fft.irfft2(spec, (n, n))
    gx = np.fft.irfft2(spec * 1j * qx, (n, n))
    gy = np.fft.irfft2(spec * 1j * qy, (n, n))
    return h * 0.1 / np.sqrt(np.mean(gx**2 + gy**2))


def _elastic_eigenvalues(n, modulus, across=None, aliases=6):
    """Piecewise-constant cells on an elastic half-space of modulus ``modulus`` (E0 units):
    ``Σ sinc sinc /(E |q|)`` over ``|l|, |k| <= aliases``, the outer two partial sums averaged;
    the modes constant along x (``qx = 0``) with the modulus ``across`` when given."""
    w = np.ones(2 * aliases + 1)
    w[[0, -1]], w[[1, -2]] = 0.25, 0.75
    nn = np.arange(n // 2 + 1.0)[None, :]
    jj = np.fft.fftfreq(n, 1 / n)[:, None]
    lam = np.zeros((n, n // 2 + 1))
    for l, wl in zip(range(-aliases, aliases + 1), w):
        for k, wk in zip(range(-aliases, aliases + 1), w):
            mx, my = nn + l * n, jj + k * n
            q = np.hypot(mx, my)
            q[q == 0] = np.inf
            lam += wl * wk * np.sinc(mx / n) * np.sinc(my / n) / q
    lam[0, 0] = 0.0
    lam[:, 1:] /= modulus
    lam[:, 0] /= modulus if across is None else across
    return lam


def _polonsky_keer(lam, heights, mean_pressure, tol=1e-11, max_iter=5000):
    """Polonsky & Keer's (1999) conjugate gradients under a given mean pressure, plain (no
    preconditioner): the reference solution and its gap."""
    shape = heights.shape

    def apply(v):
        return np.fft.irfft2(lam * np.fft.rfft2(v), shape)

    p = np.full(shape, mean_pressure)
    t = np.zeros(shape)
    g_old, delta = 1.0, 0.0
    for _ in range(max_iter):
        s = p > 0
        g = apply(p) - heights
        g -= g[s].mean()
        viol = max(np.abs(g[s]).max(), -min(g[~s].min(initial=0.0), 0.0))
        if viol < tol:
            return p, g
        big_g = np.sum(g[s] ** 2)
        t = np.where(s, g + delta * big_g / g_old * t, 0.0)
        g_old = big_g
        r = apply(t)
        r -= r[s].mean()
        tau = np.sum(g[s] * t[s]) / np.sum(r[s] * t[s])
        p = np.maximum(p - tau * t, 0.0)
        overlap = (p == 0) & (g < 0)
        delta = 0.0 if overlap.any() else 1.0
        p[overlap] -= tau * g[overlap]
        p *= mean_pressure / p.mean()
    raise AssertionError("the reference solver did not converge")


@pytest.mark.parametrize("zeta,modulus,load", [(1e-8, 1.0, 0.15), (1e8, BETA, 1.5)])
def test_elastic_limits_agree_with_an_independent_fft_solver(zeta, modulus, load):
    """An SLS at ζ = 1e-8 is elastic with E0, at ζ = 1e8 with E∞ = βE0 except on the modes
    constant along the sliding direction, which never change in time and see E0 at any speed:
    the contact area and the pressures of the reference solver on the same grid within 1e-3
    (the two operators differ by the reference's truncated alias sums, below 1e-3 of each
    eigenvalue). E∞ on every mode instead gives 8 % less area on this surface."""
    n = 64
    h = _self_affine(n)
    r = ArealSpectral().solve(ArealProblem(surface=h, rheology=SLS, zeta=zeta,
                                           mean_pressure=load), fields=True)
    assert r.converged
    amplitude = h.max()
    p, gap = _polonsky_keer(_elastic_eigenvalues(n, modulus, across=1.0), h / amplitude,
                            load)
    assert 0.1 < np.mean(p > 0) < 0.4
    assert r.extras["area_fraction"] == pytest.approx(area_fraction(p, gap), rel=1e-3)
    assert np.mean(r.fields["pressure"] > 0) == pytest.approx(np.mean(p > 0), rel=1e-3)
    assert np.abs(r.fields["pressure"] - p).max() <= 1e-3 * p.max()
    # no dissipation; μ from the slope vanishes to the discretisation error (μ/√m2 = 1.4e-3
    # and 4e-4 measured, against 0.7 at ζ = 1)
    assert abs(r.extras["friction_dissipation"]) < 1e-7
    assert abs(r.reduced_friction) < 3e-3


def _cap(n, radius):
    """One paraboloid cap per cell, ``-ρ²/(2R)`` with ``ρ`` the periodic distance to the
    centre of the cell."""
    x = TWO_PI * np.arange(n) / n
    d = np.mod(x, TWO_PI) - np.pi
    return -(d[None, :] ** 2 + d[:, None] ** 2) / (2 * radius)


def test_one_cap_per_cell_is_hertz():
    """Hertz: ``a³ = 3PR/(4E*)``, ``p0 = 2E*a/(πR)``; with ``a = 0.5`` (10 cells, a/L = 0.08) on
    128² cells the radius from the area and the central pressure within 1 % (radius measured
    1.8 %, 0.5 % and 0.14 % off at 64², 128², 256²)."""
    n, radius, a = 128, 4.0, 0.5
    h = _cap(n, radius)
    amplitude = (h - h.mean()).max()
    load = 4 * a**3 / (3 * radius)                        # P/E*, q0 = 1
    # p̃ = 2(1-ν²)p/(E0 q0 Λ) = 2p/(E* Λ̃): the mean over the cell (2π)²
    r = ArealSpectral().solve(ArealProblem(surface=h, rheology=Elastic(),
                                           mean_pressure=2 * load / amplitude / TWO_PI**2),
                              fields=True)
    assert r.converged and r.n_contacts == 1
    radius_found = np.sqrt(r.extras["area_fraction"] * TWO_PI**2 / np.pi)
    assert radius_found == pytest.approx(a, rel=1e-2)
    p0 = r.fields["pressure"].max() * amplitude / 2       # p/E*
    assert p0 == pytest.approx(2 * a / (np.pi * radius), rel=1e-2)
    assert r.extras["patches"]["mean_elongation"] == pytest.approx(1.0, abs=2e-2)


@pytest.mark.parametrize("zeta,bound", [(1e-2, 0.15), (1.0, 2e-3), (100.0, 2e-3)])
def test_friction_and_dissipated_power_converge_to_each_other(zeta, bound):
    """μ from the pressure and the slope, and the power fed into the solid over V·load (the
    loss weights), are positive and approach each other as the grid is refined: relative gaps
    at 32², 64², 128² measured 0.47, 0.23, 0.075 (ζ = 0.01, memory length ζ/β = 1e-3 against
    cells of 0.05), 0.030, 1.8e-3, 7.8e-4 (ζ = 1) and 0.26, 1.8e-3, 9.5e-4 (ζ = 100); on the
    same surface at 256² 0.016, 6.5e-4, 2.9e-4."""
    gaps = []
    for n in (32, 64, 128):
        h = _self_affine(128)[:: 128 // n, :: 128 // n]
        r = ArealSpectral().solve(ArealProblem(surface=h, rheology=SLS, zeta=zeta,
                                               mean_pressure=0.5))
        assert r.converged and r.friction > 0 and r.extras["dissipated_power"] > 0
        assert r.extras["dissipated_power"] == pytest.approx(
            r.extras["friction_dissipation"] * r.mean_pressure, rel=1e-12)
        gaps.append(abs(r.friction / r.extras["friction_dissipation"] - 1))
    assert gaps[2] < gaps[0] and gaps[2] < bound


def test_maugis_dugdale_on_a_self_affine_surface():
    """The cohesive law on a 64² self-affine surface (zone q0a0 = 2.25, 23 cells): the tips
    along every row settle, no cell carries more tension than σ̃0, the zones hold tension
    without contact, adhesion adds area at the same load (0.199 against 0.158), and μ stays
    within 1 % of the dissipated power (measured 1.8e-3)."""
    from viscocontact.adhesion import MaugisDugdale

    h = _self_affine(64)
    bare = ArealSpectral().solve(ArealProblem(surface=h, rheology=SLS, zeta=1.0,
                                              mean_pressure=0.5))
    r = ArealSpectral().solve(ArealProblem(surface=h, rheology=SLS, zeta=1.0, mean_pressure=0.5,
                                           adhesion=MaugisDugdale(gamma=1e-4, range=3e-2)),
                              fields=True)
    assert r.converged and r.residual < 1e-8
    law = r.extras["cohesive"]
    p = r.fields["pressure"]
    assert p.min() >= -law["strength"] * (1 + 1e-12)
    assert r.extras["cohesive"]["cohesive_cells"] > 0 and np.mean(p) == pytest.approx(0.5)
    assert r.extras["area_fraction"] > 1.1 * bare.extras["area_fraction"]
    assert r.friction == pytest.approx(r.extras["friction_dissipation"], rel=1e-2)


def test_pull_off_of_a_cap_in_the_dmt_limit():
    """Maugis-Dugdale on one paraboloid cap per cell at Maugis's λ = 0.05 (range h̃0 = 0.3, γ̃ =
    2.4e-4, R = 4): the largest tension over a scan of penetrations is Derjaguin's
    ``2πRΔγ`` within 2 % (measured 0.992 of it at 128², near Δ̃ = -0.005, with the cohesive
    zone alone or a contact of a few cells: the rigid limit's force ``2πRσ0(h0 - s)`` falls
    off linearly with the separation on the other side)."""
    from viscocontact.adhesion import MaugisDugdale

    n, radius, h0, gamma = 128, 4.0, 0.3, 2.4e-4
    md = MaugisDugdale(gamma=gamma, range=h0)
    lam = 2 * (np.pi * gamma / h0) * (radius / (np.pi**2 * gamma * 16 / 9)) ** (1 / 3)
    assert lam == pytest.approx(0.05, abs=2e-3)          # σ0/E* = πγ̃/h̃0, Δγ/E* = πγ̃
    h = _cap(n, radius)
    amplitude = (h - h.mean()).max()
    dmt = 2 * np.pi * radius * np.pi * gamma               # 2πRΔγ/E*, q0 = 1
    loads = []
    for d in np.arange(-0.007, -0.0025, 0.001):
        r = ArealSpectral().solve(ArealProblem(surface=h, rheology=Elastic(), penetration=d,
                                               adhesion=md))
        assert r.converged
        loads.append(r.mean_pressure * amplitude / 2 * TWO_PI**2)   # P/E*
    assert -min(loads) == pytest.approx(dmt, rel=2e-2)
