"""The public solver conformance check: built-ins and the scipy example pass, broken ones fail."""
import attrs
import numpy as np
import pytest
from hypothesis import given, settings

from viscocontact.solvers import (Bisection, Broyden, Newton, NonlinearCG, SolverResult, Status,
                                  Tolerances)
from viscocontact.solvers.base import NonlinearSolver
from viscocontact.testing.conformance_solvers import check_solver
from viscocontact.testing.example_scipy_solver import ScipyRoot
from viscocontact.testing.strategies_solvers import (CoupledPair, InjectedError, NoRoot,
                                                     RecordingProblem, solver_cases,
                                                     standard_cases)


@pytest.mark.parametrize("solver", [
    Newton(), Newton(difference="central", damping=False), Broyden(),
    Broyden(relaxation=0.6, restart=False), NonlinearCG(),
    NonlinearCG(beta="fletcher-reeves", line_search="wolfe"), Bisection(),
    Bisection(growth=2.0, shrink=0.4), Bisection(newton_below=1e-2)], ids=repr)
def test_builtin_solvers_conform(solver):
    check_solver(solver)


@pytest.mark.parametrize("method", ["hybr", "lm", "krylov"])
def test_scipy_example_plugin_conforms(method):
    check_solver(ScipyRoot(method=method), honours_max_step=False)


def test_scipy_example_propagates_exceptions_through_minpack():
    case = standard_cases()[1]
    rec = RecordingProblem(case.problem, fail_at=3)
    with pytest.raises(InjectedError):
        ScipyRoot().solve(rec, case.x0, case.tolerances)
    assert rec.calls == 3


def test_scipy_example_does_not_trust_scipy_success():
    # hybr stops on a small relative step; the wrapper still demands max|r| <= tol
    res = ScipyRoot().solve(NoRoot(), np.full(2, 0.5), Tolerances(max_evaluations=200))
    assert not res.converged and res.status in (Status.FAILED, Status.STALLED,
                                                Status.MAX_EVALUATIONS)


@settings(max_examples=20, deadline=None)
@given(case=solver_cases())
def test_scipy_example_keeps_the_contract_on_random_systems(case):
    # hybr's trust region can end in the saturated tanh plateau (not converged): that is
    # allowed, claiming convergence there is not
    res = ScipyRoot().solve(case.problem, case.x0, case.tolerances)
    if res.converged:
        assert case.is_near_root(res.x) and res.residual_norm <= case.tolerances.residual
    else:
        assert res.status is not Status.CONVERGED
        assert res.residual_norm > case.tolerances.residual


def test_strategy_problems_have_the_advertised_roots():
    for case in standard_cases():
        assert np.max(np.abs(case.problem.residual(case.root))) <= 1e-14
    pair = CoupledPair()
    np.testing.assert_array_equal(pair.residual(np.ones(2)), [0.0, 0.0])


# ---- deliberately broken solvers are caught ------------------------------------------------
@attrs.frozen(kw_only=True)
class _Good(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        return Newton()._solve(problem, x0, tolerances)


@attrs.frozen(kw_only=True)
class SwallowsExceptions(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        try:
            return Newton()._solve(problem, x0, tolerances)
        except Exception:  # noqa: BLE001 - the bug under test
            r = np.full(x0.shape, np.inf)
            return SolverResult(x=x0, residual=r, converged=False, status=Status.FAILED,
                                message="oops", iterations=0, function_evaluations=1)


@attrs.frozen(kw_only=True)
class ClaimsConvergence(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        res = Newton()._solve(problem, x0, tolerances)
        return attrs.evolve(res, converged=True, status=Status.CONVERGED)


@attrs.frozen(kw_only=True)
class UndercountsEvaluations(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        res = Newton()._solve(problem, x0, tolerances)
        return attrs.evolve(res, function_evaluations=res.iterations + 1)


@attrs.frozen(kw_only=True)
class IgnoresMaxStep(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        class Hide:
            residual = staticmethod(problem.residual)
        res = Newton()._solve(Hide(), x0, tolerances)
        if hasattr(problem, "max_step"):
            problem.max_step(res.x)   # asks, but too late
        return res


@attrs.frozen(kw_only=True)
class ReturnsStaleResidual(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        res = Newton()._solve(problem, x0, tolerances)
        return attrs.evolve(res, x=res.x + 1e-3)


class NotAttrs(NonlinearSolver):
    def _solve(self, problem, x0, tolerances):
        return Newton()._solve(problem, x0, tolerances)


def test_reference_wrapper_passes():
    check_solver(_Good())


@pytest.mark.parametrize("solver, message", [
    (SwallowsExceptions(), "swallowed|converted"),
    (ClaimsConvergence(), "converged"),
    (UndercountsEvaluations(), "function_evaluations"),
    (IgnoresMaxStep(), "max_step"),
    (ReturnsStaleResidual(), "not the residual at result.x"),
    (NotAttrs(), "attrs"),
])
def test_broken_solvers_are_reported(solver, message):
    with pytest.raises(AssertionError, match=message):
        check_solver(solver)
