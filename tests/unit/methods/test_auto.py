"""The planned method: which method a scene gets, and the BEM finishing a grid that cannot."""
import pytest

from viscocontact.adhesion import EnergyBalance
from viscocontact.errors import ValidationError
from viscocontact.methods.auto import Auto
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Sinusoid
from viscocontact.reference import westergaard_area
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.scene import Scene
from viscocontact.solvers import Bisection, Newton
from viscocontact.methods.bem import BEM


def _wavy(**kw):
    kw.setdefault("rheology", Elastic())
    kw.setdefault("method", BEM())
    return ContactProblem(profile=Sinusoid(amplitude=0.1), solver=Bisection(), **kw)


def test_adhesionless_goes_to_the_grid_adhesive_to_the_bem():
    method, reason = Auto().choose(_wavy(mean_pressure=0.3))
    assert method.name == "spectral" and "adhesionless" in reason
    adhesive = _wavy(mean_pressure=0.3, adhesion=EnergyBalance(gamma=1e-4))
    method, reason = Auto().choose(adhesive)
    assert method.name == "bem" and "adhesi" in reason


def test_a_scene_without_method_is_planned():
    scene = Scene.from_toml('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\n'
                            'kind = "elastic"\n[load]\nmean_pressure = 0.3\n')
    assert scene.to_dict()["method"]["kind"] == "auto"
    result = ContactProblem.from_scene(scene).solve()
    assert result.method == "spectral" and result.error_estimate <= 1e-3
    assert result.area == pytest.approx(westergaard_area(0.3), rel=1e-3)
    assert result.extras["events"][0].startswith("method spectral: adhesionless scene")


def test_the_bem_finishes_what_the_grid_cannot():
    """A grid capped at 256 cells cannot reach 1e-6: the BEM solves from the grid's contact set,
    and its answer is Westergaard's to the BEM's own accuracy (2.2e-4 at 64 elements)."""
    result = _wavy(mean_pressure=0.3, method=Auto(tolerance=1e-6, max_points=256),
                   rheology=StandardLinearSolid(beta=10.0), zeta=0.0).solve()
    assert result.converged and result.method == "bem"
    assert any("stayed above the tolerance" in e for e in result.extras["events"])
    assert result.area == pytest.approx(westergaard_area(0.3), rel=5e-4)
    # without the finish, the grid's own answer says that it missed the tolerance, and warns
    from viscocontact.errors import AccuracyWarning

    with pytest.warns(AccuracyWarning, match="tolerance 1e-06 not met"):
        grid = _wavy(mean_pressure=0.3, method=Auto(tolerance=1e-6, max_points=256,
                                                    finish_with_bem=False)).solve()
    assert grid.method == "spectral" and grid.extras["tolerance_met"] is False
    assert grid.converged and grid.error_estimate > 1e-6


def test_the_grid_answer_stands_where_the_bem_finish_fails(monkeypatch):
    """The grid misses the tolerance and the BEM asked to finish does not converge: the grid's
    converged answer is returned with its estimate (it warns that the tolerance was not met),
    not the failure; the events say that the BEM was tried."""
    import attrs

    from viscocontact.errors import AccuracyWarning
    from viscocontact.result import SolveStatus

    solve = BEM.solve

    def fails(self, *args, **kwargs):
        return attrs.evolve(solve(self, *args, **kwargs), converged=False,
                            status=SolveStatus.NOT_CONVERGED,
                            message="contact set cycles (made to fail here)")

    monkeypatch.setattr(BEM, "solve", fails)
    auto = Auto(tolerance=1e-6, max_points=256)
    with pytest.warns(AccuracyWarning, match="tolerance 1e-06 not met"):
        result = _wavy(mean_pressure=0.3, method=auto).solve()
    grid = _wavy(mean_pressure=0.3, method=Auto(tolerance=1e-6, max_points=256,
                                                finish_with_bem=False)).solve()
    assert result.converged and result.method == "spectral"
    assert result.area == grid.area and result.error_estimate == grid.error_estimate > 1e-6
    assert any("did not converge (contact set cycles" in e and "grid's answer stands" in e
               for e in result.extras["events"])


