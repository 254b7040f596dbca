r"""The tips of a cohesive law's zones on the spectral grid: where the runs of cells in range end
(:func:`tip_positions`), the share of each cell under the cohesive stress (:func:`tip_weights`),
and how the tips move from one inner solve of :func:`~.cohesive.cohesive_solve` to the next
(:func:`moved_tips`: by the secant of their residuals ``g - η`` within the bracket of their
root once they have one, else to where the gap crosses ``η``). Cell ``k`` spans
``[k - 1/2, k + 1/2]`` in cell coordinates; a run's extent is ``[L, R]`` in them, ``R >= L``
(unwrapped)."""
from __future__ import annotations

from typing import TYPE_CHECKING

import attrs
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


#: A bracket's side is kept for this many samples of its tip: the tip's residual shares the
#: other tips' moves, so an older sample no longer bounds its root (a zone that creeps with
#: its neighbours would be held in a bracket that its root has left).
BRACKET_AGE = 3


@attrs.frozen
class TipTrack:
    """One tip's recent samples since its run last changed, in its outward coordinate ``s``
    (``-x`` for a run's first tip, ``x`` for its last: the zone grows as ``s`` grows), with its
    residual ``r = g - η`` (a zone whose tip has ``r < 0`` grows, one with ``r > 0``
    shrinks).

    ``last`` is the previous sample ``(s, r)``; ``inner`` the sample with ``r < 0`` and
    ``outer`` the one with ``r > 0`` that bracket the tip's root (``inner[0] < outer[0]``), as
    ``(s, r, n)`` with ``n`` the sample's number, each None until one is seen or once it is
    older than :data:`BRACKET_AGE` samples; ``count`` the samples so far."""

    last: tuple[float, float] | None = None
    inner: tuple[float, float, int] | None = None
    outer: tuple[float, float, int] | None = None
    count: int = 0

    def sampled(self, s: float, r: float) -> "TipTrack":
        """The track with the sample ``(s, r)``: it replaces the bracket's side of its sign.
        The other side is let go where the sample lies beyond it, or where the sample is nearer
        to it than the side it replaces and yet no smaller (a residual that rises outwards
        cannot do that: the root has moved with the other tips)."""
        n = self.count + 1
        inner, outer = ((side if side is not None and n - side[2] <= BRACKET_AGE else None)
                        for side in (self.inner, self.outer))
        if r < 0.0:
            if outer is not None and (s >= outer[0] or (inner is not None and s > inner[0]
                                                         and r <= inner[1])):
                outer = None
            if inner is None or s > inner[0]:
                inner = (s, r, n)
        elif r > 0.0:
            if inner is not None and (s <= inner[0] or (outer is not None and s < outer[0]
                                                        and r >= outer[1])):
                inner = None
            if outer is None or s < outer[0]:
                outer = (s, r, n)
        return TipTrack(last=(s, r), inner=inner, outer=outer, count=n)


def _tip_step(track: TipTrack, s: float, r: float, fresh: float,
              slope_hint: float) -> tuple[float, TipTrack]:
    """The next outward coordinate of one tip and its track.

    The secant of the tip's last two samples where its slope is usable: two samples of
    opposite signs, or a residual that rises outwards, as a tip's residual does at a stable
    root, by at least :data:`FLATTEST_SLOPE` times the gap's own ``slope_hint`` (the slope the
    residual would have without the zone's own stress). A residual that falls outwards (a zone
    that grows under its own stress, as one born at a local minimum of the gap does, where
    ``slope_hint`` is about zero or negative) has no root the way the residual says: its
    secant would send the tip back across the run, and the zone would cycle. While a root is
    bracketed (recent samples of each sign, :class:`TipTrack`), the tip stays within the
    bracket's inner 98 %: the secant there, else the false position between its sides, else
    its middle; so a zone that snaps over many cells settles instead of cycling between the two
    sides of a kinked residual. Unbracketed, the tip moves the way its residual says (out where
    ``r < 0``, in where ``r > 0``): by the secant, else by twice its last move where the fixed
    point ``fresh`` (where the gap crosses η) moves on by less than that (a zone that grows
    under its own stress, the jump of a snap, or a soft zone whose fixed point creeps: the
    moves double until the residual changes sign), else to ``fresh``."""
    before = track.last
    track = track.sampled(s, r)
    secant = None
    if before is not None and s != before[0]:
        slope = (r - before[1]) / (s - before[0])
        if r * before[1] < 0.0 or (slope > 0.0
                                   and abs(slope) >= FLATTEST_SLOPE * abs(slope_hint)):
            secant = s - r / slope
    if track.inner is not None and track.outer is not None:
        (a, ra, _), (b, rb, _) = track.inner, track.outer
        margin = 0.01 * (b - a)
        for guess in (secant, a - ra * (b - a) / (rb - ra)):
            if guess is not None and a + margin <= guess <= b - margin:
                return guess, track
        return 0.5 * (a + b), track
    if secant is not None:
        return secant, track
    if before is not None and s != before[0]:
        last, ahead = s - before[0], fresh - s
        if last * r < 0.0 and last * ahead > 0.0 and abs(ahead) < 2.0 * abs(last):
            return s + 2.0 * last, track
    return fresh, track


def row_tips(gap, contact, law: GridLaw, rows: int) -> list:
    """:func:`tip_positions` of every row (cells flat, row by row)."""
    g = np.asarray(gap).reshape(rows, -1)
    c = np.asarray(contact).reshape(rows, -1)
    return [tip_positions(gr, cr, law) for gr, cr in zip(g, c)]


def whole_row(extents, points: int) -> bool:
    """Whether a row is in range from end to end (one run over every cell: no tips)."""
    return len(extents) == 1 and extents[0][1] - extents[0][0] >= points


def moved_tips(extents, residuals, fresh, gap, tracks):
    """The next tips of one row and their tracks: each tip by :func:`_tip_step` in its
    outward coordinate (``tracks``: the row's previous tracks, per run, None after its runs
    changed). Two tips of a run that would cross meet at their middle (the zone vanishes
    there, and the next solve's runs say so)."""
    moved, kept = [], []
    for j, ((lo, hi), (r_lo, r_hi), (f_lo, f_hi)) in enumerate(zip(extents, residuals, fresh)):
        t_lo, t_hi = (TipTrack(), TipTrack()) if tracks is None else tracks[j]
        s_lo, t_lo = _tip_step(t_lo, -lo, r_lo, -f_lo,
                               _interp(gap, lo - 0.5) - _interp(gap, lo + 0.5))
        s_hi, t_hi = _tip_step(t_hi, hi, r_hi, f_hi,
                               _interp(gap, hi + 0.5) - _interp(gap, hi - 0.5))
        new_lo, new_hi = -s_lo, s_hi
        if new_lo > new_hi:
            new_lo = new_hi = 0.5 * (new_lo + new_hi)
        moved.append((new_lo, new_hi))
        kept.append((t_lo, t_hi))
    return moved, kept


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
