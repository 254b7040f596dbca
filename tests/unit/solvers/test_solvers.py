"""The four built-in nonlinear solvers: convergence, contract, budgets, step bounds, options."""
import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact.errors import ValidationError
from viscocontact.solvers import (Bisection, Broyden, Newton, NonlinearCG, NonlinearSolver,
                                  SolverResult, Status, Tolerances)
from viscocontact.testing.strategies_solvers import (CoupledPair, FunctionProblem, NoRoot,
                                                     RecordingProblem, TanhSystem, solver_cases,
                                                     tanh_systems)

FAST = settings(max_examples=30, deadline=None)

SOLVERS = [Newton(), Broyden(), NonlinearCG(), Bisection()]
#: the bisection march that finishes with Newton steps (the BEM's default fallback)
FINISH = Bisection(newton_below=1e-2)
VARIANTS = SOLVERS + [Newton(difference="central", damping=False), Broyden(relaxation=0.7),
                      NonlinearCG(beta="fletcher-reeves", line_search="wolfe"), FINISH]
TOL = Tolerances(residual=1e-9, max_iterations=2000, max_evaluations=50_000)


def ids(solver):
    return repr(solver).split(",")[0] + ")"


def coupling(n, k, seed, width=None):
    """Zero diagonal, row sums of |A| = k, |A_ij| <= k·w_j/w_i (as the strategies build it)."""
    a = np.random.default_rng(seed).uniform(-1.0, 1.0, (n, n))
    np.fill_diagonal(a, 0.0)
    a *= k / np.sum(np.abs(a), axis=1, keepdims=True)
    w = np.ones(n) if width is None else np.asarray(width, float)
    return a * np.minimum(1.0, w[None, :] / w[:, None])


# ---- (a) diagonal-dominant, (b) 2x2, (c) very different scales ---------------------------
DIAG = TanhSystem(root=np.linspace(-1.0, 2.0, 10), width=np.ones(10), scale=np.ones(10),
                  coupling=coupling(10, 0.3, 1))
DIAG_X0 = DIAG.root + 0.6 * np.cos(np.arange(10))
WIDTHS = [0.02, 0.5, 2.0, 10.0]
SCALED = TanhSystem(root=[1e-3, 0.5, 20.0, 100.0], width=WIDTHS, scale=[0.3, -1.0, 3.0, -1.0],
                    coupling=coupling(4, 0.3, 2, WIDTHS))
SCALED_X0 = SCALED.root + SCALED.width * np.array([0.5, -0.4, 0.3, -0.5])

PROBLEMS = {
    "diagonal-dominant": (DIAG.as_problem(), DIAG_X0, DIAG.root, DIAG.root_atol(1e-9)),
    "coupled-pair": (CoupledPair(), np.array([1.3, 0.8]), np.ones(2), np.full(2, 1e-8)),
    "different-scales": (SCALED.as_problem(orientation=True), SCALED_X0, SCALED.root,
                         SCALED.root_atol(1e-9)),
}


@pytest.mark.parametrize("solver", VARIANTS, ids=ids)
@pytest.mark.parametrize("name", sorted(PROBLEMS))
def test_solves_reference_problems(solver, name):
    problem, x0, root, atol = PROBLEMS[name]
    rec = RecordingProblem(problem)
    res = solver.solve(rec, x0, TOL)
    assert isinstance(res, SolverResult)
    assert res.converged and res.status is Status.CONVERGED, (res.status, res.message)
    assert res.residual_norm <= TOL.residual
    assert np.all(np.abs(res.x - root) <= atol)
    assert res.function_evaluations == rec.calls > 0
    assert 0 < res.iterations <= TOL.max_iterations
    assert len(res.residual_history) >= 2
    assert res.residual_history[0] == pytest.approx(np.max(np.abs(problem.residual(x0))))
    assert res.residual_history[-1] == pytest.approx(res.residual_norm)
    np.testing.assert_array_equal(res.residual, problem.residual(res.x))


