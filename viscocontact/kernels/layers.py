r"""Layers of finite thickness ``d`` (thesis equations 2.41-2.44, figure 2.11).

``A_m(q0 d)`` of eqs. 2.42 (confined: bonded to a rigid plate) and 2.43 (free: uniform pressure on
top) are evaluated in a form multiplied through by ``e^{-2t}`` (``t = m q0 d``), so that neither
overflows nor cancels for any ``t``:

* confined: ``A = [2(5 + 2t² + 2t - 4ν(3-2ν)) e^{-2t} + 2(3-4ν) e^{-4t}] / D``,
  ``D = 2(5 + 2t² - 4ν(3-2ν)) e^{-2t} + (3-4ν)(1 + e^{-4t})``;
* free: ``A = 1 + (2t + sinh 2t)/(1 + 2t² - cosh 2t)`` with the denominator
  ``-2 (sinh t - t)(sinh t + t)`` (series for ``sinh t - t`` at small t).

``S_m = 1 - A_m`` → 1 as ``d → ∞`` (half-plane), → 0 for a thin confined layer (stiff),
and grows like ``6/(m d)³`` for a thin free layer (plate bending). The mean displacement of eq. 2.44,
``u_m = -(1+ν)(1-2ν) σ_m d / ((1-ν) E0)``, is the constant kernel ``c0 = -(1-2ν) d̃ / (4π(1-ν)²)``
in the units of eq. 4.17; it vanishes for ν = 1/2. With a layer, the penetration Δ̃ is measured from
the undeformed far surface.
"""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import in_range, positive
from .base import GreenKernel


def _sinh_minus_x(t):
    t = np.asarray(t, dtype=float)
    small = t < 0.1
    ts = np.where(small, t, 0.0)
    series = ts**3 / 6 * (1 + ts**2 / 20 * (1 + ts**2 / 42 * (1 + ts**2 / 72 * (1 + ts**2 / 110))))
    with np.errstate(over="ignore"):
        direct = np.sinh(np.where(small, 1.0, np.minimum(t, 700.0))) - np.where(small, 1.0, t)
    return np.where(small, series, direct)


def confined_layer_A(t, nu):
    """``A_m`` of eq. 2.42 at ``t = m q0 d`` (stable for all t >= 0)."""
    t = np.asarray(t, dtype=float)
    e2, e4 = np.exp(-2 * t), np.exp(-4 * t)
    c = 4 * nu * (3 - 2 * nu)
    num = 2 * (5 + 2 * t**2 + 2 * t - c) * e2 + 2 * (3 - 4 * nu) * e4
    den = 2 * (5 + 2 * t**2 - c) * e2 + (3 - 4 * nu) * (1 + e4)
    return num / den


def free_layer_A(t):
    """``A_m`` of eq. 2.43 at ``t = m q0 d`` (stable for all t > 0)."""
    t = np.asarray(t, dtype=float)
    big = t > 20
    tb = np.where(big, t, 1.0)
    ts = np.where(big, 1.0, t)
    # large t: A = [2(1+2t+2t²)e^{-2t} - 2e^{-4t}] / [2(1+2t²)e^{-2t} - 1 - e^{-4t}]
    e2, e4 = np.exp(-2 * tb), np.exp(-4 * tb)
    a_big = (2 * (1 + 2 * tb + 2 * tb**2) * e2 - 2 * e4) / (2 * (1 + 2 * tb**2) * e2 - 1 - e4)
    sm = _sinh_minus_x(ts)
    den = -2.0 * sm * (sm + 2 * ts)          # 1 + 2t² - cosh 2t = 2t² - 2 sinh² t
    a_small = 1.0 + (2 * ts + np.sinh(2 * ts)) / den
    return np.where(big, a_big, a_small)


def _modes_for(thickness: float) -> int:
    # A_m ~ poly(t) e^{-2t}: below 1e-17 once 2t > 45
    return int(np.ceil(25.0 / thickness)) + 8


@attrs.frozen(kw_only=True)
class _Layer(GreenKernel):
    thickness: float = attrs.field(validator=[positive, in_range(1e-3, 1e6)])
    poisson: float = attrs.field(default=0.5, validator=in_range(-1.0, 0.5, lo_open=True))

    def correction_modes(self) -> int:
        return _modes_for(self.thickness)

    def mean_compliance(self) -> float:
        nu = self.poisson
        return -(1 - 2 * nu) * self.thickness / (4 * np.pi * (1 - nu) ** 2)


@attrs.frozen(kw_only=True)
class ConfinedLayer(_Layer):
    """Layer of dimensionless thickness ``q0·d`` bonded to a rigid plate (equation 2.42).

    Parameters
    ----------
    thickness : float
        ``q0·d`` in ``[1e-3, 1e6]``.
    poisson : float
        Poisson's ratio ν in ``(-1, 0.5]``.
    """

    def geometry_factors(self, m):
        return 1.0 - confined_layer_A(np.asarray(m, dtype=float) * self.thickness, self.poisson)


@attrs.frozen(kw_only=True)
class FreeLayer(_Layer):
    """Layer of dimensionless thickness ``q0·d`` under uniform pressure on top (equation 2.43).

    Parameters
    ----------
    thickness : float
        ``q0·d`` in ``[1e-3, 1e6]``.
    poisson : float
        Poisson's ratio ν in ``(-1, 0.5]`` (eq. 2.43 itself does not depend on ν; eq. 2.44 does).
    """

    def geometry_factors(self, m):
        return 1.0 - free_layer_A(np.asarray(m, dtype=float) * self.thickness)
