"""The spectral method against closed forms and against the BEM: Westergaard, full contact, the
elastic limits of a standard linear solid, layers, viscoelastic scenes at ζ = 1, the two friction
measures, the definition of the penetration and the coordinates of the edges."""
import attrs
import numpy as np
import pytest

from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.kernels.layers import ConfinedLayer, FreeLayer
from viscocontact.methods.spectral import Spectral
from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.reference import westergaard_area, westergaard_penetration
from viscocontact.rheology import Elastic, PronySeries, StandardLinearSolid
from viscocontact.solvers import Broyden
from viscocontact.methods.bem import BEM

TOL = Spectral().tolerance
SLS = StandardLinearSolid(beta=10.0)


def _problem(profile=None, rheology=None, zeta=0.0, kernel=None, **load):
    return ContactProblem(method=BEM(), profile=profile or Sinusoid(amplitude=0.1),
                          rheology=rheology or Elastic(), solver=Broyden(),
                          kernel=kernel or HalfPlane(), zeta=zeta, **load)


def _small_rough(seed=1):
    return SelfAffineProfile(hurst=0.8, scales=8, rms=0.01, seed=seed)


@pytest.mark.parametrize("load", [0.02, 0.1, 0.3, 0.6, 0.9, 0.99])
def test_westergaard_within_the_tolerance_and_the_estimate(load):
    r = Spectral().solve(_problem(mean_pressure=load))
    exact = westergaard_area(load)
    err = abs(r.area / exact - 1)
    assert r.converged and r.extras["tolerance_met"] and r.n_contacts == 1
    assert err <= TOL and err <= r.extras["error_estimate"]
    assert abs(r.penetration / westergaard_penetration(exact) - 1) <= TOL
    assert abs(r.edges[0, 0] + exact / 2) <= TOL * exact and abs(r.edges[0, 1] - exact / 2) \
        <= TOL * exact


@pytest.mark.parametrize("tolerance", [1e-2, 1e-4])
def test_westergaard_meets_other_tolerances(tolerance):
    r = Spectral(tolerance=tolerance).solve(_problem(mean_pressure=0.4))
    assert r.extras["tolerance_met"]
    assert abs(r.area / westergaard_area(0.4) - 1) <= tolerance


@pytest.mark.parametrize("load", [1.0 + 1e-9, 1.2, 3.0])
def test_full_contact_from_a_unit_load(load):
    r = Spectral().solve(_problem(mean_pressure=load))
    assert r.full_contact and r.converged and r.area == 2 * np.pi
    assert r.n_contacts == 1 and r.edges.shape == (0, 2)
    assert r.penetration == pytest.approx(1.0, abs=1e-12)


@pytest.mark.parametrize("profile,load", [(Sinusoid(amplitude=0.1), 0.3),
                                          (_small_rough(), 0.3)])
def test_the_elastic_limits_of_a_standard_linear_solid(profile, load):
    """ζ → 0: the relaxed solid E0; ζ → ∞: the glassy one, E∞ = β E0, at the load over β."""
    method = Spectral()
    relaxed = method.solve(_problem(profile, SLS, 1e-9, mean_pressure=load))
    glassy = method.solve(_problem(profile, SLS, 1e9, mean_pressure=load))
    e0 = method.solve(_problem(profile, Elastic(), mean_pressure=load))
    e_inf = method.solve(_problem(profile, Elastic(modulus=10.0), mean_pressure=load / 10.0))
    assert relaxed.area == pytest.approx(e0.area, rel=2 * TOL)
    assert glassy.area == pytest.approx(e_inf.area, rel=2 * TOL)
    assert glassy.penetration == pytest.approx(e_inf.penetration, rel=2 * TOL)
    slope = np.sqrt(profile.statistics().m2)
    assert abs(relaxed.friction) <= 1e-3 * slope and abs(glassy.friction) <= 1e-3 * slope


@pytest.mark.parametrize("layer", [ConfinedLayer(thickness=1e3, poisson=0.5),
                                   FreeLayer(thickness=1e3, poisson=0.5)])
def test_a_thick_layer_is_the_half_plane(layer):
    base = _problem(_small_rough(), SLS, 0.1, mean_pressure=0.3)
    a = Spectral(points=2048).solve(base)
    b = Spectral(points=2048).solve(attrs.evolve(base, kernel=layer))
    for key in ("area", "friction", "penetration"):
        assert getattr(b, key) == pytest.approx(getattr(a, key), rel=1e-9), key


@pytest.mark.parametrize("kernel", [ConfinedLayer(thickness=1.0, poisson=0.3),
                                    FreeLayer(thickness=2.0, poisson=0.3)])
def test_layers_against_the_bem(kernel):
    prob = _problem(rheology=SLS, zeta=0.1, kernel=kernel, mean_pressure=0.3)
    s, b = Spectral().solve(prob), prob.solve()
    assert s.converged and b.converged
    assert s.area == pytest.approx(b.area, rel=2 * TOL)
    assert s.friction == pytest.approx(b.friction, rel=2 * TOL)
    assert s.penetration == pytest.approx(b.penetration, rel=2 * TOL)


