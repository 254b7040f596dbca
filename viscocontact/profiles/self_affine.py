"""Self-affine (fractal) random profiles with a power-law spectrum (thesis §3.1 and §4.6).

The discrete profile is a Fourier series over the roughness scales ``k = 1..N_q`` (``q_k = k q0``)::

    q0·r(x̃) = Σ_k a_k cos(k x̃ + φ_k),     a_k = A · sqrt(C(k q0) Δq / C0),  Δq = q0,

with ``C(q) ∝ (q/q0)^-(2H+1)`` (eqs. 3.14-3.15 with n = 1, eq. 4.52), deterministic amplitudes
(``a_k ∝ k^-(H+1/2)``) and random phases. The constant A is fixed so that the rms height is exactly
the requested one (``Σ a_k²/2 = (q0 r_rms)²``, eq. 3.12), which is *not* what eq. 4.53's printed C0
gives; :class:`PowerLawPSD` holds the continuous PSD of eqs. 4.52-4.54 with either normalisation
(see ``docs/profiles.md``).
"""
from __future__ import annotations

import functools
import math

import attrs
import numpy as np

from .._validation import in_range, int_range, positive
from ..errors import ValidationError
from .base import TWO_PI
from .spectral import Modes, SpectralProfile, as_float

__all__ = ["PowerLawPSD", "SelfAffineProfile"]


def _check_rolloff(inst, attribute, value):
    if value is None:
        return
    in_range(1.0, float(inst.scales))(inst, attribute, value)


