"""Nonlinear conjugate gradients on a merit function (thesis §4.5.3, equations 4.43-4.45)."""
from __future__ import annotations

import warnings

import attrs
import numpy as np
from scipy.optimize import line_search as _scipy_line_search

from .._validation import in_range, int_range, one_of, positive
from ..errors import ValidationError
from ._fd import (FiniteDifferenceOptions, DIFFERENCES, BudgetExhausted, CountedResidual, FiniteDifference, max_abs,
                  result, step_bound)
from .base import NonlinearProblem, NonlinearSolver, SolverResult, Status, Tolerances, optional

__all__ = ["NonlinearCG"]

BETAS = ("polak-ribiere", "fletcher-reeves")
LINE_SEARCHES = ("armijo", "wolfe")
GRADIENTS = ("least-squares", "residual")
PRECONDITIONERS = ("jacobi", "none")
WEIGHTINGS = ("diagonal", "none")


class _Point:
    """Residual (and lazily the Jacobian and problem merit) at one point."""

    __slots__ = ("x", "r", "J", "merit")

    def __init__(self, x, r):
        self.x, self.r, self.J, self.merit = x, r, None, None


class _Objective:
    """The merit ``f(x)`` and its gradient, with a small cache keyed by x (so that the Wolfe
    search, which asks for values and gradients at the same points, pays each only once).

    Least-squares mode: ``f = 0.5·|w∘r|²`` (or ``problem.merit``), gradient ``Jᵀ(w²∘r)``;
    residual mode: ``f = problem.merit``, gradient ``r``.
    """

    def __init__(self, problem, fun: CountedResidual, fd: FiniteDifference, mode: str):
        self.problem, self.fun, self.fd, self.mode = problem, fun, fd, mode
        self.merit_fn = optional(problem, "merit")
        self.jac_fn = optional(problem, "jacobian")
        self.weights: np.ndarray | None = None
        self.merit_calls = 0
        self.jacobians = 0
        self._cache: dict[bytes, _Point] = {}

    def point(self, x: np.ndarray) -> _Point:
        key = np.asarray(x, dtype=float).tobytes()
        p = self._cache.get(key)
        if p is None:
            x = np.array(x, dtype=float)
            p = _Point(x, self.fun(x))
            if len(self._cache) > 8:
                self._cache.clear()
            self._cache[key] = p
        return p

    def f(self, p: _Point) -> float:
        if not np.all(np.isfinite(p.r)):
            return float("inf")
        if self.merit_fn is not None:
            if p.merit is None:
                self.merit_calls += 1
                p.merit = float(self.merit_fn(p.x.copy()))
            value = p.merit
        else:
            wr = p.r if self.weights is None else self.weights * p.r
            value = 0.5 * float(wr @ wr)
        return value if np.isfinite(value) else float("inf")

    def jacobian(self, p: _Point) -> np.ndarray:
        if p.J is None:
            if self.jac_fn is not None:
                p.J = np.asarray(self.jac_fn(p.x.copy()), dtype=float).reshape(p.x.size, -1)
            else:
                p.J, _ = self.fd.jacobian(self.fun, p.x, p.r)
            self.jacobians += 1
        return p.J

    def gradient(self, p: _Point) -> np.ndarray:
        if self.mode == "residual":
            return p.r.copy()
        w2r = p.r if self.weights is None else self.weights**2 * p.r
        return self.jacobian(p).T @ w2r

    def reweight(self, p: _Point) -> None:
        """``w_i = 1/|J_ii|`` at p (floored at 1e-8·max|J_ii|); only for the default merit."""
        if self.mode == "residual" or self.merit_fn is not None:
            return
        d = np.abs(np.diag(self.jacobian(p)))
        top = float(np.max(d)) if d.size else 0.0
        if not np.isfinite(top) or top == 0.0:
            self.weights = None
            return
        self.weights = 1.0 / np.maximum(d, 1e-8 * top)
        self.weights /= float(np.max(self.weights))


