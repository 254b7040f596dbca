"""Time-temperature superposition: WLF (eq. 2.27, log10), Arrhenius (eq. 2.28, ln), shift()."""
import math

import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact.errors import ValidationError
from viscocontact.rheology import (
    WLF, Arrhenius, Elastic, PronySeries, StandardLinearSolid, shift)
from viscocontact.rheology.shift import GAS_CONSTANT
from viscocontact.testing.strategies_rheology import log_uniform, rheologies

WLF_UNIVERSAL = WLF(c1=17.44, c2=51.6, reference_temperature=300.0)


def test_wlf_is_eq_2_27_with_decimal_log():
    t = np.array([280.0, 300.0, 310.0, 350.0])
    dt = t - 300.0
    expected = 10.0 ** (-17.44 * dt / (51.6 + dt))
    np.testing.assert_allclose(WLF_UNIVERSAL.shift_factor(t), expected, rtol=1e-14)
    np.testing.assert_allclose(WLF_UNIVERSAL.log10_shift_factor(t), np.log10(expected),
                               atol=1e-13)
    assert WLF_UNIVERSAL.shift_factor(300.0) == 1.0
    assert WLF_UNIVERSAL.shift_factor(310.0) < 1.0 < WLF_UNIVERSAL.shift_factor(290.0)


@pytest.mark.parametrize("temperature", [300.0 - 51.6, 240.0, [310.0, 248.4]])
def test_wlf_raises_at_and_below_the_singularity(temperature):
    with pytest.raises(ValidationError, match="WLF.shift_factor.temperature") as info:
        WLF_UNIVERSAL.shift_factor(temperature)
    assert "C2" in str(info.value) and "248.4" in str(info.value)
    assert WLF_UNIVERSAL.vogel_temperature == pytest.approx(248.4)


def test_arrhenius_is_eq_2_28_with_natural_log():
    arr = Arrhenius(activation_energy=80e3, reference_temperature=250.0)
    t = np.array([200.0, 250.0, 260.0])
    expected = np.exp(80e3 / GAS_CONSTANT * (1 / t - 1 / 250.0))
    np.testing.assert_allclose(arr.shift_factor(t), expected, rtol=1e-14)
    assert arr.shift_factor(250.0) == 1.0
    assert arr.shift_factor(260.0) < 1.0 < arr.shift_factor(240.0)
    assert GAS_CONSTANT == pytest.approx(8.314462618)


@pytest.mark.parametrize("make, field", [
    (lambda: WLF(c1=-1.0, c2=51.6, reference_temperature=300.0), "WLF.c1"),
    (lambda: WLF(c1=17.0, c2=0.0, reference_temperature=300.0), "WLF.c2"),
    (lambda: WLF(c1=17.0, c2=50.0, reference_temperature=float("nan")),
     "WLF.reference_temperature"),
    (lambda: Arrhenius(activation_energy=-5.0, reference_temperature=300.0),
     "Arrhenius.activation_energy"),
    (lambda: Arrhenius(activation_energy=5.0, reference_temperature=0.0),
     "Arrhenius.reference_temperature"),
    (lambda: Arrhenius(activation_energy=5.0, reference_temperature=300.0).shift_factor(-3.0),
     "Arrhenius.shift_factor.temperature"),
    (lambda: WLF_UNIVERSAL.shift_factor(float("nan")), "WLF.shift_factor.temperature"),
    (lambda: WLF_UNIVERSAL.shift_factor(248.5), "WLF.shift_factor.temperature"),   # overflow
    (lambda: Arrhenius(activation_energy=5e5, reference_temperature=300.0).shift_factor(10.0),
     "Arrhenius.shift_factor.temperature"),
])
def test_bad_parameters_name_the_field(make, field):
    with pytest.raises(ValidationError, match=field.replace(".", r"\.")):
        make()


def test_shift_scales_every_time_field():
    sls = shift(StandardLinearSolid(modulus=2.0, beta=5.0, tau=4.0), 0.25)
    assert sls == StandardLinearSolid(modulus=2.0, beta=5.0, tau=1.0)
    p = PronySeries(relaxed_modulus=1.0, moduli=[1.0, 2.0], times=[0.1, 10.0], reference_time=2)
    q = shift(p, 10.0)
    np.testing.assert_allclose(q.times, [1.0, 100.0], rtol=1e-15)
    np.testing.assert_array_equal(q.moduli, p.moduli)
    assert q.relaxed_modulus == p.relaxed_modulus and q.reference_time == 20.0
    assert shift(Elastic(modulus=3.0, reference_time=1.0), 2.0) == \
        Elastic(modulus=3.0, reference_time=2.0)


@settings(max_examples=50, deadline=None)
@given(rheologies(), log_uniform(-4.0, 4.0))
def test_shifted_modulus_is_the_master_curve_at_reduced_frequency(r, a):
    """E(ω; T) = E(a_T·ω; T_ref) and the creep function stretches by a_T."""
    s = shift(r, a)
    assert type(s) is type(r)
    w = np.logspace(-6, 6, 25) / r.reference_time
    np.testing.assert_allclose(s.complex_modulus(w), r.complex_modulus(a * w), rtol=1e-12)
    t = np.logspace(-3, 3, 13) * r.reference_time
    np.testing.assert_allclose(s.creep_function(a * t), r.creep_function(t), rtol=1e-11)
    assert s.reference_time == pytest.approx(a * r.reference_time, rel=1e-15)


def test_heating_moves_the_loss_peak_to_higher_frequency():
    """Thesis Fig. 2.8, with WLF a_T from eq. 2.27."""
    master = StandardLinearSolid(beta=100.0, tau=1.0)
    w = np.logspace(-4, 8, 1201)
    peaks = [w[np.argmax(shift(master, WLF_UNIVERSAL.shift_factor(t)).loss_modulus(w))]
             for t in (300.0, 310.0, 320.0)]
    assert peaks[0] < peaks[1] < peaks[2]
    assert peaks[1] / peaks[0] == pytest.approx(1 / WLF_UNIVERSAL.shift_factor(310.0), rel=0.02)


@pytest.mark.parametrize("a", [0.0, -1.0, float("nan"), float("inf"), "fast"])
def test_shift_factor_must_be_positive_and_finite(a):
    with pytest.raises(ValidationError, match=r"shift\.a_T"):
        shift(Elastic(), a)


def test_shift_rejects_objects_without_time_fields():
    @attrs.frozen
    class NoTimes:
        modulus: float = 1.0

    with pytest.raises(ValidationError, match=r"shift\.rheology"):
        shift(NoTimes(), 2.0)
    with pytest.raises(ValidationError, match=r"shift\.rheology"):
        shift(object(), 2.0)


@settings(max_examples=50, deadline=None)
@given(st.floats(200.0, 400.0), st.floats(200.0, 400.0))
def test_arrhenius_factors_compose(t1, t2):
    """a_T is a ratio of material times: a(T2; ref T1) = a(T2; ref T0) / a(T1; ref T0)."""
    arr = Arrhenius(activation_energy=60e3, reference_temperature=300.0)
    moved = attrs.evolve(arr, reference_temperature=t1)
    assert math.isclose(moved.shift_factor(t2), arr.shift_factor(t2) / arr.shift_factor(t1),
                        rel_tol=1e-10)


@settings(max_examples=50, deadline=None)
@given(st.floats(255.0, 500.0))
def test_wlf_decreases_with_temperature(t):
    a = WLF_UNIVERSAL.shift_factor(t)
    assert 0 < a and (a < 1.0) == (t > 300.0)
    assert WLF_UNIVERSAL.shift_factor(t + 1.0) < a
