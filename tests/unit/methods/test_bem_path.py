"""The approach path's predictor (``Path.predicted``), step control and crossing of folds
(``Path.cross``), and the growth of contacts born adhesive (``Equilibrium.grow``)."""
from __future__ import annotations

import attrs
import numpy as np
import pytest

from viscocontact.adhesion import EnergyBalance
from viscocontact.methods.bem.method import Solve
from viscocontact.methods.bem.sets import Control
from viscocontact.methods.bem.state import Outcome, State
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Bisection, Broyden, Newton

SLS = StandardLinearSolid(beta=10.0)
WAVY = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=SLS, solver=Newton(),
                      adhesion=EnergyBalance(gamma=1e-4), mean_pressure=0.1, zeta=1e-3,
                      discretization=Discretization(elements=32))
#: A 12-scale self-affine profile, adhesive, Broyden (p̃∞ = 0.2, ζ = 0.1): contacts are born and
#: merge on the way into one.
ROUGH12 = ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=12, rms=0.01, seed=3),
                         rheology=SLS, solver=Broyden(), adhesion=EnergyBalance(gamma=2.387e-7),
                         mean_pressure=0.2, zeta=0.1, discretization=Discretization(elements=32))


def _both(problem):
    """The solve from first touch without and with the predictor."""
    out = []
    for predict in (False, True):
        solve = Solve(problem, problem.prepare())
        solve.path.predict = predict
        out.append(solve.run(None, False))
    return out


def _assert_same_equilibrium(plain, predicted, edges_to):
    assert plain.converged and predicted.converged, (plain.message, predicted.message)
    assert predicted.n_contacts == plain.n_contacts
    assert np.allclose(predicted.edges, plain.edges, rtol=0, atol=edges_to)
    assert predicted.area == pytest.approx(plain.area, rel=edges_to)
    assert predicted.function_evaluations < plain.function_evaluations


def test_the_predicted_path_reaches_the_equilibrium_of_the_plain_one():
    """Adhesive sinusoid (Λ̃ = 0.1, Γ̃ = 0.01, ζ = 1e-3, Johnson-like branch), Newton. Both end at
    the same root to the solver tolerance: the residual's round-off floor (3e-9 here) over the
    trailing edge's small stiffness (about 0.05) leaves the edges uncertain by about 1e-7."""
    plain, predicted = _both(WAVY)
    _assert_same_equilibrium(plain, predicted, edges_to=1e-6)


@pytest.mark.slow
def test_the_predicted_path_reaches_the_rough_equilibrium_of_the_plain_one():
    """A 12-scale self-affine profile, adhesive (γ̃ = 2.387e-7, Broyden, p̃∞ = 0.2, ζ = 0.1):
    contacts are born and merge on the way into one; the same contact and area to 1e-8 (the
    plain path: 726 evaluations, the predicted one: 246)."""
    problem = ROUGH12
    plain, predicted = _both(problem)
    _assert_same_equilibrium(plain, predicted, edges_to=1e-8)


def test_failed_approach_steps_are_cut_short_and_not_retried_at_once(monkeypatch):
    """The probation of adhesive approach steps and the step ceiling after a failure
    (:data:`~viscocontact.methods.bem.path.APPROACH_PROBATION`, ``CEILING_GROWTH``) reach the
    equilibrium the path reached without them, with fewer evaluations: a 12-scale self-affine
    profile (γ̃ = 2.387e-7, Broyden, p̃∞ = 0.2, ζ = 0.1, contacts born and merged on the way;
    measured 104 against 217 evaluations, Ã to 1.5e-11)."""
    from viscocontact.methods.bem import path

    problem = ROUGH12
    ruled = Solve(problem, problem.prepare()).run(None, False)
    monkeypatch.setattr(path, "APPROACH_PROBATION", 0)
    monkeypatch.setattr(path, "CEILING_GROWTH", np.inf)
    plain = Solve(problem, problem.prepare()).run(None, False)
    _assert_same_equilibrium(plain, ruled, edges_to=1e-8)       # and fewer evaluations


