"""The jump rule: the edges' overdamped motion lands where Johnson's wavy contact says, on the
side of the unstable root it starts from, and the landing does not depend on the integration
tolerance."""
import contextlib

import attrs
import numpy as np
import pytest
from scipy.optimize import brentq

import viscocontact as vc
from viscocontact.methods.bem import BEM
from viscocontact.methods.bem.relax import RelaxFrom, Relaxation
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Modes, SpectralProfile
from viscocontact.reference.johnson import JohnsonWavy

GAMMA, AMPLITUDE, LOAD = 0.02, 0.05, 0.3
JOHNSON = JohnsonWavy(Gamma=GAMMA, modulus_ratio=1.0)
#: Johnson's roots of p̃∞(Ã) = LOAD: the stable one (rising load) and the unstable one (falling)
STABLE = brentq(lambda a: JOHNSON.mean_pressure(a) - LOAD, 0.72, 4.79)
UNSTABLE = brentq(lambda a: JOHNSON.mean_pressure(a) - LOAD, 4.8, 6.2)


def problem(**control):
    return ContactProblem(profile=vc.Sinusoid(amplitude=AMPLITUDE), rheology=vc.Elastic(),
                          adhesion=vc.EnergyBalance(gamma=GAMMA * AMPLITUDE**2),
                          solver=vc.Newton(), zeta=1.0, **(control or {"mean_pressure": LOAD}))


@pytest.mark.parametrize("start", [0.1, 0.97 * UNSTABLE])
def test_below_the_unstable_root_the_edges_settle_on_the_stable_one(start):
    """From a narrow contact (it grows) and from just inside the unstable root (it shrinks) the
    motion ends on the stable root, at both tolerances; the area is Johnson's to the mesh's
    error (about 1e-4 of the area at the default mesh) and the two tolerances agree to the
    solver's tolerance."""
    areas = []
    for tol in (0.02, 0.002):
        result = problem().solve(initial=RelaxFrom([-start / 2, start / 2], tolerance=tol))
        assert result.converged and result.n_contacts == 1
        assert any("overdamped motion" in e for e in result.extras["events"])
        areas.append(result.area)
    assert areas[0] == pytest.approx(STABLE, rel=3e-4)
    assert areas[1] == pytest.approx(areas[0], rel=1e-7)


def test_outside_the_unstable_root_the_edges_run_away_from_the_stable_one():
    """Just outside the unstable root the contact grows instead, away from the stable root,
    towards closure. (Johnson's contact closes; the BEM's mesh does not resolve a gap below
    about 2e-3 of the period between two edges, where it may stop on a near-closed state
    instead: ``docs/histories.md``.)"""
    for tol in (0.02, 0.002):
        result = problem().solve(initial=RelaxFrom([-0.515 * UNSTABLE, 0.515 * UNSTABLE],
                                                   tolerance=tol))
        assert result.converged and (result.full_contact or result.area > 0.99 * 2 * np.pi)


def test_a_motion_that_does_not_stop_within_its_steps_says_so():
    from viscocontact.methods.bem.method import Solve

    p = problem()
    solve = Solve(p, p.prepare())
    relax = Relaxation(solve.equilibrium, solve.closed, tolerance=0.02, max_steps=2)
    from viscocontact.methods.bem.sets import Control

    out = relax.run(np.array([-0.05, 0.05]), Control.load_of(LOAD))
    assert not out.converged and "did not stop within 2 steps" in out.message


def _load_fold():
    """The BEM's largest load of Johnson's wavy contact before it closes, and the edges and
    area there: the vertex of the load against the penetration (penetration-controlled states,
    which stay stable past it), from parabolas through three states, each closer than the last."""
    depth, states = 0.927, None
    for spacing in (5e-3, 5e-4, 1e-4):
        depths = depth + spacing * np.array([-1.0, 0.0, 1.0])
        states = [problem(penetration=d).solve() for d in depths]
        assert all(s.converged and s.n_contacts == 1 for s in states)
        c = np.polyfit(depths - depths[1], [s.mean_pressure for s in states], 2)
        depth = depths[1] - c[1] / (2 * c[0])
    at = problem(penetration=depth).solve()
    return at.mean_pressure, at.edges, at.area


