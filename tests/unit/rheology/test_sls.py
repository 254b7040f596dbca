"""Standard linear solid: exact E(ω), C(ω), J(t), R(t) (eqs. 4.4-4.5) and its one-arm Prony form."""
from importlib.metadata import entry_points

import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from scipy.integrate import quad
from scipy.optimize import minimize_scalar

from viscocontact.errors import ValidationError
from viscocontact.rheology import PronySeries, StandardLinearSolid
from viscocontact.testing.strategies_rheology import standard_linear_solids

FAST = settings(max_examples=50, deadline=None)


def omegas(r):
    return np.logspace(-6, 6, 61) / r.tau


@FAST
@given(standard_linear_solids())
def test_modulus_times_compliance_is_one(r):
    w = omegas(r)
    np.testing.assert_allclose(r.complex_modulus(w) * r.complex_compliance(w), 1.0, rtol=1e-13)
    cs = r.creep_spectrum()
    c = cs.instantaneous + np.sum(cs.weights / (1 + 1j * w[:, None] * cs.times), axis=-1)
    np.testing.assert_allclose(c * r.complex_modulus(w), 1.0, rtol=1e-13)


@FAST
@given(standard_linear_solids())
def test_frequency_limits_and_positive_loss(r):
    e_low = r.complex_modulus(1e-12 / r.tau)
    e_high = r.complex_modulus(1e12 * r.beta / r.tau)   # ω·τ_r = 1e12
    np.testing.assert_allclose(e_low.real, r.modulus, rtol=1e-10)
    np.testing.assert_allclose(e_high.real, r.modulus * r.beta, rtol=1e-10)
    assert r.instantaneous_modulus == pytest.approx(r.beta * r.modulus, rel=1e-15)
    assert np.all(r.loss_modulus(omegas(r)) > 0)
    assert np.all(np.diff(r.storage_modulus(omegas(r))) >= -1e-14 * r.instantaneous_modulus)


@FAST
@given(standard_linear_solids())
def test_creep_function_is_eq_4_4(r):
    e0, einf = r.modulus, r.beta * r.modulus
    t = r.tau * np.array([0.0, 1e-3, 0.3, 1.0, 4.0, 50.0])
    expected = 1 / e0 - (1 / e0 - 1 / einf) * np.exp(-t / r.tau)         # eqs. 4.4-4.5
    np.testing.assert_allclose(r.creep_function(t), expected, rtol=1e-12)
    assert r.creep_function(0.0) == pytest.approx(1 / einf, rel=1e-14)    # J(0+) = 1/E∞
    assert r.creep_function(1e3 * r.tau) == pytest.approx(1 / e0, rel=1e-14)   # J(∞) = 1/E0
    assert r.creep_function(-r.tau) == 0.0
    rate = r.creep_rate(np.linspace(0, 20, 41) * r.tau)
    assert np.all(rate >= 0)
    assert np.all(np.diff(r.creep_function(np.linspace(0, 20, 41) * r.tau)) >= 0)


@FAST
@given(standard_linear_solids())
def test_relaxation_function_and_time(r):
    assert r.relaxation_time == pytest.approx(r.tau / r.beta, rel=1e-15)
    assert r.reference_time == r.tau
    tr = r.relaxation_time
    np.testing.assert_allclose(r.relaxation_function([0.0, tr, 1e3 * tr]),
                               [r.beta * r.modulus,
                                r.modulus * (1 + (r.beta - 1) / np.e), r.modulus], rtol=1e-12)
    assert r.relaxation_function(-1.0) == 0.0


@FAST
@given(standard_linear_solids())
def test_one_arm_prony_series_is_the_same_solid(r):
    p = r.to_prony()
    assert isinstance(p, PronySeries)
    assert p.reference_time == r.tau
    w = omegas(r)
    np.testing.assert_allclose(p.complex_modulus(w), r.complex_modulus(w), rtol=1e-12)
    t = r.tau * np.logspace(-4, 2, 25)
    np.testing.assert_allclose(p.creep_function(t), r.creep_function(t), rtol=1e-12)
    np.testing.assert_allclose(p.relaxation_function(t), r.relaxation_function(t), rtol=1e-12)
    cs_p, cs_r = p.creep_spectrum(), r.creep_spectrum()
    assert cs_p.instantaneous == pytest.approx(cs_r.instantaneous, rel=1e-13)
    np.testing.assert_allclose(cs_p.weights, cs_r.weights, rtol=1e-12)
    np.testing.assert_allclose(cs_p.times, cs_r.times, rtol=1e-12)


