"""Approach-retraction cycles: the path, detachment, pull-off and the toughness of eq. 4.57."""
import math

import numpy as np
import pytest

from viscocontact.errors import ValidationError
from viscocontact.studies import Cycle, cycle_metrics, run


def test_path(adhesionless):
    cycle = Cycle(scene=adhesionless, max_penetration=0.5, step=0.2, start=-0.1,
                  min_penetration=-0.4)
    assert np.allclose(cycle.approach_targets(), [-0.1, 0.1, 0.3, 0.5])
    assert np.allclose(cycle.retract_targets(), [0.3, 0.1, -0.1, -0.3])
    chain = cycle.chains()[0]
    assert chain.scene["load"] == {"penetration": -0.1} and chain.zetas == (1.0,)


@pytest.mark.parametrize("options,field", [
    ({"max_penetration": 0.5, "step": 0.0}, "cycle.step"),
    ({"max_penetration": -0.5, "step": 0.1}, "cycle.max_penetration"),
    ({"max_penetration": 0.5, "step": 0.1, "min_penetration": 0.6}, "cycle.min_penetration"),
    ({"max_penetration": 0.5, "step": 0.1, "refine": -1}, "cycle.refine"),
    ({"max_penetration": 0.5, "step": 0.1, "gammas": [-1e-5]}, "cycle.gammas"),
])
def test_bad_parameters(adhesionless, options, field):
    with pytest.raises(ValidationError) as info:
        Cycle(scene=adhesionless, **options)
    assert info.value.field == field


def synthetic(p_ret, d_out=-0.2):
    """A cycle whose retraction follows ``p_ret(Δ)`` from Δ = 1 down to ``d_out``, then detaches
    at ``d_out - 0.1`` (the approach follows p = Δ - 0.1 from 0.1)."""
    app = np.linspace(0.0, 1.0, 11)
    ret = np.r_[np.linspace(0.9, d_out, 12), d_out - 0.1]
    n_app, n_ret = len(app), len(ret)
    target = np.r_[app, ret]
    contact = np.r_[app >= 0.1, np.ones(n_ret - 1, bool), False]
    pm = np.where(contact, np.r_[app - 0.1, p_ret(ret)], 0.0)
    return {"phase": np.array(["approach"] * n_app + ["retract"] * n_ret),
            "target": target, "converged": np.ones(n_app + n_ret, bool),
            "status": np.where(contact, "converged", "no_contact"),
            "n_contacts": contact.astype(int), "full_contact": np.zeros(n_app + n_ret, bool),
            "mean_pressure": pm, "area": np.where(contact, 1.0 + target, 0.0)}


def test_toughness_of_a_linear_branch():
    """p̃∞ = Δ̃ - 0.3 on the way out, detachment at -0.2:
    T̃ = 2π ∫_{0.3}^{-0.2} (Δ - 0.3) dΔ = 2π · 0.5²/2."""
    m = cycle_metrics(synthetic(lambda d: d - 0.3))
    assert m.zero_load_penetration == pytest.approx(0.3)
    assert m.toughness == pytest.approx(2 * math.pi * 0.125)
    assert m.detached and m.detachment_penetration == pytest.approx(-0.2)
    assert m.detachment_bracket == pytest.approx(0.1)
    assert m.pull_off_pressure == pytest.approx(-0.5)
    assert m.pull_off_penetration == pytest.approx(-0.2)
    # loop: ∫ approach (Δ - 0.1) over [0.1, 1] minus the retraction, which starts at the turning
    # point (1, 0.9), drops to (0.9, 0.6) and follows Δ - 0.3 down to -0.2
    retraction = 0.5 * (0.9 + 0.6) * 0.1 + (0.6**2 - 0.5**2) / 2
    work = 2 * math.pi * (0.9**2 / 2 - retraction)
    assert m.cycle_work == pytest.approx(work)


def test_failed_solves_are_no_detachment():
    """Retraction points that did not converge below Δ̃ = 0 say nothing about detachment: the
    cycle is not detached and its bracket is unknown (they were once taken for detachment)."""
    points = synthetic(lambda d: d - 0.3)
    last = len(points["target"]) - 1
    points["status"] = points["status"].astype("<U13")
    points["status"][last] = "not_converged"
    points["converged"][last] = False
    m = cycle_metrics(points)
    assert not m.detached and math.isnan(m.detachment_bracket)
    assert m.detachment_penetration == pytest.approx(-0.2)      # last converged contact
    from viscocontact.studies.cycle import is_detached

    record = {k: v[last] for k, v in points.items()}
    assert not is_detached(record)
    record.update(status="no_contact", converged=True)
    assert is_detached(record)


def test_no_tension_no_toughness():
    m = cycle_metrics(synthetic(lambda d: d + 0.3, d_out=-0.2))
    assert m.toughness == 0.0 and math.isnan(m.zero_load_penetration)
    assert m.pull_off_pressure == 0.0 and math.isnan(m.pull_off_penetration)


