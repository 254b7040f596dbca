r"""The result of a spectral solve: the final grid's measures, fields and diagnostics as a
:class:`~viscocontact.result.ContactResult` (:func:`contact_result`)."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...result import ContactResult, SolveStatus
from .closed import ClosedContact
from .cohesive import GridLaw, law_violation, zone_cells
from .edges import runs
from .measures import GridMeasures
from .operator import convolve
from .solvers import violation


def _cohesive_extras(law: GridLaw, current: GridMeasures) -> dict:
    """``extras["cohesive"]``: the law, its zones' cells and their share of the load."""
    w, loaded, points = current.weights, current.contact, current.grid.points
    assert w is not None            # a cohesive law's measures carry its weights
    alone = sum(1 for f, n in runs(w > 0) if not loaded[(f + np.arange(n)) % points].any())
    return {"strength": law.strength, "opening": law.opening, "zone": law.zone,
            "cells_per_zone": zone_cells(law, points),
            "cohesive_cells": int(np.sum((w > 0) & ~loaded)),
            # the zones' share of p̃∞ (tensile)
            "load": float(-law.strength * np.sum(np.where(loaded, 0.0, w)) / points),
            "tension_without_contact": int(alone)}


def contact_result(problem, prep, current: GridMeasures, *, iterations: int, applications: int,
                   fields: bool, extras: dict, closed: ClosedContact, law: GridLaw | None,
                   tolerance: float, workers: int) -> ContactResult:
    """The result of the final grid of a spectral solve.

    Parameters
    ----------
    problem : ContactProblem
    prep : SpectralPrepared
        The problem's tables and operator cache.
    current : GridMeasures
        The final grid's solution and measures.
    iterations, applications : int
        Solver steps and operator products, summed over the grids.
    fields : bool
        Return ``x``, ``pressure``, ``displacement`` and ``gap`` on the final grid.
    extras : dict
        The solve's diagnostics, completed here (the dissipated power's friction, the solver,
        a cohesive law's zones) and returned in the result.
    closed : ClosedContact
        The closed contact, returned when every cell is loaded.
    law : GridLaw or None
        The cohesive law (None: adhesionless).
    tolerance : float
        The requested accuracy, named in the message when the estimate misses it.
    workers : int
        Threads of ``scipy.fft``.
    """
    grid, sol = current.grid, current.solution
    common: dict[str, Any] = dict(iterations=int(iterations),
                                  function_evaluations=int(applications),
                                  zeta=float(problem.zeta), edge_perturbation=0.0, extras=extras)
    if current.closed:
        return closed.result(prep.m2, common, problem.mean_pressure, problem.penetration,
                             fields, message="every cell loaded: contact closed over the "
                                             "period to the grid's resolution",
                             strength=0.0 if law is None else law.strength)
    p = sol.pressure
    op = prep.operators.circulant(prep.kernel, grid.points)
    u = convolve(p, op.eigenvalues, workers)
    gap = u - (grid.heights - 1.0 + sol.penetration)
    loaded = current.contact
    pm = float(p.mean())
    if law is not None:
        extras["cohesive"] = _cohesive_extras(law, current)
    extras["friction_dissipation"] = current.dissipation
    extras["solver"] = sol.solver
    mu = current.friction
    sqrt_m2 = math.sqrt(prep.m2) if prep.m2 > 0 else np.nan
    fld = ({"x": grid.x.copy(), "pressure": p.copy(), "displacement": u, "gap": gap}
           if fields else None)
    return ContactResult(
        area=current.area, mean_pressure=pm, penetration=float(sol.penetration), friction=mu,
        reduced_friction=mu / sqrt_m2, n_contacts=len(runs(loaded)),
        edges=current.edges, full_contact=False, converged=bool(sol.converged),
        status=SolveStatus.CONVERGED if sol.converged else SolveStatus.NOT_CONVERGED,
        message=("converged" if sol.converged else f"grid solve did not converge: "
                 f"{sol.message}") + ("" if extras["tolerance_met"] else
                                      f"; tolerance {tolerance:g} not met (estimate "
                                      f"{extras['error_estimate']:.2g})"),
        residual=(violation(gap, loaded) if law is None
                  else law_violation(p, gap, loaded, current.weights, law)),
        min_gap=float(np.min(gap[~loaded])) if (~loaded).any() else 0.0,
        fields=fld, **common)
