"""MeasuredProfile: Fourier series of samples, CSV and HDF5 readers, validation."""
from __future__ import annotations

import attrs
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact import ValidationError
from viscocontact.profiles import MeasuredProfile, SelfAffineProfile
from viscocontact.testing.strategies_profiles import measured_profiles

TWO_PI = 2 * np.pi
SETTINGS = settings(max_examples=50, deadline=None)


def grid(n: int, length: float = TWO_PI) -> np.ndarray:
    return length * np.arange(n) / n


@pytest.fixture(scope="module")
def rough():
    return SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=4)


def test_round_trip_of_a_self_affine_profile(rough):
    m = MeasuredProfile.from_samples(rough.heights(grid(4096)), length=TWO_PI)
    x = np.random.default_rng(1).uniform(-3, 10, 2000)
    np.testing.assert_allclose(m.heights(x), rough.heights(x), rtol=0, atol=1e-10)
    np.testing.assert_allclose(m.slopes(x), rough.slopes(x), rtol=0, atol=1e-10)
    assert m.amplitudes.size == 2048
    assert m.m2 == pytest.approx(rough.m2, rel=1e-10)
    assert m.amplitude == pytest.approx(rough.amplitude, abs=1e-12)
    trunc = MeasuredProfile.from_samples(rough.heights(grid(4096)), length=TWO_PI, max_modes=50)
    assert trunc.amplitudes.size == 50
    np.testing.assert_allclose(trunc.amplitudes, rough.modes.amplitudes, rtol=1e-10)


def test_physical_units_become_q0_heights():
    length, amp = 1e-3, 2e-6
    z = amp * np.cos(TWO_PI * grid(64, length) / length + 0.3)
    m = MeasuredProfile.from_samples(z, length=length)
    assert m.q0 == pytest.approx(TWO_PI / length)
    assert m.amplitudes[0] == pytest.approx(m.q0 * amp, rel=1e-12)
    assert m.phases[0] == pytest.approx(0.3, abs=1e-12)
    np.testing.assert_allclose(m.amplitudes[1:], 0.0, atol=1e-16)


@SETTINGS
@given(n=st.integers(4, 80), seed=st.integers(0, 10_000))
def test_samples_are_reproduced_exactly_even_and_odd_n(n, seed):
    z = np.random.default_rng(seed).normal(size=n)
    m = MeasuredProfile.from_samples(z, length=TWO_PI)
    assert m.amplitudes.size == n // 2
    np.testing.assert_allclose(m.heights(grid(n)), z - z.mean(), rtol=0, atol=1e-12)
    nyquist = np.fft.rfft(z)[-1].real / n if n % 2 == 0 else 0.0
    assert m.m0 == pytest.approx(np.var(z) - nyquist**2 / 2, rel=1e-12)
    assert m.m0 == pytest.approx(np.mean(m.heights(grid(4 * n)) ** 2), rel=1e-12)


def test_linear_detrend_removes_tilt_and_offset(rough):
    x = grid(512)
    z = rough.heights(x)
    a = MeasuredProfile.from_samples(z, TWO_PI, detrend="linear")
    b = MeasuredProfile.from_samples(z + 0.03 * x - 1.0, TWO_PI, detrend="linear")
    np.testing.assert_allclose(b.heights(x), a.heights(x), rtol=0, atol=1e-13)
    with pytest.raises(ValidationError) as err:
        MeasuredProfile.from_samples(0.2 * x + 1.0, TWO_PI, detrend="linear")
    assert err.value.field == "MeasuredProfile.heights"


@pytest.mark.parametrize("heights, length, kwargs, field", [
    ([0.0, 1.0, np.nan, 2.0, 1.0], 1.0, {}, "MeasuredProfile.heights"),
    ([0.0, 1.0, 0.5], 1.0, {}, "MeasuredProfile.heights"),
    ([[0.0, 1.0], [1.0, 0.0]], 1.0, {}, "MeasuredProfile.heights"),
    ([1.0] * 8, 1.0, {}, "MeasuredProfile.heights"),
    ([0.0, 1.0, 0.0, -1.0], 0.0, {}, "MeasuredProfile.length"),
    ([0.0, 1.0, 0.0, -1.0], np.inf, {}, "MeasuredProfile.length"),
    ([0.0, 1.0, 0.0, -1.0], 1.0, dict(detrend="quadratic"), "MeasuredProfile.detrend"),
    ([0.0, 1.0, 0.0, -1.0], 1.0, dict(max_modes=0), "MeasuredProfile.max_modes"),
    ([0.0, 1.0, 0.0, -1.0], 1.0, dict(max_modes=1.5), "MeasuredProfile.max_modes"),
])
def test_from_samples_validation_names_the_field(heights, length, kwargs, field):
    with pytest.raises(ValidationError) as err:
        MeasuredProfile.from_samples(heights, length, **kwargs)
    assert err.value.field == field


@pytest.mark.parametrize("kwargs, field", [
    (dict(amplitudes=[1.0, -0.1], phases=[0, 0], length=1.0), "MeasuredProfile.amplitudes"),
    (dict(amplitudes=[0.0, 0.0], phases=[0, 0], length=1.0), "MeasuredProfile.amplitudes"),
    (dict(amplitudes=[], phases=[], length=1.0), "MeasuredProfile.amplitudes"),
    (dict(amplitudes=[1.0, 0.1], phases=[0], length=1.0), "MeasuredProfile.phases"),
    (dict(amplitudes=[1.0], phases=[np.nan], length=1.0), "MeasuredProfile.phases"),
    (dict(amplitudes=[1.0], phases=[0.0], length=-2.0), "MeasuredProfile.length"),
])
def test_constructor_validation_names_the_field(kwargs, field):
    with pytest.raises(ValidationError) as err:
        MeasuredProfile(**kwargs)
    assert err.value.field == field


