"""ζ-sweeps: chains, continuation, failures stored, realizations."""
import attrs
import numpy as np
import pytest

from viscocontact.errors import ValidationError
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.scene import Scene
from viscocontact.studies import Sweep, run
from viscocontact.studies.base import secant_start
from viscocontact.studies.parallel import single_blas_thread


def test_chains_pair_loads_seeds(adhesive):
    sweep = Sweep(scene=adhesive, zetas=[0.1, 1.0], loads=[0.1, 0.2])
    assert sweep.variants == ("adhesive", "adhesionless")
    chains = sweep.chains()
    assert len(chains) == 4 and all(c.zetas == (0.1, 1.0) for c in chains)
    assert [c.labels["variant"] for c in chains] == ["adhesive"] * 2 + ["adhesionless"] * 2
    assert chains[2].scene["adhesion"] == {"kind": "none"} and chains[2].labels["gamma"] == 0.0
    assert chains[0].labels["gamma"] == 3e-5 and chains[1].labels["load"] == 0.2
    assert Sweep(scene=adhesive, zetas=[1.0], pair=False).variants == ("adhesive",)
    single = Sweep(scene=adhesive, zetas=[0.1, 1.0, 10.0], continuation=False)
    assert [c.zetas for c in single.chains()][:3] == [(0.1,), (1.0,), (10.0,)]
    assert len(single.chains()) == 6


@pytest.mark.parametrize("options,field", [
    ({"zetas": [-1.0]}, "sweep.zetas"),
    ({"zetas": []}, "sweep.zetas"),
    ({"zetas": [1.0], "control": "force"}, "sweep.control"),
    ({"zetas": [1.0], "seeds": [0, 1]}, "profile.seed"),     # a sinusoid has no seed
    ({"zetas": [1.0], "loads": [float("nan")]}, "sweep.loads"),
])
def test_bad_parameters(adhesionless, options, field):
    with pytest.raises(ValidationError) as info:
        Sweep(scene=adhesionless, **options)
    assert info.value.field == field


def test_points_are_continued_from_their_neighbour(tmp_path, adhesionless, mesh):
    """The stored points are the ContactProblem solves of a hand-written continuation (from the
    previous point's edges, and from the secant through the previous two once there are two)."""
    zetas = [0.1, 1.0, 10.0]
    data = run(Sweep(scene=adhesionless, zetas=zetas, discretization=mesh, fields=True),
               tmp_path / "s.h5", progress=None)
    assert data.complete and len(data) == 3
    assert data.points["started_from"].tolist() == ["first touch", "neighbour", "neighbour"]
    previous, done = None, []
    for i, zeta in enumerate(zetas):
        problem = ContactProblem.from_scene(attrs.evolve(adhesionless, zeta=zeta),
                                            discretization=Discretization(**mesh))
        start = previous
        if i >= 2 and done[-1].n_contacts == done[-2].n_contacts:
            records = [{"converged": r.converged, "n_contacts": r.n_contacts,
                        "full_contact": r.full_contact, "edges": r.edges.ravel(), "zeta": z}
                       for r, z in zip(done[-2:], zetas[i - 2:i])]
            predicted = secant_start(records, "zeta", zeta, log=True)
            start = previous if predicted is None else predicted
        with single_blas_thread():
            previous = problem.solve(initial=start)
        done.append(previous)
        assert data.points["area"][i] == previous.area
        assert data.points["friction"][i] == previous.friction
        assert np.array_equal(data.points["edges"][i], previous.edges.ravel())
    table = data.table("area")
    assert table.shape == (1, 1, 1, 3) and np.array_equal(table[0, 0, 0], data.points["area"])
    fields = data.fields(2)
    assert set(fields) == {"x", "pressure", "displacement", "gap"}
    assert len(fields["x"]) == Discretization().check_points and fields["gap"].min() > -1e-9


def test_default_study_is_a_sweep_from_first_touch():
    from viscocontact.study import WavyStudy

    sweep = WavyStudy().sweep()
    assert sweep.variants == ("adhesive", "adhesionless") and not sweep.continuation
    assert len(sweep.zetas) == 15 and len(sweep.chains()) == 30
    assert sweep.scene.adhesion.gamma == pytest.approx(0.01 * 0.1**2)


