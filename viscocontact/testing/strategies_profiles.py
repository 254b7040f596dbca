"""Hypothesis strategies for profiles, for the package's tests and for plugin authors.

Examples
--------
>>> import numpy as np
>>> from hypothesis import given, settings
>>> from viscocontact.testing.strategies_profiles import profiles
>>> @settings(max_examples=5, deadline=None)
... @given(profiles())
... def test_zero_mean(p):
...     r = p.heights(np.linspace(0, 2 * np.pi, 512, endpoint=False))
...     assert abs(r.mean()) <= 1e-12 * p.amplitude
>>> test_zero_mean()
"""
from __future__ import annotations

import numpy as np
from hypothesis import strategies as st

from ..profiles import MeasuredProfile, SelfAffineProfile, Sinusoid

__all__ = ["measured_profiles", "profiles", "self_affine_profiles", "sinusoids"]


def sinusoids(min_amplitude: float = 1e-3, max_amplitude: float = 10.0) -> st.SearchStrategy:
    """:class:`Sinusoid` with ``Λ̃`` in ``[min_amplitude, max_amplitude]``."""
    return st.builds(Sinusoid, amplitude=st.floats(min_amplitude, max_amplitude))


@st.composite
def self_affine_profiles(draw, max_scales: int = 64, min_hurst: float = 0.05,
                         min_rms: float = 1e-3, max_rms: float = 1.0,
                         rolloff: bool = True) -> SelfAffineProfile:
    """:class:`SelfAffineProfile` with ``N_q <= max_scales``, any seed, optional roll-off."""
    scales = draw(st.integers(1, max_scales))
    r = None
    if rolloff and draw(st.booleans()):
        r = draw(st.floats(1.0, float(scales)))
    return SelfAffineProfile(hurst=draw(st.floats(min_hurst, 1.0)), scales=scales,
                             rms=draw(st.floats(min_rms, max_rms)),
                             seed=draw(st.integers(0, 2**32 - 1)), rolloff=r)


@st.composite
def measured_profiles(draw, max_modes: int = 32, max_amplitude: float = 1.0) -> MeasuredProfile:
    """:class:`MeasuredProfile` with up to ``max_modes`` arbitrary Fourier coefficients."""
    n = draw(st.integers(1, max_modes))
    amps = draw(st.lists(st.floats(0.0, max_amplitude), min_size=n, max_size=n))
    if not any(a > 0 for a in amps):
        amps[0] = max_amplitude
    phases = draw(st.lists(st.floats(0.0, 2 * np.pi, exclude_max=True), min_size=n, max_size=n))
    length = draw(st.floats(1e-6, 1.0))
    return MeasuredProfile(amplitudes=amps, phases=phases, length=length)


def profiles(max_modes: int = 64) -> st.SearchStrategy:
    """Any built-in profile kind."""
    return st.one_of(sinusoids(), self_affine_profiles(max_scales=max_modes),
                     measured_profiles(max_modes=min(max_modes, 32)))