@SETTINGS
@given(p=measured_profiles())
def test_is_a_read_only_value(p):
    q = attrs.evolve(p)
    assert q == p
    assert attrs.evolve(p, length=p.length * 2) != p
    with pytest.raises(ValueError):
        p.amplitudes[0] = 1.0
    np.testing.assert_array_equal(p.modes.wavenumbers, np.arange(1, p.amplitudes.size + 1))


# -- CSV ----------------------------------------------------------------------------------------

def write(path, text):
    path.write_text(text)
    return path


def test_csv_two_columns_with_header_and_unit(tmp_path, rough):
    n, length_um = 256, 500.0
    x = grid(n, length_um)
    z = rough.heights(TWO_PI * x / length_um) / TWO_PI * length_um  # r in µm for λ0 = 500 µm
    lines = ["# profilometer export", "x_um,z_um"] + [f"{a:.17g},{b:.17g}" for a, b in zip(x, z)]
    path = write(tmp_path / "trace.csv", "\n".join(lines) + "\n")
    m = MeasuredProfile.from_csv(path, unit=1e-6)
    assert m.length == pytest.approx(500e-6, rel=1e-12)
    xs = np.linspace(0, TWO_PI, 100)
    np.testing.assert_allclose(m.heights(xs), rough.heights(xs), rtol=0, atol=1e-12)
    by_name = MeasuredProfile.from_csv(path, column="z_um", unit=1e-6)
    assert by_name == m
    with pytest.raises(ValidationError) as err:
        MeasuredProfile.from_csv(path, column="height")
    assert err.value.field == "MeasuredProfile.column"
    with pytest.raises(ValidationError) as err:
        MeasuredProfile.from_csv(path, length=length_um * 1.1)
    assert err.value.field == "MeasuredProfile.length"


def test_csv_single_column_needs_length(tmp_path, rough):
    z = rough.heights(grid(128))
    path = write(tmp_path / "z.txt", "\n".join(f"{v:.17g}" for v in z))
    m = MeasuredProfile.from_csv(path, length=TWO_PI)
    np.testing.assert_allclose(m.heights(grid(128)), z - z.mean(), rtol=0, atol=1e-14)
    with pytest.raises(ValidationError) as err:
        MeasuredProfile.from_csv(path)
    assert err.value.field == "MeasuredProfile.length"


def test_csv_whitespace_delimited_three_columns(tmp_path):
    x = grid(16, 2.0)
    z = np.cos(TWO_PI * x / 2.0)
    text = "\n".join(f"{a:.17g} 7.0\t{b:.17g}" for a, b in zip(x, z))
    m = MeasuredProfile.from_csv(write(tmp_path / "t.dat", text), column=2)
    assert m.length == pytest.approx(2.0)
    assert m.amplitudes[0] == pytest.approx(TWO_PI / 2.0, rel=1e-12)


@pytest.mark.parametrize("text, field", [
    ("x,z\n0,1\n1,nan\n2,0\n3,1\n", "MeasuredProfile.heights"),
    ("x,z\n0,1\n1,\n2,0\n3,1\n", "MeasuredProfile.heights"),
    ("x,z\n0,1\n1,2\n", "MeasuredProfile.heights"),
    ("x,z\n0,1\n1,2\n2.5,0\n3,1\n4,0\n", "MeasuredProfile.x"),
    ("x,z\n3,1\n2,2\n1,0\n0,1\n", "MeasuredProfile.x"),
    ("x,z\n0,1\n1,abc\n2,0\n3,1\n", "MeasuredProfile.heights"),
    ("x,z\n0,1\n1\n2,0\n3,1\n", "MeasuredProfile.heights"),
    ("# nothing\n", "MeasuredProfile.heights"),
])
def test_bad_csv_files_name_the_field(tmp_path, text, field):
    path = write(tmp_path / "bad.csv", text)
    with pytest.raises(ValidationError) as err:
        MeasuredProfile.from_csv(path)
    assert err.value.field == field
    assert "bad.csv" in str(err.value)


# -- HDF5 ---------------------------------------------------------------------------------------

def test_hdf5_length_from_attribute_or_argument(tmp_path, rough):
    h5py = pytest.importorskip("h5py")
    z = rough.heights(grid(512)) / 1000.0  # λ0 = 2π mm, heights in m
    path = tmp_path / "p.h5"
    with h5py.File(path, "w") as f:
        f.create_dataset("scan/z", data=z).attrs["length"] = TWO_PI / 1000.0
        f.create_dataset("no_length", data=z)
        f.create_dataset("xz", data=np.column_stack([grid(512, 3.0), z]))
        f.create_dataset("nan", data=np.where(np.arange(512) == 7, np.nan, z))
        f.create_dataset("cube", data=np.zeros((4, 4, 4)))
    m = MeasuredProfile.from_hdf5(path, "scan/z")
    assert m.length == pytest.approx(TWO_PI / 1000.0)
    np.testing.assert_allclose(m.heights(grid(64)), rough.heights(grid(64)), rtol=0, atol=1e-12)
    assert MeasuredProfile.from_hdf5(path, "no_length", length=TWO_PI / 1000.0) == m
    assert MeasuredProfile.from_hdf5(path, "xz").length == pytest.approx(3.0)
    for dataset, field in [("no_length", "MeasuredProfile.length"),
                           ("missing", "MeasuredProfile.dataset"),
                           ("cube", "MeasuredProfile.dataset"),
                           ("nan", "MeasuredProfile.heights")]:
        with pytest.raises(ValidationError) as err:
            MeasuredProfile.from_hdf5(path, dataset)
        assert err.value.field == field
