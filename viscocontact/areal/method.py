r"""The spectral method on a 2D grid: :class:`ArealSpectral`.

The 1D spectral method (:mod:`viscocontact.methods.spectral`) made areal: the same grid solvers
(:func:`~viscocontact.methods.spectral.solvers.grid_solve`: Polonsky-Keer conjugate gradients
when the operator is symmetric, the primal-dual active set with GMRES otherwise, both
preconditioned by the inverse circulant), which see flat vectors and a circulant whose products
:func:`~viscocontact.methods.spectral.operator.convolve` takes by ``rfft2``; the operator of
:class:`~viscocontact.areal.kernels.ArealKernel` (piecewise-constant cells, the 1D operator on the
modes constant in ``y``); the same dimensionless groups, load or penetration control and
two-grid error estimate. A surface extruded along ``y`` is solved as the 1D method solves its
profile on the same grid.

Grids. The finest grid is the array's (an array surface) or ``points`` (a :class:`Surface`);
the solve runs the grids ``finest/2^k`` from the first one with at most :data:`LADDER_START`
cells per side, each started from the previous solution (nested iteration), the coarse grids
sampling the finest one's heights. The estimate is the Richardson one of the 1D method
(:func:`~viscocontact.methods.spectral.method.estimate`: the change of ``Ã`` and ``μ`` between the
last two grids, at least half the change before); ``tolerance_met`` says whether it is within
the tolerance (a finer grid of an array cannot be made up).

Memory. Each cell costs about :data:`BYTES_PER_CELL` bytes in the solve plus the GMRES basis of
the active set, ``2 restart · 8`` bytes per loaded cell (:meth:`ArealSpectral.memory`); a
scene that needs more than ``max_memory`` is refused before anything is computed, with the
figure it needs.
"""
from __future__ import annotations

import math
import time
from typing import ClassVar

import attrs
import numpy as np

from .._events import EventList
from .._validation import in_range, int_range
from ..errors import ValidationError
from ..kernels.clausen import TWO_PI
from ..methods.spectral.cohesive import (CELLS_PER_ZONE, GridLaw, cohesive_solve,
                                         law_violation, zone_cells)
from ..methods.spectral.method import estimate
from ..methods.spectral.operator import Circulant, convolve
from ..methods.spectral.solvers import GridSolution, grid_solve, violation
from ..methods.spectral.traction import grid_law
from ..result import ContactResult, SolveStatus
from .kernels import ArealKernel
from .problem import ArealProblem
from .results import area_fraction, cell_rise, edge_corrections, friction, patch_statistics
from .planning import BYTES_PER_CELL, PLANNED_CONTACT, RESTART

#: The ladder of grids begins at this many cells per side or fewer.
LADDER_START = 64


@attrs.frozen(kw_only=True, eq=False)
class Level:
    """One grid of the ladder: its heights, slopes and operator."""

    nx: int
    ny: int
    heights: np.ndarray        # r̃ = q0 h/Λ̃, flat (row by row)
    slope: np.ndarray          # ∂(q0 h)/∂s̃ along the sliding direction, per cell, flat
    circulant: Circulant
    direction: float = 0.0     # the sliding direction, radians from x̃


@attrs.frozen(kw_only=True, eq=False)
class Measured:
    """A grid solution and its two integral measures (the estimate's ``area``, ``friction``)."""

    level: Level
    solution: GridSolution
    gap: np.ndarray
    area: float                # 2π × area fraction (the 1D method's Ã on an extruded surface)
    friction: float
    contact: np.ndarray        # cells in contact (flat)
    weights: np.ndarray | None = None   # share of each cell under a cohesive law's stress


@attrs.define(kw_only=True)
class _Ladder:
    """The state of a solve's ladder of grids (mutable, private to one solve)."""

    fine: np.ndarray
    m2: float
    current: Measured | None = None
    converged: bool = False
    last: tuple[float, float] | None = None
    errors: tuple[float, ...] = (np.inf, np.inf)
    iterations: int = 0
    applications: int = 0


def _points(value):
    if value is None:
        return None
    pts = (value, value) if np.isscalar(value) else tuple(value)
    if len(pts) != 2 or any(isinstance(v, bool) or int(v) != v or v < 8 or v % 2
                            for v in pts):
        raise ValidationError("ArealSpectral.points", value,
                              "None, or an even integer >= 8 or a pair (nx, ny) of them")
    return int(pts[0]), int(pts[1])


