"""Averages over roughness realizations: the mean and a confidence band.

The thesis averages every quantity over 20 realizations of the random profile (§4.6). A study with
``seeds`` solves one realization per seed; :func:`confidence_band` reduces the seed axis to the
mean and a Student-t confidence interval of the mean,

    mean ± t_{(1+c)/2, n-1} · s / √n,

with ``s`` the sample standard deviation (``ddof = 1``) and ``n`` the number of finite values
(failed points are NaN and are left out, so ``n`` may vary from point to point). With ``n < 2`` the
band is NaN.
"""
from __future__ import annotations

import attrs
import numpy as np


@attrs.frozen(kw_only=True)
class Band:
    """Mean and confidence band over realizations (arrays of the reduced shape).

    Attributes
    ----------
    mean, lower, upper : ndarray
    count : ndarray of int
        Realizations that entered each mean.
    confidence : float
    """

    mean: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    count: np.ndarray
    confidence: float


def confidence_band(values, axis: int = -1, confidence: float = 0.95) -> Band:
    """Mean and Student-t confidence interval of the mean along ``axis``, NaNs left out.

    Examples
    --------
    >>> band = confidence_band([[1.0, 2.0, 3.0, float("nan")]])
    >>> band.mean.tolist(), band.count.tolist()
    ([2.0], [3])
    >>> round(float(band.upper[0] - band.mean[0]), 4)   # t(0.975, 2) * 1 / sqrt(3)
    2.4841
    """
    from scipy import stats

    from ..errors import ValidationError

    if not 0.0 < confidence < 1.0:
        raise ValidationError("confidence", confidence, "a probability in (0, 1)")
    values = np.asarray(values, dtype=float)
    finite = np.isfinite(values)
    count = finite.sum(axis=axis)
    total = np.where(finite, values, 0.0).sum(axis=axis)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.where(count > 0, total / np.maximum(count, 1), np.nan)
        dev = np.where(finite, values - np.expand_dims(mean, axis), 0.0)
        var = (dev**2).sum(axis=axis) / (count - 1)
        half = stats.t.ppf(0.5 + 0.5 * confidence, np.maximum(count - 1, 1)) * np.sqrt(var / count)
    half = np.where(count >= 2, half, np.nan)
    return Band(mean=mean, lower=mean - half, upper=mean + half, count=count.astype(int),
                confidence=float(confidence))
