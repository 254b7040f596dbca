"""The package's traction laws pass the public check, and the check catches a broken law."""
import attrs
import numpy as np
import pytest

from viscocontact.adhesion import LennardJones, MaugisDugdale
from viscocontact.testing.conformance_adhesion import check_traction_law


@pytest.mark.parametrize("model", [MaugisDugdale(gamma=1e-3, range=0.01),
                                   LennardJones(gamma=1e-3, range=0.01),
                                   LennardJones(gamma=0.3, range=5.0)])
def test_traction_laws_conform(model):
    check_traction_law(model)


@attrs.frozen(kw_only=True)
class _HalfWork(LennardJones):
    """A law whose traction is half its claimed work's."""

    def traction(self, gap):
        return 0.5 * super().traction(gap)


@attrs.frozen(kw_only=True)
class _Compressive(LennardJones):
    def traction(self, gap):
        return super().traction(gap) - 1e-3 * np.exp(-np.asarray(gap, float))


@pytest.mark.parametrize("model, match", [
    (_HalfWork(gamma=1e-3, range=0.01), "work of separation"),
    (_Compressive(gamma=1e-3, range=0.01), ">= 0"),
    (LennardJones(gamma=0.0, range=0.01), "adhesive law"),
])
def test_a_broken_law_is_named(model, match):
    with pytest.raises(AssertionError, match=match):
        check_traction_law(model)
