"""The campaign's sampler covers the scene space it claims, and its checks catch each violated
identity on results made to violate it (``viscocontact.testing.campaign``)."""
import math

import attrs
import numpy as np
import pytest

from viscocontact.result import ContactResult, SolveStatus
from viscocontact.scene import Scene
from viscocontact.testing.campaign import (FRICTION_ZERO, RANGES, check, classify, describe,
                                           draw, judge)

SEEDS = range(300)


@pytest.fixture(scope="module")
def tables():
    return [draw(seed) for seed in SEEDS]


def test_draw_is_deterministic_and_seeds_differ(tables):
    assert draw(17) == tables[17]
    assert len({repr(t) for t in tables}) == len(tables)


def test_every_kind_is_drawn(tables):
    labels = [describe(t) for t in tables]
    for group, kinds in (("profile", RANGES["profile"]), ("rheology", RANGES["rheology"]),
                         ("kernel", RANGES["kernel"]), ("adhesion", RANGES["adhesion"]),
                         ("control", RANGES["control"]), ("solver", RANGES["solver"])):
        counts = {k: sum(lab[group] == k for lab in labels) for k in kinds}
        assert min(counts.values()) >= 20, (group, counts)


def _values(tables, section, key):
    return np.array([t[section][key] for t in tables if key in t[section]], dtype=float)


@pytest.mark.parametrize("section, key", [
    ("profile", "amplitude"), ("profile", "hurst"), ("profile", "scales"), ("profile", "rms"),
    ("rheology", "beta"), ("kernel", "thickness"), ("adhesion", "gamma"),
    ("adhesion", "range"), ("load", "mean_pressure"), ("load", "penetration"),
    ("sliding", "zeta")])
def test_draws_stay_in_and_span_their_ranges(tables, section, key):
    """Every value inside its range, and the drawn values reach within a tenth of each end (a
    tenth of the log-range where it spans decades)."""
    v = _values(tables, section, key)
    lo, hi = RANGES[key]
    assert np.all((v >= lo) & (v <= hi))
    log = hi / lo > 20
    f = np.log if log else (lambda a: a)
    span = f(hi) - f(lo)
    assert f(v.min()) - f(lo) < 0.1 * span and f(hi) - f(v.max()) < 0.1 * span


def test_prony_draws_have_the_drawn_glassy_ratio(tables):
    pronys = [t["rheology"] for t in tables if t["rheology"]["kind"] == "prony"]
    assert {len(p["moduli"]) for p in pronys} == {2, 3}
    ratios = np.array([1 + sum(p["moduli"]) for p in pronys])
    assert ratios.min() >= RANGES["beta"][0] * (1 - 1e-12)
    assert ratios.max() <= RANGES["beta"][1] * (1 + 1e-12)


def test_every_drawn_scene_builds(tables):
    for table in tables[:25]:
        Scene.from_dict(table)


@pytest.mark.parametrize("message, kind", [
    ("contact set still changing after 200 restarts", "path"),
    ("edge solve did not converge: max_evaluations: 80 residual evaluations", "path"),
    ("edge solve did not converge: failed: residual at x0 is not finite (...)", "path"),
    ("no equilibrium at the target load on the approach branch", "scene"),
    ("the equilibrium found is unstable under load control (dp̃∞/dΔ̃ = -1)", "scene"),
    ("contact set cycles: a merged contact carries tension", "path"),
    ("met a contact set without a valid field (no zone lengths bound the stress)", "path"),
    ("something else", "unclassified")])
def test_classify(message, kind):
    assert classify(message) == kind


WAVY = {"profile": {"kind": "sinusoid", "amplitude": 0.1},
        "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
        "load": {"mean_pressure": 0.3}, "sliding": {"zeta": 1.0}}


def _result(**changes):
    base = dict(area=1.0, mean_pressure=0.3, penetration=0.5, friction=0.05,
                reduced_friction=0.7, n_contacts=1, edges=np.array([[-0.5, 0.5]]),
                full_contact=False, converged=True, status=SolveStatus.CONVERGED,
                message="converged", residual=1e-10, iterations=3, function_evaluations=9,
                zeta=1.0, edge_perturbation=0.0, min_gap=0.01,
                extras={"method": "bem", "error_estimate": 1e-3,
                        "friction_dissipation": 0.05, "friction_edges": 0.0,
                        "outside_model": ""})
    extras = {**base["extras"], **changes.pop("extras", {})}
    return ContactResult(**{**base, **changes, "extras": extras})