@attrs.frozen(kw_only=True)
class ArealSpectral:
    r"""The spectral method for areal surfaces (module docstring).

    Parameters
    ----------
    tolerance : float
        Relative accuracy of the area and ``μ`` the estimate is checked against, ``[1e-6, 0.1]``.
    points : int or (int, int) or None
        Cells ``(nx, ny)`` of the finest grid for a :class:`Surface` (an array surface uses its
        own); ``None``: 256 per side (``ny`` scaled by the aspect), doubled until the estimate
        meets the tolerance or a side would exceed ``max_points`` or the memory ``max_memory``.
    max_points : int
        Most cells a side of an automatically refined grid, ``[64, 65536]``.
    max_memory : float
        Bytes a solve may plan for, ``[1e6, 1e12]``.
    workers : int or None
        Threads of ``scipy.fft`` (``None``: 1).
    friction_floor : float
        ``μ`` is resolved relative to ``max(|μ|, friction_floor·√m2)``, in ``[0, 1]``.
    residual, krylov_tolerance, max_iterations, max_updates
        As for :class:`~viscocontact.methods.spectral.Spectral`.

    Examples
    --------
    One bump per cell, ``0.1·(cos x̃ + cos ỹ)``, on an elastic half-space:

    >>> import numpy as np
    >>> from viscocontact.areal.problem import ArealProblem
    >>> from viscocontact.rheology import Elastic
    >>> x = 2 * np.pi * np.arange(32) / 32
    >>> bumps = 0.1 * (np.cos(x)[None, :] + np.cos(x)[:, None])
    >>> r = ArealSpectral().solve(ArealProblem(surface=bumps, rheology=Elastic(),
    ...                                        mean_pressure=0.05))
    >>> r.converged, r.n_contacts, r.extras["points"]
    (True, 1, (32, 32))
    >>> bool(0.0 < r.extras["area_fraction"] < 0.5), bool(abs(r.friction) < 1e-3)
    (True, True)
    """

    name: ClassVar[str] = "areal-spectral"

    tolerance: float = attrs.field(default=1e-3, validator=in_range(1e-6, 0.1))
    points: tuple[int, int] | None = attrs.field(default=None, converter=_points)
    max_points: int = attrs.field(default=4096, validator=int_range(64, 1 << 16))
    max_memory: float = attrs.field(default=2e9, validator=in_range(1e6, 1e12))
    workers: int | None = attrs.field(
        default=None, validator=attrs.validators.optional(int_range(1, 1024)))
    friction_floor: float = attrs.field(default=1e-2, validator=in_range(0.0, 1.0))
    residual: float = attrs.field(default=1e-9, validator=in_range(1e-15, 1e-4))
    krylov_tolerance: float = attrs.field(default=1e-10, validator=in_range(1e-15, 1e-2))
    max_iterations: int = attrs.field(default=20000, validator=int_range(10, 10**7))
    max_updates: int = attrs.field(default=100, validator=int_range(2, 10**5))

    # ---- planning ----------------------------------------------------------------------------
    def grid_of(self, problem: ArealProblem) -> tuple[int, int]:
        """``(nx, ny)`` of the finest grid."""
        native = problem.native_points
        if native is not None:
            if self.points is not None and self.points != native:
                raise ValidationError("ArealSpectral.points", self.points,
                                      f"None or the array surface's grid {native}")
            return native
        if self.points is not None:
            return self.points
        ny = 2 * max(4, int(round(128 * problem.cell_aspect)))
        return 256, ny

    def ladder(self, nx: int, ny: int) -> list[tuple[int, int]]:
        """The grids of a solve, coarse to fine: each side halved while both stay even, the
        coarser side at least 8, and the finer side above :data:`LADDER_START` or a single grid
        so far (the estimate needs two)."""
        grids = [(nx, ny)]
        while (max(nx, ny) > LADDER_START or len(grids) < 2) and nx % 4 == 0 and ny % 4 == 0 \
                and min(nx, ny) >= 16:
            nx, ny = nx // 2, ny // 2
            grids.append((nx, ny))
        return grids[::-1]

    def memory(self, nx: int, ny: int, symmetric: bool = False) -> float:
        """Bytes a solve on ``(nx, ny)`` is planned to need (module docstring)."""
        cells = nx * ny
        basis = 0.0 if symmetric else 2 * RESTART * 8 * PLANNED_CONTACT * cells
        return float(BYTES_PER_CELL * cells + basis)

    def plan(self, problem: ArealProblem):
        """The decisions of a solve (grids, memory, solver, adhesion, estimate) as a
        :class:`~viscocontact.plan.SolvePlan` (``str()`` gives one line per decision;
        :func:`~viscocontact.areal.planning.plan_steps`)."""
        from .planning import plan_steps

        return plan_steps(self, problem)

    # ---- the solve ---------------------------------------------------------------------------
    def solve(self, problem: ArealProblem, *, fields: bool = False) -> ContactResult:
        """The equilibrium of an areal ``problem`` (:meth:`_solve`), with BLAS on
        one thread (the Gram-Schmidt products of GMRES ran 3.6 times slower on two threads of a
        loaded two-core machine, 512² grid)."""
        from .._blas import single_blas_thread

        with single_blas_thread():
            return self._solve(problem, fields)

    def _solve(self, problem: ArealProblem, fields: bool) -> ContactResult:
        """The solve behind :meth:`solve`.

        Returns a :class:`~viscocontact.result.ContactResult`: ``area`` is ``2π`` times the
        area fraction (the mean contact length per grid row, as the 1D method's ``Ã``),
        ``n_contacts`` the number of patches, ``edges`` empty; ``extras`` hold
        ``area_fraction``, ``mean_gap``, ``dissipated_power``, ``friction_dissipation``,
        ``patches`` (:meth:`PatchStatistics.summary`), ``points``, the estimate and ``grids`` (per
        grid: cells, solver, iterations, operator products, area, μ, seconds). With
        ``fields``: ``x``, ``y``, ``heights``, ``pressure``, ``displacement``, ``gap`` of shape
        ``(ny, nx)`` and the :class:`~viscocontact.areal.results.PatchStatistics`.

        Raises
        ------
        ValidationError
            When the planned memory exceeds ``max_memory``.
        """
        started = time.perf_counter()
        nx, ny = self.grid_of(problem)
        kernel = problem.areal_kernel()
        need = self.memory(nx, ny)
        if need > self.max_memory:
            raise ValidationError("ArealSpectral.max_memory", self.max_memory,
                                  f">= {need:.3g} bytes for a {nx}×{ny} grid (or a coarser grid)")
        fine = problem.heights(nx, ny)
        amplitude = float(fine.max())
        if not amplitude > 0:
            raise ValidationError("ArealProblem.surface", "a flat surface", "heights with a peak")
        events: list[str] = EventList(self.name)       # logged as they happen
        extras: dict = {"method": self.name, "events": events, "grids": [], "seconds": 0.0}
        common: dict = dict(zeta=float(problem.zeta), edge_perturbation=0.0, extras=extras)
        load, pen = problem.mean_pressure, problem.penetration
        law = self.law(problem, amplitude)
        if law is not None and load is not None and not load > 0:
            raise ValidationError("ArealProblem.mean_pressure", load,
                                  "> 0 with a cohesive law under load control (the grid starts "
                                  "from the adhesionless contact); use penetration control")
        reach = 0.0 if law is None else -law.opening
        if (load is not None and not load > 0) or (pen is not None and not pen > reach):
            return ContactResult(
                area=0.0, mean_pressure=0.0, penetration=np.nan if pen is None else float(pen),
                friction=np.nan, reduced_friction=np.nan, n_contacts=0, edges=np.zeros((0, 2)),
                full_contact=False, converged=True, status=SolveStatus.NO_CONTACT,
                message="no contact at this load", residual=0.0, iterations=0,
                function_evaluations=0, min_gap=np.inf, **common)
        ladder = _Ladder(fine=fine, m2=_m2(fine, kernel))
        for gx, gy in self.ladder(nx, ny):
            if not self._step(ladder, problem, kernel, amplitude, (gx, gy), law, extras):
                break
        # a Surface without given points is refined until the estimate meets the tolerance
        while (problem.native_points is None and self.points is None and ladder.converged
               and max(ladder.errors) > self.tolerance):
            gx, gy = 2 * ladder.fine.shape[1], 2 * ladder.fine.shape[0]
            if max(gx, gy) > self.max_points or self.memory(gx, gy) > self.max_memory:
                extras["events"].append(f"estimate {max(ladder.errors):.2g} > tolerance; "
                                        f"{gx}×{gy} cells exceed max_points or max_memory")
                break
            extras["events"].append(f"estimate {max(ladder.errors):.2g} > tolerance: grid "
                                    "doubled")
            ladder.fine = problem.heights(gx, gy)
            self._step(ladder, problem, kernel, amplitude, (gx, gy), law, extras)
        current, errors, m2 = ladder.current, ladder.errors, ladder.m2
        assert current is not None, "the ladder has at least one grid"
        iterations, applications = ladder.iterations, ladder.applications
        error = float(max(errors))
        extras.update(error_estimate=error, points=(current.level.nx, current.level.ny),
                      tolerance_met=bool(error <= self.tolerance),
                      estimates={"area": float(errors[0]), "friction": float(errors[1])})
        if law is not None:
            _cohesive_extras(law, current, extras)
        result = _assemble(self, kernel, current, amplitude, m2, (iterations, applications),
                           fields, common, law)
        extras["seconds"] = time.perf_counter() - started
        return result

    def _step(self, ladder: "_Ladder", problem, kernel: ArealKernel, amplitude: float,
              points: tuple[int, int], law: GridLaw | None, extras: dict) -> bool:
        """Solve the next grid of ``ladder`` (from the previous grid's solution) and update its
        estimate; False when the grid solve failed."""
        begun = time.perf_counter()
        gx, gy = points
        ny, nx = ladder.fine.shape
        level = self._level(ladder.fine, amplitude, kernel, nx, ny, gx, gy)
        load, pen = problem.mean_pressure, problem.penetration
        previous = ladder.current
        start = None if previous is None else _refine(previous.solution.pressure,
                                                       previous.level, inside=law is None,
                                                       gap=previous.gap)
        start_pen = None if previous is None else previous.solution.penetration
        if law is None:
            sol = grid_solve(level.circulant, level.heights, mean_pressure=load,
                             penetration=pen, start=start, start_penetration=start_pen,
                             presolve=start is None, **self._grid_options())
            current = self._measure(level, sol)
        else:
            sol, contact, weights = self._solve_cohesive(level, load, pen, start, start_pen,
                                                         law)
            current = self._measure(level, sol, law, contact, weights)
        ladder.iterations += sol.iterations
        ladder.applications += sol.applications
        extras["events"].append(f"{gx}×{gy} cells: {sol.solver}, {sol.message}")
        extras["grids"].append({"points": (gx, gy), "solver": sol.solver,
                                "iterations": int(sol.iterations),
                                "applications": int(sol.applications),
                                "area": current.area, "friction": current.friction,
                                "seconds": time.perf_counter() - begun})
        ladder.current = current
        ladder.converged = bool(sol.converged)
        if not sol.converged:
            return False
        if previous is not None:
            change = _changes(previous, current, ladder.m2, self.friction_floor)
            ladder.errors = estimate(change, ladder.last)
            ladder.last = change
        return True

    def _grid_options(self) -> dict:
        return dict(tolerance=self.residual, krylov_tolerance=self.krylov_tolerance,
                    max_updates=self.max_updates, max_iterations=self.max_iterations,
                    workers=self.workers or 1)

    def _level(self, fine, amplitude, kernel: ArealKernel, nx, ny, gx, gy) -> Level:
        step = nx // gx
        heights = fine[::step, ::step] / amplitude
        hx, hy = TWO_PI / gx, TWO_PI * kernel.aspect / gy
        slope = math.cos(kernel.direction) * cell_rise(fine, step, axis=1) / hx
        if kernel.direction != 0.0:
            slope = slope + math.sin(kernel.direction) * cell_rise(fine, step, axis=0) / hy
        return Level(nx=gx, ny=gy, heights=heights.ravel(), slope=slope.ravel(),
                     circulant=kernel.circulant(gx, gy), direction=kernel.direction)

    def _measure(self, level: Level, sol: GridSolution, law: GridLaw | None = None,
                 contact=None, weights=None) -> Measured:
        p = sol.pressure
        gap = convolve(p, level.circulant.eigenvalues, self.workers or 1) \
            - (level.heights - 1.0 + sol.penetration)
        shape = (level.ny, level.nx)
        if law is None:
            contact = p > 0
            shifted = p
        else:        # the Maugis-Dugdale edge has the adhesionless field of p + σ̃0
            shifted = np.where(contact, p + law.strength * weights, 0.0)
        area = TWO_PI * area_fraction(shifted.reshape(shape), gap.reshape(shape),
                                      level.direction)
        return Measured(level=level, solution=sol, gap=gap, area=area,
                        friction=friction(p, level.slope), contact=np.asarray(contact, bool),
                        weights=weights)

    def _solve_cohesive(self, level: Level, load, pen, start, start_pen, law: GridLaw):
        """A cohesive grid solve (:func:`~viscocontact.methods.spectral.cohesive.
        cohesive_solve`, tips along the rows); on the first grid from the adhesionless
        solution (load control) or from no load (penetration control)."""
        its = apps = 0
        if start is None and load is not None:
            bare = grid_solve(level.circulant, level.heights, mean_pressure=load,
                              presolve=True, **self._grid_options())
            its, apps = bare.iterations, bare.applications
            start, start_pen = bare.pressure, bare.penetration
        elif start is None:
            start = np.zeros(level.heights.size)
        solved = cohesive_solve(level.circulant, level.heights, law, mean_pressure=load,
                                penetration=pen, start=start, start_penetration=start_pen,
                                rows=level.ny, contact_start=True,
                                **self._grid_options())
        sol = attrs.evolve(solved.solution, iterations=solved.solution.iterations + its,
                           applications=solved.solution.applications + apps)
        return sol, solved.contact, solved.weights

    @staticmethod
    def law(problem: ArealProblem, amplitude: float) -> GridLaw | None:
        """The problem's cohesive law on the grid, None without adhesion."""
        model = problem.adhesion
        if model is None or not float(model.work_of_adhesion) > 0:
            return None
        law = grid_law(model, amplitude)
        if law is None:
            raise ValidationError("ArealProblem.adhesion", model, "a finite-range law with a "
                                  "traction (maugis-dugdale, lennard-jones)")
        return law