def test_iteration_counts_on_the_diagonal_system():
    """Regression on the cost ranking the thesis discusses (evaluations with FD Jacobians)."""
    problem, x0 = PROBLEMS["diagonal-dominant"][:2]
    fev = {type(s).__name__: s.solve(problem, x0, TOL).function_evaluations for s in SOLVERS}
    assert fev["Broyden"] < fev["Newton"] < fev["NonlinearCG"]
    assert fev["Newton"] <= 6 * 11          # <= 5 Newton iterations of n + 1 evaluations
    assert fev["Bisection"] < 300


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_start_at_the_root_takes_no_iteration(solver):
    res = solver.solve(DIAG.as_problem(), DIAG.root, TOL)
    assert res.converged and res.iterations == 0 and res.function_evaluations == 1


# ---- non-convergence is reported, never hidden -------------------------------------------
@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_iteration_budget_gives_max_iterations(solver):
    tol = Tolerances(residual=1e-12, max_iterations=2)
    res = solver.solve(DIAG.as_problem(), DIAG_X0, tol)
    assert not res.converged
    assert res.status is Status.MAX_ITERATIONS
    assert res.iterations == 2
    assert res.residual_norm > tol.residual
    np.testing.assert_array_equal(res.residual, DIAG.residual(res.x))


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_evaluation_budget_is_never_exceeded(solver):
    tol = Tolerances(residual=1e-12, max_evaluations=7)
    rec = RecordingProblem(DIAG.as_problem())
    res = solver.solve(rec, DIAG_X0, tol)
    assert rec.calls <= 7 and res.function_evaluations == rec.calls
    assert not res.converged and res.status is Status.MAX_EVALUATIONS


@pytest.mark.parametrize("solver", VARIANTS, ids=ids)
@pytest.mark.parametrize("x0", [0.5, 0.0, -2.0])
def test_problem_without_root_is_not_converged(solver, x0):
    tol = Tolerances(residual=1e-9, max_iterations=60, max_evaluations=3000)
    res = solver.solve(NoRoot(), np.full(3, x0), tol)
    assert not res.converged
    assert res.status is not Status.CONVERGED
    assert res.residual_norm >= 1.0
    assert res.message


@pytest.mark.parametrize("x0", [0.5, 0.0, -2.0])
def test_broyden_stops_when_it_makes_no_progress(x0):
    """Without a root Broyden wanders (no line search); ``stall_iterations`` ends it as STALLED
    once the best residual stops falling, long before the iteration budget."""
    tol = Tolerances(residual=1e-9, max_iterations=500, max_evaluations=100_000)
    res = Broyden(stall_iterations=20).solve(NoRoot(), np.full(3, x0), tol)
    assert res.status is Status.STALLED and not res.converged
    assert 20 <= res.iterations < 60
    assert "no progress in 20 iterations" in res.message
    h = res.residual_history
    assert min(h[-20:]) >= 0.9 * min(h[:-20])       # the rule, on the history it reports
    off = Broyden(stall_iterations=0).solve(NoRoot(), np.full(3, x0), tol)
    assert off.status is Status.MAX_ITERATIONS and off.iterations == 500


def test_broyden_stall_rule_leaves_progressing_solves_alone():
    """A slow but steady solve (heavy under-relaxation: linear convergence with ratio 0.9) is
    not stopped: each window of iterations lowers the best residual by more than the rule's 0.9."""
    problem = SMOOTH.as_problem(jacobian=True)
    res = Broyden(relaxation=0.1, stall_iterations=5).solve(problem, SMOOTH_X0, TOL)
    assert res.converged


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
@pytest.mark.parametrize("x0", [0.5, 0.0, -2.0])
def test_probation_stops_a_solve_without_progress(solver, x0):
    """``Tolerances.probation``: a solve whose best residual after the first ``probation``
    evaluations is not below ``progress`` times the first stops as STALLED before the next
    evaluation, and says so."""
    tol = Tolerances(residual=1e-9, max_iterations=500, max_evaluations=3000, probation=4,
                     progress=1e-2)
    rec = RecordingProblem(NoRoot())
    res = solver.solve(rec, np.full(3, x0), tol)
    assert res.status is Status.STALLED and not res.converged
    assert rec.calls == res.function_evaluations <= 5
    assert "no progress in 4 residual evaluations" in res.message or rec.calls < 5


