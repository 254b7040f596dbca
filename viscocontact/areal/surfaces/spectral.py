"""Spectral surfaces: finite 2D Fourier series on the cell ``[0, 2π) × [0, 2π·aspect)``.

Contract for implementers
-------------------------
1. Subclass :class:`SpectralSurface` (a frozen attrs class, keyword-only) and implement
   :attr:`~SpectralSurface.modes`, returning a :class:`SurfaceModes` value, and
   :attr:`~viscocontact.areal.surfaces.base.Surface.aspect`.
2. Everything else is exact and inherited: :meth:`~SpectralSurface.heights` on any grid (one
   inverse FFT; modes beyond the grid's Nyquist wavenumbers alias exactly as point sampling
   aliases them), the moments and :meth:`~SpectralSurface.statistics`.

Notes
-----
The field is ``q0·h(x̃, ỹ) = Σ_j a_j cos(k_j x̃ + l_j ỹ/aspect + φ_j)`` over modes of one half
plane (``l > 0``, or ``l = 0`` and ``k > 0``): the wavevector of mode j is ``(k_j, l_j/aspect)``
in units of q0 (``q_y = 2π l/L_y``). Each mode holds the mean square ``a_j²/2``, so::

    m0 = <(q0 h)²> = Σ a²/2,    <|∇h|²> = Σ |q̃|² a²/2,    <(∇²h)²>/q0² = Σ |q̃|⁴ a²/2,

(``q̃ = q/q0``), the 2D counterparts of the 1D profiles' ``m0, m2, m4``
(:mod:`viscocontact.profiles.spectral`).
"""
from __future__ import annotations

import abc
import math

import attrs
import numpy as np
import scipy.fft

from ..._validation import array_eq, readonly_floats, readonly_ints
from ...errors import ValidationError
from .analysis import SurfaceStatistics
from .base import Surface

__all__ = ["SpectralSurface", "SurfaceModes", "check_grid"]


def _int_array(value):
    return readonly_ints(value, "SurfaceModes.wavenumbers", "integers")


def _check_shape(inst, attribute, value):
    name = f"SurfaceModes.{attribute.name}"
    if value.ndim != 1:
        raise ValidationError(name, value.shape, "a 1-d array")
    if value.shape != inst.kx.shape:
        raise ValidationError(name, value.shape, f"the shape of kx {inst.kx.shape}")
    if not np.all(np.isfinite(value)):
        raise ValidationError(name, "array with NaN/inf", "finite entries")


def _check_kx(inst, attribute, value):
    if value.ndim != 1 or value.size == 0:
        raise ValidationError("SurfaceModes.kx", value.shape, "a non-empty 1-d array")


def _check_half_plane(inst, attribute, value):
    _check_shape(inst, attribute, value)
    half = (value > 0) | ((value == 0) & (inst.kx > 0))
    if not np.all(half):
        i = int(np.flatnonzero(~half)[0])
        raise ValidationError("SurfaceModes.ky", (int(inst.kx[i]), int(value[i])),
                              "modes of the half plane l > 0, or l = 0 and k > 0")
    key = np.sort(value.astype(np.int64) * (2 * int(np.abs(inst.kx).max()) + 1) + inst.kx)
    if np.any(key[1:] == key[:-1]):
        raise ValidationError("SurfaceModes.kx/ky", "a repeated (k, l) pair", "distinct modes")


@attrs.frozen(kw_only=True)
class SurfaceModes:
    """The Fourier modes of a spectral surface: ``q0·h = Σ a cos(k x̃ + l ỹ/aspect + φ)``.

    Attributes
    ----------
    kx, ky : ndarray of int, shape (N,)
        Mode indices ``(k, l)`` of the half plane ``l > 0`` or (``l = 0``, ``k > 0``), distinct.
        The wavevector is ``(k, l/aspect)`` in units of q0.
    amplitudes : ndarray of float, shape (N,)
        ``a >= 0`` in units of 1/q0.
    phases : ndarray of float, shape (N,)
        ``φ`` in radians.
    """

    kx: np.ndarray = attrs.field(converter=_int_array, validator=_check_kx, eq=array_eq(),
                                 hash=False)
    ky: np.ndarray = attrs.field(converter=_int_array, validator=_check_half_plane,
                                 eq=array_eq(), hash=False)
    amplitudes: np.ndarray = attrs.field(converter=readonly_floats, validator=_check_shape,
                                         eq=array_eq(), hash=False)
    phases: np.ndarray = attrs.field(converter=readonly_floats, validator=_check_shape,
                                     eq=array_eq(), hash=False)

    def wavevectors(self, aspect: float) -> tuple[np.ndarray, np.ndarray]:
        """``(q̃x, q̃y) = (k, l/aspect)`` in units of q0."""
        return self.kx.astype(float), self.ky / float(aspect)

    def moment(self, px: int, py: int, aspect: float) -> float:
        """``Σ q̃x^px q̃y^py a²/2``: e.g. ``(0, 0)`` is m0, ``(2, 0)`` the mean square of
        ``∂h/∂x``, ``(0, 2)`` that of ``∂h/∂y``."""
        qx, qy = self.wavevectors(aspect)
        return float(np.sum(qx**px * qy**py * self.amplitudes**2) / 2.0)

    def gradient_moment(self, aspect: float, power: int = 2) -> float:
        """``Σ |q̃|^power a²/2``: ``<|∇h|²>`` for 2, ``<(∇²h)²>/q0²`` for 4."""
        qx, qy = self.wavevectors(aspect)
        return float(np.sum((qx * qx + qy * qy) ** (power / 2) * self.amplitudes**2) / 2.0)


