"""The Maugis–Dugdale adhesion model: parameters, units, registration and its cohesive zones."""
import tomllib
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact import _registry
from viscocontact.adhesion import AdhesionModel, MaugisDugdale
from viscocontact.contact.cohesive import (bounded_weights, intensity, intensity_jacobian, room,
                                           tip_gap_jacobian, tip_gaps, tips, zone_fields,
                                           zone_loads)
from viscocontact.contact.fields import (BOUNDED_POWERS, NormalizedProfile, intensity_matrix,
                                         solve_fields, stress_intensity, with_loads)
from viscocontact.contact.mesh import MeshSpec, build_mesh
from viscocontact.errors import ValidationError
from viscocontact.kernels import HalfPlane
from viscocontact.profiles import Sinusoid
from viscocontact.reference.maugis_dugdale import MaugisDugdaleWavy
from viscocontact.rheology import Elastic, StandardLinearSolid

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


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), bounded=st.booleans())
def test_intensity_matrix_is_the_fit(seed, bounded):
    """``W σ̃`` is :func:`stress_intensity`'s fit (pseudo-inverse against least squares: equal to
    round-off) on a two-contact mesh with edge elements of 1e-6 and any field."""
    rng = np.random.default_rng(seed)
    mesh = build_mesh(np.array([-1.0, -0.3, 0.2, 1.5]), MeshSpec(elements=96, smallest=1e-6))
    r = np.minimum(mesh.mid - mesh.edges[np.searchsorted(mesh.edges, mesh.mid) - 1],
                   mesh.edges[np.searchsorted(mesh.edges, mesh.mid)] - mesh.mid)
    field = rng.normal(size=mesh.mid.size) + rng.normal() / np.sqrt(r)
    powers = BOUNDED_POWERS if bounded else (-0.5, 0.5, 1.5)
    k = stress_intensity(mesh, field, powers)
    assert np.allclose(intensity_matrix(mesh, powers) @ field, k,
                       rtol=0, atol=1e-12 * np.max(np.abs(k)))


@settings(max_examples=15, deadline=None)
@given(d=st.lists(st.floats(1e-5, 3e-2), min_size=4, max_size=4),
       zeta=st.sampled_from([0.0, 1e-2, 1.0]), load=st.booleans(),
       zones=st.sampled_from([(0, 1, 2, 3), (1, 2), (3,)]))
def test_intensity_jacobian_equals_central_differences(d, zeta, load, zones):
    """``∂K̃_i/∂d_j`` of two contacts of a sinusoid with zones (elastic, or an SLS β = 10 at
    ζ = 1e-2 and 1), in both controls: against central differences of the field solved with
    the zones, Richardson-extrapolated from steps of 3e-3 and 1.5e-3 of each zone. Their error:
    the fields' round-off (about 2e-11 in K̃) over h, which rules out small steps at a zone of
    1e-5, and truncation, which is not O(h⁴) everywhere (the kernel table is a C¹ piecewise
    cubic), which rules out large ones. Measured on the two drawn examples that failed other
    steps: at most 2e-7 and 7e-7 of a column's largest entry at 3e-3 (1e-6 and 4e-6 at 1e-2,
    1.2e-6 and 4e-7 at 1e-3, 1.2e-5 and 5e-7 at 1e-4); over 150 random draws (both controls,
    the three kernels, zones 1e-5 to 3e-2) at most 1.3e-6. Tolerance 1e-5 of each column's
    largest entry: the reference's accuracy (a wrong term, such as the load control's
    penetration change, is off by 8e-4 to 1e-2 here)."""
    rheology = Elastic() if zeta == 0 else StandardLinearSolid(beta=10.0)
    kernel = HalfPlane().prepare(rheology, zeta)
    shape = NormalizedProfile.of(Sinusoid(amplitude=0.1))
    edges = np.array([-0.9, -0.35, 0.25, 0.8])
    mesh = build_mesh(edges, MeshSpec(elements=96, smallest=1e-5))
    control = {"mean_pressure": 0.05} if load else {"penetration": 0.4}
    base = solve_fields(mesh, kernel, shape, **control)
    d = np.array(d)
    stress = 12.0

    def k_of(lengths):
        return intensity(with_loads(base, kernel, zone_loads(edges, lengths, stress), **control))

    cols = np.array(zones)
    f = with_loads(base, kernel, zone_loads(edges, d, stress), **control)
    J = intensity_jacobian(f, kernel, stress=stress, control=control, columns=cols)

    def central(j, h):
        plus, minus = d.copy(), d.copy()
        plus[j] += h
        minus[j] -= h
        return (k_of(plus) - k_of(minus)) / (2 * h)

    fd = np.empty_like(J)
    for col, j in enumerate(cols):
        h = 3e-3 * d[j]
        fd[:, col] = (4 * central(j, h / 2) - central(j, h)) / 3
    scale = np.max(np.abs(fd), axis=0)
    assert np.all(np.abs(J - fd) <= 1e-5 * scale), (J, fd)


