r"""The Clausen function and the periodic log kernel.

The periodic half-plane kernel of the thesis (eq. 4.3, dimensionless 4.19) is built on

.. math:: g(x) = \log|2\sin(x/2)| = -\sum_{m\ge 1} \cos(m x)/m ,

whose antiderivative is minus the Clausen function,
:math:`\int_0^x g(s)\,ds = -\mathrm{Cl}_2(x)`, :math:`\mathrm{Cl}_2(x) = \sum_m \sin(m x)/m^2`.
Integrating the log singularity through ``Cl2`` is what lets an influence coefficient of a tiny element
next to a large one keep its accuracy.

``Cl2`` is evaluated after reduction to ``[-π, π]`` from the series (Abramowitz & Stegun 27.8.2)

.. math:: \mathrm{Cl}_2(\theta) = \theta - \theta\log|\theta|
          + \theta\sum_{k\ge1} \frac{2\zeta(2k)}{(2\pi)^{2k}\,2k(2k+1)}\,\theta^{2k},

whose terms shrink at least as ``4^{-k}`` on ``|θ| <= π``; 30 terms give full double precision, and
the polynomial in ``θ²`` they sum to is economized to degree 14 for speed.
"""
from __future__ import annotations

import numpy as np
from scipy.special import zeta as _riemann_zeta

TWO_PI = 2.0 * np.pi

_K = np.arange(1, 31)
# Horner coefficients in θ², highest power first.
_CL2_COEF = (2.0 * _riemann_zeta(2.0 * _K) / (TWO_PI ** (2 * _K) * (2 * _K) * (2 * _K + 1)))[::-1].copy()


def _economized(degree: int = 14) -> np.ndarray:
    """The 30-term series in ``u = θ²`` replaced by its least-squares polynomial of ``degree`` on
    ``[0, π²]`` (Horner order): the same values to 7e-16 (``tests/unit/kernels``) at half the cost."""
    u = np.linspace(0.0, np.pi**2, 2001)
    series = np.zeros_like(u)
    for c in _CL2_COEF:
        series = series * u + c
    return np.polynomial.Polynomial.fit(u, series, degree).convert().coef[::-1].copy()


_CL2_FAST = _economized()


def wrap(x):
    """Reduce ``x`` to ``[-π, π)``.

    Arguments within ``[-3π, 3π)`` (differences of two points of one period, the common case)
    take one shift of ``2π``, several times faster than the general ``mod`` reduction.
    """
    t = np.array(x, dtype=float)          # a copy: shifted in place below
    if t.size == 0:
        return t
    lo, hi = t.min(), t.max()
    if not (lo >= -3.0 * np.pi and hi < 3.0 * np.pi):
        return np.mod(t + np.pi, TWO_PI) - np.pi
    if hi >= np.pi:
        t[t >= np.pi] -= TWO_PI
    if lo < -np.pi:
        t[t < -np.pi] += TWO_PI
    return t


def cl2(x, *, wrapped: bool = False):
    """Clausen function ``Cl2(x) = Σ sin(m x)/m²`` (odd, 2π-periodic, max 1.0149 at π/3).

    Parameters
    ----------
    x : array_like
        Argument (any real).
    wrapped : bool
        ``x`` is already in ``[-π, π]`` (an array, which is then not copied by :func:`wrap`).

    Returns
    -------
    ndarray
        ``Cl2(x)``, absolute error below ~1e-15.

    Examples
    --------
    >>> round(float(cl2(np.pi / 3)), 12)
    1.01494160641
    """
    t = x if wrapped else wrap(x)
    t2 = t * t
    acc = np.full_like(t, _CL2_FAST[0])
    for c in _CL2_FAST[1:]:             # Horner in place (the same arithmetic, no temporaries)
        acc *= t2
        acc += c
    with np.errstate(divide="ignore", invalid="ignore"):
        lg = np.where(t == 0.0, 0.0, t * np.log(np.abs(t)))
    tail = t * t2
    tail *= acc
    out = t - lg
    out += tail
    return out


def cl2_smooth(x):
    """``S(x) = x + x³ P(x²)`` and ``S'(x)``, the smooth part of ``Cl2 = S - x log|x|`` on
    ``[-π, π]`` (the series of the module docstring without its singular term).

    Examples
    --------
    >>> x = 0.4
    >>> bool(abs(cl2_smooth(x)[0] - x * np.log(x) - cl2(x)) < 1e-15)
    True
    """
    x = np.asarray(x, dtype=float)
    u = x * x
    p = np.polyval(_CL2_FAST, u)
    dp = np.polyval(np.polyder(_CL2_FAST), u)
    return x + x * u * p, 1.0 + 3.0 * u * p + 2.0 * u * u * dp


def log_kernel(x):
    """``g(x) = log|2 sin(x/2)|`` (``-inf`` at multiples of 2π)."""
    with np.errstate(divide="ignore"):
        return np.log(np.abs(2.0 * np.sin(0.5 * np.asarray(x, dtype=float))))


def log_kernel_derivative(x):
    """``g'(x) = cot(x/2)/2``."""
    with np.errstate(divide="ignore"):
        return 0.5 / np.tan(0.5 * np.asarray(x, dtype=float))
