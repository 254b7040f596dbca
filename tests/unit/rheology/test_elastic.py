"""Elastic: E(ω) = E, J(t) = 1/E, value semantics and validation."""
from importlib.metadata import entry_points

import attrs
import numpy as np
import pytest
from hypothesis import given, settings

from viscocontact.errors import ValidationError
from viscocontact.rheology import CreepSpectrum, Elastic, Rheology
from viscocontact.testing.strategies_rheology import elastic_solids

OMEGA = np.logspace(-12, 12, 49)


@settings(max_examples=50, deadline=None)
@given(elastic_solids())
def test_modulus_is_frequency_independent_and_compliance_is_its_inverse(r):
    e = r.complex_modulus(OMEGA)
    assert e.shape == OMEGA.shape and e.dtype == complex
    np.testing.assert_array_equal(e, r.modulus)
    np.testing.assert_allclose(e * r.complex_compliance(OMEGA), 1.0, rtol=1e-15)
    np.testing.assert_array_equal(r.loss_modulus(OMEGA), 0.0)
    np.testing.assert_array_equal(r.loss_tangent(OMEGA), 0.0)
    assert r.relaxed_modulus == r.instantaneous_modulus == r.modulus
    assert r.modulus_ratio == 1.0


@settings(max_examples=50, deadline=None)
@given(elastic_solids())
def test_creep_and_relaxation_are_steps(r):
    cs = r.creep_spectrum()
    assert isinstance(cs, CreepSpectrum)
    assert cs.instantaneous == 1.0 / r.modulus
    assert cs.weights.shape == cs.times.shape == (0,)
    t = np.array([-1.0, 0.0, 1e-9, 1.0, 1e9])
    np.testing.assert_array_equal(r.creep_function(t), [0.0] + [1.0 / r.modulus] * 4)
    np.testing.assert_array_equal(r.creep_rate(t), 0.0)
    np.testing.assert_array_equal(r.relaxation_function(t), [0.0] + [r.modulus] * 4)


def test_defaults_shape_and_scalar_input():
    r = Elastic()
    assert (r.modulus, r.reference_time) == (1.0, 1.0)
    assert isinstance(r, Rheology)
    assert r.complex_modulus(3.0).shape == ()
    assert r.complex_modulus(np.ones((2, 3))).shape == (2, 3)


def test_value_semantics():
    r = Elastic(modulus=2.0, reference_time=3.0)
    assert r == Elastic(modulus=2, reference_time=3)
    assert hash(r) == hash(Elastic(modulus=2.0, reference_time=3.0))
    assert r != Elastic(modulus=2.5, reference_time=3.0)
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        r.modulus = 5.0
    assert attrs.evolve(r, modulus=4.0).modulus == 4.0
    with pytest.raises(TypeError):
        Elastic(2.0)  # keyword-only


@pytest.mark.parametrize("field, value", [
    ("modulus", -1.0), ("modulus", 0.0), ("modulus", float("nan")), ("modulus", float("inf")),
    ("modulus", "stiff"), ("reference_time", 0.0), ("reference_time", float("nan")),
])
def test_bad_input_names_the_field(field, value):
    with pytest.raises(ValidationError, match=rf"Elastic\.{field}") as info:
        Elastic(**{field: value})
    assert info.value.field == f"Elastic.{field}"


def test_registered_entry_point_loads_this_class():
    eps = {ep.name: ep for ep in entry_points(group="viscocontact.rheologies")}
    assert eps["elastic"].load() is Elastic
