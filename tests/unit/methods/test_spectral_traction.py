"""A smooth traction law (Lennard-Jones) cell by cell on the uniform grid: the grid's law of each
model, the rigid limit, the areal method on an extruded profile against the 1D method, and a
tension that does not settle reported as such."""
import numpy as np
import pytest

from viscocontact.adhesion import EnergyBalance, LennardJones, MaugisDugdale, NoAdhesion
from viscocontact.areal.method import ArealSpectral
from viscocontact.areal.problem import ArealProblem
from viscocontact.methods.spectral import Spectral
from viscocontact.methods.spectral.cohesive import GridLaw, cohesive_solve
from viscocontact.methods.spectral.grid import UniformGrid
from viscocontact.methods.spectral.traction import GridTraction, grid_law
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.solvers import Bisection

SLS = StandardLinearSolid(beta=10.0)
LJ = LennardJones(gamma=1e-4, range=3e-2)


def test_the_grid_law_of_each_model():
    """A Dugdale form is solved by its tips, a traction alone by the tension; no adhesion and
    the energy balance (no traction) have none. The smooth law's tension is the model's."""
    md = grid_law(MaugisDugdale(gamma=1e-4, range=1e-2), 0.1)
    assert isinstance(md, GridLaw) and md.strength == pytest.approx(2 * np.pi * 1e-4 / 1e-3)
    lj = grid_law(LJ, 0.1)
    assert isinstance(lj, GridTraction)
    assert lj.strength == pytest.approx(LJ.strength(0.1))
    g = np.linspace(0.0, 2.0, 7)
    np.testing.assert_allclose(lj.tension(g), LJ.traction(0.1 * g) / 0.1, rtol=1e-15)
    assert float(LJ.traction(0.1 * lj.opening)) <= 1e-6 * LJ.strength(1.0)
    assert grid_law(NoAdhesion(), 0.1) is None
    assert grid_law(LennardJones(gamma=0.0, range=0.1), 0.1) is None
    assert grid_law(EnergyBalance(gamma=1e-4), 0.1) is None


@pytest.mark.parametrize("control", [dict(mean_pressure=0.2), dict(penetration=-0.05)])
def test_an_extruded_profile_with_lennard_jones_is_the_1d_solution(control):
    """ζ = 1 (the active set, non-symmetric operator): the areal method on the profile extruded
    along y gives the 1D method's area, load, penetration and μ on the same grid within 1e-8
    (measured 1e-10; at Δ̃ = -0.05 the solid is held by tension without contact)."""
    prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=SLS, solver=Bisection(),
                          zeta=1.0, adhesion=LJ, **control)
    prep = prob.prepare()
    grid = UniformGrid.of(prep.shape, 512)
    heights = np.broadcast_to(grid.heights * prep.shape.amplitude, (8, 512))
    r1 = Spectral(points=512).solve(prob)
    r2 = ArealSpectral().solve(ArealProblem(surface=heights, rheology=SLS, zeta=1.0,
                                            adhesion=LJ, **control))
    assert r1.converged and r2.converged
    assert r2.mean_pressure == pytest.approx(r1.mean_pressure, rel=1e-8)
    assert r2.penetration == pytest.approx(r1.penetration, rel=1e-8)
    assert r2.area == pytest.approx(r1.area, rel=1e-8, abs=1e-12)
    assert r2.friction == pytest.approx(r1.friction, rel=1e-8)
    assert r1.residual < 1e-8
    if "penetration" in control:
        assert r1.n_contacts == 0 and r1.mean_pressure < 0


def test_the_rigid_limit_is_the_traction_of_the_rigid_gap():
    """A law too weak to deform the solid much: the load is minus the mean tension of the
    undeformed gap, the difference first order in the deformation, i.e. in γ̃ (measured 6.5e-4
    at γ̃ = 1e-7 and 6.5e-3 at 1e-6: ten times as much)."""
    deviations = []
    for gamma in (1e-7, 1e-6):
        weak = LennardJones(gamma=gamma, range=0.03)
        prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                              solver=Bisection(), adhesion=weak, penetration=-0.01)
        r = Spectral(points=256).solve(prob)
        assert r.converged and r.n_contacts == 0
        prep = prob.prepare()
        grid = UniformGrid.of(prep.shape, 4096)
        gap = -(grid.heights - 1.0 - 0.01)                 # units of the amplitude
        rigid = -float(np.mean(weak.traction(0.1 * gap))) / 0.1
        deviations.append(r.mean_pressure / rigid - 1.0)
    assert abs(deviations[0]) < 1e-3
    assert deviations[1] / deviations[0] == pytest.approx(10.0, rel=0.05)


def test_a_tension_that_does_not_settle_is_reported():
    """Two iterations of the tension are not enough: not converged, and the message says so."""
    prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                          solver=Bisection(), adhesion=LJ, penetration=0.05)
    prep = prob.prepare()
    grid = UniformGrid.of(prep.shape, 256)
    op = Spectral().prepare(prob).operators.circulant(prep.kernel, 256)
    out = cohesive_solve(op, grid.heights, grid_law(LJ, prep.shape.amplitude),
                         penetration=0.05, start=np.zeros(256), max_sets=2)
    assert not out.solution.converged
    assert "did not settle in 2" in out.solution.message


def test_a_law_that_never_falls_off_is_refused():
    """A plugin's traction that stays at its peak at every gap has no range for the grid."""
    import attrs

    @attrs.frozen(kw_only=True)
    class Flat(LennardJones):
        def traction(self, gap):
            return np.full(np.shape(gap), self.strength(1.0))

    from viscocontact.errors import ValidationError

    with pytest.raises(ValidationError, match="Flat.traction"):
        grid_law(Flat(gamma=1e-3, range=0.01), 0.1)


def test_auto_sends_a_traction_law_to_the_grid():
    """No edge condition for the BEM: ``auto`` takes the spectral method, which solves it."""
    from viscocontact.methods.auto import Auto

    prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                          solver=Bisection(), adhesion=LJ, mean_pressure=0.2)
    method, why = Auto().choose(prob)
    assert method.name == "spectral" and "no edge condition" in why
    r = prob.solve()
    assert r.converged and r.extras["method"] == "spectral"