def test_the_bem_solves_what_the_grid_does_not_converge_on():
    """A very stiff solid at ζ = 1 (β = 1e4: a trailing-edge layer of ζ/β = 1e-4 that no grid of
    the default ladder resolves): the active set does not settle, and the BEM solves the scene
    from first touch instead of the planned method reporting a failure. Its area agrees with the
    BEM on edge elements of 1e-5 (1.963126) to the BEM's discretisation error."""
    problem = ContactProblem(profile=Sinusoid(amplitude=0.1), solver=Newton(),
                             rheology=StandardLinearSolid(beta=1e4), zeta=1.0,
                             mean_pressure=0.49878, method=Auto())
    result = problem.solve()
    assert result.converged and result.method == "bem" and result.n_contacts == 1
    assert any("spectral solve did not converge" in e for e in result.extras["events"])
    assert result.area == pytest.approx(1.963126, abs=1e-4)


@pytest.mark.parametrize("field, value", [("tolerance", 0.0), ("tolerance", 1.0),
                                          ("max_points", 10), ("finish_with_bem", "yes")])
def test_bad_options_name_the_field(field, value):
    with pytest.raises((ValidationError, TypeError), match=field):
        Auto(**{field: value})


def test_an_adhesive_scene_solved_by_auto_is_the_bem_solve():
    adhesive = dict(mean_pressure=0.1, adhesion=EnergyBalance(gamma=1e-4), zeta=1.0,
                    rheology=StandardLinearSolid(beta=10.0))
    planned = ContactProblem(profile=Sinusoid(amplitude=0.1), solver=Newton(), method=Auto(),
                             **adhesive).solve()
    direct = ContactProblem(method=BEM(),
                            profile=Sinusoid(amplitude=0.1), solver=Newton(), **adhesive).solve()
    assert planned.method == direct.method == "bem"
    assert planned.area == direct.area and planned.friction == direct.friction


def test_solver_events_reach_logging(caplog, monkeypatch):
    """Each event of a solve is a record of the ``viscocontact.solve`` logger; a solve that
    does not converge warns there too."""
    import logging

    with caplog.at_level(logging.INFO, logger="viscocontact.solve"):
        result = _wavy(mean_pressure=0.3, method=Auto()).solve()
    messages = [r.getMessage() for r in caplog.records if r.name == "viscocontact.solve"]
    events = result.extras["events"]              # auto's choice, then the method's, as they came
    assert messages[0] == f"auto: {events[0]}"
    assert [m.split("] ", 1)[1] for m in messages[1:]] == events[1:]
    assert all(m.startswith("spectral: [") for m in messages[1:])
    caplog.clear()
    _starve(monkeypatch)
    stalled = ContactProblem(method=BEM(), profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                             solver=Newton(), adhesion=EnergyBalance(gamma=1e-4),
                             penetration=0.3)
    with caplog.at_level(logging.INFO, logger="viscocontact.solve"):
        out = stalled.solve()
    assert not out.converged
    assert any(r.levelno == logging.WARNING and "bem" in r.getMessage() for r in caplog.records)


def test_a_problem_refuses_a_method_that_is_not_one():
    from viscocontact.errors import ValidationError

    with pytest.raises(ValidationError, match="ContactProblem.method.*Spectral"):
        _wavy(mean_pressure=0.3, method="spectral")


def _starve(monkeypatch) -> None:
    """Make the BEM's approach fail (as one that runs out of evaluations does): the state it
    returns is not converged. The solve's other parts are the real ones."""
    import numpy as np

    from viscocontact.methods.bem.approach import Approach
    from viscocontact.methods.bem.state import Outcome, State

    def fails(self, target):
        return State(outcome=Outcome.NOT_CONVERGED, edges=np.array([-0.5, 0.5]),
                     residual=1.0, message="edge solve did not converge: starved")

    monkeypatch.setattr(Approach, "run", fails)


