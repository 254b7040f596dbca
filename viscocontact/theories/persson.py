r"""Persson's theory of the elastic contact area (thesis §3.3, equations 3.34-3.45), for a 1D
profile.

Derivation for line roughness on a half-plane
---------------------------------------------
A rigid profile ``r(x)`` (uniform along y) pressed on an elastic half-space is a plane-strain
problem. In full contact the surface displacement follows the profile, and a Fourier mode of
wavenumber q needs the pressure ``p_q = (E*/2)|q| u_q`` (``E* = E/(1-ν²)``); for Westergaard's
sinusoid this is ``p* = E*q0Λ/2 = πE*Λ/λ0``. The pressure fluctuation is ``(E*/2)`` times the
Hilbert transform of the slope, so its variance is

.. math:: V = \langle (p - \bar p)^2\rangle = \frac{E^{*2}}{4}\,\langle r'^2\rangle
          = \frac{E^{*2}}{4}\,m_2 .

Resolving the roughness up to the magnification ``ζ_P = q/q0`` (the thesis's ζ of §3.3, *not* the
sliding speed ζ of eq. 4.17; for the package's periodic profiles ``q_L = q0``), Persson's pressure
distribution diffuses (eq. 3.34) with ``f = dV/(2dζ_P)``, starts from ``δ(σ - p̄)`` (eq. 3.38) and is
absorbed at ``σ = 0`` (eq. 3.42):

.. math::
    P(\sigma, \zeta_P) = g(\sigma - \bar p) - g(\sigma + \bar p),\qquad
    \frac{A}{A_0} = \int_0^\infty P\,d\sigma = \mathrm{erf}\Big(\frac{\bar p}{\sqrt{2V}}\Big)
    = \mathrm{erf}\Big(\frac{\sqrt2\,\bar p}{E^*\sqrt{m_2(\zeta_P)}}\Big),

with ``g`` the Gaussian of variance ``V(ζ_P) = E*² m2(ζ_P)/4`` and
``m2(ζ_P) = ∫_{q0}^{ζ_P q0} q² C₁(q) dq`` (one-sided 1D PSD). This is Persson's 3D result written
with the rms gradient ``ḡ``: there ``V = 2Gp̄² = (E*²/4)<|∇h|²>`` (eqs. 3.36, 3.39), so in both
dimensions ``A/A0 = erf(√2 p̄/(E* ḡ))``, with ``ḡ² = <|∇h|²>`` (surface) or ``<r'²>`` (line). At small
load ``A/A0 ≈ κ p̄/(E*ḡ)`` with ``κ = √(8/π) ≈ 1.60``.

The thesis's eq. 3.45, ``erf(p̄/(E*√m2))`` with ``m2 = π∫q³C dq``, is the same result for an
*isotropic surface* (``<|∇h|²> = 2m2``, and ``m2`` is then the mean square slope of any of its
profiles): :meth:`PerssonContact.area_fraction_isotropic`. Applied to a line profile it would give an
area ``1/√2`` times too small at small load. (Eq. 3.43 prints ``erf(π/(2√G))``; eqs. 3.36-3.39 give
``erf(1/(2√G))``, which is what eq. 3.45 follows from.) Carbone et al. (2009) report that for 1D
roughness Persson's theory underestimates the BEM contact area by about a factor 1/2 (§3.4); that
comparison is part of the validation report, not of this module.

In the package's groups (eq. 4.17) ``p̄/E* = p̃Λ̃/2``, so

.. math:: \frac{A}{A_0} = \frac{\tilde A}{2\pi} = \mathrm{erf}\Big(\frac{\tilde p\,\tilde\Lambda}
          {\sqrt{2 m_2}}\Big),\qquad \text{pressure std } \frac{\sqrt{m_2}}{\tilde\Lambda}
          \ \text{in } \tilde p \text{ units.}

References
----------
Persson, B. N. J. (2001). Theory of rubber friction and contact mechanics. J. Chem. Phys. 115,
3840-3861. doi:10.1063/1.1388626
Carbone, G., Scaraggi, M., Tartaglino, U. (2009). Adhesive contact of rough surfaces: comparison
between numerical calculations and analytical theories. Eur. Phys. J. E 30, 65-74.
"""
from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import special

from . import _args
from .spectrum import LineSpectrum

__all__ = ["PerssonContact"]


