"""PronySeries: eq. 2.17/2.24 relaxation form, exact creep form (2.20, 4.6), round trips, I/O."""
from importlib.metadata import entry_points

import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from scipy.integrate import quad

from viscocontact.errors import ValidationError
from viscocontact.rheology import CreepSpectrum, PronySeries, StandardLinearSolid
from viscocontact.testing.strategies_rheology import prony_series, standard_linear_solids

FAST = settings(max_examples=50, deadline=None)


def spectrum_compliance(cs: CreepSpectrum, w):
    return cs.instantaneous + np.sum(cs.weights / (1 + 1j * np.asarray(w)[:, None] * cs.times),
                                     axis=-1)


def omegas(p, pad=6.0):
    return np.logspace(-pad - np.log10(p.times.max()), pad - np.log10(p.times.min()), 200)


# ---- frequency domain ------------------------------------------------------------------------
@FAST
@given(prony_series())
def test_complex_modulus_is_eq_2_24_and_inverse_of_the_creep_compliance(p):
    w = omegas(p)
    x = 1j * w[:, None] * p.times
    expected = p.relaxed_modulus + np.sum(p.moduli * x / (1 + x), axis=-1)
    np.testing.assert_allclose(p.complex_modulus(w), expected, rtol=1e-14)
    # C(ω) = J0 + Σ c_k/(1 + iωθ_k) from the creep spectrum equals 1/E(ω) of the relaxation form
    np.testing.assert_allclose(spectrum_compliance(p.creep_spectrum(), w) * p.complex_modulus(w),
                               1.0, rtol=1e-12)
    np.testing.assert_allclose(p.complex_modulus(w) * p.complex_compliance(w), 1.0, rtol=1e-14)


@FAST
@given(prony_series())
def test_frequency_limits_and_positive_loss(p):
    e0, einf = p.relaxed_modulus, p.relaxed_modulus + p.moduli.sum()
    assert p.instantaneous_modulus == pytest.approx(einf, rel=1e-15)
    np.testing.assert_allclose(p.storage_modulus(1e-12 / p.times.max()), e0, rtol=1e-9)
    np.testing.assert_allclose(p.storage_modulus(1e12 / p.times.min()), einf, rtol=1e-9)
    w = omegas(p)
    assert np.all(p.loss_modulus(w) >= 0)
    assert np.all(p.loss_modulus(w[50:150]) > 0)
    assert np.all(np.diff(p.storage_modulus(w)) >= -1e-14 * einf)   # monotone up to round-off


# ---- time domain -----------------------------------------------------------------------------
@FAST
@given(prony_series())
def test_creep_function_limits_and_monotonicity(p):
    cs = p.creep_spectrum()
    einf = p.instantaneous_modulus
    assert cs.instantaneous == pytest.approx(1 / einf, rel=1e-14)
    assert p.creep_function(0.0) == pytest.approx(1 / einf, rel=1e-14)          # J(0+)
    assert p.creep_function(1e3 * cs.times.max()) == pytest.approx(1 / p.relaxed_modulus,
                                                                   rel=1e-10)  # J(∞)
    assert np.all(cs.weights > 0) and np.all(cs.times > 0)
    t = np.concatenate([[0.0], np.logspace(-3, 3, 120)]) * np.sqrt(cs.times.min() * cs.times.max())
    assert np.all(p.creep_rate(t) >= 0)
    assert np.all(np.diff(p.creep_function(t)) >= -1e-15 / p.relaxed_modulus)
    assert p.creep_function(-1.0) == 0.0


@FAST
@given(prony_series())
def test_relaxation_function_is_eq_2_17(p):
    assert p.relaxation_function(0.0) == pytest.approx(p.instantaneous_modulus, rel=1e-14)
    assert p.relaxation_function(1e3 * p.times.max()) == pytest.approx(p.relaxed_modulus,
                                                                       rel=1e-12)
    t = np.logspace(-2, 2, 9) * p.times[0]
    expected = p.relaxed_modulus + np.sum(p.moduli * np.exp(-t[:, None] / p.times), axis=-1)
    np.testing.assert_allclose(p.relaxation_function(t), expected, rtol=1e-14)
    assert p.relaxation_function(-1.0) == 0.0


@FAST
@given(prony_series())
def test_retardation_times_interlace_with_relaxation_times(p):
    """τ_1 < θ_1 < τ_2 < θ_2 < ... < τ_n < θ_n (the zeros of E(s) interlace with its poles)."""
    theta = p.creep_spectrum().times
    assert theta.size == p.times.size
    assert np.all(p.times < theta)
    assert np.all(theta[:-1] < p.times[1:])