def check_grid(nx, ny) -> tuple[int, int]:
    """``(nx, ny)`` as integers ``>= 2``, or a :class:`ValidationError` naming the bad one."""
    out = []
    for name, n in (("nx", nx), ("ny", ny)):
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
            raise ValidationError(f"Surface.heights.{name}", n, "an integer >= 2")
        out.append(int(n))
    return out[0], out[1]


class SpectralSurface(Surface):
    """A surface given by a finite 2D Fourier series; see the module docstring."""

    @property
    @abc.abstractmethod
    def modes(self) -> SurfaceModes:
        """The Fourier modes of the surface."""

    def heights(self, nx: int, ny: int) -> np.ndarray:
        """``q0·h`` on the ``(ny, nx)`` grid of :meth:`grid`, exact to rounding (one inverse FFT).

        Modes with ``|k| >= nx/2`` or ``|l| >= ny/2`` alias as point sampling aliases them; use
        :attr:`nyquist_grid` for the smallest grid that resolves every mode.
        """
        nx, ny = check_grid(nx, ny)
        m = self.modes
        return self._synthesis(nx, ny, 0.5 * m.amplitudes * np.exp(1j * m.phases))

    def gradient(self, nx: int, ny: int) -> tuple[np.ndarray, np.ndarray]:
        """``(∂h/∂x, ∂h/∂y)`` (dimensionless slopes) on the grid of :meth:`heights`, exact: the
        derivatives of the Fourier series, sampled."""
        nx, ny = check_grid(nx, ny)
        m = self.modes
        c = 0.5 * m.amplitudes * np.exp(1j * m.phases)
        qx, qy = m.wavevectors(self.aspect)
        return (self._synthesis(nx, ny, 1j * qx * c), self._synthesis(nx, ny, 1j * qy * c))

    def _synthesis(self, nx: int, ny: int, c: np.ndarray) -> np.ndarray:
        """``Σ c e^{i(k x̃ + l ỹ/aspect)} + conj`` over the modes, sampled on the grid."""
        m = self.modes
        # the columns 0..nx/2 of the full Hermitian spectrum: each mode and its conjugate where
        # their aliased x index falls (both in the self-conjugate columns 0 and nx/2)
        spec = np.zeros((ny, nx // 2 + 1), dtype=complex)
        for sign, coef in ((1, c), (-1, np.conj(c))):
            kx, ky = (sign * m.kx) % nx, (sign * m.ky) % ny
            keep = kx <= nx // 2
            np.add.at(spec, (ky[keep], kx[keep]), coef[keep])
        spec[0, 0] = 0.0                       # aliased onto the mean: heights keep zero mean
        return scipy.fft.irfft2(spec * (nx * ny), s=(ny, nx))

    @property
    def nyquist_grid(self) -> tuple[int, int]:
        """The smallest ``(nx, ny)`` that samples every mode without aliasing: ``2 max|k| + 1``
        and ``2 max|l| + 1``."""
        m = self.modes
        return 2 * int(np.abs(m.kx).max()) + 1, 2 * int(np.abs(m.ky).max()) + 1

    @property
    def m0(self) -> float:
        """``<(q0 h)²>``, exact."""
        return self.modes.moment(0, 0, self.aspect)

    @property
    def gradient_variance(self) -> float:
        """``<|∇h|²>`` (dimensionless mean square gradient), exact."""
        return self.modes.gradient_moment(self.aspect, 2)

    def statistics(self) -> SurfaceStatistics:
        """Exact moments from the modes; ``amplitude`` (the highest height) from the samples of
        a power-of-two grid at least twice as fine as :attr:`nyquist_grid` (the grid maximum is a
        lower bound that converges quadratically); skewness and kurtosis are exact (grid means of
        ``h³``, ``h⁴`` on more than ``4 max|k|`` and ``4 max|l|`` points)."""
        m = self.modes
        a = self.aspect
        nx, ny = (1 << max(5, math.ceil(math.log2(2 * n))) for n in self.nyquist_grid)
        h = self.heights(nx, ny)
        m0 = m.moment(0, 0, a)
        sd = math.sqrt(m0)
        return SurfaceStatistics(
            amplitude=float(h.max()), m0=m0, m2x=m.moment(2, 0, a), m2y=m.moment(0, 2, a),
            m2xy=m.moment(1, 1, a), m4=m.gradient_moment(a, 4), rms=sd,
            skewness=float(np.mean(h**3) / sd**3) if sd > 0 else 0.0,
            kurtosis=float(np.mean(h**4) / sd**4) if sd > 0 else 0.0)
