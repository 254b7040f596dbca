r"""The spectral method's error estimate: the relative changes of ``Ã`` and ``μ`` between two
grids (:func:`changes`) and the Richardson estimate built from them (:func:`estimate`)."""
from __future__ import annotations

import math

import numpy as np

from .measures import GridMeasures

#: Convergence order assumed by the Richardson estimate: the lowest observed on rough profiles
#: (module docstring of :mod:`viscocontact.methods.spectral`).
ORDER = 1.0


def changes(coarse: GridMeasures, fine: GridMeasures, m2: float,
            friction_floor: float) -> tuple[float, float]:
    """Relative changes of ``Ã`` and ``μ`` from the coarse to the fine grid.

    Parameters
    ----------
    coarse, fine : GridMeasures
        The measures of two grids, the fine one twice as fine.
    m2 : float
        The profile's mean square slope.
    friction_floor : float
        ``μ`` is compared relative to ``max(|μ|, friction_floor·√m2)``.

    Returns
    -------
    tuple of float
        The changes of ``Ã`` (relative to the fine grid's) and of ``μ``; a friction undefined
        on both grids (no load) has changed by 0, on one of them by infinity.
    """
    d_area = abs(fine.area - coarse.area) / max(fine.area, 1e-300)
    scale = max(abs(fine.friction), friction_floor * math.sqrt(max(m2, 0.0)), 1e-300)
    d_mu = abs(fine.friction - coarse.friction) / scale
    if not np.isfinite(d_mu):
        d_mu = 0.0 if not (np.isfinite(fine.friction) or np.isfinite(coarse.friction)) else np.inf
    return float(d_area), float(d_mu)


def estimate(change: tuple[float, float], previous: tuple[float, float] | None = None
             ) -> tuple[float, float]:
    """Relative error estimates of ``Ã`` and ``μ`` on the finer of two grids (ratio 2).

    Richardson: the change between the two grids over ``2^p - 1`` (``p = ORDER``), and at least
    the change between the two grids before over ``2^p (2^p - 1)`` (``previous``), so that a
    change that happens to be small does not hide a larger error seen one level down.

    Parameters
    ----------
    change : tuple of float
        :func:`changes` between the last two grids.
    previous : tuple of float, optional
        :func:`changes` between the two grids before.

    Returns
    -------
    tuple of float
        The estimates for ``Ã`` and ``μ``.

    Examples
    --------
    >>> estimate((1e-3, 2e-4), previous=(8e-3, 1e-3))
    (0.004, 0.0005)
    """
    factor = 2.0**ORDER - 1.0
    out = [c / factor for c in change]
    if previous is not None:
        out = [max(o, c / (factor * 2.0**ORDER)) for o, c in zip(out, previous)]
    return float(out[0]), float(out[1])
