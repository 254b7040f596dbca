r"""Maugis's (1992) adhesive elastic sphere: the Dugdale law between a rigid sphere and a
half-space, from DMT to JKR.

A sphere of radius ``R`` on an elastic half-space of plane-strain modulus ``E*`` (``K = 4E*/3``),
Dugdale's law between them: the tension σ0 wherever the gap is below ``h0``, ``σ0h0 = Δγ``. The
contact has radius ``a``, the cohesive zone reaches ``c = m a``. In the units

.. math:: \bar a = a\Big(\frac{K}{\pi R^2\Delta\gamma}\Big)^{1/3},\quad
          \bar P = \frac{P}{\pi R\Delta\gamma},\quad
          \lambda = 2\sigma_0\Big(\frac{R}{\pi\Delta\gamma K^2}\Big)^{1/3}

the equilibrium is (Maugis 1992, eqs. 33-34; the load tensile negative)

.. math::
    \frac{\lambda\bar a^2}{2}\Big[\sqrt{m^2-1} + (m^2 - 2)\arctan\sqrt{m^2-1}\Big]
    + \frac{4\lambda^2\bar a}{3}\Big[\sqrt{m^2-1}\arctan\sqrt{m^2-1} - m + 1\Big] = 1,

    \bar P = \bar a^3 - \lambda\bar a^2\Big[\sqrt{m^2-1} + m^2\arctan\sqrt{m^2-1}\Big].

The pull-off is the least ``P̄`` over ``ā`` (:func:`maugis_pull_off`): 2 (Derjaguin, DMT) for
``λ → 0``, 1.5 (JKR) for ``λ → ∞``. With the Lennard-Jones peak stress
``σ0 = 16Δγ/(9√3ε)``, ``λ ≈ 1.157 μ_T`` (Tabor's ``μ_T = (RΔγ²/(E*²ε³))^{1/3}``).

References
----------
Maugis, D. (1992). Adhesion of spheres: the JKR-DMT transition using a Dugdale model.
J. Colloid Interface Sci. 150, 243-269. doi:10.1016/0021-9797(92)90285-T
"""
from __future__ import annotations

import math

from scipy.optimize import brentq, minimize_scalar

from ..errors import ValidationError


def maugis_load(radius: float, transition: float) -> tuple[float, float]:
    """``(P̄, m)`` at the contact radius ``ā = radius`` and Maugis's ``λ = transition``."""
    if not (radius > 0 and transition > 0 and math.isfinite(radius * transition)):
        raise ValidationError("maugis_load", (radius, transition),
                              "a finite contact radius ā > 0 and transition parameter λ > 0")
    a, lam = radius, transition

    def closure(m):
        s = math.sqrt(m * m - 1.0)
        t = math.atan(s)
        return (lam * a * a / 2 * (s + (m * m - 2) * t)
                + 4 * lam * lam * a / 3 * (s * t - m + 1) - 1.0)

    hi = 2.0
    while closure(hi) < 0:
        hi *= 2.0
    m = brentq(closure, 1.0, hi, xtol=1e-15, rtol=1e-15)
    s = math.sqrt(m * m - 1.0)
    return a**3 - lam * a * a * (s + m * m * math.atan(s)), m


def maugis_pull_off(transition: float) -> float:
    """The pull-off force ``-min P̄ = F/(πRΔγ)`` at Maugis's ``λ = transition``."""
    best = minimize_scalar(lambda s: maugis_load(math.exp(s), transition)[0],
                           bounds=(-16.0, 2.0), method="bounded", options={"xatol": 1e-10})
    return float(-best.fun)