def test_a_failing_point_is_stored_and_the_sweep_goes_on(tmp_path, adhesionless, monkeypatch,
                                                        mesh):
    original = ContactProblem.solve

    def solve(self, *args, **kwargs):
        if self.zeta == 1.0:
            raise RuntimeError("boom")
        return original(self, *args, **kwargs)

    monkeypatch.setattr(ContactProblem, "solve", solve)
    data = run(Sweep(scene=adhesionless, zetas=[0.1, 1.0, 10.0], discretization=mesh),
               tmp_path / "s.h5", progress=None)
    assert data.points["status"].tolist() == ["converged", "error", "converged"]
    assert data.points["message"][1] == "RuntimeError: boom"
    assert data.points["started_from"][2] == "neighbour"        # from ζ = 0.1, the last good one
    assert data.failed.tolist() == [1] and np.isnan(data.table("area")[0, 0, 0, 1])


def test_realizations_of_a_single_mode_profile_agree(tmp_path, mesh):
    """A one-scale self-affine profile is a sinusoid with a random phase: every seed gives the
    same contact area, and the band collapses onto the mean."""
    scene = Scene.from_dict({
        "profile": {"kind": "self-affine", "hurst": 0.8, "scales": 1, "rms": 0.0707},
        "rheology": {"kind": "standard-linear-solid", "beta": 10.0}, "solver": {"kind": "newton"},
        "load": {"penetration": 0.5}, "sliding": {"zeta": 1.0}})
    data = run(Sweep(scene=scene, zetas=[0.3, 3.0], seeds=[0, 1], discretization=mesh),
               tmp_path / "r.h5", progress=None)
    assert data.seeds.tolist() == [0, 1] and data.axes()["seed"] == (0, 1)
    table = data.table("area")
    assert table.shape == (1, 1, 2, 2)
    assert np.allclose(table[0, 0, 0], table[0, 0, 1], rtol=1e-6)
    band = data.band("area")
    assert band.count.tolist() == [[[2, 2]]]
    assert np.allclose(band.upper, band.mean, rtol=1e-5) and np.all(band.upper >= band.lower)
    assert data.points["control"].tolist() == ["penetration"] * 4


def test_time_limit_stores_the_point_as_an_error_and_the_chain_goes_on(tmp_path, adhesive,
                                                                       adhesionless, mesh):
    """A point past the time limit is an error with its reason; the next point of the chain
    is still computed. 1 ms is far below an adhesive first touch (a second or more); the
    adhesionless twin solved with a generous limit is unaffected."""
    sweep = Sweep(scene=adhesive, zetas=[1.0, 10.0], pair=False, discretization=mesh)
    data = run(sweep, tmp_path / "s.h5", progress=None, time_limit=1e-3)
    p = data.points
    assert len(p["status"]) == 2
    assert all(m == "TimeLimitExceeded: time limit of 0.001 s reached" for m in p["message"])
    assert not p["converged"].any()
    ok = run(Sweep(scene=adhesionless, zetas=[1.0], discretization=mesh), tmp_path / "t.h5",
             progress=None, time_limit=600.0)
    assert ok.points["converged"].all()


@pytest.mark.parametrize("limit", [0.0, -1.0, float("nan"), float("inf"), "10", True])
def test_bad_time_limit(tmp_path, adhesionless, limit):
    with pytest.raises(ValidationError) as info:
        run(Sweep(scene=adhesionless, zetas=[1.0]), tmp_path / "s.h5", progress=None,
            time_limit=limit)
    assert info.value.field == "time_limit"


@pytest.mark.parametrize("step", [0, -0.5, 10.5, float("nan"), "0.25", True])
def test_bad_zeta_step(adhesive, step):
    with pytest.raises(ValidationError) as info:
        Sweep(scene=adhesive, zetas=[1.0], zeta_step=step)
    assert info.value.field == "sweep.zeta_step"


