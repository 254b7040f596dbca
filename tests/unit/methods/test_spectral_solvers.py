"""The grid solvers' fast paths against the general ones: the loss part iterated with
Polonsky-Keer solves (a nearly elastic operator) against the active set, the 2D product by
one-axis transforms against ``rfft2``. (The single-precision preconditioner of the active set on
2D grids is checked by the areal tests: a profile extruded along ``y`` gives the 1D method's
solution, whose preconditioner is in double precision, to 1e-8.)"""
import math
import re

import numpy as np
import pytest
import scipy.fft

import viscocontact.methods.spectral.solvers as solvers
from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.methods.spectral.grid import UniformGrid
from viscocontact.methods.spectral.operator import Circulant, convolve
from viscocontact.methods.spectral.solvers import (ACTIVE_SET, LOSS_ITERATED, active_set,
                                                   grid_solve, loss_iterated, loss_ratio)
from viscocontact.methods.spectral import Spectral
from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.solvers import Bisection

SLS = StandardLinearSolid(beta=10.0)
N = 2048


def _scene(zeta, rheology=SLS):
    """The operator on ``N`` cells and the heights of the thesis's kind of rough profile."""
    prob = ContactProblem(method=Spectral(), profile=SelfAffineProfile(hurst=0.8, scales=50,
                                                                       rms=0.01, seed=3),
                          rheology=rheology, kernel=HalfPlane(), solver=Bisection(), zeta=zeta,
                          mean_pressure=0.25)
    grid = UniformGrid.of(Spectral().prepare(prob).shape, N)
    return Circulant.build(HalfPlane().prepare(rheology, zeta), N), grid.heights


def test_loss_ratio_is_tan_delta_at_the_grid_frequencies():
    """0 for an elastic solid (round-off of the closed form's FFT); for a standard linear solid
    proportional to ζ at small ζ and below the multiplier's largest ``Im λ/Re λ`` over the grid's
    wavenumbers (``(1 - 1/β) m ζ`` at ``m = N/2``; the grid's alias sums at the highest modes
    lower it: 2.7e-6 against 9.2e-6 at ζ = 1e-8), below the peak of tan δ, ``(β - 1)/(2√β)``
    = 1.42 at β = 10, near it (1.40 at ζ = 1e-2)."""
    assert loss_ratio(_scene(0.0, Elastic())[0].eigenvalues) < 1e-10
    ratios = {}
    for zeta in (1e-8, 1e-6, 1e-2):
        lam = _scene(zeta)[0].eigenvalues
        m = np.arange(1, N // 2 + 1, dtype=float)
        multiplier = np.asarray(HalfPlane().prepare(SLS, zeta).multiplier(m))
        ratios[zeta] = loss_ratio(lam)
        assert 0 < ratios[zeta] <= np.max(multiplier.imag / multiplier.real)
    assert ratios[1e-6] == pytest.approx(100 * ratios[1e-8], rel=1e-4)
    assert 1.0 < ratios[1e-2] <= 9.0 / (2 * math.sqrt(10.0))


@pytest.mark.parametrize("zeta", [1e-8, 1e-6, 3e-4])
@pytest.mark.parametrize("control", [{"mean_pressure": 0.25}, {"penetration": 0.4}])
def test_loss_iteration_gives_the_active_set_solution(zeta, control):
    """The same discrete solution as the active set (the problem has one), in at most
    ``1 + log(tolerance)/log κ`` Polonsky-Keer solves after the first (each contracts the error
    by the loss ratio κ)."""
    op, heights = _scene(zeta)
    kappa = loss_ratio(op.eigenvalues)
    assert kappa <= solvers.LOSS_ITERATION
    fast = loss_iterated(op, heights, tolerance=1e-11, **control)
    assert fast.converged and fast.solver == LOSS_ITERATED and fast.residual <= 1e-11
    start = grid_solve(Circulant(points=N, eigenvalues=op.eigenvalues.real.astype(complex),
                                 inverse=op.inverse.real.astype(complex), symmetric=True),
                       heights, tolerance=1e-6, **control).pressure
    slow = active_set(op, heights, start=start, tolerance=1e-11, **control)
    assert slow.converged and slow.solver == ACTIVE_SET
    assert np.max(np.abs(fast.pressure - slow.pressure)) <= 1e-8 * np.max(slow.pressure)
    assert fast.penetration == pytest.approx(slow.penetration, abs=1e-9)
    solves = int(re.search(r"in (\d+) Polonsky-Keer solves", fast.message).group(1))
    assert solves <= 2 + math.ceil(math.log(1e-11) / math.log(kappa))


def test_grid_solve_hands_a_stalled_loss_iteration_to_the_active_set(monkeypatch):
    """With one Polonsky-Keer solve allowed (κ = 0.08 needs several) the active set finishes
    from its pressure, converged, with the counts of both."""
    zeta = 3e-4
    op, heights = _scene(zeta)
    assert 0.05 < loss_ratio(op.eigenvalues) <= solvers.LOSS_ITERATION
    reference = grid_solve(op, heights, mean_pressure=0.25, tolerance=1e-11)
    assert reference.converged and reference.solver == LOSS_ITERATED
    monkeypatch.setattr(solvers, "LOSS_SOLVES", 1)
    handed = grid_solve(op, heights, mean_pressure=0.25, tolerance=1e-11)
    assert handed.converged and handed.solver == ACTIVE_SET
    assert np.max(np.abs(handed.pressure - reference.pressure)) <= 1e-8 * reference.pressure.max()


def test_the_2d_product_is_that_of_rfft2():
    rng = np.random.default_rng(0)
    ny, nx = 48, 64
    values = rng.standard_normal(ny * nx)
    spectrum = rng.standard_normal((ny, nx // 2 + 1)) + 1j * rng.standard_normal((ny, nx // 2 + 1))
    spectrum[:, 0] = spectrum[:, 0].real          # a real operator's self-conjugate columns
    spectrum[:, -1] = spectrum[:, -1].real
    direct = scipy.fft.irfft2(spectrum * scipy.fft.rfft2(values.reshape(ny, nx)), (ny, nx))
    out = convolve(values, spectrum)
    assert out.dtype == np.float64 and out.shape == (ny * nx,)
    assert np.max(np.abs(out - direct.ravel())) <= 1e-14 * np.max(np.abs(direct))
    single = convolve(values, spectrum.astype(np.complex64))
    assert single.dtype == np.float32
    assert np.max(np.abs(single - direct.ravel())) <= 1e-5 * np.max(np.abs(direct))

