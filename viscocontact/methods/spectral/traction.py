r"""A smooth traction-separation law on the uniform grid (1D and areal), cell by cell.

A model's law (:meth:`AdhesionModel.traction <viscocontact.adhesion.AdhesionModel.traction>`:
:class:`~viscocontact.adhesion.LennardJones`) gives the tension ``t(g)`` at every gap ``g >= 0``
beyond contact; contact is a hard wall. With the pressure ``p`` (compressive positive) and the
gap ``g = A p - (r̃ - 1 + Δ̃)`` every cell is in contact (``g = 0``, ``p >= -t(0)``) or free
(``g > 0``, ``p = -t(g)``). For a given tension field ``t`` the shifted pressure ``q = p + t``
obeys the adhesionless conditions with the heights raised by ``A t`` (as for the Dugdale law,
:func:`~viscocontact.methods.spectral.cohesive.ranged_heights`): one adhesionless grid solve.
The tension is then the fixed point ``t = t(g(t))``, found by Anderson's acceleration of the
iteration (:data:`ANDERSON` last steps) started from the warm start's tension; converged when
no cell's tension changes by more than ``10·tolerance`` of the law's peak. Each free cell's
update is divided by ``1 + t'(g)·A_ii`` (its own stiffness against its self-compliance, the
local part of the map's Jacobian, at least :data:`LOCAL_FLOOR`), where the plain iteration
overshoots at a contact's edge.

The iteration settles where the law is soft against the solid (Tabor's parameter up to about
1-2 on a cap: the DMT side and the transition); towards the JKR side the traction is stiffer
than the solid around the edge and the equilibria are several (jumps): the iteration may then
not settle, which it reports (``converged=False``). A Dugdale law (a step) has its own solver
by tips (:mod:`~viscocontact.methods.spectral.cohesive`).

:func:`grid_law` turns a model into the grid's law: the Dugdale form where the model has one
(:meth:`~viscocontact.adhesion.AdhesionModel.cohesive_law`), else its traction.
"""
from __future__ import annotations

from typing import Any, Callable

import attrs
import numpy as np

from ...errors import ValidationError
from .cohesive import CohesiveSolution, GridLaw
from .operator import convolve
from .solvers import GridSolution, circulant_diagonal, grid_solve, violation

#: Previous iterates that Anderson's acceleration combines.
ANDERSON = 6
#: Most outer (tension) iterations.
MAX_OUTER = 200
#: Least divisor of a free cell's update (its stiffness may exceed its self-compliance's:
#: a cell wider than the law's process zone).
LOCAL_FLOOR = 0.1
#: The law's tension below this fraction of its peak counts as none: beyond the gap where it
#: stays below (:attr:`GridTraction.opening`) the surfaces are apart.
TAIL = 1e-6


@attrs.frozen(kw_only=True, eq=False)
class GridTraction:
    """A smooth traction law on the grid, in the units of the grid solve.

    Attributes
    ----------
    law : callable
        The model's :meth:`traction` (q0-scaled gaps → ``σ̃Λ̃``).
    amplitude : float
        ``Λ̃``: grid gaps are ``q0·g/Λ̃``, grid tensions ``σ̃ = t/Λ̃``.
    strength : float
        The peak tension ``σ̃_max`` (eq. 4.17 units): ``strength·weights`` is each cell's tension.
    zone : float
        The length a grid must resolve (the Dugdale zone of the same peak and work, ``x̃``).
    opening : float
        The gap (units of ``Λ̃``) beyond which the tension stays below :data:`TAIL` of its peak.
    scale : float
        The law's own length in units of ``Λ̃`` (a tension error ``δ·σ̃_max`` counts as a gap
        error ``δ·scale`` in :meth:`violation`).
    """

    law: Callable[[Any], np.ndarray]
    amplitude: float
    strength: float
    zone: float
    opening: float
    scale: float

    def solve(self, circulant, heights, **options):
        """The equilibrium of this law on one grid (:func:`traction_solve`; the cohesive
        solve hands a smooth law over to it)."""
        return traction_solve(circulant, heights, self, **options)

    def tension(self, gap) -> np.ndarray:
        """``σ̃`` at the grid gaps ``gap`` (contact cells: ``gap = 0``)."""
        return np.asarray(self.law(self.amplitude * np.maximum(gap, 0.0)), float) / self.amplitude

    def slope(self, gap) -> np.ndarray:
        """``dσ̃/dg`` at the grid gaps (central differences of :meth:`tension`, one-sided at
        contact, steps of 1e-6 of :attr:`scale`)."""
        h = 1e-6 * self.scale
        g = np.asarray(gap, float)
        lo = np.maximum(g - h, 0.0)
        return (self.tension(g + h) - self.tension(lo)) / (g + h - lo)

    def violation(self, pressure, gap, contact) -> float:
        """The hard wall's conditions (:func:`~.solvers.violation` of the gaps, a contact cell's
        tension at most ``t(0)``) and the law's ``|p + t(g)|`` on the free cells, as gaps (units
        of ``Λ̃``: tensions over the peak times :attr:`scale`)."""
        p, g = np.asarray(pressure, float), np.asarray(gap, float)
        c = np.asarray(contact, bool)
        t = self.tension(g)
        law = np.max(np.abs(p + t)[~c], initial=0.0)
        wall = np.max(-(p + t)[c], initial=0.0)
        return max(violation(g, c), max(law, wall) / self.strength * self.scale)


