r"""Contacts of a grid solution and their edges to a fraction of a cell.

A contact is a maximal (cyclic) run of loaded cells. Its edges lie within a cell of the outermost
loaded centres; where exactly follows from the square-root field at an adhesionless edge
(``p ∝ √s`` inside at a distance ``s``, ``g ∝ s^{3/2}`` outside). On a grid much finer than the
contact, the discrete solution near an edge is that of a semi-infinite contact, the same for
every edge up to its scale: the ratio ``ρ = p_out/p_next`` of the outermost loaded cell's
pressure to its neighbour's, and the ratio ``γ = g_1/g_2`` of the gaps of the first two free
cells, are universal functions of the edge's offset ``θ`` beyond the outermost loaded centre, in
cells. Their inverses :func:`edge_offset` and :func:`gap_edge_offset` were fitted on Westergaard's
solution (edge known in closed form) on grids of 8192-8600 cells, ``h/a`` below 1e-3, over the
whole range ``θ ∈ [-0.175, 0.825)`` that one cell spans (``benchmarks/spectral_edges.py``). They
reproduce the edges of those solutions to 6e-4 (``ρ``) and 5e-4 cells (``γ``), and on grids four
times coarser at other loads to 2.5e-3 and 2.8e-3 cells. The classical estimate from ``p²``
linear in ``s`` (``θ = ρ²/(1 - ρ²)``) is off by up to 0.14 cells.

Direction of sliding. A viscoelastic kernel remembers the stress ahead of a point
(:mod:`viscocontact.kernels`): its memory integral adds a term ``∝ x log|x|/ζ_i`` on one side of
the singularity, which the universal local problem does not have. Measured on a sinusoid with a
standard linear solid (β = 10, ζ = 0.1, ``h`` from ζ/130), the pressure side is clean at the
trailing (left) edge and the gap side at the leading (right) edge: there ``θ`` is found to 2e-3
cells, while the other side is off by 0.03 cells (and by 0.2 at ζ = 0.01, ζ/h = 14). So the
left edge of a contact is located from ``ρ`` and the right edge from ``γ`` (from ``ρ`` when
the next contact leaves fewer than two free cells); on an elastic kernel both are unbiased.

Edges stay approximate where the local problem is not the universal one: a contact of one or two
cells (its cells are its extent), two contacts a few cells apart (a weak square-root field that
turns into ``s^{3/2}`` within a cell), a memory length of a few cells. The two-grid estimate of
the method sees those errors.
"""
from __future__ import annotations

import numpy as np

from ...kernels.clausen import TWO_PI

#: θ(ρ) as a polynomial in ρ = p_out/p_next, highest power first (see the module docstring).
PRESSURE_MAP = (0.166255, 0.123148, 0.442004, 0.998653, -0.174582)
#: θ(γ) as a polynomial in γ = g_1/g_2, the gaps of the first two free cells.
GAP_MAP = (-80.775776, 46.770632, -15.825487, -0.050758, -1.064523, 0.826041)
#: ``θ`` for ``ρ → 0``: the offset at which a cell starts to carry load.
THETA_MIN = float(PRESSURE_MAP[-1])


def edge_offset(ratio) -> np.ndarray:
    """Offset ``θ`` (cells) of an edge beyond the outermost loaded centre, from
    ``ρ = p_out/p_next``; clipped to the one-cell range ``[THETA_MIN, THETA_MIN + 1]``."""
    rho = np.clip(np.asarray(ratio, dtype=float), 0.0, None)
    return np.clip(np.polyval(PRESSURE_MAP, rho), THETA_MIN, THETA_MIN + 1.0)


def gap_edge_offset(ratio) -> np.ndarray:
    """The same offset from ``γ = g_1/g_2``, the gaps of the two free cells next to the edge."""
    gamma = np.clip(np.asarray(ratio, dtype=float), 0.0, None)
    return np.clip(np.polyval(GAP_MAP, gamma), THETA_MIN, THETA_MIN + 1.0)


def runs(loaded: np.ndarray) -> list[tuple[int, int]]:
    """Maximal cyclic runs ``(first, length)`` of True cells (one run ``(0, N)`` when all are)."""
    loaded = np.asarray(loaded, bool)
    n = loaded.size
    if loaded.all():
        return [(0, n)]
    if not loaded.any():
        return []
    start = int(np.flatnonzero(~loaded)[0]) + 1         # just after a gap: no run wraps
    rolled = np.roll(loaded, -start).astype(np.int8)
    steps = np.diff(np.concatenate([[0], rolled, [0]]))
    firsts = np.flatnonzero(steps == 1)
    lasts = np.flatnonzero(steps == -1)
    return [(int((f + start) % n), int(e - f)) for f, e in zip(firsts, lasts)]


def contact_edges(x0: float, cell: float, pressure: np.ndarray, gap: np.ndarray) -> np.ndarray:
    """Edges ``[[X_start, X_end], ...]`` of every contact of a grid solution.

    Parameters
    ----------
    x0, cell : float
        Centre of cell 0 and the cell width.
    pressure, gap : ndarray
        Cell pressures (``> 0`` on the loaded cells) and gaps ``u - (r̃ - 1 + Δ̃)``.

    Returns
    -------
    ndarray, shape (n_contacts, 2)
        Sorted by start, the starts in ``[x0 - π, x0 + π)`` (the window of
        :mod:`viscocontact.contact.topology`, whose origin is the peak minus π); a run of at
        least three cells gets sub-cell edges (its left edge from :func:`edge_offset`, its right
        edge from :func:`gap_edge_offset`), a shorter one its cells.
    """
    p = np.asarray(pressure, dtype=float)
    n = p.size
    out = []
    for first, length in runs(p > 0):
        if length == n:
            raise ValueError("every cell is loaded: a closed contact has no edges")
        last = first + length - 1
        lo: float | np.ndarray = x0 + cell * (first - 0.5)   # 0-d arrays at sub-cell edges
        hi: float | np.ndarray = x0 + cell * (last + 0.5)
        if length >= 3:
            lo = x0 + cell * (first - edge_offset(p[first] / p[(first + 1) % n]))
            g1, g2 = gap[(last + 1) % n], gap[(last + 2) % n]
            if p[(last + 2) % n] == 0.0 and 0.0 < g1 < g2:
                hi = x0 + cell * (last + gap_edge_offset(g1 / g2))
            else:
                hi = x0 + cell * (last + edge_offset(p[last % n] / p[(last - 1) % n]))
        start = x0 - np.pi + np.mod(lo - (x0 - np.pi), TWO_PI)
        out.append((start, start + (hi - lo)))
    out.sort()
    return np.array(out, dtype=float).reshape(-1, 2)
