"""The public surface checks pass on every registered kind and catch broken surfaces."""
from __future__ import annotations

import attrs
import numpy as np
import pytest
from hypothesis import given, settings

from viscocontact.areal.surfaces import (ExtrudedProfile, MeasuredSurface, SelfAffineSurface,
                                         SinusoidSurface, SphericalCapLattice, Surface)
from viscocontact.areal.surfaces.tables import build_surface, surface_table
from viscocontact.errors import ValidationError
from viscocontact.profiles import SelfAffineProfile
from viscocontact.testing.conformance_surfaces import check_surface
from viscocontact.testing.strategies_surfaces import surfaces

from .conftest import declared_surfaces

EXAMPLES = {
    "self-affine": SelfAffineSurface(hurst=0.8, scales=12, rms=0.01, seed=3, anisotropy=2.0,
                                     orientation=0.4, aspect=1.5),
    "measured": MeasuredSurface.from_samples(
        SelfAffineSurface(hurst=0.6, scales=5, rms=0.02).heights(12, 10) * 1e-7, 1e-6),
    "extruded": ExtrudedProfile(profile=SelfAffineProfile(hurst=0.8, scales=20, rms=0.01),
                                aspect=0.5),
    "spherical-caps": SphericalCapLattice(radius=3.0, height=0.5),
    "sinusoid": SinusoidSurface(amplitude=0.1, kx=2, ky=1),
}


def test_every_declared_surface_has_an_example():
    assert set(declared_surfaces()) == set(EXAMPLES)


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_registered_surfaces_conform(name, surface_registry):
    surface = EXAMPLES[name]
    assert surface_registry.get(name) is type(surface)
    check_surface(surface)
    table = surface_table(surface)
    assert table["kind"] == name


def test_extruded_table_nests_the_profile(surface_registry):
    table = surface_table(EXAMPLES["extruded"])
    assert table["profile"]["kind"] == "self-affine"
    assert build_surface(table) == EXAMPLES["extruded"]


def test_table_errors_name_the_key(surface_registry):
    with pytest.raises(ValidationError, match=r"surface\.kind.*did you mean 'sinusoid'"):
        build_surface({"kind": "sinusiod", "amplitude": 0.1})
    with pytest.raises(ValidationError, match=r"surface\.amplitude"):
        build_surface({"kind": "sinusoid", "amplitude": -0.1})
    with pytest.raises(ValidationError, match=r"surface\.wavelength"):
        build_surface({"kind": "sinusoid", "amplitude": 0.1, "wavelength": 2})


def test_unregistered_round_trip_goes_through_the_constructor():
    check_surface(SinusoidSurface(amplitude=0.1), registered=False)


@attrs.frozen(kw_only=True)
class OffsetSurface(Surface):
    """A broken surface: heights with a non-zero mean."""

    amplitude: float = 0.1

    def heights(self, nx, ny):
        x, _ = self.grid(nx, ny)
        return self.amplitude * (1.0 + np.cos(x))


@attrs.frozen(kw_only=True)
class TransposedSurface(Surface):
    """A broken surface: heights of shape (nx, ny)."""

    amplitude: float = 0.1

    def heights(self, nx, ny):
        return self.amplitude * np.cos(self.grid(ny, nx)[0])


@attrs.frozen(kw_only=True)
class AveragedSurface(Surface):
    """A broken surface: cell averages of a steep wave instead of point samples."""

    amplitude: float = 0.1

    def heights(self, nx, ny):
        x, _ = self.grid(nx, ny)
        h = np.pi / nx
        return self.amplitude * np.cos(3 * x) * np.sin(3 * h) / (3 * h)


@attrs.frozen(kw_only=True)
class CachedSurface(Surface):
    """A broken surface: hands out the array it keeps."""

    table: np.ndarray = attrs.field(factory=lambda: np.cos(np.arange(16.0)), eq=False)

    def heights(self, nx, ny):
        return np.broadcast_to(self.table[:nx] - self.table[:nx].mean(), (ny, nx))


class MutableSurface(Surface):
    def heights(self, nx, ny):
        return np.zeros((ny, nx))


@pytest.mark.parametrize("surface, message", [
    (OffsetSurface(), "zero mean"),
    (TransposedSurface(), "shape"),
    (AveragedSurface(), "point samples"),
    (CachedSurface(), "writable"),
    (MutableSurface(), "attrs"),
])
def test_broken_surfaces_fail(surface, message):
    with pytest.raises(AssertionError, match=message):
        check_surface(surface, registered=False)


@settings(max_examples=20, deadline=None, derandomize=True)
@given(surfaces())
def test_generated_surfaces_conform(surface):
    check_surface(surface, registered=False)
