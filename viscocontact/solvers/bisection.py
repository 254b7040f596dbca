"""Component-wise bisection on the edge residuals (thesis §4.5.4)."""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import in_range, int_range, positive
from ._fd import (BudgetExhausted, CountedResidual, FiniteDifference, first_residual,
                  linear_solve, max_abs, problem_jacobian, result, step_bound)
from .base import NonlinearProblem, NonlinearSolver, SolverResult, Status, Tolerances, optional

__all__ = ["Bisection"]


@attrs.frozen(kw_only=True)
class Bisection(NonlinearSolver):
    """Move every unknown by ``±s_i`` against the sign of its own residual; halve ``s_i`` once
    the sign flips (thesis §4.5.4).

    Each iteration updates all unknowns together and costs one residual evaluation:

    * an unknown with ``|r_i| <= tolerances.residual`` does not move;
    * otherwise ``Δx_i = -orientation_i·sign(r_i)·s_i``, with ``orientation()`` the sign of
      ``∂r_i/∂x_i`` (+1 when the problem has no ``orientation``); for a contact edge the
      residual is the edge pressure and the move is toward the zero-pressure point;
    * when ``r_i`` changes sign the root is bracketed: ``s_i ← shrink·s_i``; inside a bracket
      ``s_i`` keeps shrinking every iteration, which with ``shrink = 0.5`` is exactly bisection
      of the bracket (the current point is always one of its ends);
    * before a bracket is found ``s_i ← growth·s_i`` after each move (``growth = 1``: the
      thesis's fixed step ``δX``; 2 gives an expanding bracket search);
    * because the other unknowns move too, the root of ``r_i`` may leave its bracket: after
      ``patience`` consecutive moves in one direction inside a bracket the bracket is forgotten
      and the lost root is chased with ``s_i`` growing by ``1/shrink`` per move up to
      ``initial_step`` (and by ``growth`` beyond) until the sign flips again.

    Parameters
    ----------
    initial_step : float
        ``s_i`` at the start, in the units of x (thesis's ``δX̃``).
    shrink : float
        Factor in (0, 1) applied to ``s_i`` at a sign change and inside a bracket.
    growth : float
        Factor >= 1 applied to ``s_i`` after a move that found no bracket.
    patience : int
        Consecutive same-direction moves after which a bracket is abandoned.
    newton_below : float
        Finish with Newton steps (0: never, the thesis's march). Once ``max|r|`` is below this
        fraction of the largest ``max|r|`` of the march, the march tries ``Δx = -J⁻¹r`` with
        the problem's Jacobian (``jacobian(x)``, else forward differences through the counted
        residual), bounded by ``max_step``. The step is taken when ``max|r|`` falls at least
        tenfold there, and Newton goes on from the new point; otherwise the point is left and the
        march continues by bisection without trying Newton again. Bisection gains one bit per
        evaluation; this close to a root Newton gains digits in each and lands on the root the
        march is closing in on.

    Notes
    -----
    * ``max_step`` clips every ``|Δx_i|`` separately (component-wise), as the components are
      independent here.
    * Stops with ``Status.STALLED`` when ``s_i < tolerances.step`` for every unknown that is not
      yet converged. Convergence is linear (one bit per iteration once bracketed) but needs
      neither Jacobian nor merit; ``newton_below`` makes the end quadratic where the problem has
      a Jacobian (with forward differences it costs ``n`` evaluations a step).
    * A Newton step is one iteration; the result's ``extras["newton_steps"]`` counts them.

    Examples
    --------
    >>> import numpy as np
    >>> class Edges:          # r_i decreases with x_i: orientation -1
    ...     def residual(self, x):
    ...         return np.array([0.05, 0.12]) - x
    ...     def orientation(self):
    ...         return np.array([-1.0, -1.0])
    >>> res = Bisection(initial_step=0.02).solve(Edges(), np.zeros(2))
    >>> res.converged, np.round(res.x, 8).tolist()
    (True, [0.05, 0.12])
    """

    initial_step: float = attrs.field(default=1e-2, converter=float, validator=positive)
    shrink: float = attrs.field(default=0.5, converter=float,
                                validator=in_range(0.0, 1.0, lo_open=True, hi_open=True))
    growth: float = attrs.field(default=1.0, converter=float, validator=in_range(1.0, 10.0))
    patience: int = attrs.field(default=3, validator=int_range(1))
    newton_below: float = attrs.field(default=0.0, converter=float,
                                      validator=in_range(0.0, 1.0, hi_open=True))

    def _solve(self, problem: NonlinearProblem, x0: np.ndarray,
               tolerances: Tolerances) -> SolverResult:
        fun = CountedResidual.of(problem, tolerances)
        n = x0.size
        orient_fn = optional(problem, "orientation")
        orient = np.ones(n) if orient_fn is None else np.sign(
            np.broadcast_to(np.asarray(orient_fn(), dtype=float), (n,)))
        orient = np.where(orient == 0, 1.0, orient)
        s = np.full(n, self.initial_step)
        bracketed = np.zeros(n, dtype=bool)
        lost = np.zeros(n, dtype=bool)
        run = np.zeros(n, dtype=int)
        x, r = x0, np.full(x0.shape, np.inf)
        history: list[float] = []
        it = rejected = newton = 0
        try_newton = self.newton_below > 0
        status, message = Status.FAILED, ""
        tol = tolerances.residual
        try:
            r, early = first_residual(fun, x, tolerances, history)
            if early is not None:
                return early
            while True:
                if max_abs(r) <= tol:
                    status = Status.CONVERGED
                    break
                if it >= tolerances.max_iterations:
                    status, message = Status.MAX_ITERATIONS, f"{it} iterations"
                    break
                active = np.abs(r) > tol
                if try_newton and max_abs(r) <= self.newton_below * max(history):
                    step = self._newton(problem, fun, x, r)
                    if step is None:
                        try_newton = False
                    else:
                        x, r = step
                        it += 1
                        newton += 1
                        history.append(max_abs(r))
                        continue
                if np.all(s[active] < tolerances.step):
                    status = Status.STALLED
                    message = f"every active step below tolerances.step = {tolerances.step:g}"
                    break
                dx = np.where(active, -orient * np.sign(r) * s, 0.0)
                bound = step_bound(problem, x)
                dx = np.clip(dx, -bound, bound)
                xt = x + dx
                rt = fun(xt)
                if not np.all(np.isfinite(rt)):  # too far: shrink the moving steps, retry
                    s[active] *= self.shrink
                    rejected += 1
                    continue
                flip = active & (np.sign(rt) * np.sign(r) < 0)
                inside = active & bracketed & ~flip
                searching = active & ~bracketed & ~flip
                run[inside] += 1
                leave = inside & (run >= self.patience)
                s[flip] *= self.shrink
                s[inside & ~leave] *= self.shrink
                # a lost root is chased with steps growing by 1/shrink up to initial_step
                chase = searching & lost
                s[chase] = np.maximum(np.minimum(s[chase] / self.shrink, self.initial_step),
                                      s[chase] * self.growth)
                s[searching & ~lost] *= self.growth
                bracketed[flip] = True
                bracketed[leave] = False
                lost[flip] = False
                lost[leave] = True
                run[flip | leave] = 0
                x, r = xt, rt
                it += 1
                history.append(max_abs(r))
        except BudgetExhausted:
            status, message = fun.stop
        return result(x, r, tolerances, status, message, it, fun.count, history,
                      steps=s.copy(), bracketed=bracketed.copy(), rejected=rejected,
                      newton_steps=newton)

    @staticmethod
    def _newton(problem: NonlinearProblem, fun: CountedResidual, x: np.ndarray,
                r: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
        """``(x + Δx, r(x + Δx))`` of one Newton step, or None when it is not finite, exceeds
        ``max_step`` or does not reduce ``max|r|`` tenfold (see ``newton_below``)."""
        J, _ = problem_jacobian(problem, fun, x, r, FiniteDifference())
        dx = linear_solve(J, -r)
        if not (np.all(np.isfinite(dx)) and np.all(np.abs(dx) <= step_bound(problem, x))):
            return None
        xt = x + dx
        rt = fun(xt)
        if not max_abs(rt) <= 0.1 * max_abs(r):
            return None
        return xt, rt