def test_a_consistent_result_passes():
    failures, used, _ = check(Scene.from_dict(WAVY), _result())
    assert failures == [] and used == "estimate"


@pytest.mark.parametrize("changes, words", [
    (dict(mean_pressure=0.31), "load not met"),
    (dict(min_gap=-1e-3), "interpenetration"),
    (dict(friction=-0.01, extras={"friction_dissipation": -0.01}), "against the sliding"),
    (dict(extras={"friction_dissipation": 0.0505}), "power balance"),
    (dict(extras={"friction_dissipation": 0.06, "error_estimate": float("nan")}),
     "fallback tolerance")])
def test_each_violated_identity_is_named(changes, words):
    failures, _, _ = check(Scene.from_dict(WAVY), _result(**changes))
    assert len(failures) == 1 and words in failures[0]


@pytest.mark.parametrize("load, flagged", [
    ({"penetration": 0.2}, True), ({"penetration": -0.1}, False),
    ({"mean_pressure": 0.3}, True), ({"mean_pressure": -0.1}, False)])
def test_no_contact_is_flagged_where_a_contact_must_be(load, flagged):
    """No contact is no answer under a compressive load, nor at a positive penetration (past
    the first touch at Δ̃ = 0 the profile penetrates the undeformed solid); a tensile load or a
    negative penetration may leave none."""
    none = _result(area=0.0, n_contacts=0, edges=np.zeros((0, 2)), friction=0.0,
                   mean_pressure=0.0, penetration=load.get("penetration", 0.0),
                   status=SolveStatus.NO_CONTACT, message="no contact at this load")
    scene = Scene.from_dict({**WAVY, "load": load,
                             "adhesion": {"kind": "energy-balance", "gamma": 1e-3}})
    failures = check(scene, none)[0]
    assert bool(failures) == flagged
    if flagged:
        assert "no contact" in failures[0]


def test_friction_under_a_tensile_load_is_negative():
    """μ = F_t/p̃∞: a force that opposes sliding under a tensile load (p̃∞ < 0) gives μ < 0."""
    r = _result(mean_pressure=-0.3, friction=-0.05, extras={"friction_dissipation": -0.05})
    scene = Scene.from_dict({**WAVY, "load": {"mean_pressure": -0.3},
                             "adhesion": {"kind": "energy-balance", "gamma": 1e-3}})
    assert check(scene, r)[0] == []
    assert "against the sliding" in check(scene, attrs.evolve(r, friction=0.05))[0][0]


def test_a_result_outside_the_model_is_excused_only_what_it_says():
    """A result that says it lies outside the model is not held to the power balance nor to
    μ >= 0 (the friction of a process zone), but still to its load and gap."""
    outside = {"outside_model": "the bulk dissipation is 46 times the friction"}
    r = _result(friction=-0.01, extras={**outside, "friction_dissipation": 0.46})
    assert check(Scene.from_dict(WAVY), r)[0] == []
    assert judge(Scene.from_dict(WAVY), r).outcome == "outside-model"
    r = attrs.evolve(r, min_gap=-1e-3)
    assert "interpenetration" in check(Scene.from_dict(WAVY), r)[0][0]


def test_an_elastic_friction_at_round_off_is_zero():
    """μ = 1e-7 against no dissipation on an elastic solid passes (below FRICTION_ZERO √m2),
    μ = 1e-5 does not, nor μ = 1e-7 against 2e-7 on a lossy solid."""
    scene = Scene.from_dict({**WAVY, "rheology": {"kind": "elastic"}})
    m2 = scene.profile.statistics().m2
    assert 1e-7 < FRICTION_ZERO * math.sqrt(m2) < 1e-5
    zero = {"friction_dissipation": 0.0}
    assert check(scene, _result(friction=1e-7, extras=zero))[0] == []
    assert check(scene, _result(friction=1e-5, extras=zero))[0]
    lossy = check(Scene.from_dict(WAVY), _result(friction=1e-7,
                                                  extras={"friction_dissipation": 2e-7}))
    assert "power balance" in lossy[0][0]


def test_not_converged_results_are_classified():
    scene = Scene.from_dict(WAVY)
    path = _result(converged=False, status=SolveStatus.NOT_CONVERGED,
                   message="contact set still changing after 200 restarts")
    assert judge(scene, path).outcome == "path" and not judge(scene, path).passed
    fold = attrs.evolve(path, message="no equilibrium at the target load: the contact grows "
                                      "unstably")
    assert judge(scene, fold).outcome == "scene" and judge(scene, fold).passed
