"""The solve plan (``viscocontact solve --explain``) and the tolerance-driven dissipative band."""
from __future__ import annotations

import json

import attrs

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from viscocontact.adhesion import EnergyBalance
from viscocontact.kernels import ConfinedLayer, HalfPlane
from viscocontact.kernels.clausen import cl2
from viscocontact.kernels.memory import MemoryTable
from viscocontact.kernels.prepared import (ACTIVE, FROZEN, RELAXED, branch_regimes,
                                           frozen_error_bound, relaxed_error_bound)
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.solvers import Newton
from viscocontact.methods.bem import BEM

X = np.linspace(-np.pi, np.pi, 4001)


def _deviation_from_relaxed(zeta):
    tab = MemoryTable(zeta)
    return float(np.max(np.abs(tab.antiderivative(X) + cl2(X))))


def _deviation_from_frozen(zeta):
    return float(np.max(np.abs(MemoryTable(zeta).antiderivative(X))))


@settings(max_examples=12, deadline=None)
@given(st.floats(-9.0, -1.0))
def test_relaxed_bound_holds_for_the_tabulated_memory_integral(log_zeta):
    zeta = 10.0**log_zeta
    assert _deviation_from_relaxed(zeta) <= relaxed_error_bound(zeta)


@settings(max_examples=12, deadline=None)
@given(st.floats(1.0, 9.0))
def test_frozen_bound_holds_for_the_tabulated_memory_integral(log_zeta):
    zeta = 10.0**log_zeta
    assert _deviation_from_frozen(zeta) <= frozen_error_bound(zeta)


def test_bounds_are_not_loose_by_orders_of_magnitude():
    assert _deviation_from_relaxed(1e-4) > 0.05 * relaxed_error_bound(1e-4)
    assert _deviation_from_frozen(1e4) > 0.05 * frozen_error_bound(1e4)


@given(st.lists(st.floats(1e-15, 1e15), min_size=1, max_size=6),
       st.one_of(st.none(), st.floats(1e-14, 1e-2)))
def test_regimes_are_ordered_in_the_memory_length(lengths, tol):
    z = np.sort(np.asarray(lengths))
    order = {RELAXED: 0, ACTIVE: 1, FROZEN: 2}
    ranks = [order[r] for r in branch_regimes(z, tol)]
    assert ranks == sorted(ranks)
    if tol is None:
        assert list(branch_regimes([1e-13, 1e-6, 1e13])) == [RELAXED, ACTIVE, FROZEN]


def test_a_tolerance_removes_the_memory_table_and_keeps_the_limit():
    sls = StandardLinearSolid(beta=10.0)
    strict = HalfPlane().prepare(sls, 1e-10)
    loose = HalfPlane().prepare(sls, 1e-10, tolerance=1e-7)
    assert len(strict.zetas) == 1 and len(loose.zetas) == 0
    x = np.linspace(-3.0, 3.0, 101)
    assert np.max(np.abs(strict.antiderivative(x) - loose.antiderivative(x))) <= 1e-7


def _problem(**kw):
    base = dict(profile=Sinusoid(amplitude=0.1), rheology=StandardLinearSolid(beta=10.0),
                solver=Newton(), mean_pressure=0.1, zeta=1.0)
    base.update(kw)
    return ContactProblem(method=BEM(), **base)


def test_plan_of_an_adhesive_viscoelastic_half_plane():
    plan = {s.stage: s for s in _problem(adhesion=EnergyBalance(gamma=1e-4)).plan().steps}
    assert "1 memory table" in plan["kernel"].choice
    assert plan["mean displacement"].choice.startswith("skipped")
    assert plan["layer series"].choice == "none"
    assert "edge zones" in plan["mesh"].choice and "no edge zones" not in plan["mesh"].choice
    assert "bordered" in plan["edges"].choice
    assert "only when asked" in plan["fields"].choice


@pytest.mark.parametrize("zeta, outside", [(5e-4, True), (2e-3, False)])
def test_plan_says_when_the_edge_advance_is_past_the_relaxation_length(zeta, outside):
    """A standard linear solid (β = 10) relaxes 90 % of its glassy modulus at ζ/β: with
    δX = 1e-4 past it (ζ = 5e-4) the plan says the result will lie outside the model."""
    reason = {s.stage: s for s in _problem(adhesion=EnergyBalance(gamma=1e-4), zeta=zeta)
              .plan().steps}["edges"].reason
    assert ("90 % of the glassy modulus relaxes within δX (from a relaxation length of 5e-05)"
            in reason) is outside
    assert ("outside the model" in reason) is outside