def _positive_rms(value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if not (math.isfinite(v) and v > 0):
        raise ValidationError("PowerLawPSD.rms", value, "a real number in (0, inf)")
    return v


def _rolloff_converter(value):
    return None if value is None else as_float(value)


@attrs.frozen(kw_only=True)
class SelfAffineProfile(SpectralProfile):
    """Random self-affine profile with ``N_q`` roughness scales and an exact rms height.

    Parameters
    ----------
    hurst : float
        Hurst exponent ``H`` in (0, 1]; the PSD decays as ``k^-(2H+1)`` (1D fractal dimension
        ``2 - H``, eq. 3.16).
    scales : int
        Number of roughness scales ``N_q >= 1``; modes ``k = 1..N_q`` (``q1 = N_q q0``).
    rms : float
        Dimensionless rms height ``q0·r_rms > 0``; the profile's ``m0`` equals ``rms²`` exactly.
    seed : int
        Seed ``>= 0`` of ``numpy.random.default_rng``; the phases are
        ``default_rng(seed).uniform(0, 2π, N_q)`` (so the first phases do not depend on ``N_q``).
    rolloff : float or None
        Roll-off wavenumber ``k_r = q_r/q0`` in ``[1, N_q]``: the PSD is flat, ``C(k_r q0)``, for
        ``k < k_r``. None (default) means no roll-off, as in the thesis's §4.6.

    Notes
    -----
    Amplitudes ``a_k = A w_k`` with ``w_k = max(k, k_r)^-(H+1/2)`` (``k_r = 1`` without roll-off)
    and ``A = rms·sqrt(2/Σw_k²)``. Hence ``m2 = rms²·Σk²w_k²/Σw_k²`` does not depend on the seed.
    For the thesis's case (H = 0.8, N_q = 50, rms = 0.01) ``m2 = 7.705e-4``; the continuous
    integral of eq. 4.54 differs, see :class:`PowerLawPSD` and ``docs/profiles.md``.

    Examples
    --------
    >>> p = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=3)
    >>> abs(p.m0 - 0.01**2) < 1e-18
    True
    >>> round(p.m2, 7)
    0.0007705
    """

    hurst: float = attrs.field(converter=as_float, validator=in_range(0.0, 1.0, lo_open=True))
    scales: int = attrs.field(validator=int_range(1))
    rms: float = attrs.field(converter=as_float, validator=positive)
    seed: int = attrs.field(default=0, validator=int_range(0))
    rolloff: float | None = attrs.field(default=None, converter=_rolloff_converter,
                                        validator=_check_rolloff)

    def relative_amplitudes(self) -> np.ndarray:
        """``w_k = max(k, k_r)^-(H+1/2)`` for ``k = 1..N_q`` (``a_k ∝ sqrt(C(k q0))``)."""
        k = np.arange(1, self.scales + 1, dtype=float)
        if self.rolloff is not None:
            k = np.maximum(k, self.rolloff)
        return k ** -(self.hurst + 0.5)

    @functools.cached_property
    def modes(self) -> Modes:
        """Modes ``k = 1..N_q`` with amplitudes scaled to the exact rms and seeded phases
        (computed once; the arrays are read-only)."""
        w = self.relative_amplitudes()
        a = w * (self.rms * math.sqrt(2.0) / math.sqrt(float(np.sum(w * w))))
        phases = np.random.default_rng(self.seed).uniform(0.0, TWO_PI, self.scales)
        modes = Modes(wavenumbers=np.arange(1, self.scales + 1), amplitudes=a, phases=phases)
        for arr in (modes.wavenumbers, modes.amplitudes, modes.phases):
            arr.flags.writeable = False
        return modes

    def continuous_psd(self) -> PowerLawPSD:
        """The continuous PSD of eqs. 4.52-4.53 with ``C0`` exactly as printed in eq. 4.53.

        Use :meth:`PowerLawPSD.normalised` for the PSD whose m0 equals ``rms²``.
        """
        return PowerLawPSD.from_thesis(hurst=self.hurst, scales=self.scales, rms=self.rms)


@attrs.frozen(kw_only=True)
class PowerLawPSD:
    """Continuous power-law PSD of eq. 4.52 in dimensionless form.

    ``C̃(k) = c0 · max(k, k_r)^-(2H+1)`` for ``1 <= k <= N_q`` and 0 elsewhere, with ``k = q/q0``,
    ``C̃(k) = q0³ C(q)`` and ``c0 = q0³ C0``. Moments are ``m_p = ∫ k^p C̃(k) dk`` over ``[1, N_q]``
    (one-sided reading of eq. 3.11, ``n = 1``), doubled with ``two_sided=True`` (the PSD of
    eq. 4.51 is even in q, so ``<r²> = ∫_{-∞}^{∞} C dq = 2∫_{q0}^{q1} C dq``).

    Parameters
    ----------
    hurst : float
        H in (0, 1].
    scales : float
        ``N_q = q1/q0 > 1``.
    c0 : float
        ``q0³ C0 > 0`` (for q0 in 1/m and C0 in m³, this is dimensionless).
    rolloff : float or None
        Roll-off ``k_r`` in ``[1, N_q]`` (flat PSD below it), or None.
    """

    hurst: float = attrs.field(converter=as_float, validator=in_range(0.0, 1.0, lo_open=True))
    scales: float = attrs.field(converter=as_float, validator=in_range(1.0, lo_open=True))
    c0: float = attrs.field(converter=as_float, validator=positive)
    rolloff: float | None = attrs.field(default=None, converter=_rolloff_converter,
                                        validator=_check_rolloff)

    @classmethod
    def from_thesis(cls, *, hurst: float, scales: float, rms: float) -> PowerLawPSD:
        """``C0`` as printed in eq. 4.53: ``q0 C0 = r_rms² (1 - N_q^-2H)^-1``.

        With this C0 the one-sided ``m0`` is ``rms²/(2H)`` and the two-sided one ``rms²/H``: the
        printed formula lacks a factor 2H (one-sided) or H (two-sided) to give ``m0 = rms²``.
        """
        unit = cls(hurst=hurst, scales=scales, c0=1.0)
        rms = _positive_rms(rms)
        return attrs.evolve(unit, c0=rms**2 / (1.0 - unit.scales ** (-2.0 * unit.hurst)))

    @classmethod
    def normalised(cls, *, hurst: float, scales: float, rms: float, rolloff: float | None = None,
                   two_sided: bool = False) -> PowerLawPSD:
        """The PSD whose ``m0`` (one- or two-sided) is exactly ``rms²``."""
        unit = cls(hurst=hurst, scales=scales, c0=1.0, rolloff=rolloff)
        rms = _positive_rms(rms)
        return attrs.evolve(unit, c0=rms**2 / unit.moment(0, two_sided=two_sided))

    def __call__(self, k: np.ndarray) -> np.ndarray:
        """``C̃(k)`` (zero outside ``[1, N_q]``)."""
        k = np.asarray(k, dtype=float)
        kr = 1.0 if self.rolloff is None else self.rolloff
        inside = (k >= 1.0) & (k <= self.scales)
        return np.where(inside, self.c0 * np.maximum(k, kr) ** -(2 * self.hurst + 1), 0.0)

    def moment(self, p: float, *, two_sided: bool = False) -> float:
        """``m_p = ∫_1^{N_q} k^p C̃(k) dk`` (times 2 if ``two_sided``); ``m2`` is eq. 4.54."""
        b = 2 * self.hurst + 1
        kr = 1.0 if self.rolloff is None else self.rolloff
        flat = kr ** -b * (kr ** (p + 1) - 1.0) / (p + 1)
        e = p + 1 - b
        tail = math.log(self.scales / kr) if e == 0 else (self.scales**e - kr**e) / e
        return (2.0 if two_sided else 1.0) * self.c0 * (flat + tail)

    def physical_c0(self, q0: float) -> float:
        """``C0 = c0/q0³`` in m³ for ``q0`` in 1/m (eq. 4.53 quotes ≈ 1e-13 m³ for q0 ≈ 1000/m)."""
        return self.c0 / float(q0) ** 3