def _largest_step(bound: np.ndarray, d: np.ndarray) -> float:
    """Largest α with ``|α·d_i| <= bound_i`` for all i (inf when nothing bounds it)."""
    active = (d != 0) & np.isfinite(bound)
    if not np.any(active):
        return float("inf") if np.any(d != 0) else 0.0
    with np.errstate(over="ignore"):
        return float(np.min(bound[active] / np.abs(d[active])))


@attrs.frozen(kw_only=True)
class NonlinearCG(FiniteDifferenceOptions, NonlinearSolver):
    """Nonlinear conjugate gradients minimising a merit function whose minimum is the root.

    Parameters
    ----------
    beta : {"polak-ribiere", "fletcher-reeves"}
        ``β_k`` of eq. 4.44 (used as PR+, ``max(β, 0)``) or eq. 4.43 (with the preconditioned
        gradient ``z`` in place of g: ``β = zᵀ(g - g_old)/z_oldᵀg_old``).
    line_search : {"armijo", "wolfe"}
        Backtracking with safeguarded quadratic interpolation until the Armijo condition
        ``f(x + αd) <= f(x) + c1·α·gᵀd`` holds, or a strong-Wolfe search
        (:func:`scipy.optimize.line_search`, curvature constant ``curvature``) falling back to
        Armijo when it fails. Wolfe needs the gradient at trial points: with finite differences
        that is ``n`` (or ``2n``) more evaluations per trial.
    gradient : {"least-squares", "residual"}
        ``"least-squares"``: the merit is the sum of squares of eq. 4.45 (see ``weighting``;
        ``problem.merit`` instead when the problem has one, assumed to be a scaled sum of
        squares) with gradient ``Jᵀr``; J is analytic or by finite differences at *every*
        iteration (``n``/``2n`` evaluations). ``"residual"``: r is the gradient of
        ``problem.merit`` (an energy whose stationary point is sought, the thesis's elastic
        case of §4.5.3); no Jacobian is needed and the problem must have ``merit``.
    weighting : {"diagonal", "none"}
        For the default merit: ``"none"`` is eq. 4.45, ``0.5·Σ r_i²``; ``"diagonal"`` minimises
        ``0.5·Σ (r_i/|J_ii|)²`` (weights refreshed at every steepest-descent restart), so that
        unknowns whose residuals have very different scales count alike. Same roots; equal to
        eq. 4.45 up to a factor when all ``|J_ii|`` are equal.
    preconditioner : {"jacobi", "none"}
        ``"jacobi"`` divides the gradient by ``diag(JᵀJ)`` (least-squares mode only): on the
        strongly diagonal edge systems this removes the scale differences between unknowns.
    restart_every : int
        Steepest-descent restart every this many iterations; 0 means the number of unknowns.
        A direction that is not a descent direction (``gᵀd >= 0``) is also replaced by the
        steepest descent, and so is one along which the line search fails or moves no unknown
        by more than ``tolerances.step``; failing along the steepest descent too stops with
        ``Status.STALLED``.
    armijo, curvature : float
        Line-search constants ``0 < c1 < c2 < 1`` (``c1 < 0.5``).
    max_backtracks : int
        Merit evaluations allowed per Armijo search.
    difference, rel_step, typical_scale
        Finite-difference Jacobian options (see :class:`~viscocontact.solvers.Newton`).

    Notes
    -----
    * ``max_step`` caps the step length: ``α <= min_i max_step_i/|d_i|``, a common factor on
      the whole step (trial points of the line search included).
    * The first trial step is the Gauss-Newton minimiser along d, ``α0 = -gᵀd/|Ŵ J d|²``
      (least squares), or ``α_{k-1}·g_{k-1}ᵀd_{k-1}/g_kᵀd_k`` (residual mode;
      ``1/max(max|d|, 1)`` at the first iteration).
    * Cost per iteration in least-squares mode: one Jacobian (0, ``n`` or ``2n`` evaluations)
      plus the line-search trials (usually 1-3): nonlinear CG needs more evaluations than
      Newton on these small systems; it is here for the thesis's comparison and for energy
      minimisation (``gradient="residual"``), where it needs no Jacobian at all.
    * Converged means ``max|r| <= tolerances.residual``, never a small gradient; a stationary
      point of the merit that is not a root ends with ``Status.STALLED``. For a non-singular J
      the only stationary points of ``0.5|r|²`` are roots, whether J is symmetric or not.

    Examples
    --------
    >>> import numpy as np
    >>> class P:
    ...     def residual(self, x):
    ...         return np.array([[3.0, 1.0], [-1.0, 2.0]]) @ x - np.array([1.0, 2.0])
    >>> res = NonlinearCG().solve(P(), np.zeros(2))
    >>> res.converged, np.round(res.x, 8).tolist()
    (True, [0.0, 1.0])
    """

    beta: str = attrs.field(default="polak-ribiere", validator=one_of(BETAS))
    line_search: str = attrs.field(default="armijo", validator=one_of(LINE_SEARCHES))
    gradient: str = attrs.field(default="least-squares", validator=one_of(GRADIENTS))
    weighting: str = attrs.field(default="none", validator=one_of(WEIGHTINGS))
    preconditioner: str = attrs.field(default="jacobi", validator=one_of(PRECONDITIONERS))
    restart_every: int = attrs.field(default=0, validator=int_range(0))
    armijo: float = attrs.field(default=1e-4, converter=float,
                                validator=in_range(0.0, 0.5, lo_open=True, hi_open=True))
    curvature: float = attrs.field(default=0.1, converter=float,
                                   validator=in_range(0.0, 1.0, lo_open=True, hi_open=True))
    max_backtracks: int = attrs.field(default=20, validator=int_range(1))

    @curvature.validator
    def _curvature_above_armijo(self, attribute, value):
        if value <= self.armijo:
            in_range(self.armijo, 1.0, lo_open=True, hi_open=True)(self, attribute, value)

    # ---- pieces of one iteration -------------------------------------------------------
    def _precondition(self, obj: _Objective, p: _Point, g: np.ndarray) -> np.ndarray:
        if self.preconditioner == "none" or obj.mode == "residual":
            return g
        J = obj.jacobian(p)
        if obj.weights is not None:
            J = obj.weights[:, None] * J
        m = np.einsum("ij,ij->j", J, J)
        top = float(np.max(m)) if m.size else 0.0
        if not np.isfinite(top) or top <= 0.0:
            return g
        return g / np.maximum(m, 1e-30 * top)

    def _beta(self, g, z, g_old, z_old) -> float:
        den = float(z_old @ g_old)
        if den <= 0 or not np.isfinite(den):
            return 0.0
        if self.beta == "fletcher-reeves":
            return float(z @ g) / den
        return max(float(z @ (g - g_old)) / den, 0.0)

    def _first_trial(self, obj: _Objective, p: _Point, d, slope, memory) -> float:
        if obj.mode == "least-squares" and obj.merit_fn is None:
            Jd = obj.jacobian(p) @ d
            if obj.weights is not None:
                Jd = obj.weights * Jd
            nrm = float(Jd @ Jd)
            if nrm > 0 and np.isfinite(nrm):
                return -slope / nrm
        if memory is not None:
            a_old, slope_old = memory
            return a_old * slope_old / slope
        return 1.0 / max(max_abs(d), 1.0)  # first step no longer than 1 in every unknown

    def _armijo(self, obj: _Objective, p: _Point, f0, d, slope, alpha, alpha_max):
        """Backtracking with safeguarded quadratic interpolation: the accepted point or None."""
        alpha = min(alpha, alpha_max)
        for _ in range(self.max_backtracks):
            q = obj.point(p.x + alpha * d)
            fq = obj.f(q)
            if fq <= f0 + self.armijo * alpha * slope:
                return q, alpha
            if np.isfinite(fq):
                denom = 2.0 * (fq - f0 - slope * alpha)
                trial = -slope * alpha * alpha / denom if denom > 0 else 0.5 * alpha
                alpha = min(max(trial, 0.1 * alpha), 0.5 * alpha)
            else:
                alpha *= 0.1
        return None, alpha

    def _wolfe(self, obj: _Objective, p: _Point, f0, d, alpha, alpha_max):
        """Strong-Wolfe search by scipy on ``φ(t) = f(x + t·α·d)`` (first trial t = 1)."""
        alpha = min(alpha, alpha_max)
        pk = alpha * d
        amax = alpha_max / alpha if np.isfinite(alpha_max) else None
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t = _scipy_line_search(lambda x: obj.f(obj.point(x)),
                                   lambda x: obj.gradient(obj.point(x)),
                                   p.x, pk, gfk=obj.gradient(p), old_fval=f0,
                                   c1=self.armijo, c2=self.curvature, amax=amax, maxiter=10)[0]
        if t is None or not np.isfinite(t) or t <= 0:
            return None, alpha
        q = obj.point(p.x + t * pk)
        if not obj.f(q) < f0:
            return None, alpha
        return q, t * alpha

    def _line_search(self, obj, p, d, slope, alpha0, alpha_max):
        f0 = obj.f(p)
        q, alpha = None, alpha0
        if self.line_search == "wolfe":
            q, alpha = self._wolfe(obj, p, f0, d, alpha0, alpha_max)
        if q is None:
            q, alpha = self._armijo(obj, p, f0, d, slope, alpha0, alpha_max)
        return q, alpha

    # ---- the loop ----------------------------------------------------------------------
    def _solve(self, problem: NonlinearProblem, x0: np.ndarray,
               tolerances: Tolerances) -> SolverResult:
        if self.gradient == "residual" and optional(problem, "merit") is None:
            raise ValidationError("NonlinearCG.gradient", self.gradient,
                                  "'least-squares' for a problem without merit(x)")
        fun = CountedResidual.of(problem, tolerances)
        obj = _Objective(problem, fun, self.finite_difference, self.gradient)
        restart_every = self.restart_every or x0.size
        x, r = x0, np.full(x0.shape, np.inf)
        history: list[float] = []
        it = restarts = 0
        status, message = Status.FAILED, ""
        try:
            p = obj.point(x0)
            x, r = p.x, p.r
            history.append(max_abs(r))
            if not np.isfinite(obj.f(p)):
                return result(x, r, tolerances, Status.FAILED,
                              "residual or merit at x0 is not finite", 0, fun.count, history)
            d = g_old = z_old = memory = None
            since_restart = 0
            while True:
                if max_abs(p.r) <= tolerances.residual:
                    status = Status.CONVERGED
                    break
                if it >= tolerances.max_iterations:
                    status, message = Status.MAX_ITERATIONS, f"{it} iterations"
                    break
                steepest = d is None or since_restart >= restart_every
                if steepest and self.weighting == "diagonal":
                    obj.reweight(p)
                g = obj.gradient(p)
                if not np.any(g) or not np.all(np.isfinite(g)):
                    status = Status.STALLED
                    message = "zero or non-finite merit gradient at a point that is not a root"
                    break
                z = self._precondition(obj, p, g)
                if not steepest:
                    assert d is not None  # steepest is set while there is no direction yet
                    d = -z + self._beta(g, z, g_old, z_old) * d
                    steepest = not float(g @ d) < 0.0
                bound = step_bound(problem, p.x)
                for _attempt in ("conjugate", "steepest"):
                    if steepest:
                        d = -z
                        since_restart = 0
                        restarts += 1
                    assert d is not None  # set above, or by the steepest descent
                    alpha_max = _largest_step(bound, d)
                    slope = float(g @ d)
                    q, alpha = self._line_search(
                        obj, p, d, slope,
                        self._first_trial(obj, p, d, slope, memory),
                        alpha_max)
                    if q is not None and max_abs(q.x - p.x) <= tolerances.step:
                        q = None  # a negligible step is no progress either
                    if q is not None or steepest:
                        break
                    steepest = True  # the line search failed along d: retry along -z
                if q is None:
                    status = Status.STALLED
                    message = ("line search found no decrease of the merit larger than "
                               "tolerances.step along the steepest descent")
                    break
                memory = (alpha, slope)
                g_old, z_old = g, z
                p = q
                x, r = p.x, p.r
                it += 1
                since_restart += 1
                history.append(max_abs(r))
        except BudgetExhausted:
            status, message = fun.stop
        return result(x, r, tolerances, status, message, it, fun.count, history,
                      jacobians=obj.jacobians, steepest_descent_steps=restarts,
                      merit_evaluations=obj.merit_calls)