@pytest.mark.parametrize("profile", [Sinusoid(amplitude=0.1), _small_rough(1),
                                     pytest.param(_small_rough(3), marks=pytest.mark.slow)])
def test_viscoelastic_scene_against_the_bem(profile):
    """ζ = 1, β = 10: area, friction, penetration and edges (in the BEM's coordinates)."""
    prob = _problem(profile, SLS, 1.0, mean_pressure=0.3)
    s, b = Spectral().solve(prob), prob.solve()
    assert s.converged and b.converged and s.n_contacts == b.n_contacts
    assert s.area == pytest.approx(b.area, rel=2 * TOL)
    assert s.friction == pytest.approx(b.friction, rel=2 * TOL)
    assert s.penetration == pytest.approx(b.penetration, rel=2 * TOL)
    assert np.abs(s.edges - b.edges).max() <= 2 * TOL * s.area


def test_prony_series_against_the_bem():
    """Three Maxwell arms, one memory length each inside the dissipative band."""
    prony = PronySeries(relaxed_modulus=1.0, moduli=[2.0, 5.0, 3.0], times=[1e-2, 0.3, 10.0])
    prob = _problem(_small_rough(2), prony, 1.0, mean_pressure=0.3)
    s, b = Spectral().solve(prob), prob.solve()
    assert s.converged and b.converged and s.n_contacts == b.n_contacts
    assert s.area == pytest.approx(b.area, rel=2 * TOL)
    assert s.friction == pytest.approx(b.friction, rel=2 * TOL)


def test_penetration_is_the_bems():
    """Penetration control at the BEM's Δ̃ of a load-controlled solve gives back its load."""
    for kernel in (HalfPlane(), ConfinedLayer(thickness=1.0, poisson=0.3)):
        bem = _problem(_small_rough(), SLS, 1.0, kernel=kernel, mean_pressure=0.3).solve()
        s = Spectral().solve(_problem(_small_rough(), SLS, 1.0, kernel=kernel,
                                      penetration=bem.penetration))
        assert s.converged
        assert s.mean_pressure == pytest.approx(0.3, rel=2 * TOL)
        assert s.area == pytest.approx(bem.area, rel=2 * TOL)


@pytest.mark.parametrize("kernel,zeta", [(HalfPlane(), 1e-2), (HalfPlane(), 1.0),
                                         (FreeLayer(thickness=2.0, poisson=0.3), 0.1)])
def test_friction_is_the_dissipated_power(kernel, zeta):
    """Eq. 4.16 (profile rise × pressure) and the power fed into the solid over V (loss
    compliance × pressure spectrum) converge to each other with the grid."""
    prob = _problem(rheology=SLS, zeta=zeta, kernel=kernel, mean_pressure=0.3)
    gaps = []
    for n in (512, 2048, 8192):
        r = Spectral(points=n).solve(prob)
        gaps.append(abs(r.friction - r.extras["friction_dissipation"]) / r.friction)
    assert gaps[2] < gaps[1] < gaps[0] and gaps[2] <= 1e-4


def test_the_profile_rise_friction_is_the_more_accurate_measure():
    """Why ``friction`` is eq. 4.16 and the dissipated power only its check: against 16384 cells
    (both measures within 1e-7 there) eq. 4.16 is within the method's friction estimate and 10
    to 14 times closer than the power over the load (errors 5.6e-6, 1.6e-6, 5.7e-7 against
    5.6e-5, 2.2e-5, 7.7e-6 at 512, 1024, 2048 cells), whose error the estimate does not bound.
    Only ``-<p ∂u/∂x>`` with the kernel's ``u`` equals the power on a grid to round-off, and that
    is the power itself (``benchmarks/friction_measures.py``)."""
    prob = _problem(rheology=SLS, zeta=1.0, mean_pressure=0.3)
    ref = Spectral(points=16384, residual=1e-12).solve(prob)
    assert ref.friction == pytest.approx(ref.extras["friction_dissipation"], rel=1e-7)
    for n in (512, 1024, 2048):
        r = Spectral(points=n, residual=1e-12).solve(prob)
        err = abs(r.friction / ref.friction - 1)
        err_power = abs(r.extras["friction_dissipation"] / ref.friction - 1)
        assert err <= r.extras["estimates"]["friction"] and 5 * err < err_power


@pytest.mark.slow
def test_observed_order_of_the_area_on_westergaard():
    """Second order on average (least squares over 256-4096 cells; docstring of
    :mod:`viscocontact.methods.spectral`)."""
    sizes = np.array([256, 512, 1024, 2048, 4096])
    for load in (0.05, 0.3, 0.7):
        exact = westergaard_area(load)
        err = [abs(Spectral(points=int(n)).solve(_problem(mean_pressure=load)).area / exact - 1)
               for n in sizes]
        order = -np.polyfit(np.log(sizes), np.log(err), 1)[0]
        assert order >= 1.5
