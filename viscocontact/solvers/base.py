"""The :class:`NonlinearSolver` interface: solvers of ``f(x) = 0`` that know no contact physics.

Contract for implementers
-------------------------
1. Subclass :class:`NonlinearSolver` as a frozen attrs class (options are validated fields) and
   implement :meth:`NonlinearSolver._solve`, returning a :class:`SolverResult`.
2. Use only the :class:`NonlinearProblem` protocol: ``residual(x)`` always; ``jacobian(x)``,
   ``merit(x)``, ``orientation()`` and ``max_step(x)`` when the problem has them (``hasattr``);
   otherwise fall back to finite differences, ``0.5·|r|²``, ``+1`` and ``inf``.
3. Never swallow exceptions raised by ``residual``: the orchestrator uses them (for instance to
   change the number of unknowns when contacts merge) and restarts the solver.
4. Stop with ``converged=True`` only when ``max|r| <= tolerances.residual``; otherwise report the
   reason in ``status``/``message``. Count every call of ``residual`` in ``function_evaluations``.
   ``tolerances.probation`` and ``tolerances.pace`` (stop early without progress) may be
   honoured or ignored: a solve that ignores them costs its caller evaluations, not
   correctness; ``CountedResidual.of`` in ``viscocontact.solvers._fd`` implements them with
   the budget.
"""
from __future__ import annotations

import abc
import enum
from typing import Any, Protocol, runtime_checkable

import attrs
import numpy as np

from .._validation import in_range, int_range
from ..errors import ValidationError


@attrs.frozen(kw_only=True)
class Tolerances:
    """Stopping rules shared by every solver (``tol`` means the same thing everywhere).

    Parameters
    ----------
    residual : float
        Converged when ``max_i |r_i| <= residual``.
    step : float
        Stall when ``max_i |Δx_i| <= step`` without convergence.
    max_iterations : int
        Iteration budget.
    max_evaluations : int
        Budget of residual evaluations (finite-difference Jacobians included).
    probation : int
        Residual evaluations after the first within which a solve must make progress (0: no
        such rule): when the smallest ``max|r|`` among them is above ``progress`` times the
        first one's, the solve stops as ``Status.STALLED`` before the next evaluation. A caller
        that can retry from a better start (the BEM's approach path: a shorter step) sets it,
        since a Newton-type solve from a close start with an exact Jacobian gains digits in
        every iteration and one that has not gained two in a few is outside its root's basin.
        Honoured by the built-in solvers (:class:`~viscocontact.solvers._fd.CountedResidual`).
    progress : float
        The fraction of the first ``max|r|`` that ``probation`` asks for, in (0, 1).
    pace : tuple of float
        Earlier checkpoints of the probation (empty: none): the solve also stops as
        ``Status.STALLED`` when, after ``j`` evaluations past the first (``j <= len(pace)``,
        fewer than ``probation``), the smallest ``max|r|`` among them is above ``pace[j - 1]``
        times the first one's. Each in (0, 1]. A solve that is not gaining at the start of its
        probation stops there instead of at its end.
    """

    residual: float = attrs.field(default=1e-10, validator=in_range(0.0, lo_open=True))
    step: float = attrs.field(default=1e-14, validator=in_range(0.0))
    max_iterations: int = attrs.field(default=200, validator=int_range(1))
    max_evaluations: int = attrs.field(default=20_000, validator=int_range(1))
    probation: int = attrs.field(default=0, validator=int_range(0))
    progress: float = attrs.field(default=1e-2, validator=in_range(0.0, 1.0, lo_open=True,
                                                                   hi_open=True))
    pace: tuple[float, ...] = attrs.field(default=(), converter=tuple,
                                          validator=attrs.validators.deep_iterable(
                                              in_range(0.0, 1.0, lo_open=True)))

    @pace.validator
    def _pace_within_probation(self, attribute, value):
        if value and len(value) >= max(self.probation, 1):
            raise ValidationError("Tolerances.pace", value, f"fewer checkpoints than probation = "
                                                 f"{self.probation}")


@runtime_checkable
class NonlinearProblem(Protocol):
    """What a solver may ask of a problem. Only ``residual`` is required.

    Optional methods: ``jacobian(x) -> (n, n)``; ``merit(x) -> float`` (objective minimised by
    nonlinear CG, default ``0.5·|r|²``, eq. 4.45); ``orientation() -> (n,)`` the sign of
    ``∂r_i/∂x_i`` (used by bisection); ``max_step(x) -> (n,)`` largest safe change of each
    unknown in one step.
    """

    def residual(self, x: np.ndarray) -> np.ndarray: ...


class Status(enum.Enum):
    """Why a solve stopped."""

    CONVERGED = "converged"
    MAX_ITERATIONS = "max_iterations"
    MAX_EVALUATIONS = "max_evaluations"
    STALLED = "stalled"
    DIVERGED = "diverged"
    FAILED = "failed"


@attrs.frozen(kw_only=True)
class SolverResult:
    """Outcome of a nonlinear solve (same keys for every method; method-specific data in extras)."""

    x: np.ndarray
    residual: np.ndarray
    converged: bool
    status: Status
    message: str
    iterations: int
    function_evaluations: int
    residual_history: tuple = ()
    extras: dict = attrs.field(factory=dict)

    @property
    def residual_norm(self) -> float:
        return float(np.max(np.abs(self.residual))) if self.residual.size else 0.0


class NonlinearSolver(abc.ABC):
    """A method for ``f(x) = 0``; see the module docstring for the contract."""

    def solve(self, problem: NonlinearProblem, x0: np.ndarray,
              tolerances: Tolerances | None = None) -> SolverResult:
        """Solve ``problem.residual(x) = 0`` from ``x0``."""
        x0 = np.array(x0, dtype=float, copy=True)
        return self._solve(problem, x0, tolerances or Tolerances())

    @abc.abstractmethod
    def _solve(self, problem: NonlinearProblem, x0: np.ndarray,
               tolerances: Tolerances) -> SolverResult:
        """Implementation (``x0`` is a private float copy)."""


def optional(problem: Any, name: str):
    """The problem's optional method ``name`` or None."""
    return getattr(problem, name, None)
