"""``contact.fields.dissipated_friction``: the power fed into the solid by a piecewise-constant
stress, exact in real space, against a Fourier sum of the kernel's loss."""
import numpy as np
import pytest

from viscocontact.contact.fields import KnownLoads, dissipated_friction
from viscocontact.contact.mesh import Mesh
from viscocontact.kernels import HalfPlane
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.testing.fourier import dissipated_power, step_coefficients

AMP = 0.1


def _field(seed=0, n=40):
    rng = np.random.default_rng(seed)
    nodes = np.sort(rng.uniform(-1.2, 1.3, n + 1))
    mesh = Mesh(left=nodes[:-1], right=nodes[1:], contact=np.zeros(n, int),
                edges=np.array([nodes[0], nodes[-1]]))
    sigma = rng.normal(size=n) - 0.5
    loads = KnownLoads(left=[nodes[0] - 0.2, nodes[-1]], right=[nodes[0], nodes[-1] + 0.15],
                       stress=[2.0, 2.0])
    p = -(mesh.width @ sigma + loads.force()) / (2 * np.pi)
    return mesh, sigma, loads, p


def _fourier(kernel, mesh, sigma, loads, p, modes=200_000):
    left = np.concatenate([mesh.left, loads.left])
    right = np.concatenate([mesh.right, loads.right])
    sig = np.concatenate([sigma, loads.stress])
    return AMP * dissipated_power(kernel, left, right, sig, modes) / (2 * np.pi * p)


@pytest.mark.parametrize("zeta", [0.1, 1.0, 10.0])
def test_real_space_power_is_the_fourier_sum(zeta):
    kernel = HalfPlane().prepare(StandardLinearSolid(beta=10.0), zeta)
    mesh, sigma, loads, p = _field()
    exact = dissipated_friction(kernel, mesh, sigma, AMP, p, loads, chunk=7)
    # the Fourier tail falls like 1/M (stress jumps): 2e5 modes leave ~1e-5 relative
    assert exact == pytest.approx(_fourier(kernel, mesh, sigma, loads, p), rel=5e-5)


def test_elastic_kernel_dissipates_nothing_and_limits():
    mesh, sigma, loads, p = _field()
    assert dissipated_friction(HalfPlane().prepare(Elastic(), 0.0), mesh, sigma, AMP, p, loads) == 0
    kernel = HalfPlane().prepare(StandardLinearSolid(beta=10.0), 1.0)
    assert np.isnan(dissipated_friction(kernel, mesh, sigma, AMP, 0.0, loads))


def test_large_meshes_get_their_power_too():
    """No size limit: 3000 elements (more end points than the 2048 beyond which the power used to
    be left out, as it was on the rough thesis profile at p̃∞ = 0.6, ζ = 0.1) give the same power
    in any chunking of the pair sum."""
    kernel = HalfPlane().prepare(StandardLinearSolid(beta=10.0), 0.1)
    mesh, sigma, loads, p = _field(n=3000)
    whole = dissipated_friction(kernel, mesh, sigma, AMP, p, loads)
    assert np.isfinite(whole) and whole > 0
    assert dissipated_friction(kernel, mesh, sigma, AMP, p, loads, chunk=1000) == pytest.approx(
        whole, rel=1e-12)


def test_step_coefficients_are_the_element_by_element_sum():
    """The blocked Fourier reference against the plain sum of its formula, for elements of very
    different widths and a mode count that is not a multiple of the block."""
    rng = np.random.default_rng(3)
    nodes = np.sort(rng.uniform(-np.pi, np.pi, 41))
    left, right, stress = nodes[:-1], nodes[1:], rng.normal(size=40)
    m = np.arange(1, 3001, dtype=float)
    plain = sum(s * (np.exp(-1j * m * a) - np.exp(-1j * m * b))
                for a, b, s in zip(left, right, stress)) / (2j * np.pi * m)
    blocked = step_coefficients(left, right, stress, m.size)
    assert np.max(np.abs(blocked - plain)) <= 1e-13 * np.max(np.abs(plain))


def test_step_coefficients_name_a_bad_input():
    with pytest.raises(ValueError, match="one entry per element"):
        step_coefficients([0.0, 1.0], [1.0], [1.0], 10)
    with pytest.raises(ValueError, match="modes must be at least 1"):
        step_coefficients([0.0], [1.0], [1.0], 0)


def test_fourier_power_vanishes_without_loss_and_is_positive_with_it():
    """An elastic solid stores the work of a sliding stress (no loss modulus: zero power); a
    standard linear solid dissipates it (every ``Im`` of its multiplier is positive)."""
    mesh, sigma, _, _ = _field()
    lossless = HalfPlane().prepare(Elastic(), 1.0)
    lossy = HalfPlane().prepare(StandardLinearSolid(beta=10.0), 1.0)
    assert dissipated_power(lossless, mesh.left, mesh.right, sigma, 5000) == 0.0
    assert dissipated_power(lossy, mesh.left, mesh.right, sigma, 5000) > 0.0
