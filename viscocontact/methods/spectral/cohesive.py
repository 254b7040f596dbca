r"""A Dugdale cohesive law on the uniform grid: the spectral method's finite-range adhesion.

The law of :class:`~viscocontact.adhesion.MaugisDugdale` cell by cell: a uniform tensile stress
σ̃0 wherever the gap lies in ``[0, η)`` (``η = h̃0/Λ̃``, the range in units of the amplitude),
nothing where it is ``η`` or more. With the pressure ``p`` (compressive positive, as in
:mod:`~viscocontact.methods.spectral.solvers`) and the gap ``g = A p - (r̃ - 1 + Δ̃)``,
every cell is

* in contact: ``g = 0`` and ``p >= -σ̃0``;
* cohesive: ``p = -σ̃0`` and ``0 <= g < η``;
* free: ``p = 0`` and ``g >= η``.

No edge condition is imposed: the stress at a contact edge comes out bounded (the
Maugis–Dugdale condition) because the cells carry at most σ̃0 of tension, and a cohesive run
needs no contact beside it (tension without contact). With ``w`` the share of each cell under
the cohesive stress (1 in contact and in the zones; between 0 and 1 in the cell that holds a
zone's tip), the shifted pressure ``q = p + σ̃0 w`` obeys the adhesionless conditions
``q >= 0``, ``g >= 0``, ``q g = 0``, with the heights raised by the displacement of the cohesive
stress, ``r̃ + σ̃0 A w``, and in load control the load raised by ``σ̃0 mean(w)``. So for given
tips one adhesionless grid solve (Polonsky-Keer or the active set) gives the equilibrium, and
the tips are found by iterating on the gaps, each tip ``g = η`` placed between two cell centres
(:mod:`~viscocontact.methods.spectral.tips`, :func:`cohesive_solve`); on a 1D grid all the tips
also take Newton's step together where it holds (:mod:`~.tip_newton`).

The law is non-convex (the traction jumps at ``g = η``), so a scene can have several equilibria
(the JKR-like branches); this iteration finds the one it reaches from its start, and the
spectral method starts it along the approach from first touch
(:mod:`~viscocontact.methods.spectral.approach`), then from the previous grid's solution. The
cross-check it serves is the low-Tabor side, where the zones are wide: a zone must span many
cells (:func:`zone_cells`).
"""
from __future__ import annotations

from typing import Any

import attrs
import numpy as np

from .grid_law import GridLaw
from .operator import convolve
from .solvers import GridSolution, grid_solve, violation
from .tip_newton import TipResponses, newton_tips
from .tips import (FLATTEST_SLOPE, contact_extents, moved_tips, row_tips, same_runs,
                   tip_positions, tip_residuals, tip_weights, whole_row)

__all__ = ["GridLaw", "CohesiveSolution", "cohesive_solve", "zone_cells", "ranged_heights",
           "law_violation", "tip_positions", "tip_weights", "MAX_SETS", "LOOSE_INNER",
           "FLATTEST_SLOPE", "CELLS_PER_ZONE"]

#: Most inner solves per grid.
MAX_SETS = 60
#: Residual of the inner solves while the runs change (``contact_start``; then a hundredth of the
#: tips' largest residual, down to the tolerance).
LOOSE_INNER = 1e-6
#: Fewest cells per quasi-static Dugdale zone ``h̃0²/(4γ̃)`` on the first trusted grid (a
#: viscoelastic zone lies within ``[a0/2, βa0]``).
CELLS_PER_ZONE = 32.0


def zone_cells(law: GridLaw, points: int) -> float:
    """Cells of a grid of ``points`` cells per quasi-static zone."""
    return law.zone * points / (2.0 * np.pi)


def ranged_heights(heights, weights, law: GridLaw, eigenvalues, workers: int = 1) -> np.ndarray:
    """``r̃ + σ̃0 A w``: the heights that make the shifted pressure ``q = p + σ̃0 w`` an
    adhesionless problem, ``w`` the share of each cell under the cohesive stress."""
    return np.asarray(heights, dtype=float) + law.strength * convolve(
        np.asarray(weights, dtype=float), eigenvalues, workers)


