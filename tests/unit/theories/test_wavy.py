"""Westergaard and Johnson wavy contact: the re-exports and the inverse forms."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact import reference
from viscocontact.theories import wavy

SETTINGS = settings(max_examples=40, deadline=None)


def test_reexports_are_the_reference_oracles():
    assert wavy.JohnsonWavy is reference.JohnsonWavy
    assert wavy.westergaard_pressure is reference.westergaard_pressure
    assert wavy.westergaard_area is reference.westergaard_area
    assert wavy.westergaard_penetration is reference.westergaard_penetration


@SETTINGS
@given(area=st.floats(1e-6, 2 * math.pi))
def test_westergaard_area_at_penetration_inverts(area):
    d = float(wavy.westergaard_penetration(area))
    assert wavy.westergaard_area_at_penetration(d) == pytest.approx(area, rel=1e-9)


def test_westergaard_penetration_ends_and_monotonicity():
    assert wavy.westergaard_area_at_penetration(0.0) == 0.0
    assert wavy.westergaard_area_at_penetration(1.0) == 2 * math.pi
    a = np.linspace(1e-3, 2 * math.pi, 400)
    assert np.all(np.diff(wavy.westergaard_penetration(a)) > 0)


@pytest.mark.parametrize("gamma,beta", [(0.01, 1.0), (0.05, 1.0), (0.01, 10.0)])
def test_pull_off_wrappers(gamma, beta):
    jw = wavy.JohnsonWavy(Gamma=gamma, modulus_ratio=beta)
    assert wavy.johnson_pull_off_load(gamma, beta) == jw.pull_off("load")
    assert wavy.johnson_pull_off_penetration(gamma, beta) == jw.pull_off("penetration")
    a_load, p_load, _ = wavy.johnson_pull_off_load(gamma, beta)
    a_pen, p_pen, d_pen = wavy.johnson_pull_off_penetration(gamma, beta)
    # as for JKR: under penetration control the contact survives to a smaller area and a less
    # tensile load
    assert a_pen < a_load and p_load < p_pen < 0 and d_pen < 0
    assert jw.area_at_penetration(d_pen + 1e-3) > a_pen