def test_plan_skips_what_an_elastic_adhesionless_scene_does_not_need():
    plan = {s.stage: s for s in _problem(rheology=Elastic()).plan().steps}
    assert plan["kernel"].choice.startswith("elastic")
    assert "no edge zones" in plan["mesh"].choice
    assert "no energy perturbations" in plan["edges"].reason


def test_plan_of_a_layer_and_a_relaxed_branch():
    layer = ConfinedLayer(thickness=0.5, poisson=0.4)
    plan = {s.stage: s for s in _problem(kernel=layer, zeta=1e-11, kernel_tolerance=1e-6)
            .plan().steps}
    assert "E0" in plan["kernel"].choice and "relaxed" in plan["kernel"].reason
    assert plan["mean displacement"].choice.startswith("constant kernel")
    assert "modes" in plan["layer series"].choice
    incompressible = {s.stage: s for s in _problem(kernel=ConfinedLayer(thickness=0.5)).plan().steps}
    assert "ν = 0.5" in incompressible["mean displacement"].reason


def test_kernel_tolerance_is_validated():
    from viscocontact.errors import ValidationError

    with pytest.raises(ValidationError, match="kernel_tolerance"):
        _problem(kernel_tolerance=0.5)


def test_cli_explain_prints_the_plan_without_solving(tmp_path, capsys):
    from viscocontact.cli import main

    scene = tmp_path / "s.toml"
    scene.write_text('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\n'
                     'kind = "standard-linear-solid"\nbeta = 10.0\n[load]\nmean_pressure = 0.1\n'
                     '[sliding]\nzeta = 1.0\n', encoding="utf-8")
    assert main(["solve", str(scene), "--explain"]) == 0
    text = capsys.readouterr().out
    for stage in ("kernel", "mean displacement", "layer series", "method", "grid", "fields"):
        assert stage in text
    assert "spectral" in text and "adhesionless" in text       # the plan's method and why
    assert "area" not in text                                   # no solve, no result
    adhesive = tmp_path / "a.toml"
    adhesive.write_text(scene.read_text(encoding="utf-8")
                        + '[adhesion]\nkind = "energy-balance"\ngamma = 1e-4\n', encoding="utf-8")
    assert main(["solve", str(adhesive), "--explain"]) == 0
    text = capsys.readouterr().out
    for stage in ("method", "mesh", "edges", "path", "solver"):
        assert stage in text
    assert "bem" in text
    assert main(["solve", str(scene), "--explain", "--json"]) == 0
    steps = json.loads(capsys.readouterr().out)
    assert [s["stage"] for s in steps][:3] == ["kernel", "mean displacement", "layer series"]
    glassy = tmp_path / "g.toml"
    glassy.write_text(scene.read_text(encoding="utf-8").replace("zeta = 1.0", "zeta = 1e8"),
                      encoding="utf-8")
    assert main(["solve", str(glassy), "--explain"]) == 0
    assert "memory table" in capsys.readouterr().out.splitlines()[0]
    assert main(["solve", str(glassy), "--explain", "--kernel-tolerance", "1e-6"]) == 0
    assert "elastic with E∞" in capsys.readouterr().out.splitlines()[0]
    for bad in ("0", "0.5", "nan"):
        assert main(["solve", str(glassy), "--kernel-tolerance", bad]) == 2
        assert "--kernel-tolerance" in capsys.readouterr().err


# ---- the stiffness scale of the edge residual tolerance ----------------------------------------
@settings(max_examples=30, deadline=None)
@given(beta=st.floats(1.01, 1e4), log_zeta=st.floats(-8.0, 8.0))
def test_residual_scale_lies_between_relaxed_and_glassy_stiffness(beta, log_zeta):
    """``max(1, E_eff/E0)`` with E_eff between E0 and E∞ = β E0, increasing with ζ, 1 when
    elastic, and at the limits the relaxed (1) and glassy (β) stiffness."""
    from viscocontact.problem import residual_scale

    sls = StandardLinearSolid(beta=beta)
    s = residual_scale(HalfPlane().prepare(sls, 10.0**log_zeta))
    zeta = 10.0**log_zeta          # SLS: K(1) = 1/β + (1 - 1/β)/(1 - iζ) in E0 units
    assert s == pytest.approx(max(1.0, 1.0 / abs(1 / beta + (1 - 1 / beta) / (1 - 1j * zeta))),
                              rel=1e-12)
    assert s <= beta * (1 + 1e-12)
    assert s <= residual_scale(HalfPlane().prepare(sls, 10.0**(log_zeta + 1))) * (1 + 1e-12)
    assert residual_scale(HalfPlane().prepare(sls, 0.0)) == pytest.approx(1.0)
    assert residual_scale(HalfPlane().prepare(sls, 1e12)) == pytest.approx(beta, rel=1e-9)
    assert residual_scale(HalfPlane().prepare(Elastic(), 10.0**log_zeta)) == 1.0


