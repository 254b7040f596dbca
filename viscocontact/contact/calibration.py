r"""The calibration of stress-intensity factors fitted on an edge-graded mesh.

On an edge-graded mesh the relative error of the collocation stress near an edge does not vanish
with refinement (the mesh is self-similar there), so the ``K̃`` fitted by
:func:`~viscocontact.contact.fields.stress_intensity` is off by a factor that depends on the mesh
type and on the contact's half-width (and the edge element's size over it, with edge zones): about
0.985 for n = 1 and 0.943 with geometric edge zones of ratio 1.25. The factor is the fitted over
the exact ``K̃`` of the homogeneous single-contact elastic field ``cos(x/2)/√(s² - sin²(x/2))`` on
the same mesh, tabulated over ``log`` half-width (and ``log`` edge element over half-width).

A table costs 26 (or 26 × 7) dense solves, 0.5 s for 64 elements per contact and more for more;
the tables of the default meshes (64 to 512 elements, the default clustering and grading, with and
without edge zones) ship with the package in :mod:`._calibration_data`, computed by this module
with one BLAS thread, and ``python -m viscocontact.contact.calibration`` writes them again (a test
checks that one of them is what this module computes). Other meshes are computed once per process.
"""
from __future__ import annotations

import functools

import numpy as np

from .._files import write_atomic
from .fields import stress_intensity
from .mesh import ZONE_CAP, MeshSpec, build_mesh

_CAL_ALPHA = np.concatenate([np.geomspace(1e-3, 0.5, 12), np.linspace(0.6, 3.1, 14)])
_CAL_REL = np.geomspace(1e-9, ZONE_CAP, 7)


def _fitted_ratio(pk, spec: MeshSpec, a: float) -> float:
    """The fitted over the exact ``K̃`` of one mesh, its influence matrix from the Clausen
    function in closed form (the reference the kernel's table is tested against: on edge
    elements of 1e-9 of the half-width the table's few ulps would move the ratios by up to
    1e-6, twice the round-off of the solve)."""
    from ..kernels.prepared import element_integrals

    mesh = build_mesh(np.array([-a, a]), spec)
    B = (element_integrals(pk.antiderivative_terms, mesh.mid, mesh.left, mesh.right)
         + pk.mean * (mesh.right - mesh.left))
    sigma = np.linalg.solve(B, np.ones(len(mesh.mid)))
    k_exact = np.sqrt(2 * np.pi / np.tan(a / 2)) / (2 * np.log(np.sin(a / 2)))
    return float(stress_intensity(mesh, sigma)[1] / k_exact)


@functools.lru_cache(maxsize=32)
def _calibration_table(elements: int, exponent: float, grading: float, zones: bool):
    """Interpolant of the fitted/exact ratio over log(half-width) (and log(h0/α) with zones):
    the shipped table of this mesh type, or one computed now."""
    from scipy.interpolate import PchipInterpolator

    from ._calibration_data import TABLES

    key = (int(elements), float(exponent), float(grading), bool(zones))
    ratios = TABLES.get(key)
    ratios = calibration_ratios(*key) if ratios is None else np.array(ratios)
    if not zones:
        return PchipInterpolator(np.log(_CAL_ALPHA), ratios, extrapolate=True)
    return _Bilinear(np.log(_CAL_ALPHA), np.log(_CAL_REL), ratios)


def calibration_ratios(elements: int, exponent: float, grading: float, zones: bool) -> np.ndarray:
    """Fitted over exact ``K̃`` at the half-widths ``_CAL_ALPHA`` (and, with edge zones, the edge
    element sizes ``_CAL_REL`` relative to the half-width), computed with one BLAS thread so that
    the table is the same in every process."""
    from .._blas import single_blas_thread
    from ..kernels.half_plane import HalfPlane
    from ..rheology.elastic import Elastic

    with single_blas_thread():
        pk = HalfPlane().prepare(Elastic(), 0.0)
        if not zones:
            spec = MeshSpec(elements=elements, exponent=exponent, grading=grading)
            return np.array([_fitted_ratio(pk, spec, a) for a in _CAL_ALPHA])
        return np.array([[_fitted_ratio(pk, MeshSpec(elements=elements, exponent=exponent,
                                                     grading=grading, smallest=rel * a), a)
                          for rel in _CAL_REL] for a in _CAL_ALPHA])


class _Bilinear:
    """Bilinear interpolation on a rectangular grid (the arithmetic of scipy's
    ``RegularGridInterpolator(method="linear")`` without its per-call overhead, which was a
    sixth of a residual evaluation); points are clipped to the grid beforehand."""

    def __init__(self, x0: np.ndarray, x1: np.ndarray, values: np.ndarray):
        self.x0, self.x1, self.values = x0, x1, values

    def __call__(self, points: np.ndarray) -> np.ndarray:
        p0, p1 = points[:, 0], points[:, 1]
        i = np.clip(np.searchsorted(self.x0, p0, side="right") - 1, 0, len(self.x0) - 2)
        j = np.clip(np.searchsorted(self.x1, p1, side="right") - 1, 0, len(self.x1) - 2)
        t = (p0 - self.x0[i]) / (self.x0[i + 1] - self.x0[i])
        u = (p1 - self.x1[j]) / (self.x1[j + 1] - self.x1[j])
        v = self.values
        return ((1 - t) * ((1 - u) * v[i, j] + u * v[i, j + 1])
                + t * ((1 - u) * v[i + 1, j] + u * v[i + 1, j + 1]))


def sif_calibration(spec: MeshSpec, half_width, first=None) -> np.ndarray:
    """Ratio of fitted to exact K̃ for the homogeneous single-contact elastic field
    ``cos(x/2)/√(s² - sin²(x/2))`` on a contact of the given half-width (mesh of the same spec;
    ``first``: the edge element's size over the half-width, with edge zones)."""
    table = _calibration_table(spec.elements, spec.exponent, spec.grading,
                               spec.smallest is not None)
    hw = np.clip(np.asarray(half_width, dtype=float), _CAL_ALPHA[0], _CAL_ALPHA[-1])
    if spec.smallest is None:
        return table(np.log(hw))
    if first is None:
        first = spec.smallest / np.asarray(half_width, dtype=float)
    rel = np.clip(first, _CAL_REL[0], _CAL_REL[-1])
    return table(np.column_stack([np.log(hw), np.log(rel)]))


#: The mesh types whose tables ship: the default :class:`~viscocontact.methods.bem.meshing.
#: Discretization` (clustering 1, grading 1.15) at every element count its interior refinement
#: gives, with and without edge zones.
SHIPPED = tuple((n, 1.0, 1.15, zones) for n in (64, 128, 256, 512) for zones in (False, True))


def write_shipped(path) -> None:
    """Compute the :data:`SHIPPED` tables and write them as the module :mod:`._calibration_data`."""
    lines = ['"""Shipped stress-intensity calibration tables: written by',
             '``python -m viscocontact.contact.calibration`` (see :mod:`.calibration`)."""',
             "", "TABLES = {"]
    for key in SHIPPED:
        ratios = calibration_ratios(*key)
        rows = ratios.reshape(len(_CAL_ALPHA), -1) if key[3] else ratios[:, None]
        lines.append(f"    {key!r}: [")
        for row in rows:
            values = ", ".join(repr(float(v)) for v in row)
            lines.append(f"        [{values}]," if key[3] else f"        {values},")
        lines.append("    ],")
    lines += ["}", ""]
    write_atomic(path, "\n".join(lines).encode())


if __name__ == "__main__":
    from pathlib import Path

    write_shipped(Path(__file__).resolve().with_name("_calibration_data.py"))