def test_boltzmann_relaxation_and_creep_are_inverse():
    """R(t)·J(0) + ∫_0^t R(t-u) J'(u) du = 1: creep under unit stress (eqs. 2.11-2.14)."""
    p = PronySeries(relaxed_modulus=1.0, moduli=[30.0, 3.0, 8.0], times=[0.01, 0.3, 5.0])
    for t in [0.005, 0.2, 3.0, 40.0]:
        integral, _ = quad(lambda u: float(p.relaxation_function(t - u) * p.creep_rate(u)),
                           0.0, t, epsabs=1e-13, epsrel=1e-12, limit=200, points=[0.01, 0.3])
        assert float(p.relaxation_function(t) * p.creep_function(0.0)) + integral == \
            pytest.approx(1.0, abs=1e-9)


# ---- interconversion -------------------------------------------------------------------------
@FAST
@given(prony_series(shuffle=True))
def test_relaxation_creep_round_trip(p):
    cs = p.creep_spectrum()
    back = PronySeries.from_creep(cs.instantaneous, cs.weights, cs.times,
                                  reference_time=p.reference_time)
    assert back.reference_time == p.reference_time
    assert back.relaxed_modulus == pytest.approx(p.relaxed_modulus, rel=1e-9)
    np.testing.assert_allclose(back.moduli, p.moduli, rtol=1e-9)
    np.testing.assert_allclose(back.times, p.times, rtol=1e-9)


@FAST
@given(standard_linear_solids())
def test_one_arm_series_equals_the_sls(r):
    p = PronySeries(relaxed_modulus=r.modulus, moduli=[(r.beta - 1) * r.modulus],
                    times=[r.tau / r.beta], reference_time=r.tau)
    assert p == r.to_prony()
    w = np.logspace(-6, 6, 49) / r.tau
    np.testing.assert_allclose(p.complex_modulus(w), r.complex_modulus(w), rtol=1e-12)
    t = np.logspace(-4, 3, 30) * r.tau
    np.testing.assert_allclose(p.creep_function(t), r.creep_function(t), rtol=1e-12)
    assert p.creep_spectrum().times[0] == pytest.approx(r.tau, rel=1e-12)


def test_interconversion_with_moduli_over_twelve_decades():
    """Zeros that sit a relative 1e-12 from a pole are still found to full precision."""
    p = PronySeries(relaxed_modulus=1e-6, moduli=[1e6, 1e-6, 3.0, 1e5, 1e-3],
                    times=[1e-5, 1e-4, 2e-1, 3.0, 7e3])
    cs = p.creep_spectrum()
    w = np.logspace(-10, 10, 400)
    np.testing.assert_allclose(spectrum_compliance(cs, w) * p.complex_modulus(w), 1, rtol=1e-13)
    back = PronySeries.from_creep(cs.instantaneous, cs.weights, cs.times)
    np.testing.assert_allclose(back.moduli, p.moduli, rtol=1e-11)
    np.testing.assert_allclose(back.times, p.times, rtol=1e-12)


def test_from_creep_accepts_any_order_and_matches_the_sls():
    """SLS with E0 = 1, β = 10, creep time 2: J0 = 0.1, c = 0.9, θ = 2 -> E1 = 9, τ1 = 0.2."""
    p = PronySeries.from_creep(0.1, [0.9], [2.0], reference_time=2.0)
    assert p.relaxed_modulus == pytest.approx(1.0, rel=1e-14)
    np.testing.assert_allclose(p.moduli, [9.0], rtol=1e-13)
    np.testing.assert_allclose(p.times, [0.2], rtol=1e-13)
    a = PronySeries.from_creep(0.5, [0.1, 2.0, 0.3], [10.0, 0.01, 1.0])
    b = PronySeries.from_creep(0.5, [2.0, 0.3, 0.1], [0.01, 1.0, 10.0])
    assert a == b


def test_zero_moduli_and_repeated_times_are_merged_in_the_creep_form():
    p = PronySeries(relaxed_modulus=1.0, moduli=[2.0, 0.0, 3.0, 4.0], times=[0.1, 1.0, 5.0, 0.1])
    q = PronySeries(relaxed_modulus=1.0, moduli=[6.0, 3.0], times=[0.1, 5.0])
    w = np.logspace(-3, 3, 31)
    np.testing.assert_allclose(p.complex_modulus(w), q.complex_modulus(w), rtol=1e-14)
    cp, cq = p.creep_spectrum(), q.creep_spectrum()
    assert cp.times.size == 2
    np.testing.assert_allclose(cp.times, cq.times, rtol=1e-14)
    np.testing.assert_allclose(cp.weights, cq.weights, rtol=1e-14)


def test_empty_series_is_elastic_both_ways():
    p = PronySeries(relaxed_modulus=3.0)
    assert p.instantaneous_modulus == 3.0
    cs = p.creep_spectrum()
    assert cs.instantaneous == pytest.approx(1 / 3) and cs.weights.size == cs.times.size == 0
    np.testing.assert_array_equal(p.complex_modulus([0.0, 1.0]), [3.0, 3.0])
    assert PronySeries.from_creep(0.5, [], []) == PronySeries(relaxed_modulus=2.0)
    assert PronySeries.from_creep(0.5, [0.0], [1.0]) == PronySeries(relaxed_modulus=2.0)


