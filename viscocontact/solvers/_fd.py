"""Machinery shared by the built-in solvers: finite-difference Jacobians, counted evaluations,
step limits.

Nothing here knows about a particular method; each solver module holds only its own loop.

* :class:`FiniteDifference` — forward (eq. 4.49) or central (eq. 4.50) Jacobian with the step
  ``h_i = rel_step·max(|x_i|, typical_scale)``; returns ``(J, evaluations)``.
* :class:`CountedResidual` — wraps ``problem.residual``: counts every call, enforces
  ``Tolerances.max_evaluations`` (raising :class:`BudgetExhausted` *before* a call that would
  exceed it) and never catches what ``residual`` raises.
* :func:`limit_step` — scale a step by one common factor so that ``|Δx_i| <= max_step_i``;
  :func:`step_bound` — ``max_step(x)`` or inf.
* :func:`problem_jacobian` — ``problem.jacobian`` when present, else finite differences through
  the counted residual; :func:`linear_solve` — ``J⁻¹b`` with a least-squares fallback.
* :func:`result` — the :class:`SolverResult`, with ``converged`` derived from ``max|r| <= tol``
  only (a loop cannot claim convergence by mistake).
"""
from __future__ import annotations

from typing import Callable

import attrs
import numpy as np

from .._validation import _name, one_of, positive
from ..errors import ValidationError
from .base import NonlinearProblem, SolverResult, Status, Tolerances, optional

__all__ = ["BudgetExhausted", "CountedResidual", "FiniteDifference", "boolean", "fd_jacobian",
           "limit_step", "linear_solve", "max_abs", "problem_jacobian", "result", "step_bound"]

DIFFERENCES = ("forward", "central")


def boolean(inst, attribute, value):
    """Validator: exactly True or False (not 0/1 or "yes")."""
    if not isinstance(value, (bool, np.bool_)):
        raise ValidationError(_name(inst, attribute), value, "True or False")


@attrs.frozen(kw_only=True)
class FiniteDifference:
    """Finite-difference approximation of the Jacobian ``J_ij = ∂r_i/∂x_j`` (thesis §4.5.5).

    Parameters
    ----------
    scheme : {"forward", "central"}
        ``"forward"`` (eq. 4.49, first order, ``n`` evaluations besides ``r(x)``) or
        ``"central"`` (eq. 4.50, second order, ``2n`` evaluations).
    rel_step : float
        Relative step: ``h_i = rel_step·max(|x_i|, typical_scale)``. About ``√ε ≈ 1e-8`` is
        optimal for forward differences and ``ε^(1/3) ≈ 6e-6`` for central ones on a residual
        computed to machine precision; use larger steps for noisy residuals.
    typical_scale : float
        Magnitude below which ``|x_i|`` is not trusted to set the step (so that ``x_i = 0`` still
        gets ``h_i = rel_step·typical_scale``), in the units of x.

    Examples
    --------
    >>> import numpy as np
    >>> fd = FiniteDifference(scheme="central", rel_step=1e-5)
    >>> J, n = fd.jacobian(lambda x: np.array([x[0]**2, x[0]*x[1]]), np.array([1.0, 2.0]))
    >>> np.round(J, 6).tolist(), n
    ([[2.0, 0.0], [2.0, 1.0]], 4)
    """

    scheme: str = attrs.field(default="forward", validator=one_of(DIFFERENCES))
    rel_step: float = attrs.field(default=1e-7, converter=float, validator=positive)
    typical_scale: float = attrs.field(default=1.0, converter=float, validator=positive)

    def steps(self, x: np.ndarray) -> np.ndarray:
        """The steps ``h_i``, rounded so that ``x_i + h_i`` is exact in floating point."""
        x = np.asarray(x, dtype=float)
        h = self.rel_step * np.maximum(np.abs(x), self.typical_scale)
        return (x + h) - x

    def jacobian(self, fun: Callable[[np.ndarray], np.ndarray], x: np.ndarray,
                 f0: np.ndarray | None = None) -> tuple[np.ndarray, int]:
        """``(J, evaluations)``; ``f0 = fun(x)`` is reused by the forward scheme when given.

        Exceptions raised by ``fun`` propagate unchanged.
        """
        x = np.asarray(x, dtype=float)
        h = self.steps(x)
        n = x.size
        count = 0
        if self.scheme == "forward" and f0 is None:
            f0 = np.asarray(fun(x.copy()), dtype=float)
            count += 1
        columns = []
        for j in range(n):
            xp = x.copy()
            xp[j] += h[j]
            fp = np.asarray(fun(xp), dtype=float)
            count += 1
            if self.scheme == "forward":
                columns.append((fp - f0) / h[j])
            else:
                xm = x.copy()
                xm[j] -= h[j]
                fm = np.asarray(fun(xm), dtype=float)
                count += 1
                columns.append((fp - fm) / (2.0 * h[j]))
        return np.column_stack(columns) if columns else np.zeros((0, 0)), count


