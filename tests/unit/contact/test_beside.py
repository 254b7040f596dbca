"""What an evaluation computes beside the factorisation of its influence matrix (the finite-δX
borders' new rows and columns, the kernel slopes of the derivatives asked for first) changes no
bit: one thread, two threads, and the borders computed when asked for agree."""
from __future__ import annotations

import numpy as np
import pytest

from viscocontact._threads import set_threads
from viscocontact.adhesion import EnergyBalance
from viscocontact.contact.edges import EdgeContext, border_geometry
from viscocontact.methods.bem.method import Solve
from viscocontact.methods.bem.sets import Control
from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Broyden
from viscocontact.methods.bem import BEM

# four contacts of the thesis rough profile (seed 11) near ζ = 1e-2, p̃∞ = 0.1
EDGES = np.array([4.47037, 4.62705, 4.70036, 5.09036, 5.16383, 5.20679, 5.31652, 5.39046])


@pytest.fixture(autouse=True)
def restore():
    yield
    set_threads(None)


@pytest.fixture(scope="module")
def solve():
    p = ContactProblem(method=BEM(),
                       profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=11),
                       rheology=StandardLinearSolid(beta=10.0),
                       adhesion=EnergyBalance(gamma=2.387e-7), solver=Broyden(),
                       mean_pressure=0.1, zeta=1e-2)
    return Solve(p, p.prepare())


@pytest.mark.parametrize("load", [False, True])
def test_one_and_two_threads_give_the_same_residuals_and_derivatives(solve, load):
    control = Control.load_of(0.1) if load else Control.penetration_of(0.35)
    out = {}
    for count in (1, 2):
        set_threads(count)
        system = solve.equilibrium.system(control, EDGES)
        system.shared = None                      # computed here, not taken from the other
        fields, ctx, r = system.evaluate(EDGES)
        d = system.derivatives(EDGES)
        out[count] = (r, d.jacobian, d.control, d.pressure, fields.sigma, ctx)
    for a, b in zip(out[1][:5], out[2][:5]):
        assert np.array_equal(a, b)
    assert out[1][5]._geometry is None            # one thread: the borders when asked for
    assert out[2][5]._geometry is not None        # two: beside the factorisation


def test_borders_of_some_advances_beside_a_geometry_prepared_for_all(solve):
    """A context whose geometry was prepared for other advances than those asked for computes
    the borders afresh: the bordered fields equal those of a context without one."""
    set_threads(1)
    system = solve.equilibrium.system(Control.penetration_of(0.35), EDGES)
    fields, ctx, _ = system.evaluate(EDGES)
    advances = solve.equilibrium.adhesion.bordered_advances(fields.mesh)
    assert len(advances) == len(EDGES) and all(dx > 0 for _, dx in advances)
    prep = solve.equilibrium.prep
    geometry = border_geometry(fields.mesh, prep.kernel, prep.shape, system.spec, advances)
    some = advances[1::3]
    given = EdgeContext(fields, prep.kernel, prep.shape, system.spec, prep.shape.amplitude,
                        system.zones, system.counts, geometry=geometry)
    fresh = EdgeContext(fields, prep.kernel, prep.shape, system.spec, prep.shape.amplitude,
                        system.zones, system.counts)
    given.prepare_borders(some)
    fresh.prepare_borders(some)
    for key in some:
        a, b = given.border(*key), fresh.border(*key)
        assert np.array_equal(a.c, b.c) and np.array_equal(a.r, b.r)
        assert np.array_equal(a.left, b.left)
        scale = np.max(np.abs(b.s_old))
        assert np.max(np.abs(a.s_old - b.s_old)) <= 1e-12 * scale
        assert abs(a.d_u - b.d_u) <= 1e-12 * abs(b.d_u)
        assert abs(a.d_lp - b.d_lp) <= 1e-12 * max(abs(b.d_lp), 1e-300)
