"""The 2D circulant product by one-axis transforms against ``rfft2``, in double and single
precision. (The single-precision preconditioner of the areal active set is checked by the areal
tests: a profile extruded along ``y`` gives the 1D method's solution, whose preconditioner is in
double precision, to 1e-8.)"""
import numpy as np
import scipy.fft

from viscocontact.methods.spectral.operator import convolve


def test_the_2d_product_is_that_of_rfft2():
    rng = np.random.default_rng(0)
    ny, nx = 48, 64
    values = rng.standard_normal(ny * nx)
    spectrum = rng.standard_normal((ny, nx // 2 + 1)) + 1j * rng.standard_normal((ny, nx // 2 + 1))
    spectrum[:, 0] = spectrum[:, 0].real          # a real operator's self-conjugate columns
    spectrum[:, -1] = spectrum[:, -1].real
    direct = scipy.fft.irfft2(spectrum * scipy.fft.rfft2(values.reshape(ny, nx)), (ny, nx))
    out = convolve(values, spectrum)
    assert out.dtype == np.float64 and out.shape == (ny * nx,)
    assert np.max(np.abs(out - direct.ravel())) <= 1e-14 * np.max(np.abs(direct))
    single = convolve(values, spectrum.astype(np.complex64))
    assert single.dtype == np.float32
    assert np.max(np.abs(single - direct.ravel())) <= 1e-5 * np.max(np.abs(direct))
