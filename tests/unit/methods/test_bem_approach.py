"""The approach with events: its events (each fires on a
case), the fold estimate on a branch whose fold is known, and the answer converged in the step."""
from __future__ import annotations

import attrs
import numpy as np
import pytest

from viscocontact.adhesion import EnergyBalance
from viscocontact.methods.bem.approach import ApproachOptions
from viscocontact.methods.bem.sets import Control
from viscocontact.methods.bem.state import Outcome, State
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Broyden, Newton

SLS = StandardLinearSolid(beta=10.0)


def rough12(path_step=0.05, **control):
    """A 12-scale self-affine profile, adhesive (γ̃ = 2.387e-7, Broyden, ζ = 0.1): contacts are
    born, fold, jump and merge on the way into one."""
    return ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=12, rms=0.01, seed=3),
                          rheology=SLS, solver=Broyden(), adhesion=EnergyBalance(gamma=2.387e-7),
                          zeta=0.1, discretization=Discretization(elements=32,
                                                                  path_step=path_step),
                          **(control or {"penetration": 0.4}))


def kinds(result) -> set:
    return {e["kind"] for e in result.extras["path_events"]}


def test_a_rough_approach_meets_births_folds_jumps_and_merges_and_is_converged_in_the_step():
    """In penetration control the approach meets every kind of event of a rough contact, and
    a four times finer path (its events located four times closer) reaches the same
    equilibrium: the same contact, Ã to the solver's tolerance (measured 5e-12)."""
    coarse, fine = (rough12(path_step=0.05 / k).solve() for k in (1, 4))
    assert coarse.converged and fine.converged
    assert {"birth", "fold", "jump", "merge"} <= kinds(coarse)
    assert coarse.n_contacts == fine.n_contacts
    assert coarse.area == pytest.approx(fine.area, rel=1e-8)
    # every jump leaves the branch at a fold or where a contact is born (an adhesive spot
    # born at a point jumps open), at a penetration
    events = coarse.extras["path_events"]
    jumps = [j for j, e in enumerate(events) if e["kind"] == "jump"]
    assert jumps and all("penetration" in events[j] for j in jumps)
    for j in jumps:
        before = [e["kind"] for e in events[:j]]
        assert {"fold", "birth"} & set(before[-3:]), before


@pytest.mark.slow
def test_under_load_control_the_rough_approach_is_converged_in_the_step():
    coarse, fine = (rough12(path_step=0.05 / k, mean_pressure=0.2).solve() for k in (1, 4))
    assert coarse.converged and fine.converged and coarse.n_contacts == fine.n_contacts
    assert coarse.area == pytest.approx(fine.area, rel=1e-8)


def test_past_its_load_peak_a_wavy_contact_jumps_to_closure_under_load_control():
    """The adhesive sinusoid (Λ̃ = 0.05, γ̃ = 1e-5, β = 10, ζ = 0.01) at p̃∞ = 0.6: its branch's
    load peaks below the target (a fold in the load), the edges' motion past it closes the
    contact, and a closed adhesive contact carries the load."""
    problem = ContactProblem(profile=Sinusoid(amplitude=0.05), rheology=SLS, solver=Broyden(),
                             adhesion=EnergyBalance(gamma=1e-5), mean_pressure=0.6, zeta=0.01)
    result = problem.solve()
    assert result.converged and result.full_contact
    events = result.extras["path_events"]
    assert [e["kind"] for e in events][-2:] == ["fold", "closure"]
    assert "mean_pressure" in events[-2] and events[-2]["mean_pressure"] < 0.6


def test_under_load_control_the_first_contact_settles_at_zero_load(monkeypatch):
    """Loaded from zero, the profile first touches under no load: its first contact snaps in
    under load control, at p̃∞ = 0, not at the first touch's penetration (which left it at a
    tensile load on the branch that load control cannot hold)."""
    from viscocontact.methods.bem.approach import Approach

    starts = []
    climb = Approach.climb

    def recorded(self, state, target):
        starts.append(float(state.fields.mean_pressure))
        return climb(self, state, target)

    monkeypatch.setattr(Approach, "climb", recorded)
    problem = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=SLS, solver=Newton(),
                             adhesion=EnergyBalance(gamma=1e-4), zeta=1e-3, mean_pressure=0.1)
    assert problem.solve().converged
    # load control imposes the landing's load: zero to round-off (at the touch's penetration
    # the landing sat at p̃∞ = -0.083)
    assert starts and abs(starts[0]) < 1e-9


