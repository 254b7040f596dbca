r"""Persson's mean-field viscoelastic friction for a 1D profile (a trend reference).

A rigid profile slides at speed V over a viscoelastic half-plane with complex modulus ``E(ω)``
(:class:`~viscocontact.rheology.Rheology`: ``exp(iωt)``, ``E'' >= 0``). A mode of wavenumber
``q = k q0`` excites the solid at ``ω = qV``, i.e. ``ωτ = kζ`` with the package's
``ζ = q0Vτ`` (eq. 4.17; τ the rheology's ``reference_time``).

Full contact (exact, linear)
----------------------------
With ``u = r`` on the whole period the pressure of mode k is ``(|q|E(qV)/(2(1-ν²))) u_q``. The
friction stress ``τ_f = -<p u'>`` (the power fed into the solid over V; ``docs/thesis-notes.md`` §4
for the sign of eq. 4.16) is then, with ``w_k`` the one-sided weights of ``q0·r``
(:class:`~viscocontact.theories.spectrum.LineSpectrum`),

.. math:: \tau_f = \frac{E_0}{2(1-\nu^2)}\sum_k k^2 w_k\,\mathrm{Im}\,\frac{E(k\zeta)}{E_0},

the line analogue of Persson's ``(1/2)∫q³C(q)∫dφ cosφ Im E(qV cosφ)/(1-ν²)`` in 3D.

Partial contact (Persson 2001)
------------------------------
Each mode acts only on the fraction ``P(k)`` of the nominal area in contact at that magnification,
from the viscoelastic pressure variance ``V(k) = Σ_{j<=k} k_j² w_j |E(k_jζ)|²/(4(1-ν²)²)``
(:mod:`viscocontact.theories.persson` with ``E*`` replaced by ``|E(ω)|/(1-ν²)``). In the package's
groups (``p̃ = 2(1-ν²)p/(E0 q0 Λ)``, ``Λ̃ = q0Λ``):

.. math::
    P(k) = \mathrm{erf}\Big(\frac{\tilde p\tilde\Lambda}
        {\sqrt{2\sum_{j\le k} k_j^2 w_j |E(k_j\zeta)/E_0|^2}}\Big),\qquad
    \mu = \frac{1}{\tilde p\tilde\Lambda}\sum_k k^2 w_k\,P(k)\,S(k)\,
        \mathrm{Im}\frac{E(k\zeta)}{E_0},

with ``S = 1`` (Persson 2001) or ``S = γ + (1-γ)P²`` (Persson's later correction, ``γ ≈ 1/2``) when
``contact_correction = γ`` is given. ``μ`` is positive, vanishes in both elastic limits
(``ζ → 0``: ``E → E0``; ``ζ → ∞``: ``E → E∞``, both real) and decreases with load. It is a
mean-field trend for adhesionless sliding: no edge physics, no adhesion. ``μ/√m2`` is the reduced
coefficient of eq. 4.59.

References
----------
Persson, B. N. J. (2001). Theory of rubber friction and contact mechanics. J. Chem. Phys. 115,
3840-3861. doi:10.1063/1.1388626
"""
from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import special

from .._validation import in_range
from ..rheology.base import Rheology
from . import _args
from .spectrum import LineSpectrum

__all__ = ["PerssonFriction"]


@attrs.frozen(kw_only=True)
class PerssonFriction:
    """Persson's viscoelastic friction and contact area for a 1D profile (module docstring).

    Parameters
    ----------
    spectrum : LineSpectrum
        One-sided spectrum and amplitude of the profile.
    rheology : Rheology
        The viscoelastic solid (E0 = ``relaxed_modulus``, τ = ``reference_time``).
    contact_correction : float or None
        ``γ`` in ``S = γ + (1-γ)P²`` (in [0, 1]), or None for ``S = 1``.

    Examples
    --------
    >>> from viscocontact.profiles import Sinusoid
    >>> from viscocontact.rheology import StandardLinearSolid
    >>> f = PerssonFriction(spectrum=LineSpectrum.from_profile(Sinusoid(amplitude=0.1)),
    ...                     rheology=StandardLinearSolid(beta=10.0))
    >>> float(f.coefficient(1e-9, 0.5)) < 1e-9 < float(f.coefficient(1.0, 0.5))
    True
    """

    spectrum: LineSpectrum = attrs.field(validator=attrs.validators.instance_of(LineSpectrum))
    # attrs' instance_of stub takes a concrete type[T]; an abstract class is valid at run time
    rheology: Rheology = attrs.field(
        validator=attrs.validators.instance_of(Rheology))  # type: ignore[type-abstract]
    contact_correction: float | None = attrs.field(
        default=None, validator=attrs.validators.optional(in_range(0.0, 1.0)))

    @classmethod
    def from_profile(cls, profile, rheology: Rheology, *,
                     contact_correction: float | None = None) -> PerssonFriction:
        """The theory for a :class:`~viscocontact.profiles.Profile` on ``rheology``."""
        return cls(spectrum=LineSpectrum.from_profile(profile), rheology=rheology,
                   contact_correction=contact_correction)

    def moduli(self, zeta):
        """``E(kζ/τ)/E0`` for every wavenumber k; shape ``(*shape(ζ), K)``."""
        z = _args.non_negative("zeta", zeta)
        omega = np.multiply.outer(z, self.spectrum.wavenumbers) / self.rheology.reference_time
        return self.rheology.complex_modulus(omega) / self.rheology.relaxed_modulus

    def contact_fractions(self, zeta, mean_pressure):
        """``P(k)``: contact fraction with the roughness resolved up to each k; ``(*shape(ζ), K)``."""
        p = _args.positive("mean_pressure", mean_pressure)
        e = self.moduli(zeta)
        var = np.cumsum(self.spectrum.slope_weights * np.abs(e) ** 2, axis=-1)
        return special.erf(p * self.spectrum.amplitude / np.sqrt(2.0 * var))

    def area_fraction(self, zeta, mean_pressure):
        """``A/A0`` with all the roughness resolved (``Ã = 2π·A/A0``)."""
        return self.contact_fractions(zeta, mean_pressure)[..., -1]

    def coefficient(self, zeta, mean_pressure):
        """Friction coefficient ``μ >= 0`` at speed ``ζ`` and mean pressure ``p̃ > 0``."""
        p = _args.positive("mean_pressure", mean_pressure)
        e = self.moduli(zeta)
        frac = self.contact_fractions(zeta, p)
        if self.contact_correction is not None:
            g = float(self.contact_correction)
            frac = frac * (g + (1.0 - g) * frac**2)
        work = np.sum(self.spectrum.slope_weights * frac * e.imag, axis=-1)
        return work / (p * self.spectrum.amplitude)

    def reduced_coefficient(self, zeta, mean_pressure):
        """``μ/√m2`` (eq. 4.59)."""
        return self.coefficient(zeta, mean_pressure) / math.sqrt(self.spectrum.moment(2))
