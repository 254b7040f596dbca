"""The 2D sinusoid ``q0·h = Λ̃ cos(k x̃) cos(l ỹ/aspect)``.

Johnson, Greenwood and Higginson's (1985) wavy surface for ``k = l = 1``.
"""
from __future__ import annotations

import attrs
import numpy as np

from ..._validation import int_range, positive
from ...errors import ValidationError
from ...profiles.spectral import as_float
from .spectral import SpectralSurface, SurfaceModes, check_grid

__all__ = ["SinusoidSurface"]


def _check_not_flat(inst, attribute, value):
    int_range(0)(inst, attribute, value)
    if value == 0 and inst.kx == 0:
        raise ValidationError("SinusoidSurface.kx/ky", (inst.kx, value),
                              "integers >= 0, not both 0")


@attrs.frozen(kw_only=True)
class SinusoidSurface(SpectralSurface):
    """Doubly sinusoidal surface ``q0·h = Λ̃ cos(k x̃) cos(l ỹ/aspect)``, peak at the origin.

    Parameters
    ----------
    amplitude : float
        ``Λ̃ = q0·max h > 0``.
    kx, ky : int
        Wavenumbers ``k, l >= 0`` (not both 0) of the cell: ``k`` waves along x, ``l`` along y.
        ``ky = 0`` is the 1D sinusoid extruded along y.
    aspect : float
        Cell side ratio ``L_y/L_x > 0``.

    Notes
    -----
    With ``k, l >= 1`` this is the surface ``Δ[1 - cos(2πx/λ) cos(2πy/λ)]`` of Johnson, Greenwood
    and Higginson (1985) with ``Λ̃ = q0Δ`` (up to the constant): ``m0 = Λ̃²/4`` and
    ``<|∇h|²> = Λ̃²(k² + l²/aspect²)/4``. With ``l = 0``, ``m0 = Λ̃²/2`` as for the 1D sinusoid.

    References
    ----------
    Johnson, K. L., Greenwood, J. A., Higginson, J. G. (1985). The contact of elastic regular wavy
    surfaces. Int. J. Mech. Sci. 27, 383-396. doi:10.1016/0020-7403(85)90029-3

    Examples
    --------
    >>> s = SinusoidSurface(amplitude=0.1)
    >>> float(s.heights(8, 8)[0, 0]), round(s.m0, 12)
    (0.1, 0.0025)
    """

    amplitude: float = attrs.field(converter=as_float, validator=positive)
    kx: int = attrs.field(default=1, validator=int_range(0))
    ky: int = attrs.field(default=1, validator=_check_not_flat)
    aspect: float = attrs.field(default=1.0, converter=as_float, validator=positive)

    @property
    def modes(self) -> SurfaceModes:
        """``(k, l)`` and ``(-k, l)`` with ``a = Λ̃/2`` each (one mode, ``a = Λ̃``, if k or l
        is 0)."""
        if self.kx == 0 or self.ky == 0:
            return SurfaceModes(kx=[self.kx], ky=[self.ky], amplitudes=[self.amplitude],
                                phases=[0.0])
        return SurfaceModes(kx=[-self.kx, self.kx], ky=[self.ky, self.ky],
                            amplitudes=[0.5 * self.amplitude] * 2, phases=[0.0, 0.0])

    def heights(self, nx: int, ny: int) -> np.ndarray:
        """``Λ̃ cos(k x̃_i) cos(l ỹ_j/aspect)`` evaluated directly (no FFT)."""
        nx, ny = check_grid(nx, ny)
        cx = np.cos(2.0 * np.pi * self.kx * np.arange(nx) / nx)
        cy = np.cos(2.0 * np.pi * self.ky * np.arange(ny) / ny)
        return self.amplitude * np.outer(cy, cx)
