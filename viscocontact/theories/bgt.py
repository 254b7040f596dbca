r"""Greenwood's (2006) simplified BGT model (thesis equations 3.29-3.33).

Intrinsically 3D (isotropic Gaussian surface; the profile is its cross-section, see
:mod:`viscocontact.theories.summits`). Bush, Gibson and Thomas treat every summit as an elliptic
paraboloid with the principal curvatures of Nayak's joint density (eq. 3.33); Greenwood replaces each
elliptic Hertz contact by a spherical one of radius ``1/K_g`` with ``K_g = √(K1 K2)`` (eq. 3.29):

.. math::
    \frac{A}{A_0} = \iiint \frac{\pi\,(z - d)}{K_g}\,\Upsilon\,dz\,dK_1\,dK_2,\qquad
    \frac{P}{A_0} = \iiint \tfrac{4}{3}E^* K_g^{-1/2}(z - d)^{3/2}\,\Upsilon\,dz\,dK_1\,dK_2
    \quad(3.30\text{-}3.31)

over summits above ``d`` (``A_i σ_m`` of eq. 3.31 is the Hertz load ``(4/3)E*√R δ^{3/2}``). Integrating
eq. 3.32's ``ψ_s(z, K_g)`` over ``K_g`` is the same as integrating eq. 3.33 over ``(K1, K2)``; the
Jacobian ``2K_g/√(K_g² + χ²)`` is that of ``(K1, K2) → (K_g, χ)``. Eq. 3.33 is normalised per
*ordered* pair of curvatures (see :mod:`~viscocontact.theories.summits`), so ``χ`` runs over
``χ > 0`` only here; eq. 3.32 as printed (``χ`` over all reals) would double both integrals.

In dimensionless form, ``t = d/√m0`` (from the surface's mean plane), ``s = -(k1 + k2)/2``,
``u = |k1 - k2|/2``, ``b = 3/(2√α)`` and ``T_n`` of
:func:`~viscocontact.theories.asperity.gaussian_tail_moment`:

.. math::
    \frac{A}{A_0} = \frac{\sqrt{27}\sqrt{\alpha}}{32\pi\sqrt{C_1}}\iint
        T_1\big(\sqrt{2C_1}(t - bs)\big)\,4u\sqrt{s^2 - u^2}\,e^{-3s^2/4 - 3u^2/2}\,du\,ds,

    \frac{P}{A_0E^*\sqrt{m_2}} = \frac{\sqrt{27}\,\alpha^{3/4}}{12\pi^2\,2^{5/4}C_1^{3/4}}\iint
        T_{3/2}\big(\sqrt{2C_1}(t - bs)\big)\,4u\,(s^2 - u^2)^{3/4}e^{-3s^2/4 - 3u^2/2}\,du\,ds,

the height integral being done in closed form and the two curvature integrals by Gauss-Legendre
(``u = s sin θ``). For vanishing load the area is asymptotically proportional to load,
``A/A0 → √π p/(E*√m2)`` (BGT's ``κ = √(2π)`` with the rms gradient of the surface ``√(2 m2)``).

References
----------
Bush, A. W., Gibson, R. D., Thomas, T. R. (1975). The elastic contact of a rough surface. Wear 35,
87-111.
Greenwood, J. A. (2006). A simplified elliptic model of rough surface contact. Wear 261, 191-200.
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from . import _args
from .asperity import AsperityModel, gaussian_tail_moment
from .summits import RoughnessMoments

__all__ = ["SimplifiedBGT"]

_THETA_X, _THETA_W = np.polynomial.legendre.leggauss(32)
_S_X, _S_W = np.polynomial.legendre.leggauss(24)
_U_MAX = 9.0          # e^{-3u²/2} < 1e-52 beyond


@attrs.frozen(kw_only=True)
class SimplifiedBGT(AsperityModel):
    """Greenwood's simplified elliptic (BGT) model; see the module docstring.

    Parameters
    ----------
    moments : RoughnessMoments
        Profile moments (``α = m0 m4/m2² > 3/2``) and, for ``p̃``, the amplitude.

    Notes
    -----
    The separation is ``t = d/√m0`` measured from the mean plane of the surface heights.
    """

    moments: RoughnessMoments = attrs.field(
        validator=attrs.validators.instance_of(RoughnessMoments))

    def __attrs_post_init__(self):
        self.moments.require_isotropic()

    @classmethod
    def from_profile(cls, profile) -> SimplifiedBGT:
        """The model for a :class:`~viscocontact.profiles.Profile`."""
        return cls(moments=RoughnessMoments.from_profile(profile))

    @property
    def amplitude(self) -> float | None:
        """``Λ̃`` of the moments."""
        return self.moments.amplitude

    def _integrals(self, t: float) -> tuple[float, float]:
        """``(∬ T_1 ... , ∬ T_{3/2} ...)`` of the module docstring at separation ``t``."""
        alpha = self.moments.alpha
        c1 = alpha / (2.0 * alpha - 3.0)
        b = 1.5 / math.sqrt(alpha)
        a_s = 0.75 + c1 * b * b
        s_peak = max(c1 * b * t / a_s, 0.0)
        s_max = s_peak + 14.0 / math.sqrt(a_s) + 2.0
        edges = np.linspace(0.0, s_max, 9)
        lo, hi = edges[:-1, None], edges[1:, None]
        s = (0.5 * (hi + lo) + 0.5 * (hi - lo) * _S_X).ravel()
        ws = (0.5 * (hi - lo) * _S_W).ravel()
        th_max = np.arcsin(np.minimum(1.0, _U_MAX / np.maximum(s, 1e-300)))
        th = 0.5 * th_max[:, None] * (1.0 + _THETA_X)
        wt = 0.5 * th_max[:, None] * _THETA_W
        u = s[:, None] * np.sin(th)
        root = s[:, None] * np.cos(th)                       # √(s² - u²)
        du = root * wt                                        # du = s cos θ dθ
        base = 4.0 * u * np.exp(-0.75 * s[:, None] ** 2 - 1.5 * u * u) * du
        inner_a = np.sum(base * root, axis=1)
        inner_p = np.sum(base * root**1.5, axis=1)
        h = math.sqrt(2.0 * c1) * (t - b * s)
        area = float(np.sum(ws * gaussian_tail_moment(1.0, h) * inner_a))
        load = float(np.sum(ws * gaussian_tail_moment(1.5, h) * inner_p))
        return area, load

    def _constants(self) -> tuple[float, float]:
        alpha = self.moments.alpha
        c1 = alpha / (2.0 * alpha - 3.0)
        ka = math.sqrt(27.0) * math.sqrt(alpha) / (32.0 * math.pi * math.sqrt(c1))
        kp = (math.sqrt(27.0) * alpha**0.75 / (12.0 * math.pi**2 * 2.0**1.25 * c1**0.75))
        return ka, kp

    def _map(self, separation, which: int):
        t = _args.real("separation", separation)
        k = self._constants()[which]
        vals = [k * self._integrals(float(x))[which] for x in np.ravel(t)]
        return vals[0] if np.ndim(t) == 0 else np.reshape(vals, np.shape(t))

    def area_fraction(self, separation):
        """``A/A0`` (eq. 3.30) at ``t = d/√m0``."""
        return self._map(separation, 0)

    def reduced_pressure(self, separation):
        """``P/(A0 E* √m2)`` (eq. 3.31)."""
        return self._map(separation, 1)

    def pressure_over_modulus(self, separation):
        """``P/(A0 E*)`` (eq. 3.31)."""
        return math.sqrt(self.moments.m2) * np.asarray(self.reduced_pressure(separation))
