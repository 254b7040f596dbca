"""Spectral profiles: finite Fourier series ``q0·r(x̃) = Σ_k a_k cos(k x̃ + φ_k)``.

Contract for implementers
-------------------------
1. Subclass :class:`SpectralProfile` (a frozen attrs class, keyword-only) and implement the
   :attr:`~SpectralProfile.modes` property, returning a :class:`Modes` value (integer wavenumbers
   ``k >= 1`` in units of q0, amplitudes ``a_k`` in units of 1/q0, phases ``φ_k`` in radians).
2. Everything else is exact and inherited: heights, slopes and curvatures at any ``x̃`` (evaluated
   directly, no FFT), values on uniform grids (:meth:`~SpectralProfile.grid_values`, by FFT), the
   spectral moments, :meth:`~SpectralProfile.peak` (to machine precision) and
   :meth:`~SpectralProfile.statistics`.

Notes
-----
For a Fourier series the spectral moments of the thesis's eq. 3.11 are sums over the modes (the
one-sided discrete PSD of mode k is ``a_k²/2``, see :mod:`viscocontact.profiles.analysis`)::

    m0 = <r²>   = Σ a_k²/2,     m2 = <r'²> = Σ k² a_k²/2,     m4 = <r''²> = Σ k⁴ a_k²/2,

with heights in units of 1/q0, so ``m0 = (q0 r_rms)²`` (eq. 3.12) while m2 is the dimensionless mean
square slope of eq. 4.54.
"""
from __future__ import annotations

import abc
import math

import attrs
import numpy as np

from .._validation import array_eq, readonly_floats, readonly_ints
from ..errors import ValidationError
from .base import TWO_PI, Profile, ProfileStatistics, sampled_maxima

__all__ = ["Modes", "SpectralProfile"]

#: Largest number of (point × mode) products evaluated at once by the direct summation.
_CHUNK = 1 << 18


