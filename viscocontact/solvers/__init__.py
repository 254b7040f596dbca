"""Nonlinear solvers for ``r(x) = 0`` (thesis §4.5); they know no contact physics.

The interface and its contract are in :mod:`viscocontact.solvers.base`. Built-in methods:

* :class:`Newton` — Newton-Raphson with analytic or finite-difference Jacobian, backtracking.
* :class:`Broyden` — good Broyden with Sherman-Morrison inverse update, under-relaxation, restarts.
* :class:`NonlinearCG` — Fletcher-Reeves / Polak-Ribière on the merit ``0.5|r|²`` (eq. 4.45).
* :class:`Bisection` — component-wise sign-driven bisection of the edge residuals.

Every solver takes a :class:`Tolerances` object and returns a :class:`SolverResult`.
"""
from .base import NonlinearProblem, NonlinearSolver, SolverResult, Status, Tolerances
from .bisection import Bisection
from .broyden import Broyden
from .newton import Newton
from .nonlinear_cg import NonlinearCG

__all__ = ["Bisection", "Broyden", "Newton", "NonlinearCG", "NonlinearProblem",
           "NonlinearSolver", "SolverResult", "Status", "Tolerances"]
