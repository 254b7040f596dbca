"""Near the elastic limits the areal grids are solved by Polonsky-Keer solves with the loss part
iterated: the plan and the result say so, and the solution is the elastic one of the limit's
modulus to the loss left at that ζ."""
import numpy as np
import pytest

from viscocontact.areal.method import ArealSpectral
from viscocontact.areal.problem import ArealProblem
from viscocontact.methods.spectral.solvers import LOSS_ITERATED
from viscocontact.rheology import Elastic, StandardLinearSolid

SLS = StandardLinearSolid(beta=10.0)


def _surface(n=64, seed=2):
    """A random band-limited surface (wavenumbers up to 8), q0·h of rms 0.1."""
    rng = np.random.default_rng(seed)
    spec = np.zeros((n, n // 2 + 1), complex)
    spec[:9, :9] = rng.standard_normal((9, 9)) + 1j * rng.standard_normal((9, 9))
    spec[-8:, :9] = rng.standard_normal((8, 9)) + 1j * rng.standard_normal((8, 9))
    spec[0, 0] = 0.0
    h = np.fft.irfft2(spec, (n, n))
    return 0.1 * h / h.std()


@pytest.mark.parametrize("zeta", [1e-8, 1e8])
def test_the_elastic_limits_are_solved_as_elastic(zeta):
    """ζ = 1e-8 is the relaxed solid (modulus 1), ζ = 1e8 the glassy one along the sliding
    direction (modes constant along it stay relaxed, so only the plan and solver are checked
    there); the relaxed limit's area and penetration are the elastic solve's within 5e-8 (measured 5e-9
    and 2e-10; the loss ratio of the 64² grid is 6e-7 at ζ = 1e-8)."""
    prob = ArealProblem(surface=_surface(), rheology=SLS, zeta=zeta, mean_pressure=0.2)
    plan = {step.stage: step for step in ArealSpectral().plan(prob).steps}
    assert "loss part iterated" in plan["solver"].choice
    r = ArealSpectral().solve(prob)
    assert r.converged and r.extras["solver"] == LOSS_ITERATED
    assert all(g["solver"] == LOSS_ITERATED for g in r.extras["grids"])
    if zeta < 1:
        elastic = ArealSpectral().solve(ArealProblem(surface=_surface(), rheology=Elastic(),
                                                     mean_pressure=0.2))
        assert r.area == pytest.approx(elastic.area, rel=5e-8)
        assert r.penetration == pytest.approx(elastic.penetration, rel=5e-8)
