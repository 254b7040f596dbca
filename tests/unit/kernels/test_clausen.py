import numpy as np
import scipy.special as sp
from hypothesis import given, settings, strategies as st

from viscocontact.kernels.clausen import cl2, log_kernel


def test_cl2_matches_dilogarithm():
    x = np.concatenate([np.linspace(-20, 20, 2001), [0.0, 1e-300, 1e-12, np.pi, np.pi / 3]])
    ref = sp.spence(1 - np.exp(1j * x)).imag     # Cl2(x) = Im Li2(e^{ix})
    assert np.max(np.abs(cl2(x) - ref)) < 1e-14


def test_cl2_known_values():
    assert abs(cl2(np.pi / 3) - 1.0149416064096536) < 1e-15   # maximum, Catalan-like constant
    assert abs(cl2(np.pi / 2) - 0.915965594177219) < 1e-15     # Catalan's constant
    assert cl2(0.0) == 0.0


@settings(max_examples=60, deadline=None)
@given(st.floats(-30, 30), st.floats(1e-4, 1e-2))
def test_cl2_derivative_is_minus_log_kernel(x, h):
    if abs(np.sin(x / 2)) < 0.05:
        return
    fd = (cl2(x + h) - cl2(x - h)) / (2 * h)
    # central difference: error h²/6·|Cl2'''(c)| = h²/6·|g''(c)| <= h²/6 / (4 min sin²(s/2))
    # over [x - h, x + h], plus the rounding of the difference quotient
    s = np.linspace(x - h, x + h, 201)
    bound = h**2 / 6 / (4 * np.min(np.sin(s / 2) ** 2)) + 1e-13 / h
    assert abs(fd + log_kernel(x)) <= bound


@settings(max_examples=60, deadline=None)
@given(st.floats(-30, 30))
def test_cl2_odd_and_periodic(x):
    assert abs(cl2(-x) + cl2(x)) < 1e-13
    assert abs(cl2(x + 2 * np.pi) - cl2(x)) < 1e-12


def test_economized_series_matches_the_full_series():
    from viscocontact.kernels.clausen import _CL2_COEF

    t = np.linspace(-np.pi, np.pi, 100_001)
    full = np.zeros_like(t)
    for c in _CL2_COEF:                                   # the 30-term series, in θ²
        full = full * t * t + c
    lg = np.where(t == 0.0, 0.0, t * np.log(np.abs(t)))
    # a few ulp of the largest term (|θ log|θ|| <= 3.6, ulp 4.4e-16)
    assert np.max(np.abs(cl2(t) - (t - lg + t**3 * full))) < 4e-15


def test_wrap_fast_and_general_paths_agree():
    from viscocontact.kernels.clausen import wrap

    x = np.linspace(-3 * np.pi, 3 * np.pi, 10_001)[:-1]
    far = np.concatenate([x, [7 * np.pi + 0.3]])             # forces the general path
    assert np.allclose(wrap(x), np.mod(x + np.pi, 2 * np.pi) - np.pi, rtol=0, atol=4e-15)
    assert np.allclose(wrap(far)[:-1], wrap(x), rtol=0, atol=4e-15)
    w = wrap(x)
    assert np.all((w >= -np.pi) & (w < np.pi))
