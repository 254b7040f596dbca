"""SelfAffineProfile and the continuous PowerLawPSD (thesis eqs. 4.51-4.54)."""
from __future__ import annotations

import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

from viscocontact import ValidationError
from viscocontact.profiles import PowerLawPSD, SelfAffineProfile, fit_hurst
from viscocontact.testing.strategies_profiles import self_affine_profiles

SETTINGS = settings(max_examples=50, deadline=None)
THESIS = dict(hurst=0.8, scales=50, rms=0.01)  # §4.6: H = 0.8, N_q = 50, q0·r_rms = 0.01


@SETTINGS
@given(p=self_affine_profiles(max_scales=256))
def test_rms_is_exactly_the_requested_one(p):
    assert np.sqrt(p.m0) == pytest.approx(p.rms, rel=1e-12)
    assert p.statistics().rms == pytest.approx(p.rms, rel=1e-12)
    n = 4 * p.scales + 4
    assert np.sqrt(np.mean(p.grid_values(n) ** 2)) == pytest.approx(p.rms, rel=1e-12)


@SETTINGS
@given(p=self_affine_profiles(), other=st.integers(0, 2**32 - 1))
def test_seed_determines_the_profile(p, other):
    same = attrs.evolve(p)
    assert same == p and same.modes == p.modes
    x = np.linspace(0, 7, 50)
    np.testing.assert_array_equal(same.heights(x), p.heights(x))
    if other != p.seed:
        q = attrs.evolve(p, seed=other)
        assert q != p
        assert not np.array_equal(q.modes.phases, p.modes.phases)
        np.testing.assert_array_equal(q.modes.amplitudes, p.modes.amplitudes)


def test_phases_are_the_documented_default_rng_draws():
    p = SelfAffineProfile(hurst=0.5, scales=30, rms=0.1, seed=42)
    expected = np.random.default_rng(42).uniform(0, 2 * np.pi, 30)
    np.testing.assert_array_equal(p.modes.phases, expected)
    # first phases do not depend on the number of scales
    longer = attrs.evolve(p, scales=60)
    np.testing.assert_array_equal(longer.modes.phases[:30], p.modes.phases)
    # a few fixed values guard against platform/numpy changes of the stream
    np.testing.assert_allclose(p.modes.phases[:3],
                               [4.862909272689599, 2.757554564287996, 5.3947298351621535],
                               rtol=1e-15)


def test_amplitudes_follow_the_power_law_and_rolloff():
    p = SelfAffineProfile(hurst=0.3, scales=100, rms=0.2, seed=1)
    k = np.arange(1, 101)
    a = p.modes.amplitudes
    np.testing.assert_allclose(a / a[0], k ** -(0.3 + 0.5), rtol=1e-13)
    r = SelfAffineProfile(hurst=0.3, scales=100, rms=0.2, seed=1, rolloff=10)
    b = r.modes.amplitudes
    np.testing.assert_allclose(b[:10], b[9], rtol=1e-14)
    np.testing.assert_allclose(b[9:] / b[9], (k[9:] / 10.0) ** -(0.8), rtol=1e-13)
    assert np.sqrt(r.m0) == pytest.approx(0.2, rel=1e-12)


@pytest.mark.parametrize("hurst", [0.3, 0.5, 0.8])
def test_fitted_hurst_of_long_profiles(hurst):
    p = SelfAffineProfile(hurst=hurst, scales=2000, rms=0.05, seed=7)
    assert fit_hurst(p) == pytest.approx(hurst, abs=0.05)


@settings(max_examples=5, deadline=None)
@given(hurst=st.floats(0.2, 0.95), seed=st.integers(0, 1000))
def test_fitted_hurst_property(hurst, seed):
    p = SelfAffineProfile(hurst=hurst, scales=2000, rms=0.05, seed=seed)
    assert fit_hurst(p) == pytest.approx(hurst, abs=0.05)
    q = attrs.evolve(p, scales=500, rolloff=20.0)
    assert fit_hurst(q, kmin=20) == pytest.approx(hurst, abs=0.05)


def test_m2_of_the_thesis_case_does_not_depend_on_the_seed():
    m2 = [SelfAffineProfile(**THESIS, seed=s).m2 for s in range(20)]
    k = np.arange(1, 51.0)
    expected = 0.01**2 * np.sum(k**2 * k**-2.6) / np.sum(k**-2.6)
    np.testing.assert_allclose(m2, expected, rtol=1e-13)
    assert expected == pytest.approx(7.7049e-4, rel=1e-4)


