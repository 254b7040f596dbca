"""The memory integral M_ζ[f](x) = ∫ f(x + ζt) e^{-t} dt against adaptive quadrature."""
import numpy as np
import pytest
from scipy.integrate import quad

from viscocontact.kernels.clausen import cl2, log_kernel
from viscocontact.kernels.memory import MemoryTable


def _reference(f, x, zeta):
    """∫_0^∞ f(x + s) e^{-s/ζ} ds/ζ with breakpoints at the singularity and log-spaced near 0."""
    span = min(2 * np.pi, 60 * zeta)
    bps = [0.0, span]
    bps += list(np.geomspace(1e-16, span, 40))
    for k in range(1, 3):
        s = 2 * np.pi * k - x
        if 0 < s < span:
            bps += [s]
    bps = np.unique(bps)
    val = sum(quad(lambda s: f(x + s) * np.exp(-s / zeta) / zeta, a, b, epsabs=1e-16,
                   epsrel=1e-13, limit=200)[0] for a, b in zip(bps[:-1], bps[1:]))
    if span == 2 * np.pi:
        val /= -np.expm1(-2 * np.pi / zeta)
    return val


@pytest.mark.parametrize("zeta", [1e-8, 1e-4, 1e-2, 1.0, 1e2])
def test_antiderivative_table_accuracy(zeta):
    tab = MemoryTable(zeta)
    rng = np.random.default_rng(0)
    xs = np.concatenate([rng.uniform(-np.pi, np.pi, 6), [1e-9, -1e-9, -0.5 * zeta, 0.5 * zeta]])
    h0 = _reference(lambda s: -cl2(s), 0.0, zeta)
    for x in xs:
        ref = _reference(lambda s: -cl2(s), x, zeta) - h0
        assert abs(tab.antiderivative(x) - ref) < 1e-9, (zeta, x)


@pytest.mark.parametrize("zeta", [1e-6, 1e-2, 1.0])
def test_kernel_values_accuracy(zeta):
    tab = MemoryTable(zeta)
    for x in [-2.0, -0.3 * zeta, 1e-7, 0.7, 3.0]:
        assert abs(tab.values(x) - _reference(log_kernel, x, zeta)) < 1e-7, (zeta, x)


def test_limits_of_memory_operator():
    x = np.linspace(-3, 3, 13)
    small = MemoryTable(1e-10)
    assert np.max(np.abs(small.antiderivative(x) + cl2(x))) < 1e-8       # ζ→0: M[Φ] → Φ
    big = MemoryTable(1e9)
    assert np.max(np.abs(big.antiderivative(x))) < 1e-8                  # ζ→∞: → mean (0)


def test_rejects_bad_zeta():
    for z in [0.0, -1.0, np.inf, np.nan]:
        with pytest.raises(ValueError):
            MemoryTable(z)
