r"""Statistics of areal surfaces: moments, rms height, gradient and curvature, radial PSD.

Normalisation
-------------
From samples ``h_ij`` of ``q0·h`` on the ``(ny, nx)`` grid of a cell of side ratio ``aspect``, with
``X = fft2(h)/(nx·ny)``, each bin holds the mean square ``P = |X|²`` at the wavevector
``q̃ = (k, l/aspect)`` (units of q0; bins at and beyond the Nyquist index are read as negative
wavenumbers by ``numpy.fft.fftfreq``). Parseval gives ``Σ P = <(h - <h>)²> = m0`` exactly. The
2D PSD is the density of this mean square in the wavevector plane, whose bins have the area
``Δq̃x·Δq̃y = 1/aspect``::

    C̃(q̃) = aspect · P,        ∫ C̃ d²q̃ = m0,        C(q) = C̃/q0⁴  (m⁴),

which is Persson's ``C(q) = (2π)^-2 ∫ <h(x)h(0)> e^{-iq·x} d²x`` (``<h²> = ∫ C d²q``). A
self-affine surface has ``C ∝ q^{-2(1+H)}``. The radial average of :func:`power_spectrum` is the
mean of ``C̃`` over the bins of each annulus ``|q̃| ∈ [j - 1/2, j + 1/2)``.

Moments of the gradient come from the same bins: ``m2x = Σ q̃x² P = <(∂h/∂x)²>``,
``m2y = <(∂h/∂y)²>``, ``m4 = Σ |q̃|⁴ P = <(∇²h)²>/q0²``. For an isotropic surface
``m2x = m2y = m2`` (the mean square slope of any profile cut from it), so
``<|∇h|²> = 2 m2`` and ``<(∇²h)²> = (8/3) m4`` of a profile (Nayak 1971).
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from ..._validation import array_eq
from ...errors import ValidationError
from .base import Surface

__all__ = ["RadialSpectrum", "SurfaceStatistics", "fit_hurst", "power_spectrum",
           "sample_statistics"]


@attrs.frozen(kw_only=True)
class SurfaceStatistics:
    """Height, gradient and curvature statistics of a surface over its cell (q0 units).

    Attributes
    ----------
    amplitude : float
        ``q0·max h`` (heights from the mean plane).
    m0 : float
        ``<(q0 h)²>``.
    m2x, m2y, m2xy : float
        ``<(∂h/∂x)²>``, ``<(∂h/∂y)²>`` and ``<∂h/∂x ∂h/∂y>`` (dimensionless).
    m4 : float
        ``<(∇²h)²>/q0²``.
    rms : float
        ``q0·h_rms = √m0``.
    skewness, kurtosis : float
        Third and fourth standardised moments of the heights.
    """

    amplitude: float
    m0: float
    m2x: float
    m2y: float
    m2xy: float
    m4: float
    rms: float
    skewness: float
    kurtosis: float

    @property
    def rms_slope(self) -> float:
        """``ḡ = √<|∇h|²> = √(m2x + m2y)``, the rms gradient."""
        return math.sqrt(self.m2x + self.m2y)

    @property
    def rms_curvature(self) -> float:
        """``√<(∇²h/2)²>/q0``: the rms of the mean curvature (half the Laplacian), q0 units."""
        return 0.5 * math.sqrt(self.m4)


def _ro(value):
    arr = np.array(value, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


@attrs.frozen(kw_only=True)
class RadialSpectrum:
    """The radially averaged 2D PSD (see the module docstring for the normalisation).

    Attributes
    ----------
    wavenumbers : ndarray, shape (K,)
        Mean ``|q̃| = |q|/q0`` of the bins in each annulus ``j = 1..K`` (annuli inside the
        grid's Nyquist circle only, so each is complete).
    psd : ndarray, shape (K,)
        Mean ``C̃ = q0⁴ C(|q|)`` over the annulus (``∫ C̃ d²q̃ = m0``).
    counts : ndarray, shape (K,)
        Number of bins averaged in each annulus.
    """

    wavenumbers: np.ndarray = attrs.field(converter=_ro, eq=array_eq(), hash=False)
    psd: np.ndarray = attrs.field(converter=_ro, eq=array_eq(), hash=False)
    counts: np.ndarray = attrs.field(converter=_ro, eq=array_eq(), hash=False)


def _samples(surface_or_heights, nx, ny, aspect) -> tuple[np.ndarray, float]:
    if isinstance(surface_or_heights, Surface):
        surface = surface_or_heights
        if aspect is not None:
            raise ValidationError("aspect", aspect, "None when a Surface is given (its own)")
        if nx is None or ny is None:
            grid = getattr(surface, "nyquist_grid", None)
            nx, ny = ((256, 256) if grid is None
                      else (1 << max(6, math.ceil(math.log2(2 * n))) for n in grid))
        return np.asarray(surface.heights(nx, ny), dtype=float), float(surface.aspect)
    h = np.array(surface_or_heights, dtype=float)
    if nx is not None or ny is not None:
        raise ValidationError("nx/ny", (nx, ny), "None when samples are given")
    if h.ndim != 2 or min(h.shape) < 2:
        raise ValidationError("heights", h.shape, "a 2-d array (ny, nx) with nx, ny >= 2")
    if not np.all(np.isfinite(h)):
        raise ValidationError("heights", "array with NaN/inf", "finite entries")
    a = 1.0 if aspect is None else float(aspect)
    if not (math.isfinite(a) and a > 0):
        raise ValidationError("aspect", aspect, "a real number in (0, inf)")
    return h, a


def _periodogram(h: np.ndarray, aspect: float):
    ny, nx = h.shape
    X = np.fft.fft2(h - h.mean()) / (nx * ny)
    qx = np.fft.fftfreq(nx, 1.0 / nx)[None, :]
    qy = (np.fft.fftfreq(ny, 1.0 / ny) / aspect)[:, None]
    return np.abs(X) ** 2, qx, qy


def sample_statistics(surface_or_heights, nx: int | None = None, ny: int | None = None, *,
                      aspect: float | None = None) -> SurfaceStatistics:
    """Statistics of the samples of a surface (or of a height array), by FFT.

    Parameters
    ----------
    surface_or_heights : Surface or array_like, shape (ny, nx)
        A surface, sampled on ``(nx, ny)`` points, or samples of ``q0·h`` on its grid.
    nx, ny : int or None
        Grid for a surface; default a power of two at least twice its
        :attr:`~viscocontact.areal.surfaces.spectral.SpectralSurface.nyquist_grid` (256² for
        surfaces without one).
    aspect : float or None
        ``L_y/L_x`` of the samples' cell (default 1); not given with a surface.

    Notes
    -----
    The gradient moments are those of the trigonometric interpolant of the samples (spectral
    derivatives), exact for a band-limited surface sampled above its Nyquist grid; for a surface
    with kinks (the spherical caps' rims) they converge as the grid is refined.
    """
    h, a = _samples(surface_or_heights, nx, ny, aspect)
    P, qx, qy = _periodogram(h, a)
    q2 = qx * qx + qy * qy
    hc = h - h.mean()
    m0 = float(np.mean(hc * hc))
    sd = math.sqrt(m0)
    return SurfaceStatistics(
        amplitude=float(hc.max()), m0=m0, m2x=float(np.sum(qx * qx * P)),
        m2y=float(np.sum(qy * qy * P)), m2xy=float(np.sum(qx * qy * P)),
        m4=float(np.sum(q2 * q2 * P)), rms=sd,
        skewness=float(np.mean(hc**3) / sd**3) if sd > 0 else 0.0,
        kurtosis=float(np.mean(hc**4) / sd**4) if sd > 0 else 0.0)


def power_spectrum(surface_or_heights, nx: int | None = None, ny: int | None = None, *,
                   aspect: float | None = None) -> RadialSpectrum:
    """Radially averaged PSD of a surface (sampled on ``(nx, ny)``) or of height samples.

    Parameters are those of :func:`sample_statistics`.

    Examples
    --------
    >>> from viscocontact.areal.surfaces import SinusoidSurface
    >>> s = power_spectrum(SinusoidSurface(amplitude=0.2, kx=3, ky=4), nx=32, ny=32)
    >>> i = int(s.psd.argmax())                 # all the power at |q̃| = 5: m0 = Λ̃²/4
    >>> round(float(s.wavenumbers[i])), round(float(s.psd[i] * s.counts[i]), 12)
    (5, 0.01)
    """
    h, a = _samples(surface_or_heights, nx, ny, aspect)
    P, qx, qy = _periodogram(h, a)
    q = np.hypot(qx, qy)
    ny_, nx_ = h.shape
    kmax = int(math.floor(min(nx_ // 2, (ny_ // 2) / a) + 0.5))
    j = np.rint(q).astype(np.int64)
    inside = (j >= 1) & (j <= kmax) & (q < kmax + 0.5)
    idx = j[inside] - 1
    counts = np.bincount(idx, minlength=kmax)
    psd = np.bincount(idx, weights=a * P[inside], minlength=kmax)
    kq = np.bincount(idx, weights=q[inside], minlength=kmax)
    keep = counts > 0
    return RadialSpectrum(wavenumbers=kq[keep] / counts[keep], psd=psd[keep] / counts[keep],
                          counts=counts[keep])


def fit_hurst(surface_or_heights, nx: int | None = None, ny: int | None = None, *,
              aspect: float | None = None, kmin: float = 1.0, kmax: float | None = None) -> float:
    """Hurst exponent from a least-squares line through ``log C̃`` against ``log |q̃|``.

    Every bin with power (not the radial averages) in ``kmin <= |q̃| <= kmax`` enters the fit;
    ``H = -s/2 - 1`` for the fitted slope ``s`` (``C ∝ q^{-2(1+H)}``). For a
    :class:`~viscocontact.areal.surfaces.SelfAffineSurface` (isotropic, deterministic amplitudes)
    sampled above its Nyquist grid this is H to rounding; use ``kmin = rolloff`` with a roll-off.
    """
    h, a = _samples(surface_or_heights, nx, ny, aspect)
    P, qx, qy = _periodogram(h, a)
    q = np.hypot(qx, qy)
    floor = 1e-28 * max(float(P.max()), np.finfo(float).tiny)
    hi = float(q[P > floor].max()) if np.any(P > floor) else 0.0
    hi = hi if kmax is None else float(kmax)
    use = (P > floor) & (q >= kmin * (1 - 1e-12)) & (q <= hi * (1 + 1e-12))
    if np.count_nonzero(np.unique(np.round(q[use], 9))) < 2:
        raise ValidationError("fit_hurst.kmin/kmax", (kmin, kmax),
                              "a range holding at least 2 wavenumbers with non-zero power")
    slope = np.polyfit(np.log(q[use]), np.log(P[use]), 1)[0]
    return float(-slope / 2.0 - 1.0)