@pytest.mark.parametrize("solver", VARIANTS, ids=ids)
@pytest.mark.parametrize("name", sorted(PROBLEMS))
def test_probation_leaves_solves_that_gain_two_digits_alone(solver, name):
    """On the reference problems a solve whose best ``max|r|`` among evaluations 2-5 is a
    hundredth of the first ends exactly as without the rule (same iterate, same count); any
    other stops as STALLED after five evaluations."""
    problem, x0, _, _ = PROBLEMS[name]
    free_rec = RecordingProblem(problem)
    free = solver.solve(free_rec, x0, TOL)
    sizes = [float(np.max(np.abs(problem.residual(x)))) for x in free_rec.points]
    ruled = solver.solve(RecordingProblem(problem), x0, attrs.evolve(TOL, probation=4))
    if len(sizes) <= 5 or min(sizes[1:5]) <= 1e-2 * sizes[0]:
        assert ruled.status is free.status
        assert ruled.function_evaluations == free.function_evaluations
        np.testing.assert_array_equal(ruled.x, free.x)
    else:
        assert ruled.status is Status.STALLED and ruled.function_evaluations == 5
        assert "no progress in 4 residual evaluations" in ruled.message


@pytest.mark.parametrize("field, value", [("probation", -1), ("progress", 0.0),
                                          ("progress", 1.0)])
def test_probation_options_are_validated(field, value):
    with pytest.raises(ValidationError, match=field):
        Tolerances(**{field: value})


@pytest.mark.parametrize("pace, probation", [((0.0,), 4), ((1.5,), 4), ((0.9, 0.6), 2),
                                             ((0.9,), 0)])
def test_pace_is_validated(pace, probation):
    with pytest.raises(ValidationError, match="Tolerances.pace"):
        Tolerances(probation=probation, pace=pace)


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_pace_stops_a_solve_without_progress_at_its_checkpoint(solver):
    """``Tolerances.pace``: after one evaluation past the first without the gain the first
    checkpoint asks for, the solve stops as STALLED before its third evaluation, and says so."""
    tol = Tolerances(residual=1e-9, max_iterations=500, max_evaluations=3000, probation=4,
                     progress=1e-2, pace=(0.5,))
    rec = RecordingProblem(NoRoot())
    res = solver.solve(rec, np.full(3, 0.5), tol)
    assert res.status is Status.STALLED and not res.converged
    sizes = [float(np.max(np.abs(NoRoot().residual(x)))) for x in rec.points]
    if len(sizes) >= 2 and sizes[1] > 0.5 * sizes[0]:
        assert rec.calls == res.function_evaluations == 2
        assert "too little progress in 1 residual evaluation" in res.message


@pytest.mark.parametrize("solver", VARIANTS, ids=ids)
@pytest.mark.parametrize("name", sorted(PROBLEMS))
def test_pace_leaves_solves_that_keep_it_alone(solver, name):
    """On the reference problems a solve whose best ``max|r|`` after one and two evaluations
    past the first is within the pace (0.9, 0.6) ends exactly as under the probation alone;
    any other stops as STALLED at the first checkpoint it misses."""
    problem, x0, _, _ = PROBLEMS[name]
    free_rec = RecordingProblem(problem)
    free = solver.solve(free_rec, x0, attrs.evolve(TOL, probation=4))
    sizes = [float(np.max(np.abs(problem.residual(x)))) for x in free_rec.points]
    paced = solver.solve(RecordingProblem(problem), x0, attrs.evolve(TOL, probation=4,
                                                                     pace=(0.9, 0.6)))
    missed = [j for j, limit in ((1, 0.9), (2, 0.6))
              if len(sizes) > j + 1 and min(sizes[1:j + 1]) > limit * sizes[0]]
    if not missed:
        assert paced.status is free.status
        assert paced.function_evaluations == free.function_evaluations
        np.testing.assert_array_equal(paced.x, free.x)
    else:
        assert paced.status is Status.STALLED
        assert paced.function_evaluations == missed[0] + 1
        assert f"too little progress in {missed[0]} residual evaluation" in paced.message


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_non_finite_residual_at_start_fails(solver):
    res = solver.solve(FunctionProblem(lambda x: np.full(2, np.nan)), np.zeros(2), TOL)
    assert not res.converged and res.status is Status.FAILED


class Boom(Exception):
    pass


