"""Every registered component passes the public conformance checks (plugins included)."""
import numpy as np
import pytest

from viscocontact import _registry
from viscocontact.testing.conformance import check_profile, check_rheology
from viscocontact.testing.conformance_kernels import check_kernel

EXAMPLES = {
    ("profiles", "sinusoid"): dict(amplitude=0.05),
    ("profiles", "self-affine"): dict(hurst=0.8, scales=50, rms=0.01, seed=3),
    ("profiles", "two-scale"): dict(amplitude=0.05, ratio=5, secondary=0.2),
    ("rheologies", "elastic"): dict(),
    ("rheologies", "standard-linear-solid"): dict(beta=10.0),
    ("rheologies", "prony"): dict(moduli=[2.0, 5.0], times=[0.1, 10.0]),
    ("kernels", "half-plane"): dict(),
    ("kernels", "confined-layer"): dict(thickness=0.8, poisson=0.3),
    ("kernels", "free-layer"): dict(thickness=2.0, poisson=0.5),
    ("surfaces", "self-affine"): dict(hurst=0.8, scales=12, rms=0.01, seed=3, anisotropy=2.0),
    ("surfaces", "extruded"): dict(profile={"kind": "sinusoid", "amplitude": 0.05}),
    ("surfaces", "spherical-caps"): dict(radius=3.0, height=0.5),
    ("surfaces", "sinusoid"): dict(amplitude=0.05),
}


def _instance(group, name):
    cls = _registry.REGISTRIES[group].get(name)
    if (group, name) in EXAMPLES:
        return cls(**EXAMPLES[(group, name)])
    example = getattr(cls, "example", None)
    if example is None:
        pytest.fail(f"registered {group} component {name!r} has no example() classmethod: "
                    "plugin components provide one so that the conformance suite can build them")
    return example()


def _names(group):
    return [n for n in _registry.REGISTRIES[group].names()
            if not (group in ("profiles", "surfaces") and n == "measured")]


@pytest.mark.parametrize("name", _names("profiles"))
def test_profiles_conform(name):
    check_profile(_instance("profiles", name))


def test_measured_profile_conforms():
    from viscocontact.profiles.measured import MeasuredProfile
    from viscocontact.profiles.self_affine import SelfAffineProfile

    x = np.linspace(0, 2 * np.pi, 512, endpoint=False)
    heights = SelfAffineProfile(hurst=0.7, scales=20, rms=0.01).heights(x) / 1000.0
    check_profile(MeasuredProfile.from_samples(heights, 2 * np.pi / 1000.0))


@pytest.mark.parametrize("name", _names("rheologies"))
def test_rheologies_conform(name):
    check_rheology(_instance("rheologies", name))


@pytest.mark.parametrize("name", _names("kernels"))
def test_kernels_conform(name):
    check_kernel(_instance("kernels", name))


@pytest.mark.parametrize("name", _registry.REGISTRIES["methods"].names())
def test_methods_conform(name):
    from viscocontact.testing.conformance_methods import check_method

    check_method(_registry.REGISTRIES["methods"].get(name)())


@pytest.mark.parametrize("name", _names("surfaces"))
def test_surfaces_conform(name):
    from viscocontact.testing.conformance_surfaces import check_surface

    check_surface(_instance("surfaces", name))


def test_measured_surface_conforms():
    from viscocontact.areal.surfaces import MeasuredSurface, SelfAffineSurface
    from viscocontact.testing.conformance_surfaces import check_surface

    heights = SelfAffineSurface(hurst=0.7, scales=6, rms=0.01).heights(16, 12) * 1e-7
    check_surface(MeasuredSurface.from_samples(heights, 1e-6),
                  registered="measured" in _registry.REGISTRIES["surfaces"])
