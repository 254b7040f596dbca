"""The edge zones that ``methods.bem.meshing.mesh_spec`` asks for."""
import numpy as np
import pytest

from viscocontact.adhesion import EnergyBalance, NoAdhesion
from viscocontact.kernels import HalfPlane
from viscocontact.methods.bem.meshing import SMALLEST_RESOLVED, Discretization, mesh_spec
from viscocontact.rheology import Elastic, StandardLinearSolid

DISC = Discretization()
SLS = StandardLinearSolid(beta=10.0)


def _smallest(rheology, zeta, adhesion):
    return mesh_spec(DISC, HalfPlane().prepare(rheology, zeta), adhesion).smallest


def test_a_sharp_edge_resolves_the_relaxation_length():
    """δX = 0 with adhesion: its K̃ is set below the relaxation length ζ/β, which gets
    ``edge_resolution`` elements (ζ = 1e-3: 1e-5), down to 1e-8 (ζ = 1e-6: 1e-8, below the
    floor of other edges); a finite δX and no adhesion keep one element per relaxation
    length."""
    sharp = EnergyBalance(gamma=1e-6, edge_perturbation=0.0)
    assert _smallest(SLS, 1e-3, sharp) == pytest.approx(1e-5)
    assert _smallest(SLS, 1e-6, sharp) == pytest.approx(1e-8)
    assert _smallest(SLS, 1e-3, NoAdhesion()) == pytest.approx(1e-4)
    assert _smallest(SLS, 1e-6, NoAdhesion()) == SMALLEST_RESOLVED


def test_an_elastic_sharp_edge_gets_a_zone():
    """The closed form's fitted K̃ on an elastic kernel: a zone down to 1e-5; none without
    adhesion."""
    assert _smallest(Elastic(), 0.0, EnergyBalance(gamma=1e-6, edge_perturbation=0.0)) == \
        pytest.approx(1e-5)
    assert _smallest(Elastic(), 0.0, NoAdhesion()) is None


def test_a_contact_that_is_no_interval_gets_no_edge_zone():
    """A start whose edges crossed (a speed ramp's secant prediction of a shrinking contact)
    has a negative half-width: it gets no zone (whose geometric growth towards a negative end
    never stopped and filled the memory: 24 GB), and the solve repairs the contact set."""
    from viscocontact.contact.mesh import MeshSpec, zone_pattern

    spec = MeshSpec(elements=64, exponent=1.0, grading=1.15, smallest=1e-5, advance=1e-4)
    assert zone_pattern(-6.0e-4, spec) is None and zone_pattern(0.0, spec) is None
    assert zone_pattern(np.inf, spec) is None and zone_pattern(np.nan, spec) is None
    assert zone_pattern(0.5, spec) is not None


def test_a_solve_from_crossed_edges_repairs_them():
    import viscocontact as vc

    scene = vc.Scene.from_toml("examples/scenes/thesis_rough.toml").replace(
        load=vc.Load(mean_pressure=0.3), zeta=10.0)
    crossed = np.array([[1.9284, 1.8449], [2.2366, 2.314], [2.5091, 2.6319]])
    r = vc.solve(scene, initial=crossed)
    assert r.converged, r.message
    assert "1 contact(s) detached" in r.extras["events"]


def test_zones_are_squeezed_below_half_the_contact_they_were_made_for():
    """A zone made for a contact (reaching about 0.21 of its half-width on the default mesh)
    fits it unscaled down to about half its width; :func:`squeezed` says when
    :func:`graded_nodes` compresses it more than twice, for the contact that shrank and not its
    neighbour."""
    from viscocontact.contact.mesh import squeezed, zone_patterns

    spec = mesh_spec(DISC, HalfPlane().prepare(SLS, 1e-2), EnergyBalance(gamma=1e-6))
    made = np.array([-0.5, -0.2, 0.3, 0.9])          # half-widths 0.15 and 0.3
    zones = zone_patterns(made, spec)
    assert all(zone is not False for zone in zones)
    assert not squeezed(zones, made)
    assert not squeezed(zones, np.array([-0.5, -0.35, 0.45, 0.75]))    # both at half
    assert squeezed(zones, np.array([-0.5, -0.2, 0.55, 0.65]))         # the second at 1/6
    assert squeezed(zones, np.array([-0.36, -0.34, 0.3, 0.9]))         # the first at 1/15
