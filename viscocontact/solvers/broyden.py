"""Broyden's ("good") quasi-Newton method with a Sherman-Morrison inverse update (thesis §4.5.2)."""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import in_range, int_range, one_of, positive
from ._fd import (FiniteDifferenceOptions, DIFFERENCES, BudgetExhausted, CountedResidual, FiniteDifference, boolean,
                  first_residual, limit_step, max_abs, problem_jacobian, result)
from .base import NonlinearProblem, NonlinearSolver, SolverResult, Status, Tolerances

__all__ = ["Broyden", "InverseJacobian"]

#: Relative size below which the Sherman-Morrison denominator ``sᵀHy`` counts as zero.
DENOMINATOR_RTOL = 1e-12

#: Progress that ``stall_iterations`` asks for: the best ``max|r|`` of the last iterations must
#: fall below this fraction of the best before them.
STALL_PROGRESS = 0.9


def _merit(r: np.ndarray) -> float:
    return 0.5 * float(r @ r) if np.all(np.isfinite(r)) else float("inf")


class InverseJacobian:
    """Approximation ``H ≈ J⁻¹`` updated by the good-Broyden rule (eq. 4.42).

    ``H ← H + (s - H·y)·(sᵀH) / (sᵀH·y)`` is the Sherman-Morrison form of eq. 4.41
    ``B ← B + (y - B·s)·sᵀ/(sᵀs)`` with ``H = B⁻¹``: after the update ``H·y = s`` (secant
    condition) and ``H`` is unchanged on vectors orthogonal to ``sᵀH``.
    """

    def __init__(self, J: np.ndarray):
        J = np.asarray(J, dtype=float)
        if not np.all(np.isfinite(J)):
            # a differenced column crossed into points where the residual is undefined: the
            # steps are NaN, which the solver reports as a failed step (as Newton's
            # linear_solve does); the pseudo-inverse's SVD would raise instead
            self.H = np.full(J.shape, np.nan)
            return
        try:
            self.H = np.linalg.inv(J) if np.linalg.cond(J) < 1e14 else np.linalg.pinv(J)
        except np.linalg.LinAlgError:
            self.H = np.linalg.pinv(J)

    def solve(self, r: np.ndarray) -> np.ndarray:
        """``H·r`` (the Newton-like step is ``-H·r``)."""
        return self.H @ r

    def update(self, s: np.ndarray, y: np.ndarray) -> bool:
        """Apply eq. 4.42 for the step ``s`` and residual change ``y``; False (and no change)
        when the denominator ``sᵀHy`` is tiny relative to ``|s|·|Hy|``."""
        Hy = self.H @ y
        den = float(s @ Hy)
        small = DENOMINATOR_RTOL * np.linalg.norm(s) * np.linalg.norm(Hy)
        if not np.isfinite(den) or abs(den) <= small:
            return False
        self.H = self.H + np.outer(s - Hy, s @ self.H) / den
        return True


