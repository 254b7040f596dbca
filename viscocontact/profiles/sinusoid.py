"""The single-wavelength (wavy) profile ``q0·r(x̃) = Λ̃ cos x̃``."""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import positive
from .spectral import Modes, SpectralProfile, as_float

__all__ = ["Sinusoid"]


@attrs.frozen(kw_only=True)
class Sinusoid(SpectralProfile):
    """Sinusoidal profile of wavelength λ0: ``q0·r(x̃) = Λ̃ cos x̃``, peak at ``x̃ = 0``.

    Parameters
    ----------
    amplitude : float
        Dimensionless amplitude ``Λ̃ = q0·Λ = 2πΛ/λ0 > 0``.

    Notes
    -----
    The mean square slope is ``m2 = Λ̃²/2 = 2(πΛ/λ0)²`` (thesis eq. 4.58); ``m0 = Λ̃²/2`` and
    ``m4 = Λ̃²/2`` as well (heights in units of 1/q0).

    Examples
    --------
    >>> p = Sinusoid(amplitude=0.1)
    >>> p.peak()
    (0.0, 0.1)
    >>> round(p.m2, 12)
    0.005
    """

    amplitude: float = attrs.field(converter=as_float, validator=positive)

    @property
    def modes(self) -> Modes:
        """One mode: ``k = 1``, ``a = Λ̃``, ``φ = 0``."""
        return Modes(wavenumbers=[1], amplitudes=[self.amplitude], phases=[0.0])

    def heights(self, x: np.ndarray) -> np.ndarray:
        """``Λ̃ cos x̃``."""
        return self.amplitude * np.cos(np.asarray(x, dtype=float))

    def slopes(self, x: np.ndarray) -> np.ndarray:
        """``-Λ̃ sin x̃``."""
        return -self.amplitude * np.sin(np.asarray(x, dtype=float))

    def curvatures(self, x: np.ndarray) -> np.ndarray:
        """``-Λ̃ cos x̃``."""
        return -self.amplitude * np.cos(np.asarray(x, dtype=float))

    def peak(self) -> tuple[float, float]:
        """``(0, Λ̃)`` exactly."""
        return 0.0, self.amplitude

    @property
    def crest_length(self) -> float:
        """``Λ̃``: the crest radius is ``1/(q0²Λ)``."""
        return float(self.amplitude)
