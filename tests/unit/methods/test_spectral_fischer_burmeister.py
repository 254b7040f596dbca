"""The Fischer-Burmeister Newton method of the spectral grid: it solves the contact problem of a
strongly non-symmetric operator on which the active set's Newton steps do not settle, its answer
meets the contact conditions, and on a mild operator it gives the active set's answer."""
import numpy as np
import pytest

from viscocontact.methods.spectral import Spectral
from viscocontact.methods.spectral.fischer_burmeister import FISCHER_BURMEISTER, fischer_burmeister
from viscocontact.methods.spectral.grid import UniformGrid
from viscocontact.methods.spectral.grid_solution import violation
from viscocontact.methods.spectral.operator import convolve
from viscocontact.methods.spectral.primal_dual import active_set
from viscocontact.methods.spectral.solvers import grid_solve
from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import StandardLinearSolid

TOLERANCE = 1e-9


def grid(beta: float, zeta: float, points: int = 1024):
    """The operator and heights of the thesis's rough profile (seed 0) on ``points`` cells."""
    problem = ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0),
                             rheology=StandardLinearSolid(beta=beta), mean_pressure=0.25,
                             zeta=zeta)
    prep = Spectral().prepare(problem)
    cells = UniformGrid.of(prep.shape, points)
    return prep.operators.circulant(prep.kernel, points), cells.heights


def conditions(op, heights, sol, load):
    """The largest violation of the contact conditions and the load's relative misfit."""
    g = convolve(sol.pressure, op.eigenvalues) - (heights - 1.0 + sol.penetration)
    return violation(g, sol.pressure > 0), abs(sol.pressure.mean() - load) / load


def test_where_the_active_set_does_not_settle_the_fischer_burmeister_newton_method_solves():
    """β = 1000 at ζ = 1 (|Im Λ|/Re Λ above 5 on the grid): the active set does not converge
    in its 100 steps, the Fischer-Burmeister method converges from the same start and meets the
    contact conditions and the load, and the grid solve returns its answer."""
    op, heights = grid(1000.0, 1.0)
    assert np.nanmax(np.abs(op.eigenvalues.imag[1:] / op.eigenvalues.real[1:])) > 5
    start = (heights > 0.95).astype(float)
    plain = active_set(op, heights, mean_pressure=0.25, start=start, tolerance=TOLERANCE)
    assert not plain.converged
    sol = fischer_burmeister(op, heights, mean_pressure=0.25, start=start,
                             tolerance=TOLERANCE)
    assert sol.converged and sol.solver == FISCHER_BURMEISTER, sol.message
    res, load = conditions(op, heights, sol, 0.25)
    assert res <= 2 * TOLERANCE and load <= 1e-12 and np.min(sol.pressure) >= 0.0
    chosen = grid_solve(op, heights, mean_pressure=0.25, start=start, tolerance=TOLERANCE)
    assert chosen.converged and chosen.solver == FISCHER_BURMEISTER


@pytest.mark.parametrize("control", ["mean_pressure", "penetration"])
def test_on_a_mild_operator_it_gives_the_active_sets_answer(control):
    """β = 10 at ζ = 0.1, where the active set converges: the same pressure to the contact
    tolerance (over the solid's compliance), in either control."""
    op, heights = grid(10.0, 0.1, points=512)
    value = {"mean_pressure": 0.25, "penetration": 0.4}[control]
    start = (heights > 0.9).astype(float)
    ref = active_set(op, heights, start=start, tolerance=TOLERANCE, **{control: value})
    sol = fischer_burmeister(op, heights, start=start, tolerance=TOLERANCE, **{control: value})
    assert ref.converged and sol.converged, (ref.message, sol.message)
    assert np.array_equal(ref.pressure > 0, sol.pressure > 0)
    stiffness = 1.0 / np.mean(op.eigenvalues.real)
    assert np.max(np.abs(sol.pressure - ref.pressure)) <= 100 * TOLERANCE * stiffness
    assert sol.penetration == pytest.approx(ref.penetration, abs=10 * TOLERANCE)


def test_without_damping_the_active_set_stops_where_its_full_steps_do_not_settle():
    """β = 1000 at ζ = 1: ``damp=False`` stops within :data:`UNDAMPED_STEPS` steps (the set
    still changes, or a cycle of sets), not converged, having taken a small fraction of the
    products the damped steps spend; the grid solve then converges by the Fischer-Burmeister
    method from the same start."""
    from viscocontact.methods.spectral.primal_dual import UNDAMPED_STEPS

    op, heights = grid(1000.0, 1.0)
    start = (heights > 0.95).astype(float)
    kwargs = dict(mean_pressure=0.25, start=start, tolerance=TOLERANCE)
    full = active_set(op, heights, damp=False, **kwargs)
    damped = active_set(op, heights, **kwargs)
    assert not full.converged and not damped.converged
    assert full.iterations <= UNDAMPED_STEPS
    assert "full steps" in full.message or "cycle" in full.message, full.message
    assert full.applications < damped.applications / 5
    chosen = grid_solve(op, heights, **kwargs)
    assert chosen.converged and chosen.solver == FISCHER_BURMEISTER, chosen.message
    assert chosen.applications < damped.applications