def test_intermediate_steps_to_a_reduction_and_on_pace_reach_the_same_equilibrium(monkeypatch):
    """The approach's intermediate steps converged to :data:`STEP_REDUCTION` of their start's
    residual, and failing steps stopped at the probation's earlier checkpoints
    (:data:`APPROACH_PACE`), reach the equilibrium the path reached without either, with fewer
    evaluations (the scene of the test above: 86 against 99 evaluations, Ã the same to 1e-10;
    the pace stops no step of this path, whose one failing solve comes after births)."""
    from viscocontact.methods.bem import path

    problem = ROUGH12
    ruled = Solve(problem, problem.prepare()).run(None, False)
    monkeypatch.setattr(path, "STEP_REDUCTION", 0.0)
    monkeypatch.setattr(path, "APPROACH_PACE", ())
    plain = Solve(problem, problem.prepare()).run(None, False)
    _assert_same_equilibrium(plain, ruled, edges_to=1e-8)       # and fewer evaluations


@pytest.mark.parametrize("solver, adhesive, expected", [
    (Broyden(), True, 4), (Newton(), True, 4), (Broyden(), False, 0),
    (Bisection(), True, 0)])
def test_only_adhesive_approach_steps_with_jacobians_are_on_probation(solver, adhesive, expected):
    """Adhesionless steps that start far from their root progress slowly but steadily and keep
    the full budget; a march without Jacobians (bisection) keeps it too."""
    from viscocontact.adhesion import NoAdhesion

    problem = attrs.evolve(WAVY, solver=solver,
                           adhesion=WAVY.adhesion if adhesive else NoAdhesion())
    assert Solve(problem, problem.prepare()).path.probation == expected


class _Edges:
    """An equilibrium stand-in for :meth:`Path.cross`: edge ``lead`` has the residual
    ``±(x - root)`` with the sign of a contact edge (negative: it wants to move outward), the
    others none; ``solve`` returns the state it is started from."""

    adhesive = True
    analytic = True
    jacobian_solver = True
    log = None

    def __init__(self, lead: int, root: float):
        self.lead, self.root = lead, root
        self.evaluations = 0
        self.starts: list[np.ndarray] = []
        self.options: list[dict] = []

    def residual_at(self, edges, control):
        self.evaluations += 1
        r = np.zeros(len(edges))
        outward = -1.0 if self.lead % 2 == 0 else 1.0      # left edges move outward to -x
        r[self.lead] = outward * (edges[self.lead] - self.root)
        return r

    def solve(self, start, control, **kwargs):
        self.starts.append(np.asarray(start, dtype=float))
        self.options.append(kwargs)
        return attrs.evolve(_CONVERGED, edges=np.asarray(start, dtype=float))


_CONVERGED = State(outcome=Outcome.CONVERGED, edges=np.zeros(0))


def _crossing(eq, edges, tangent):
    from viscocontact.methods.bem.path import Path

    state = attrs.evolve(_CONVERGED, edges=np.asarray(edges, dtype=float))
    return Path(eq, closed=None, path_step=0.05).cross(state, np.asarray(tangent, dtype=float),
                                                       Control.penetration_of(0.3))


def test_a_crossing_moves_the_fastest_edge_alone_until_it_lands():
    """The left edge of the first contact (half-width 0.5) runs fastest; its landing 0.8
    half-widths away is bracketed by moves of 1/16, 1/8, ..., 1 half-width (five residual
    evaluations) and solved from the bracket's middle, the other edges held."""
    eq = _Edges(lead=0, root=0.6)
    out = _crossing(eq, [1.0, 2.0, 3.0, 3.5], [-10.0, 0.1, 0.2, -0.1])
    assert out.outcome is Outcome.CONVERGED
    assert eq.evaluations == 5
    np.testing.assert_allclose(eq.starts[0], [1.0 - 0.75 * 0.5, 2.0, 3.0, 3.5])


def test_a_crossing_lands_on_the_approach_steps_probation():
    """The landing's solve stops where it gains no two digits in four evaluations and hands
    over to the fallback march (where the contact set has no equilibrium near the landing,
    Broyden wandered 35-47 evaluations before its stall rule; ``benchmarks/results`` §18)."""
    from viscocontact.methods.bem.path import APPROACH_BUDGET, APPROACH_PROBATION

    eq = _Edges(lead=0, root=0.6)
    _crossing(eq, [1.0, 2.0, 3.0, 3.5], [-10.0, 0.1, 0.2, -0.1])
    (options,) = eq.options
    assert options["probation"] == APPROACH_PROBATION > 0
    assert options["budget"] == APPROACH_BUDGET
    assert options.get("use_fallback", True)


