r"""The ladder of grids of a spectral solve: each grid twice as fine as the one before and
started from its solution (:func:`next_start`), from at most :data:`LADDER_START` cells up to
the first trusted grid, then on until the two-grid estimate meets the tolerance
(:class:`Ladder`)."""
from __future__ import annotations

import numpy as np

from .cohesive import GridLaw
from .estimate import changes, estimate, friction_scale, power_bounded
from .grid import UniformGrid, cells_inside, refine
from .history import cohesive_grid_solve, record_approach
from .measures import GridMeasures, measure
from .planning import trusted_points
from .solvers import GridSolution, grid_solve

#: Fewest cells of the coarsest grid of the ladder.
COARSEST = 32
#: Without a warm start the ladder begins at this many cells or fewer (nested iteration: each
#: grid starts from the solution on the previous one, so the coarse grids cost little).
LADDER_START = 256


def next_start(grid: UniformGrid, coarse: GridMeasures) -> np.ndarray:
    """The starting pressure on ``grid`` (twice as fine as ``coarse``'s): the coarse pressure
    carried over (:func:`~viscocontact.methods.spectral.grid.refine`) on the cells whose centres
    lie inside the coarse contacts' sub-cell edges, zero elsewhere, so that the first loaded set
    is already the fine grid's to within the edge estimates."""
    p = refine(coarse.solution.pressure)
    if coarse.closed or coarse.edges.size == 0:
        return p
    inside = cells_inside(grid, coarse.edges)
    floor = 1e-3 * float(np.mean(p[p > 0])) if np.any(p > 0) else 1.0
    return np.where(inside, np.maximum(p, floor), 0.0)


def grid_options(method) -> dict:
    """The options of every grid solve of a :class:`Spectral` ``method``
    (:func:`~.solvers.grid_solve`, :func:`~.cohesive.cohesive_solve`)."""
    return dict(tolerance=method.residual, krylov_tolerance=method.krylov_tolerance,
                max_updates=method.max_updates, max_iterations=method.max_iterations,
                workers=method.workers or 1)


def warm_start(grid: UniformGrid, initial, load: float | None) -> np.ndarray:
    """The first grid's starting pressure from a warm start: the cells inside its contacts
    (``initial`` a result or an array of edges; a closed contact loads every cell, none the
    peak's cell), uniformly loaded to ``load`` in load control."""
    if getattr(initial, "full_contact", False):
        mask = np.ones(grid.points, bool)
    else:
        edges = np.asarray(getattr(initial, "edges", initial), dtype=float)
        mask = cells_inside(grid, edges.ravel()) if edges.size else np.zeros(grid.points, bool)
    if not mask.any():
        mask[0] = True                               # the peak
    start = mask.astype(float)
    if load is not None:
        start *= load / start.mean()
    return start