def law_violation(pressure, gap, contact, weights, law: GridLaw) -> float:
    """The largest violation of the cohesive law, in units of the amplitude: the adhesionless
    conditions of ``q = p + σ̃0 w`` (:func:`~.solvers.violation` on the contact cells), ``g < η``
    on the cells wholly under the cohesive stress and ``g >= η`` on the free ones (the cells
    that hold a tip straddle ``η``); a smooth traction law's own
    (:meth:`~.traction.GridTraction.violation`)."""
    if not isinstance(law, GridLaw):
        return law.violation(pressure, gap, contact)
    g = np.asarray(gap, float)
    w = np.asarray(weights, float)
    out = violation(g, contact)
    cohesive = (w == 1.0) & ~contact
    free = w == 0.0
    if cohesive.any():
        out = max(out, float(np.max(g[cohesive] - law.opening, initial=0.0)))
    if free.any():
        out = max(out, float(np.max(law.opening - g[free], initial=0.0)))
    return out


@attrs.frozen(kw_only=True, eq=False)
class CohesiveSolution:
    """The outcome of one cohesive grid solve.

    Attributes
    ----------
    solution : GridSolution
        ``pressure`` is the cell pressure ``p`` (tension negative); the counts add up over the
        inner solves.
    contact : ndarray of bool
        Cells in contact (``q > 0``).
    weights : ndarray
        Share of each cell under the cohesive stress (1 in contact and in the zones, between 0
        and 1 at the tips).
    gap : ndarray
        ``g`` at the cell centres.
    sets : int
        Inner solves (tip positions tried).
    """

    solution: GridSolution
    contact: np.ndarray
    weights: np.ndarray
    gap: np.ndarray
    sets: int