@pytest.mark.parametrize("solver", VARIANTS, ids=ids)
@pytest.mark.parametrize("k", [1, 2, 5, 13])
def test_exception_from_residual_propagates(solver, k):
    rec = RecordingProblem(DIAG.as_problem(), fail_at=k, error=Boom(f"call {k}"))
    with pytest.raises(Boom, match=f"call {k}"):
        solver.solve(rec, DIAG_X0, TOL)
    assert rec.calls == k


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_exception_from_jacobian_propagates(solver):
    def jacobian(x):
        raise Boom("jacobian")

    problem = FunctionProblem(DIAG.residual, jacobian=jacobian)
    if isinstance(solver, Bisection):  # needs no Jacobian: must simply not call it
        assert solver.solve(problem, DIAG_X0, TOL).converged
    else:
        with pytest.raises(Boom):
            solver.solve(problem, DIAG_X0, TOL)


# ---- max_step ----------------------------------------------------------------------------
def iterates_and_trials(rec):
    """Pairs (iterate, bound, residual point) from the recorded events."""
    out, current = [], None
    for kind, x in rec.events:
        if kind == "max_step":
            current = x
        elif current is not None:
            out.append((current, x))
    return out


@pytest.mark.parametrize("solver", VARIANTS, ids=ids)
def test_max_step_is_honoured(solver):
    bound = 0.05 + 0.05 * np.arange(10) / 9          # 0.05 .. 0.10, per component
    rec = RecordingProblem(DIAG.as_problem(max_step=bound))
    res = solver.solve(rec, DIAG_X0, TOL)
    assert res.converged
    pairs = iterates_and_trials(rec)
    queries = sum(kind == "max_step" for kind, _ in rec.events)
    assert queries >= res.iterations
    assert pairs
    for current, x in pairs:   # every trial (FD perturbations aside) within the bound
        assert np.all(np.abs(x - current) <= bound * (1 + 1e-12) + 1e-6)
    # the initial distance is up to 0.6 and the bound 0.05-0.1: at least 6 steps
    assert res.iterations >= 6


def test_newton_scales_the_whole_step_by_a_common_factor():
    bound = np.full(10, 0.05)
    rec = RecordingProblem(DIAG.as_problem(jacobian=True, max_step=bound))
    Newton().solve(rec, DIAG_X0, TOL)
    first_step = rec.points[1] - rec.points[0]
    newton_step = -np.linalg.solve(DIAG.jacobian(DIAG_X0), DIAG.residual(DIAG_X0))
    assert np.max(np.abs(first_step)) == pytest.approx(0.05)
    np.testing.assert_allclose(first_step, newton_step * 0.05 / np.max(np.abs(newton_step)),
                               rtol=1e-12)


def test_bisection_clips_each_component():
    bound = np.array([0.01, 1.0])
    rec = RecordingProblem(FunctionProblem(lambda x: x - np.array([1.0, -1.0]), max_step=bound))
    Bisection(initial_step=0.5).solve(rec, np.zeros(2), TOL)
    step = rec.points[1] - rec.points[0]
    np.testing.assert_allclose(step, [0.01, -0.5])   # clipped / free, independently


# ---- hypothesis: random diagonal-dominant systems with known roots ------------------------
@pytest.mark.parametrize("solver", SOLVERS + [FINISH], ids=ids)
@FAST
@given(case=solver_cases())
def test_random_diagonal_systems_are_solved(solver, case):
    res = solver.solve(case.problem, case.x0, case.tolerances)
    assert res.converged, (res.status, res.message, case.name)
    assert res.residual_norm <= case.tolerances.residual
    assert case.is_near_root(res.x)


@pytest.mark.parametrize("solver", [Newton(), Broyden(), Bisection(growth=2.0),
                                    Bisection(growth=2.0, newton_below=1e-2)], ids=ids)
@FAST
@given(case=solver_cases(systems=tanh_systems(width_decades=(-1.5, 1.5),
                                              scale_decades=(-1.0, 1.0),
                                              negative_scales=True)))
def test_random_badly_scaled_systems_are_solved(solver, case):
    res = solver.solve(case.problem, case.x0, case.tolerances)
    assert res.converged and case.is_near_root(res.x), (res.status, res.message)


@FAST
@given(case=solver_cases(systems=tanh_systems(scale_decades=(-2.0, 2.0), negative_scales=True)))
def test_weighted_cg_handles_residuals_of_different_scales(case):
    res = NonlinearCG(weighting="diagonal").solve(case.problem, case.x0, case.tolerances)
    assert res.converged and case.is_near_root(res.x), (res.status, res.message)


