"""A periodic lattice of spherical caps: one cap per cell, centred in it."""
from __future__ import annotations

import math

import attrs
import numpy as np

from ..._validation import positive
from ...errors import ValidationError
from ...profiles.spectral import as_float
from .base import TWO_PI, Surface
from .spectral import check_grid

__all__ = ["SphericalCapLattice"]


def _check_height(inst, attribute, value):
    positive(inst, attribute, value)
    if value > inst.radius:
        raise ValidationError("SphericalCapLattice.height", value,
                              f"a real number in (0, radius = {inst.radius:g}] (at most a "
                              "hemisphere)")


def _check_fits(inst, attribute, value):
    positive(inst, attribute, value)
    room = math.pi * min(1.0, value)
    if inst.base_radius > room * (1.0 + 1e-12):
        raise ValidationError("SphericalCapLattice.height", inst.height,
                              f"a cap whose base radius √(2Rh - h²) = {inst.base_radius:.6g} "
                              f"fits in the cell (<= π·min(1, aspect) = {room:.6g})")


@attrs.frozen(kw_only=True)
class SphericalCapLattice(Surface):
    """A spherical cap of radius ``R̃ = q0·R`` and height ``h̃_c`` on a flat, once per cell.

    The cap's centre is the cell's centre ``(π, π·aspect)``; before the mean is removed the
    surface is ``√(R̃² - ρ²) - (R̃ - h̃_c)`` for ``ρ <= b̃`` (``ρ`` the distance to the centre,
    ``b̃ = √(2R̃h̃_c - h̃_c²)`` the base radius) and 0 outside.

    Parameters
    ----------
    radius : float
        ``R̃ = q0·R > 0``, the sphere's radius.
    height : float
        ``h̃_c = q0·`` the cap's height above the flat, in ``(0, R̃]``; the base must fit in the
        cell (``b̃ <= π·min(1, aspect)``).
    aspect : float
        Cell side ratio ``L_y/L_x > 0``.

    Notes
    -----
    :meth:`heights` samples the caps and subtracts the mean of the samples, so the grid's mean is
    zero (the contract) and the cap's top stands ``h̃_c - mean`` above it, where the exact mean is
    the cap's volume over the cell area, ``π h̃_c²(3R̃ - h̃_c)/(3·4π²·aspect)``
    (:attr:`mean_height`). A Hertzian contact of radius ``ã`` on it needs ``ã << b̃`` and a grid
    with many cells across ``ã``.

    Examples
    --------
    >>> s = SphericalCapLattice(radius=10.0, height=0.2)
    >>> h = s.heights(64, 64)
    >>> abs(float(h.mean())) < 1e-15, round(float(h.max() - h.min()), 12)
    (True, 0.2)
    """

    radius: float = attrs.field(converter=as_float, validator=positive)
    height: float = attrs.field(converter=as_float, validator=_check_height)
    aspect: float = attrs.field(default=1.0, converter=as_float, validator=_check_fits)

    @property
    def base_radius(self) -> float:
        """``b̃ = √(2R̃h̃_c - h̃_c²)``, the radius of the cap's rim."""
        return math.sqrt(self.height * (2.0 * self.radius - self.height))

    @property
    def mean_height(self) -> float:
        """The cell mean of the caps above the flat (exact): cap volume over the cell area."""
        volume = math.pi * self.height**2 * (3.0 * self.radius - self.height) / 3.0
        return volume / (TWO_PI * TWO_PI * self.aspect)

    @property
    def m0(self) -> float:
        """``<(q0 h)²>`` over the cell, exact: ``(1/A)∫z² dA - mean²`` with
        ``∫z² dA = π[(R̃⁴ - c⁴)/2 - 4c(R̃³ - c³)/3 + c²(R̃² - c²)]``, ``c = R̃ - h̃_c``."""
        r, c = self.radius, self.radius - self.height
        integral = math.pi * ((r**4 - c**4) / 2.0 - 4.0 * c * (r**3 - c**3) / 3.0
                              + c * c * (r * r - c * c))
        return integral / (TWO_PI * TWO_PI * self.aspect) - self.mean_height**2

    @property
    def gradient_variance(self) -> float:
        """``<|∇h|²>`` over the cell, exact: ``(π/A)[2R̃² ln(R̃/c) - b̃²]`` (infinite for a
        hemisphere, whose rim is vertical)."""
        r, c = self.radius, self.radius - self.height
        if c <= 0.0:
            return math.inf
        return math.pi * (2.0 * r * r * math.log(r / c) - self.base_radius**2) / (
            TWO_PI * TWO_PI * self.aspect)

    def heights(self, nx: int, ny: int) -> np.ndarray:
        """The caps sampled on the ``(ny, nx)`` grid, minus the samples' mean."""
        nx, ny = check_grid(nx, ny)
        x = TWO_PI * np.arange(nx) / nx - math.pi
        y = TWO_PI * self.aspect * (np.arange(ny) / ny - 0.5)
        rho2 = x[None, :] ** 2 + y[:, None] ** 2
        z = np.sqrt(np.maximum(self.radius**2 - rho2, 0.0)) - (self.radius - self.height)
        z = np.maximum(z, 0.0)
        return z - z.mean()
