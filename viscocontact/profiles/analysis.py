"""Spectral analysis of profiles: periodogram PSD and Hurst-exponent fit.

Normalisation
-------------
From ``n`` uniform samples ``r_j`` of ``q0·r`` over one period, with
``X_k = Σ_j r_j e^{-2πijk/n}/n``, the one-sided periodogram is::

    P_k = 2|X_k|²   (0 < k < n/2),      P_{n/2} = |X_{n/2}|²   (n even),

at the dimensionless wavenumbers ``k = q/q0`` (spacing ``Δk = 1``). Parseval's theorem gives
``Σ_k P_k Δk = <(r - <r>)²> = m0`` exactly, and for a Fourier series ``Σ a_k cos(k x̃ + φ_k)``
sampled with ``n > 2 k_max``, ``P_k = a_k²/2``. In physical units the one-sided PSD is
``C₁(q_k) = P_k/q0³`` (m³) with ``Σ C₁(q_k) q0 = r_rms²``; the even, two-sided PSD of eq. 4.51 is
``C(±q_k) = C₁(q_k)/2``. Spectral moments are ``m_p = Σ k^p P_k`` (eq. 3.11).
"""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import array_eq
from ..errors import ValidationError
from .base import TWO_PI, Profile
from .spectral import SpectralProfile

__all__ = ["PowerSpectrum", "fit_hurst", "power_spectrum"]


def _ro(value):
    arr = np.array(value, copy=True)
    arr.setflags(write=False)
    return arr


@attrs.frozen(kw_only=True)
class PowerSpectrum:
    """One-sided discrete PSD (see the module docstring for the normalisation).

    Attributes
    ----------
    wavenumbers : ndarray of int, shape (K,)
        ``k = q/q0 = 1..⌊n/2⌋``.
    psd : ndarray, shape (K,)
        ``P_k`` in units of ``(1/q0)²`` per unit k, with ``Σ P_k = m0``.
    """

    wavenumbers: np.ndarray = attrs.field(converter=_ro, eq=array_eq())
    psd: np.ndarray = attrs.field(converter=_ro, eq=array_eq())

    def moment(self, p: float) -> float:
        """``m_p = Σ k^p P_k`` (``m0`` = mean square height, ``m2`` = mean square slope)."""
        return float(np.sum(self.wavenumbers.astype(float) ** p * self.psd))


def power_spectrum(profile_or_heights: Profile | np.ndarray, n: int | None = None) -> PowerSpectrum:
    """Periodogram of a profile (sampled on ``n`` points) or of uniform height samples.

    Parameters
    ----------
    profile_or_heights : Profile or array_like, shape (n,)
        A profile, or samples of ``q0·r`` at ``x̃_j = 2πj/n`` (one period, end point excluded).
    n : int or None
        Number of samples for a profile; default ``max(4096, 4 k_max)`` for spectral profiles
        (exact ``P_k = a_k²/2``), 4096 otherwise. Must not be given with samples.

    Returns
    -------
    PowerSpectrum
        ``P_k`` for ``k = 1..⌊n/2⌋`` with ``Σ P_k = m0`` (Parseval).

    Examples
    --------
    >>> from viscocontact.profiles import Sinusoid
    >>> s = power_spectrum(Sinusoid(amplitude=0.2), n=64)
    >>> round(float(s.psd[0]), 12), round(s.moment(0), 12)
    (0.02, 0.02)
    """
    if isinstance(profile_or_heights, Profile):
        profile = profile_or_heights
        if n is None:
            n = 4096
            if isinstance(profile, SpectralProfile):
                n = max(n, 4 * int(profile.modes.wavenumbers[-1]))
        n = _check_n(n)
        if isinstance(profile, SpectralProfile):
            r = profile.grid_values(n)
        else:
            r = profile.heights(TWO_PI * np.arange(n) / n)
    else:
        r = np.array(profile_or_heights, dtype=float)
        if n is not None:
            raise ValidationError("power_spectrum.n", n, "None when samples are given")
        if r.ndim != 1 or r.size < 4:
            raise ValidationError("power_spectrum.heights", r.shape, "a 1-d array of >= 4 samples")
        if not np.all(np.isfinite(r)):
            raise ValidationError("power_spectrum.heights", "array with NaN/inf", "finite entries")
        n = r.size
    X = np.fft.rfft(r) / n
    P = 2.0 * np.abs(X[1:]) ** 2
    if n % 2 == 0:
        P[-1] = np.abs(X[-1]) ** 2
    return PowerSpectrum(wavenumbers=np.arange(1, P.size + 1), psd=P)


def fit_hurst(profile: Profile | np.ndarray, kmin: float | None = None,
              kmax: float | None = None) -> float:
    """Hurst exponent from a least-squares line through ``log P_k`` against ``log k``.

    Parameters
    ----------
    profile : Profile or array_like
        A profile or uniform samples of ``q0·r`` (as in :func:`power_spectrum`).
    kmin, kmax : float or None
        Fit range in ``k = q/q0``; defaults 1 and the largest k with non-zero power. Use
        ``kmin = rolloff`` for profiles with a roll-off.

    Returns
    -------
    float
        ``H = -(s + 1)/2`` where ``s`` is the fitted slope (``C ∝ q^-(2H+1)``, eqs. 3.14-3.15,
        n = 1). Not clipped to (0, 1].

    Notes
    -----
    For :class:`~viscocontact.profiles.SelfAffineProfile` the amplitudes are deterministic, so the
    fit returns H to rounding; for measured or random-amplitude profiles the periodogram scatter
    (≈ 5.6 dB) makes the estimate converge like ``1/sqrt(number of modes)``.
    """
    spec = power_spectrum(profile)
    k = spec.wavenumbers.astype(float)
    P = spec.psd
    floor = 1e-28 * max(float(P.max()), np.finfo(float).tiny)
    nonzero = P > floor
    lo = 1.0 if kmin is None else float(kmin)
    hi = (float(k[nonzero].max()) if nonzero.any() else 0.0) if kmax is None else float(kmax)
    use = nonzero & (k >= lo) & (k <= hi)
    if np.count_nonzero(use) < 2:
        raise ValidationError("fit_hurst.kmin/kmax", (kmin, kmax),
                              "a range holding at least 2 wavenumbers with non-zero power")
    slope = np.polyfit(np.log(k[use]), np.log(P[use]), 1)[0]
    return float(-(slope + 1.0) / 2.0)


def _check_n(n) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 4:
        raise ValidationError("power_spectrum.n", n, "an integer >= 4")
    return int(n)