def as_float(value):
    """attrs converter: ``float(value)`` when possible, else the raw value for the validator to
    reject with a :class:`ValidationError` naming the field."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return value


def _int_array(value):
    return readonly_ints(value, "Modes.wavenumbers", "integers >= 1")


def _check_modes(inst, attribute, value):
    if value.ndim != 1:
        raise ValidationError(f"Modes.{attribute.name}", value.shape, "a 1-d array")
    if attribute.name == "wavenumbers":
        if value.size == 0:
            raise ValidationError("Modes.wavenumbers", value, "at least one wavenumber")
        if np.any(value < 1) or np.any(np.diff(value) <= 0):
            raise ValidationError("Modes.wavenumbers", value, "strictly increasing integers >= 1")
    else:
        if value.shape != inst.wavenumbers.shape:
            raise ValidationError(f"Modes.{attribute.name}", value.shape,
                                  f"the shape of wavenumbers {inst.wavenumbers.shape}")
        if not np.all(np.isfinite(value)):
            raise ValidationError(f"Modes.{attribute.name}", "array with NaN/inf", "finite entries")


@attrs.frozen(kw_only=True)
class Modes:
    """The Fourier modes of a spectral profile: ``q0·r(x̃) = Σ_i a_i cos(k_i x̃ + φ_i)``.

    Attributes
    ----------
    wavenumbers : ndarray of int, shape (N,)
        ``k_i = q_i/q0``, strictly increasing, ``>= 1`` (no mean term: heights have zero mean).
    amplitudes : ndarray of float, shape (N,)
        ``a_i`` in units of 1/q0 (i.e. ``q0·`` the physical amplitude).
    phases : ndarray of float, shape (N,)
        ``φ_i`` in radians.
    """

    wavenumbers: np.ndarray = attrs.field(converter=_int_array, validator=_check_modes,
                                          eq=array_eq(), hash=False)
    amplitudes: np.ndarray = attrs.field(converter=readonly_floats, validator=_check_modes,
                                         eq=array_eq(), hash=False)
    phases: np.ndarray = attrs.field(converter=readonly_floats, validator=_check_modes, eq=array_eq(), hash=False)

    @property
    def coefficients(self) -> np.ndarray:
        """Complex coefficients ``c_i = a_i exp(iφ_i)``: ``q0·r = Re Σ c_i exp(i k_i x̃)``."""
        return self.amplitudes * np.exp(1j * self.phases)

    def moment(self, p: int) -> float:
        """Spectral moment ``m_p = Σ k^p a²/2`` (eq. 3.11 with the discrete one-sided PSD a²/2)."""
        k = self.wavenumbers.astype(float)
        return float(np.sum(k**p * self.amplitudes**2) / 2.0)


class SpectralProfile(Profile):
    """A profile given by a finite Fourier series; see the module docstring for the contract."""

    @property
    @abc.abstractmethod
    def modes(self) -> Modes:
        """The Fourier modes (wavenumbers, amplitudes, phases) of the profile."""

    # -- evaluation --------------------------------------------------------------------------------

    def heights(self, x: np.ndarray) -> np.ndarray:
        """``q0·r(x̃)``, exact (direct summation over the modes), same shape as ``x``."""
        return _evaluate(self.modes, x, 0)

    def slopes(self, x: np.ndarray) -> np.ndarray:
        """``dr/dx = d(q0 r)/dx̃ = -Σ k a_k sin(k x̃ + φ_k)``, exact."""
        return _evaluate(self.modes, x, 1)

    def curvatures(self, x: np.ndarray) -> np.ndarray:
        """``d²(q0 r)/dx̃² = -Σ k² a_k cos(k x̃ + φ_k)``, exact."""
        return _evaluate(self.modes, x, 2)

    def grid_values(self, n: int, derivative: int = 0) -> np.ndarray:
        """Values on the uniform grid ``x̃_j = 2πj/n``, ``j = 0..n-1``, by one inverse FFT.

        Parameters
        ----------
        n : int
            Number of grid points (any ``n >= 1``; modes above ``n/2`` are aliased exactly as point
            sampling aliases them).
        derivative : int
            0 for heights, 1 for slopes, 2 for curvatures (any order >= 0 works).

        Returns
        -------
        ndarray, shape (n,)
            Equal (to rounding) to ``heights(2π·arange(n)/n)`` and its derivatives.
        """
        n = int(n)
        if n < 1:
            raise ValidationError("grid_values.n", n, "an integer >= 1")
        modes = self.modes
        c = modes.coefficients * (1j * modes.wavenumbers) ** int(derivative)
        kk = modes.wavenumbers % n
        flip = kk > n // 2
        c = np.where(flip, np.conj(c), c)
        kk = np.where(flip, n - kk, kk)
        spec = np.zeros(n // 2 + 1, dtype=complex)
        # Re(c e^{ikx}) with 0 < k < n/2 contributes n·c/2 to the rfft bin; the bins 0 and n/2 are
        # real (e^{ikx_j} = ±1 there), so only Re(c) counts, with weight n.
        edge = (kk == 0) | (2 * kk == n)
        np.add.at(spec, kk[~edge], 0.5 * n * c[~edge])
        np.add.at(spec, kk[edge], n * c[edge].real)
        return np.fft.irfft(spec, n)

    # -- moments and statistics --------------------------------------------------------------------

    @property
    def shortest_wavelength(self) -> float:
        """``2π/k_max``, ``k_max`` the highest wavenumber with a non-zero amplitude."""
        modes = self.modes
        nonzero = np.flatnonzero(modes.amplitudes != 0)
        kmax = int(modes.wavenumbers[nonzero[-1]]) if nonzero.size else 1
        return TWO_PI / kmax

    @property
    def m0(self) -> float:
        """``<r²> = Σ a²/2`` (q0² units, eq. 3.12), exact."""
        return self.modes.moment(0)

    @property
    def m2(self) -> float:
        """``<r'²> = Σ k² a²/2`` (dimensionless mean square slope, eq. 4.54), exact."""
        return self.modes.moment(2)

    @property
    def m4(self) -> float:
        """``<r''²> = Σ k⁴ a²/2`` (mean square curvature in q0 units), exact."""
        return self.modes.moment(4)

    def statistics(self, n: int = 1 << 14) -> ProfileStatistics:
        """Exact moments, amplitude, skewness and kurtosis; ``ra`` from ``n`` uniform samples.

        Notes
        -----
        The grid mean of ``r^p`` over ``M > p·k_max`` uniform points equals the period mean exactly
        (``r^p`` is a trigonometric polynomial of degree ``p·k_max``), so skewness and kurtosis are
        computed on ``M = max(n, 4 k_max + 1)`` points and are exact to rounding. ``ra = <|r|>``
        converges spectrally with ``n``.
        """
        modes = self.modes
        m0, m2, m4 = modes.moment(0), modes.moment(2), modes.moment(4)
        sd = math.sqrt(m0)
        r = self.grid_values(max(int(n), 4 * int(modes.wavenumbers[-1]) + 1))
        return ProfileStatistics(
            amplitude=self.amplitude, m0=m0, m2=m2, m4=m4, rms=sd, ra=float(np.mean(np.abs(r))),
            skewness=float(np.mean(r**3) / sd**3) if sd > 0 else 0.0,
            kurtosis=float(np.mean(r**4) / sd**4) if sd > 0 else 0.0)

    # -- peak --------------------------------------------------------------------------------------

    def local_maxima(self) -> np.ndarray:
        """Local maxima from ``n >= 16 k_max`` FFT samples (see :meth:`Profile.local_maxima`)."""
        kmax = int(self.modes.wavenumbers[-1])
        n = 1 << max(13, math.ceil(math.log2(16 * kmax)))
        return sampled_maxima(self.grid_values(n), self.grid_values(n, derivative=1))

    def peak(self) -> tuple[float, float]:
        """``(x̃_peak, Λ̃)``: position in ``[0, 2π)`` and value of the global maximum of ``q0·r``.

        Notes
        -----
        The heights are sampled by FFT on ``n >= 16 k_max`` points; every sampled local maximum that
        could hide the global one (within ``h² Σ k²|a_k| / 8`` of the sampled maximum, h the grid
        step) is refined by safeguarded Newton iteration on the exact slope and curvature (bisection
        fallback), and the best is returned. ``Λ̃`` is exact to rounding (~1e-15 relative).
        """
        modes = self.modes
        kmax = int(modes.wavenumbers[-1])
        n = 1 << max(12, math.ceil(math.log2(16 * kmax)))
        h = TWO_PI / n
        r = self.grid_values(n)
        is_max = (r >= np.roll(r, 1)) & (r >= np.roll(r, -1))
        k = modes.wavenumbers.astype(float)
        a = np.abs(modes.amplitudes)
        tol = h * h / 8.0 * float(np.sum(k * k * a)) + 64 * np.finfo(float).eps * float(np.sum(a))
        cand = np.flatnonzero(is_max & (r >= r.max() - tol))
        cand = cand[np.argsort(r[cand])[::-1][:32]]
        best_x, best_r = float(cand[0] * h), float(r[cand[0]])
        for i in cand:
            x = _refine_max(self, i * h, h)
            rx = float(self.heights(np.array(x)))
            if rx > best_r:
                best_x, best_r = x, rx
        return float(np.mod(best_x, TWO_PI)), best_r


