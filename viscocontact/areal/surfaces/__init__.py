"""Areal surfaces: rigid periodic 2D height fields (entry-point group ``viscocontact.surfaces``).

Every surface is a :class:`Surface`: dimensionless coordinates ``x̃ = q0·x``, ``ỹ = q0·y`` on the
cell ``[0, 2π) × [0, 2π·aspect)``, heights ``q0·h`` with zero mean, sampled on uniform grids.

===============================  ==================================================================
:class:`SelfAffineSurface`       power-law PSD ``∝ q^{-2(1+H)}``, exact rms height or gradient,
                                 seeded phases, roll-off, anisotropy ratio and orientation
:class:`MeasuredSurface`         trigonometric interpolant of a height map (``.npy``, text, HDF5)
:class:`ExtrudedProfile`         any 1D profile extruded along y
:class:`SphericalCapLattice`     one spherical cap per cell
:class:`SinusoidSurface`         ``Λ̃ cos(k x̃) cos(l ỹ/aspect)``
:class:`SpectralSurface`         base of the Fourier-series surfaces: exact heights and moments
===============================  ==================================================================

Analysis: :func:`sample_statistics` (rms height, gradient, curvature), :func:`power_spectrum`
(radially averaged PSD) and :func:`fit_hurst`.
"""
from .analysis import (RadialSpectrum, SurfaceStatistics, fit_hurst, power_spectrum,
                       sample_statistics)
from .base import Surface
from .extruded import ExtrudedProfile
from .measured import MeasuredSurface
from .self_affine import SelfAffineSurface
from .sinusoid import SinusoidSurface
from .spectral import SpectralSurface, SurfaceModes
from .spherical_cap import SphericalCapLattice

__all__ = [
    "ExtrudedProfile", "MeasuredSurface", "RadialSpectrum", "SelfAffineSurface", "SinusoidSurface",
    "SpectralSurface", "SphericalCapLattice", "Surface", "SurfaceModes", "SurfaceStatistics",
    "fit_hurst", "power_spectrum", "sample_statistics",
]
