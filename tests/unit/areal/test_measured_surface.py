"""MeasuredSurface: units at the boundary, the interpolant through the samples, file readers."""
from __future__ import annotations

import numpy as np
import pytest

from viscocontact.areal.surfaces import MeasuredSurface, SelfAffineSurface, sample_statistics
from viscocontact.errors import ValidationError

TWO_PI = 2 * np.pi


def height_map(nx=24, ny=18):
    """A rough map in nm on 2 µm pixels (a cell of 48 µm × 36 µm)."""
    s = SelfAffineSurface(hurst=0.7, scales=6, rms=0.01, seed=5, aspect=ny / nx)
    return s.heights(nx, ny) / TWO_PI * nx * 2e-6 / 1e-9


def test_samples_are_converted_once_to_q0_h():
    z = height_map()
    s = MeasuredSurface.from_samples(z, 2e-6, unit=1e-9)
    assert s.length == pytest.approx(48e-6) and s.aspect == pytest.approx(0.75)
    assert s.pixel_size == pytest.approx((2e-6, 2e-6))
    expected = (z - z.mean()) * 1e-9 * s.q0
    assert np.max(np.abs(s.heights(24, 18) - expected)) < 1e-15 * np.abs(expected).max() * 10


@pytest.mark.parametrize("shape", [(18, 24), (17, 25)])      # even sides have Nyquist bins
def test_interpolant_passes_through_the_samples(shape):
    ny, nx = shape
    rng = np.random.default_rng(0)
    z = rng.normal(size=shape) * 1e-8
    s = MeasuredSurface.from_samples(z, 1e-6)
    via_modes = super(MeasuredSurface, s).heights(nx, ny)
    assert np.max(np.abs(via_modes - s.samples)) < 1e-13 * np.abs(s.samples).max()
    fine = s.heights(3 * nx, 2 * ny)
    assert np.max(np.abs(fine[::2, ::3] - s.samples)) < 1e-13 * np.abs(s.samples).max()
    # the interpolant's exact moments equal the samples' where no bin is a Nyquist bin
    if nx % 2 and ny % 2:
        st = sample_statistics(s.samples, aspect=s.aspect)
        assert s.m0 == pytest.approx(st.m0, rel=1e-12)
        assert s.gradient_variance == pytest.approx(st.m2x + st.m2y, rel=1e-12)


def test_rectangular_pixels_and_plane_detrend():
    j, i = np.mgrid[0:16, 0:32]
    wave = np.cos(TWO_PI * i / 32) * np.cos(TWO_PI * j / 16)
    tilt = 0.3 * i - 0.2 * j + 5.0
    s = MeasuredSurface.from_samples(wave + tilt, (1e-3, 4e-3), unit=1e-6, detrend="plane")
    assert s.aspect == pytest.approx(2.0)
    # a tilted plane is not periodic: the least-squares plane leaves the wave (orthogonal to
    # i, j and 1 on the grid) untouched
    assert np.max(np.abs(s.samples - wave * 1e-6 * s.q0)) < 1e-12 * 1e-6 * s.q0


def test_file_readers_agree(tmp_path):
    h5py = pytest.importorskip("h5py")
    z = height_map()
    np.save(tmp_path / "map.npy", z)
    np.savetxt(tmp_path / "map.txt", z)
    with h5py.File(tmp_path / "map.h5", "w") as f:
        ds = f.create_dataset("heights", data=z)
        ds.attrs["pixel_size"] = 2e-6
        ds.attrs["unit"] = 1e-9
    ref = MeasuredSurface.from_samples(z, 2e-6, unit=1e-9)
    assert MeasuredSurface.from_npy(tmp_path / "map.npy", 2e-6, unit=1e-9) == ref
    text = MeasuredSurface.from_text(tmp_path / "map.txt", 2e-6, unit=1e-9)
    assert np.max(np.abs(text.samples - ref.samples)) < 1e-14 * np.abs(ref.samples).max()
    assert MeasuredSurface.from_hdf5(tmp_path / "map.h5", "heights") == ref
    with pytest.raises(ValidationError, match="MeasuredSurface.dataset"):
        MeasuredSurface.from_hdf5(tmp_path / "map.h5", "nope")


def test_units_are_checked():
    z = height_map()                                # nm
    with pytest.raises(ValidationError, match="MeasuredSurface.unit"):
        MeasuredSurface.from_samples(z, 2e-6)       # read as metres: 1e-4 m over a 48 µm cell
    with pytest.raises(ValidationError, match="MeasuredSurface.length"):
        MeasuredSurface.from_samples(z, 2e-6, unit=1e-9, length=50e-6)
    MeasuredSurface.from_samples(z, 2e-6, unit=1e-9, length=48e-6)
    with pytest.raises(ValidationError, match="MeasuredSurface.pixel_size"):
        MeasuredSurface.from_samples(z, -1.0, unit=1e-9)
    with pytest.raises(ValidationError, match="MeasuredSurface.heights"):
        MeasuredSurface.from_samples(np.ones((8, 8)), 1e-6)
    with pytest.raises(ValidationError, match="MeasuredSurface.heights"):
        MeasuredSurface.from_samples(np.zeros(8), 1e-6)
    with pytest.raises(ValidationError, match="MeasuredSurface.detrend"):
        MeasuredSurface.from_samples(z, 2e-6, unit=1e-9, detrend="linear")
