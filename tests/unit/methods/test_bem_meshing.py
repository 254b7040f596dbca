"""The edge zones that ``methods.bem.meshing.mesh_spec`` asks for."""
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