class Ladder:
    """The grids of one spectral solve, from the coarsest to the one whose estimate meets the
    tolerance.

    :meth:`run` solves them in turn, each from the previous one's solution, and records the
    events and the estimate (``extras``); :meth:`rung` solves one grid.

    Parameters
    ----------
    method : Spectral
        Its tolerance, grid sizes and grid-solve options.
    problem : ContactProblem
    prep : SpectralPrepared
        The problem's tables and operator cache.
    law : GridLaw or None
        The cohesive law (None: adhesionless).
    events : list of str
        The solve's event log (appended to).
    extras : dict
        The result's diagnostics (updated).
    """

    def __init__(self, method, problem, prep, law: GridLaw | None, events, extras: dict):
        self.method, self.problem, self.prep, self.law = method, problem, prep, law
        self.events, self.extras = events, extras
        self.load, self.pen = problem.mean_pressure, problem.penetration
        self.options = grid_options(method)

    def bounds(self) -> tuple[int, int]:
        """The first trusted grid and the finest the ladder may reach."""
        method = self.method
        if method.points is not None:
            return method.points, method.points
        # a warm start contributes its contact set only (not the grid it was computed on):
        # a result and its edges, as a study stores them, give the same answer
        return trusted_points(method, self.prep.shape.wavelength, self.law), method.max_points

    @staticmethod
    def start_points(target: int) -> int:
        """Cells of the ladder's first grid: ``target`` halved exactly down to the first at or
        below :data:`LADDER_START` cells (and at least :data:`COARSEST`)."""
        # the ladder halves the target grid exactly down to its first grid, the first at or
        # below LADDER_START cells, with or without a warm start: a ladder that began one grid
        # below the target had a single change to estimate from, and along a ζ-path on the
        # thesis's rough profile (seed 1, p̃∞ = 0.3, ζ = 0.1) it stopped at 2048 cells with an
        # estimate of 8.4e-4 and an actual error of 3.9e-3; the warm start only seeds the first
        # grid's contact set, so a warm and a cold solve take the same grids
        n = target // 2
        while n % 4 == 0 and n // 2 >= COARSEST and n > LADDER_START:
            n //= 2
        return n

    def rung(self, grid: UniformGrid, start, previous: GridMeasures | None,
             warm: bool) -> tuple[GridSolution, GridMeasures]:
        """One grid solved from ``start`` (``previous``: the coarser grid's measures, None on
        the first grid; ``warm``: the start is a warm start's), and its measures."""
        method, prep, law = self.method, self.prep, self.law
        op = prep.operators.circulant(prep.kernel, grid.points)
        start_penetration = None if previous is None else previous.solution.penetration
        workers = method.workers or 1
        dissipated = dict(loss=prep.operators.dissipation(prep.kernel, grid.points),
                          amplitude=prep.shape.amplitude)
        if law is None:
            # the first grid starts from the solution for the operator's symmetric part
            sol = grid_solve(op, grid.heights, mean_pressure=self.load, penetration=self.pen,
                             start=start, start_penetration=start_penetration,
                             presolve=start is None, **self.options)
            return sol, measure(grid, sol, op.eigenvalues, workers, **dissipated)
        history: dict = {}
        solved = cohesive_grid_solve(op, grid, law, self.load, self.pen, start,
                                     start_penetration, options=self.options,
                                     settings=method.approach, first=previous is None,
                                     warm=warm, history=history)
        if previous is None and history:
            record_approach(history, self.events, self.extras)
        return solved.solution, measure(grid, solved.solution, op.eigenvalues, workers,
                                        law=law, contact=solved.contact,
                                        weights=solved.weights, **dissipated)

    def run(self, initial) -> tuple[GridMeasures, int, int]:
        """The grids in turn from a cold or a warm start (``initial``: a result or edges,
        :func:`warm_start`); returns the last grid's measures and the solver steps and operator
        products over all grids."""
        method, events, shape = self.method, self.events, self.prep.shape
        target, final = self.bounds()
        grid = UniformGrid.of(shape, self.start_points(target))
        start = None
        if initial is not None:
            start = warm_start(grid, initial, self.load)
            events.append(f"warm start: {int(np.sum(start > 0))} of {grid.points} cells loaded")
        previous, current, before = None, None, None
        iterations = applications = 0
        errors: tuple[float, ...] = (np.inf, np.inf, np.inf)
        last = None
        while True:
            sol, current = self.rung(grid, start, previous, initial is not None)
            iterations += sol.iterations
            applications += sol.applications
            events.append(f"{grid.points} cells: {sol.solver}, {sol.message}")
            if not sol.converged:
                if previous is not None and np.all(np.isfinite(errors[:2])):
                    # a finer grid that does not converge leaves the last converged one, whose
                    # estimate (from the grids below it) says how far it is from the limit
                    events.append(f"the answer is the {previous.grid.points}-cell grid's: "
                                  f"the {grid.points}-cell grid did not converge")
                    current, previous = previous, before
                break
            if previous is not None:
                change = changes(previous, current, self.prep.m2, method.friction_floor)
                errors = power_bounded(estimate(change, last), current, self.prep.m2,
                                       method.friction_floor)
                last = change
            if previous is not None and grid.points >= target:
                # the tolerance is that of the results Ã and μ (the dissipation's estimate is
                # reported beside them)
                if max(errors[:2]) <= method.tolerance or 2 * grid.points > final:
                    break
                events.append(f"estimate {max(errors[:2]):.2g} > tolerance at {grid.points} "
                              "cells: grid doubled")
            previous, before = current, previous
            grid = UniformGrid.of(shape, 2 * grid.points)
            start = next_start(grid, current) if self.law is None else refine(sol.pressure)
        self.report(current, previous, errors)
        return current, iterations, applications

    def report(self, current: GridMeasures, previous: GridMeasures | None, errors) -> None:
        """The estimate on the last grid (and the grid before) into ``extras``; an event when it
        misses the tolerance."""
        tolerance, extras = self.method.tolerance, self.extras
        error = float(max(errors[:2]))
        extras.update(error_estimate=error, points=current.grid.points,
                      tolerance_met=bool(error <= tolerance),
                      estimates={"area": float(errors[0]), "friction": float(errors[1]),
                                 "dissipation": float(errors[2]),
                                 "friction_scale": friction_scale(
                                     current.friction, self.prep.m2,
                                     self.method.friction_floor)})
        if previous is not None:
            extras["coarse"] = {"points": previous.grid.points, "area": previous.area,
                                "friction": previous.friction,
                                "dissipation": previous.dissipation}
        if current.solution.converged and error > tolerance:
            self.events.append(f"tolerance {tolerance:g} not met: estimate {error:.2g} at "
                               f"{current.grid.points} cells")