@pytest.mark.parametrize("beta", [1.5, 10.0, 1000.0])
def test_loss_peaks(beta):
    """-C'' peaks at ωτ = 1, E'' at ωτ = β, tan δ at ωτ = √β with value (β-1)/(2√β)."""
    r = StandardLinearSolid(modulus=2.0, beta=beta, tau=0.5)
    b = (-6.0, 6.0)

    def argmax(f):
        res = minimize_scalar(lambda x: -f(10.0**x / r.tau), bounds=b, method="bounded",
                              options={"xatol": 1e-10})
        return 10.0**res.x, -res.fun

    assert argmax(lambda w: -r.complex_compliance(w).imag)[0] == pytest.approx(1.0, rel=1e-5)
    assert argmax(r.loss_modulus)[0] == pytest.approx(beta, rel=1e-5)
    at, peak = argmax(r.loss_tangent)
    assert at == pytest.approx(np.sqrt(beta), rel=1e-5)
    assert peak == pytest.approx((beta - 1) / (2 * np.sqrt(beta)), rel=1e-9)


def test_boltzmann_relaxation_and_creep_are_inverse():
    """R(t)·J(0) + ∫_0^t R(t-u) J'(u) du = 1: a unit stress step (eqs. 2.11-2.14)."""
    r = StandardLinearSolid(modulus=1.0, beta=7.0, tau=2.0)
    for t in [0.1, 1.0, 5.0, 30.0]:
        integral, _ = quad(lambda u: float(r.relaxation_function(t - u) * r.creep_rate(u)),
                           0.0, t, epsabs=1e-13, epsrel=1e-12)
        assert float(r.relaxation_function(t) * r.creep_function(0.0)) + integral == \
            pytest.approx(1.0, abs=1e-10)


def test_from_moduli_and_value_semantics():
    r = StandardLinearSolid.from_moduli(2.0, 20.0, tau=3.0)
    assert r == StandardLinearSolid(modulus=2.0, beta=10.0, tau=3.0)
    assert hash(r) == hash(StandardLinearSolid(modulus=2.0, beta=10.0, tau=3.0))
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        r.beta = 3.0
    assert attrs.evolve(r, tau=1.0).relaxation_time == pytest.approx(0.1)
    assert StandardLinearSolid(beta=2.0) == StandardLinearSolid(modulus=1.0, beta=2.0, tau=1.0)


@pytest.mark.parametrize("beta", [1.0, 0.5, -2.0, float("nan"), float("inf"), "x"])
def test_beta_must_exceed_one_and_message_suggests_elastic(beta):
    with pytest.raises(ValidationError, match=r"StandardLinearSolid\.beta") as info:
        StandardLinearSolid(beta=beta)
    assert "Elastic" in str(info.value) and "> 1" in str(info.value)


@pytest.mark.parametrize("field, value", [("modulus", -1.0), ("modulus", 0.0),
                                          ("modulus", float("nan")), ("tau", 0.0),
                                          ("tau", -3.0), ("tau", float("nan"))])
def test_bad_input_names_the_field(field, value):
    with pytest.raises(ValidationError, match=rf"StandardLinearSolid\.{field}"):
        StandardLinearSolid(beta=2.0, **{field: value})


def test_beta_is_required_and_from_moduli_validates():
    with pytest.raises(TypeError):
        StandardLinearSolid()
    with pytest.raises(ValidationError, match="beta"):
        StandardLinearSolid.from_moduli(2.0, 2.0)
    with pytest.raises(ValidationError, match="relaxed_modulus"):
        StandardLinearSolid.from_moduli(-1.0, -5.0)


def test_registered_entry_point_loads_this_class():
    eps = {ep.name: ep for ep in entry_points(group="viscocontact.rheologies")}
    assert eps["standard-linear-solid"].load() is StandardLinearSolid