@attrs.frozen(kw_only=True)
class Broyden(FiniteDifferenceOptions, NonlinearSolver):
    """Broyden's method ``x_{k+1} = x_k - α·H_k·r(x_k)`` (equations 4.40-4.42).

    Parameters
    ----------
    relaxation : float
        Under-relaxation α in (0, 1] scaling every step (the thesis's α < 1 for stability near
        flat residuals; α < 1 makes convergence linear with ratio about 1 - α).
    difference : {"forward", "central"}
        Finite-difference scheme for the initial Jacobian and for restarts when the problem has
        no ``jacobian`` (``n`` or ``2n`` evaluations each time).
    rel_step, typical_scale : float
        Finite-difference step ``h_i = rel_step·max(|x_i|, typical_scale)``.
    restart : bool
        Recompute the Jacobian (and invert it) at the current point when the merit ``0.5|r|²``
        grew in ``restart_after`` consecutive steps, when the Sherman-Morrison denominator is
        tiny, or before declaring a stall with a stale Jacobian. Without restarts such updates
        are skipped and the old approximation is kept.
    restart_after : int
        Number of consecutive merit increases that triggers a restart.
    max_halvings : int
        A trial point whose residual is not finite is retried with half the step, at most this
        many times (then ``Status.DIVERGED``). Steps that merely increase the merit are
        accepted: Broyden has no line search.
    stall_iterations : int
        Stop with ``Status.STALLED`` when the best ``max|r|`` of the last ``stall_iterations``
        iterations is not below :data:`STALL_PROGRESS` (0.9) times the best before them
        (0: never). Without a line search, an iteration on a problem without a nearby root
        (an edge system whose contact set has no equilibrium: a contact that must detach)
        wanders or repeats a cycle of steps through its restarts until ``max_iterations``;
        MINPACK's ``hybrd`` stops in the same way ("not making good progress ... from the last
        ten iterations"). A caller with a fallback hands over at once.

    Notes
    -----
    * ``max_step`` scales the whole step ``-α·H·r`` by one common factor (the direction is
      kept). The secant update uses the step actually taken, so the secant condition holds
      whatever the scaling.
    * Cost: the initial Jacobian (0, ``n`` or ``2n`` evaluations) and then one evaluation per
      iteration, plus the Jacobian at each restart (counted in ``extras["restarts"]``).
    * Convergence is superlinear for α = 1 and a good initial Jacobian.

    Examples
    --------
    >>> import numpy as np
    >>> class P:
    ...     def residual(self, x):
    ...         return np.tanh(x - np.array([0.2, -0.4])) + 0.1 * np.sin(x[::-1])
    >>> res = Broyden(relaxation=0.8).solve(P(), np.zeros(2))
    >>> res.converged, res.status.value
    (True, 'converged')
    """

    relaxation: float = attrs.field(default=1.0, converter=float,
                                    validator=in_range(0.0, 1.0, lo_open=True))
    restart: bool = attrs.field(default=True, validator=boolean)
    restart_after: int = attrs.field(default=2, validator=int_range(1))
    max_halvings: int = attrs.field(default=10, validator=int_range(0, 60))
    stall_iterations: int = attrs.field(default=30, validator=int_range(0))

    def _solve(self, problem: NonlinearProblem, x0: np.ndarray,
               tolerances: Tolerances) -> SolverResult:
        fun = CountedResidual.of(problem, tolerances)
        fd = self.finite_difference
        x, r = x0, np.full(x0.shape, np.inf)
        history: list[float] = []
        it = restarts = skipped = 0
        status, message = Status.FAILED, ""
        try:
            r, early = first_residual(fun, x, tolerances, history)
            if early is not None:
                return early
            if max_abs(r) <= tolerances.residual:
                return result(x, r, tolerances, Status.CONVERGED, "", 0, fun.count, history)
            H = InverseJacobian(problem_jacobian(problem, fun, x, r, fd)[0])
            fresh, grew = True, 0
            while True:
                if max_abs(r) <= tolerances.residual:
                    status = Status.CONVERGED
                    break
                if it >= tolerances.max_iterations:
                    status, message = Status.MAX_ITERATIONS, f"{it} iterations"
                    break
                if self._stalled(history):
                    status = Status.STALLED
                    message = (f"no progress in {self.stall_iterations} iterations: the best "
                               f"max|r| stayed at {min(history):.3g}")
                    break
                s = -self.relaxation * H.solve(r)
                if np.all(np.isfinite(s)):
                    s, _ = limit_step(problem, x, s)
                if not np.all(np.isfinite(s)) or max_abs(s) <= tolerances.step:
                    if self.restart and not fresh:
                        H = InverseJacobian(problem_jacobian(problem, fun, x, r, fd)[0])
                        fresh, grew, restarts = True, 0, restarts + 1
                        continue
                    if np.all(np.isfinite(s)):
                        status = Status.STALLED
                        message = f"step {max_abs(s):.3g} <= tolerances.step with a fresh Jacobian"
                    else:
                        status = Status.FAILED
                        message = ("no finite step: the Jacobian is not finite (a difference "
                                   "crossed into points where the residual is undefined)"
                                   if not np.all(np.isfinite(H.H)) else "no finite step")
                    break
                xt = x + s
                rt = fun(xt)
                k = 0
                while not np.all(np.isfinite(rt)) and k < self.max_halvings:
                    k += 1
                    s = 0.5 * s
                    xt = x + s
                    rt = fun(xt)
                if not np.all(np.isfinite(rt)):
                    status, message = Status.DIVERGED, "residual became non-finite"
                    break
                updated = H.update(s, rt - r)
                skipped += not updated
                grew = grew + 1 if _merit(rt) > _merit(r) else 0
                x, r = xt, rt
                it += 1
                history.append(max_abs(r))
                fresh = False
                if (self.restart and max_abs(r) > tolerances.residual
                        and (not updated or grew >= self.restart_after)):
                    H = InverseJacobian(problem_jacobian(problem, fun, x, r, fd)[0])
                    fresh, grew, restarts = True, 0, restarts + 1
        except BudgetExhausted:
            status, message = fun.stop
        return result(x, r, tolerances, status, message, it, fun.count, history,
                      restarts=restarts, skipped_updates=skipped)

    def _stalled(self, history: list[float]) -> bool:
        """Whether the last ``stall_iterations`` entries of ``history`` (max|r| per iteration,
        the start first) made no progress against the best before them."""
        n = self.stall_iterations
        if n == 0 or len(history) <= n:
            return False
        return min(history[-n:]) >= STALL_PROGRESS * min(history[:-n])