def _assemble(method: ArealSpectral, kernel: ArealKernel, current: Measured, amplitude: float,
              m2: float, counts: tuple[int, int], fields: bool, common: dict,
              law: GridLaw | None = None) -> ContactResult:
    """The :class:`ContactResult` of the finest grid's solution, its extras and fields."""
    level, sol, extras = current.level, current.solution, common["extras"]
    shape = (level.ny, level.nx)
    p, gap = sol.pressure, current.gap
    loaded = current.contact
    pm = float(p.mean())
    workers = method.workers or 1
    weights = kernel.dissipation_weights(level.nx, level.ny)
    power = amplitude * _power(p.reshape(shape), weights, workers)
    stats = patch_statistics(loaded.reshape(shape), kernel.aspect, kernel.direction)
    extras.update(area_fraction=current.area / TWO_PI, mean_gap=float(gap.mean()),
                  dissipated_power=power, friction_dissipation=power / pm,
                  patches=stats.summary(), solver=sol.solver, amplitude=amplitude)
    fld = None
    if fields:
        y, x = np.mgrid[0:level.ny, 0:level.nx]
        fld = {"x": x * TWO_PI / level.nx, "y": y * TWO_PI * kernel.aspect / level.ny,
               "heights": level.heights.reshape(shape), "pressure": p.reshape(shape),
               "displacement": (gap + level.heights - 1.0 + sol.penetration).reshape(shape),
               "gap": gap.reshape(shape), "patches": stats}
    full = bool(loaded.all())
    mu = current.friction
    return ContactResult(
        area=current.area, mean_pressure=pm, penetration=float(sol.penetration),
        friction=mu, reduced_friction=mu / math.sqrt(m2) if m2 > 0 else np.nan,
        n_contacts=1 if full else stats.count, edges=np.zeros((0, 2)), full_contact=full,
        converged=bool(sol.converged),
        status=SolveStatus.CONVERGED if sol.converged else SolveStatus.NOT_CONVERGED,
        message=("converged" if sol.converged else f"grid solve did not converge: "
                 f"{sol.message}") + ("" if extras["tolerance_met"] else
                                      f"; tolerance {method.tolerance:g} not met (estimate "
                                      f"{extras['error_estimate']:.2g})"),
        residual=(violation(gap, loaded) if law is None else
                  law_violation(p, gap, loaded, current.weights, law)),
        iterations=int(counts[0]), function_evaluations=int(counts[1]),
        min_gap=float(np.min(gap[~loaded])) if (~loaded).any() else 0.0,
        fields=fld, **common)