@pytest.mark.parametrize("kwargs, field", [
    (dict(hurst=0.0, scales=10, rms=0.1), "SelfAffineProfile.hurst"),
    (dict(hurst=1.2, scales=10, rms=0.1), "SelfAffineProfile.hurst"),
    (dict(hurst=np.nan, scales=10, rms=0.1), "SelfAffineProfile.hurst"),
    (dict(hurst=0.5, scales=0, rms=0.1), "SelfAffineProfile.scales"),
    (dict(hurst=0.5, scales=2.5, rms=0.1), "SelfAffineProfile.scales"),
    (dict(hurst=0.5, scales=True, rms=0.1), "SelfAffineProfile.scales"),
    (dict(hurst=0.5, scales=10, rms=0.0), "SelfAffineProfile.rms"),
    (dict(hurst=0.5, scales=10, rms="x"), "SelfAffineProfile.rms"),
    (dict(hurst=0.5, scales=10, rms=0.1, seed=-1), "SelfAffineProfile.seed"),
    (dict(hurst=0.5, scales=10, rms=0.1, seed=1.0), "SelfAffineProfile.seed"),
    (dict(hurst=0.5, scales=10, rms=0.1, rolloff=0.5), "SelfAffineProfile.rolloff"),
    (dict(hurst=0.5, scales=10, rms=0.1, rolloff=11), "SelfAffineProfile.rolloff"),
])
def test_validation_names_the_field(kwargs, field):
    with pytest.raises(ValidationError) as err:
        SelfAffineProfile(**kwargs)
    assert err.value.field == field
    assert field in str(err.value)


def test_single_scale_is_a_sinusoid_with_the_requested_rms():
    p = SelfAffineProfile(hurst=1.0, scales=1, rms=0.1, seed=3)
    assert p.amplitude == pytest.approx(0.1 * np.sqrt(2), rel=1e-14)
    assert p.m2 == pytest.approx(p.m0, rel=1e-15)


# -- continuous PSD --------------------------------------------------------------------------------

def quad_moment(psd: PowerLawPSD, p: float) -> float:
    kr = psd.rolloff or 1.0
    points = [kr] if kr > 1 else None
    return integrate.quad(lambda k: k**p * float(psd(k)), 1.0, psd.scales, points=points,
                          epsabs=0, epsrel=1e-12, limit=200)[0]


@pytest.mark.parametrize("hurst, rolloff, p", [(0.8, None, 0), (0.8, None, 2), (0.5, None, 1),
                                               (0.3, 5.0, 2), (1.0, 3.0, 0), (0.5, 4.0, 1)])
def test_continuous_moments_match_quadrature(hurst, rolloff, p):
    psd = PowerLawPSD(hurst=hurst, scales=50, c0=2.0, rolloff=rolloff)
    assert psd.moment(p) == pytest.approx(quad_moment(psd, p), rel=1e-10)
    assert psd.moment(p, two_sided=True) == pytest.approx(2 * psd.moment(p), rel=1e-15)


def test_thesis_numbers_eqs_4_53_and_4_54():
    printed = SelfAffineProfile(**THESIS).continuous_psd()
    assert printed == PowerLawPSD.from_thesis(**THESIS)
    assert printed.physical_c0(q0=1000.0) == pytest.approx(1.0e-13, rel=2e-3)  # "≈ 1e-13"
    # the printed C0 does not give m0 = r_rms² in either convention
    assert printed.moment(0) == pytest.approx(0.01**2 / 1.6, rel=1e-12)
    assert printed.moment(0, two_sided=True) == pytest.approx(0.01**2 / 0.8, rel=1e-12)
    assert printed.moment(2) == pytest.approx(9.4725e-4, rel=1e-4)
    assert printed.moment(2, two_sided=True) == pytest.approx(1.8945e-3, rel=1e-4)
    one = PowerLawPSD.normalised(**THESIS)
    two = PowerLawPSD.normalised(**THESIS, two_sided=True)
    assert one.moment(0) == pytest.approx(1e-4, rel=1e-13)
    assert two.moment(0, two_sided=True) == pytest.approx(1e-4, rel=1e-13)
    assert one.moment(2) == pytest.approx(two.moment(2, two_sided=True), rel=1e-13)
    assert one.moment(2) == pytest.approx(1.5156e-3, rel=1e-4)
    # printed C0 lacks the factor 2H (one-sided) / H (two-sided)
    assert one.c0 == pytest.approx(1.6 * printed.c0, rel=1e-13)
    assert two.c0 == pytest.approx(0.8 * printed.c0, rel=1e-13)


def test_continuous_psd_values_and_validation():
    psd = PowerLawPSD(hurst=0.5, scales=10, c0=1.0, rolloff=2.0)
    np.testing.assert_allclose(psd(np.array([0.5, 1.0, 2.0, 4.0, 10.0, 11.0])),
                               [0.0, 0.25, 0.25, 1 / 16, 1e-2, 0.0], rtol=1e-15)
    for kwargs, field in [(dict(hurst=0.5, scales=1.0, c0=1.0), "PowerLawPSD.scales"),
                          (dict(hurst=0.0, scales=5.0, c0=1.0), "PowerLawPSD.hurst"),
                          (dict(hurst=0.5, scales=5.0, c0=-1.0), "PowerLawPSD.c0")]:
        with pytest.raises(ValidationError) as err:
            PowerLawPSD(**kwargs)
        assert err.value.field == field
    with pytest.raises(ValidationError, match="PowerLawPSD.rms"):
        PowerLawPSD.normalised(hurst=0.5, scales=5, rms=0.0)
    with pytest.raises(ValidationError, match="PowerLawPSD.scales"):
        PowerLawPSD.from_thesis(hurst=0.5, scales=1, rms=0.1)