def test_a_motion_that_slows_down_past_a_fold_goes_on_through_it():
    """Johnson's wavy contact under load control, started at the BEM's largest load before
    closure (located to about 1e-10): just past it (2.4e-7 of the load) no equilibrium is left,
    the edges crawl where the root has just vanished (max|r| below the motion's rest level), the
    equilibrium solve there fails, and the motion goes on through that bottleneck and closes
    the contact; just below it the motion lands on the partial contact there."""
    fold, edges, area = _load_fold()
    past = problem(mean_pressure=fold + 1e-7).solve(initial=RelaxFrom(edges))
    assert past.converged and past.full_contact, past.message
    assert any(e.startswith("the edges' motion slowed down past a fold")
               for e in past.extras["events"])
    before = problem(mean_pressure=fold - 1e-7).solve(initial=RelaxFrom(edges))
    assert before.converged and before.n_contacts == 1 and not before.full_contact
    assert before.area == pytest.approx(area, rel=1e-2)


@attrs.frozen
class _TwoPeaks(SpectralProfile):
    """Two asperities a period: ``Λ̃ (0.2 cos x̃ + cos 2x̃)``."""

    amplitude: float = 0.05

    @property
    def modes(self) -> Modes:
        return Modes(wavenumbers=[1, 2], amplitudes=[0.2 * self.amplitude, self.amplitude],
                     phases=[0.0, 0.0])


@pytest.mark.parametrize("penetration", [0.5, 0.6])
@pytest.mark.parametrize("start", [(-0.3, np.pi + 0.3), (-0.8, np.pi + 0.8)])
def test_a_contact_at_rest_that_carries_tension_splits_and_moves_on(penetration, start):
    """One contact over both asperities (adhesionless, elastic): its edges come to rest with
    tension over the valley between the peaks, the contact splits there, and the motion of the
    parts ends at the unique adhesionless equilibrium, the one the approach from first touch
    reaches (to the solver's tolerance)."""
    problem = ContactProblem(profile=_TwoPeaks(), rheology=vc.Elastic(), solver=vc.Newton(),
                             penetration=penetration, method=BEM())
    moved = problem.solve(initial=RelaxFrom(list(start)))
    assert moved.converged and moved.n_contacts == 2
    assert [r["kind"] for r in moved.extras["path_events"]] == ["split"]
    assert any("opened at 1 place(s) where they carried tension" in e
               for e in moved.extras["events"])
    assert moved.area == pytest.approx(problem.solve().area, rel=1e-7)


def test_a_first_contact_that_shrinks_away_detaches():
    """Campaign seed 150 (sinusoid, SLS β = 9483 on a free layer, ζ = 2e-4, weak adhesion):
    the first contact spreads to about 1.2 wide, then shrinks to nothing. On the zones made in
    the motion's first steps, a contact thousands of times narrower had residuals of round-off
    (hundreds of times the work of adhesion, of either sign) and the motion wandered for 2000
    steps; with its zones remade as it shrinks, and detached once narrower than the mesh
    resolves, the motion ends: no contact holds at first touch."""
    from viscocontact.methods.bem.method import Solve
    from viscocontact.methods.bem.sets import Control, first_touch
    from viscocontact.methods.bem.state import Outcome
    from viscocontact.testing.campaign import draw

    p = ContactProblem.from_scene(vc.Scene.from_dict(draw(150)))
    solve = Solve(p, p.prepare())
    d0, edges = first_touch(solve.prep.shape)
    touch = Control.penetration_of(d0)
    out = Relaxation(solve.equilibrium, solve.closed).run(
        solve.approach.with_field(edges, touch), touch, final=False, births=False)
    assert out.outcome is Outcome.NO_CONTACT, out.message
    assert solve.log.events[-1] == "the edges' motion detached every contact"