def test_a_crossing_that_meets_the_neighbour_solves_the_merged_contact():
    """The right edge of the first contact runs towards the second and never lands: the
    contacts merge and the merged contact is solved."""
    eq = _Edges(lead=1, root=100.0)
    out = _crossing(eq, [1.0, 2.0, 2.4, 3.0], [0.1, 5.0, -0.2, 0.1])
    assert out.outcome is Outcome.CONVERGED
    np.testing.assert_allclose(eq.starts[0], [1.0, 3.0])


def test_a_crossing_that_finds_no_landing_within_its_reach_gives_up():
    eq = _Edges(lead=0, root=-100.0)
    assert _crossing(eq, [-1.0, -0.9, 2.0, 2.5], [-3.0, 0.0, 0.0, 0.0]) is None
    # moves of 1/16 ... 8 half-widths, each a residual evaluation
    assert eq.evaluations == 8


def test_the_fold_estimate_is_exact_on_a_parabolic_branch():
    """``Δ̃ = Δ̃* - c (x - x*)²``: the edge speed ``1/(2√(c (Δ̃* - Δ̃)))`` at two states gives
    ``Δ̃*``; edges that slow down give no estimate."""
    from viscocontact.methods.bem.path import Path

    fold, c = 0.3, 40.0

    def speed(d):
        return 1.0 / (2.0 * np.sqrt(c * (fold - d)))

    assert Path.fold_ahead((0.2, speed(0.2)), (0.25, speed(0.25))) == pytest.approx(fold,
                                                                                     rel=1e-12)
    assert Path.fold_ahead((0.25, speed(0.25)), (0.2, speed(0.2))) is None
    assert Path.fold_ahead((0.2, 2.0), (0.25, 1.0)) is None
    assert Path.fold_ahead((0.2, None), (0.25, 1.0)) is None


class _Parabola:
    """Residuals with a parabolic fold: ``r₀ = a(x₀ - x*)² - (Δ̃* - Δ̃)`` (the left edge of the
    first contact runs into the fold at ``Δ̃*``), every other edge ``rᵢ = xᵢ - xᵢ⁰ - sᵢΔ̃``
    (linear, never folds). The stand-in of both the state's edge system (its derivatives) and
    the equilibrium (``residual_at``)."""

    log = None

    def __init__(self, a, x_star, fold, x_lin, s_lin):
        self.a, self.x_star, self.fold = a, x_star, fold
        self.x_lin, self.s_lin = np.asarray(x_lin, float), np.asarray(s_lin, float)

    def residual_at(self, x, control):
        d = control.value
        return np.concatenate([[self.a * (x[0] - self.x_star) ** 2 - (self.fold - d)],
                               x[1:] - self.x_lin - self.s_lin * d])

    def on_branch(self, d):
        return np.concatenate([[self.x_star - np.sqrt((self.fold - d) / self.a)],
                               self.x_lin + self.s_lin * d])

    def derivatives(self, x):
        from viscocontact.methods.bem.system import EdgeDerivatives

        J = np.eye(len(x))
        J[0, 0] = 2.0 * self.a * (x[0] - self.x_star)
        c = np.concatenate([[1.0], -self.s_lin])
        return EdgeDerivatives(jacobian=J, control=c, pressure=np.zeros(len(x) + 1))


#: Two contacts: the first's left edge folds at Δ̃* = 0.3, the second's right edge moves
#: linearly and faster (in half-widths of its contact per unit penetration) at Δ̃ = 0.25.
_TWO_CONTACTS = dict(a=40.0, x_star=-0.5, fold=0.3, x_lin=[-0.2, 1.0, 1.2], s_lin=[0.0, 0.0, 5.0])


def _tangent(branch, x0):
    d = branch.derivatives(x0)
    return -np.linalg.solve(d.jacobian, d.control)


def _fold_from_start(branch, d0, step, scale=1.0):
    from viscocontact.methods.bem.path import Path

    x0 = branch.on_branch(d0)
    tangent = _tangent(branch, x0)
    state = attrs.evolve(_CONVERGED, edges=x0, system=branch)
    path = Path(branch, closed=None, path_step=0.05)
    return path.fold_from_start(state, tangent, x0 + scale * tangent * step, d0, step)