def grid_law(model, amplitude: float):
    """The grid's law of an adhesion ``model`` at the amplitude ``Λ̃``: a
    :class:`~.cohesive.GridLaw` (Dugdale, by tips) where the model has a cohesive form, a
    :class:`GridTraction` where it has only a traction, None without adhesion or without
    either."""
    if model is None or not float(model.work_of_adhesion) > 0:
        return None
    dugdale = model.cohesive_law(amplitude)
    if dugdale is not None:
        return GridLaw(strength=float(dugdale[0]), opening=float(dugdale[1]),
                       zone=float(dugdale[2]))
    if model.traction(0.0) is None:
        return None
    missing = [name for name in ("strength", "quasi_static_zone") if not hasattr(model, name)]
    if missing:
        raise ValidationError(f"{type(model).__name__}", model,
                              "a traction law with its peak strength(amplitude) and the "
                              f"length quasi_static_zone (missing: {', '.join(missing)})")
    peak = float(model.strength(amplitude)) * amplitude
    reach = float(model.range)
    for _ in range(64):
        if float(model.traction(reach)) <= TAIL * peak:
            break
        reach *= 2.0
    else:
        raise ValidationError(f"{type(model).__name__}.traction", model,
                              f"a law whose tension falls below {TAIL:g} of its peak at some gap")
    return GridTraction(law=model.traction, amplitude=float(amplitude),
                        strength=peak / amplitude, zone=float(model.quasi_static_zone),
                        opening=reach / amplitude, scale=float(model.range) / amplitude)


def _anderson(history: list, t: np.ndarray, f: np.ndarray) -> np.ndarray:
    """The next tension from the last iterates ``history`` of ``(t, f = T(t) - t)``:
    ``t + f - (ΔT + ΔF)γ`` with ``γ`` the least-squares fit of ``f`` by the ``ΔF``."""
    history.append((t, f))
    del history[:-ANDERSON - 1]
    if len(history) < 2:
        return t + f
    dt = np.stack([b[0] - a[0] for a, b in zip(history, history[1:])], axis=1)
    df = np.stack([b[1] - a[1] for a, b in zip(history, history[1:])], axis=1)
    coef = np.linalg.lstsq(df, f, rcond=None)[0]
    return t + f - (dt + df) @ coef


def traction_solve(circulant, heights, law: GridTraction, *, mean_pressure=None,
                   penetration=None, start=None, start_penetration=None, start_contact=None,
                   tolerance: float = 1e-10, krylov_tolerance: float = 1e-10,
                   max_updates: int = 100, max_iterations: int = 20000,
                   max_sets: int = MAX_OUTER, workers: int = 1, rows: int = 1,
                   contact_start: bool = False):
    """The equilibrium of a smooth traction law on one grid (module docstring), with the
    signature and the outcome (:class:`~.cohesive.CohesiveSolution`) of
    :func:`~.cohesive.cohesive_solve`; ``weights`` are the cells' tensions over the peak.
    ``start`` gives the first tension field (the tension of its cells where ``p < 0``);
    ``rows``, ``contact_start`` and ``start_contact`` play no part (the law has no tips)."""

    lam = circulant.eigenvalues
    diagonal = circulant_diagonal(lam)
    r = np.asarray(heights, dtype=float)
    load = mean_pressure is not None
    p = np.zeros(r.size) if start is None else np.asarray(start, dtype=float)
    t = np.maximum(-p, 0.0)
    q = np.maximum(p, 0.0)
    delta = start_penetration
    history: list = []
    iterations = applications = 0
    converged, message = False, f"the tension did not settle in {max_sets} iterations"
    sol: GridSolution | None = None
    g = np.zeros(r.size)
    for k in range(1, max_sets + 1):
        shifted = r + convolve(t, lam, workers)
        control: dict[str, Any] = ({"mean_pressure": float(mean_pressure) + float(t.mean())}
                                   if load else {"penetration": float(penetration)})
        if not load and np.all(shifted - 1.0 + penetration <= 0.0):
            # nothing reaches the wall: no contact pressure (the solvers need a contact)
            q, delta = np.zeros(r.size), float(penetration)
            g = -(shifted - 1.0 + delta)
        else:
            sol = grid_solve(circulant, shifted, start=q if q.any() else None,
                             start_penetration=delta if load else None,
                             presolve=not (circulant.symmetric or q.any()),
                             tolerance=tolerance, krylov_tolerance=krylov_tolerance,
                             max_updates=max_updates, max_iterations=max_iterations,
                             workers=workers, **control)
            iterations += sol.iterations
            applications += sol.applications
            if not sol.converged:
                message = f"inner solve: {sol.message}"
                break
            q, delta = sol.pressure, float(sol.penetration)
            g = convolve(q, lam, workers) - (shifted - 1.0 + delta)
        free_gap = np.where(q > 0, 0.0, g)
        f = law.tension(free_gap) - t
        change = float(np.max(np.abs(f))) / law.strength
        if change <= 10.0 * tolerance:
            converged = True
            break
        # each free cell's own stiffness against its self-compliance (the local part of the
        # map's Jacobian, which makes the plain iteration overshoot at a contact's edge)
        local = 1.0 + np.where(q > 0, 0.0, law.slope(free_gap)) * diagonal
        f = f / np.maximum(local, LOCAL_FLOOR)
        t = np.maximum(_anderson(history, t, f), 0.0)
    contact = q > 0.0
    p = q - t
    gap = np.where(contact, 0.0, g)
    res = law.violation(p, g, contact)
    if converged:
        message = (f"converged: {int(contact.sum())} contact cells, the tension settled in "
                   f"{k} iterations")
    out = GridSolution(pressure=p, penetration=float(delta if delta is not None else np.nan),
                       converged=converged, residual=res, iterations=iterations,
                       applications=applications,
                       solver="traction " + (sol.solver if sol is not None else "free"),
                       message=message)
    return CohesiveSolution(solution=out, contact=contact, weights=t / law.strength, gap=gap,
                            sets=k)