def _cohesive_extras(law: GridLaw, current: Measured, extras: dict) -> None:
    """The law and its zones in ``extras["cohesive"]``; an event when a zone spans fewer than
    :data:`~viscocontact.methods.spectral.cohesive.CELLS_PER_ZONE` cells."""
    cells = zone_cells(law, current.level.nx)
    w = current.weights
    extras["cohesive"] = {
        "strength": law.strength, "opening": law.opening, "zone": law.zone,
        "cells_per_zone": cells,
        "cohesive_cells": 0 if w is None else int(np.sum((w > 0) & ~current.contact))}
    if cells < CELLS_PER_ZONE:
        extras["events"].append(
            f"the cohesive zone q0a0 = {law.zone:.3g} spans {cells:.1f} cells (fewer than "
            f"{CELLS_PER_ZONE:g}): under-resolved along x")


def _refine(pressure: np.ndarray, level: Level, inside: bool = True,
            gap: np.ndarray | None = None) -> np.ndarray:
    """A coarse pressure carried to the grid twice as fine: the coarse values at the coinciding
    centres, the mean of the neighbours between them; with ``inside`` only where all of those
    neighbours carry load, or where one does and the coarse solution's edge (``gap`` given: its
    sub-cell place along the grid lines, :func:`~.results.edge_corrections`, as the area places
    it) lies beyond the fine centre, half a coarse cell out; zero elsewhere. The first loaded
    set is then the fine grid's to within the edge estimates (flat, row by row)."""
    p = pressure.reshape(level.ny, level.nx)
    if gap is not None and inside:
        g = gap.reshape(level.ny, level.nx)
        beyond = (edge_corrections(p, g, axis=1) > 0, edge_corrections(p, g, axis=0) > 0)
    else:
        beyond = (np.zeros(p.shape, bool), np.zeros(p.shape, bool))

    def between(a, axis, out_beyond):
        right = np.roll(a, -1, axis=axis)
        mean = 0.5 * (a + right)
        if not inside:
            return mean
        # one side loaded: the loaded side's edge is past the middle
        reach = (a > 0) & out_beyond | (right > 0) & np.roll(out_beyond, -1, axis=axis)
        return np.where(((a > 0) & (right > 0)) | reach, mean, 0.0)

    out = np.empty((2 * level.ny, 2 * level.nx))
    out[0::2, 0::2] = p
    out[0::2, 1::2] = between(p, 1, beyond[0])
    # across the rows: the coarse columns' edges, each fine column with its coarse column's
    out[1::2, :] = between(out[0::2, :], 0, np.repeat(beyond[1], 2, axis=1))
    return out.ravel()