def test_the_target_ends_the_path_exactly():
    for control in ({"penetration": 0.3}, {"mean_pressure": 0.1}):
        problem = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=SLS, solver=Newton(),
                                 adhesion=EnergyBalance(gamma=1e-4), zeta=1e-3, **control)
        result = problem.solve()
        key, value = next(iter(control.items()))
        assert result.converged and getattr(result, key) == pytest.approx(value, abs=1e-9)


class _Parabola:
    """Residuals with a parabolic fold: ``r₀ = a(x₀ - x*)² - (v* - v)`` (the left edge of the
    first contact runs into the fold at ``v*``), every other edge ``rᵢ = xᵢ - xᵢ⁰ - sᵢv``
    (linear). The stand-in of both the state's edge system and the equilibrium."""

    log = None
    control = Control.penetration_of(0.0)       # (a system in penetration control)

    def __init__(self, a, x_star, fold, x_lin, s_lin):
        self.a, self.x_star, self.fold = a, x_star, fold
        self.x_lin, self.s_lin = np.asarray(x_lin, float), np.asarray(s_lin, float)

    def residual_at(self, x, control):
        v = control.value
        return np.concatenate([[self.a * (x[0] - self.x_star) ** 2 - (self.fold - v)],
                               x[1:] - self.x_lin - self.s_lin * v])

    def on_branch(self, v):
        return np.concatenate([[self.x_star - np.sqrt((self.fold - v) / self.a)],
                               self.x_lin + self.s_lin * v])

    def derivatives(self, x):
        from viscocontact.methods.bem.system import EdgeDerivatives

        J = np.eye(len(x))
        J[0, 0] = 2.0 * self.a * (x[0] - self.x_star)
        c = np.concatenate([[1.0], -self.s_lin])
        return EdgeDerivatives(jacobian=J, control=c, pressure=np.zeros(len(x) + 1))


def _fold_ahead(v0, step, scale=1.0):
    branch = _Parabola(a=40.0, x_star=-0.5, fold=0.3, x_lin=[-0.2, 1.0, 1.2],
                       s_lin=[0.0, 0.0, 5.0])
    x0 = branch.on_branch(v0)
    d = branch.derivatives(x0)
    tangent = -np.linalg.solve(d.jacobian, d.control)
    state = State(outcome=Outcome.CONVERGED, edges=x0, system=branch)
    from viscocontact.methods.bem.path import Path

    from viscocontact.methods.bem.climb import Climb

    climb = Climb.__new__(Climb)
    climb.eq = branch
    climb.path = Path(branch, closed=None, path_step=0.05)
    return climb.fold_ahead(state, tangent, x0 + scale * tangent * step,
                               Control.penetration_of(v0 + step), v0)


def _climb_on(branch, **attributes):
    """A :class:`Climb` on the stand-in ``branch`` in penetration control, with ``attributes``
    set (the parts of a climb that its predictors read)."""
    from viscocontact.methods.bem.climb import Climb
    from viscocontact.methods.bem.path import Path

    climb = Climb.__new__(Climb)
    climb.eq, climb.path = branch, Path(branch, closed=None, path_step=0.05)
    climb.options = ApproachOptions(path_step=0.05)
    climb.kind, climb.load, climb.below, climb.gaps = "penetration", False, None, []
    for name, value in attributes.items():
        setattr(climb, name, value)
    return climb


def _on_parabola(branch, v):
    x = branch.on_branch(v)
    return State(outcome=Outcome.CONVERGED, edges=x, system=branch, fields=object())


def test_a_look_ahead_ends_the_step_a_quarter_resolution_short_of_a_predicted_fold():
    """The fields at the predicted start of a step across the parabola's fold predict it: the
    step ends a quarter of the resolution short of it, and once the state lies within half the
    resolution, as far past it; a step short of the fold is kept."""
    branch = _Parabola(a=40.0, x_star=-0.5, fold=0.3, x_lin=[-0.2, 1.0, 1.2],
                       s_lin=[0.0, 0.0, 5.0])
    branch.fields_at = lambda edges, control: object()

    class _NoBirth:
        @staticmethod
        def closing(before, after):
            return None

    branch.checks = _NoBirth()
    climb = _climb_on(branch)
    width = climb.options.smallest
    state = _on_parabola(branch, 0.25)

    def ahead(v, step):
        s = _on_parabola(branch, v) if v != 0.25 else state
        return climb.looked_ahead(s, v, v + step, climb.path.tangent(s, False))

    assert ahead(0.25, 0.08) == pytest.approx(0.3 - 0.25 * width, rel=1e-12)
    assert ahead(0.25, 0.04) == 0.29
    near = 0.3 - 0.4 * width
    assert ahead(near, 0.01) == pytest.approx(0.3 + 0.25 * width, rel=1e-9)