@attrs.frozen(kw_only=True)
class PerssonContact:
    """Persson's elastic contact area for a 1D profile (see the module docstring).

    Parameters
    ----------
    spectrum : LineSpectrum
        The profile's one-sided spectrum and amplitude (``LineSpectrum.from_profile(profile)``).

    Examples
    --------
    >>> from viscocontact.profiles import SelfAffineProfile
    >>> p = PerssonContact(spectrum=LineSpectrum.from_profile(
    ...     SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)))
    >>> round(float(p.area_fraction(0.1)), 6)
    0.056199
    """

    spectrum: LineSpectrum = attrs.field(validator=attrs.validators.instance_of(LineSpectrum))

    @classmethod
    def from_profile(cls, profile) -> PerssonContact:
        """The theory for a :class:`~viscocontact.profiles.Profile` (its spectrum and ``Λ̃``)."""
        return cls(spectrum=LineSpectrum.from_profile(profile))

    def slope_variance(self, magnification: float | None = None) -> float:
        """``m2(ζ_P) = Σ_{k <= ζ_P} k² w_k`` (all modes when ``magnification`` is None)."""
        sw = self.spectrum.slope_weights
        if magnification is None:
            return float(np.sum(sw))
        z = _args.real("magnification", magnification, 1.0)
        return float(np.sum(sw[self.spectrum.wavenumbers <= z * (1 + 1e-12)]))

    def area_fraction(self, mean_pressure, magnification: float | None = None):
        """``A/A0 = erf(p̃Λ̃/√(2 m2(ζ_P)))`` for a line profile; ``Ã = 2π·A/A0``.

        ``mean_pressure`` is ``p̃ >= 0`` (eq. 4.17); ``magnification`` ``ζ_P = q/q0 >= 1`` (None: all
        the roughness). Below the first mode (no roughness resolved) the contact is full.
        """
        p = _args.non_negative("mean_pressure", mean_pressure)
        m2 = self.slope_variance(magnification)
        if m2 == 0.0:
            return np.ones_like(p) if np.ndim(p) else 1.0
        return special.erf(p * self.spectrum.amplitude / math.sqrt(2.0 * m2))

    def area_fraction_isotropic(self, mean_pressure):
        """Eq. 3.45 as printed, ``erf(p̄/(E*√m2)) = erf(p̃Λ̃/(2√m2))``: an isotropic surface whose
        profiles have this spectrum."""
        p = _args.non_negative("mean_pressure", mean_pressure)
        return special.erf(p * self.spectrum.amplitude / (2.0 * math.sqrt(self.slope_variance())))

    def mean_pressure_at_area(self, area_fraction):
        """Inverse of :meth:`area_fraction`: ``p̃ = √(2m2) erfinv(A/A0)/Λ̃``, ``A/A0 in [0, 1)``."""
        f = _args.real("area_fraction", area_fraction, 0.0, 1.0, hi_open=True)
        return math.sqrt(2.0 * self.slope_variance()) * special.erfinv(f) / self.spectrum.amplitude

    @property
    def small_load_slope(self) -> float:
        """``d(A/A0)/dp̃`` at ``p̃ = 0``: ``√(2/π) Λ̃/√m2``.

        That is ``κ = √(8/π)`` against ``p̄/(E*√m2)``.
        """
        return math.sqrt(2.0 / math.pi) * self.spectrum.amplitude / math.sqrt(self.slope_variance())

    def pressure_distribution(self, stress, mean_pressure, magnification: float | None = None):
        """``P(σ̃, ζ_P) = g(σ̃ - p̃) - g(σ̃ + p̃)`` for ``σ̃ >= 0`` (0 below), in ``p̃`` units.

        ``g`` is the Gaussian of standard deviation ``√m2(ζ_P)/Λ̃`` (eqs. 3.39, 3.42). Its integral
        is :meth:`area_fraction` and its first moment is ``p̃`` (the load is carried by the contact).
        """
        p = _args.positive("mean_pressure", mean_pressure)
        s = np.asarray(stress, dtype=float)
        sd = math.sqrt(self.slope_variance(magnification)) / self.spectrum.amplitude
        norm = 1.0 / (sd * math.sqrt(2.0 * math.pi))
        val = norm * (np.exp(-0.5 * ((s - p) / sd) ** 2) - np.exp(-0.5 * ((s + p) / sd) ** 2))
        return np.where(s >= 0, val, 0.0)
