"""Hypothesis strategies for areal surfaces, for the package's tests and for plugin authors.

Examples
--------
>>> from hypothesis import given, settings
>>> from viscocontact.testing.strategies_surfaces import surfaces
>>> @settings(max_examples=5, deadline=None, derandomize=True)
... @given(surfaces())
... def test_zero_mean(s):
...     h = s.heights(16, 12)
...     assert abs(h.mean()) <= 1e-12 * abs(h).max()
>>> test_zero_mean()
"""
from __future__ import annotations

import math

from hypothesis import strategies as st

from ..areal.surfaces import (ExtrudedProfile, SelfAffineSurface, SinusoidSurface,
                              SphericalCapLattice)
from .strategies_profiles import sinusoids

__all__ = ["extruded_profiles", "self_affine_surfaces", "sinusoid_surfaces",
           "spherical_cap_lattices", "surfaces"]

_aspects = st.sampled_from([0.5, 1.0, 1.5])


def sinusoid_surfaces() -> st.SearchStrategy:
    """:class:`SinusoidSurface` with ``Λ̃`` in [1e-3, 1] and wavenumbers 0..4 (not both 0)."""
    return st.builds(SinusoidSurface, amplitude=st.floats(1e-3, 1.0), kx=st.integers(1, 4),
                     ky=st.integers(0, 4), aspect=_aspects)


def self_affine_surfaces(max_scales: int = 12) -> st.SearchStrategy:
    """:class:`SelfAffineSurface` with H in [0.2, 1], up to ``max_scales`` scales, any seed,
    anisotropy in [1/2, 2] at any orientation."""
    return st.builds(SelfAffineSurface, hurst=st.floats(0.2, 1.0),
                     scales=st.integers(1, max_scales), rms=st.floats(1e-3, 0.1), seed=st.integers(0, 2**32 - 1),
                     anisotropy=st.floats(0.5, 2.0),
                     orientation=st.floats(0.0, math.pi, exclude_max=True), aspect=_aspects)


@st.composite
def spherical_cap_lattices(draw) -> SphericalCapLattice:
    """:class:`SphericalCapLattice` whose cap fits in the cell."""
    aspect = draw(_aspects)
    radius = draw(st.floats(0.5, 50.0))
    room = math.pi * min(1.0, aspect)
    top = min(radius, radius - math.sqrt(max(radius**2 - room**2, 0.0)))
    height = draw(st.floats(1e-3 * top, top))
    return SphericalCapLattice(radius=radius, height=height, aspect=aspect)


def extruded_profiles() -> st.SearchStrategy:
    """:class:`ExtrudedProfile` of a sinusoid."""
    return st.builds(ExtrudedProfile, profile=sinusoids(), aspect=_aspects)


def surfaces() -> st.SearchStrategy:
    """Any of the built-in kinds above (measured surfaces are built from samples in tests)."""
    return st.one_of(sinusoid_surfaces(), self_affine_surfaces(), spherical_cap_lattices(),
                     extruded_profiles())