class _TipIteration:
    """The state of :func:`cohesive_solve`: the cell pressure, penetration, gaps and contact
    of the last inner solve, the tips (run extents per row) of the next one, and the counts.

    :meth:`solve` runs the inner adhesionless solve for the current tips, :meth:`settled`
    moves the tips (and says whether they are found), :meth:`result` is the outcome.
    """

    def __init__(self, circulant, heights, law: GridLaw, *, mean_pressure, penetration, start,
                 start_penetration, start_contact, options: dict, rows: int,
                 contact_start: bool):
        self.circulant, self.law, self.options = circulant, law, options
        self.mean_pressure, self.penetration = mean_pressure, penetration
        self.start_penetration, self.contact_start = start_penetration, contact_start
        self.lam = circulant.eigenvalues
        self.r = r = np.asarray(heights, dtype=float)
        self.rows, self.width = rows, r.size // rows
        self.load = load = mean_pressure is not None
        workers = options["workers"]
        self.p = p = np.asarray(start, dtype=float).copy()
        u = convolve(p, self.lam, workers)
        if not load:
            delta = float(penetration)
        elif start_penetration is None:
            delta = 1.0 + float(np.mean((u - r)[p > 0])) if np.any(p > 0) else 0.0
        else:
            delta = float(start_penetration)
        self.delta = delta
        self.g = u - (r - 1.0 + delta)
        if start_contact is None:
            self.contact = p > 0.0
            self.extents = row_tips(self.g, self.contact, law, rows)
        else:
            self.contact = np.asarray(start_contact, bool)
            self.extents = contact_extents(self.contact, self.width)
        self.before: list | None = None  # the tips' tracks per row (None: the runs changed)
        # a 1D grid's tips also take Newton's step together (tip_newton)
        self.responses = (TipResponses(circulant, law.strength, load, options["workers"])
                          if rows == 1 else None)
        self.loose = LOOSE_INNER
        self.iterations = self.applications = 0
        self.solution: GridSolution | None = None

    def solve(self, k: int) -> GridSolution:
        """Inner solve ``k`` (from 1): the adhesionless problem of the shifted pressure for the
        current tips; the pressure, penetration, gaps and contact then are its."""
        law, opts = self.law, self.options
        self.w = w = np.concatenate([tip_weights(e, self.width) for e in self.extents])
        shifted = ranged_heights(self.r, w, law, self.lam, opts["workers"])
        q0 = np.maximum(self.p + law.strength * w, 0.0)
        if self.contact_start:
            q0[~self.contact] = 0.0       # a cell new to a zone is cohesive, not in contact
        if not q0.any():
            q0[int(np.argmax(shifted))] = 1.0
        control: dict[str, Any] = (
            {"mean_pressure": float(self.mean_pressure) + law.strength * float(w.mean())}
            if self.load else {"penetration": float(self.penetration)})
        tolerance = opts["tolerance"]
        self.inner = inner = tolerance if not self.contact_start else max(tolerance, self.loose)
        options = dict(opts, start=q0, tolerance=inner,
                       krylov_tolerance=max(opts["krylov_tolerance"], 0.1 * inner), **control)
        counts = self._inner_solves(k, shifted, options)
        sol = self.solution = counts[-1]
        self.iterations += sum(c.iterations for c in counts)
        self.applications += sum(c.applications for c in counts)
        q, self.delta = sol.pressure, float(sol.penetration)
        self.p = q - law.strength * w
        self.g = convolve(self.p, self.lam, opts["workers"]) - (self.r - 1.0 + self.delta)
        self.contact = q > 0.0
        return sol

    def _inner_solves(self, k: int, shifted, options: dict) -> list[GridSolution]:
        """The grid solves of inner solve ``k``, the last one the answer (a contact-free answer
        takes none and counts nothing)."""
        circulant, counts = self.circulant, []
        sol = None
        if not self.load and np.max(shifted) - 1.0 + float(self.penetration) <= 0.0:
            # no cell reaches the plane under the cohesive stress (tension without contact):
            # q = 0 is the solution
            sol = GridSolution(pressure=np.zeros(shifted.size),
                               penetration=float(self.penetration), converged=True,
                               residual=0.0, iterations=0, applications=0, solver="none",
                               message="no contact")
        elif (k > 1 or circulant.symmetric or self.contact_start
              or self.start_penetration is not None):
            # from the last solution (the tips moved a little), or from a start with its
            # penetration, a nearby state (the approach's last step, a coarser grid's): on a
            # λ = 5 sinusoid at ζ = 1, Δ̃ = 0.5 the presolve's start failed at 4096 cells
            # where this one converges
            sol = grid_solve(circulant, shifted,
                             start_penetration=self.delta if self.load else None, **options)
            counts.append(sol)
        if sol is None or not (sol.converged or circulant.symmetric or sol.solver == "none"):
            # a start far from the solution (the adhesionless contact, a coarser grid's carried
            # over): the active set then needs damped steps by the dozen (on a sinusoid at
            # ζ = 1e-2 it failed in 100), so it starts from the solution for the operator's
            # symmetric part, as on the spectral method's first grid
            sol = grid_solve(circulant, shifted, presolve=True, **options)
            counts.append(sol)
        return counts if counts else [sol]

    def settled(self) -> bool:
        """Whether the tips are found (the runs the same, every tip's residual within
        ``10·tolerance``, the last inner solve at the tolerance); if not, the next tips: where
        the gap crosses η in a row whose runs changed, else each by its own residual, within
        the bracket of its root once it has one (:func:`moved_tips`), or on a 1D grid all
        together by Newton's step where that holds (:func:`~.tip_newton.newton_tips`)."""
        width, law = self.width, self.law
        fresh = row_tips(self.g, self.contact, law, self.rows)
        same = [same_runs(old, new, width) or (whole_row(old, width) and whole_row(new, width))
                for old, new in zip(self.extents, fresh)]
        if not any(same):
            self.extents, self.before = fresh, None     # the runs changed: start the tips again
            return False
        rows_g = np.asarray(self.g).reshape(self.rows, width)
        residuals = tip_residuals(rows_g, self.extents, same, law, width)
        worst = max((abs(v) for row in residuals if row is not None for pair in row for v in pair),
                    default=0.0)
        tolerance = self.options["tolerance"]
        if all(same) and worst <= 10.0 * tolerance and self.inner == tolerance:
            return True
        # inexact inner solves while the tips move: a hundredth of their largest residual
        self.loose = 1e-2 * worst if all(same) else LOOSE_INNER
        before = self.before
        moved_rows: list = []
        tracks: list = []
        for i, (ext, res, fr, gr) in enumerate(zip(self.extents, residuals, fresh, rows_g)):
            if not res:
                moved_rows.append(fr)
                tracks.append(None)
                continue
            row, kept = moved_tips(ext, res, fr, gr, None if before is None else before[i])
            moved_rows.append(row)
            tracks.append(kept)
        self.before = tracks
        if self.responses is not None and all(same) and residuals[0]:
            newton = newton_tips(self.extents[0], residuals[0], rows_g[0], self.contact,
                                 self.responses)
            if newton is not None:
                moved_rows = [newton]
        self.extents = moved_rows
        return False

    def result(self, sets: int, converged: bool, message: str) -> CohesiveSolution:
        """The outcome after ``sets`` inner solves."""
        p, g, contact, w, sol = self.p, self.g, self.contact, self.w, self.solution
        res = law_violation(p, g, contact, w, self.law)
        if converged:
            message = (f"converged: {int(contact.sum())} contact and "
                       f"{int(np.sum((w > 0) & ~contact))} cohesive cells after {sets} inner "
                       "solves")
        out = GridSolution(pressure=p, penetration=self.delta, converged=converged,
                           residual=res, iterations=self.iterations,
                           applications=self.applications,
                           solver="cohesive " + (sol.solver if sol is not None else "grid"),
                           message=message)
        return CohesiveSolution(solution=out, contact=contact, weights=w, gap=g, sets=sets)


