"""The spectral method's parts against independent references: the circulant against the BEM's
influence coefficients, the loss weights against the displacement's work, the edge maps against
Westergaard's edges, the result conventions against the BEM, and the contact conditions against
a dense operator built from the prepared kernel, on random scenes."""
import attrs
import numpy as np
import pytest
import scipy.fft
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from viscocontact.adhesion import EnergyBalance
from viscocontact.errors import AccuracyWarning, ValidationError
from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.kernels.layers import ConfinedLayer, FreeLayer
from viscocontact.methods.base import SolutionMethod
from viscocontact.methods.spectral import Spectral, SpectralPrepared
from viscocontact.methods.spectral.edges import contact_edges, runs
from viscocontact.methods.spectral.grid import UniformGrid, cells_inside, refine
from viscocontact.methods.spectral.operator import (Circulant, convolve, dissipation_weights,
                                                    eigenvalues, power)
from viscocontact.methods.spectral.solvers import polonsky_keer
from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.reference import westergaard_area
from viscocontact.result import SolveStatus
from viscocontact.rheology import Elastic, PronySeries, StandardLinearSolid
from viscocontact.solvers import Bisection
from viscocontact.methods.bem import BEM

SLS = StandardLinearSolid(beta=10.0)


def _problem(profile=None, rheology=None, zeta=0.0, kernel=None, **load):
    load = load or {"mean_pressure": 0.3}
    return ContactProblem(method=BEM(), profile=profile or Sinusoid(amplitude=0.1),
                          rheology=rheology or Elastic(), solver=Bisection(),
                          kernel=kernel or HalfPlane(), zeta=zeta, **load)


def _rough(seed=1, scales=16):
    return SelfAffineProfile(hurst=0.8, scales=scales, rms=0.01, seed=seed)


# ---- input -------------------------------------------------------------------------------
@pytest.mark.parametrize("field,value", [
    ("points", 63), ("points", 66.0), ("points", 32), ("points", 1 << 23), ("points", True),
    ("tolerance", 0.0), ("tolerance", 0.5), ("tolerance", float("nan")), ("tolerance", 1e-7),
    ("max_points", 1001), ("max_points", 16), ("workers", 0), ("friction_floor", -1.0),
    ("residual", 0.0), ("krylov_tolerance", 1.0), ("max_iterations", 1), ("max_updates", 0)])
def test_bad_input_names_the_field(field, value):
    with pytest.raises(ValidationError, match=f"Spectral.{field} = "):
        Spectral(**{field: value})


def test_points_above_max_points_are_rejected():
    with pytest.raises(ValidationError, match="Spectral.points = 4096.*max_points = 2048"):
        Spectral(points=4096, max_points=2048)


def test_is_a_solution_method_with_a_name():
    method = Spectral()
    assert isinstance(method, SolutionMethod) and method.name == "spectral"
    assert attrs.evolve(method, tolerance=1e-4).tolerance == 1e-4


def test_adhesive_scene_is_unsupported():
    prob = attrs.evolve(_problem(), adhesion=EnergyBalance(gamma=1e-4))
    method = Spectral()
    assert "adhesive" in method.unsupported(prob)
    assert method.unsupported(_problem()) is None
    with pytest.raises(ValidationError, match="adhesion"):
        method.solve(prob)
    steps = method.plan_steps(prob, prob.prepare())
    assert len(steps) == 1 and "not applicable" in steps[0].choice


# ---- operator ----------------------------------------------------------------------------
@pytest.mark.parametrize("kernel,rheology,zeta", [
    (HalfPlane(), Elastic(), 0.0), (HalfPlane(), SLS, 0.3),
    (ConfinedLayer(thickness=0.5, poisson=0.3), SLS, 1e-2),
    (FreeLayer(thickness=2.0, poisson=0.4), SLS, 3.0)])
