r"""The one-sided roughness spectrum of a 1D profile, as Persson's theory needs it.

A :class:`LineSpectrum` is a list of wavenumbers ``k_j = q_j/q0`` with weights ``w_j`` such that
every spectral integral of the thesis's eq. 3.11 (n = 1, one-sided) is a sum::

    m_p = ∫ q^p C₁(q) dq  →  Σ_j k_j^p w_j ,        m0 = Σ w_j = <(q0 r)²>,   m2 = Σ k_j² w_j = <r'²>.

For a Fourier series ``Σ a_k cos(k x̃ + φ_k)`` (every :class:`~viscocontact.profiles.SpectralProfile`)
the weights are exactly ``a_k²/2`` (docs/profiles.md); for other profiles they are the periodogram
of :func:`~viscocontact.profiles.power_spectrum`; for a continuous
:class:`~viscocontact.profiles.PowerLawPSD` they are Gauss-Legendre weights of ``C̃(k) dk`` in
``log k``. The amplitude ``Λ̃ = q0·max r`` converts pressures to the package's ``p̃`` (eq. 4.17).
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from .._validation import array_eq, positive
from ..errors import ValidationError
from ._args import as_float

__all__ = ["LineSpectrum"]


def _ro(value):
    arr = np.array(value, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


def _check_wavenumbers(inst, attribute, value):
    if value.ndim != 1 or value.size == 0:
        raise ValidationError("LineSpectrum.wavenumbers", value.shape, "a non-empty 1-d array")
    if not np.all(np.isfinite(value)) or np.any(value <= 0) or np.any(np.diff(value) <= 0):
        raise ValidationError("LineSpectrum.wavenumbers", value,
                              "strictly increasing finite numbers > 0")


def _check_weights(inst, attribute, value):
    if value.shape != inst.wavenumbers.shape:
        raise ValidationError("LineSpectrum.weights", value.shape,
                              f"the shape of wavenumbers {inst.wavenumbers.shape}")
    if not np.all(np.isfinite(value)) or np.any(value < 0) or not np.any(value > 0):
        raise ValidationError("LineSpectrum.weights", value,
                              "finite numbers >= 0, not all zero")


@attrs.frozen(kw_only=True)
class LineSpectrum:
    """Discrete one-sided spectrum of a 1D profile (see the module docstring).

    Parameters
    ----------
    wavenumbers : array_like, shape (K,)
        ``k_j = q_j/q0 > 0``, strictly increasing.
    weights : array_like, shape (K,)
        ``w_j >= 0`` (units of (1/q0)², i.e. of ``m0``).
    amplitude : float
        ``Λ̃ = q0·max r > 0``.

    Examples
    --------
    >>> from viscocontact.profiles import Sinusoid
    >>> s = LineSpectrum.from_profile(Sinusoid(amplitude=0.2))
    >>> round(s.moment(0), 12), round(s.moment(2), 12), s.amplitude
    (0.02, 0.02, 0.2)
    """

    wavenumbers: np.ndarray = attrs.field(converter=_ro, validator=_check_wavenumbers,
                                          eq=array_eq(), hash=False)
    weights: np.ndarray = attrs.field(converter=_ro, validator=_check_weights, eq=array_eq(),
                                      hash=False)
    amplitude: float = attrs.field(converter=as_float, validator=positive)

    @classmethod
    def from_profile(cls, profile, n: int | None = None) -> LineSpectrum:
        """Exact weights ``a_k²/2`` of a spectral profile, else its periodogram on ``n`` points."""
        from ..profiles import SpectralProfile, power_spectrum

        if isinstance(profile, SpectralProfile):
            modes = profile.modes
            return cls(wavenumbers=modes.wavenumbers.astype(float),
                       weights=modes.amplitudes**2 / 2.0, amplitude=profile.amplitude)
        ps = power_spectrum(profile, n)
        keep = ps.psd > 0
        return cls(wavenumbers=ps.wavenumbers[keep].astype(float), weights=ps.psd[keep],
                   amplitude=profile.amplitude)

    @classmethod
    def from_psd(cls, psd, *, amplitude: float, nodes: int = 64,
                 two_sided: bool = False) -> LineSpectrum:
        """Quadrature of a continuous :class:`~viscocontact.profiles.PowerLawPSD`.

        ``nodes`` Gauss-Legendre points in ``log k`` on ``[1, k_r]`` and on ``[k_r, N_q]`` (the PSD
        is a power law on each, exact to rounding for ``m0, m2`` with the default). ``two_sided``
        doubles the weights, so that ``Σ w = psd.moment(0, two_sided=True)``.
        """
        if not isinstance(nodes, (int, np.integer)) or nodes < 2:
            raise ValidationError("LineSpectrum.from_psd.nodes", nodes, "an integer >= 2")
        x, w = np.polynomial.legendre.leggauss(int(nodes))
        kr = 1.0 if psd.rolloff is None else float(psd.rolloff)
        ks, ws = [], []
        for lo, hi in ((1.0, kr), (kr, float(psd.scales))):
            if hi <= lo:
                continue
            a, b = math.log(lo), math.log(hi)
            k = np.exp(0.5 * (a + b) + 0.5 * (b - a) * x)
            ks.append(k)
            ws.append(0.5 * (b - a) * w * k * psd(k))
        k = np.concatenate(ks)
        wt = np.concatenate(ws) * (2.0 if two_sided else 1.0)
        return cls(wavenumbers=k, weights=wt, amplitude=amplitude)

    def moment(self, p: float) -> float:
        """``m_p = Σ k^p w`` (eq. 3.11, one-sided)."""
        return float(np.sum(self.wavenumbers**p * self.weights))

    @property
    def slope_weights(self) -> np.ndarray:
        """``k² w``: each wavenumber's share of ``m2``."""
        return self.wavenumbers**2 * self.weights
