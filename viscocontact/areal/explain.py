"""The plan of an areal scene's solve (``viscocontact solve --explain``): the method's decisions
(:func:`~viscocontact.areal.planning.plan_steps`: grids, memory, cells per cohesive zone,
solver, estimate), whether the memory fits, and a time estimate.

The time estimate counts the FFT products of the solve: about :data:`PRODUCTS` operator
products per grid of the ladder (300 to 500 measured by ``benchmarks/areal.py`` on the
acceptance scene, nearly independent of the grid), :data:`COHESIVE_FACTOR` times as many with a
cohesive law (its zones are iterated), at :data:`SECONDS_PER_CELL_PRODUCT` seconds per cell and
product (1.7e-8 to 2.5e-8 s measured from 256² to 1024² on a shared two-core machine). It is an
order of magnitude, not a promise: the number of products depends on the contact.
"""
from __future__ import annotations

import numpy as np

from ..plan import PlanStep, SolvePlan

#: Operator products per grid of the ladder (``benchmarks/results/raw/areal.json``: 300-500).
PRODUCTS = 400
#: Seconds per cell and operator product (two FFTs; 1.7e-8 to 2.5e-8 measured).
SECONDS_PER_CELL_PRODUCT = 2e-8
#: A cohesive solve's products over an adhesionless one's (zones iterated; 5-10 measured at 256²).
COHESIVE_FACTOR = 10


def estimated_seconds(grids, cohesive: bool = False) -> float:
    """Seconds a solve on the ladder ``grids`` (``[(nx, ny), ...]``) is estimated to take."""
    cells = sum(nx * ny for nx, ny in grids)
    return float(SECONDS_PER_CELL_PRODUCT * PRODUCTS * cells
                 * (COHESIVE_FACTOR if cohesive else 1))


def _duration(seconds: float) -> str:
    if seconds < 1.0:
        return "under a second"
    if seconds < 120.0:
        return f"about {seconds:.0f} s"
    return f"about {seconds / 60.0:.0f} min"


def scene_plan(scene) -> SolvePlan:
    """The :class:`~viscocontact.plan.SolvePlan` of an
    :class:`~viscocontact.areal.scene.ArealScene`: the method's steps, then ``memory check``
    (fits, or refused with the figure needed) and ``time``."""
    method, problem = scene.method, scene.problem()
    steps = list(method.plan(problem).steps)
    nx, ny = method.grid_of(problem)
    need = method.memory(nx, ny)
    if need > method.max_memory:
        fits = _largest_fitting(method, nx, ny)
        steps.append(PlanStep(
            stage="memory check",
            choice=f"REFUSED: {need / 1e6:.0f} MB needed for {nx}×{ny} cells",
            reason=f"max_memory {method.max_memory / 1e6:.0f} MB; "
                   + (f"{fits[0]}×{fits[1]} cells fit" if fits else "no grid fits")))
    else:
        steps.append(PlanStep(stage="memory check", choice="fits",
                              reason=f"{need / 1e6:.0f} MB of max_memory "
                                     f"{method.max_memory / 1e6:.0f} MB"))
    grids = method.ladder(nx, ny)
    law = scene.adhesive and method.law(problem, 1.0) is not None
    seconds = estimated_seconds(grids, cohesive=law)
    refine = (problem.native_points is None and method.points is None)
    steps.append(PlanStep(
        stage="time",
        choice=_duration(seconds) + (" for the first finest grid; each doubling about 4× more"
                                     if refine else ""),
        reason=f"~{PRODUCTS} operator products per grid at "
               f"{SECONDS_PER_CELL_PRODUCT:.0e} s per cell"
               + (f", ×{COHESIVE_FACTOR} for the cohesive zones" if law else "")
               + " (an order of magnitude)"))
    return SolvePlan(steps=tuple(steps))


def _largest_fitting(method, nx: int, ny: int):
    """The finest grid ``(nx, ny)/2^k`` within ``max_memory`` (None if even 8 cells a side do
    not fit)."""
    while min(nx, ny) >= 16 and nx % 2 == 0 and ny % 2 == 0:
        nx, ny = nx // 2, ny // 2
        if method.memory(nx, ny) <= method.max_memory:
            return nx, ny
    return None


def cells_per_zone(scene) -> float | None:
    """Cells of the finest grid per quasi-static cohesive zone (None without a cohesive law)."""
    from ..methods.spectral.cohesive import zone_cells

    problem = scene.problem()
    nx, ny = scene.method.grid_of(problem)
    law = scene.method.law(problem, float(np.max(problem.heights(nx, ny))))
    return None if law is None else float(zone_cells(law, nx))
