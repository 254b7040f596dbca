r"""Pull-off of an adhesive areal contact: a retraction in penetration control on one grid.

:func:`retraction` follows the equilibria of a traction law (:class:`~viscocontact.adhesion.
MaugisDugdale`, :class:`~viscocontact.adhesion.LennardJones`) along decreasing penetrations
``Δ̃``, each grid solve started from the last one's pressure, so that the path stays on the branch
it started on (the first from the adhesionless contact at the first ``Δ̃``; an adhesive contact has several equilibria at one ``Δ̃``: the JKR-like branch that
a retraction follows and the one a fresh approach reaches). Under penetration control the
branch passes through the most tensile load (in JKR's theory the load minimum lies on the stable
part of the branch under fixed grips), so the pull-off force — the most tensile load under load
control — is the least mean pressure along the path (:attr:`Retraction.pull_off`), refined by
the parabola through the least sampled load and its two neighbours.

The solid is taken at its speed ``ζ`` (elastic for ``ζ = 0`` or an elastic rheology); the grid is
the method's finest (``points``), without the ladder's error estimate: the caller checks the
grid by solving on two (the tests do).
"""
from __future__ import annotations

import attrs
import numpy as np

from ..errors import ValidationError
from ..methods.spectral.cohesive import cohesive_solve
from ..methods.spectral.solvers import grid_solve
from ..methods.spectral.traction import grid_law
from .problem import ArealProblem


@attrs.frozen(kw_only=True, eq=False)
class Retraction:
    """The equilibria along a retraction (:func:`retraction`).

    Attributes
    ----------
    penetrations : ndarray
        ``Δ̃`` of each equilibrium (decreasing).
    loads : ndarray
        ``p̃∞`` (tension negative), eq. 4.17 units.
    contact_cells : ndarray of int
        Cells in contact at each.
    amplitude : float
        ``Λ̃`` of the grid (a force per cell is ``p̃∞Λ̃E*A/2``).
    converged : bool
        Every solve converged.
    message : str
    """

    penetrations: np.ndarray
    loads: np.ndarray
    contact_cells: np.ndarray
    amplitude: float
    converged: bool
    message: str

    @property
    def pull_off(self) -> float:
        """The least ``p̃∞`` (the most tensile), the vertex of the parabola through the least
        sampled load and its neighbours when it lies inside the path; raises
        :class:`~viscocontact.errors.ValidationError` when the least load is at an end of the
        path (the path does not bracket it)."""
        k = int(np.argmin(self.loads))
        if k == 0 or k == len(self.loads) - 1:
            raise ValidationError("retraction.penetrations", (self.penetrations[0],
                                                              self.penetrations[-1]),
                                  "a path whose least load lies inside it (the least load is at "
                                  f"an end, Δ̃ = {self.penetrations[k]:.4g})")
        x, y = self.penetrations[k - 1:k + 2], self.loads[k - 1:k + 2]
        a, b, c = np.polyfit(x, y, 2)
        return float(c - b * b / (4 * a)) if a > 0 else float(y[1])


def retraction(problem: ArealProblem, penetrations, points: tuple[int, int], *,
               method=None, max_sets: int = 300) -> Retraction:
    """The equilibria of ``problem`` (its penetration is ignored) at ``penetrations``, in the
    order given (a retraction: decreasing), on the ``points = (nx, ny)`` grid, each from the
    previous one's pressure (module docstring); ``method`` an :class:`~viscocontact.areal.
    method.ArealSpectral` for its solver options; ``max_sets`` the most inner solves per point
    (the tips of a short zone creep by about a cell per solve from the adhesionless start: 53 on
    a 256² grid at Maugis's λ = 3). Stops at the first solve that fails."""
    from .method import ArealSpectral

    method = ArealSpectral() if method is None else method
    pens = np.asarray(penetrations, dtype=float)
    if pens.ndim != 1 or len(pens) < 3 or np.any(np.diff(pens) >= 0):
        raise ValidationError("retraction.penetrations", penetrations,
                              "at least three decreasing penetrations")
    nx, ny = points
    fine = problem.heights(nx, ny)
    amplitude = float(fine.max())
    r = (fine / amplitude).ravel()
    kernel = problem.areal_kernel()
    law = grid_law(problem.adhesion, amplitude)
    if law is None:
        raise ValidationError("ArealProblem.adhesion", problem.adhesion,
                              "an adhesion model with a traction law (a retraction's pull-off)")
    op = kernel.circulant(nx, ny)
    options = dict(tolerance=method.residual, krylov_tolerance=method.krylov_tolerance,
                   max_updates=method.max_updates, max_iterations=method.max_iterations,
                   workers=method.workers or 1)
    # the path starts from the adhesionless contact at its first penetration
    p = grid_solve(op, r, penetration=float(pens[0]), presolve=not op.symmetric,
                   **options).pressure
    loads, cells, done = [], [], []
    converged, message = True, "converged"
    for d in pens:
        solved = cohesive_solve(op, r, law, penetration=float(d), start=p, rows=ny,
                                contact_start=True, max_sets=max_sets, **options)
        if not solved.solution.converged:
            converged, message = False, f"Δ̃ = {d:.6g}: {solved.solution.message}"
            break
        p = solved.solution.pressure
        loads.append(float(p.mean()))
        cells.append(int(solved.contact.sum()))
        done.append(float(d))
    return Retraction(penetrations=np.array(done), loads=np.array(loads),
                      contact_cells=np.array(cells, dtype=int), amplitude=amplitude,
                      converged=converged, message=message)
