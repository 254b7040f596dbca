"""The areal steady-sliding kernel against the 1D kernels, its symmetries and a brute-force alias
sum."""
import itertools

import numpy as np
import pytest

from viscocontact.areal.kernels import ALIASES, ArealKernel, _alias_weights
from viscocontact.errors import ValidationError
from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.kernels.layers import ConfinedLayer, FreeLayer
from viscocontact.methods.spectral.operator import dissipation_weights, eigenvalues
from viscocontact.rheology import Elastic, PronySeries, StandardLinearSolid

SLS = StandardLinearSolid(beta=10.0)
PRONY = PronySeries(relaxed_modulus=1.0, moduli=[2.0, 5.0], times=[0.1, 3.0])
KERNELS = [HalfPlane(), ConfinedLayer(thickness=0.7, poisson=0.3), FreeLayer(thickness=2.0)]


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("rheology,zeta", [(SLS, 1.0), (PRONY, 0.05), (Elastic(), 0.0)])
def test_the_multiplier_along_the_sliding_direction_is_the_1d_one(kernel, rheology, zeta):
    """``λ(m, 0) = S_m K(m)/m`` (the 1D multiplier), and a plane wave turned in the plane with
    the sliding direction sees the same response: ``S`` of ``|q|``, ``K`` of ``q·e``."""
    k = ArealKernel.prepare(kernel, rheology, zeta)
    m = np.array([1.0, 2.0, 7.0, 40.0])
    one_d = k.prepared.multiplier(m) / m
    assert np.allclose(k.multiplier(m, 0.0), one_d, rtol=1e-14, atol=0)
    assert np.allclose(k.multiplier(-m, 0.0), np.conj(one_d), rtol=1e-14, atol=0)
    angle = 0.6
    turned = ArealKernel.prepare(kernel, rheology, zeta, direction=angle)
    qx, qy = m * np.cos(angle), m * np.sin(angle)
    assert np.allclose(turned.multiplier(qx, qy), one_d, rtol=1e-13, atol=0)
    # across the sliding direction the solid is relaxed (E0): K(0) = 1
    relaxed = kernel.geometry_factors(m) / m
    assert np.allclose(k.multiplier(0.0, m), relaxed, rtol=1e-13, atol=0)


@pytest.mark.parametrize("kernel", KERNELS)
def test_the_row_constant_in_y_is_the_1d_operator(kernel):
    k = ArealKernel.prepare(kernel, SLS, 0.3, aspect=1.7)
    lam = k.eigenvalues(32, 12)
    assert np.array_equal(lam[0], eigenvalues(k.prepared, 32))
    d = k.dissipation_weights(32, 12)
    assert np.array_equal(d[0], dissipation_weights(k.prepared, 32))


def test_eigenvalues_are_the_alias_sum_of_the_multiplier():
    """The separated sum of :meth:`ArealKernel.eigenvalues` against the plain double sum
    (inner columns; the first and last columns are made Hermitian)."""
    for kernel, direction in ((ConfinedLayer(thickness=0.5, poisson=0.3), 0.0),
                              (HalfPlane(), 0.4)):
        k = ArealKernel.prepare(kernel, SLS, 0.3, aspect=1.5, direction=direction)
        lam = k.eigenvalues(16, 12)
        n = np.arange(9.0)[None, :]
        j = np.fft.fftfreq(12, 1 / 12)[:, None]
        w = _alias_weights(ALIASES)
        total = 0.0
        for (l, wl), (m, wm) in itertools.product(zip(range(-ALIASES, ALIASES + 1), w),
                                                  repeat=2):
            mx, my = n + 16 * l, j + 12 * m
            total = total + wl * wm * k.multiplier(mx, my / 1.5) * np.sinc(mx / 16) \
                * np.sinc(my / 12)
        assert np.allclose(lam[1:, 1:-1], total[1:, 1:-1], rtol=1e-12, atol=1e-15)


def test_alias_sums_converge():
    """Four aliases a side are within 0.3 % of forty, mode by mode (elastic half-space)."""
    k = ArealKernel.prepare(HalfPlane(), Elastic(), 0.0)
    lam = k.eigenvalues(32, 32)
    many = k._alias_sum(32, 32, 40, 1, k.prepared.compliance, _alias_weights(40))
    rel = np.abs(lam - many)[1:] / np.abs(many)[1:]
    assert rel.max() < 3e-3


@pytest.mark.parametrize("rheology,zeta", [(SLS, 1.0), (PRONY, 0.05)])
def test_operator_is_real_and_dissipates(rheology, zeta):
    """A real pressure gives a real displacement (``Λ(-q) = conj Λ(q)``), the loss weights are
    non-negative, and the power they give is ``-<p ∂u/∂x>`` of the displacement."""
    k = ArealKernel.prepare(HalfPlane(), rheology, zeta)
    op = k.circulant(16, 8)
    rng = np.random.default_rng(0)
    p = rng.random((8, 16))
    u = np.fft.irfft2(op.eigenvalues * np.fft.rfft2(p), p.shape)
    back = np.fft.ifft2(np.fft.fft2(p) * _full(op.eigenvalues, 16))
    assert np.abs(back.imag).max() < 1e-12 * np.abs(u).max()
    assert np.allclose(back.real, u, rtol=1e-12, atol=1e-14)
    assert not op.symmetric
    d = k.dissipation_weights(16, 8)
    assert d.min() >= 0.0 and d.max() > 0.0


def _full(half, nx):
    """The full spectrum of a real operator from its rfft2 half."""
    ny = half.shape[0]
    full = np.zeros((ny, nx), complex)
    full[:, :nx // 2 + 1] = half
    for c in range(nx // 2 + 1, nx):
        full[:, c] = np.conj(half[(-np.arange(ny)) % ny, nx - c])
    return full


def test_elastic_kernels_are_symmetric_and_lossless():
    k = ArealKernel.prepare(FreeLayer(thickness=1.0), Elastic(), 0.0)
    assert k.circulant(16, 16).symmetric
    assert np.all(k.dissipation_weights(16, 16) == 0.0)


@pytest.mark.parametrize("nx,ny", [(15, 8), (8, 0), (True, 8)])
def test_odd_grids_are_refused(nx, ny):
    k = ArealKernel.prepare(HalfPlane(), SLS, 1.0)
    with pytest.raises(ValidationError, match="grid.n"):
        k.eigenvalues(nx, ny)


def test_bad_direction_is_refused():
    with pytest.raises(ValidationError, match="ArealKernel.direction"):
        ArealKernel.prepare(HalfPlane(), SLS, 1.0, direction=4.0)
