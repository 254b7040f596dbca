"""Mean and Student-t confidence band over realizations."""
import numpy as np
import pytest
from scipy import stats

from viscocontact.errors import ValidationError
from viscocontact.studies import confidence_band


def test_band_matches_student_t():
    rng = np.random.default_rng(1)
    values = rng.normal(2.0, 0.5, size=(3, 20))
    band = confidence_band(values, axis=1, confidence=0.9)
    mean = values.mean(axis=1)
    half = stats.t.ppf(0.95, 19) * values.std(axis=1, ddof=1) / np.sqrt(20)
    assert np.allclose(band.mean, mean) and np.allclose(band.upper - band.mean, half)
    assert np.allclose(band.mean - band.lower, half)
    assert band.count.tolist() == [20, 20, 20] and band.confidence == 0.9


def test_nan_are_left_out_and_single_values_have_no_band():
    band = confidence_band([[1.0, np.nan, 3.0], [np.nan, 5.0, np.nan], [np.nan] * 3])
    assert band.count.tolist() == [2, 1, 0]
    assert band.mean[0] == 2.0 and band.mean[1] == 5.0 and np.isnan(band.mean[2])
    assert np.isfinite(band.upper[0]) and np.isnan(band.upper[1]) and np.isnan(band.lower[2])


def test_confidence_out_of_range():
    with pytest.raises(ValidationError, match="confidence"):
        confidence_band([1.0, 2.0], confidence=1.5)
