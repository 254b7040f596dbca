"""The plan of an areal solve (``ArealSpectral.plan``): what is computed and why, before
anything is."""
from __future__ import annotations

import numpy as np

from ..kernels.clausen import TWO_PI
from ..methods.spectral.cohesive import CELLS_PER_ZONE, zone_cells
from ..plan import PlanStep, SolvePlan


#: Bytes per cell of a solve besides the GMRES basis (heights, slopes, pressure, gaps, search
#: directions, the eigenvalue tables and the FFT work arrays): the peak resident memory of a
#: 1024² solve at 10 % contact rose by 160 bytes per cell over the interpreter's, GMRES basis
#: included (``benchmarks/areal.py``).
BYTES_PER_CELL = 200
#: Restart length of the active set's GMRES (its basis and directions: ``2·restart`` vectors).
RESTART = 60
#: Share of the cells the GMRES basis is planned for (its vectors live on the loaded cells).
PLANNED_CONTACT = 0.25

def plan_steps(method, problem) -> SolvePlan:
    """The decisions of ``method`` (an :class:`~viscocontact.areal.method.ArealSpectral`) on
    ``problem``: method, adhesion (cells per zone, or how many a side it needs), grids, memory,
    solver and estimate."""
    nx, ny = method.grid_of(problem)
    kernel = problem.areal_kernel()
    viscous = bool(np.any(kernel.prepared.all_weights > 0) and 0 < problem.zeta
                   and np.isfinite(problem.zeta))
    need = method.memory(nx, ny, symmetric=not viscous)
    grids = " → ".join(f"{a}×{b}" for a, b in method.ladder(nx, ny))
    law = method.law(problem, float(np.max(problem.heights(nx, ny))))
    cohesive: tuple = ()
    if law is not None:
        cells = zone_cells(law, nx)
        cohesive = (PlanStep(
            stage="adhesion",
            choice=f"cohesive law cell by cell: tension σ̃0 = {law.strength:.4g} where the "
                   f"gap is below η = {law.opening:.4g}; tips along the rows; {cells:.1f} "
                   f"cells per quasi-static zone q0a0 = {law.zone:.3g}",
            reason=(f"at least {CELLS_PER_ZONE:g} cells per zone wanted" if
                    cells >= CELLS_PER_ZONE else
                    f"UNDER-RESOLVED: fewer than {CELLS_PER_ZONE:g} cells per zone; the "
                    f"zone needs {int(np.ceil(CELLS_PER_ZONE * TWO_PI / law.zone))} cells "
                    "a side")),)
    return SolvePlan(steps=(
        PlanStep(stage="method", choice="areal spectral: uniform 2D grid, rfft2 products",
                 reason="adhesionless areal scene" if law is None else
                        "finite-range cohesive law (wide zones)"),
        *cohesive,
        PlanStep(stage="grid", choice=f"{grids} cells (nested iteration)",
                 reason="the array's own grid" if problem.native_points else
                        "points" if method.points else
                        f"default 256 per side, doubled until the estimate is <= "
                        f"{method.tolerance:g} (at most {method.max_points} a side)"),
        PlanStep(stage="memory", choice=f"{need / 1e6:.0f} MB planned",
                 reason=f"limit {method.max_memory / 1e6:.0f} MB; {BYTES_PER_CELL} B per "
                        "cell" + ("" if not viscous else
                                  f" + GMRES basis and directions, 2×{RESTART} vectors on "
                                  f"{PLANNED_CONTACT:.0%} of the cells")),
        PlanStep(stage="solver", choice="active set + GMRES" if viscous else
                 "Polonsky-Keer conjugate gradients",
                 reason="viscoelastic operator (not symmetric)" if viscous else
                        "symmetric operator"),
        PlanStep(stage="estimate", choice="Richardson on the area and μ between the two "
                                          "finest grids", reason=f"tolerance "
                                                                 f"{method.tolerance:g}")))

