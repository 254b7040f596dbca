"""An areal result as flat numbers: what ``viscocontact solve`` prints for an areal scene and what
a study stores per point (the areal columns of :data:`~viscocontact.studies.point.COLUMNS`).

The patch statistics (:class:`~viscocontact.areal.results.PatchStatistics`) are reduced to their
area-weighted means; the size distribution is kept whole (``patch_areas``, largest first).
"""
from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from .results import PatchStatistics


def _weighted(values: np.ndarray, areas: np.ndarray) -> float:
    ok = np.isfinite(values)
    if not ok.any():
        return float("nan")
    return float(np.sum(areas[ok] * values[ok]) / np.sum(areas[ok]))


def areal_quantities(result) -> dict[str, Any]:
    """The areal quantities of an :class:`~viscocontact.areal.method.ArealSpectral` result
    (solved with ``fields=True`` for the patch orientation and size distribution; without,
    those are NaN and empty).

    Keys: ``area_fraction``, ``mean_gap``, ``dissipated_power``, ``friction_dissipation``,
    ``patch_mean_area``, ``patch_largest_area``, ``patch_elongation`` (area-weighted mean
    ``√(λmax/λmin)``), ``patch_orientation`` (area-weighted mean ``|φ|`` of the major axis from
    the sliding direction, radians in ``[0, π/2]``), ``patch_alignment`` (area-weighted
    ``<anisotropy · cos 2φ>``), ``percolating``, ``cells_per_zone`` (NaN without a cohesive
    law), ``grid`` (``"nx×ny"`` of the finest grid) and ``patch_areas`` (JSON list, largest
    first).
    """
    extras = result.extras
    nan = float("nan")
    summary = extras.get("patches") or {}
    stats = (result.fields or {}).get("patches")
    orientation, areas = nan, "[]"
    if isinstance(stats, PatchStatistics) and stats.count:
        orientation = _weighted(np.abs(stats.orientations), stats.areas)
        areas = json.dumps([float(f"{a:.6g}") for a in stats.areas])
    points = extras.get("points")
    cohesive = extras.get("cohesive") or {}
    return {
        "area_fraction": float(extras.get("area_fraction", nan)),
        "mean_gap": float(extras.get("mean_gap", nan)),
        "dissipated_power": float(extras.get("dissipated_power", nan)),
        "friction_dissipation": float(extras.get("friction_dissipation", nan)),
        "patch_mean_area": float(summary.get("mean_area", nan)),
        "patch_largest_area": float(summary.get("largest_area", nan)),
        "patch_elongation": float(summary.get("mean_elongation", nan)),
        "patch_orientation": orientation,
        "patch_alignment": float(summary.get("alignment", nan)),
        "percolating": int(summary.get("percolating", 0)),
        "cells_per_zone": float(cohesive.get("cells_per_zone", nan)),
        "grid": "" if points is None else f"{points[0]}×{points[1]}",
        "patch_areas": areas,
    }


def areal_fields(result) -> dict[str, np.ndarray] | None:
    """The fields a study stores for an areal point: ``x`` and ``y`` (the grid's coordinates,
    1D), ``pressure``, ``displacement``, ``gap`` (shape ``(ny, nx)``)."""
    fields = result.fields
    if fields is None:
        return None
    return {"x": np.asarray(fields["x"][0], float), "y": np.asarray(fields["y"][:, 0], float),
            **{k: np.asarray(fields[k], float) for k in ("pressure", "displacement", "gap")}}


def areal_groups(scene) -> dict[str, Any]:
    """The dimensionless groups of an :class:`~viscocontact.areal.scene.ArealScene`
    (``viscocontact describe``): the component kinds, the grid, ``amplitude`` Λ̃ (its highest
    point on the grid), ``rms``, ``rms_slope``, ``m2x``, ``zeta``, ``direction``, ``beta``,
    ``poisson``, the load, ``gamma`` and with a cohesive law ``cohesive_stress`` σ̃0,
    ``range_ratio`` η (the range over Λ), ``quasi_static_zone`` q0a0 and ``cells_per_zone``;
    ``physical`` and ``warnings`` (an under-resolved zone)."""
    from ..components import _param, kind_of
    from ..methods.spectral.cohesive import CELLS_PER_ZONE, zone_cells
    from .surfaces import sample_statistics
    from .surfaces.tables import surface_table

    nx, ny = scene.grid
    stats = sample_statistics(scene.problem().heights(nx, ny), aspect=scene.problem().cell_aspect)
    groups: dict[str, Any] = {
        "surface": surface_table(scene.surface)["kind"],
        **{s: kind_of(s, getattr(scene, s)) for s in ("rheology", "kernel", "adhesion")},
        "grid": f"{nx}×{ny}", "amplitude": scene.amplitude, "rms": float(stats.rms),
        "rms_slope": float(stats.rms_slope), "m2x": float(stats.m2x), "zeta": scene.zeta,
        "direction": scene.direction, "beta": float(scene.rheology.modulus_ratio),
        "poisson": scene.poisson, scene.load.controlled: scene.load.value,
        "gamma": float(_param(scene.adhesion, "gamma") or 0.0) if scene.adhesive else 0.0}
    warnings: list[str] = []
    problem = scene.problem()
    law = scene.method.law(problem, scene.amplitude)
    if law is not None:
        cells = float(zone_cells(law, nx))
        groups.update(cohesive_stress=law.strength, range_ratio=law.opening,
                      quasi_static_zone=law.zone, cells_per_zone=cells)
        if cells < CELLS_PER_ZONE:
            need = int(math.ceil(CELLS_PER_ZONE * 2 * math.pi / law.zone))
            warnings.append(f"the cohesive zone spans {cells:.1f} cells of the {nx}×{ny} grid "
                            f"(fewer than {CELLS_PER_ZONE:g}): under-resolved; it needs {need} "
                            "cells a side")
    groups["physical"] = dict(scene.physical) if scene.physical is not None else None
    groups["warnings"] = warnings
    return groups
