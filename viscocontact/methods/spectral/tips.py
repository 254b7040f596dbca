r"""The tips of a cohesive law's zones on the spectral grid: where the runs of cells in range end
(:func:`tip_positions`), the share of each cell under the cohesive stress (:func:`tip_weights`),
and how the tips move from one inner solve of :func:`~.cohesive.cohesive_solve` to the next
(:func:`moved_tips`: by the secant of their residuals ``g - η``, else to where the gap crosses
``η``). Cell ``k`` spans ``[k - 1/2, k + 1/2]`` in cell coordinates; a run's extent is ``[L, R]``
in them, ``R >= L`` (unwrapped)."""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .edges import runs

if TYPE_CHECKING:
    from .grid_law import GridLaw

#: A tip's secant slope is used down to this fraction of the gap's own slope there.
FLATTEST_SLOPE = 0.05


def _runs(inside: np.ndarray) -> list[tuple[int, int]]:
    """``(first, last)`` of each cyclic run of True cells, ``last >= first`` (unwrapped)."""
    return [(f, f + n - 1) for f, n in runs(inside)]


def _interp(values: np.ndarray, position: float) -> float:
    """``values`` (periodic, at the integer cell coordinates) at ``position``, linearly."""
    k = int(np.floor(position))
    t = position - k
    n = values.size
    return float((1.0 - t) * values[k % n] + t * values[(k + 1) % n])


def tip_positions(gap, contact, law: GridLaw) -> list[tuple[float, float]]:
    """The extent ``[L, R]`` (cell coordinates: cell ``k`` spans ``[k - 1/2, k + 1/2]``) of each
    run of cells in range (in contact or with ``g < η``), its tips ``g = η`` placed by linear
    interpolation between the last centre in range and the first out of it."""
    g = np.asarray(gap, dtype=float)
    inside = np.asarray(contact, bool) | (g < law.opening)
    n = g.size
    if inside.all():
        return [(-0.5, n - 0.5)]
    out = []
    for first, last in _runs(inside):
        ends = []
        for a, b in ((first, first - 1), (last, last + 1)):
            rise = g[b % n] - g[a % n]
            t = (law.opening - g[a % n]) / rise if rise > 0 else 0.5
            ends.append(a + (b - a) * min(max(t, 0.0), 1.0))
        out.append((ends[0], ends[1]))
    return out


def tip_weights(extents, points: int) -> np.ndarray:
    """The share of each cell under the cohesive stress for runs of extents ``[L, R]``
    (:func:`tip_positions`): the cells within a run wholly, the cell that holds a tip in
    proportion to its part inside (a tip quantised to whole cells moves the load by up to
    ``σ̃0 h`` per tip, a first-order error that, on a slow solid, drowns its small friction)."""
    w = np.zeros(points)
    for lo, hi in extents:
        if hi - lo >= points:
            return np.ones(points)
        k = np.arange(int(np.floor(lo + 0.5)), int(np.floor(hi + 0.5)) + 1)
        share = np.clip(np.minimum(k + 0.5, hi) - np.maximum(k - 0.5, lo), 0.0, 1.0)
        np.add.at(w, k % points, share)
    return np.minimum(w, 1.0)


def same_runs(old, new, points: int) -> bool:
    """Whether two lists of run extents describe the same runs (same count, each new run
    overlapping its old one): the tips can then be moved by secants."""
    if len(old) != len(new):
        return False
    for (a, b), (c, d) in zip(old, new):
        if b - a >= points or d - c >= points or d < a or c > b:
            return False
    return True


def _secant(position, residual, before, slope_hint):
    """The next position of one tip from its last two residuals (``before``: the previous
    ``(position, residual)``), or None when they give no usable slope (same position, or a
    slope against the gap's own or flatter than :data:`FLATTEST_SLOPE` times it). Two residuals
    of opposite signs bracket the tip: the secant then interpolates between them, whatever its
    slope."""
    if before is None or position == before[0]:
        return None
    slope = (residual - before[1]) / (position - before[0])
    if residual * before[1] < 0.0:
        return position - residual / slope
    if not slope * slope_hint > 0 or abs(slope) < FLATTEST_SLOPE * abs(slope_hint):
        return None
    return position - residual / slope


def _tip_step(position, residual, before, fresh, slope_hint):
    """The next position of one tip: the secant (:func:`_secant`), else, when the fixed point
    ``fresh`` (where the gap crosses η) moves on in the direction of the last move but by less
    than twice it, twice the last move (a zone that grows under its own stress, the jump of a
    snap, or a soft zone whose fixed point creeps: the moves double until the residual changes
    sign, and the secant then interpolates), else ``fresh``."""
    moved = _secant(position, residual, before, slope_hint)
    if moved is not None:
        return moved
    if before is None:
        return fresh
    last, ahead = position - before[0], fresh - position
    if last * ahead > 0.0 and abs(ahead) < 2.0 * abs(last):
        return position + 2.0 * last
    return fresh


def row_tips(gap, contact, law: GridLaw, rows: int) -> list:
    """:func:`tip_positions` of every row (cells flat, row by row)."""
    g = np.asarray(gap).reshape(rows, -1)
    c = np.asarray(contact).reshape(rows, -1)
    return [tip_positions(gr, cr, law) for gr, cr in zip(g, c)]


def whole_row(extents, points: int) -> bool:
    """Whether a row is in range from end to end (one run over every cell: no tips)."""
    return len(extents) == 1 and extents[0][1] - extents[0][0] >= points


def moved_tips(extents, residuals, fresh, gap, before):
    """The next tips of one row: each by the secant of its last two residuals (``before``: the
    previous extents and residuals of the row), else where the gap crosses η (``fresh``)."""
    moved = []
    for j, ((lo, hi), (r_lo, r_hi), (f_lo, f_hi)) in enumerate(zip(extents, residuals, fresh)):
        old = None if before is None else before[j]
        new_lo = _tip_step(lo, r_lo, None if old is None else (old[0][0], old[1][0]), f_lo,
                           _interp(gap, lo + 0.5) - _interp(gap, lo - 0.5))
        new_hi = _tip_step(hi, r_hi, None if old is None else (old[0][1], old[1][1]), f_hi,
                           _interp(gap, hi + 0.5) - _interp(gap, hi - 0.5))
        moved.append((new_lo, new_hi))
    return moved


def contact_extents(contact, width: int) -> list:
    """The run extents of the cells of a given contact set, row by row (a warm start: the
    cohesive stress on these cells only)."""
    return [[(-0.5, width - 0.5)] if c.all() else
            [(first - 0.5, last + 0.5) for first, last in _runs(c)]
            for c in np.asarray(contact).reshape(-1, width)]


def tip_residuals(rows_g, extents, same, law: GridLaw, width: int) -> list:
    """Each tip's residual ``g - η``, row by row: None for a row whose runs changed, an empty
    list for a row in range from end to end."""
    return [None if not ok else [] if whole_row(ext, width) else
            [(_interp(gr, lo) - law.opening, _interp(gr, hi) - law.opening)
             for lo, hi in ext]
            for gr, ext, ok in zip(rows_g, extents, same)]