def test_creep_spectrum_is_cached_and_read_only():
    p = PronySeries(relaxed_modulus=1.0, moduli=[1.0, 2.0], times=[1.0, 10.0])
    cs = p.creep_spectrum()
    assert PronySeries(relaxed_modulus=1.0, moduli=[1.0, 2.0], times=[1.0, 10.0]) \
        .creep_spectrum() is cs
    with pytest.raises(ValueError):
        cs.weights[0] = 0.0


# ---- value semantics -------------------------------------------------------------------------
def test_arrays_sorted_copied_read_only_and_compared_by_value():
    moduli, times = np.array([3.0, 1.0, 2.0]), np.array([10.0, 0.1, 1.0])
    p = PronySeries(relaxed_modulus=1.0, moduli=moduli, times=times)
    np.testing.assert_array_equal(p.times, [0.1, 1.0, 10.0])
    np.testing.assert_array_equal(p.moduli, [1.0, 2.0, 3.0])
    moduli[0] = 100.0
    assert p.moduli[2] == 3.0
    for arr in (p.moduli, p.times):
        with pytest.raises(ValueError):
            arr[0] = 5.0
    q = PronySeries(relaxed_modulus=1.0, moduli=[1.0, 2.0, 3.0], times=(0.1, 1.0, 10.0))
    assert p == q and hash(p) == hash(q)
    assert p != attrs.evolve(q, moduli=[1.0, 2.0, 3.5])
    assert p != PronySeries(relaxed_modulus=1.0, moduli=[1.0, 2.0], times=[0.1, 1.0])
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        p.relaxed_modulus = 2.0


@pytest.mark.parametrize("kwargs, field", [
    (dict(relaxed_modulus=-1.0), "relaxed_modulus"),
    (dict(relaxed_modulus=0.0), "relaxed_modulus"),
    (dict(relaxed_modulus=float("nan")), "relaxed_modulus"),
    (dict(moduli=[1.0, -2.0], times=[1.0, 2.0]), "moduli"),
    (dict(moduli=[1.0, float("nan")], times=[1.0, 2.0]), "moduli"),
    (dict(moduli=[1.0, 2.0], times=[1.0, 0.0]), "times"),
    (dict(moduli=[1.0, 2.0], times=[1.0, float("inf")]), "times"),
    (dict(moduli=[1.0, 2.0], times=[1.0]), "times"),
    (dict(moduli=[[1.0, 2.0]], times=[[1.0, 2.0]]), "moduli"),
    (dict(moduli=["a"], times=[1.0]), "moduli"),
    (dict(moduli=[1.0], times=[1.0], reference_time=-1.0), "reference_time"),
])
def test_bad_input_names_the_field(kwargs, field):
    with pytest.raises(ValidationError, match=rf"PronySeries\.{field}") as info:
        PronySeries(**kwargs)
    assert info.value.field == f"PronySeries.{field}"


@pytest.mark.parametrize("args, field", [
    ((0.0, [1.0], [1.0]), "instantaneous"),
    ((float("nan"), [1.0], [1.0]), "instantaneous"),
    ((1.0, [-1.0], [1.0]), "weights"),
    ((1.0, [1.0], [0.0]), "times"),
    ((1.0, [1.0, 2.0], [1.0]), "times"),
])
def test_from_creep_bad_input_names_the_field(args, field):
    with pytest.raises(ValidationError, match=rf"from_creep\.{field}"):
        PronySeries.from_creep(*args)


# ---- from_table ------------------------------------------------------------------------------
def test_from_table_csv_with_header_and_comments(tmp_path):
    path = tmp_path / "prony.csv"
    path.write_text("time_s, modulus_Pa\n# rubbery plateau first\ninf, 1.0e6\n"
                    "1e-1, 2.5e6   # slow arm\n1e-3,4.0e6\n\n")
    p = PronySeries.from_table(path, reference_time=0.5)
    assert p == PronySeries(relaxed_modulus=1e6, moduli=[4e6, 2.5e6], times=[1e-3, 1e-1],
                            reference_time=0.5)


def test_from_table_whitespace_and_str_path(tmp_path):
    path = tmp_path / "prony.txt"
    path.write_text("0.1\t9\nInfinity 1\n")
    p = PronySeries.from_table(str(path))
    assert p == StandardLinearSolid(beta=10.0, tau=1.0).to_prony()


@pytest.mark.parametrize("text, match", [
    ("1e-3, 4.0\n", "exactly one row with time = inf"),
    ("inf, 1\ninf, 2\n", "exactly one row with time = inf"),
    ("inf, 1\n1e-3, 4, 5\n", "line 2"),
    ("inf, 1\n1e-3, abc\n", "line 2"),
    ("inf, 1\n1e-3, -4\n", r"PronySeries\.moduli"),
])
def test_from_table_rejects_bad_tables(tmp_path, text, match):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ValidationError, match=match):
        PronySeries.from_table(path)


def test_registered_entry_point_loads_this_class():
    eps = {ep.name: ep for ep in entry_points(group="viscocontact.rheologies")}
    assert eps["prony"].load() is PronySeries
