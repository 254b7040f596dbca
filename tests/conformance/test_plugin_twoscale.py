"""The example plugin distribution ``viscocontact-twoscale`` and the public conformance checks.

CI installs the plugin with ``pip install ./plugins/viscocontact-twoscale``.
"""
from __future__ import annotations

import math

import attrs
import numpy as np
import pytest

from viscocontact import ValidationError
from viscocontact._registry import profiles
from viscocontact.groups import dimensionless_groups
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.profiles.base import Profile
from viscocontact.rheology.base import CreepSpectrum, Rheology
from viscocontact.rheology.elastic import Elastic
from viscocontact.rheology.prony import PronySeries
from viscocontact.rheology.sls import StandardLinearSolid
from viscocontact.scene import Scene
from viscocontact.testing.conformance import check_profile, check_rheology

SCENE = """
[profile]
kind = "two-scale"
amplitude = 0.05
ratio = 8
secondary = 0.2

[rheology]
kind = "standard-linear-solid"
beta = 10.0

[adhesion]
kind = "energy-balance"
gamma = 1e-5

[load]
mean_pressure = 0.3

[sliding]
zeta = 0.01
"""


def test_plugin_is_registered():
    assert "two-scale" in profiles.names()
    entry = next(d for d in profiles.describe() if d["name"] == "two-scale")
    assert entry["distribution"] == "viscocontact-twoscale"
    cls = profiles.get("two-scale")
    assert issubclass(cls, Profile) and cls.__name__ == "TwoScaleProfile"


@pytest.mark.parametrize("params", [
    dict(amplitude=0.05, ratio=8, secondary=0.2),
    dict(amplitude=1.5, ratio=2, secondary=0.9, phase=1.0),
    dict(amplitude=0.01, ratio=30, secondary=0.0),
    dict(amplitude=0.3, ratio=3, secondary=0.5, phase=math.pi),
])
def test_two_scale_conforms(params):
    check_profile(profiles.get("two-scale")(**params))


def test_two_scale_shape():
    p = profiles.get("two-scale")(amplitude=0.05, ratio=8, secondary=0.2)
    x = np.linspace(0.0, 2 * np.pi, 33)
    np.testing.assert_allclose(p.heights(x), 0.05 * (np.cos(x) + 0.2 * np.cos(8 * x)) / 1.2,
                               rtol=0, atol=1e-16)
    assert p.peak() == (0.0, 0.05) and p.amplitude == 0.05
    shifted = profiles.get("two-scale")(amplitude=0.05, ratio=2, secondary=0.5, phase=2.0)
    fine = np.linspace(0.0, 2 * np.pi, 1 << 16, endpoint=False)
    assert shifted.peak()[1] == pytest.approx(0.05, rel=1e-12)
    assert float(np.max(shifted.heights(fine))) == pytest.approx(0.05, rel=1e-8)


def test_scene_with_two_scale_profile():
    scene = Scene.from_toml(SCENE)
    assert type(scene.profile).__name__ == "TwoScaleProfile"
    assert Scene.from_toml(scene.to_toml()) == scene
    assert scene.to_dict()["profile"] == {"kind": "two-scale", "amplitude": 0.05, "ratio": 8,
                                          "secondary": 0.2, "phase": 0.0}
    groups = dimensionless_groups(scene)
    assert groups["profile"] == "two-scale"
    assert groups["amplitude"] == 0.05
    assert groups["m2"] == pytest.approx((0.05 / 1.2) ** 2 * (1 + 0.2**2 * 64) / 2, rel=1e-12)


def test_scene_two_scale_physical_amplitude_and_bad_key():
    text = SCENE.replace("amplitude = 0.05\n", "") + (
        "[physical]\nwavelength = 1e-3\namplitude = 2e-5\nE0 = 1e7\n")
    text = text.replace("mean_pressure = 0.3", "penetration = 0.5")
    scene = Scene.from_toml(text)
    assert scene.profile.amplitude == pytest.approx(2 * math.pi / 1e-3 * 2e-5, rel=1e-15)
    with pytest.raises(ValidationError) as info:
        Scene.from_toml(SCENE.replace("ratio = 8", "ratio = 1"))
    assert info.value.field == "profile.ratio"
    with pytest.raises(ValidationError) as info:
        Scene.from_toml(SCENE.replace("ratio = 8", "ratios = 8"))
    assert info.value.field == "profile.ratios" and "'secondary'" in str(info.value)