@pytest.fixture
def starved(monkeypatch):
    """A BEM whose approach fails (:func:`_starve`); the scenes' control."""
    _starve(monkeypatch)
    return {"penetration": 0.5}


def _cohesive(**kw):
    """A Maugis-Dugdale sinusoid (λ ≈ 1.2, the example scene's law) that the grid applies."""
    from viscocontact.adhesion import MaugisDugdale

    return ContactProblem(profile=Sinusoid(amplitude=0.05), rheology=Elastic(), solver=Newton(),
                          adhesion=MaugisDugdale(gamma=2e-5, range=0.005), **kw)


def test_the_grid_solves_an_adhesive_scene_the_bem_fails_on(starved):
    """A BEM that fails: the grid solves the scene instead, its answer is the spectral method's own, and the events say
    that the BEM ran first and why the grid took over."""
    from viscocontact.methods.spectral import Spectral

    assert not _cohesive(method=BEM(), **starved).solve().converged
    result = _cohesive(method=Auto(), **starved).solve()
    grid = _cohesive(method=Spectral(tolerance=1e-3), **starved).solve()
    assert result.converged and result.method == "spectral"
    assert result.error_estimate <= 1e-3
    assert result.area == grid.area and result.friction == grid.friction
    events = result.extras["events"]
    assert events[0].startswith("method bem: adhesive scene")
    assert events[1].startswith("method spectral: the bem solve did not converge")


def test_without_the_grid_the_bem_failure_is_reported(starved):
    """The same starved BEM with an energy balance (no law the grid applies), or with the
    fallback switched off: the BEM's failure is the result, and says that the grid was not
    tried where it does not apply."""
    off = _cohesive(method=Auto(spectral_fallback=False), **starved).solve()
    assert not off.converged and off.method == "bem"
    energy = _wavy(method=Auto(), adhesion=EnergyBalance(gamma=1e-4), **starved).solve()
    assert not energy.converged and energy.method == "bem"
    assert any(e.startswith("the spectral method was not tried: adhesive scene")
               for e in energy.extras["events"])


def test_a_bem_answer_short_of_the_tolerance_is_refined_on_its_branch():
    """A converged BEM answer whose estimate (5e-5) is above the tolerance asked (1e-5) is
    solved again from its own edges on a mesh twice as fine, before the grid (which reaches its
    equilibrium from the adhesionless contact) is tried: the answer is the finer mesh's solve
    from first touch (the same history), the change from the coarse answer is within the
    coarse estimate, and the events say so."""
    import numpy as np
    from viscocontact.adhesion import MaugisDugdale
    from viscocontact.methods.bem.estimate import finer
    from viscocontact.problem import Discretization

    def scene(**kw):
        return ContactProblem(profile=Sinusoid(amplitude=0.05), zeta=0.1, solver=Newton(),
                              rheology=StandardLinearSolid(beta=10.0), mean_pressure=0.1,
                              adhesion=MaugisDugdale(gamma=2e-5, range=0.005), **kw)

    coarse = scene(method=BEM()).solve()
    assert 1e-5 < coarse.error_estimate < 1e-4
    result = scene(method=Auto(tolerance=1e-5)).solve()
    direct = scene(method=BEM(), discretization=finer(Discretization())).solve()
    assert result.converged and result.method == "bem"
    assert result.error_estimate < 1e-5 and direct.error_estimate < 1e-5
    for name in ("area", "friction"):
        value, reference = getattr(result, name), getattr(direct, name)
        # the same root of the same mesh's equations, to the solver's tolerance
        assert value == pytest.approx(reference, rel=1e-7)
        scale = max(abs(getattr(coarse, name)), 1e-300)
        assert abs(getattr(coarse, name) - value) / scale <= coarse.error_estimate
    assert any("solved again with 128 elements per contact, kept" in e
               for e in result.extras["events"])
    assert np.array_equal(result.edges.shape, coarse.edges.shape)