def test_a_failed_steps_start_puts_the_fold_where_a_parabolic_branch_folds():
    """On ``Δ̃* - Δ̃ = a(x - x*)²`` the residual at the start predicted along the tangent is
    ``½h²r''`` exactly, and ``x'/(2x'')`` of the folding edge is ``Δ̃* - Δ̃``: the estimate is
    the fold, led by that edge, although another edge runs faster (about 6.9 half-widths per
    unit penetration against 2.1)."""
    branch = _Parabola(**_TWO_CONTACTS)
    x0 = branch.on_branch(0.25)
    half = np.repeat(0.5 * (x0[1::2] - x0[0::2]), 2)
    speed = np.abs(_tangent(branch, x0)) / half
    assert np.argmax(speed) == 3 and speed[3] > 3 * speed[0]
    fold, edge = _fold_from_start(branch, 0.25, 0.08)
    assert fold == pytest.approx(0.3, rel=1e-12)
    assert edge == 0


def test_a_step_short_of_the_fold_or_scaled_down_gives_no_estimate():
    branch = _Parabola(**_TWO_CONTACTS)
    assert _fold_from_start(branch, 0.25, 0.04) is None           # the fold lies beyond it
    assert _fold_from_start(branch, 0.25, 0.08, scale=0.5) is None   # not the tangent's start


def test_an_approach_that_crosses_a_fold_reaches_the_equilibrium_of_one_that_halves_its_steps(
        monkeypatch):
    """A 12-scale self-affine profile (seed 1, γ̃ = 2.387e-7, Broyden, p̃∞ = 0.2, ζ = 0.1): a
    contact's edge runs towards a fold on the way. Crossed there, the path reaches the
    equilibrium it reaches by failing at the fold and halving its steps down to it, with fewer
    evaluations: the fold estimated from two states ahead of it or from a failed step's start
    (measured 87 evaluations with both estimates, 88 with the failed step's alone, 122 halving
    the steps)."""
    from viscocontact.methods.bem.path import Path

    problem = ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=12, rms=0.01, seed=1),
                             rheology=SLS, solver=Broyden(),
                             adhesion=EnergyBalance(gamma=2.387e-7), mean_pressure=0.2, zeta=0.1,
                             discretization=Discretization(elements=32))
    crossed = Solve(problem, problem.prepare()).run(None, False)
    assert any("fastest edge jumped" in e for e in crossed.extras["events"])
    monkeypatch.setattr(Path, "fold_ahead", staticmethod(lambda before, after: None))
    after_failure = Solve(problem, problem.prepare()).run(None, False)
    assert any("start's residual puts the branch's fold" in e
               for e in after_failure.extras["events"])
    monkeypatch.setattr(Path, "fold_from_start", lambda self, *args: None)
    halved = Solve(problem, problem.prepare()).run(None, False)
    assert not any("fastest edge jumped" in e for e in halved.extras["events"])
    _assert_same_equilibrium(halved, crossed, edges_to=1e-8)     # and fewer evaluations
    _assert_same_equilibrium(halved, after_failure, edges_to=1e-8)


def test_the_tangent_predicts_a_small_step_to_second_order():
    """From a converged state the tangent ``-J⁻¹ ∂r/∂Δ̃`` predicts the equilibrium a step away
    with an error that falls like the step squared (measured: 6.3e-5, 1.6e-5, 3.9e-6 for steps
    of 8e-3, 4e-3, 2e-3, while the edges move by 1e-2 to 3e-3). The equilibria a step away
    keep the state's zones (no polish), so that only the step separates them."""
    solve = Solve(WAVY, WAVY.prepare())
    eq = solve.equilibrium
    state = eq.solve(np.array([-0.8, 0.6]), Control.penetration_of(0.4))
    assert state.outcome is Outcome.CONVERGED
    errors = []
    for step in (8e-3, 4e-3, 2e-3):
        target = eq.solve(state.edges, Control.penetration_of(0.4 + step), polish=False)
        moved = np.max(np.abs(target.edges - state.edges))
        errors.append(np.max(np.abs(solve.path.predicted(state, step) - target.edges)))
        assert errors[-1] < 0.01 * moved
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.1)
    assert errors[1] / errors[2] == pytest.approx(4.0, rel=0.1)


