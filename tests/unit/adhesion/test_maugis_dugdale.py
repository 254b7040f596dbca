"""The Maugis–Dugdale adhesion model: parameters, units, registration and its cohesive zones."""
import tomllib
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest

from viscocontact import _registry
from viscocontact.adhesion import AdhesionModel, MaugisDugdale
from viscocontact.contact.cohesive import intensity, room, tips, zone_fields, zone_loads
from viscocontact.contact.fields import NormalizedProfile, solve_fields, stress_intensity
from viscocontact.contact.mesh import MeshSpec, build_mesh
from viscocontact.errors import ValidationError
from viscocontact.kernels import HalfPlane
from viscocontact.profiles import Sinusoid
from viscocontact.reference.maugis_dugdale import MaugisDugdaleWavy
from viscocontact.rheology import Elastic

ROOT = Path(__file__).resolve().parents[3]


@pytest.mark.parametrize("kw, field", [
    (dict(gamma=-1.0, range=1e-3), "gamma"),
    (dict(gamma=1e-3, range=0.0), "range"),
    (dict(gamma=1e-3, range=float("nan")), "range"),
    (dict(gamma=float("inf"), range=1e-3), "gamma"),
])
def test_invalid_parameters_name_the_field_and_range(kw, field):
    with pytest.raises(ValidationError, match=f"MaugisDugdale.{field}"):
        MaugisDugdale(**kw)


def test_cohesive_stress_matches_the_reference_scaling():
    """σ̃0 = 2πγ̃/(h̃0Λ̃) and η = h̃0/Λ̃ as in MaugisDugdaleWavy.from_groups."""
    m = MaugisDugdale(gamma=3e-4, range=2e-3)
    ref = MaugisDugdaleWavy.from_groups(gamma=3e-4, h0=2e-3, amplitude=0.07)
    assert m.strength(0.07) == pytest.approx(ref.cohesive_stress, rel=1e-14)
    assert m.opening(0.07) == pytest.approx(ref.h0, rel=1e-14)
    assert m.strength(0.07) * m.opening(0.07) == pytest.approx(m.target(0.07), rel=1e-14)
    assert m.quasi_static_zone == pytest.approx(2e-3**2 / (4 * 3e-4))
    assert m.resolved_lengths() == (pytest.approx(m.quasi_static_zone / 16),)
    assert MaugisDugdale(gamma=0.0, range=1e-3).resolved_lengths() == ()


def test_registered_as_maugis_dugdale_in_pyproject():
    """The entry point written in pyproject.toml loads the class (a fake entry point, so that
    the test does not depend on the installed metadata)."""
    eps = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["entry-points"]
    value = eps["viscocontact.adhesion"]["maugis-dugdale"]
    ep = metadata.EntryPoint(name="maugis-dugdale", group="viscocontact.adhesion", value=value)
    reg = _registry.Registry("viscocontact.adhesion", _registry._base("adhesion"),
                             entry_points=lambda: [ep])
    assert reg.get("maugis-dugdale") is MaugisDugdale
    assert issubclass(MaugisDugdale, AdhesionModel)


def _reference_field(lam, n=128):
    """Field of the elastic wavy MD state of transition λ (Γ̃ = 0.05, Λ̃ = 0.1) at its own edges."""
    amp, G = 0.1, 0.05
    ref = MaugisDugdaleWavy.from_transition(Gamma=G, transition=lam)
    state = ref.state_at_pressure(0.0)
    model = MaugisDugdale(gamma=G * amp**2, range=ref.h0 * amp)
    a = 0.5 * state.area
    edges = np.array([-a, a])
    spec = MeshSpec(elements=n, smallest=1e-4)
    mesh = build_mesh(edges, spec)
    kernel = HalfPlane().prepare(Elastic(), 0.0)
    shape = NormalizedProfile.of(Sinusoid(amplitude=amp))
    base = solve_fields(mesh, kernel, shape, penetration=state.penetration)
    return ref, state, model, kernel, shape, base


