r"""What an areal solve measures: contact area, gaps, friction, dissipation and contact patches.

All functions take grid fields of shape ``(ny, nx)`` on the cell ``[0, 2π) × [0, 2π·aspect)``
(cells of ``hx = 2π/nx`` by ``hy = 2π·aspect/ny`` centred at the samples) in the units of
:class:`~viscocontact.areal.problem.ArealProblem`.

* Area (:func:`area_fraction`): along the grid lines closest to the sliding direction the
  contact's edges are placed to a fraction of a cell from the square-root field at an
  adhesionless edge, as the 1D spectral method places them
  (:mod:`viscocontact.methods.spectral.edges`); the area fraction is the mean contact length
  per line over the line's length. A surface extruded across the sliding direction has the 1D
  method's area.
* Friction (:func:`friction`): ``μ = -<p ∂h/∂s>/<p>`` with ``∂h/∂s`` the slope of the rigid
  surface along the sliding direction (eq. 4.16 in 2D), the rise of each cell from the
  trigonometric interpolant of the heights (exact for a band-limited surface, and equal to the
  1D method's rise on an extruded one).
* Patches (:func:`patch_statistics`): connected components of the contact cells
  (4-connectivity, :func:`scipy.ndimage.label`) joined across the periodic boundaries; their
  areas, and from the second moments of their cells (each cell a uniform rectangle) the
  orientation of the major axis against the sliding direction and the elongation
  ``√(λ_max/λ_min)``.
"""
from __future__ import annotations

import attrs
import numpy as np
import scipy.fft
import scipy.ndimage

from ..kernels.clausen import TWO_PI
from ..methods.spectral.edges import edge_offset, gap_edge_offset


def cell_rise(heights: np.ndarray, step: int = 1, axis: int = 1) -> np.ndarray:
    """``h(c + H/2) - h(c - H/2)`` along ``axis`` at the centres ``c`` of the grid coarsened by
    ``step`` (``H = step`` fine cells) from the trigonometric interpolant of the fine samples
    ``heights``; shape of ``heights[::step, ::step]``."""
    h = np.asarray(heights, dtype=float)
    n = h.shape[axis]
    spec = scipy.fft.rfft(h, axis=axis)
    k = np.arange(spec.shape[axis], dtype=float)
    shift = 2j * np.sin(np.pi * k * step / n)
    if n % 2 == 0:
        shift[-1] = 0.0            # the Nyquist mode has no defined shifted value
    shape = [1, 1]
    shape[axis] = -1
    rise = scipy.fft.irfft(spec * shift.reshape(shape), n, axis=axis)
    return rise[::step, ::step]