# ---- the checks pass on the built-ins and catch broken components -----------------------------
@pytest.mark.parametrize("profile", [Sinusoid(amplitude=0.3),
                                     SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=4)])
def test_check_profile_builtins(profile):
    check_profile(profile)


@pytest.mark.parametrize("rheology", [Elastic(modulus=2.0), StandardLinearSolid(beta=10.0, tau=0.5),
                                      PronySeries(moduli=[1.0, 5.0], times=[0.01, 3.0])])
def test_check_rheology_builtins(rheology):
    check_rheology(rheology)


@attrs.frozen(kw_only=True)
class _WrongSlope(Profile):
    amplitude_: float = 0.1

    def heights(self, x):
        return self.amplitude_ * np.cos(np.asarray(x, dtype=float))

    def slopes(self, x):
        return self.amplitude_ * np.sin(np.asarray(x, dtype=float))  # sign error


@attrs.define(kw_only=True)
class _Mutable(Profile):
    a: float = 0.1

    def heights(self, x):
        return self.a * np.cos(np.asarray(x, dtype=float))

    def slopes(self, x):
        return -self.a * np.sin(np.asarray(x, dtype=float))


@attrs.frozen(kw_only=True)
class _NotPeriodic(_WrongSlope):
    def heights(self, x):
        return self.amplitude_ * np.cos(1.1 * np.asarray(x, dtype=float))

    def slopes(self, x):
        return -1.1 * self.amplitude_ * np.sin(1.1 * np.asarray(x, dtype=float))


@pytest.mark.parametrize("profile,message", [
    (_WrongSlope(), "slopes are not the derivative"),
    (_Mutable(), "mutable"),
    (_NotPeriodic(), "not 2π-periodic"),
])
def test_check_profile_catches(profile, message):
    with pytest.raises(AssertionError, match=message):
        check_profile(profile, registered=False)


def test_check_profile_requires_registration():
    @attrs.frozen(kw_only=True)
    class Unregistered(Profile):
        a: float = 0.1

        def heights(self, x):
            return self.a * np.cos(np.asarray(x, dtype=float))

        def slopes(self, x):
            return -self.a * np.sin(np.asarray(x, dtype=float))

    check_profile(Unregistered(), registered=False)
    with pytest.raises(AssertionError, match="not registered"):
        check_profile(Unregistered())


@attrs.frozen(kw_only=True)
class _BadCreep(Rheology):
    """An SLS whose creep spectrum has the wrong retardation time."""

    def _e(self, omega):
        w = np.asarray(omega, dtype=float)
        return (1 + 1j * w) / (1 + 1j * w / 10.0)

    relaxed_modulus = property(lambda self: 1.0)
    instantaneous_modulus = property(lambda self: 10.0)
    reference_time = property(lambda self: 1.0)

    def complex_modulus(self, omega):
        return self._e(omega)

    def creep_spectrum(self):
        return CreepSpectrum(instantaneous=0.1, weights=[0.9], times=[2.0])


@attrs.frozen(kw_only=True)
class _Active(_BadCreep):
    """Negative loss modulus (an active material)."""

    def complex_modulus(self, omega):
        return np.conj(self._e(omega))

    def creep_spectrum(self):
        return CreepSpectrum(instantaneous=0.1, weights=[0.9], times=[1.0])


@pytest.mark.parametrize("rheology,message", [
    (_BadCreep(), "creep spectrum"),
    (_Active(), "loss modulus"),
])
def test_check_rheology_catches(rheology, message):
    with pytest.raises(AssertionError, match=message):
        check_rheology(rheology, registered=False)


def test_solve_with_the_plugin_profile_through_the_scene():
    """The plugin's profile, named only in a scene file, solves with no change to the core."""
    from viscocontact.problem import solve

    scene = Scene.from_toml(SCENE.replace('kind = "energy-balance"\ngamma = 1e-5', 'kind = "none"'))
    assert type(scene.profile).__name__ == "TwoScaleProfile" and not scene.adhesive
    result = solve(scene)
    assert result.converged, result.message
    assert result.mean_pressure == pytest.approx(0.3, rel=1e-10)
    assert 0 < result.area < 2 * np.pi
    assert result.min_gap >= 0.0
    assert result.friction > 0          # viscoelastic dissipation at ζ = 0.01