@FAST
@given(case=solver_cases(), budget=st.integers(1, 6))
def test_never_claims_convergence_it_does_not_have(case, budget):
    tol = Tolerances(residual=1e-13, max_iterations=budget)
    for solver in SOLVERS:
        res = solver.solve(case.problem, case.x0, tol)
        assert res.converged == (res.residual_norm <= tol.residual)
        assert res.converged == (res.status is Status.CONVERGED)
        assert res.iterations <= budget


# ---- convergence rates -------------------------------------------------------------------
SMOOTH = TanhSystem(root=np.linspace(-1.0, 1.0, 10), width=np.ones(10), scale=np.ones(10),
                    coupling=coupling(10, 0.3, 7))
SMOOTH_X0 = SMOOTH.root + 0.5 * np.cos(np.arange(10))


def test_newton_converges_quadratically():
    res = Newton().solve(SMOOTH.as_problem(jacobian=True), SMOOTH_X0,
                         Tolerances(residual=1e-13))
    h = [e for e in res.residual_history if e > 1e-15]
    pairs = [(a, b) for a, b in zip(h, h[1:]) if a < 0.1]
    assert len(pairs) >= 2
    for a, b in pairs:           # e_{k+1} <= C·e_k² with a modest C
        assert b <= 2.0 * a * a
    assert res.iterations <= 5


def test_broyden_is_superlinear_and_beats_the_chord_method():
    problem = SMOOTH.as_problem(jacobian=True)
    res = Broyden().solve(problem, SMOOTH_X0, Tolerances(residual=1e-12))
    assert res.converged and res.extras["restarts"] == 0
    J0 = SMOOTH.jacobian(SMOOTH_X0)            # chord: the same initial Jacobian, never updated
    x, chord = SMOOTH_X0.copy(), 0
    while np.max(np.abs(SMOOTH.residual(x))) > 1e-12:
        x -= np.linalg.solve(J0, SMOOTH.residual(x))
        chord += 1
    assert res.iterations < 0.75 * chord
    h = res.residual_history
    ratios = [b / a for a, b in zip(h, h[1:])]
    assert min(ratios[-4:]) < 0.1                 # the contraction factor goes to zero


def test_broyden_relaxation_slows_it_down_linearly():
    problem = SMOOTH.as_problem(jacobian=True)
    its = [Broyden(relaxation=a).solve(problem, SMOOTH_X0, TOL).iterations
           for a in (1.0, 0.7, 0.4)]
    assert its[0] < its[1] < its[2]


def test_broyden_restarts_after_growing_merit():
    """A wrong initial Jacobian (sign flipped) makes the merit grow: Broyden restarts."""
    system = TanhSystem(root=np.linspace(-1.0, 1.0, 6), width=np.ones(6), scale=np.ones(6),
                        coupling=coupling(6, 0.3, 7))
    calls = []

    def bad_then_good(x):
        calls.append(1)
        return (-1.0 if len(calls) == 1 else 1.0) * system.jacobian(x)

    problem = FunctionProblem(system.residual, jacobian=bad_then_good)
    x0 = system.root + 0.5 * np.cos(np.arange(6) * 1.7)
    res = Broyden().solve(problem, x0, TOL)
    assert res.converged and res.extras["restarts"] >= 1 and len(calls) >= 2
    calls.clear()
    plain = Broyden(restart=False).solve(problem, x0, TOL)
    assert plain.extras["restarts"] == 0 and len(calls) == 1
    assert res.iterations < plain.iterations


def test_forward_and_central_newton_agree_with_analytic():
    problem, x0 = PROBLEMS["diagonal-dominant"][:2]
    a = Newton().solve(DIAG.as_problem(jacobian=True), x0, TOL)
    f = Newton().solve(problem, x0, TOL)
    c = Newton(difference="central").solve(problem, x0, TOL)
    assert a.iterations == f.iterations == c.iterations
    assert a.function_evaluations == a.iterations + 1
    assert f.function_evaluations == 1 + f.iterations * (1 + 10)
    assert c.function_evaluations == 1 + c.iterations * (1 + 20)


