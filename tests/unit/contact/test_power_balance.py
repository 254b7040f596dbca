"""The power balance of a contact field with square-root edges: the friction ``∫ p r' dx`` is the
bulk dissipation (``contact.fields.dissipated_friction``) plus the net energy flux into the
edges' singularities (``contact.fields.edge_flux_friction``, ``K_e K̃²/4`` into each trailing
edge, out of each leading one)."""
import numpy as np
import pytest

from viscocontact.contact.edges import EdgeContext
from viscocontact.contact.fields import (NormalizedProfile, dissipated_friction,
                                         edge_flux_friction, friction, solve_fields)
from viscocontact.contact.mesh import MeshSpec, build_mesh
from viscocontact.kernels import HalfPlane
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import StandardLinearSolid


def _parts(zeta, smallest):
    """``(μ, bulk, edges)`` of the field of the fixed contact [-0.9, 0.6] at Δ̃ = 0.3 on a
    sinusoid of amplitude 0.05 (its two edges carry different K̃: the field is not an
    equilibrium, and the identity does not need one)."""
    shape = NormalizedProfile.of(Sinusoid(amplitude=0.05))
    kernel = HalfPlane().prepare(StandardLinearSolid(beta=10.0), zeta)
    spec = MeshSpec(elements=64, exponent=1.0, grading=1.15, smallest=smallest)
    f = solve_fields(build_mesh(np.array([-0.9, 0.6]), spec), kernel, shape, penetration=0.3)
    ctx = EdgeContext(f, kernel, shape, spec, shape.amplitude)
    mu = friction(f.mesh, f.sigma, shape, f.mean_pressure)
    bulk = dissipated_friction(kernel, f.mesh, f.sigma, shape.amplitude, f.mean_pressure)
    edges = edge_flux_friction(ctx.stress_intensity(), ctx.edge_compliance, shape.amplitude,
                               f.mean_pressure)
    return mu, bulk, edges


@pytest.mark.parametrize("zeta", [0.0, 0.1, 10.0])
def test_friction_is_bulk_dissipation_plus_edge_flux(zeta):
    """Relaxed elastic (no bulk loss: the friction is the edges' alone), and memory lengths 0.1
    and 10 resolved by edge elements of 1e-4. The misfit is the error of the fitted K̃², first
    order in the edge element: at ζ = 0.1 it is 3 % of the edge term with elements of 1e-3 and
    0.33 % with 1e-4 (elastic 0.02 %, ζ = 10 0.01 %)."""
    mu, bulk, edges = _parts(zeta, 1e-4)
    assert abs(edges) > 0.04 * abs(mu)          # 100 %, 5.3 % and 42 % of the friction
    assert mu - bulk == pytest.approx(edges, rel=1e-2)


def test_edge_flux_formula():
    """Equal edges cancel, the trailing (left) edge counts positive, no edges give 0 and no
    load NaN."""
    assert edge_flux_friction([0.3, 0.3, -0.2, 0.2], 0.1, 0.05, 0.4) == 0.0
    assert edge_flux_friction([0.3, 0.1], 0.1, 0.05, 0.4) > 0.0 > edge_flux_friction(
        [0.1, 0.3], 0.1, 0.05, 0.4)
    assert edge_flux_friction(np.empty(0), 1.0, 0.05, 0.4) == 0.0
    assert np.isnan(edge_flux_friction([0.3, 0.1], 1.0, 0.05, 0.0))
