"""The thesis's rough profile (H = 0.8, N_q = 50, q0 r_rms = 0.01): multi-contact solves."""
import attrs
import numpy as np
import pytest

from viscocontact.adhesion import EnergyBalance, NoAdhesion
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Newton

SLS = StandardLinearSolid(beta=10.0)
COARSE = Discretization(elements=32)


def _problem(seed, **kw):
    return ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=seed),
                          rheology=SLS, solver=Newton(), discretization=COARSE, **kw)


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("zeta,p", [(1e-6, 0.05), (1.0, 0.6), (1e4, 0.3)])
def test_rough_adhesionless(seed, zeta, p):
    r = _problem(seed, mean_pressure=p, zeta=zeta).solve()
    assert r.converged, r.message
    assert r.mean_pressure == pytest.approx(p, rel=1e-9)
    assert r.min_gap >= 0                                   # no interpenetration on the check grid
    assert r.n_contacts >= 1 and 0 < r.area < 2 * np.pi
    assert r.friction >= -1e-6
    edges = r.edges
    assert np.all(edges[:, 1] > edges[:, 0]) and np.all(edges[1:, 0] > edges[:-1, 1])


def test_rough_load_path_merges_and_detaches():
    """Penetration up then down, each step continued from the previous contact set."""
    prob = _problem(0, penetration=0.05, zeta=0.1)
    prep = prob.prepare()
    path = list(np.linspace(0.05, 0.6, 12)) + list(np.linspace(0.55, 0.05, 11))
    previous, counts, events = None, [], []
    for d in path:
        r = attrs.evolve(prob, penetration=float(d)).solve(initial=previous, prepared=prep)
        assert r.converged, (d, r.message)
        assert r.min_gap >= 0
        counts.append(r.n_contacts)
        events += r.extras["events"]
        previous = r
    assert max(counts) > counts[0] and counts[-1] < max(counts)
    assert any("born" in e for e in events)
    assert any("merged" in e for e in events) or any("detached" in e for e in events)


@pytest.mark.parametrize("zeta", [1.0, 1e4])
def test_rough_adhesive_converges(zeta):
    r = _problem(0, mean_pressure=0.3, zeta=zeta, adhesion=EnergyBalance(gamma=2.387e-7)).solve()
    assert r.converged, r.message
    assert r.min_gap >= 0
    t = r.edge_terms
    assert np.allclose(t.stored + t.nonconservative, t.target, rtol=1e-3, atol=1e-7)
