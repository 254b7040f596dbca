"""The interior resolution of contacts: per-contact element counts and the rule that picks them."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from viscocontact.adhesion import NoAdhesion
from viscocontact.contact.mesh import MeshSpec, build_mesh, clustered_nodes
from viscocontact.methods.bem.method import Solve
from viscocontact.problem import INTERIOR_CAP, ContactProblem, Discretization
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology import Elastic
from viscocontact.solvers import Newton
from viscocontact.methods.bem import BEM


@settings(max_examples=40, deadline=None)
@given(counts=st.lists(st.sampled_from([8, 16, 32, 64]), min_size=1, max_size=4))
def test_build_mesh_gives_each_contact_its_count(counts):
    """Contact j gets counts[j] elements that tile it exactly, left to right."""
    edges = np.ravel([[1.0 * j, 1.0 * j + 0.4] for j in range(len(counts))])
    mesh = build_mesh(edges, MeshSpec(elements=32), counts=tuple(counts))
    for j, n in enumerate(counts):
        sl = mesh.slice(j)
        assert sl.stop - sl.start == n
        assert mesh.left[sl][0] == edges[2 * j] and mesh.right[sl][-1] == edges[2 * j + 1]
        np.testing.assert_allclose(mesh.right[sl][:-1], mesh.left[sl][1:], rtol=0, atol=0)


def _run(profile, elements=32, resolution=8.0):
    prob = ContactProblem(method=BEM(), profile=profile, rheology=Elastic(), adhesion=NoAdhesion(),
                          solver=Newton(), mean_pressure=0.3,
                          discretization=Discretization(elements=elements,
                                                        interior_resolution=resolution))
    return Solve(prob, prob.prepare()).policy


@settings(max_examples=40, deadline=None)
@given(widths=st.lists(st.floats(1e-3, 2.0), min_size=1, max_size=5))
def test_counts_resolve_the_shortest_wavelength(widths):
    """Every count is the base doubled just enough for the largest element to be <= λ_min/8
    (or the cap); narrow contacts keep the base count."""
    run = _run(SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0))
    target = 2 * np.pi / 50 / 8
    edges = np.ravel([[3.0 * j, 3.0 * j + w] for j, w in enumerate(widths)])
    counts = run.counts_for(edges) or (32,) * len(widths)
    for w, n in zip(widths, counts):
        largest = np.max(np.diff(clustered_nodes(w / 2, n, 1.0)))
        assert largest <= target or n == INTERIOR_CAP
        if n > 32:
            assert np.max(np.diff(clustered_nodes(w / 2, n // 2, 1.0))) > target


def test_a_sinusoid_and_a_switched_off_rule_keep_the_counts():
    assert _run(Sinusoid(amplitude=0.1)).counts_for(np.array([-3.0, 3.0])) is None
    rough = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)
    assert _run(rough, resolution=None).counts_for(np.array([0.0, 2.0])) is None
    assert _run(rough).counts_for(np.array([0.0, 2.0])) == (256,)


def test_interior_resolution_is_validated():
    with pytest.raises(Exception, match="interior_resolution"):
        Discretization(interior_resolution=0.5)


@settings(max_examples=30, deadline=None)
@given(n_contacts=st.integers(1, 4), which=st.integers(0, 3), base=st.sampled_from([16, 32, 64]))
def test_a_refined_point_doubles_only_the_contact_holding_it(n_contacts, which, base):
    """``refine_at`` gives the contact holding the point twice its elements, periodically (the
    point may be given a period away), and leaves the others alone; at the cap it refuses."""
    which %= n_contacts
    run = _run(Sinusoid(amplitude=0.1), elements=base)
    edges = np.ravel([[1.5 * j, 1.5 * j + 0.3] for j in range(n_contacts)])
    assert run.counts_for(edges) is None
    assert run.refine_at([1.5 * which + 0.1 + 2 * np.pi], [base])
    counts = run.counts_for(edges)
    assert counts == tuple(2 * base if j == which else base for j in range(n_contacts))
    assert not run.refine_at([0.1], [INTERIOR_CAP])


def test_a_coarser_mesh_of_a_solve_keeps_its_refinements_in_proportion():
    """The coarse meshes of an error estimate refine the contacts the solve refined, by the
    same factor over their own elements (else a contact refined for a nearly vanishing tension
    cycles again on the coarse mesh and the estimate is lost)."""
    fine = _run(Sinusoid(amplitude=0.1), elements=64)
    edges = np.array([0.0, 0.3, 1.5, 1.8])
    assert fine.refine_at([0.1], [64]) and fine.refine_at([0.1], [128])
    assert fine.counts_for(edges) == (256, 64)
    coarse = _run(Sinusoid(amplitude=0.1), elements=32)
    coarse.inherit(fine, 0.5)
    assert coarse.counts_for(edges) == (128, 32)
