"""Sinusoid: the wavy profile Λ̃ cos x̃."""
from __future__ import annotations

import attrs
import numpy as np
import pytest
from hypothesis import given, settings

from viscocontact import ValidationError
from viscocontact.profiles import Profile, Sinusoid, SpectralProfile
from viscocontact.testing.strategies_profiles import sinusoids

SETTINGS = settings(max_examples=50, deadline=None)


@SETTINGS
@given(p=sinusoids())
def test_m2_is_half_amplitude_squared_eq_4_58(p):
    assert p.m2 == pytest.approx(p.amplitude**2 / 2, rel=1e-15)
    assert p.statistics().m2 == pytest.approx(p.amplitude**2 / 2, rel=1e-15)
    x = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    assert np.mean(p.slopes(x) ** 2) == pytest.approx(p.amplitude**2 / 2, rel=1e-12)


def test_eq_4_58_in_physical_units():
    lam0, big_lambda = 1e-3, 8e-6  # the thesis's equivalent sinusoid of §4.6.2
    p = Sinusoid(amplitude=2 * np.pi * big_lambda / lam0)
    assert p.m2 == pytest.approx(2 * (np.pi * big_lambda / lam0) ** 2, rel=1e-14)
    assert p.m2 == pytest.approx(0.0012633, rel=1e-4)


@SETTINGS
@given(p=sinusoids())
def test_peak_heights_and_statistics(p):
    assert p.peak() == (0.0, p.amplitude)
    assert SpectralProfile.peak(p)[1] == pytest.approx(p.amplitude, rel=1e-15)
    x = np.array([0.0, np.pi / 2, np.pi, 1.234])
    np.testing.assert_allclose(p.heights(x), p.amplitude * np.cos(x), rtol=1e-15)
    np.testing.assert_allclose(p.slopes(x), -p.amplitude * np.sin(x), rtol=1e-15)
    np.testing.assert_allclose(SpectralProfile.heights(p, x), p.heights(x), rtol=0,
                               atol=1e-15 * p.amplitude)
    s = p.statistics()
    assert s.amplitude == p.amplitude
    assert s.rms == pytest.approx(p.amplitude / np.sqrt(2), rel=1e-14)
    assert s.ra == pytest.approx(2 * p.amplitude / np.pi, rel=1e-7)
    assert s.skewness == pytest.approx(0.0, abs=1e-12)
    assert s.kurtosis == pytest.approx(1.5, rel=1e-12)


@pytest.mark.parametrize("bad", [0.0, -1.0, np.nan, np.inf, "big"])
def test_bad_amplitude_names_the_field(bad):
    with pytest.raises(ValidationError) as err:
        Sinusoid(amplitude=bad)
    assert err.value.field == "Sinusoid.amplitude"


def test_is_a_frozen_keyword_only_value():
    p = Sinusoid(amplitude=0.3)
    assert isinstance(p, Profile)
    assert p == Sinusoid(amplitude=0.3) and hash(p) == hash(Sinusoid(amplitude=0.3))
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        p.amplitude = 1.0  # type: ignore[misc]
    with pytest.raises(TypeError):
        Sinusoid(0.3)  # type: ignore[misc]
    assert attrs.evolve(p, amplitude=0.5).m0 == pytest.approx(0.125, rel=1e-15)