def test_undamped_newton_reports_divergence_or_failure():
    # Newton on atan from x0 = 3 diverges (|x| grows each step) without damping
    def jacobian(x):
        with np.errstate(over="ignore"):
            return np.diag(1.0 / (1.0 + x * x))

    problem = FunctionProblem(np.arctan, jacobian=jacobian)
    res = Newton(damping=False).solve(problem, np.array([3.0]), Tolerances(max_iterations=30))
    assert not res.converged
    damped = Newton().solve(problem, np.array([3.0]), Tolerances(max_iterations=30))
    assert damped.converged and damped.extras["halvings"] > 0


# ---- nonlinear CG specifics --------------------------------------------------------------
class Energy:
    """U(x) = Σ log cosh(x_i - c_i) + ½(x - c)ᵀS(x - c); the residual is its gradient."""

    def __init__(self, n, seed=3):
        rng = np.random.default_rng(seed)
        self.c = rng.uniform(-1, 1, n)
        a = rng.uniform(-1, 1, (n, n))
        self.S = 0.05 * (a @ a.T) / n

    def residual(self, x):
        u = x - self.c
        return np.tanh(u) + self.S @ u

    def merit(self, x):
        u = x - self.c
        return float(np.sum(np.log(np.cosh(u))) + 0.5 * u @ self.S @ u)


@pytest.mark.parametrize("beta", ["polak-ribiere", "fletcher-reeves"])
@pytest.mark.parametrize("line_search", ["armijo", "wolfe"])
def test_cg_minimises_an_energy_without_jacobian(beta, line_search):
    energy = Energy(12)
    res = NonlinearCG(gradient="residual", beta=beta, line_search=line_search).solve(
        energy, np.zeros(12), TOL)
    assert res.converged and res.extras["jacobians"] == 0
    np.testing.assert_allclose(res.x, energy.c, atol=1e-8)
    assert res.extras["merit_evaluations"] > 0


def test_cg_residual_mode_needs_a_merit():
    with pytest.raises(ValidationError, match="NonlinearCG.gradient"):
        NonlinearCG(gradient="residual").solve(DIAG.as_problem(), DIAG_X0, TOL)


def test_cg_uses_the_problem_merit_when_given():
    merit_calls = []

    def merit(x):
        merit_calls.append(1)
        r = DIAG.residual(x)
        return 3.0 * float(r @ r)

    problem = FunctionProblem(DIAG.residual, jacobian=DIAG.jacobian, merit=merit)
    res = NonlinearCG().solve(problem, DIAG_X0, TOL)
    assert res.converged and res.extras["merit_evaluations"] == len(merit_calls) > 0


def test_cg_with_nonsymmetric_jacobian_finds_the_root():
    A = np.array([[3.0, 1.0], [-1.0, 2.0]])        # non-symmetric, non-singular
    problem = FunctionProblem(lambda x: A @ x + 0.1 * np.sin(x) - np.array([1.0, 2.0]))
    res = NonlinearCG().solve(problem, np.zeros(2), TOL)
    assert res.converged


# ---- bisection specifics -----------------------------------------------------------------
def test_bisection_follows_orientation():
    s = TanhSystem(root=[0.2, -0.3], width=[1.0, 1.0], scale=[-1.0, 2.0],
                   coupling=[[0.0, 0.1], [0.1, 0.0]])
    res = Bisection().solve(s.as_problem(orientation=True), np.zeros(2), TOL)
    assert res.converged
    np.testing.assert_allclose(res.x, s.root, atol=1e-8)
    wrong = Bisection().solve(s.as_problem(), np.zeros(2), Tolerances(max_iterations=300))
    assert not wrong.converged      # orientation +1 walks component 0 away from its root


def test_bisection_is_one_bit_per_iteration_once_bracketed():
    root = 0.123456789
    res = Bisection(initial_step=0.5).solve(FunctionProblem(lambda x: x - root), np.zeros(1),
                                            Tolerances(residual=1e-10))
    assert res.converged
    assert res.iterations <= 1 + int(np.ceil(np.log2(0.5 / 1e-10))) + 1
    assert res.function_evaluations == res.iterations + 1


