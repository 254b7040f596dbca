"""The edge systems of one equilibrium solver share their last evaluations: a point another
system of the same control, element counts and edge zones has just evaluated is taken from it,
with the same numbers, and nothing else is."""
from __future__ import annotations

import numpy as np
import pytest

from viscocontact.adhesion import EnergyBalance
from viscocontact.contact.mesh import same_zones
from viscocontact.methods.bem.method import Solve
from viscocontact.methods.bem.sets import Control
from viscocontact.methods.bem.system import EVALUATIONS_KEPT, Evaluations
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Broyden
from viscocontact.methods.bem import BEM

EDGES = np.array([-0.9, 0.8])


@pytest.fixture
def equilibrium():
    p = ContactProblem(method=BEM(),
                       profile=Sinusoid(amplitude=0.1), rheology=StandardLinearSolid(beta=10.0),
                       adhesion=EnergyBalance(gamma=1e-4), solver=Broyden(), mean_pressure=0.1,
                       zeta=1e-2)
    return Solve(p, p.prepare()).equilibrium


def test_a_new_system_takes_the_point_another_has_just_evaluated(equilibrium):
    control = Control.penetration_of(0.3)
    first = equilibrium.system(control, EDGES)
    out = first.evaluate(EDGES.copy())
    second = equilibrium.system(control, EDGES)
    again = second.evaluate(EDGES.copy())
    assert first.evaluations == 1 and second.evaluations == 0
    assert all(a is b for a, b in zip(out, again))
    np.testing.assert_array_equal(second.last_valid, EDGES)
    # computed afresh, it has the same numbers
    alone = equilibrium.system(control, EDGES)
    alone.shared = None
    fresh = alone.evaluate(EDGES.copy())
    assert alone.evaluations == 1
    np.testing.assert_array_equal(fresh[2], out[2])
    np.testing.assert_array_equal(fresh[0].sigma, out[0].sigma)


def test_another_control_or_point_is_computed(equilibrium):
    first = equilibrium.system(Control.penetration_of(0.3), EDGES)
    first.evaluate(EDGES.copy())
    other_control = equilibrium.system(Control.penetration_of(0.31), EDGES)
    other_control.evaluate(EDGES.copy())
    other_point = equilibrium.system(Control.penetration_of(0.3), EDGES)
    other_point.evaluate(EDGES + np.array([-1e-3, 1e-3]))
    assert other_control.evaluations == 1 and other_point.evaluations == 1


def test_other_counts_or_zones_are_computed(equilibrium):
    control = Control.penetration_of(0.3)
    first = equilibrium.system(control, EDGES)
    first.evaluate(EDGES.copy())
    finer = equilibrium.system(control, EDGES, counts=(2 * equilibrium.spec.elements,))
    finer.evaluate(EDGES.copy())
    assert finer.evaluations == 1
    # zones made for a much narrower contact
    narrow = equilibrium.system(control, np.array([-0.05, 0.05]))
    assert narrow.counts == first.counts and not same_zones(narrow.zones, first.zones)
    narrow.evaluate(EDGES.copy())
    assert narrow.evaluations == 1


def test_only_the_last_few_are_kept():
    kept = Evaluations()
    for n in range(EVALUATIONS_KEPT + 2):
        kept.keep(bytes([n]), "c", None, (), n)
    assert kept.find(bytes([0]), "c", None, ()) is None
    assert kept.find(bytes([1]), "c", None, ()) is None
    assert kept.find(bytes([EVALUATIONS_KEPT + 1]), "c", None, ()) == EVALUATIONS_KEPT + 1
    # a point found is the latest used: it stays when another is kept
    assert kept.find(bytes([2]), "c", None, ()) == 2
    kept.keep(b"new", "c", None, (), "new")
    assert kept.find(bytes([2]), "c", None, ()) == 2