def fd_jacobian(fun, x, f0=None, *, scheme: str = "forward", rel_step: float = 1e-7,
                typical_scale: float = 1.0) -> tuple[np.ndarray, int]:
    """Functional form of :meth:`FiniteDifference.jacobian`."""
    return FiniteDifference(scheme=scheme, rel_step=rel_step,
                            typical_scale=typical_scale).jacobian(fun, x, f0)


class BudgetExhausted(Exception):
    """Raised by :class:`CountedResidual` instead of a call beyond ``max_evaluations`` (or past a
    ``probation`` without progress); :attr:`CountedResidual.stop` says which.

    Solvers catch this class only; it never comes from a problem's ``residual``.
    """


class CountedResidual:
    """``problem.residual`` with a call counter, an evaluation budget and the progress rule of
    :attr:`Tolerances.probation`.

    Calling it returns a float array (a copy of ``x`` is passed, so the problem may keep it).
    Once it has raised :class:`BudgetExhausted`, :attr:`stop` is the ``(status, message)`` the
    solver reports.
    """

    def __init__(self, problem: NonlinearProblem, budget: int, probation: int = 0,
                 progress: float = 1e-2, pace: tuple[float, ...] = ()):
        self._residual = problem.residual
        self.budget = budget
        self.probation = probation
        self.progress = progress
        self.pace = tuple(pace) if probation else ()
        self.count = 0
        self._first = np.inf          # max|r| of the first call
        self._best = np.inf           # smallest max|r| of the calls after it
        self.stop: tuple[Status, str] = (Status.MAX_EVALUATIONS, "")

    @classmethod
    def of(cls, problem: NonlinearProblem, tolerances: Tolerances) -> "CountedResidual":
        """The counter for a solve under ``tolerances``."""
        return cls(problem, tolerances.max_evaluations, tolerances.probation, tolerances.progress,
                   tolerances.pace)

    def __call__(self, x: np.ndarray) -> np.ndarray:
        if self.count >= self.budget:
            self.stop = (Status.MAX_EVALUATIONS, f"{self.count} residual evaluations")
            raise BudgetExhausted
        if (self.probation and self.count == self.probation + 1
                and not self._best <= self.progress * self._first):
            self.stop = (Status.STALLED,
                         f"no progress in {self.probation} residual evaluations: max|r| "
                         f"{self._first:.3g} at the start, at best {self._best:.3g} since")
            raise BudgetExhausted
        j = self.count - 1                    # evaluations past the first so far
        if 1 <= j <= len(self.pace) and not self._best <= self.pace[j - 1] * self._first:
            self.stop = (Status.STALLED,
                         f"too little progress in {j} residual evaluation(s): max|r| "
                         f"{self._first:.3g} at the start, at best {self._best:.3g} since "
                         f"(pace {self.pace[j - 1]:g})")
            raise BudgetExhausted
        self.count += 1
        r = np.asarray(self._residual(np.array(x, dtype=float)), dtype=float).reshape(-1)
        if self.probation and self.count <= self.probation + 1:
            if self.count == 1:
                self._first = max_abs(r)
            else:
                self._best = min(self._best, max_abs(r))
        return r


def max_abs(v: np.ndarray) -> float:
    """``max_i |v_i|`` (0 for an empty array, inf when v has NaN)."""
    v = np.asarray(v, dtype=float)
    if v.size == 0:
        return 0.0
    if not np.all(np.isfinite(v)):
        return float("inf")
    return float(np.max(np.abs(v)))


