r"""What the grid solvers of the spectral method share: the outcome of one grid solve
(:class:`GridSolution`), the violation of the contact conditions it stops on (:func:`violation`)
and the diagonal of a circulant (:func:`circulant_diagonal`)."""
from __future__ import annotations

import attrs
import numpy as np


@attrs.frozen(kw_only=True, eq=False)
class GridSolution:
    """The outcome of one grid solve.

    Attributes
    ----------
    pressure : ndarray
        Cell pressures ``p_k >= 0``.
    penetration : float
        ``Δ̃`` (given, or the load multiplier).
    converged : bool
    residual : float
        Largest violation of the contact conditions (units of the profile amplitude).
    iterations : int
        Conjugate-gradient steps, or active-set updates.
    applications : int
        Products with ``A`` or its inverse (one FFT pair each).
    solver : str
        :data:`POLONSKY_KEER` or :data:`ACTIVE_SET`.
    message : str
    """

    pressure: np.ndarray
    penetration: float
    converged: bool
    residual: float
    iterations: int
    applications: int
    solver: str
    message: str


def violation(gap: np.ndarray, loaded: np.ndarray) -> float:
    """``max(max_C |g|, max_{∉C} -g, 0)``: the largest violation of the contact conditions."""
    inside = np.max(np.abs(gap[loaded]), initial=0.0)
    outside = -np.min(gap[~loaded], initial=0.0)
    return float(max(inside, outside, 0.0))


def circulant_diagonal(spectrum) -> float:
    """The diagonal entry of a real symmetric circulant from its rfft (or rfft2) eigenvalues
    (their mean over all modes; the last axis holds the half spectrum)."""
    v = np.asarray(spectrum).real
    n = 2 * (v.shape[-1] - 1) * int(np.prod(v.shape[:-1]))
    return float((v[..., 0].sum() + 2.0 * v[..., 1:-1].sum() + v[..., -1].sum()) / n)
