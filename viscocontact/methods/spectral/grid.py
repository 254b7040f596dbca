r"""The uniform grid of the spectral method: cells, heights, transfers between grids.

``N`` cells of width ``h = 2π/N`` centred at ``x_k = x_peak + k h`` (the global maximum of the
profile at the centre of cell 0, so that the first contact is never missed), ``r̃_k`` the normalised
heights at the centres (eq. 4.18) and ``Δr_k = q0 r(x_k + h/2) - q0 r(x_k - h/2)`` the rise of the
profile over each cell, which gives the friction of a piecewise-constant pressure exactly
(eq. 4.16; :func:`viscocontact.contact.fields.friction`).
"""
from __future__ import annotations

import attrs
import numpy as np
import scipy.fft

from ...kernels.clausen import TWO_PI
from ...profiles.spectral import SpectralProfile


def _readonly(a):
    a = np.array(a, dtype=float, copy=True)
    a.setflags(write=False)
    return a


@attrs.frozen(kw_only=True, eq=False)
class UniformGrid:
    """Cell centres, heights and rises of one profile on ``points`` cells.

    Attributes
    ----------
    points : int
    start : float
        Centre of cell 0 (the profile's peak), ``x̃`` units.
    x : ndarray
        Cell centres ``x_peak + k h``.
    heights : ndarray
        ``r̃`` at the centres (max 1).
    rise : ndarray
        ``q0 r`` at the right end of each cell minus at its left end.
    """

    points: int
    start: float
    x: np.ndarray = attrs.field(converter=_readonly)
    heights: np.ndarray = attrs.field(converter=_readonly)
    rise: np.ndarray = attrs.field(converter=_readonly)

    @classmethod
    def of(cls, shape, points: int) -> "UniformGrid":
        """The grid of a :class:`~viscocontact.contact.fields.NormalizedProfile`."""
        n = int(points)
        h = TWO_PI / n
        start = float(shape.peak_position)
        x = start + h * np.arange(n)
        both = uniform_heights(shape.profile, start, 2 * n)  # centres (even) and right ends (odd)
        ends = both[1::2]
        return cls(points=n, start=start, x=x, heights=both[0::2] / shape.amplitude,
                   rise=ends - np.roll(ends, 1))

    @property
    def cell(self) -> float:
        """Cell width ``h = 2π/N``."""
        return TWO_PI / self.points


def uniform_heights(profile, start: float, n: int) -> np.ndarray:
    """``q0 r`` at ``start + 2πj/n``, ``j = 0..n-1``: by one inverse FFT for a
    :class:`~viscocontact.profiles.spectral.SpectralProfile` whose highest wavenumber is below
    ``n/2`` (equal to the direct sum to rounding), else by :meth:`Profile.heights`."""
    x = start + TWO_PI * np.arange(n) / n
    if not isinstance(profile, SpectralProfile):
        return profile.heights(x)
    modes = profile.modes
    k = modes.wavenumbers
    if 2 * int(k[-1]) >= n:
        return profile.heights(x)
    spec = np.zeros(n // 2 + 1, dtype=complex)
    np.add.at(spec, k, 0.5 * n * modes.coefficients * np.exp(1j * k * start))
    return scipy.fft.irfft(spec, n)


def refine(values: np.ndarray) -> np.ndarray:
    """A field on ``N`` cells carried to ``2N`` (same first centre): the coarse value at the
    coinciding centres, the mean of the two neighbours between them."""
    v = np.asarray(values, dtype=float)
    out = np.empty(2 * v.size)
    out[0::2] = v
    out[1::2] = 0.5 * (v + np.roll(v, -1))
    return out


def coarsen(mask: np.ndarray) -> np.ndarray:
    """A cell set on ``2N`` cells carried to ``N``: a coarse cell is in the set when the fine
    cell at its centre is."""
    return np.asarray(mask, bool)[0::2].copy()


def cells_inside(grid: UniformGrid, edges) -> np.ndarray:
    """Cells whose centre lies in one of the contacts ``edges`` (shape (n, 2) or flat
    ``[a1, b1, a2, b2, ...]``, periodic)."""
    e = np.asarray(edges, dtype=float).reshape(-1, 2)
    inside = np.zeros(grid.points, bool)
    for a, b in e:
        if b - a >= TWO_PI:
            return np.ones(grid.points, bool)
        offset = np.mod(grid.x - a, TWO_PI)
        inside |= offset <= b - a
    return inside
