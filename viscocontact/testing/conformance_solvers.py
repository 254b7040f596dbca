"""Conformance check for :class:`~viscocontact.solvers.base.NonlinearSolver` implementations.

Public, so that plugin authors run it on their own solvers::

    from viscocontact.testing.conformance_solvers import check_solver

    def test_my_solver_conforms():
        check_solver(MySolver(relaxation=0.5))

The check runs the solver over the deterministic problems of
:func:`~viscocontact.testing.strategies_solvers.standard_cases` and asserts the contract of
:mod:`viscocontact.solvers.base`; it raises :class:`AssertionError` naming the case and the
property that failed.
"""
from __future__ import annotations

from typing import Any, Iterable

import attrs
import numpy as np

from ..solvers.base import NonlinearSolver, SolverResult, Status, Tolerances
from .strategies_solvers import (InjectedError, RecordingProblem, SolverCase, no_root_case,
                                 standard_cases)

__all__ = ["check_solver"]


def _fail(name: str, message: str) -> None:
    raise AssertionError(f"{name}: {message}")


def _max_abs(v) -> float:
    v = np.asarray(v, dtype=float)
    return float(np.max(np.abs(v))) if v.size else 0.0


def _check_value_semantics(solver: Any, name: str) -> None:
    from .conformance import _check_frozen, _check_hashable

    _check_frozen(solver, name)
    _check_hashable(solver, name)


def _check_result(res: Any, case: SolverCase, rec: RecordingProblem, tol: Tolerances,
                  name: str, where: str) -> None:
    """Properties every result must have, converged or not."""
    if not isinstance(res, SolverResult):
        _fail(name, f"{where}: solve returned {type(res).__name__}, not SolverResult")
    if not isinstance(res.status, Status):
        _fail(name, f"{where}: status {res.status!r} is not a Status")
    x = np.asarray(res.x)
    if x.shape != np.shape(case.x0):
        _fail(name, f"{where}: x has shape {x.shape}, expected {np.shape(case.x0)}")
    if res.function_evaluations != rec.calls:
        _fail(name, f"{where}: function_evaluations = {res.function_evaluations} but residual "
                    f"was called {rec.calls} times (count every call, finite differences too)")
    if rec.calls > tol.max_evaluations:
        _fail(name, f"{where}: {rec.calls} residual calls exceed max_evaluations = "
                    f"{tol.max_evaluations}")
    if not 0 <= res.iterations <= tol.max_iterations:
        _fail(name, f"{where}: iterations = {res.iterations} outside [0, max_iterations = "
                    f"{tol.max_iterations}]")
    norm = _max_abs(res.residual) if np.all(np.isfinite(res.residual)) else np.inf
    if res.converged != (norm <= tol.residual):
        _fail(name, f"{where}: converged = {res.converged} but max|r| = {norm:.3g} and "
                    f"tolerances.residual = {tol.residual:g} (converged iff max|r| <= tol)")
    if res.converged != (res.status is Status.CONVERGED):
        _fail(name, f"{where}: converged = {res.converged} with status {res.status}")
    if np.all(np.isfinite(x)):
        again = np.asarray(case.problem.residual(x.copy()), dtype=float)
        scale = max(_max_abs(again), tol.residual)
        if again.shape != np.shape(res.residual) or not np.allclose(
                again, res.residual, rtol=1e-9, atol=1e-9 * scale):
            _fail(name, f"{where}: result.residual is not the residual at result.x "
                        f"(max difference {_max_abs(again - res.residual):.3g})")
    if not isinstance(res.residual_history, tuple):
        _fail(name, f"{where}: residual_history must be a tuple")
    if res.residual_history and np.isfinite(norm) and not np.isclose(
            res.residual_history[-1], norm, rtol=1e-9, atol=0.0):
        _fail(name, f"{where}: residual_history[-1] = {res.residual_history[-1]:.6g} is not "
                    f"max|r| at the returned x ({norm:.6g})")


