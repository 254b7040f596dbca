"""fit_prony: NNLS + refinement recovers known spectra; fit_report; input validation."""
import numpy as np
import pytest
from hypothesis import given, settings

from viscocontact.errors import ValidationError
from viscocontact.rheology import FitReport, PronySeries, fit_prony, fit_report
from viscocontact.testing.strategies_rheology import prony_series

TRUE = PronySeries(relaxed_modulus=1.0, moduli=[5.0, 20.0, 3.0], times=[3e-3, 0.4, 17.0])
OMEGA = np.logspace(-3, 4, 71)          # brackets all three times by a decade or more
DATA = TRUE.complex_modulus(OMEGA)


def relative_errors(fit, w, e):
    m = fit.complex_modulus(w)
    return np.abs(m.real / e.real - 1), np.abs(m.imag / e.imag - 1)


def test_recovers_a_three_term_series_within_one_percent():
    fit = fit_prony(OMEGA, DATA.real, DATA.imag)
    d_storage, d_loss = relative_errors(fit, OMEGA, DATA)
    assert d_storage.max() < 0.01 and d_loss.max() < 0.01       # each relative to itself
    assert fit.relaxed_modulus == pytest.approx(1.0, rel=0.01)
    assert fit.instantaneous_modulus == pytest.approx(29.0, rel=0.01)
    assert np.all(fit.moduli > 0)
    report = fit_report(fit, OMEGA, DATA.real, DATA.imag)
    assert isinstance(report, FitReport) and report.max_relative_error < 1e-4


def test_nnls_alone_meets_the_documented_grid_accuracy():
    fit = fit_prony(OMEGA, DATA.real, DATA.imag, n_per_decade=10, refine=False)
    assert fit_report(fit, OMEGA, DATA.real, DATA.imag).max_relative_error < 0.005
    coarse = fit_prony(OMEGA, DATA.real, DATA.imag, n_per_decade=1, refine=False)
    assert fit_report(coarse, OMEGA, DATA.real, DATA.imag).max_relative_error < 0.15


@settings(max_examples=30, deadline=None)
@given(prony_series(max_terms=3, time_decades=(-2.0, 2.0), modulus_decades=(-1.0, 1.0),
                    min_spacing=0.5))
def test_recovers_random_sparse_series(p):
    # data reaching both plateaus (else E0 is not determined and fit_prony says so)
    w = np.logspace(-2 - np.log10(p.times.max()), 2 - np.log10(p.times.min()), 60)
    e = p.complex_modulus(w)
    fit = fit_prony(w, e.real, e.imag)
    d_storage, d_loss = relative_errors(fit, w, e)
    assert d_storage.max() < 1e-3 and d_loss.max() < 1e-3


def test_noisy_data_fit_to_the_noise_level():
    rng = np.random.default_rng(7)
    e1 = DATA.real * (1 + 0.01 * rng.standard_normal(OMEGA.size))
    e2 = DATA.imag * (1 + 0.01 * rng.standard_normal(OMEGA.size))
    fit = fit_prony(OMEGA, e1, e2)
    assert fit_report(fit, OMEGA, DATA.real, DATA.imag).max_relative_error < 0.03
    assert np.all(fit.loss_modulus(OMEGA) > 0)


def test_imposed_relaxed_modulus_is_kept():
    fit = fit_prony(OMEGA, DATA.real, DATA.imag, relaxed_modulus=1.0)
    assert fit.relaxed_modulus == 1.0
    assert fit_report(fit, OMEGA, DATA.real, DATA.imag).max_relative_error < 0.01


def test_explicit_times_and_reference_time():
    fit = fit_prony(OMEGA, DATA.real, DATA.imag, times=[3e-3, 0.4, 17.0], refine=False,
                    reference_time=2.0)
    assert fit.reference_time == 2.0
    np.testing.assert_allclose(fit.times, TRUE.times)
    np.testing.assert_allclose(fit.moduli, TRUE.moduli, rtol=1e-8)
    assert fit.relaxed_modulus == pytest.approx(1.0, rel=1e-8)


def test_elastic_data_give_no_arms():
    w = np.logspace(-2, 2, 9)
    fit = fit_prony(w, np.full(9, 3.0), np.zeros(9))
    assert fit.relaxed_modulus == pytest.approx(3.0, rel=1e-12) and fit.moduli.size == 0


def test_data_order_and_shape_do_not_matter():
    order = np.random.default_rng(1).permutation(OMEGA.size)
    a = fit_prony(OMEGA, DATA.real, DATA.imag, refine=False)
    b = fit_prony(OMEGA[order].reshape(71, 1), DATA.real[order].reshape(71, 1),
                  DATA.imag[order].reshape(71, 1), refine=False)
    np.testing.assert_allclose(a.moduli, b.moduli, rtol=1e-8)


@pytest.mark.parametrize("args, kwargs, field", [
    ((OMEGA[:-1], DATA.real, DATA.imag), {}, "fit_prony.storage/loss"),
    ((OMEGA, DATA.real, DATA.imag[:-1]), {}, "fit_prony.storage/loss"),
    ((-OMEGA, DATA.real, DATA.imag), {}, "fit_prony.omega"),
    ((np.r_[0.0, OMEGA[1:]], DATA.real, DATA.imag), {}, "fit_prony.omega"),
    ((OMEGA, np.r_[np.nan, DATA.real[1:]], DATA.imag), {}, "fit_prony.storage"),
    ((OMEGA, DATA.real, np.r_[np.inf, DATA.imag[1:]]), {}, "fit_prony.loss"),
    ((OMEGA, -DATA.real, DATA.imag), {}, "fit_prony.storage"),
    (([], [], []), {}, "fit_prony.omega"),
    ((OMEGA, DATA.real, DATA.imag), {"n_per_decade": 0}, "fit_prony.n_per_decade"),
    ((OMEGA, DATA.real, DATA.imag), {"times": [1.0, -1.0]}, "fit_prony.times"),
    ((OMEGA, DATA.real, DATA.imag), {"relaxed_modulus": -1.0}, "fit_prony.relaxed_modulus"),
])
def test_bad_input_names_the_field(args, kwargs, field):
    with pytest.raises(ValidationError, match=field.replace(".", r"\.")):
        fit_prony(*args, **kwargs)


def test_fluid_like_data_are_rejected_with_advice():
    """A Maxwell fluid (E0 = 0) has no relaxed modulus to fit."""
    w = np.logspace(-1, 3, 40)
    x = 1j * w * 1.0
    e = 10 * x / (1 + x)
    with pytest.raises(ValidationError, match="relaxed_modulus"):
        fit_prony(w, e.real, e.imag, times=[1.0], refine=False)