def test_zeta_path_bounds_every_step():
    from viscocontact.studies.sweep import zeta_path

    path = zeta_path(1e3, 1e-5, 0.25)
    steps = np.abs(np.diff(np.log10([1e3, *path, 1e-5])))
    assert len(path) == 31 and np.allclose(steps, 0.25)
    path = zeta_path(0.02, 3.0, 0.3)                # upwards, not a whole number of steps
    steps = np.diff(np.log10([0.02, *path, 3.0]))
    assert np.all(steps > 0) and steps.max() <= 0.3 and np.allclose(steps, steps[0])
    assert zeta_path(1.0, 10 ** -0.25, 0.25) == ()  # exactly one step
    assert zeta_path(1.0, 1e-3, None) == () and zeta_path(0.0, 1.0, 0.25) == ()


def test_zeta_step_is_written_only_when_set(adhesive):
    """Study files written before the parameter existed read as one step (its default)."""
    one = Sweep(scene=adhesive, zetas=[1.0, 1e-2])
    assert one.zeta_step is None and "zeta_step" not in one.params()
    assert Sweep.from_params(adhesive, one.params()) == one
    bounded = Sweep(scene=adhesive, zetas=[1.0, 1e-2], zeta_step=0.25)
    assert bounded.params()["zeta_step"] == 0.25
    assert Sweep.from_params(adhesive, bounded.params()) == bounded


def test_a_wide_gap_is_crossed_through_intermediate_equilibria(tmp_path, adhesive, mesh):
    """The adhesive point at ζ = 1e-2 after ζ = 1 is the solve of a hand-written continuation
    through ζ = 10^-0.5, 0.1, 10^-1.5 (not stored); the adhesionless twin takes one step."""
    data = run(Sweep(scene=adhesive, zetas=[1.0, 1e-2], zeta_step=0.5, discretization=mesh),
               tmp_path / "s.h5", progress=None)
    assert data.complete and len(data) == 4
    points = {(v, float(z)): i for i, (v, z) in
              enumerate(zip(data.points["variant"], data.points["zeta"]))}
    for variant, scene, path in (("adhesive", adhesive, [10 ** -0.5, 0.1, 10 ** -1.5]),
                                 ("adhesionless", None, [])):
        if scene is None:
            data_dict = adhesive.to_dict()
            data_dict["adhesion"] = {"kind": "none"}
            scene = Scene.from_dict(data_dict)
        previous = None
        with single_blas_thread():
            for zeta in [1.0, *path, 1e-2]:
                problem = ContactProblem.from_scene(attrs.evolve(scene, zeta=zeta),
                                                    discretization=Discretization(**mesh))
                result = problem.solve(initial=previous)
                previous = result if result.converged else previous
        row = points[variant, 1e-2]
        assert data.points["converged"][row]
        assert data.points["area"][row] == pytest.approx(result.area, rel=1e-12, abs=0)
        assert np.allclose(data.points["edges"][row], result.edges.ravel(), rtol=0, atol=1e-12)


def _refusing_far_steps(monkeypatch, decades, first_touch=True):
    """Make every solve of a study point fail whose ζ lies more than ``decades`` from the last
    ζ solved successfully (or from the first one asked), and with ``first_touch=False`` every
    solve from first touch after the first; returns the list of ``(ζ, converged)`` of the
    calls."""
    from viscocontact.studies import point

    real = point._solve_at
    calls: list = []

    def solve_at(scene, zeta, start, options, *, fields=False):
        z = float(scene["sliding"]["zeta"] if zeta is None else zeta)
        last = next((c for c, ok in reversed(calls) if ok), None)
        far = last is not None and (abs(np.log10(z / last)) > decades if start is not None
                                    else not first_touch)
        result = real(scene, zeta, start, options, fields=fields)
        if far:
            result = attrs.evolve(result, converged=False, message="too far")
        calls.append((z, result.converged))
        return result

    monkeypatch.setattr(point, "_solve_at", solve_at)
    return calls


