r"""Greenwood-Williamson with height-dependent summit curvature (Carbone 2009; thesis equations
3.46-3.49).

Intrinsically 3D (isotropic Gaussian surface; the profile is its cross-section, see
:mod:`viscocontact.theories.summits`). Every summit of height ``ξ = z/√m0`` is a Hertzian sphere
whose curvature is the mean summit curvature at that height, ``-K̄_A*(ξ)√m4``
(:func:`~viscocontact.theories.summits.summit_mean_curvature`), with Nayak's summit height density
``p_sum(ξ)`` (eq. 3.49) and ``D_s = m4/(6π√3 m2)``. With ``t = d/√m0`` from the surface's mean plane:

.. math::
    \frac{A}{A_0} = \frac{\sqrt{\alpha}}{6\sqrt3}\int_t^\infty \frac{\xi - t}{-\bar K_A^*(\xi)}
        p_{sum}(\xi)\,d\xi,\qquad
    \frac{P}{A_0E^*\sqrt{m_2}} = \frac{2\alpha^{3/4}}{9\pi\sqrt3}\int_t^\infty
        \frac{(\xi - t)^{3/2}}{\sqrt{-\bar K_A^*(\xi)}}\,p_{sum}(\xi)\,d\xi\quad(3.46\text{-}3.47).

Eq. 3.46 as printed divides the area integrand by ``√(-K̄_A*)``. Hertz's ``A_i = πRδ = πδ/K`` needs
``1/(-K̄_A*)``: the prefactor ``√α/(6√3) = π D_s √(m0/m4)`` of eq. 3.46 is exactly that of
``D_s ∫ π (z - d)/K``, and only with ``1/(-K̄_A*)`` does the model have the property the thesis
claims, an area asymptotically proportional to load, ``A/A0 → √π p/(E*√m2)`` for ``t → ∞`` (the BGT
value; with the printed square root the ratio grows like ``√t``). This module uses ``1/(-K̄_A*)``.

Eq. 3.48 (the printed ``K̄_A*``) is not used: it disagrees with the conditional mean computed from
eq. 3.33 except at ``ξ = 0`` (see ``docs/theories.md``). The integrals use the substitution
``ξ = t + y²`` and composite Gauss-Legendre in ``y``.

References
----------
Carbone, G. (2009). A slightly corrected Greenwood and Williamson model predicts asymptotic
linearity between contact area and load. J. Mech. Phys. Solids 57, 1093-1102.
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from . import _args
from .asperity import AsperityModel
from .summits import RoughnessMoments, _summit_integrals

__all__ = ["HeightCurvatureModel"]

_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)


@attrs.frozen(kw_only=True)
class HeightCurvatureModel(AsperityModel):
    """GW with the summit curvature a function of summit height; see the module docstring.

    Parameters
    ----------
    moments : RoughnessMoments
        Profile moments (``α > 3/2``) and, for ``p̃``, the amplitude.

    Notes
    -----
    The separation is ``t = d/√m0`` from the mean plane of the surface heights.
    """

    moments: RoughnessMoments = attrs.field(
        validator=attrs.validators.instance_of(RoughnessMoments))

    def __attrs_post_init__(self):
        self.moments.require_isotropic()

    @classmethod
    def from_profile(cls, profile) -> HeightCurvatureModel:
        """The model for a :class:`~viscocontact.profiles.Profile`."""
        return cls(moments=RoughnessMoments.from_profile(profile))

    @property
    def amplitude(self) -> float | None:
        """``Λ̃`` of the moments."""
        return self.moments.amplitude

    def _integrals(self, t: float) -> tuple[float, float]:
        """``(∫(ξ-t) p/(-K̄), ∫(ξ-t)^{3/2} p/√(-K̄))`` over ``ξ > t``."""
        alpha = self.moments.alpha
        # ξ - t up to L: beyond, p_sum(ξ)/p_sum(t) < e^{-60} (tail) or p_sum < e^{-90} (ξ > 14)
        span = 14.0 - min(t, 0.0) if t <= 4.0 else min(14.0, 60.0 / t)
        y_max = math.sqrt(span)
        edges = np.linspace(0.0, y_max, 41)
        lo, hi = edges[:-1, None], edges[1:, None]
        y = (0.5 * (hi + lo) + 0.5 * (hi - lo) * _GL_X).ravel()
        w = (0.5 * (hi - lo) * _GL_W).ravel()
        xi = t + y * y
        p_s, n_s, scale = _summit_integrals(xi, alpha)
        with np.errstate(under="ignore"):
            p = p_s * np.exp(scale)
        kbar = n_s / p_s                                     # -K̄_A* > 0
        jac = 2.0 * y * w                                    # dξ = 2y dy
        area = float(np.sum(y**2 / kbar * p * jac))
        load = float(np.sum(y**3 / np.sqrt(kbar) * p * jac))
        return area, load

    def _map(self, separation, which: int):
        t = _args.real("separation", separation)
        alpha = self.moments.alpha
        k = (math.sqrt(alpha) / (6.0 * math.sqrt(3.0)),
             2.0 * alpha**0.75 / (9.0 * math.pi * math.sqrt(3.0)))[which]
        vals = [k * self._integrals(float(x))[which] for x in np.ravel(t)]
        return vals[0] if np.ndim(t) == 0 else np.reshape(vals, np.shape(t))

    def area_fraction(self, separation):
        """``A/A0`` (eq. 3.46, with ``1/(-K̄_A*)``) at ``t = d/√m0``."""
        return self._map(separation, 0)

    def reduced_pressure(self, separation):
        """``P/(A0 E* √m2)`` (eq. 3.47)."""
        return self._map(separation, 1)

    def pressure_over_modulus(self, separation):
        """``P/(A0 E*)``."""
        return math.sqrt(self.moments.m2) * np.asarray(self.reduced_pressure(separation))
