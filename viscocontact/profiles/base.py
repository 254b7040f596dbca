"""The :class:`Profile` interface: a rigid 1D periodic profile.

Contract for implementers
-------------------------
1. Coordinates are the thesis's dimensionless ``x̃ = q0·x``; the period is ``2π`` (fundamental
   wavelength λ0). Heights are ``q0·r(x)`` (so the sinusoid's amplitude is ``Λ̃ = q0·Λ``) and slopes
   are ``dr/dx`` (dimensionless, scale-free).
2. Implement :meth:`heights` and :meth:`slopes` (vectorised over any array shape; exact for
   spectral profiles). Everything else has a default built on them.
3. Implementations are frozen attrs classes, keyword-only, validated at construction.
"""
from __future__ import annotations

import abc

import attrs
import numpy as np

TWO_PI = 2.0 * np.pi


@attrs.frozen(kw_only=True)
class ProfileStatistics:
    """Height and slope statistics of a profile over one period (heights in units of 1/q0).

    Attributes
    ----------
    amplitude : float
        ``Λ̃ = q0·max r`` (heights are measured from the mean line).
    m0, m2, m4 : float
        Spectral moments ``<r²>`` (q0² units), ``<r'²>`` (dimensionless), ``<r''²>`` (q0^-2 units).
    rms, ra : float
        Root-mean-square and arithmetic-mean height (q0·r units).
    skewness, kurtosis : float
        Third and fourth standardised moments of the heights.
    """

    amplitude: float
    m0: float
    m2: float
    m4: float
    rms: float
    ra: float
    skewness: float
    kurtosis: float


def sampled_maxima(r: np.ndarray, s: np.ndarray | None = None) -> np.ndarray:
    """Local maxima of periodic samples ``r`` on ``x_j = 2πj/n`` (parabolic vertex, sorted).

    With the slopes ``s`` sampled on the same grid, every fall of the slope from + to - between
    two samples is a maximum as well (at the linear zero of the slope) unless a vertex already
    lies within a sample of it: a shoulder can hold a maximum-minimum pair closer than one sample
    that the heights alone do not show.
    """
    n = len(r)
    h = TWO_PI / n
    left, right = np.roll(r, 1), np.roll(r, -1)
    i = np.flatnonzero((r > left) & (r >= right))
    curv = left[i] - 2.0 * r[i] + right[i]
    with np.errstate(divide="ignore", invalid="ignore"):
        shift = np.where(curv < 0, 0.5 * (left[i] - right[i]) / curv, 0.0)
    x = (i + np.clip(shift, -0.5, 0.5)) * h
    if s is not None:
        nxt = np.roll(s, -1)
        j = np.flatnonzero((s > 0) & (nxt <= 0))
        xs = (j + s[j] / (s[j] - nxt[j])) * h
        if len(x):
            gap = np.abs(np.angle(np.exp(1j * (xs[:, None] - x[None, :])))).min(axis=1)
            xs = xs[gap > h]
        x = np.concatenate([x, xs])
    x = np.mod(x, TWO_PI)
    return np.sort(np.where(x >= TWO_PI, 0.0, x))       # mod of -1e-17 rounds to 2π


class Profile(abc.ABC):
    """A rigid 1D profile, periodic over ``x̃ ∈ [0, 2π)``; see the module docstring."""

    @abc.abstractmethod
    def heights(self, x: np.ndarray) -> np.ndarray:
        """``q0·r(x̃)`` with zero mean over the period."""

    @abc.abstractmethod
    def slopes(self, x: np.ndarray) -> np.ndarray:
        """``dr/dx`` at ``x̃``."""

    def curvatures(self, x: np.ndarray) -> np.ndarray:
        """``d²(q0 r)/dx̃²`` (default: central difference of :meth:`slopes`)."""
        x = np.asarray(x, dtype=float)
        h = 1e-5
        return (self.slopes(x + h) - self.slopes(x - h)) / (2 * h)

    def peak(self) -> tuple[float, float]:
        """``(x̃_peak, Λ̃)``: the position in ``[0, 2π)`` and value of the global maximum height."""
        x = np.linspace(0.0, TWO_PI, 8192, endpoint=False)
        r = self.heights(x)
        i = int(np.argmax(r))
        # refine with a few safeguarded Newton steps on the slope
        xp = x[i]
        for _ in range(30):
            s, c = float(self.slopes(xp)), float(self.curvatures(xp))
            if c >= 0 or not np.isfinite(s / c):
                break
            step = -s / c
            if abs(step) > x[1] - x[0]:
                break
            xp += step
            if abs(step) < 1e-15:
                break
        if self.heights(xp) < r[i]:
            xp = x[i]
        return float(np.mod(xp, TWO_PI)), float(self.heights(xp))

    def local_maxima(self) -> np.ndarray:
        """Sorted positions in ``[0, 2π)`` of the local maxima of the heights: where contacts are
        born, however narrow (the interpenetration check samples the gap there as well as on its
        uniform grid). Default: the maxima of 8192 samples, each refined by the vertex of the
        parabola through it and its neighbours, and the falls of the sampled slope between them
        (see :func:`sampled_maxima`). Override when features are finer than that."""
        x = np.linspace(0.0, TWO_PI, 8192, endpoint=False)
        return sampled_maxima(self.heights(x), self.slopes(x))

    @property
    def shortest_wavelength(self) -> float | None:
        """Shortest wavelength (``x̃`` units) of the heights, or ``None`` when not known.

        The contact solver sizes the elements inside a contact from it
        (:attr:`~viscocontact.problem.Discretization.interior_resolution`); ``None`` leaves the
        elements per contact as given. Spectral profiles return ``2π/k_max``.
        """
        return None

    @property
    def amplitude(self) -> float:
        """``Λ̃ = q0·max r``."""
        return self.peak()[1]

    @property
    def crest_length(self) -> float:
        """``L̃`` of the crest radius ``R = 1/(q0²L)`` that the adhesion parameters (Tabor's μ_T,
        Maugis's λ) take: the equivalent sinusoid of eq. 4.55, ``L̃ = q0·r_rms``, not the crest
        of the highest asperity (:class:`~viscocontact.profiles.Sinusoid`: its amplitude)."""
        return float(self.statistics().rms)

    def statistics(self, n: int = 1 << 14) -> ProfileStatistics:
        """Statistics from ``n`` uniform samples (spectral profiles override with exact moments)."""
        x = np.linspace(0.0, TWO_PI, n, endpoint=False)
        r = self.heights(x)
        s = self.slopes(x)
        k = self.curvatures(x)
        rc = r - r.mean()
        m0 = float(np.mean(rc**2))
        sd = np.sqrt(m0)
        return ProfileStatistics(
            amplitude=self.amplitude, m0=m0, m2=float(np.mean(s**2)), m4=float(np.mean(k**2)),
            rms=float(sd), ra=float(np.mean(np.abs(rc))),
            skewness=float(np.mean(rc**3) / sd**3) if sd > 0 else 0.0,
            kurtosis=float(np.mean(rc**4) / sd**4) if sd > 0 else 0.0)