def test_a_contact_born_adhesive_grows_until_its_edges_hold():
    """A contact born as the check grid's narrow negative-gap region is far below its
    equilibrium: both its edges want to grow. The growth stops where neither does any more
    (or it merges), one residual evaluation per doubling step."""
    solve = Solve(WAVY, WAVY.prepare())
    eq = solve.equilibrium
    control = Control.penetration_of(0.3)
    born = (-0.01, 0.01)
    before = solve.log.evaluations
    grown = eq.grow(np.array(born), control, [born])
    assert grown[0] < born[0] and grown[1] > born[1]
    r = eq.residual_at(grown, control)
    assert np.all(r >= 0)
    assert solve.log.evaluations - before <= 12
    final = eq.solve(grown, control)
    assert final.outcome is Outcome.CONVERGED
    assert final.edges[0] > grown[0] and final.edges[1] < grown[1]   # within the overshoot


@pytest.mark.parametrize("strength, load, holds", [(0.5, 0.6, True), (0.5, 0.4, False),
                                                   (np.inf, -5.0, True), (0.0, 1.01, True),
                                                   (0.0, 0.99, False)])
def test_a_closed_interface_holds_while_its_tension_is_within_its_strength(strength, load,
                                                                           holds):
    """Full contact on an elastic sinusoid carries ``cos x̃ - p̃∞`` (largest tension 1 - p̃∞);
    a Maugis-Dugdale interface (finite strength σ̃0) opens where that exceeds σ̃0, one without
    adhesion (strength 0) wherever it is tensile, one of vanishing range never."""
    from viscocontact.methods.bem.closed import ClosedContact
    from viscocontact.rheology import Elastic

    prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(), solver=Newton(),
                          mean_pressure=load)
    closed = ClosedContact(prob.prepare(), 1024, 0.0, adhesive=strength > 0, strength=strength)
    assert closed.largest_tension(load) == pytest.approx(1.0 - load, abs=1e-12)
    assert closed.supports(load) is holds
    assert closed.holds(Control.load_of(load)) is holds


def _load_steps_solve(monkeypatch, reach):
    """A solve of :data:`WAVY` whose equilibrium solves fail when asked for a load more than
    ``reach`` from the last load they reached; returns it and the converged state at p̃∞ = 0.02."""
    solve = Solve(WAVY, WAVY.prepare())
    state = solve.path.approach(Control.load_of(0.02))
    assert state.outcome is Outcome.CONVERGED
    real = solve.equilibrium.solve
    last = [0.02]

    def solve_within_reach(edges, control, **kwargs):
        if abs(control.value - last[0]) > reach:
            return attrs.evolve(state, outcome=Outcome.NOT_CONVERGED, message="too far")
        out = real(edges, control, **kwargs)
        if out.outcome is Outcome.CONVERGED:
            last[0] = control.value
        return out

    monkeypatch.setattr(solve.equilibrium, "solve", solve_within_reach)
    return solve, state, real


def test_load_steps_halve_until_they_reach_the_target_load(monkeypatch):
    """From p̃∞ = 0.02 to 0.1 with solves that fail beyond 0.03 of the last load reached: the
    steps go 0.06 (fails), 0.04, 0.08 (fails), 0.06, 0.1 (fails), 0.08, 0.1; the state is the
    equilibrium a direct solve from there reaches (edges to the solves' tolerance: residuals
    of 1e-8 move them by 1e-7)."""
    solve, state, real = _load_steps_solve(monkeypatch, 0.03)
    out = solve.path.in_load_steps(state, Control.load_of(0.1))
    assert out is not None and out.outcome is Outcome.CONVERGED
    assert out.fields.mean_pressure == pytest.approx(0.1, abs=1e-10)
    assert "the target load reached from there in 7 steps of load" in solve.log.events
    direct = real(out.edges, Control.load_of(0.1))
    assert np.allclose(direct.edges, out.edges, rtol=0, atol=1e-6)