def _evaluate(modes: Modes, x, derivative: int) -> np.ndarray:
    """``Re Σ c_k (ik)^d exp(ikx)`` by blocked direct summation (exact to rounding).

    ``exp(i k x)`` with ``k = mB + j`` (``0 <= j < B``) is the product of ``exp(ijx)`` and
    ``exp(imBx)``, both computed by cos/sin, so only ``B + k_max/B`` trigonometric evaluations per
    point are needed and the rest is a real matrix product; rounding error stays ~2 ulp per mode.
    """
    x = np.asarray(x, dtype=float)
    shape = x.shape
    xf = x.ravel()
    k = modes.wavenumbers
    kmax = int(k[-1])
    B = max(1, math.isqrt(kmax))
    M = kmax // B + 1
    c = np.zeros(M * B, dtype=complex)
    c[k] = modes.coefficients * (1j * k) ** int(derivative)
    C = c.reshape(M, B).T  # C[j, m] = c_{mB+j}
    used = np.flatnonzero(np.any(C != 0, axis=0))
    C = C[:, used]
    Cr, Ci = np.ascontiguousarray(C.real), np.ascontiguousarray(C.imag)
    jj = np.arange(B, dtype=float)
    mm = (used * B).astype(float)
    out = np.empty(xf.size)
    step = max(1, _CHUNK // (B + len(used)))
    for s in range(0, xf.size, step):
        xs = xf[s:s + step]
        pj = np.multiply.outer(xs, jj)
        pm = np.multiply.outer(xs, mm)
        ec, es = np.cos(pj), np.sin(pj)
        pr = ec @ Cr - es @ Ci
        pi = ec @ Ci + es @ Cr
        out[s:s + step] = np.sum(np.cos(pm) * pr - np.sin(pm) * pi, axis=1)
    return out.reshape(shape)


def _refine_max(profile: SpectralProfile, x0: float, h: float) -> float:
    """Local maximiser of ``profile.heights`` in ``[x0 - h, x0 + h]`` (rtsafe on the slope)."""
    lo, hi = x0 - h, x0 + h
    s_lo, s_hi = float(profile.slopes(np.array(lo))), float(profile.slopes(np.array(hi)))
    if not (s_lo >= 0.0 >= s_hi):
        return _golden_max(profile, lo, hi)
    x = x0
    for _ in range(100):
        s = float(profile.slopes(np.array(x)))
        if s == 0.0:
            return x
        if s > 0:
            lo = x
        else:
            hi = x
        c = float(profile.curvatures(np.array(x)))
        step = -s / c if c < 0 else np.inf
        x_new = x + step
        if not (lo < x_new < hi):
            x_new = 0.5 * (lo + hi)
        if abs(x_new - x) <= 4 * np.finfo(float).eps * max(1.0, abs(x)) or hi - lo <= 1e-15:
            return x_new
        x = x_new
    return x


def _golden_max(profile: SpectralProfile, lo: float, hi: float) -> float:
    """Golden-section maximisation of the heights on ``[lo, hi]`` (fallback for flat maxima)."""
    g = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo, hi
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = float(profile.heights(np.array(c))), float(profile.heights(np.array(d)))
    while b - a > 1e-13:
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = float(profile.heights(np.array(c)))
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = float(profile.heights(np.array(d)))
    return 0.5 * (a + b)
