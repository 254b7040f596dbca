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
    assert abs(fd + log_kernel(x)) < 1e-3 * h / 1e-2 + 1e-9


@settings(max_examples=60, deadline=None)
@given(st.floats(-30, 30))
def test_cl2_odd_and_periodic(x):
    assert abs(cl2(-x) + cl2(x)) < 1e-13
    assert abs(cl2(x + 2 * np.pi) - cl2(x)) < 1e-12