@pytest.mark.parametrize("zeta", [0.0, 1.0])
@pytest.mark.parametrize("load", [False, True])
def test_tip_gap_jacobian_equals_central_differences(zeta, load):
    """``∂g̃(c_i)/∂d_j`` (the tip condition that ``TipCondition`` mixes into the zones'
    equations) of two contacts with zones of 0.03 to 0.4 (elastic and an SLS β = 10 at ζ = 1,
    both controls) against central differences of the field solved with the zones, steps of
    1e-6: measured within 2.4e-8 of the largest entry; tolerance 1e-6 (the zone's own far-end
    term alone is 0.4 of it)."""
    rheology = Elastic() if zeta == 0 else StandardLinearSolid(beta=10.0)
    kernel = HalfPlane().prepare(rheology, zeta)
    shape = NormalizedProfile.of(Sinusoid(amplitude=0.1))
    edges = np.array([-1.2, -0.35, 0.45, 1.1])
    mesh = build_mesh(edges, MeshSpec(elements=96, smallest=1e-5))
    control = {"mean_pressure": 0.05} if load else {"penetration": 0.4}
    base = solve_fields(mesh, kernel, shape, **control)
    d = np.array([0.4, 0.03, 0.1, 0.25])
    stress = 0.8

    def g_of(lengths):
        f = with_loads(base, kernel, zone_loads(edges, lengths, stress), **control)
        return tip_gaps(f, kernel, shape, tips(edges, lengths))

    f = with_loads(base, kernel, zone_loads(edges, d, stress), **control)
    J = tip_gap_jacobian(f, kernel, shape, stress=stress, control=control, columns=np.arange(4))
    fd = np.empty_like(J)
    for j in range(4):
        plus, minus = d.copy(), d.copy()
        plus[j] += 1e-6
        minus[j] -= 1e-6
        fd[:, j] = (g_of(plus) - g_of(minus)) / 2e-6
    assert np.max(np.abs(J - fd)) <= 1e-6 * np.max(np.abs(fd)), (J, fd)


def test_the_fit_rows_are_computed_once_per_mesh():
    """The zone iteration, the residual and the edge terms fit on one mesh: its rows are kept
    (the same array, read-only, equal to a fresh computation) and a new mesh gets its own."""
    mesh = build_mesh(np.array([-1.0, 1.0]), MeshSpec(elements=64, smallest=1e-4))
    w = bounded_weights(mesh)
    assert bounded_weights(mesh) is w
    assert not w.flags.writeable
    assert np.array_equal(w, intensity_matrix(mesh, BOUNDED_POWERS))
    other = build_mesh(np.array([-1.0, 1.1]), MeshSpec(elements=64, smallest=1e-4))
    assert bounded_weights(other) is not w



