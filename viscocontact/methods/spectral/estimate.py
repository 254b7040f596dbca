r"""The spectral method's error estimate: the relative changes of ``Ã``, ``μ`` and the dissipated
power's friction between two grids (:func:`changes`), the Richardson estimate built from them
(:func:`estimate`), and the power balance's bound on the two frictions' (:func:`power_bounded`)."""
from __future__ import annotations

import math

import numpy as np

from ..power import bounded_by_power
from .measures import GridMeasures

#: Convergence order assumed by the Richardson estimate: the lowest observed on rough profiles
#: (module docstring of :mod:`viscocontact.methods.spectral`).
ORDER = 1.0


def changes(coarse: GridMeasures, fine: GridMeasures, m2: float,
            friction_floor: float) -> tuple[float, float, float]:
    """Relative changes of ``Ã``, ``μ`` and the dissipated power's friction from the coarse to
    the fine grid.

    Parameters
    ----------
    coarse, fine : GridMeasures
        The measures of two grids, the fine one twice as fine.
    m2 : float
        The profile's mean square slope.
    friction_floor : float
        ``μ`` and the dissipation are compared relative to ``max(|μ|, friction_floor·√m2)``
        (:func:`friction_scale`).

    Returns
    -------
    tuple of float
        The changes of ``Ã`` (relative to the fine grid's), of ``μ`` and of the dissipation; a
        friction undefined on both grids (no load) has changed by 0, on one of them by
        infinity.
    """
    d_area = abs(fine.area - coarse.area) / max(fine.area, 1e-300)
    scale = friction_scale(fine.friction, m2, friction_floor)
    return (float(d_area), _changed(coarse.friction, fine.friction, scale),
            _changed(coarse.dissipation, fine.dissipation, scale))


def friction_scale(friction: float, m2: float, friction_floor: float) -> float:
    """``max(|μ|, friction_floor·√m2)``: what the friction's estimate is relative to (μ
    vanishes on an elastic solid)."""
    mu = abs(friction) if np.isfinite(friction) else 0.0
    return float(max(mu, friction_floor * math.sqrt(max(m2, 0.0)), 1e-300))


def _changed(coarse: float, fine: float, scale: float) -> float:
    change = abs(fine - coarse) / scale
    if not np.isfinite(change):
        return 0.0 if not (np.isfinite(fine) or np.isfinite(coarse)) else float(np.inf)
    return float(change)


def power_bounded(errors: tuple[float, ...], fine: GridMeasures, m2: float,
                  friction_floor: float) -> tuple[float, ...]:
    """``errors`` (``Ã``, ``μ``, the dissipation's) with the two frictions' raised to the power
    balance's bound on ``fine`` (:func:`~viscocontact.methods.power.bounded_by_power`): on a
    sinusoid at ζ = 113 (a Prony solid, Δ̃ = 0.67) ``μ`` on 128, 256 and 512 cells is 5.2e-7,
    3.0e-7 and -1.4e-7 from the limit, its change from 128 to 256 cells 2.2e-7, and the
    dissipation converged to 1e-9; the ladder refines on the bounded estimate as on any other."""
    scale = friction_scale(fine.friction, m2, friction_floor)
    misfit = abs(fine.friction - fine.dissipation) / scale
    friction, dissipation = bounded_by_power(errors[1], errors[2], misfit)
    return (errors[0], friction, dissipation, *errors[3:])


def estimate(change: tuple[float, ...], previous: tuple[float, ...] | None = None
             ) -> tuple[float, ...]:
    """Relative error estimates of the measures (``Ã``, ``μ``, ...) on the finer of two grids
    (ratio 2).

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
        The estimates, one per measure.

    Examples
    --------
    >>> estimate((1e-3, 2e-4), previous=(8e-3, 1e-3))
    (0.004, 0.0005)
    """
    factor = 2.0**ORDER - 1.0
    out = [c / factor for c in change]
    if previous is not None:
        out = [max(o, c / (factor * 2.0**ORDER)) for o, c in zip(out, previous)]
    return tuple(float(o) for o in out)