def test_a_point_that_fails_from_its_neighbour_is_approached_in_smaller_steps(
        tmp_path, adhesive, mesh, monkeypatch):
    """Solves that jump more than 0.6 decades fail: the point at ζ = 1e-2 after ζ = 1 is
    reached by steps that halve on failure and double on success, and it is the equilibrium of
    a hand-written continuation through the ζ that converged (not stored)."""
    calls = _refusing_far_steps(monkeypatch, 0.6)
    data = run(Sweep(scene=adhesive, zetas=[1.0, 1e-2], discretization=mesh, pair=False),
               tmp_path / "s.h5", progress=None)
    assert data.points["converged"].tolist() == [True, True]
    message = data.points["message"][1]
    assert "reached from the neighbour at ζ = 1 in" in message and "too far" in message
    path = [z for z, ok in calls[2:] if ok]          # after the first point and the direct try
    assert path[-1] == 1e-2 and len(path) >= 4
    assert all(abs(np.log10(b / a)) <= 0.6 + 1e-12 for a, b in zip([1.0] + path, path))
    previous, evaluations = None, 0
    with single_blas_thread():
        for zeta in [1.0, *path]:
            problem = ContactProblem.from_scene(attrs.evolve(adhesive, zeta=zeta),
                                                discretization=Discretization(**mesh))
            result = problem.solve(initial=previous)
            assert result.converged
            previous = result
            evaluations += result.function_evaluations
    assert data.points["area"][1] == pytest.approx(result.area, rel=1e-12, abs=0)
    assert np.allclose(data.points["edges"][1], result.edges.ravel(), rtol=0, atol=1e-12)
    # the count covers the failed tries too
    assert data.points["function_evaluations"][1] > evaluations - data.points[
        "function_evaluations"][0]


def test_a_point_whose_branch_ends_is_solved_from_first_touch_and_says_so(
        tmp_path, adhesive, mesh, monkeypatch):
    """No step of ζ reaches the point from its neighbour (the branch ends before it): it is the
    equilibrium of a first-touch solve at its own ζ, recorded as started from first touch, with
    both reasons in its message."""
    from viscocontact.studies.point import REFINE_SMALLEST, REFINE_SOLVES

    calls = _refusing_far_steps(monkeypatch, 0.0)
    data = run(Sweep(scene=adhesive, zetas=[1.0, 1e-2], discretization=mesh, pair=False),
               tmp_path / "s.h5", progress=None)
    assert data.points["converged"].tolist() == [True, True]
    assert data.points["started_from"].tolist() == ["first touch", "first touch"]
    message = data.points["message"][1]
    assert "from first touch at this ζ, the branch continued from the neighbour having ended" \
        in message
    assert "too far; approached again from the neighbour at ζ = 1" in message
    assert "no step converged" in message and "did not converge either" in message
    tries = calls[2:-1]
    assert not any(ok for _, ok in tries) and 1 <= len(tries) <= REFINE_SOLVES
    # the steps halve down to the smallest
    assert min(abs(np.log10(z)) for z, _ in tries) == pytest.approx(2 * REFINE_SMALLEST)
    with single_blas_thread():
        fresh = ContactProblem.from_scene(attrs.evolve(adhesive, zeta=1e-2),
                                          discretization=Discretization(**mesh)).solve()
    assert fresh.converged
    assert data.points["area"][1] == pytest.approx(fresh.area, rel=1e-12, abs=0)
    assert np.allclose(data.points["edges"][1], fresh.edges.ravel(), rtol=0, atol=1e-12)
    assert data.points["function_evaluations"][1] > fresh.function_evaluations


def test_a_point_that_no_start_reaches_stays_failed_and_says_so(tmp_path, adhesive, mesh,
                                                                 monkeypatch):
    calls = _refusing_far_steps(monkeypatch, 0.0, first_touch=False)
    data = run(Sweep(scene=adhesive, zetas=[1.0, 1e-2], discretization=mesh, pair=False),
               tmp_path / "s.h5", progress=None)
    assert data.points["converged"].tolist() == [True, False]
    assert data.points["started_from"].tolist() == ["first touch", "neighbour"]
    message = data.points["message"][1]
    assert message.startswith("too far; approached again from the neighbour at ζ = 1")
    assert message.endswith("; from first touch it did not converge either (too far)")
    assert not any(ok for _, ok in calls[2:])