def test_a_gap_below_the_range_outside_the_zones_snaps_into_contact():
    """η = 0.1 (h̃0 = 1e-2, Λ̃ = 0.1); zones [0.9, 1] and [2, 2.1]. A dip of the gap to 0.05
    inside a zone is the zone's business; one outside, across [3.9, 4.1], is born as a contact
    where the gap is below η (its ends interpolated between the samples). Models of vanishing
    range have no such regions."""
    from types import SimpleNamespace

    from viscocontact.adhesion import EnergyBalance, NoAdhesion
    from viscocontact.contact.cohesive import zone_loads

    m = MaugisDugdale(gamma=1e-4, range=1e-2)
    fields = SimpleNamespace(loads=zone_loads(np.array([1.0, 2.0]), np.array([0.1, 0.1]),
                                              m.strength(0.1)))
    x = np.linspace(0.0, 2 * np.pi, 629)[:-1]
    gap = np.full_like(x, 0.2)
    gap[np.abs(x - 0.95) < 0.04] = 0.05
    dip = np.abs(x - 4.0) <= 0.1 + 1e-12
    gap[dip] = 0.05
    regions = m.snap_in(x, gap, fields)
    assert len(regions) == 1
    a, b, depth = regions[0]
    first, last = np.flatnonzero(dip)[[0, -1]]
    assert x[first - 1] < a < x[first] and x[last] < b < x[last + 1]
    assert depth == pytest.approx(0.05 - 0.1)
    assert "below the range h0" in m.gap_violation(x, gap, fields)
    assert m.snap_in(x, np.full_like(x, 0.2), fields) == []
    for other in (EnergyBalance(gamma=5e-4), NoAdhesion(), MaugisDugdale(gamma=0.0, range=1e-2)):
        assert other.snap_in(x, gap, fields) == []


def test_which_models_have_singular_edges():
    """Contract item 12: energy flows into the tips of the energy balance's edges, not into a
    cohesive zone's or an adhesionless contact's (the BEM's estimate bounds μ and the
    dissipated power by their misfit for these)."""
    from viscocontact.adhesion import EnergyBalance, LennardJones, NoAdhesion

    assert EnergyBalance(gamma=1e-6).singular_edges(0.1)
    assert not EnergyBalance(gamma=0.0).singular_edges(0.1)
    assert not MaugisDugdale(gamma=1e-6, range=1e-3).singular_edges(0.1)
    assert not LennardJones(gamma=1e-6, range=1e-3).singular_edges(0.1)
    assert not NoAdhesion().singular_edges(0.1)


# two contacts of campaign seed 234's scene (rough, SLS β = 166, ζ = 6.3e-3, half-plane) that its
# first contact's motion met at Δ̃ = 9.66e-4; the neck between them is 0.082 wide
ROOTLESS_DEPTH = 0.000965986110799566
ROOTLESS_EDGES = np.array([5.64509216, 5.74881304, 5.8308437, 6.02948573])


def _campaign_solve(table):
    """The BEM solve's parts for the campaign scene ``table``."""
    import viscocontact as vc
    from viscocontact.methods.bem import BEM
    from viscocontact.methods.bem.method import Solve
    from viscocontact.problem import ContactProblem

    problem = ContactProblem.from_scene(vc.Scene.from_dict(table), method=BEM())
    return Solve(problem, problem.prepare())


@pytest.mark.parametrize("start", [None, [0.01714, 0.01117, 0.02266, 0.0104]])
def test_a_zone_without_a_root_short_of_its_neighbour_fills_the_neck(start):
    """The zone at the right contact's left edge passes the minimum of its equation with its
    edge still tensile (K̃ = 0.008 at d = 0.03): it has no root short of the facing zone.
    Shortened, it grew back past the minimum, and the iteration cycled until it gave up (the
    motion then met no field and its steps shrank to 1e-15). Now the neck fills: from short
    zones and from the zones of the motion's last state alike, the two zones tile the neck and
    the outer zones keep their roots."""
    from viscocontact.methods.bem.sets import Control
    from viscocontact.testing.campaign import draw

    solve = _campaign_solve({**draw(234), "load": {"penetration": ROOTLESS_DEPTH}})
    system = solve.equilibrium.system(Control.penetration_of(ROOTLESS_DEPTH), ROOTLESS_EDGES)
    if start is not None:
        from types import SimpleNamespace

        previous = SimpleNamespace(loads=SimpleNamespace(width=np.array(start),
                                                         stress=np.zeros(4)),
                                   mesh=SimpleNamespace(edges=ROOTLESS_EDGES))
        system._previous = previous
    system.shared = None
    fields, _, r = system.evaluate(ROOTLESS_EDGES)
    d = fields.loads.width
    neck = ROOTLESS_EDGES[2] - ROOTLESS_EDGES[1]
    assert np.all(np.isfinite(r))
    assert d[1] + d[2] == pytest.approx(neck, rel=1e-6)
    assert 0.0 < d[0] < 0.05 and 0.0 < d[3] < 0.05


