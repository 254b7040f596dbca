"""The path's predictor (``Path.predicted``) and solver budgets, and the growth of contacts
born adhesive (``Equilibrium.grow``)."""
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
    """Adhesive sinusoid (Λ̃ = 0.1, Γ̃ = 0.01, ζ = 1e-3, Johnson-like branch), Newton, on the
    default 64 elements. Both end at the same root to the solver tolerance: the residual's
    round-off floor (3e-9 here) over the trailing edge's small stiffness (about 0.05) leaves the
    edges uncertain by about 1e-7. (On 32 elements the mesh zones made for the edges near this
    root have two patterns each with its own root, 3.6e-4 apart in the leading edge, less than
    that mesh's error: Ã = 2.8078 on 32 elements, 2.8063 on 48, 2.8058 on 64. Which of the two
    a path reaches is then the mesh's, not the predictor's.)"""
    plain, predicted = _both(attrs.evolve(WAVY, discretization=Discretization(elements=64)))
    _assert_same_equilibrium(plain, predicted, edges_to=1e-6)


@pytest.mark.slow
def test_the_predicted_path_reaches_the_rough_equilibrium_of_the_plain_one():
    """A 12-scale self-affine profile, adhesive (γ̃ = 2.387e-7, Broyden, p̃∞ = 0.2, ζ = 0.1):
    contacts are born and merge on the way into one; the same contact and area to 1e-8 (the
    plain path: 726 evaluations, the predicted one: 246)."""
    problem = ROUGH12
    plain, predicted = _both(problem)
    _assert_same_equilibrium(plain, predicted, edges_to=1e-8)


@pytest.mark.parametrize("solver, adhesive, expected", [
    (Broyden(), True, 4), (Newton(), True, 4), (Broyden(), False, 0),
    (Bisection(), True, 4)])
def test_only_adhesive_approach_steps_with_jacobians_are_on_probation(solver, adhesive, expected):
    """Adhesionless steps that start far from their root progress slowly but steadily and keep
    the full budget. The steps' corrector is the built-in Newton whatever the scene's solver
    (a bisection march here) where the adhesion model gives derivatives, so adhesive steps
    are on probation with every solver."""
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


@pytest.mark.parametrize("kernel, penetration, possible", [
    ("half-plane", 0.6, False),      # the mean gap 1 - r̂0 - Δ̃ = 0.4 stays open somewhere
    ("half-plane", 1.0, True),       # the closing penetration (a sinusoid's r̂0 = 0)
    ("free-layer", 0.6, True)])      # a compressible layer (ν = 0.3) closes at any penetration
def test_full_contact_is_possible_on_an_incompressible_solid_only_at_its_closing_penetration(
        kernel, penetration, possible):
    from viscocontact.kernels import FreeLayer, HalfPlane
    from viscocontact.methods.bem.closed import ClosedContact
    from viscocontact.rheology import Elastic

    solid = HalfPlane() if kernel == "half-plane" else FreeLayer(thickness=1.0, poisson=0.3)
    prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(), kernel=solid,
                          adhesion=EnergyBalance(gamma=1e-4), penetration=penetration)
    closed = ClosedContact(prob.prepare(), 1024, 0.0, adhesive=True, strength=np.inf)
    assert closed.possible(Control.penetration_of(penetration)) == possible


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



