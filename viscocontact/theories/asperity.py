"""The :class:`AsperityModel` interface shared by the multi-asperity theories of Chapter 3.

Contract for implementers
-------------------------
1. A model is a frozen attrs class, parametrised by a dimensionless *separation* whose meaning it
   documents (GW: ``d/σ_s`` from the summits' mean plane; BGT and the height-dependent curvature
   model: ``d/√m0`` from the surface's mean plane).
2. Implement :meth:`area_fraction` (``A/A0``) and :meth:`pressure_over_modulus` (``p/E*``, with
   ``E*`` the reduced modulus; for the package's solid ``E* = E0/(1-ν²)``), both vectorised and
   non-increasing in the separation, and the :attr:`amplitude` property (``Λ̃`` or None).
3. Everything else has a default: :meth:`mean_pressure` (``p̃ = 2(p/E*)/Λ̃``, thesis eq. 4.17),
   :meth:`separation_at_pressure` and :meth:`area_fraction_at_pressure` (by bracketing and Brent's
   method). For the 1D BEM ``Ã = 2π·A/A0`` is the comparable contact length per period.

:func:`gaussian_tail_moment` is the closed form of the integrals over Gaussian heights.
"""
from __future__ import annotations

import abc
import math

import numpy as np
from scipy import special
from scipy.optimize import brentq

from ..errors import ValidationError
from . import _args

__all__ = ["AsperityModel", "gaussian_tail_moment"]

_ASYMPTOTIC_BELOW = -30.0


def gaussian_tail_moment(n: float, h):
    """``T_n(h) = ∫_0^∞ w^n exp(-(w + h)²/2) dw = Γ(n+1) e^{-h²/4} D_{-n-1}(h)`` (``n > -1``).

    ``D`` is the parabolic cylinder function (:func:`scipy.special.pbdv`). For ``h < -30`` (where
    ``D`` would overflow) the Gaussian moment expansion ``√(2π) E[(m + Z)^n]``, ``m = -h``, is used
    to four terms (relative error below 1e-13). The Greenwood-Williamson integrals of eq. 3.26 are
    ``F_n(h) = T_n(h)/√(2π)``.

    Examples
    --------
    >>> round(float(gaussian_tail_moment(1.0, 0.0)), 15)
    1.0
    """
    h = np.asarray(h, dtype=float)
    n = float(n)
    hc = np.maximum(h, _ASYMPTOTIC_BELOW)
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        exact = math.gamma(n + 1.0) * np.exp(-hc * hc / 4.0) * special.pbdv(-n - 1.0, hc)[0]
    exact = np.where(hc > 38.5, 0.0, exact)       # below 1e-300: underflow, not NaN
    m = np.maximum(-h, 1.0)
    series = 1.0
    coef = 1.0
    for j in range(1, 4):                          # E[(m+Z)^n] = m^n Σ C(n, 2j) (2j-1)!! m^-2j
        coef *= (n - 2 * j + 2) * (n - 2 * j + 1) / (2.0 * j)
        series = series + coef * m ** (-2.0 * j)
    asym = math.sqrt(2.0 * math.pi) * m**n * series
    out = np.where(h < _ASYMPTOTIC_BELOW, asym, exact)
    return float(out) if out.ndim == 0 else out


class AsperityModel(abc.ABC):
    """A multi-asperity rough-contact theory; see the module docstring."""

    @property
    @abc.abstractmethod
    def amplitude(self) -> float | None:
        """``Λ̃ = q0·max r`` of the profile, or None (then only ``p/E*`` is available)."""

    @abc.abstractmethod
    def area_fraction(self, separation):
        """``A/A0`` at the given dimensionless separation."""

    @abc.abstractmethod
    def pressure_over_modulus(self, separation):
        """``p/E*`` (nominal pressure over the reduced modulus) at the given separation."""

    # -- defaults ------------------------------------------------------------------------------
    def mean_pressure(self, separation):
        """``p̃ = 2(1-ν²)p/(E0 q0 Λ) = 2(p/E*)/Λ̃`` (thesis eq. 4.17)."""
        if self.amplitude is None:
            raise ValidationError(f"{type(self).__name__}.amplitude", None,
                                  "a real number in (0.0, inf] (p̃ = 2p/(E*Λ̃) needs Λ̃)")
        return 2.0 * np.asarray(self.pressure_over_modulus(separation)) / self.amplitude

    def separation_at_pressure(self, mean_pressure: float) -> float:
        """The separation at which :meth:`mean_pressure` equals ``p̃ > 0``."""
        p = _args.positive("mean_pressure", mean_pressure)

        def f(t):
            return float(self.mean_pressure(t)) - p

        lo, hi = 0.0, 1.0
        while f(lo) < 0:
            lo -= 2.0
            if lo < -60:
                raise ValidationError("mean_pressure", mean_pressure,
                                      f"a real number in (0.0, {f(lo) + p:.6g}] (the pressure "
                                      "at separation -60)")
        while f(hi) > 0:
            hi += 2.0
            if hi > 60:
                raise ValidationError("mean_pressure", mean_pressure,
                                      f"a real number in [{f(hi) + p:.6g}, inf] (the pressure "
                                      "at separation 60)")
        return brentq(f, lo, hi, xtol=1e-13, rtol=1e-13)

    def area_fraction_at_pressure(self, mean_pressure: float) -> float:
        """``A/A0`` at mean pressure ``p̃ > 0``."""
        return float(self.area_fraction(self.separation_at_pressure(mean_pressure)))