def test_load_steps_that_never_converge_give_up(monkeypatch):
    from viscocontact.methods.bem.path import LOAD_STEP_SMALLEST, LOAD_STEP_SOLVES

    solve, state, _ = _load_steps_solve(monkeypatch, 0.0)
    assert solve.path.in_load_steps(state, Control.load_of(0.1)) is None
    solves = int(np.log2(0.5 / LOAD_STEP_SMALLEST)) + 1
    assert solves <= LOAD_STEP_SOLVES
    assert solve.log.events[-1] == (f"no steps of load from p̃∞ = 0.02 reach the target "
                                    f"({solves} solves)")


@pytest.mark.parametrize("r, reduction, expected", [
    ([0.02, -0.5], 1e-4, 5e-5),          # a tenth-thousandth of the start's max|r|
    ([2e-5, 1e-5], 1e-4, 1e-8),          # never below the tolerance
    ([0.02, np.inf], 1e-4, 1e-8),        # a start the model rejects: the tolerance
    ([0.02, -0.5], 0.0, 1e-8)])          # no reduction asked for
def test_a_reduced_solve_converges_at_a_fraction_of_its_start(r, reduction, expected):
    from viscocontact.methods.bem.equilibrium import Equilibrium
    from viscocontact.solvers import Tolerances

    class Start:
        def residual(self, x):
            return np.array(r)

    tol = Tolerances(residual=1e-8, probation=4)
    out = Equilibrium.reduced(Start(), np.zeros(2), tol, reduction)
    assert out.residual == pytest.approx(expected, rel=1e-12)
    assert attrs.evolve(out, residual=tol.residual) == tol       # nothing else changed



def _load_controlled_root(problem):
    """``(path, state)``: the converged load-controlled state that a solve from first touch
    reaches (before its stability check)."""
    solve = Solve(problem, problem.prepare())
    state = solve.path.approach(Control.load_of(problem.mean_pressure))
    assert state.outcome is Outcome.CONVERGED, state.message
    return solve.path, state


def _central_stiffness(path, state, eps=5e-5):
    """``dp̃∞/dΔ̃`` by central differences: two penetration-controlled solves at ``Δ̃ ± eps``
    from the state's edges."""
    fields, loads = state.fields, []
    for change in (-eps, eps):
        trial = path.eq.solve(state.edges, Control.penetration_of(fields.penetration + change),
                              use_fallback=False, polish=False)
        assert trial.outcome is Outcome.CONVERGED, trial.message
        loads.append(trial.fields.mean_pressure)
    return (loads[1] - loads[0]) / (2 * eps)


def _wavy_at_zero_load(fraction):
    """Elastic wavy contact (Λ̃ = 0.1) at p̃∞ = 0 with Γ̃ a fraction of the closing one, and
    Johnson's solution for it."""
    from viscocontact.reference.johnson import JohnsonWavy
    from viscocontact.rheology import Elastic

    gamma = fraction * JohnsonWavy.closing_gamma()
    problem = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                             adhesion=EnergyBalance(gamma=gamma * 0.01), solver=Newton(),
                             mean_pressure=0.0)
    return problem, JohnsonWavy(Gamma=gamma)


def test_the_branch_stiffness_of_a_stable_wavy_root_is_johnsons():
    """Γ̃ half the closing one: the analytic ``dp̃∞/dΔ̃`` along the branch is Johnson's
    ``(dp̃∞/dÃ)/(dΔ̃/dÃ)`` at his root to 5e-4 (measured 1.3e-4 on the default mesh, 3.5e-5
    with 256 elements: the mesh) and the central difference of two perturbed solves to 2e-5.
    That bound is the difference's own error at h = 5e-5: each solve stops at
    ``max|r| <= 1e-9``, which leaves its load off by up to ``||∂p̃∞/∂r||₁ · 1e-9`` (0.20 here),
    so the difference by up to 0.2e-9/h = 4e-6 (1.1e-5 of k), while the truncation
    h²·|d³p̃∞/dΔ̃³|/6 is below 1e-9 of k. The penetration-controlled state at the same root gives it through
    the other formula, and ``load_stiffness`` takes it without a solve."""
    problem, johnson = _wavy_at_zero_load(0.5)
    path, state = _load_controlled_root(problem)
    root = johnson.area_at_pressure(0.0)
    h = 1e-6
    expected = ((johnson.mean_pressure(root + h) - johnson.mean_pressure(root - h))
                / (johnson.penetration(root + h) - johnson.penetration(root - h)))
    k = path.branch_stiffness(state)
    assert k == pytest.approx(expected, rel=5e-4)
    assert k == pytest.approx(_central_stiffness(path, state), rel=2e-5)
    pinned = path.eq.solve(state.edges, Control.penetration_of(state.fields.penetration))
    assert pinned.outcome is Outcome.CONVERGED
    assert path.branch_stiffness(pinned) == pytest.approx(k, rel=1e-5)
    evaluations = path.log.evaluations
    assert path.load_stiffness(state, 5e-5) == k
    assert path.log.evaluations == evaluations