def _changes(coarse: Measured, fine: Measured, m2: float, floor: float) -> tuple[float, float]:
    d_area = abs(fine.area - coarse.area) / max(fine.area, 1e-300)
    scale = max(abs(fine.friction), floor * math.sqrt(max(m2, 0.0)), 1e-300)
    d_mu = abs(fine.friction - coarse.friction) / scale
    return float(d_area), float(d_mu) if np.isfinite(d_mu) else 0.0


def _m2(fine: np.ndarray, kernel: ArealKernel) -> float:
    """Mean square slope of ``q0 h`` along the sliding direction (spectral derivative)."""
    ny, nx = fine.shape
    spec = np.fft.rfft2(fine)
    qx = np.arange(nx // 2 + 1)[None, :]
    qy = np.fft.fftfreq(ny, 1.0 / ny)[:, None] / kernel.aspect
    ds = 1j * (math.cos(kernel.direction) * qx + math.sin(kernel.direction) * qy)
    if nx % 2 == 0:
        ds = ds * (qx < nx // 2)
    slope = np.fft.irfft2(spec * ds, fine.shape)
    return float(np.mean(slope**2))


def _power(pressure: np.ndarray, weights: np.ndarray, workers: int = 1) -> float:
    """``Σ_q |P_q|² D_q`` over the full spectrum from the rfft2 layout (the modes ``n`` and
    ``nx - n`` of the inner columns together)."""
    import scipy.fft

    ny, nx = pressure.shape
    spec = np.abs(scipy.fft.rfft2(pressure, workers=workers)) ** 2 / (nx * ny) ** 2
    spec[:, 1:nx // 2] *= 2.0
    return float(np.sum(spec * weights))