@pytest.mark.parametrize("lam", [1.0, 10.0])
def test_zones_of_the_reference_edges_are_the_reference_zones(lam):
    """At the reference's edges and penetration, the zones that bound the stress are the
    reference's zones, their tips open to η, and the load is the reference's."""
    ref, state, model, kernel, shape, base = _reference_field(lam)
    f = zone_fields(base, kernel, stress=model.strength(0.1), control={
        "penetration": state.penetration}, start=np.full(2, 1e-3))
    assert np.allclose(f.loads.width, state.zone_width, rtol=2e-3)
    c = tips(f.mesh.edges, f.loads.width)
    gap = f.displacement(kernel, c) - (shape.heights(c) - 1.0 + f.penetration)
    assert np.allclose(gap, ref.h0, rtol=2e-3)
    assert f.mean_pressure == pytest.approx(0.0, abs=2e-4)
    # the stress next to the edges is the reference's (bounded, tending to σ̃0)
    near = slice(0, 20)
    exact = ref.stress(f.mesh.mid[near], state.area, zone_angle=state.zone_angle)
    assert np.max(np.abs(f.sigma[near] - exact)) < 1e-2 * model.strength(0.1)


def test_a_zone_whose_edge_turns_compressive_closes_while_the_other_converges():
    """At fixed edges one edge compressive without a zone (``K̃ < 0`` at ``d = 0``), the other
    tensile: the first zone closes and the second bounds its stress. (A zone stepped past zero
    used to shrink by a factor per iteration until, far below the edge element, ``K̃`` no longer
    changed with it and the guard against long zones took every iteration: no convergence in
    60 iterations; the rough profile's approach ended there.)"""
    ref, state, model, kernel, shape, _ = _reference_field(10.0)
    a = 0.5 * state.area
    mesh = build_mesh(np.array([-a + 0.9, a + 0.9]), MeshSpec(elements=128, smallest=1e-4))
    d = state.penetration + 0.25
    base = solve_fields(mesh, kernel, shape, penetration=d)
    k0 = intensity(base)
    assert k0[0] < 0 < k0[1]
    f = zone_fields(base, kernel, stress=model.strength(0.1), control={"penetration": d},
                    start=np.full(2, model.quasi_static_zone))
    k = intensity(f)
    assert f.loads.width[0] == 0.0 and k[0] < 0
    assert f.loads.width[1] > 0.5 * model.quasi_static_zone
    assert abs(k[1]) < 1e-8 * model.strength(0.1)


def test_zones_open_from_none():
    """Started without zones at tensile edges, the zones open (at Dugdale's short zone
    ``πK̃²/(8σ̃0²)``) and reach the reference's."""
    ref, state, model, kernel, shape, base = _reference_field(10.0)
    f = zone_fields(base, kernel, stress=model.strength(0.1), control={
        "penetration": state.penetration}, start=np.zeros(2))
    assert np.allclose(f.loads.width, state.zone_width, rtol=2e-3)


def test_zone_loads_and_room():
    e = np.array([-1.0, 0.5, 1.0, 2.0])
    loads = zone_loads(e, np.array([0.1, 0.2, 0.1, 0.3]), 2.0)
    assert np.allclose(loads.left, [-1.1, 0.5, 0.9, 2.0])
    assert np.allclose(loads.width, [0.1, 0.2, 0.1, 0.3])
    assert loads.force() == pytest.approx(2.0 * 0.7)
    assert np.allclose(room(e), [2 * np.pi - 3.0, 0.5, 0.5, 2 * np.pi - 3.0])


def test_bounded_fit_reads_the_singularity_under_a_constant():
    """The fit with a constant recovers K̃ of ``c + K/√(2πr)`` near an edge."""
    mesh = build_mesh(np.array([-1.0, 1.0]), MeshSpec(elements=128, smallest=1e-4))
    left = mesh.mid < 0
    ra = np.where(left, mesh.left + 1.0, 1.0 - mesh.right)
    rb = np.where(left, mesh.right + 1.0, 1.0 - mesh.left)
    field = 3.0 + 0.2 / np.sqrt(2 * np.pi) * 2 * (np.sqrt(rb) - np.sqrt(ra)) / (rb - ra)
    from viscocontact.contact.fields import BOUNDED_POWERS

    k = stress_intensity(mesh, field, BOUNDED_POWERS)
    assert np.allclose(k, 0.2, rtol=1e-6)


def test_closed_strength_is_the_cohesive_stress():
    """A closed Maugis-Dugdale interface opens where its tension exceeds σ̃0; one of vanishing
    range (energy balance) never; without adhesion wherever it is tensile."""
    from viscocontact.adhesion import EnergyBalance, NoAdhesion

    m = MaugisDugdale(gamma=5e-4, range=1e-3)
    assert m.closed_strength(0.1) == m.strength(0.1)
    assert MaugisDugdale(gamma=0.0, range=1e-3).closed_strength(0.1) == 0.0
    assert EnergyBalance(gamma=5e-4).closed_strength(0.1) == np.inf
    assert NoAdhesion().closed_strength(0.1) == 0.0
