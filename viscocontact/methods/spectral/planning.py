r"""What a spectral solve will compute: the first trusted grid (:func:`first_points`,
:func:`trusted_points`) and the steps of its plan (:func:`plan`, shown by ``solve --explain``)."""
from __future__ import annotations

import math

import numpy as np

from ...kernels.clausen import TWO_PI
from .approach import ApproachSettings
from .cohesive import CELLS_PER_ZONE, GridLaw, zone_cells
from .estimate import ORDER

#: Cells per shortest wavelength of the profile at tolerance 1e-3 (scaled by
#: ``(1e-3/tolerance)^(1/ORDER_AREA)``) for the first fine grid.
CELLS_PER_WAVELENGTH = 32.0
#: Fewest cells of the first fine grid when the tolerance does not ask for more.
FIRST_POINTS = 256
#: Expected convergence order of Ã, which sizes the first grid for a tolerance.
ORDER_AREA = 2.0


def first_points(wavelength: float | None, tolerance: float, max_points: int) -> int:
    """The first fine grid: ``CELLS_PER_WAVELENGTH`` cells per shortest wavelength of the profile
    at tolerance 1e-3, scaled with ``tolerance^(-1/ORDER_AREA)``, rounded up to a power of two,
    at least :data:`FIRST_POINTS`, at most ``max_points``."""
    per = CELLS_PER_WAVELENGTH * (1e-3 / tolerance) ** (1.0 / ORDER_AREA)
    span = TWO_PI / wavelength if wavelength else 32.0
    want = max(per * span, FIRST_POINTS)
    n = 1 << int(math.ceil(math.log2(want)))
    return int(min(n, max_points - max_points % 2))


def trusted_points(method, wavelength: float | None, law: GridLaw | None) -> int:
    """Cells of the first trusted grid of an automatic ladder.

    Parameters
    ----------
    method : Spectral
        Its ``tolerance`` and ``max_points``.
    wavelength : float or None
        The profile's shortest wavelength (``x̃`` units; None: unknown).
    law : GridLaw or None
        A cohesive law, whose zones are resolved from the first trusted grid on
        (:meth:`Spectral.zone_points`).

    Returns
    -------
    int
        :func:`first_points`, raised to resolve the cohesive zones, at most ``max_points``.
    """
    n = first_points(wavelength, method.tolerance, method.max_points)
    if law is not None:                # the cohesive zones resolved from the start
        n = min(max(n, method.zone_points(law)), method.max_points)
    return n


def cohesive_plan(law: GridLaw, points: int, settings: ApproachSettings, model: str) -> tuple:
    """The plan's steps of a cohesive law (of the adhesion model named ``model``) on a first
    trusted grid of ``points`` cells."""
    from ...plan import PlanStep

    return (PlanStep(stage="adhesion",
                     choice=(f"cohesive law cell by cell: tension σ̃0 = {law.strength:.4g} "
                             f"where the gap is below η = {law.opening:.4g}; tips between cells "
                             "by the secant of the gap; " if isinstance(law, GridLaw) else
                             f"traction law cell by cell: peak tension {law.strength:.4g}, the "
                             "tension a fixed point of the gaps; ")
                            + f"{zone_cells(law, points):.0f} cells per quasi-static zone "
                              f"q0a0 = {law.zone:.3g} on the first trusted grid",
                     reason=f"{model}: at least {CELLS_PER_ZONE:g} cells per zone"),
            PlanStep(stage="history",
                     choice=f"approach from first touch (Δ̃ = -η) to the target on the first "
                            f"grid, steps of Δ̃ up to {settings.path_step:g}, events located "
                            f"to {settings.smallest:.2g}; the finer grids start from it",
                     reason="a non-convex law has several equilibria: the one reached by "
                            "quasi-static loading, as the boundary-element method's"))


