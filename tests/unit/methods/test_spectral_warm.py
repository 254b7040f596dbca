"""A warm start changes how fast the spectral method gets there, not where it gets."""
import pytest

from viscocontact.methods.spectral import Spectral
from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Bisection


def _problem(zeta):
    return ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=1),
                          rheology=StandardLinearSolid(beta=10.0), solver=Bisection(),
                          mean_pressure=0.3, zeta=zeta, method=Spectral())


def test_a_zeta_path_warm_start_lands_where_a_cold_solve_does():
    """Seed 1 of the thesis's rough profile from ζ = 0.3 to 0.1 (10 contacts): a ladder that
    began one grid below its target stopped at 2048 cells with Ã off by 3.9e-3 while its
    two-grid estimate said 8.4e-4. Warm and cold solves take the same grids and agree to the
    solver's precision, within the tolerance of the converged area."""
    before = _problem(0.3).solve()
    warm = _problem(0.1).solve(initial=before)
    cold = _problem(0.1).solve()
    edges = _problem(0.1).solve(initial=before.edges)
    assert warm.converged and cold.converged
    assert warm.extras["points"] == cold.extras["points"] == edges.extras["points"]
    assert warm.area == pytest.approx(cold.area, rel=1e-9)
    assert edges.area == warm.area                    # a result and its edges: the same answer
    fine = _problem(0.1)
    fine = ContactProblem(**{**{a: getattr(fine, a) for a in ("profile", "rheology", "solver",
                                                              "mean_pressure", "zeta")},
                             "method": Spectral(tolerance=1e-5)}).solve()
    assert abs(warm.area / fine.area - 1) <= warm.error_estimate <= 1e-3