def test_bisection_stalls_when_steps_vanish():
    # a jump: r changes sign at 0.1 without a root; the steps shrink below tolerances.step
    problem = FunctionProblem(lambda x: np.where(x < 0.1, -1.0, 1.0))
    res = Bisection().solve(problem, np.zeros(1), Tolerances(step=1e-9))
    assert not res.converged and res.status is Status.STALLED
    assert abs(res.x[0] - 0.1) < 1e-8


def test_bisection_growth_reaches_far_roots_quickly():
    problem = FunctionProblem(lambda x: np.tanh(x - 30.0037))
    slow = Bisection().solve(problem, np.zeros(1), Tolerances(max_iterations=10_000))
    fast = Bisection(growth=2.0).solve(problem, np.zeros(1), Tolerances(max_iterations=10_000))
    assert slow.converged and fast.converged
    assert fast.iterations < 60 < 3000 < slow.iterations     # 0.01 per step up to 30


@pytest.mark.parametrize("jacobian", [True, False], ids=["analytic", "differenced"])
def test_newton_finish_lands_on_the_root_of_the_march_in_fewer_evaluations(jacobian):
    problem = DIAG.as_problem(jacobian=jacobian)
    plain = Bisection().solve(problem, DIAG_X0, TOL)
    fast = FINISH.solve(problem, DIAG_X0, TOL)
    assert plain.converged and fast.converged
    assert plain.extras["newton_steps"] == 0 < fast.extras["newton_steps"]
    atol = DIAG.root_atol(TOL.residual)
    assert np.all(np.abs(fast.x - DIAG.root) <= atol)
    assert np.all(np.abs(fast.x - plain.x) <= 2 * atol)
    # measured: 108 evaluations by bisection alone, 65 (analytic) and 85 (differenced) with it
    assert fast.function_evaluations < plain.function_evaluations
    assert max(fast.residual_history) == max(plain.residual_history)   # the same march until then


def test_newton_finish_with_a_wrong_jacobian_leaves_the_march_as_it_was():
    # a Jacobian of the wrong sign: the Newton step raises |r|, so it is left after one
    # evaluation and the march goes on exactly as without the finish
    wrong = FunctionProblem(DIAG.residual, jacobian=lambda x: -DIAG.jacobian(x))
    plain = Bisection().solve(wrong, DIAG_X0, TOL)
    fast = FINISH.solve(wrong, DIAG_X0, TOL)
    assert plain.converged and fast.converged
    assert fast.extras["newton_steps"] == 0
    assert fast.function_evaluations == plain.function_evaluations + 1
    np.testing.assert_array_equal(fast.x, plain.x)


def test_newton_finish_respects_max_step():
    # a bound far below the Newton step: no Newton step is taken, none is evaluated
    rec = RecordingProblem(FunctionProblem(DIAG.residual, jacobian=DIAG.jacobian,
                                           max_step=np.full(10, 1e-12)))
    plain = Bisection(initial_step=1e-12).solve(
        FunctionProblem(DIAG.residual, max_step=np.full(10, 1e-12)), DIAG_X0,
        Tolerances(residual=1e-9, max_iterations=40))
    fast = Bisection(initial_step=1e-12, newton_below=0.999).solve(
        rec, DIAG_X0, Tolerances(residual=1e-9, max_iterations=40))
    assert fast.extras["newton_steps"] == 0
    assert fast.function_evaluations == plain.function_evaluations


