import math

import numpy as np
import pytest
from viscocontact import ValidationError
from viscocontact.testing.conformance import check_profile
from viscocontact_twoscale import TwoScaleProfile


@pytest.mark.parametrize("phase", [0.0, 1.0, math.pi])
def test_conforms(phase):
    check_profile(TwoScaleProfile(amplitude=0.05, ratio=5, secondary=0.3, phase=phase))


def test_shape_and_amplitude():
    p = TwoScaleProfile(amplitude=0.1, ratio=3, secondary=0.5)
    x = np.linspace(0, 2 * np.pi, 101)
    expected = 0.1 * (np.cos(x) + 0.5 * np.cos(3 * x)) / 1.5
    np.testing.assert_allclose(p.heights(x), expected, atol=1e-15)
    assert p.peak() == (0.0, 0.1)


@pytest.mark.parametrize("kwargs,field", [
    (dict(amplitude=0.1, ratio=1, secondary=0.2), "ratio"),
    (dict(amplitude=0.1, ratio=2.0, secondary=0.2), "ratio"),
    (dict(amplitude=0.1, ratio=2, secondary=1.0), "secondary"),
    (dict(amplitude=-0.1, ratio=2, secondary=0.2), "amplitude"),
])
def test_rejects(kwargs, field):
    with pytest.raises(ValidationError, match=f"TwoScaleProfile.{field}"):
        TwoScaleProfile(**kwargs)