def _run(solver, case: SolverCase, tol: Tolerances | None = None, **recording):
    rec = RecordingProblem(case.problem, **recording)
    x0 = np.array(case.x0, dtype=float)
    res = solver.solve(rec, x0, tol or case.tolerances)
    if not np.array_equal(x0, case.x0):
        raise AssertionError("solve modified the caller's x0 array")
    return res, rec


def _check_max_step(rec: RecordingProblem, case: SolverCase, name: str) -> None:
    """Every residual evaluation lies within max_step of the latest iterate (the latest point
    where the solver asked for max_step), up to finite-difference perturbations."""
    bound_fn = case.problem.max_step
    queries = [x for kind, x in rec.events if kind == "max_step"]
    if not queries:
        _fail(name, f"case {case.name!r}: the problem has max_step but the solver never asked "
                    "for it")
    current = np.array(case.x0, dtype=float)
    bound = np.asarray(bound_fn(current), dtype=float)
    for k, (kind, x) in enumerate(rec.events):
        if kind == "max_step":
            current, bound = x, np.asarray(bound_fn(x), dtype=float)
            continue
        slack = 1e-6 * np.maximum(np.abs(current), 1.0)
        excess = np.abs(x - current) - bound * (1 + 1e-9) - slack
        if np.any(excess > 0):
            i = int(np.argmax(excess))
            _fail(name, f"case {case.name!r}: residual call {k} moved x[{i}] by "
                        f"{abs(x[i] - current[i]):.4g} from the iterate, more than "
                        f"max_step = {bound[i]:.4g}")


def check_solver(solver: NonlinearSolver, *, honours_max_step: bool = True,
                 cases: Iterable[SolverCase] | None = None) -> None:
    """Check a :class:`~viscocontact.solvers.base.NonlinearSolver` against its contract.

    Checks: frozen attrs value semantics and hashability; on every case of
    :func:`~viscocontact.testing.strategies_solvers.standard_cases` (or ``cases``) it converges
    near the known root with ``converged``/``status`` consistent with ``max|r| <= tol``,
    ``function_evaluations`` equal to the number of residual calls, ``result.residual`` equal to
    the residual at ``result.x``, iterations within budget, the caller's x0 untouched; the same
    solve twice gives the same answer; a start at the root converges with 0 iterations; a
    problem without a root is never reported converged; ``max_iterations = 1`` and
    ``max_evaluations = 3`` are respected; an exception raised by ``residual`` at the 1st, 2nd,
    4th or 7th call propagates unchanged; with ``honours_max_step`` every residual evaluation
    lies within ``max_step`` of the current iterate.

    Parameters
    ----------
    solver : NonlinearSolver
        Instance to check (its options as the user would set them).
    honours_max_step : bool
        False for solvers documented not to support ``max_step`` (wrappers of foreign codes).
    cases : iterable of SolverCase, optional
        Replaces the standard problems.

    Raises
    ------
    AssertionError
        Naming the case and the failed property.
    """
    name = f"check_solver({type(solver).__qualname__})"
    _check_component(solver, name)
    case_list = list(standard_cases() if cases is None else cases)
    _check_cases(solver, case_list, honours_max_step, name)
    _check_deterministic(solver, case_list[0], name)
    _check_start_at_root(solver, case_list[0], name)
    _check_no_root(solver, name)
    hard = next((c for c in case_list if c.x0.size > 1), case_list[0])
    _check_budgets(solver, hard, name)
    _check_exceptions_propagate(solver, hard, name)


def _check_component(solver: Any, name: str) -> None:
    """A :class:`~viscocontact.solvers.base.NonlinearSolver` and a frozen, hashable attrs
    value."""
    if not isinstance(solver, NonlinearSolver):
        _fail(name, "not a subclass of viscocontact.solvers.base.NonlinearSolver")
    if attrs.has(type(solver)):
        _check_value_semantics(solver, name)
    else:
        _fail(name, f"{type(solver).__qualname__} is not an attrs class (solvers are frozen "
                    "attrs classes, keyword-only)")


