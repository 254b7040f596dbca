"""Newton-Raphson with an analytic or finite-difference Jacobian (thesis §4.5.1, equations
4.33-4.37)."""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import int_range, one_of, positive
from ._fd import (FiniteDifferenceOptions, DIFFERENCES, BudgetExhausted, CountedResidual, FiniteDifference, boolean,
                  first_residual, limit_step, linear_solve, max_abs, problem_jacobian, result)
from .base import NonlinearProblem, NonlinearSolver, SolverResult, Status, Tolerances

__all__ = ["Newton"]


def _merit(r: np.ndarray) -> float:
    return 0.5 * float(r @ r) if np.all(np.isfinite(r)) else float("inf")


@attrs.frozen(kw_only=True)
class Newton(FiniteDifferenceOptions, NonlinearSolver):
    """Newton-Raphson: ``x_{k+1} = x_k - t_k·J(x_k)⁻¹ r(x_k)`` (equation 4.35).

    Parameters
    ----------
    difference : {"forward", "central"}
        Finite-difference scheme for J when the problem has no ``jacobian`` (eqs. 4.49/4.50):
        ``n`` or ``2n`` residual evaluations per iteration.
    rel_step : float
        Relative finite-difference step, ``h_i = rel_step·max(|x_i|, typical_scale)``.
    typical_scale : float
        Magnitude of the unknowns below which the FD step stops shrinking.
    damping : bool
        Backtracking on the merit ``0.5·|r|²``: halve ``t`` from 1 until the merit decreases
        (at most ``max_halvings`` times; no decrease stops with ``Status.STALLED``). Without
        damping the full step is taken (``Status.DIVERGED`` if the residual becomes non-finite).
    max_halvings : int
        Largest number of step halvings per iteration.

    Notes
    -----
    * ``max_step`` is applied by one common factor on the whole Newton step (the direction is
      kept, so it stays a descent direction of the merit), before backtracking.
    * Cost per iteration: the Jacobian (0 evaluations if analytic, ``n`` forward, ``2n``
      central) plus one evaluation per trial step. Convergence is quadratic with an analytic or
      central-difference Jacobian, and linear with ratio ``~rel_step·|x|·|J''|/|J|`` with forward
      differences (indistinguishable from quadratic at the usual tolerances).
    * A singular Jacobian gives the least-squares (minimum-norm) step.

    Examples
    --------
    >>> import numpy as np
    >>> class P:
    ...     def residual(self, x):
    ...         return np.array([x[0]**2 - 2.0])
    >>> res = Newton().solve(P(), np.array([1.0]))
    >>> res.converged, round(float(res.x[0]), 9), res.iterations
    (True, 1.414213562, 4)
    """

    damping: bool = attrs.field(default=True, validator=boolean)
    max_halvings: int = attrs.field(default=10, validator=int_range(0, 60))

    def _solve(self, problem: NonlinearProblem, x0: np.ndarray,
               tolerances: Tolerances) -> SolverResult:
        fun = CountedResidual.of(problem, tolerances)
        fd = self.finite_difference
        x, r = x0, np.full(x0.shape, np.inf)
        history: list[float] = []
        it = jacobians = halvings = 0
        status, message = Status.FAILED, ""
        try:
            r, early = first_residual(fun, x, tolerances, history)
            if early is not None:
                return early
            while True:
                if max_abs(r) <= tolerances.residual:
                    status = Status.CONVERGED
                    break
                if it >= tolerances.max_iterations:
                    status, message = Status.MAX_ITERATIONS, f"{it} iterations"
                    break
                J, _ = problem_jacobian(problem, fun, x, r, fd)
                jacobians += 1
                dx = linear_solve(J, -r)
                if not np.all(np.isfinite(dx)):
                    status, message = Status.FAILED, "Newton step is not finite (singular J)"
                    break
                dx, _ = limit_step(problem, x, dx)
                if max_abs(dx) <= tolerances.step:
                    status, message = Status.STALLED, f"step {max_abs(dx):.3g} <= tolerances.step"
                    break
                f0 = _merit(r)
                t = 1.0
                xt = x + dx
                rt = fun(xt)
                if self.damping:
                    k = 0
                    while not _merit(rt) < f0 and k < self.max_halvings:
                        k += 1
                        t *= 0.5
                        xt = x + t * dx
                        rt = fun(xt)
                    halvings += k
                    if not _merit(rt) < f0:
                        status = Status.STALLED
                        message = (f"no decrease of 0.5|r|² after {self.max_halvings} "
                                   "step halvings")
                        break
                elif not np.all(np.isfinite(rt)):
                    status, message = Status.DIVERGED, "residual became non-finite"
                    break
                x, r = xt, rt
                it += 1
                history.append(max_abs(r))
        except BudgetExhausted:
            status, message = fun.stop
        return result(x, r, tolerances, status, message, it, fun.count, history,
                      jacobians=jacobians, halvings=halvings)
