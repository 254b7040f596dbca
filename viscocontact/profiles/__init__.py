"""Rigid periodic profiles (thesis §3.1, §4.6).

Every profile is a :class:`Profile`: dimensionless coordinate ``x̃ = q0·x`` with period 2π, heights
``q0·r`` (zero mean), slopes ``dr/dx``; ``amplitude`` is ``Λ̃ = q0·max r``.

===========================  ======================================================================
:class:`Sinusoid`            ``Λ̃ cos x̃`` (wavy profile; ``m2 = Λ̃²/2``, eq. 4.58)
:class:`SelfAffineProfile`   power-law PSD over ``N_q`` scales, exact rms, seeded phases (eq. 4.52)
:class:`MeasuredProfile`     Fourier series of measured samples (``from_samples/csv/hdf5``)
:class:`SpectralProfile`     base of the three: exact Fourier-series evaluation, moments and peak
:class:`PowerLawPSD`         the continuous PSD of eqs. 4.52-4.54 (C0 of eq. 4.53 or normalised)
===========================  ======================================================================

Analysis: :func:`power_spectrum` (periodogram, ``Σ P_k = m0``) and :func:`fit_hurst`.
"""
from .analysis import PowerSpectrum, fit_hurst, power_spectrum
from .base import Profile, ProfileStatistics
from .measured import MeasuredProfile
from .self_affine import PowerLawPSD, SelfAffineProfile
from .sinusoid import Sinusoid
from .spectral import Modes, SpectralProfile

__all__ = [
    "MeasuredProfile", "Modes", "PowerLawPSD", "PowerSpectrum", "Profile", "ProfileStatistics",
    "SelfAffineProfile", "Sinusoid", "SpectralProfile", "fit_hurst", "power_spectrum",
]