# ---- options are validated ---------------------------------------------------------------
@pytest.mark.parametrize("cls, kwargs, field", [
    (Broyden, {"relaxation": 0.0}, "Broyden.relaxation"),
    (Broyden, {"relaxation": 1.5}, "Broyden.relaxation"),
    (Broyden, {"relaxation": float("nan")}, "Broyden.relaxation"),
    (Broyden, {"difference": "backward"}, "Broyden.difference"),
    (Broyden, {"restart_after": 0}, "Broyden.restart_after"),
    (Newton, {"difference": "spline"}, "Newton.difference"),
    (Newton, {"rel_step": -1e-7}, "Newton.rel_step"),
    (Newton, {"rel_step": 0.0}, "Newton.rel_step"),
    (Newton, {"typical_scale": -1.0}, "Newton.typical_scale"),
    (Newton, {"damping": "yes"}, "Newton.damping"),
    (Broyden, {"restart": 1}, "Broyden.restart"),
    (Newton, {"max_halvings": -1}, "Newton.max_halvings"),
    (NonlinearCG, {"beta": "hestenes-stiefel"}, "NonlinearCG.beta"),
    (NonlinearCG, {"line_search": "exact"}, "NonlinearCG.line_search"),
    (NonlinearCG, {"gradient": "adjoint"}, "NonlinearCG.gradient"),
    (NonlinearCG, {"armijo": 0.6}, "NonlinearCG.armijo"),
    (NonlinearCG, {"armijo": 0.2, "curvature": 0.1}, "NonlinearCG.curvature"),
    (NonlinearCG, {"restart_every": -1}, "NonlinearCG.restart_every"),
    (NonlinearCG, {"rel_step": -1.0}, "NonlinearCG.rel_step"),
    (Bisection, {"initial_step": -0.01}, "Bisection.initial_step"),
    (Bisection, {"initial_step": 0.0}, "Bisection.initial_step"),
    (Bisection, {"shrink": 1.0}, "Bisection.shrink"),
    (Bisection, {"shrink": 0.0}, "Bisection.shrink"),
    (Bisection, {"growth": 0.5}, "Bisection.growth"),
    (Bisection, {"patience": 0}, "Bisection.patience"),
    (Bisection, {"newton_below": 1.0}, "Bisection.newton_below"),
    (Bisection, {"newton_below": -1e-3}, "Bisection.newton_below"),
    (Broyden, {"stall_iterations": -1}, "Broyden.stall_iterations"),
])
def test_bad_options_name_the_field(cls, kwargs, field):
    with pytest.raises(ValidationError, match=field):
        cls(**kwargs)


@pytest.mark.parametrize("cls, kwargs", [(Broyden, {"relaxation": 0.0}),
                                         (Newton, {"difference": "x"}),
                                         (Bisection, {"initial_step": -1.0})])
def test_validation_error_carries_field_value_and_range(cls, kwargs):
    with pytest.raises(ValidationError) as info:
        cls(**kwargs)
    (key, value), = kwargs.items()
    assert info.value.field == f"{cls.__name__}.{key}"
    assert info.value.value == value
    assert info.value.allowed


@pytest.mark.parametrize("solver", SOLVERS, ids=ids)
def test_solvers_are_keyword_only_frozen_values(solver):
    import attrs

    assert isinstance(solver, NonlinearSolver)
    with pytest.raises(TypeError):
        type(solver)(1.0)
    first = attrs.fields(type(solver))[0].name
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        setattr(solver, first, getattr(solver, first))
    assert attrs.evolve(solver) == solver and hash(attrs.evolve(solver)) == hash(solver)


def test_registered_names_resolve_to_the_solvers():
    from viscocontact._registry import solvers

    assert {"newton", "broyden", "nonlinear-cg", "bisection"} <= set(solvers.names())
    assert solvers.get("broyden") is Broyden and solvers.get("bisection") is Bisection
    assert solvers.get("newton") is Newton and solvers.get("nonlinear-cg") is NonlinearCG


def test_cg_restarts_when_the_conjugate_step_is_negligible():
    """Regression (found by hypothesis): an unknown whose root is ~1e-142 made the PR direction
    so long that the Armijo step moved nothing else; the steepest-descent retry converges."""
    system = TanhSystem(root=[-1.47823193, -9.59407128e-143], width=[1.0, 1.0],
                        scale=[1.0, 1.0], coupling=np.zeros((2, 2)))
    res = NonlinearCG().solve(system.as_problem(), [-2.050642650640125, 0.278273798489942], TOL)
    assert res.converged and res.iterations <= 6


@pytest.mark.parametrize("cls", [Broyden, Newton])
def test_a_jacobian_that_is_not_finite_ends_the_solve_as_failed(cls):
    """A differenced Jacobian whose column crossed into points where the residual is undefined
    (a model's limitation there) is not finite: the solve ends as failed and says why, instead
    of raising from the inverse's SVD (Broyden did: ``LinAlgError: SVD did not converge``)."""
    class Problem:
        def residual(self, x):
            return np.array([x[0] ** 2 - 2.0, x[1] - 1.0])

        def jacobian(self, x):
            return np.array([[np.inf, 0.0], [0.0, 1.0]])

    r = cls().solve(Problem(), np.array([1.0, 0.0]))
    assert not r.converged and r.status is Status.FAILED
    assert "finite" in r.message
