"""DMT sphere (thesis §1.5)."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact.theories import DMTSphere, JKRSphere

SETTINGS = settings(max_examples=40, deadline=None)
logs = st.floats(-3.0, 3.0).map(lambda e: 10.0**e)


@SETTINGS
@given(radius=logs, modulus=logs, gamma=logs, x=st.floats(0.0, 50.0))
def test_dmt_pull_off_is_2_pi_r_dgamma_and_hertz_inside(radius, modulus, gamma, x):
    d = DMTSphere(radius=radius, reduced_modulus=modulus, work_of_adhesion=gamma)
    po = d.pull_off()
    assert po.load == pytest.approx(-2.0 * math.pi * radius * gamma, rel=1e-15)
    assert po.contact_radius == 0.0 and po.penetration == 0.0
    a = x * (radius * gamma / modulus) ** (1 / 3)
    assert float(d.load(a)) == pytest.approx(float(d.hertz.load(a)) + po.load, rel=1e-12,
                                             abs=1e-12 * abs(po.load))
    assert float(d.penetration(a)) == float(d.hertz.penetration(a))
    if x > 0.1:    # below, P + 2πΔγR cancels: a is then known only to ε·2πΔγR/P_Hertz
        assert float(d.contact_radius(d.load(a))) == pytest.approx(a, rel=1e-9)
    # DMT and JKR bracket the pull-off: |P_DMT| / |P_JKR| = 2/(3/2) = 4/3
    j = JKRSphere(radius=radius, reduced_modulus=modulus, work_of_adhesion=gamma)
    assert po.load / j.pull_off_load_control().load == pytest.approx(4.0 / 3.0, rel=1e-15)