def _check_cases(solver, case_list: list[SolverCase], honours_max_step: bool,
                 name: str) -> None:
    """Every case converges near its root with a consistent result (and, when the solver
    honours it, within the problem's ``max_step``)."""
    for case in case_list:
        try:
            res, rec = _run(solver, case)
        except AssertionError as exc:
            _fail(name, f"case {case.name!r}: {exc}")
        where = f"case {case.name!r}"
        _check_result(res, case, rec, case.tolerances, name, where)
        if not res.converged:
            _fail(name, f"{where}: did not converge ({res.status.value}: {res.message}; "
                        f"max|r| = {res.residual_norm:.3g} after {res.iterations} iterations)")
        if not case.is_near_root(res.x):
            err = np.abs(np.asarray(res.x) - case.root)
            _fail(name, f"{where}: converged to x with |x - root| = {np.max(err):.3g}, more "
                        f"than the expected {np.min(case.root_atol):.3g}")
        if honours_max_step and hasattr(case.problem, "max_step"):
            _check_max_step(rec, case, name)


def _check_deterministic(solver, case: SolverCase, name: str) -> None:
    """A solver is a value: solving twice gives the same answer."""
    first, _ = _run(solver, case)
    second, _ = _run(solver, case)
    if not (np.array_equal(first.x, second.x)
            and first.function_evaluations == second.function_evaluations):
        _fail(name, f"case {case.name!r}: two identical solves differ (hidden state?)")


def _check_start_at_root(solver, case: SolverCase, name: str) -> None:
    """Started at the root, the solver converges in 0 iterations."""
    at_root = attrs.evolve(case, x0=case.root)
    res, rec = _run(solver, at_root)
    _check_result(res, at_root, rec, at_root.tolerances, name, "start at the root")
    if not res.converged or res.iterations != 0:
        _fail(name, f"start at the root: converged = {res.converged}, iterations = "
                    f"{res.iterations} (expected True, 0)")


def _check_no_root(solver, name: str) -> None:
    """A problem without a root is never reported converged."""
    nr = no_root_case()
    res, rec = _run(solver, nr)
    _check_result(res, nr, rec, nr.tolerances, name, "no-root problem r = x² + 1")
    if res.converged or res.status is Status.CONVERGED:
        _fail(name, "no-root problem r = x² + 1 reported as converged")


def _check_budgets(solver, hard: SolverCase, name: str) -> None:
    """``max_iterations = 1`` and ``max_evaluations = 3`` are respected on ``hard``."""
    for tol in (attrs.evolve(hard.tolerances, max_iterations=1),
                attrs.evolve(hard.tolerances, max_evaluations=3)):
        res, rec = _run(solver, hard, tol)
        _check_result(res, hard, rec, tol, name,
                      f"case {hard.name!r} with max_iterations = {tol.max_iterations}, "
                      f"max_evaluations = {tol.max_evaluations}")


def _check_exceptions_propagate(solver, hard: SolverCase, name: str) -> None:
    """An exception raised by ``residual`` at the 1st, 2nd, 4th or 7th call propagates
    unchanged (neither replaced nor swallowed)."""
    for k in (1, 2, 4, 7):
        rec = RecordingProblem(hard.problem, fail_at=k)
        try:
            solver.solve(rec, np.array(hard.x0), hard.tolerances)
        except InjectedError as exc:
            if exc is not rec.error:
                _fail(name, f"exception at residual call {k} was replaced by another one")
            continue
        except Exception as exc:  # noqa: BLE001 - reporting what the solver did instead
            _fail(name, f"exception at residual call {k} was converted to "
                        f"{type(exc).__name__}: {exc}")
        if rec.calls >= k:
            _fail(name, f"exception raised by residual at call {k} was swallowed")