def test_adhesive_cycle(tmp_path, adhesive, mesh):
    cycle = Cycle(scene=adhesive, max_penetration=0.4, step=0.2, refine=2,
                  discretization=mesh | {"path_step": 0.2})
    data = run(cycle, tmp_path / "c.h5", progress=None)
    p = data.points
    assert data.complete and data.kind == "cycle"
    assert p["phase"][:3].tolist() == ["approach"] * 3
    assert p["target"][:5].tolist() == pytest.approx([0.0, 0.2, 0.4, 0.2, 0.0])
    assert p["started_from"][0] == "no contact" and p["status"][0] == "no_contact"
    assert set(p["started_from"][2:]) == {"neighbour"}           # the contact set is carried
    (cyc,) = data.cycles()
    m = cyc["metrics"]
    assert m.detached and 0 < m.detachment_bracket <= 0.2 / 2**2 + 1e-12
    assert m.detachment_penetration < 0.0 < m.zero_load_penetration < 0.4
    assert m.pull_off_pressure < 0 and m.toughness > 0
    # T̃ bounds: the branch between Δ̃_0 and Δ̃_out lies between 0 and the pull-off pressure
    width = m.zero_load_penetration - m.detachment_penetration
    assert m.toughness <= 2 * math.pi * abs(m.pull_off_pressure) * width
    metrics = data.metrics()
    assert metrics["toughness"].shape == (1, 1, 1)
    assert metrics["toughness"][0, 0, 0] == m.toughness


def test_adhesionless_cycle_detaches_at_first_touch(tmp_path, adhesionless, mesh):
    cycle = Cycle(scene=adhesionless, max_penetration=0.4, step=0.2, refine=2,
                  discretization=mesh, gammas=[0.0])
    data = run(cycle, tmp_path / "c.h5", progress=None)
    (cyc,) = data.cycles()
    m = cyc["metrics"]
    assert cyc["variant"] == "adhesionless" and cyc["gamma"] == 0.0
    assert m.toughness == 0.0 and m.detached
    assert 0.0 < m.detachment_penetration <= 0.05 + 1e-12
    assert np.all(data.points["mean_pressure"][data.points["converged"]] >= 0)


def test_a_cycle_gives_up_after_consecutive_failures(tmp_path, adhesionless, mesh, monkeypatch):
    from viscocontact.problem import ContactProblem

    original = ContactProblem.solve

    def solve(self, initial=None, **kwargs):
        edges = getattr(initial, "edges", initial)                          # (ContinueFrom)
        if edges is not None and len(edges) and self.penetration < 0.35:   # retraction
            raise RuntimeError("lost")
        return original(self, initial, **kwargs)

    monkeypatch.setattr(ContactProblem, "solve", solve)
    cycle = Cycle(scene=adhesionless, max_penetration=0.4, step=0.2, max_failures=3,
                  discretization=mesh)
    data = run(cycle, tmp_path / "c.h5", progress=None)
    assert data.complete
    assert data.points["status"].tolist() == ["no_contact", "converged", "converged"] + \
        ["error"] * 3
    assert set(data.points["message"][3:]) == {"RuntimeError: lost"}
    assert not data.cycles()[0]["metrics"].detached


@pytest.mark.slow     # two cycles of the thesis's rough scene to pull-off: 12-20 s
def test_a_rough_adhesive_cycle_does_not_depend_on_its_step(tmp_path):
    """The thesis rough scene (seed 0, ζ = 1e-2) cycled to Δ̃ = 0.4 and back to pull-off at steps
    0.1 and 0.05: each point continues the branch through its neighbour's equilibrium with the
    events located, so the common points agree to the solver's tolerance (the former continuation
    from the neighbour's edges reached Ã = 1.285 against 0.873 at Δ̃ = 0.3); the approach's points
    are those of a single solve from first touch."""
    from viscocontact import solve
    from viscocontact.scene import Load, Scene

    scene = Scene.from_toml("examples/scenes/thesis_rough.toml")    # shipped with the package
    tables = []
    for step in (0.1, 0.05):
        data = run(Cycle(scene=scene, max_penetration=0.4, step=step),
                   tmp_path / f"c{step}.h5", progress=None)
        p = data.points
        assert p["converged"].all()
        tables.append({(phase, round(float(t), 9)): float(a)
                       for phase, t, a in zip(p["phase"], p["target"], p["area"])})
    coarse, fine = tables
    common = set(coarse) & set(fine)
    assert len(common) >= 9
    for key in common:
        assert fine[key] == pytest.approx(coarse[key], rel=1e-6, abs=1e-7), key
    single = solve(scene.replace(load=Load(penetration=0.3)))
    assert coarse[("approach", 0.3)] == pytest.approx(single.area, rel=1e-6)
