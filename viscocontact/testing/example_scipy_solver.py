"""An example plugin solver: :func:`scipy.optimize.root` behind the
:class:`~viscocontact.solvers.base.NonlinearSolver` interface.

It shows what a third-party solver has to do to honour the contract:

* count every call of ``problem.residual`` and stop at ``Tolerances.max_evaluations``;
* decide convergence itself, as ``max|r| <= Tolerances.residual`` (scipy's own ``success`` uses
  other criteria, e.g. a relative step for ``hybr``): the wrapper stops scipy as soon as an
  evaluated point meets the tolerance;
* let exceptions raised by ``residual`` propagate (it catches only its own private signals).

It ignores ``max_step`` (scipy has no per-component step bound), so it is suited to problems
without one. Register it from a distribution's ``pyproject.toml``::

    [project.entry-points."viscocontact.solvers"]
    scipy-root = "viscocontact.testing.example_scipy_solver:ScipyRoot"
"""
from __future__ import annotations

import attrs
import numpy as np
from scipy import optimize

from .._validation import one_of
from ..solvers.base import (NonlinearProblem, NonlinearSolver, SolverResult, Status, Tolerances,
                            optional)

__all__ = ["ScipyRoot"]

METHODS = ("hybr", "lm", "broyden1", "broyden2", "anderson", "krylov", "df-sane")
_WITH_JACOBIAN = ("hybr", "lm")


class _Converged(Exception):
    """Private signal: an evaluated point met the residual tolerance."""


class _OutOfBudget(Exception):
    """Private signal: the evaluation or iteration budget is spent."""


class _Tracker:
    """The residual as scipy sees it: counted, with the best point kept (an *iteration* is an
    evaluation that improves the best ``max|r|``, so ``residual_history`` decreases)."""

    def __init__(self, problem: NonlinearProblem, tolerances: Tolerances):
        self.problem, self.tol = problem, tolerances
        self.calls = 0
        self.best_x: np.ndarray | None = None
        self.best_r: np.ndarray | None = None
        self.history: list[float] = []

    def __call__(self, x: np.ndarray) -> np.ndarray:
        if self.calls >= self.tol.max_evaluations:
            raise _OutOfBudget("max_evaluations")
        self.calls += 1
        x = np.array(x, dtype=float, copy=True)
        r = np.asarray(self.problem.residual(x.copy()), dtype=float).reshape(-1)
        norm = float(np.max(np.abs(r))) if r.size else 0.0
        if np.isfinite(norm) and (not self.history or norm < self.history[-1]):
            self.best_x, self.best_r = x, r.copy()
            self.history.append(norm)
            if norm <= self.tol.residual:
                raise _Converged
            if len(self.history) - 1 >= self.tol.max_iterations:
                raise _OutOfBudget("max_iterations")
        if self.best_x is None:  # non-finite first residual: remember it anyway
            self.best_x, self.best_r = x, r.copy()
        return r


@attrs.frozen(kw_only=True)
class ScipyRoot(NonlinearSolver):
    """Any :func:`scipy.optimize.root` method as a viscocontact solver.

    Parameters
    ----------
    method : str
        One of ``"hybr"`` (MINPACK Powell hybrid, default), ``"lm"``, ``"broyden1"``,
        ``"broyden2"``, ``"anderson"``, ``"krylov"``, ``"df-sane"``. ``hybr`` and ``lm`` use
        ``problem.jacobian`` when the problem has one.

    Notes
    -----
    ``iterations`` counts the evaluations that improved the best ``max|r|``; the result is the
    best point seen. ``max_step`` is not honoured.
    """

    method: str = attrs.field(default="hybr", validator=one_of(METHODS))

    def _options(self, tolerances: Tolerances, n: int) -> dict:
        if self.method == "hybr":
            return {"xtol": 1e-15, "maxfev": tolerances.max_evaluations}
        if self.method == "lm":
            return {"xtol": 1e-15, "ftol": 1e-15, "maxiter": tolerances.max_evaluations}
        if self.method == "df-sane":
            return {"fatol": 0.0, "ftol": 0.0, "maxfev": tolerances.max_evaluations}
        return {"fatol": tolerances.residual, "maxiter": tolerances.max_evaluations}

    def _solve(self, problem: NonlinearProblem, x0: np.ndarray,
               tolerances: Tolerances) -> SolverResult:
        track = _Tracker(problem, tolerances)
        jac_fn = optional(problem, "jacobian")
        jac = None
        if jac_fn is not None and self.method in _WITH_JACOBIAN:
            jac = lambda x: np.asarray(jac_fn(np.array(x, dtype=float)), dtype=float)  # noqa: E731
        status, message = Status.FAILED, ""
        try:
            sol = optimize.root(track, x0, method=self.method, jac=jac,
                                options=self._options(tolerances, x0.size))
        except _Converged:
            status, message = Status.CONVERGED, "max|r| <= tolerances.residual"
        except _OutOfBudget as exc:
            status = (Status.MAX_ITERATIONS if str(exc) == "max_iterations"
                      else Status.MAX_EVALUATIONS)
            message = f"{exc}: {track.calls} evaluations"
        else:
            status = Status.STALLED if sol.success else Status.FAILED
            message = f"scipy.optimize.root({self.method!r}) stopped: {sol.message}"
        if track.best_x is None or track.best_r is None:
            # not a single evaluation (cannot happen: max_evaluations >= 1)
            x, r = x0, np.full(x0.shape, np.inf)
        else:
            x, r = track.best_x, track.best_r
        converged = (bool(np.all(np.isfinite(r)))
                     and float(np.max(np.abs(r), initial=0.0)) <= tolerances.residual)
        if converged:
            status = Status.CONVERGED
        elif status is Status.CONVERGED:
            status = Status.FAILED
        return SolverResult(x=x, residual=r, converged=converged, status=status, message=message,
                            iterations=max(len(track.history) - 1, 0),
                            function_evaluations=track.calls,
                            residual_history=tuple(track.history),
                            extras={"method": self.method})