def limit_step(problem: NonlinearProblem, x: np.ndarray,
               dx: np.ndarray) -> tuple[np.ndarray, float]:
    """Scale ``dx`` by one common factor ``t <= 1`` so that ``|t·dx_i| <= max_step(x)_i``.

    A common factor keeps the direction (a descent direction stays one). Returns
    ``(t·dx, t)``; without ``problem.max_step`` the step is returned unchanged.
    """
    bound_fn = optional(problem, "max_step")
    if bound_fn is None:
        return dx, 1.0
    bound = np.broadcast_to(np.asarray(bound_fn(np.array(x, dtype=float)), dtype=float), dx.shape)
    big = np.abs(dx) > bound
    if not np.any(big):
        return dx, 1.0
    t = float(np.min(bound[big] / np.abs(dx[big])))
    return dx * t, t


def step_bound(problem: NonlinearProblem, x: np.ndarray) -> np.ndarray:
    """``max_step(x)`` as an array (inf when the problem has none)."""
    bound_fn = optional(problem, "max_step")
    if bound_fn is None:
        return np.full(np.shape(x), np.inf)
    return np.broadcast_to(np.asarray(bound_fn(np.array(x, dtype=float)), dtype=float),
                           np.shape(x)).copy()


def problem_jacobian(problem: NonlinearProblem, fun: CountedResidual, x: np.ndarray,
                     r: np.ndarray, fd: FiniteDifference) -> tuple[np.ndarray, bool]:
    """``(J, analytic)``: ``problem.jacobian(x)`` when it exists, else finite differences
    through the counted residual ``fun`` (its counter records the cost)."""
    jac = optional(problem, "jacobian")
    if jac is not None:
        J = np.asarray(jac(np.array(x, dtype=float)), dtype=float)
        return J.reshape(x.size, x.size), True
    J, _ = fd.jacobian(fun, x, r)
    return J, False


def linear_solve(J: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``J⁻¹b``; least squares (minimum norm) when J is singular or ill-conditioned; NaN when
    J is not finite (a differenced column crossed into points where the residual is undefined),
    which the solvers report as a failed step."""
    if not (np.all(np.isfinite(J)) and np.all(np.isfinite(b))):
        return np.full(np.shape(b), np.nan)
    try:
        if np.linalg.cond(J) < 1e14:
            return np.linalg.solve(J, b)
    except np.linalg.LinAlgError:
        pass
    return np.linalg.lstsq(J, b, rcond=None)[0]


def result(x: np.ndarray, r: np.ndarray, tolerances: Tolerances, status: Status, message: str,
           iterations: int, evaluations: int, history: list, **extras) -> SolverResult:
    """Build a :class:`SolverResult`; ``converged`` is derived from ``max|r| <= tol`` only."""
    converged = max_abs(r) <= tolerances.residual
    if converged:
        status, message = Status.CONVERGED, message or "max|r| <= tolerances.residual"
    elif status is Status.CONVERGED:  # never claim convergence the residual does not show
        status = Status.FAILED
        message = f"internal error: claimed convergence with max|r| = {max_abs(r):.3g}"
    return SolverResult(x=np.array(x, dtype=float), residual=np.array(r, dtype=float),
                        converged=converged, status=status, message=message,
                        iterations=iterations, function_evaluations=evaluations,
                        residual_history=tuple(float(h) for h in history), extras=dict(extras))


def first_residual(fun: "CountedResidual", x: np.ndarray, tolerances: Tolerances,
                   history: list) -> tuple[np.ndarray, "SolverResult | None"]:
    """Evaluate the residual at the starting point, record it, and return ``(r, early)``; ``early``
    is the failed result every solver returns when that residual is not finite."""
    r = fun(x)
    history.append(max_abs(r))
    if not np.all(np.isfinite(r)):
        return r, result(x, r, tolerances, Status.FAILED, "residual at x0 is not finite",
                         0, fun.count, history)
    return r, None


@attrs.frozen(kw_only=True)
class FiniteDifferenceOptions:
    """The finite-difference options shared by the Jacobian-based solvers (eqs. 4.49-4.50).

    Parameters
    ----------
    difference : {"forward", "central"}
        Scheme of the finite-difference Jacobian.
    rel_step : float
        Step relative to ``max(|x_i|, typical_scale)``.
    typical_scale : float
        Size of an unknown near zero.
    """

    difference: str = attrs.field(default="forward", validator=one_of(DIFFERENCES))
    rel_step: float = attrs.field(default=1e-7, converter=float, validator=positive)
    typical_scale: float = attrs.field(default=1.0, converter=float, validator=positive)

    @property
    def finite_difference(self) -> FiniteDifference:
        return FiniteDifference(scheme=self.difference, rel_step=self.rel_step,
                                typical_scale=self.typical_scale)