#: Campaign seed 189 (sinusoid Λ̃ = 0.031, SLS β = 3993, confined layer, η ≈ 0.025) at zero load
#: on its way into contact: a contact, and the next point its motion evaluated.
ONE_CONTACT = np.array([-0.04472459349322791, 0.04682680775564137])
MOVED = np.array([-0.04473792376328812, 0.0532373154492245])


def test_the_zones_do_not_depend_on_the_last_evaluation():
    """The residual at given edges is the same whatever the system evaluated before. Started
    from the zones of the last evaluation, the point ``MOVED`` after ``ONE_CONTACT`` gave
    r = (-0.196, -114.7), and from short zones (3.11, -18010): another root of the zones'
    equations, and a motion whose landing depended on how many evaluations it took."""
    from viscocontact.methods.bem.sets import Control
    from viscocontact.testing.campaign import draw

    solve = _campaign_solve({**draw(189), "method": {"kind": "bem"}})
    control = Control.load_of(0.0)
    after = solve.equilibrium.system(control, ONE_CONTACT)
    fresh = solve.equilibrium.system(control, ONE_CONTACT)
    after.shared = fresh.shared = None
    assert np.all(np.isfinite(after.evaluate(ONE_CONTACT.copy())[2]))
    r_after = after.evaluate(MOVED.copy())[2]
    r_fresh = fresh.evaluate(MOVED.copy())[2]
    assert np.all(np.isfinite(r_fresh))
    np.testing.assert_array_equal(r_after, r_fresh)


def test_a_zone_without_a_root_whose_neck_cannot_fill_has_no_field():
    """Campaign seed 29 (sinusoid, Prony, free layer, load control) just past a fold at
    p̃∞ = -0.184: the left zone of its one contact passes the minimum of its equation with its
    edge tensile, and its neck (across the period, almost the whole period wide) cannot fill.
    Shortened and regrown, it cycled until the 60 iterations ran out; now the edges have no
    field at once, for the reason that the zones meet where the traction cannot hold."""
    from viscocontact.methods.bem.sets import Control
    from viscocontact.testing.campaign import draw

    solve = _campaign_solve(draw(29))
    r = solve.equilibrium.residual_at(np.array([-0.04139057, 0.00658234]),
                                      Control.load_of(-0.18407468975388852))
    assert not np.any(np.isfinite(r))
    assert "cannot fill the neck" in solve.equilibrium.limitation


def test_zones_at_their_round_off_floor_are_taken(monkeypatch):
    """With the convergence tests made unreachable (tolerances of zero), the iteration runs
    out at the round-off of its equations: that state is taken where its equations are within
    four times their measured floor, and its zones are the converged ones'; cut off before it
    gets there (two iterations), it is no state and the iteration says so."""
    import viscocontact.contact.cohesive as cohesive
    from viscocontact.contact.cohesive import ZoneError

    ref, state, model, kernel, shape, base = _reference_field(10.0)
    arguments = dict(stress=model.strength(0.1), control={"penetration": state.penetration},
                     start=np.full(2, 1e-3))
    converged = zone_fields(base, kernel, **arguments)
    monkeypatch.setattr(cohesive, "EDGE_TOLERANCE", 0.0)
    monkeypatch.setattr(cohesive, "NOISE", 0.0)
    monkeypatch.setattr(cohesive, "EDGE_STEP", 0.0)
    floor = zone_fields(base, kernel, **arguments)
    assert np.allclose(floor.loads.width, converged.loads.width, rtol=1e-9)
    monkeypatch.setattr(cohesive, "ITERATIONS", 2)
    with pytest.raises(ZoneError, match="did not converge in 2 Newton iterations"):
        zone_fields(base, kernel, **arguments)
