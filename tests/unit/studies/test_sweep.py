"""ζ-sweeps: chains by history, warm starts, failures stored, realizations."""
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
    sweep = Sweep(scene=adhesive, zetas=[0.1, 1.0], loads=[0.1, 0.2], history="speed-ramp")
    assert sweep.variants == ("adhesive", "adhesionless")
    chains = sweep.chains()
    assert len(chains) == 4 and all(c.zetas == (0.1, 1.0) for c in chains)
    assert [c.labels["variant"] for c in chains] == ["adhesive"] * 2 + ["adhesionless"] * 2
    assert chains[2].scene["adhesion"] == {"kind": "none"} and chains[2].labels["gamma"] == 0.0
    assert chains[0].labels["gamma"] == 3e-5 and chains[1].labels["load"] == 0.2
    assert Sweep(scene=adhesive, zetas=[1.0], pair=False).variants == ("adhesive",)
    # the approach: every adhesive point its own chain; the adhesionless twin one chain
    single = Sweep(scene=adhesive, zetas=[0.1, 1.0, 10.0])
    assert [c.zetas for c in single.chains()] == [(0.1,), (1.0,), (10.0,), (0.1, 1.0, 10.0)]


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
    assert sweep.variants == ("adhesive", "adhesionless") and sweep.history.name == "approach"
    assert len(sweep.zetas) == 15 and len(sweep.chains()) == 16
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