def _grid_step(method, wavelength: float | None, law: GridLaw | None) -> tuple:
    """The plan's grid step and the cells of the first trusted grid."""
    from ...plan import PlanStep

    if method.points is not None:
        return PlanStep(stage="grid", choice=f"{method.points} cells, estimate from "
                        f"{method.points // 2}", reason="points given"), method.points
    n = trusted_points(method, wavelength, law)
    per = CELLS_PER_WAVELENGTH * (1e-3 / method.tolerance) ** (1.0 / ORDER_AREA)
    why_grid = (f"{per:.3g} cells per shortest wavelength λ_min = {wavelength:.4g} for "
                f"tolerance {method.tolerance:g}" if wavelength else
                f"shortest wavelength unknown: at least {n} cells")
    return PlanStep(stage="grid",
                    choice=f"{n // 2} then {n} cells, doubled up to {method.max_points} "
                           f"until the estimate is <= {method.tolerance:g}",
                    reason=why_grid), n


def _solver_steps(problem, prep, points: int) -> tuple:
    """The plan's operator and solver steps on a grid of ``points`` cells."""
    from ...plan import PlanStep

    op = prep.operators.circulant(prep.kernel, points)
    lam = op.eigenvalues
    asym = float(np.max(np.abs(lam.imag)) / np.max(np.abs(lam)))
    operator = PlanStep(stage="operator",
                        choice="circulant by FFT: Clausen closed form of the instantaneous "
                               "part + alias sums of the rest of the multiplier",
                        reason=f"{type(problem.kernel).__name__}, c0 = {prep.kernel.mean:.4g}")
    if op.symmetric:
        solver = PlanStep(stage="solver", choice="Polonsky-Keer conjugate gradients",
                          reason=f"the operator is symmetric (max|Im Λ|/max|Λ| = {asym:.2g})")
    else:
        solver = PlanStep(stage="solver",
                          choice="active set (semismooth Newton) + GMRES preconditioned by "
                                 "the inverse circulant; Polonsky-Keer on Re Λ to start",
                          reason=f"viscoelastic: the operator is not symmetric "
                                 f"(max|Im Λ|/max|Λ| = {asym:.2g})")
    return operator, solver


def plan(method, problem, prep, law: GridLaw | None) -> tuple:
    """The steps of a spectral solve of a problem it supports.

    Parameters
    ----------
    method : Spectral
    problem : ContactProblem
    prep : SpectralPrepared
        The problem's tables and the operator cache.
    law : GridLaw or None
        The scene's cohesive law on the grid (None: adhesionless).

    Returns
    -------
    tuple of PlanStep
        Method, grid, operator, solver, the cohesive law and its history (with a law),
        control, edges, estimate, reuse and fields.
    """
    from ...plan import PlanStep

    grid, n = _grid_step(method, prep.shape.wavelength, law)
    operator, solver = _solver_steps(problem, prep, n)
    control = ("load control, p̃∞ = " + f"{problem.mean_pressure:g}"
               if problem.mean_pressure is not None
               else "penetration control, Δ̃ = " + f"{problem.penetration:g}")
    cohesive = () if law is None else cohesive_plan(
        law, n, method.approach, type(problem.adhesion).__name__)
    return (PlanStep(stage="method", choice="spectral: uniform grid, FFT products",
                     reason="adhesionless scene" if law is None else
                            "finite-range cohesive law (wide zones)"),
            grid, operator, solver, *cohesive,
            PlanStep(stage="control", choice=control,
                     reason="the closed contact is returned directly when it carries the "
                            "load without tension"),
            PlanStep(stage="edges", choice="sub-cell edges: left ones from the pressures of "
                                           "the two outermost loaded cells, right ones from "
                                           "the gaps of the two first free cells" + (
                                               "" if law is None else " (pressures shifted "
                                               "by σ̃0: the Maugis–Dugdale edge field)"),
                     reason="universal square-root edge field (adhesionless); the memory "
                            "of a viscoelastic solid spoils the other side"),
            PlanStep(stage="estimate",
                     choice=f"Richardson on Ã and μ between N/2 and N (order {ORDER:g}), "
                            "at least half the change one level down",
                     reason=f"tolerance {method.tolerance:g}; μ relative to max(|μ|, "
                            f"{method.friction_floor:g}·√m2)"),
            PlanStep(stage="reuse", choice="eigenvalues once per (kernel, N) in "
                                           "SpectralPrepared (pass prepared= along a sweep)",
                     reason="they depend on rheology, kernel and ζ only"),
            PlanStep(stage="fields", choice="pressure, displacement and gap on the final "
                                            "grid only when asked", reason="fields=True"))