def test_eigenvalues_are_those_of_the_bem_influence_coefficients(kernel, rheology, zeta):
    """One cell's displacement at every centre from the real-space tables of the BEM (Clausen,
    memory integrals, layer spline: eq. 4.32) has the FFT of the circulant's eigenvalues."""
    prep = kernel.prepare(rheology, zeta)
    n = 64
    h = 2 * np.pi / n
    x = h * np.arange(n)
    column = -prep.influence(x, np.array([-h / 2]), np.array([h / 2]))[:, 0]    # p = -σ
    lam = eigenvalues(prep, n)
    assert np.abs(lam - np.fft.rfft(column)).max() <= 1e-7 * np.abs(lam).max()
    assert Circulant.build(prep, n).symmetric == (rheology is Elastic() or zeta == 0.0 or
                                                  isinstance(rheology, Elastic))


def test_alias_sums_are_converged():
    prep = HalfPlane().prepare(SLS, 1e-4)
    lam = eigenvalues(prep, 256)
    many = eigenvalues(prep, 256, aliases=2048)
    assert np.abs(lam - many).max() <= 1e-7 * np.abs(many).max()


@pytest.mark.parametrize("kernel,zeta", [(HalfPlane(), 0.3), (HalfPlane(), 0.02),
                                         (ConfinedLayer(thickness=1.0, poisson=0.3), 1.0)])
def test_loss_weights_give_the_work_of_the_displacement(kernel, zeta):
    """``-(1/2π)∫ p u' dx`` of a piecewise-constant pressure, with ``u`` at the cell ends from the
    BEM's influence coefficients, equals the spectral power."""
    prep = kernel.prepare(SLS, zeta)
    n = 64
    h = 2 * np.pi / n
    rng = np.random.default_rng(3)
    p = np.where(rng.random(n) < 0.6, rng.random(n), 0.0)
    ends = h * (np.arange(n) + 0.5)
    lefts = h * (np.arange(n) - 0.5)
    u_ends = -prep.influence(ends, lefts, lefts + h) @ p
    work = -np.sum(p * (u_ends - np.roll(u_ends, 1))) / (2 * np.pi)
    assert work > 0
    assert power(p, dissipation_weights(prep, n)) == pytest.approx(work, rel=2e-5)


@pytest.mark.parametrize("kernel,zeta", [(HalfPlane(), 0.3), (HalfPlane(), 1.0),
                                         (ConfinedLayer(thickness=1.0, poisson=0.3), 1.0)])