def test_a_births_place_is_the_root_of_the_parabola_through_three_gaps():
    """The gap at the birth's check point, sampled at the bracket's far end and two states of
    the branch, gives the root of the parabola through them (exact for a quadratic gap); with
    two samples, the secant's root."""
    def gap(v):
        return (0.06 - v) * (1.0 + 30.0 * v)                # closes at v = 0.06

    climb = _climb_on(_Parabola(a=1.0, x_star=0.0, fold=1.0, x_lin=[], s_lin=[]),
                      gaps=[(0.07, gap(0.07)), (0.03, gap(0.03)), (0.05, gap(0.05))])
    assert climb.birth_ahead(0.05, 0.07) == pytest.approx(0.06, rel=1e-12)
    climb.gaps = [(0.07, gap(0.07)), (0.05, gap(0.05))]
    secant = 0.05 + 0.02 * gap(0.05) / (gap(0.05) - gap(0.07))
    assert climb.birth_ahead(0.05, 0.07) == pytest.approx(secant, rel=1e-12)
    climb.gaps = [(0.07, gap(0.07))]
    assert climb.birth_ahead(0.05, 0.07) is None


def test_a_failed_steps_start_puts_the_fold_where_a_parabolic_branch_folds():
    """On ``v* - v = a(x - x*)²`` the residual at the start predicted along the tangent is
    ``½h²r''`` exactly, so the estimate is the fold (although another edge runs faster); a
    step short of the fold, or a start scaled down from the tangent's, gives none."""
    assert _fold_ahead(0.25, 0.08) == pytest.approx(0.3, rel=1e-12)
    assert _fold_ahead(0.25, 0.04) is None
    assert _fold_ahead(0.25, 0.08, scale=0.5) is None


def test_the_options_are_one_frozen_object():
    options = ApproachOptions(path_step=0.05)
    assert options.smallest == pytest.approx(0.05 / 256)
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        options.resolution = 0.5  # type: ignore[misc]


def test_the_gap_closes_where_the_earliest_check_point_outside_both_contact_sets_closes():
    """Linear in the step between the gaps before and after at the check points outside the
    contacts of both (a point inside the later contacts is left out); None while it stays
    open."""
    from viscocontact.methods.bem.checks import Checks

    gaps = {"before": (np.array([0.0, 1.0, 2.0, 3.0]), np.array([0.2, 0.1, 0.3, 0.4])),
            "after": (np.array([0.0, 1.0, 3.0]), np.array([0.1, -0.1, -0.2])),
            "open": (np.array([0.0, 1.0, 3.0]), np.array([0.1, 0.05, 0.2]))}
    checks = Checks.__new__(Checks)
    checks.gap_outside = gaps.__getitem__
    assert checks.closing("before", "after") == pytest.approx(0.5, rel=1e-12)
    assert checks.closing("before", "open") is None


def test_a_merge_is_foreseen_where_the_tangent_closes_a_neck():
    """Two contacts whose facing edges close on each other along the branch's tangent meet at
    the fraction of the step where the neck (0.2 wide, closing at 0.8 a step) vanishes; across
    the period too; none where every neck opens or closes beyond the step."""
    from viscocontact.methods.bem.climb import merging

    edges = np.array([-1.0, -0.1, 0.1, 1.0])
    assert merging(edges, np.array([0.0, 0.4, -0.4, 0.0])) == pytest.approx(0.25)
    # the neck across the period: 2π - 2, closed by 2π - 2 + 0.5 over the step
    period = 2.0 * np.pi - 2.0
    assert merging(edges, np.array([-0.5 - period, 0.0, 0.0, 0.0])) == pytest.approx(
        period / (period + 0.5))
    assert merging(edges, np.array([0.0, -0.4, 0.4, 0.0])) is None
    assert merging(edges, np.array([0.0, 0.05, -0.05, 0.0])) is None
    assert merging(np.array([-1.0, 1.0]), np.array([-0.1, 0.1])) is None