def test_the_branch_stiffness_is_negative_on_johnsons_unstable_branch():
    """Γ̃ 0.99 of the closing one: the first contact jumps past the load maximum onto the
    branch where the load falls as the contact grows (Ã = 4.3817; Johnson's root there 4.3872).
    The analytic stiffness is negative, as Johnson's is there, and equals the central
    difference of two perturbed solves to 1e-4, the difference's own error at h = 5e-5: the
    solves stop at ``max|r| <= 1e-9`` and on this branch ``||∂p̃∞/∂r||₁ = 0.58``, so each load
    is off by up to 5.8e-10 and the difference by up to 5.8e-10/h = 1.2e-5 (5.7e-5 of k); the
    truncation h²·|d³p̃∞/dΔ̃³|/6 adds 1.9e-7 of k (from differences at h = 4e-4 and 8e-4). Measured
    errors vary between 1e-7 and 5e-6 of k with the platform's round-off."""
    problem, johnson = _wavy_at_zero_load(0.99)
    path, state = _load_controlled_root(problem)
    area = float(np.sum(state.fields.mesh.width))
    assert area > johnson.closure()[0]
    k = path.branch_stiffness(state)
    assert k < 0
    assert k == pytest.approx(_central_stiffness(path, state), rel=1e-4)


def test_the_branch_stiffness_of_rough_and_cohesive_roots_is_the_perturbed_solves():
    """ROUGH12's profile at p̃∞ = 0.4 (two contacts at the root, SLS at ζ = 0.1, Broyden) and
    a Maugis-Dugdale sinusoid (SLS, ζ = 1): the analytic stiffness is the central difference of
    two perturbed penetration-controlled solves to 3e-6, the difference's error at h = 5e-5:
    the solves stop at ``max|r|`` of 1e-9 of the residual scale, which with
    ``||∂p̃∞/∂r||₁`` = 0.11 and 2e-5 leaves the difference off by up to 1.5e-6 and 1e-9 of k;
    the truncation h²·|d³p̃∞/dΔ̃³|/6 is below 6e-9 of k in both."""
    from viscocontact.adhesion import MaugisDugdale

    cohesive = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=SLS, solver=Broyden(),
                              adhesion=MaugisDugdale(gamma=5e-4, range=1.0), mean_pressure=0.1,
                              zeta=1.0)
    two = attrs.evolve(ROUGH12, mean_pressure=0.4)
    for problem, contacts in ((two, 2), (cohesive, 1)):
        path, state = _load_controlled_root(problem)
        assert state.fields.mesh.n_contacts == contacts
        k = path.branch_stiffness(state)
        assert k > 0
        assert k == pytest.approx(_central_stiffness(path, state), rel=3e-6)


def test_without_analytic_derivatives_the_stiffness_is_a_perturbed_solve():
    """A system that gives no derivatives: ``branch_stiffness`` is None and ``load_stiffness``
    is the secant of one perturbed penetration-controlled solve, as before."""
    path, state = _load_controlled_root(WAVY)

    class NoDerivatives:
        control = state.system.control

        @staticmethod
        def derivatives(x):
            return None

    blind = attrs.evolve(state, system=NoDerivatives())
    assert path.branch_stiffness(blind) is None
    eps = 5e-5
    trial = path.eq.solve(state.edges,
                          Control.penetration_of(state.fields.penetration - eps),
                          use_fallback=False, polish=False)
    secant = (state.fields.mean_pressure - trial.fields.mean_pressure) / eps
    assert path.load_stiffness(blind, eps) == secant
    assert secant == pytest.approx(path.branch_stiffness(state), rel=1e-3)