def test_a_contact_narrower_than_the_mesh_resolves_detaches_while_it_narrows():
    """Below :data:`SMALLEST_RESOLVED` a narrowing contact is collapsed (and detached by the
    repair); one that widens there (just born) and wider ones are kept."""
    from viscocontact.methods.bem.meshing import SMALLEST_RESOLVED
    from viscocontact.methods.bem.relax import _vanishing

    w = SMALLEST_RESOLVED
    before = np.array([0.0, 0.8 * w, 1.0, 1.0 + 0.5 * w, 2.0, 2.0 + 3 * w])
    after = np.array([0.0, 0.9 * w, 1.0, 1.0 + 0.4 * w, 2.0, 2.0 + 2 * w])
    out = _vanishing(before, after)
    assert out[0:2].tolist() == after[0:2].tolist()              # widening: kept
    assert out[2] == out[3] == pytest.approx(1.0 + 0.2 * w)      # narrowing below: collapsed
    assert out[4:6].tolist() == after[4:6].tolist()              # above the floor: kept


def test_a_proposed_step_is_shortened_to_its_reach_without_counting_as_a_try():
    """A step whose move would go past the reach the tolerance allows is shortened within the
    proposal (no evaluation, no try of the motion's budget): a narrow contact closing at a
    speed of order one gets a move within reach at once, from a step a thousand times too
    long."""
    from viscocontact.methods.bem.relax import _Motion, _proposed, _scale

    tolerance = 0.02
    x = np.array([1.0, 1.0 + 1e-4])                   # a contact 1e-4 wide
    r = np.array([-1.0, 1.0])                          # both edges move inwards at speed 1
    J = np.diag([1e-3, 1e-3])
    m = _Motion(system=None, x=x, r=r, J=J, h=0.1)
    out = _proposed(m, r, J, tolerance)
    assert out is not None
    move, h = out
    reach = np.max(np.abs(move) / _scale(x)) / np.sqrt(2 * tolerance)
    assert reach <= 1.0
    assert reach > 0.5                                 # not shortened past what it needs
    assert m.h == h < 1e-4


class _Edges:
    """Two edges: the first at rest, the second's residual either jumps from -0.25 to 2e-3
    across ``AT`` (``jump``) or passes through zero there with the slope 500."""

    AT = 1.0

    def __init__(self, jump: bool):
        self.jump = jump

    @contextlib.contextmanager
    def probing(self):
        yield self

    def residual(self, x):
        d = x[1] - self.AT
        if not self.jump:
            return np.array([0.0, 500.0 * d])
        return np.array([0.0, (2e-3 if d >= 0 else -0.25) + 10.0 * d])


def _crossings(system, moving: float = 0.0, changed: bool = False):
    """The two crossings of the second edge (out, then back) of a motion on ``system`` whose
    Jacobian's slope is 10, the first edge's residual at ``moving``; :func:`_held` of each."""
    from viscocontact.methods.bem.relax import _held, _Motion

    def resolved(motion):
        return 1e-9                              # the solver's tolerance

    inside, outside = np.array([0.0, _Edges.AT - 1e-6]), np.array([0.0, _Edges.AT + 1e-6])
    m = _Motion(system=system, x=inside, r=system.residual(inside), J=np.diag([1.0, 10.0]))
    out = []
    for before, after in ((inside, outside), (outside, inside)):
        m.x, m.r = before, system.residual(before) + [moving, 0.0]
        out.append(_held(m, system.residual(after) + [moving, 0.0], after, changed, resolved))
    return out, m