def test_plan_reports_the_scaled_tolerance():
    glassy = ContactProblem(method=BEM(),
                            profile=Sinusoid(amplitude=0.1),
                            rheology=StandardLinearSolid(beta=10.0),
                            solver=Newton(), mean_pressure=0.1, zeta=1e8)
    assert "× 10 (stiffness" in str(glassy.plan())
    relaxed = attrs.evolve(glassy, zeta=0.0)
    assert "stiffness" not in str(relaxed.plan())


# ---- Maugis–Dugdale zones -----------------------------------------------------------------------
def _md_plan(gamma, h0, rheology=None, zeta=1.0, **kw):
    from viscocontact.adhesion.maugis_dugdale import MaugisDugdale

    problem = _problem(adhesion=MaugisDugdale(gamma=gamma, range=h0), zeta=zeta,
                       **({"rheology": rheology} if rheology is not None else {}), **kw)
    return {s.stage: s for s in problem.plan().steps}


def test_plan_of_resolved_cohesive_zones():
    from viscocontact.reference.dugdale_crack import speed_group, steady_crack

    plan = _md_plan(5e-4, 0.00795, zeta=0.3)   # λ = 5, β = 10
    edges = plan["edges"]
    assert "Maugis-Dugdale zones" in edges.choice and "zones resolved" in edges.choice
    assert "smallest element is 0.000198" in edges.reason        # 0.1·a0/16, a0 = h̃0²/(4γ̃)
    a0 = 0.00795**2 / 2e-3
    lead = steady_crack(speed_group(0.3, 5e-4, 0.00795), 10.0, "closing").zone_length * a0
    assert f"leading {lead:.3g}" in edges.reason
    assert "cohesive zone" in plan["mesh"].reason and "inner zone" in plan["reuse"].choice
    elastic = _md_plan(5e-4, 0.00795, rheology=Elastic(), zeta=0.0)["edges"]
    assert f"shortest zone ≈ {a0:.3g} spans 160 smallest" in elastic.choice


@pytest.mark.parametrize("h0, jkr_like", [(0.007, True), (0.0398, False), (0.5, False)])
def test_plan_says_where_tension_without_contact_may_be_stable(h0, jkr_like):
    """λ = 5.7, 1 and 0.08 on the sinusoid Λ̃ = 0.1 at γ̃ = 5e-4: only the JKR-like scene's plan
    is silent about the snap-in; the others point to the spectral method's grid."""
    from viscocontact.adhesion.maugis_dugdale import MaugisDugdale

    lam = MaugisDugdale(gamma=5e-4, range=h0).transition_parameter(0.1)
    assert (lam >= 5.0) is jkr_like
    choice = _md_plan(5e-4, h0)["edges"].choice
    assert ("traction without contact" in choice) is not jkr_like
    if not jkr_like:
        assert f"λ = {lam:.3g} < 5" in choice and 'kind = "spectral"' in choice


def test_plan_says_when_the_zone_is_below_the_smallest_element():
    plan = _md_plan(2.4e-7, 1e-7, rheology=Elastic(), zeta=0.0)  # a0 = 1e-8, elements >= 1e-6
    edges = plan["edges"]
    assert "not resolved" in edges.choice and "energy-balance" in edges.choice
    assert "smallest element is 1e-06" in edges.reason


def test_plan_of_cohesive_zones_without_edge_zones():
    from viscocontact.methods.bem import Discretization

    plan = _md_plan(5e-4, 0.00398, rheology=Elastic(), zeta=0.0,   # λ = 10: a0 = 0.0079
                    discretization=Discretization(edge_resolution=None))
    assert "no edge zones" in plan["mesh"].choice
    assert "eq. 4.22" in plan["edges"].reason and "partly resolved" in plan["edges"].choice


def test_cli_explain_of_a_maugis_dugdale_scene(tmp_path, capsys):
    from viscocontact.cli import main

    scene = tmp_path / "md.toml"
    scene.write_text('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\n'
                     'kind = "standard-linear-solid"\nbeta = 10.0\n[load]\nmean_pressure = 0.05\n'
                     '[sliding]\nzeta = 0.3\n[adhesion]\nkind = "maugis-dugdale"\n'
                     'gamma = 2.4e-7\nrange = 1e-7\n', encoding="utf-8")
    assert main(["solve", str(scene), "--explain"]) == 0
    text = capsys.readouterr().out
    assert "Maugis-Dugdale zones" in text and "not resolved" in text and "area" not in text