def cohesive_solve(circulant, heights, law: GridLaw, *, mean_pressure=None, penetration=None,
                   start=None, start_penetration=None, start_contact=None,
                   tolerance: float = 1e-10, krylov_tolerance: float = 1e-10,
                   max_updates: int = 100, max_iterations: int = 20000,
                   max_sets: int = MAX_SETS, workers: int = 1,
                   rows: int = 1, contact_start: bool = False) -> CohesiveSolution:
    """The equilibrium of the cohesive law on one grid (module docstring).

    Unknowns are the tips of the runs of cells in range (:func:`tip_positions`), continuous,
    the cell that holds a tip carrying the stress in proportion (:func:`tip_weights`). Each
    inner solve takes them as given; a tip's residual is the gap there less η. The first step
    and any step after the runs changed places every tip where the last solution's gap crosses
    η (a fixed point, which on its own creeps: the new stress pulls the next cell into range,
    a cell per solve); then each tip moves by the secant of its last two residuals, and once
    a sample of each sign brackets its root, within that bracket (:func:`~.tips.moved_tips`:
    a zone that snaps over many cells then settles instead of cycling). On a 1D grid
    (``rows = 1``) the tips take Newton's step together instead where the tips' motion is
    stable and no tip moves more than a cell (:mod:`~.tip_newton`): tips coupled strongly
    (two in one cell, zones facing across a neck) settle instead of creeping. Converged
    when the runs are the same and every tip's residual is within ``10·tolerance``.

    Parameters
    ----------
    circulant : Circulant
    heights : ndarray
        ``r̃`` at the cell centres.
    law : GridLaw
    mean_pressure, penetration : float
        Exactly one: ``p̃∞ > 0`` (load control) or ``Δ̃`` (penetration control).
    start : ndarray
        Starting cell pressure ``p`` (tension negative), e.g. the adhesionless solution or the
        previous grid's carried over.
    start_penetration : float, optional
        ``Δ̃`` of ``start`` (load control; default: from the displacement of ``start`` on its
        loaded cells). Given, ``start`` is taken for a nearby state: the first inner solve
        starts from it, and from the solution for the operator's symmetric part only if it
        fails.
    start_contact : ndarray of bool, optional
        A contact set to start from (a warm start: another method's contacts) instead of the
        cells in range under ``start``: the first solve puts the cohesive stress on these
        cells only, and the zones grow from them.
    rows : int
        The cells are ``rows`` grid rows of equal length, one after the other (an areal grid,
        flat row by row): each row's runs have their own tips along the row, the cells
        across the rows are whole (one row: the 1D grid).
    contact_start : bool
        Start every inner solve from the last one's contact cells (a cell new to a zone starts
        cohesive, not loaded) and the first from ``start``'s, without the presolve for the
        operator's symmetric part unless it fails: 2-4 active-set steps per inner solve
        instead of 13-15 on an areal self-affine surface (128², ζ = 1); and solve them
        inexactly while the tips move (:data:`LOOSE_INNER` while the runs change, then a
        hundredth of the tips' largest residual), the last at ``tolerance``. By default (the
        1D method) an inner solve starts from every cell the shifted pressure loads and is
        solved to ``tolerance``.
    """
    if not isinstance(law, GridLaw):       # a smooth traction law (no tips)
        return law.solve(circulant, heights, mean_pressure=mean_pressure,
                         penetration=penetration, start=start,
                         start_penetration=start_penetration, tolerance=tolerance,
                         krylov_tolerance=krylov_tolerance, max_updates=max_updates,
                         max_iterations=max_iterations, max_sets=max_sets, workers=workers)
    options = dict(tolerance=tolerance, krylov_tolerance=krylov_tolerance,
                   max_updates=max_updates, max_iterations=max_iterations, workers=workers)
    tips = _TipIteration(circulant, heights, law, mean_pressure=mean_pressure,
                         penetration=penetration, start=start,
                         start_penetration=start_penetration, start_contact=start_contact,
                         options=options, rows=rows, contact_start=contact_start)
    converged = False
    message = f"the cohesive tips did not settle in {max_sets} solves"
    for k in range(1, max_sets + 1):
        sol = tips.solve(k)
        if not sol.converged:
            message = f"inner solve: {sol.message}"
            break
        if tips.settled():
            converged = True
            break
    return tips.result(k, converged, message)
