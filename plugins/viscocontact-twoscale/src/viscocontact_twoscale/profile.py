"""The two-scale profile: a fundamental wave plus one harmonic.

Shape ``g(x̃) = cos x̃ + s·cos(n x̃ + φ)`` with integer ``n >= 2`` (``ratio``), ``0 <= s < 1``
(``secondary``) and phase ``φ``; the heights are scaled so that, as for every viscocontact profile,
``amplitude`` is ``Λ̃ = q0·max r``::

    q0·r(x̃) = Λ̃ · g(x̃) / max g.

With the default ``φ = 0`` the maximum is at ``x̃ = 0`` and ``max g = 1 + s`` exactly, so
``q0·r = Λ̃ [cos x̃ + s cos(n x̃)] / (1 + s)``.

The class subclasses :class:`viscocontact.profiles.spectral.SpectralProfile`: declaring the two
Fourier modes is all it takes to inherit exact heights, slopes, curvatures, moments, peak and
statistics.
"""
from __future__ import annotations

import math
from functools import lru_cache

import attrs
import numpy as np
from viscocontact import ValidationError
from viscocontact.profiles.spectral import Modes, SpectralProfile

__all__ = ["TwoScaleProfile"]


def _float(value):
    """Convert numbers to float; leave anything else for the validator to reject by name."""
    if isinstance(value, bool):
        return value
    try:
        return float(value)
    except (TypeError, ValueError):
        return value


def _real(lo=None, hi=None, *, lo_open=False, hi_open=False):
    left, right = "(" if lo_open else "[", ")" if hi_open else "]"
    interval = f"{left}{'-inf' if lo is None else lo}, {'inf' if hi is None else hi}{right}"
    desc = f"a finite real number in {interval}"

    def check(inst, attribute, value):
        ok = isinstance(value, float) and math.isfinite(value)
        if ok and lo is not None:
            ok = value > lo if lo_open else value >= lo
        if ok and hi is not None:
            ok = value < hi if hi_open else value <= hi
        if not ok:
            raise ValidationError(f"TwoScaleProfile.{attribute.name}", value, desc)

    return check


def _ratio(inst, attribute, value):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 2:
        raise ValidationError("TwoScaleProfile.ratio", value, "an integer >= 2")


@attrs.frozen(kw_only=True)
class _Shape(SpectralProfile):
    """The unscaled shape ``g``, used once per (ratio, secondary, phase) to find ``max g``."""

    ratio: int
    secondary: float
    phase: float

    @property
    def modes(self) -> Modes:
        return Modes(wavenumbers=[1, self.ratio], amplitudes=[1.0, self.secondary],
                     phases=[0.0, self.phase])


@lru_cache(maxsize=256)
def _shape_max(ratio: int, secondary: float, phase: float) -> float:
    """``max g`` (exactly ``1 + s`` when the harmonic is in phase with the fundamental)."""
    if math.cos(phase) == 1.0 or secondary == 0.0:
        return 1.0 + secondary
    return _Shape(ratio=ratio, secondary=secondary, phase=phase).peak()[1]


@attrs.frozen(kw_only=True)
class TwoScaleProfile(SpectralProfile):
    """Fundamental wave plus one harmonic, scaled so that ``max q0·r = Λ̃``.

    Parameters
    ----------
    amplitude : float
        ``Λ̃ = q0·max r > 0`` (dimensionless, as for :class:`viscocontact.profiles.Sinusoid`).
    ratio : int
        Wavenumber ``n >= 2`` of the harmonic in units of q0 (the profile stays 2π-periodic).
    secondary : float
        Relative amplitude ``s`` of the harmonic, ``0 <= s < 1``.
    phase : float
        Phase ``φ`` of the harmonic (radians), default 0.

    Examples
    --------
    >>> p = TwoScaleProfile(amplitude=0.05, ratio=8, secondary=0.2)
    >>> p.peak()
    (0.0, 0.05)
    >>> round(float(p.heights(np.pi)), 6)     # (-1 + 0.2)/(1.2) * 0.05
    -0.033333
    """

    amplitude: float = attrs.field(converter=_float, validator=_real(0.0, lo_open=True))
    ratio: int = attrs.field(validator=_ratio)
    secondary: float = attrs.field(converter=_float, validator=_real(0.0, 1.0, hi_open=True))
    phase: float = attrs.field(default=0.0, converter=_float, validator=_real())

    @property
    def modes(self) -> Modes:
        """Modes ``k = 1`` and ``k = n`` with amplitudes ``Λ̃/max g`` and ``s Λ̃/max g``."""
        scale = self.amplitude / _shape_max(int(self.ratio), self.secondary, self.phase)
        return Modes(wavenumbers=[1, int(self.ratio)],
                     amplitudes=[scale, scale * self.secondary], phases=[0.0, self.phase])

    def peak(self) -> tuple[float, float]:
        """``(x̃_peak, Λ̃)``; exactly ``(0, Λ̃)`` when ``φ`` is a multiple of 2π."""
        if math.cos(self.phase) == 1.0 or self.secondary == 0.0:
            return 0.0, self.amplitude
        return super().peak()