def test_the_power_is_the_work_on_the_rise_of_the_displacement_across_the_cells(kernel, zeta):
    """``-Σ p_k [u(x_k + h/2) - u(x_k - h/2)]/2π`` with ``u`` the kernel's displacement of the
    piecewise-constant pressure (its Fourier series summed over 20000 aliases, no tail) is the
    spectral power to the truncation of that sum (measured 2e-11 to 4e-11, falling as the
    aliases' inverse square: 2e-9 to 4e-9 at 2000): the only grid friction that equals
    the dissipated power is the power itself (the rise of the rigid profile in eq. 4.16 differs
    from that of ``u`` by the rise of the gap, a discretisation error)."""
    prep = kernel.prepare(SLS, zeta)
    n, aliases = 64, 20000
    h = 2 * np.pi / n
    p = np.where(np.random.default_rng(3).random(n) < 0.6, np.random.default_rng(4).random(n), 0)
    m = np.arange(n // 2 + 1)[None, :] + n * np.arange(-aliases, aliases + 1)[:, None]
    am = np.where(m == 0, 1, np.abs(m)).astype(float)
    mult = np.asarray(prep.multiplier(am), complex)
    lam = np.where(m > 0, mult, np.conj(mult)) / am          # û_m = λ(m) p̂_m, λ(0) aside
    rise = np.where(m == 0, 0, lam * np.sinc(m / n) * 2j * np.sin(m * h / 2)).sum(axis=0)
    work = -(p @ scipy.fft.irfft(rise * scipy.fft.rfft(p), n)) / (2 * np.pi)
    assert work > 0
    assert power(p, dissipation_weights(prep, n)) == pytest.approx(work, rel=1e-9)


def test_elastic_kernel_dissipates_nothing():
    assert not np.any(dissipation_weights(HalfPlane().prepare(Elastic(), 0.0), 128))


# ---- grid and edges ----------------------------------------------------------------------
def test_runs_are_cyclic():
    assert runs(np.array([1, 1, 0, 0, 1, 0, 1, 1], bool)) == [(4, 1), (6, 4)]
    assert runs(np.ones(4, bool)) == [(0, 4)] and runs(np.zeros(4, bool)) == []


def test_refine_keeps_the_coinciding_centres():
    v = np.array([1.0, 2.0, 0.0, 4.0])
    assert np.array_equal(refine(v), [1.0, 1.5, 2.0, 1.0, 0.0, 2.0, 4.0, 2.5])


def test_cells_inside_contacts_wrap_the_period():
    grid = UniformGrid.of(Spectral().prepare(_problem()).shape, 16)      # peak at x = 0
    h = grid.cell
    inside = cells_inside(grid, [[-1.5 * h, 1.5 * h]])
    assert np.flatnonzero(inside).tolist() == [0, 1, 15]
    assert cells_inside(grid, np.array([0.0, 2 * np.pi])).all()


def test_grid_heights_are_the_profile_at_the_centres():
    shape = Spectral().prepare(_problem(profile=_rough(scales=50))).shape
    grid = UniformGrid.of(shape, 256)
    assert np.allclose(grid.heights, shape.heights(grid.x), rtol=0, atol=1e-13)
    h = grid.cell
    rise = shape.profile.heights(grid.x + h / 2) - shape.profile.heights(grid.x - h / 2)
    assert np.allclose(grid.rise, rise, rtol=0, atol=1e-15)


@pytest.mark.parametrize("n,bound", [(1000, 2.5e-2), (4000, 5e-3)])
def test_sub_cell_edges_are_westergaards(n, bound):
    """Edges to a fraction of a cell over the loads, finer as ``h/a`` falls (the maps are fitted
    at ``h/a`` below 1e-3)."""
    shape = Spectral().prepare(_problem()).shape
    grid = UniformGrid.of(shape, n)
    op = Circulant.build(HalfPlane().prepare(Elastic(), 0.0), n)
    worst = 0.0
    for load in (0.04, 0.13, 0.37, 0.58, 0.81, 0.93):
        sol = polonsky_keer(op.eigenvalues, grid.heights, mean_pressure=load, tolerance=1e-12,
                            preconditioner=op.inverse)
        gap = convolve(sol.pressure, op.eigenvalues) - (grid.heights - 1 + sol.penetration)
        edges = contact_edges(grid.start, grid.cell, sol.pressure, gap)
        a = westergaard_area(load) / 2
        assert edges.shape == (1, 2)
        worst = max(worst, np.abs(edges[0] - [-a, a]).max() / grid.cell)
    assert worst <= bound


# ---- results -----------------------------------------------------------------------------
@pytest.mark.parametrize("load", [{"mean_pressure": 0.0}, {"mean_pressure": -0.1},
                                  {"penetration": 0.0}, {"penetration": -0.2}])
def test_no_contact_is_reported_as_the_bem_reports_it(load):
    prob = _problem(**load)
    s, b = Spectral().solve(prob), prob.solve()
    assert s.status is b.status is SolveStatus.NO_CONTACT
    for key in ("area", "mean_pressure", "n_contacts", "full_contact", "converged", "residual",
                "min_gap", "message"):
        assert getattr(s, key) == getattr(b, key), key
    assert np.array_equal(s.penetration, b.penetration, equal_nan=True)
    assert s.edges.shape == b.edges.shape == (0, 2)
    assert s.extras["method"] == "spectral"


@pytest.mark.parametrize("kernel,load", [
    (HalfPlane(), {"mean_pressure": 1.3}),
    (ConfinedLayer(thickness=2.0, poisson=0.3), {"mean_pressure": 1.6}),       # closes at 1.47
    (ConfinedLayer(thickness=2.0, poisson=0.3), {"penetration": 2.4})])        # ... at 2.2
def test_closed_contact_is_reported_as_the_bem_reports_it(kernel, load):
    prob = _problem(kernel=kernel, rheology=SLS, zeta=0.5, **load)
    s, b = Spectral().solve(prob, fields=True), prob.solve(fields=True)
    assert s.full_contact and b.full_contact and s.status is b.status is SolveStatus.CONVERGED
    assert s.area == b.area == 2 * np.pi and s.n_contacts == b.n_contacts == 1
    assert s.edges.shape == (0, 2)
    for key in ("mean_pressure", "penetration", "friction", "reduced_friction"):
        assert getattr(s, key) == pytest.approx(getattr(b, key), rel=1e-9, abs=1e-12), key
    assert np.allclose(s.fields["pressure"], b.fields["pressure"], rtol=0, atol=1e-9)


def test_closed_contact_carries_its_power_and_estimates():
    """Both methods' closed contacts report the dissipated power and an error estimate: the
    area exact, μ and the power exact but for round-off on a grid four times the sinusoid's
    mode (the estimate's floor), and equal to each other within those estimates."""
    from viscocontact.contact.closure import ROUND_OFF

    prob = _problem(rheology=SLS, zeta=0.3, mean_pressure=3.0)
    for r in (Spectral().solve(prob), prob.solve()):
        assert r.full_contact and r.converged
        est = r.extras["estimates"]
        assert est["area"] == 0.0 and r.error_estimate == est["friction"] == ROUND_OFF
        assert abs(r.friction - r.extras["friction_dissipation"]) <= (
            (est["friction"] + est["dissipation"]) * est["friction_scale"])


@pytest.mark.parametrize("rheology, zeta", [(Elastic(), 0.0), (SLS, 0.5)])
def test_at_the_closing_penetration_of_an_incompressible_solid_the_contact_closes_at_the_least_load(
        rheology, zeta):
    """On a half-plane (``c0 = 0``) full contact fixes the penetration (Δ̃ = 1 for a sinusoid)
    and carries any load from the closing load up. Penetration control there gives the least
    load, the limit of the partial contacts: Westergaard's p̃∞ = 1 on the elastic sinusoid.
    Both methods report the same state; a larger penetration cannot be imposed."""
    prob = _problem(rheology=rheology, zeta=zeta, penetration=1.0)
    s, b = Spectral().solve(prob), prob.solve()
    for r in (s, b):
        assert r.converged and r.full_contact and r.area == 2 * np.pi, r.message
        assert "least load that keeps it closed" in r.message
    assert s.mean_pressure == pytest.approx(b.mean_pressure, rel=1e-9)
    if zeta == 0.0:
        assert s.mean_pressure == pytest.approx(1.0, rel=1e-9)            # Westergaard
    # the partial contacts' loads rise towards it as the penetration nears closure
    gaps = [s.mean_pressure - Spectral().solve(attrs.evolve(prob, penetration=d)).mean_pressure
            for d in (0.999, 0.9999)]
    assert 0 < gaps[1] < 0.5 * gaps[0]
    above = Spectral().solve(attrs.evolve(prob, penetration=1.001))
    assert not above.converged and "cannot be imposed" in above.message


def test_an_adhesive_closed_contact_under_its_closing_penetration_asks_for_the_load():
    """With adhesion the closed interface carries tension too, so at the closing penetration no
    least load stands out: the solve fails and says to give the mean pressure."""
    prob = attrs.evolve(_problem(penetration=1.0), adhesion=EnergyBalance(gamma=1e-3))
    r = prob.solve()
    assert not r.converged and r.full_contact
    assert "give the mean pressure" in r.message


def test_result_schema_and_contact_conditions():
    prob = _problem(profile=_rough(), rheology=SLS, zeta=0.1)
    r = Spectral().solve(prob, fields=True)
    assert r.converged and r.status is SolveStatus.CONVERGED
    for key in ("method", "error_estimate", "points", "tolerance_met", "friction_dissipation",
                "seconds", "events"):
        assert key in r.extras, key
    assert r.extras["method"] == "spectral" and r.extras["tolerance_met"]
    assert r.extras["error_estimate"] <= 1e-3
    assert r.edge_perturbation == 0.0 and r.zeta == 0.1
    assert r.function_evaluations > r.iterations > 0
    assert r.edges.shape == (r.n_contacts, 2) and np.all(np.diff(r.edges, axis=1) > 0)
    assert r.area == pytest.approx(np.sum(np.diff(r.edges, axis=1)))
    m2 = prob.profile.statistics().m2
    assert r.reduced_friction == pytest.approx(r.friction / np.sqrt(m2))
    f = r.fields
    assert len(f["x"]) == len(f["pressure"]) == r.extras["points"]
    assert np.mean(f["pressure"]) == pytest.approx(0.3, rel=1e-12)
    assert r.residual <= 1e-9 and r.min_gap >= -r.residual
    loaded = f["pressure"] > 0
    assert np.abs(f["gap"][loaded]).max() <= r.residual
    assert r.min_gap == pytest.approx(f["gap"][~loaded].min())


@pytest.mark.parametrize("rheology,options", [(Elastic(), {"max_iterations": 10}),
                                              (SLS, {"max_updates": 2})])
def test_a_solve_that_does_not_converge_says_so(rheology, options, monkeypatch):
    """Each solver on its budget: Polonsky-Keer on 10 steps; the active set on 2, then the
    Fischer-Burmeister method on 1 (on 2 it solves this grid: its second step keeps the contact
    set and solves it) and the active set from its contact set on 2."""
    from viscocontact.methods.spectral import solvers

    def short(*args, **kwargs):
        return fischer_burmeister(*args, **{**kwargs, "max_iterations": 1})

    fischer_burmeister = solvers.fischer_burmeister
    monkeypatch.setattr(solvers, "fischer_burmeister", short)
    prob = _problem(profile=_rough(scales=50), rheology=rheology, zeta=1e-2)
    r = Spectral(points=4096, **options).solve(prob)
    assert not r.converged and r.status is SolveStatus.NOT_CONVERGED
    assert "did not converge" in r.message and r.residual > 1e-9


def test_a_step_that_is_no_descent_direction_is_refused():
    """The active set's line search returns None where the merit rises at every fraction down to
    the smallest (the solve then stops, "no descent"), a fraction where it falls."""
    from viscocontact.methods.spectral.primal_dual import LINE_SEARCH_SMALLEST, _line_search

    p, g = np.array([1.0, 2.0]), np.array([1.0, 0.0])
    assert _line_search(p, g, np.array([1.0, 0.0]), np.array([1.0, 0.0]), 1.0, 0.0) is None
    assert _line_search(p, g, np.array([-0.5, 0.0]), np.array([-0.5, 0.0]), 1.0, 0.0) == 1.0
    # a descent only below an eighth of the step: the first fraction that gives it
    s = _line_search(p, g, np.array([-20.0, 0.0]), np.array([-20.0, 0.0]), 1.0, 0.0)
    assert LINE_SEARCH_SMALLEST <= s <= 1.0 / 16


def test_an_active_set_without_descent_stops(monkeypatch):
    """Steps that are no descent direction, STALLED_STEPS in a row from the first damped one, stop
    the solve at once ("no descent"), instead of a hundred steps of a thousandth (β = 1e4 at
    ζ = 1, where the active set does not settle)."""
    from viscocontact.methods.spectral import primal_dual
    from viscocontact.methods.spectral.primal_dual import STALLED_STEPS, UNDAMPED_STEPS

    prob = _problem(rheology=StandardLinearSolid(beta=1e4), zeta=1.0, mean_pressure=0.49878)
    # unpatched, the damped steps run out (100 of them) or stop where the line search finds no
    # descent (which of the two depends on round-off): the grid does not converge either way
    assert not Spectral(points=1024).solve(prob).converged
    monkeypatch.setattr(primal_dual, "_line_search", lambda *args: None)
    r = Spectral(points=1024).solve(prob)
    import re

    steps = re.search(r"no descent after (\d+) active-set steps", r.message)
    assert not r.converged and steps is not None
    assert STALLED_STEPS <= int(steps.group(1)) <= UNDAMPED_STEPS + STALLED_STEPS


def test_a_finer_grid_that_does_not_converge_leaves_the_last_converged_one(monkeypatch):
    """The ladder's answer where a refinement does not converge: the last converged grid, with
    its estimate from the grids below it, converged but short of the tolerance (the events say
    which grid failed)."""
    from viscocontact.methods.spectral import ladder

    prob = _problem(profile=_rough(scales=50), rheology=SLS, zeta=1e-2)
    method = Spectral(tolerance=1e-6, max_points=8192)
    reference = method.solve(prob)          # the ladder to 8192 cells, short of 1e-6
    assert reference.extras["points"] == 8192 and not reference.extras["tolerance_met"]
    solve = ladder.grid_solve

    def fails_at_8192(op, heights, **kw):
        out = solve(op, heights, **kw)
        return attrs.evolve(out, converged=False) if heights.size == 8192 else out

    monkeypatch.setattr(ladder, "grid_solve", fails_at_8192)
    with pytest.warns(AccuracyWarning, match="tolerance 1e-06 not met"):
        r = attrs.evolve(prob, method=method).solve()
    assert r.converged and r.extras["points"] == 4096 and not r.extras["tolerance_met"]
    coarse = reference.extras["coarse"]            # the 4096-cell grid of the full ladder
    assert coarse["points"] == 4096 and r.area == pytest.approx(coarse["area"], rel=1e-12)
    assert 0 < r.error_estimate < np.inf
    assert any("the answer is the 4096-cell grid's" in e for e in r.extras["events"])


def test_warm_start_gives_the_same_answer_with_fewer_iterations():
    prob = _problem(profile=_rough(scales=50), rheology=SLS, zeta=1e-2, mean_pressure=0.25)
    method = Spectral()
    prep = method.prepare(prob)
    cold = method.solve(prob, prepared=prep)
    for initial in (cold, cold.edges, cold.edges.ravel()):
        warm = method.solve(prob, initial=initial, prepared=prep)
        assert warm.area == pytest.approx(cold.area, rel=1e-9)
        assert warm.friction == pytest.approx(cold.friction, rel=1e-9)
        assert warm.iterations < cold.iterations
        assert warm.function_evaluations < cold.function_evaluations
    near = attrs.evolve(prob, mean_pressure=0.27)
    a, b = method.solve(near, prepared=prep), method.solve(near, initial=cold, prepared=prep)
    # along a sweep the warm start begins on the previous point's grid: its answer may be on
    # another grid than a cold solve's, the same to within both estimates
    bound = (a.extras["error_estimate"] + b.extras["error_estimate"]) * a.area
    assert abs(b.area - a.area) <= bound and b.iterations < a.iterations


def test_warm_start_from_a_closed_contact():
    closed = Spectral().solve(_problem(mean_pressure=1.2))
    assert closed.full_contact
    prob = _problem(mean_pressure=0.6)
    assert Spectral().solve(prob, initial=closed).area == pytest.approx(
        Spectral().solve(prob).area, rel=1e-9)


def test_prepared_operators_are_kept_and_reused():
    prob = _problem(rheology=SLS, zeta=0.2)
    method = Spectral()
    prep = method.prepare(prob)
    assert isinstance(prep, SpectralPrepared) and len(prep.operators) == 0
    first = method.solve(prob, prepared=prep)
    built = len(prep.operators)
    assert built > 0
    again = method.solve(prob, prepared=prep)
    assert len(prep.operators) == built and again.area == first.area
    plain = method.solve(prob, prepared=prob.prepare())         # a BEM Prepared works too
    assert plain.area == first.area


def test_penetration_control_inverts_load_control():
    load = _problem(profile=_rough(), rheology=SLS, zeta=0.1, mean_pressure=0.3)
    a = Spectral(points=2048).solve(load)
    b = Spectral(points=2048).solve(attrs.evolve(load, mean_pressure=None,
                                                 penetration=a.penetration))
    assert b.converged and b.mean_pressure == pytest.approx(0.3, rel=1e-8)
    assert b.area == pytest.approx(a.area, rel=1e-8)


def test_plan_names_the_grid_and_the_solver():
    for rheology, zeta, solver in ((Elastic(), 0.0, "Polonsky-Keer"), (SLS, 1.0, "active set")):
        prob = _problem(profile=_rough(scales=50), rheology=rheology, zeta=zeta)
        steps = {s.stage: s for s in Spectral().plan_steps(prob, prob.prepare())}
        assert solver in steps["solver"].choice
        assert "1024 then 2048 cells" in steps["grid"].choice
        assert "shortest wavelength" in steps["grid"].reason
    steps = {s.stage: s for s in Spectral(points=512).plan_steps(_problem(), None)}
    assert steps["grid"].choice.startswith("512 cells")


# ---- contact conditions on random scenes -------------------------------------------------
@st.composite
def scenes(draw):
    if draw(st.booleans()):
        profile = Sinusoid(amplitude=draw(st.floats(1e-3, 1.0)))
    else:
        profile = SelfAffineProfile(hurst=draw(st.floats(0.4, 1.0)),
                                    scales=draw(st.integers(2, 24)),
                                    rms=draw(st.floats(1e-3, 0.1)),
                                    seed=draw(st.integers(0, 2**32 - 1)))
    zeta = draw(st.one_of(st.just(0.0), st.floats(-3.0, 2.0).map(lambda e: 10.0**e)))
    if not zeta:
        rheology = Elastic()
    elif draw(st.booleans()):
        rheology = StandardLinearSolid(beta=draw(st.floats(1.5, 100.0)))
    else:                                  # three arms over four decades of relaxation time
        rheology = PronySeries(relaxed_modulus=1.0,
                               moduli=draw(st.lists(st.floats(0.1, 30.0), min_size=3,
                                                    max_size=3)),
                               times=[1e-2, 1.0, 1e2])
    kernel = draw(st.sampled_from([HalfPlane(), ConfinedLayer(thickness=1.0, poisson=0.3)]))
    control = draw(st.sampled_from(["mean_pressure", "penetration"]))
    value = draw(st.floats(0.02, 0.9))
    return ContactProblem(method=BEM(),
                          profile=profile, rheology=rheology, kernel=kernel, solver=Bisection(),
                          zeta=zeta, **{control: value})


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenes())
def test_contact_conditions_hold_on_random_scenes(prob):
    """p >= 0, g >= 0, p·g = 0 and the load, with the gap from the BEM's influence
    coefficients (an operator built independently of the FFT circulant)."""
    prep = prob.prepare()
    r = Spectral(points=256).solve(prob, fields=True, prepared=prep)
    assert r.converged, r.message
    p = r.fields["pressure"]
    if prob.mean_pressure is not None:
        assert np.mean(p) == pytest.approx(prob.mean_pressure, rel=1e-12)
    assert np.all(p >= -1e-9)
    if r.full_contact:
        return
    x = r.fields["x"]
    h = 2 * np.pi / len(x)
    u = -prep.kernel.influence(x, x - h / 2, x + h / 2) @ p
    gap = u - (prep.shape.heights(x) - 1 + r.penetration)
    scale = 1e-7 * max(1.0, float(np.max(np.abs(u))))
    loaded = p > 0
    assert np.all(gap[~loaded] >= -scale)
    assert np.all(np.abs(gap[loaded]) <= scale)
    assert np.max(np.abs(p * gap)) <= scale * max(1.0, float(p.max()))
    assert r.mean_pressure == pytest.approx(np.mean(p), rel=1e-12)


@pytest.mark.parametrize("control", [{"penetration": 0.3}, {"mean_pressure": 0.3}])
def test_polonsky_keer_recovers_from_a_start_without_descent(control):
    """A start with no loaded cell (penetration control) or a single one (load control, where
    the projected gradient vanishes) still converges, to the same pressure as the default."""
    n = 64
    op = Circulant.build(HalfPlane().prepare(Elastic(), 0.0), n)
    r = np.cos(2 * np.pi * np.arange(n) / n)
    start = np.zeros(n)
    if "mean_pressure" in control:
        start[5] = 1.0
    ref = polonsky_keer(op.eigenvalues, r, tolerance=1e-12, **control)
    for pre in (None, op.inverse):
        sol = polonsky_keer(op.eigenvalues, r, start=start, preconditioner=pre, tolerance=1e-12,
                            **control)
        assert sol.converged and np.allclose(sol.pressure, ref.pressure, rtol=0, atol=1e-9)