def edge_corrections(pressure: np.ndarray, gap: np.ndarray, axis: int = 1,
                     reverse: bool = False) -> np.ndarray:
    """Sub-cell shifts of the contact edges along ``axis``, in cells, at the cells that end a
    run of at least three loaded cells (zero elsewhere): ``θ - 1/2`` with ``θ`` the edge's
    offset beyond the outermost loaded centre, the start's from ``p_first/p_next``
    (:func:`~viscocontact.methods.spectral.edges.edge_offset`) and the end's from the gaps of
    the next two free cells (from the pressures when the next contact leaves fewer than two
    free cells), as :func:`~viscocontact.methods.spectral.edges.contact_edges` places them:
    the start is the trailing edge of a solid sliding along ``+axis`` (``reverse``: along
    ``-axis``, the roles swapped), whose pressures are clean of the memory's ``x log x``
    term, the end the leading one, whose gaps are."""
    if reverse:
        flipped = edge_corrections(np.flip(pressure, axis), np.flip(gap, axis), axis)
        return np.flip(flipped, axis)
    p = np.asarray(pressure, dtype=float)
    g = np.asarray(gap, dtype=float)
    loaded = p > 0

    def roll(a, s):
        return np.roll(a, s, axis=axis)

    long_start = loaded & ~roll(loaded, 1) & roll(loaded, -1) & roll(loaded, -2)
    long_end = loaded & ~roll(loaded, -1) & roll(loaded, 1) & roll(loaded, 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        left = edge_offset(np.where(long_start, p / roll(p, -1), 0.0))
        g1, g2 = roll(g, -1), roll(g, -2)
        by_gap = (roll(p, -2) == 0.0) & (g1 > 0.0) & (g1 < g2)
        right = np.where(by_gap, gap_edge_offset(np.where(by_gap, g1 / g2, 0.0)),
                         edge_offset(np.where(long_end, p / roll(p, 1), 0.0)))
    return np.where(long_start, left - 0.5, 0.0) + np.where(long_end, right - 0.5, 0.0)


def row_lengths(pressure: np.ndarray, gap: np.ndarray, cell: float) -> np.ndarray:
    """Contact length of every row (shape ``(ny,)``), ``x̃`` units, at most ``2π``: the 1D
    method's contacts (:func:`~viscocontact.methods.spectral.edges.contact_edges`) row by row
    (:func:`edge_corrections` along ``x̃``)."""
    loaded = np.asarray(pressure) > 0
    extra = edge_corrections(pressure, gap, axis=1)
    return np.minimum(cell * (loaded.sum(axis=1) + extra.sum(axis=1)), TWO_PI)


def area_fraction(pressure: np.ndarray, gap: np.ndarray, direction: float = 0.0) -> float:
    """The real contact area over the cell's area.

    The contacts' edges are located along the grid lines closest to the sliding ``direction``
    (radians from ``x̃``: the rows, or the columns when ``|sin| > |cos|``), each line's
    contacts as the 1D method places them (:func:`edge_corrections`, the leading edge from the
    gaps and the trailing one from the pressures); the area is the mean contact length per
    line (the midpoint rule across the lines). A surface extruded across the sliding direction
    has the 1D method's area. (The lines across the sliding direction, or both families
    weighted by the boundary's orientation, converged more slowly on rough surfaces: on a
    512² self-affine surface 2e-3 to 6e-3 off the converged area, against 1e-3 along it.)
    """
    p = np.asarray(pressure, dtype=float)
    along_x = abs(np.cos(direction)) >= abs(np.sin(direction))
    axis = 1 if along_x else 0
    reverse = bool(np.cos(direction) < 0) if along_x else bool(np.sin(direction) < 0)
    loaded = p > 0
    extra = edge_corrections(p, gap, axis, reverse=reverse)
    cells = p.shape[axis]
    lengths = np.minimum(loaded.sum(axis=axis) + extra.sum(axis=axis), cells)
    return float(np.mean(lengths) / cells)


def friction(pressure: np.ndarray, slope: np.ndarray) -> float:
    """``μ = -<p ∂h/∂s>/<p>`` (NaN without load)."""
    pm = float(np.mean(pressure))
    return float(-np.mean(pressure * slope) / pm) if pm != 0.0 else float("nan")


# ---- patches -------------------------------------------------------------------------------
@attrs.frozen(kw_only=True, eq=False)
class PatchStatistics:
    """The contact patches of one solution (periodic connected components of contact cells).

    Attributes
    ----------
    areas : ndarray
        Area of each patch, ``x̃ ỹ`` units (``q0²`` times the physical area), largest first.
    orientations : ndarray
        Angle of each patch's major axis from the sliding direction, radians in ``(-π/2, π/2]``.
    elongations : ndarray
        ``√(λ_max/λ_min)`` of each patch's second-moment tensor (1 for a disc or a square).
    anisotropy : ndarray
        ``(λ_max - λ_min)/(λ_max + λ_min)`` of each patch (0 for a disc).
    percolating : int
        Patches that wrap around the cell (their moments are not defined: NaN).
    """

    areas: np.ndarray
    orientations: np.ndarray
    elongations: np.ndarray
    anisotropy: np.ndarray
    percolating: int = 0

    @property
    def count(self) -> int:
        return int(self.areas.size)

    @property
    def alignment(self) -> float:
        """Area-weighted ``<anisotropy · cos 2φ>``: +1 for patches drawn out along the sliding
        direction, -1 across it, 0 isotropic (NaN without patches)."""
        ok = np.isfinite(self.orientations)
        if not ok.any():
            return float("nan")
        a = self.areas[ok]
        return float(np.sum(a * self.anisotropy[ok] * np.cos(2 * self.orientations[ok]))
                     / np.sum(a))

    def summary(self) -> dict:
        """Plain numbers: count, mean/median/largest area, area-weighted mean elongation,
        alignment, percolating patches."""
        if self.count == 0:
            return {"count": 0, "mean_area": 0.0, "median_area": 0.0, "largest_area": 0.0,
                    "mean_elongation": float("nan"), "alignment": float("nan"),
                    "percolating": 0}
        ok = np.isfinite(self.elongations)
        mean_el = (float(np.sum(self.areas[ok] * self.elongations[ok]) / np.sum(self.areas[ok]))
                   if ok.any() else float("nan"))
        return {"count": self.count, "mean_area": float(self.areas.mean()),
                "median_area": float(np.median(self.areas)),
                "largest_area": float(self.areas.max()), "mean_elongation": mean_el,
                "alignment": self.alignment, "percolating": int(self.percolating)}


def periodic_labels(mask: np.ndarray) -> tuple[np.ndarray, int]:
    """Labels ``1..n`` of the 4-connected components of ``mask`` on a periodic grid (0 outside)."""
    labels, n = scipy.ndimage.label(np.asarray(mask, bool))
    if n == 0:
        return labels, 0
    parent = np.arange(n + 1)

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a_side, b_side in ((labels[:, 0], labels[:, -1]), (labels[0, :], labels[-1, :])):
        both = (a_side > 0) & (b_side > 0)
        for a, b in zip(a_side[both], b_side[both]):
            ra, rb = find(int(a)), find(int(b))
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    roots = np.array([find(i) for i in range(n + 1)])
    unique, compact = np.unique(roots, return_inverse=True)
    # root 0 is the background; the others get 1..m in order
    return compact[labels].reshape(labels.shape), int(unique.size - 1)


def patch_statistics(mask: np.ndarray, aspect: float = 1.0,
                     direction: float = 0.0) -> PatchStatistics:
    """Areas, orientations and elongations of the periodic patches of ``mask`` (shape
    ``(ny, nx)``) on the cell ``[0, 2π) × [0, 2π·aspect)``, the orientation measured from the
    sliding ``direction`` (radians from ``x̃``)."""
    mask = np.asarray(mask, bool)
    ny, nx = mask.shape
    labels, n = periodic_labels(mask)
    if n == 0:
        empty = np.zeros(0)
        return PatchStatistics(areas=empty, orientations=empty, elongations=empty,
                               anisotropy=empty)
    lx, ly = TWO_PI, TWO_PI * aspect
    hx, hy = lx / nx, ly / ny
    jj, ii = np.nonzero(mask)
    lab = labels[jj, ii]
    x, y = ii * hx, jj * hy
    count = np.bincount(lab, minlength=n + 1)[1:].astype(float)

    def centred(coord, length):
        # the circular mean of each patch, then every cell within half a period of it
        ang = TWO_PI * coord / length
        c = np.arctan2(np.bincount(lab, np.sin(ang), n + 1)[1:],
                       np.bincount(lab, np.cos(ang), n + 1)[1:]) * length / TWO_PI
        d = np.mod(coord - c[lab - 1] + 0.5 * length, length) - 0.5 * length
        mean = np.bincount(lab, d, n + 1)[1:] / count
        return d - mean[lab - 1]

    dx, dy = centred(x, lx), centred(y, ly)
    sxx = np.bincount(lab, dx * dx, n + 1)[1:] / count + hx * hx / 12.0
    syy = np.bincount(lab, dy * dy, n + 1)[1:] / count + hy * hy / 12.0
    sxy = np.bincount(lab, dx * dy, n + 1)[1:] / count
    half_trace = 0.5 * (sxx + syy)
    radius = np.hypot(0.5 * (sxx - syy), sxy)
    big, small = half_trace + radius, half_trace - radius
    angle = 0.5 * np.arctan2(2.0 * sxy, sxx - syy) - direction
    angle = np.mod(angle + 0.5 * np.pi, np.pi) - 0.5 * np.pi
    angle = np.where(angle == -0.5 * np.pi, 0.5 * np.pi, angle)
    # a patch that wraps the cell in a direction has no defined moments
    wraps = _wrapping(labels, n)
    elong = np.sqrt(big / small)
    aniso = (big - small) / (big + small)
    angle, elong, aniso = (np.where(wraps, np.nan, v) for v in (angle, elong, aniso))
    order = np.argsort(-count, kind="stable")
    return PatchStatistics(areas=count[order] * hx * hy, orientations=angle[order],
                           elongations=elong[order], anisotropy=aniso[order],
                           percolating=int(wraps.sum()))


def _wrapping(labels: np.ndarray, n: int) -> np.ndarray:
    """Whether each patch (1..n) has cells in every column or in every row of the cell."""
    ny, nx = labels.shape
    jj, ii = np.nonzero(labels)
    lab = labels[jj, ii]
    columns = np.zeros((n + 1, nx), bool)
    rows = np.zeros((n + 1, ny), bool)
    columns[lab, ii] = True
    rows[lab, jj] = True
    return np.asarray(columns[1:].all(axis=1) | rows[1:].all(axis=1))
