"""Hypothesis strategies for rheologies, for the package's tests and for plugin authors.

Moduli and times are drawn log-uniformly (as decimal exponents) so that examples span decades, the
regime where interconversion and kernels are ill-conditioned if anything is.

Examples
--------
>>> import numpy as np
>>> from hypothesis import given, settings
>>> from viscocontact.testing.strategies_rheology import rheologies
>>> @settings(max_examples=5, deadline=None)
... @given(rheologies())
... def test_loss_modulus_non_negative(r):
...     assert np.all(r.loss_modulus(np.logspace(-6, 6, 25)) >= 0)
>>> test_loss_modulus_non_negative()
"""
from __future__ import annotations

import numpy as np
from hypothesis import strategies as st

from ..rheology import Elastic, PronySeries, StandardLinearSolid

__all__ = ["elastic_solids", "log_uniform", "prony_series", "rheologies",
           "standard_linear_solids"]


def log_uniform(min_exponent: float, max_exponent: float) -> st.SearchStrategy[float]:
    """Floats ``10**e`` with the decimal exponent e uniform in ``[min_exponent, max_exponent]``."""
    return st.floats(min_exponent, max_exponent).map(lambda e: float(10.0**e))


def elastic_solids(modulus_decades: tuple[float, float] = (-3.0, 3.0),
                   time_decades: tuple[float, float] = (-3.0, 3.0)) -> st.SearchStrategy:
    """:class:`Elastic` with modulus and reference time log-uniform over the given decades."""
    return st.builds(Elastic, modulus=log_uniform(*modulus_decades),
                     reference_time=log_uniform(*time_decades))


def standard_linear_solids(modulus_decades: tuple[float, float] = (-3.0, 3.0),
                           max_beta: float = 1e4,
                           time_decades: tuple[float, float] = (-3.0, 3.0)) -> st.SearchStrategy:
    """:class:`StandardLinearSolid` with ``β - 1`` log-uniform in ``[1e-3, max_beta - 1]``."""
    beta = st.floats(-3.0, float(np.log10(max_beta - 1.0))).map(lambda e: 1.0 + 10.0**e)
    return st.builds(StandardLinearSolid, modulus=log_uniform(*modulus_decades), beta=beta,
                     tau=log_uniform(*time_decades))


@st.composite
def prony_series(draw, min_terms: int = 1, max_terms: int = 5,
                 modulus_decades: tuple[float, float] = (-3.0, 3.0),
                 time_decades: tuple[float, float] = (-4.0, 4.0),
                 min_spacing: float = 0.05, shuffle: bool = False) -> PronySeries:
    """:class:`PronySeries` with ``min_terms..max_terms`` arms.

    Parameters
    ----------
    modulus_decades : (float, float)
        Decimal-exponent range of E0 and of every arm modulus E_i (each drawn independently,
        so ``β`` can reach ``1 + max_terms·10**(hi - lo)``).
    time_decades : (float, float)
        Decimal-exponent range of the relaxation times (exceeded only if ``min_spacing`` forces
        it).
    min_spacing : float
        Minimum distance in decades between consecutive times (> 0). Interconversion loses
        about ``log10(1/gap)`` digits as times merge; 0.05 keeps round trips at ~1e-12.
    shuffle : bool
        Pass the arms in a random order (the class sorts them).
    """
    n = draw(st.integers(min_terms, max_terms))
    lo, hi = time_decades
    span = hi - lo
    max_gap = max(span / max(n, 1), min_spacing)
    start = draw(st.floats(lo, lo + span / max(n, 1)))       # so that the last time <= 10**hi
    gaps = draw(st.lists(st.floats(min_spacing, max_gap), min_size=max(n - 1, 0),
                         max_size=max(n - 1, 0)))
    exponents = start + np.concatenate([[0.0], np.cumsum(gaps)])[:n]
    times = 10.0**exponents
    moduli = np.array(draw(st.lists(log_uniform(*modulus_decades), min_size=n, max_size=n)))
    if shuffle and n > 1:
        order = np.array(draw(st.permutations(range(n))))
        times, moduli = times[order], moduli[order]
    return PronySeries(relaxed_modulus=draw(log_uniform(*modulus_decades)), moduli=moduli,
                       times=times, reference_time=draw(log_uniform(-2.0, 2.0)))


def rheologies(max_terms: int = 5) -> st.SearchStrategy:
    """Any built-in rheology."""
    return st.one_of(elastic_solids(), standard_linear_solids(),
                     prony_series(max_terms=max_terms))