def test_an_edge_that_crosses_a_jump_of_its_residual_both_ways_is_held_there():
    """A sign change of a residual far larger than its Jacobian predicts, crossed out and back
    while the other edges are at rest, is bisected: where the change stays as its bracket
    narrows (a jump) the motion stops with the reason; where it shrinks (a root the Jacobian
    misjudged), it goes on. While another edge moves (a shrinking contact's unresolved
    residuals jump too) or the contact set changes, it goes on without bisecting."""
    (first, why), _ = _crossings(_Edges(jump=True))
    assert first is None
    assert why is not None and "jumps across zero (from -0.25 to 0.002" in why
    assert "outside the model" in why
    assert _crossings(_Edges(jump=False))[0] == [None, None]
    assert _crossings(_Edges(jump=True), moving=0.5)[0] == [None, None]
    out, m = _crossings(_Edges(jump=True), changed=True)
    assert out == [None, None] and m.jumps == {}


def test_a_finite_advance_holds_an_edge_where_its_stress_intensity_changes_sign():
    """Campaign seed 239 at the penetration where its approach meets it (SLS β = 8785 at
    ζ = 62, energy balance over δX = 1e-4): the right edge's release over δX reaches the work
    of adhesion where K̃ changes sign, so its residual jumps across zero there and the motion
    holds it (outside the model); with δX = 0 the release vanishes with K̃ and the same start
    converges, the edge further out (docs/edges.md, "An edge held where K̃ changes sign")."""
    from viscocontact.testing.campaign import draw

    table = draw(239)
    table["load"] = {"penetration": 0.04555835526402752}
    start = RelaxFrom([2.0716195, 2.0795354])
    held = vc.solve(vc.Scene.from_dict(table), initial=start)
    assert not held.converged
    assert "holds edge 2" in held.message and "outside the model" in held.message
    table["adhesion"] = {**table["adhesion"], "edge_perturbation": 0.0}
    limit = vc.solve(vc.Scene.from_dict(table), initial=start)
    assert limit.converged and limit.n_contacts == 1
    assert limit.edges.ravel()[1] > 2.0795354 + 1e-5


def _thesis_rough_cohesive(method):
    """The thesis rough profile (seed 0) with Maugis-Dugdale zones of range h̃0 = 1e-4 at
    ζ = 1e-2, p̃∞ = 0.3 (``benchmarks/cohesive_rough.py --range 1e-7``), as a scene."""
    return vc.Scene.from_dict({
        "profile": {"kind": "self-affine", "hurst": 0.8, "scales": 50, "rms": 0.01, "seed": 0},
        "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
        "adhesion": {"kind": "maugis-dugdale", "gamma": 2.3885e-7, "range": 1e-4},
        "solver": {"kind": "broyden"}, "load": {"mean_pressure": 0.3},
        "sliding": {"zeta": 1e-2}, "method": {"kind": method}})


def test_a_motion_that_slides_along_the_filling_of_a_neck_ends_there():
    """Past a fold at p̃∞ = 0.093 on :func:`_thesis_rough_cohesive`, the motion reaches the
    edges where the two zones of a neck switch from stopping short of each other to filling
    it, every residual jumping; the flow on both sides points at the switch, and the steps
    crossed it back and forth at a crawl until their budget of 2000 ran out (40 s). The state
    on the switch holds a zone apart from the contacts, which the BEM's zones do not
    represent: the motion ends there and says so."""
    out = vc.solve(_thesis_rough_cohesive("bem"))
    assert not out.converged
    assert "slides along the filling of a neck by cohesive zones" in out.message
    assert "zones at the edges of contacts do not represent" in out.message


@pytest.mark.slow
def test_auto_gives_a_neck_filled_in_part_to_the_grid():
    """The same scene under ``auto``: the grid, which represents a zone apart from the
    contacts, solves it once the BEM's motion has ended, and its answer passes the campaign's
    checks (load, gap, friction against the dissipated power within its estimate)."""
    from viscocontact.testing.campaign import check

    scene = _thesis_rough_cohesive("auto")
    out = vc.solve(scene)
    assert out.converged and out.method == "spectral"
    assert any("slides along the filling of a neck" in e for e in out.extras["events"])
    failures, _, _ = check(scene, out)
    assert failures == []
