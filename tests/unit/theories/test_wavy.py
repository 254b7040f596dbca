"""Westergaard and Johnson wavy contact: the re-exports and the inverse forms."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
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
@example(area=6.28125)
def test_westergaard_area_at_penetration_inverts(area):
    """The inverse gives back the area to 1e-9, or as closely as the rounded penetration
    determines it. Near full contact Δ̃ is flat (``1 - Δ̃ ≈ ε⁴/2``, ``ε = π/2 - Ã/4``): one
    rounding of Δ̃ moves Ã by ``eps Δ̃/(dΔ̃/dÃ)``, 1e-7 at Ã = 6.28125 (a CI example). There the
    inverse must still reproduce Δ̃ itself to round-off."""
    d = float(wavy.westergaard_penetration(area))
    back = wavy.westergaard_area_at_penetration(d)
    s = math.sin(area / 4)
    slope = -s * math.log(s) * math.cos(area / 4)          # dΔ̃/dÃ = (dΔ̃/ds)(ds/dÃ)
    eps = np.finfo(float).eps
    assert abs(back - area) <= 1e-9 * area + 8 * eps * d / max(slope, 1e-300)
    assert abs(float(wavy.westergaard_penetration(back)) - d) <= 8 * eps * d


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
