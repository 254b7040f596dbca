"""The Lennard-Jones 9-3 law: parameters, its traction and work, registration, and the BEM's
refusal."""
import tomllib
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from viscocontact import _registry
from viscocontact.adhesion import AdhesionLimitation, AdhesionModel, LennardJones, MaugisDugdale
from viscocontact.errors import ValidationError

ROOT = Path(__file__).resolve().parents[3]


@pytest.mark.parametrize("kw, field", [
    (dict(gamma=-1.0, range=1e-3), "gamma"),
    (dict(gamma=float("inf"), range=1e-3), "gamma"),
    (dict(gamma=1e-3, range=0.0), "range"),
    (dict(gamma=1e-3, range=11.0), "range"),
    (dict(gamma=1e-3, range=float("nan")), "range"),
])
def test_invalid_parameters_name_the_field_and_range(kw, field):
    with pytest.raises(ValidationError, match=f"LennardJones.{field}"):
        LennardJones(**kw)


@pytest.mark.parametrize("gamma, eps", [(1e-4, 1e-3), (3e-3, 0.05), (0.2, 2.0)])
def test_work_of_separation_is_the_work_of_adhesion(gamma, eps):
    """``∫_0^∞ t(g) dg = 2πγ̃`` (``Δγ`` in the law's units) by adaptive quadrature, the traction
    vanishing at equilibrium and peaking at ``s = 3^{1/6}ε`` with ``σ_max = 16Δγ/(9√3ε)``; the
    Dugdale step of the same work as a check of the units."""
    lj = LennardJones(gamma=gamma, range=eps)
    work = quad(lambda g: float(lj.traction(g)), 0.0, np.inf, limit=200, epsabs=0.0,
                epsrel=1e-12)[0]
    assert work == pytest.approx(2 * np.pi * gamma, rel=1e-10)
    assert float(lj.traction(0.0)) == 0.0
    peak = (3 ** (1 / 6) - 1) * eps
    assert float(lj.traction(peak)) == pytest.approx(lj.strength(0.3) * 0.3, rel=1e-14)
    assert float(lj.traction(peak * 1.001)) < float(lj.traction(peak))
    assert float(lj.traction(peak * 0.999)) < float(lj.traction(peak))
    md = MaugisDugdale(gamma=gamma, range=eps)
    assert quad(lambda g: float(md.traction(g)), 0.0, 2 * eps, points=[eps])[0] == \
        pytest.approx(2 * np.pi * gamma, rel=1e-12)
    assert float(md.traction(0.0)) == pytest.approx(md.strength(0.3) * 0.3, rel=1e-14)


def test_tabor_parameter_and_maugis_transition():
    """``μ_T = (RΔγ²/(E*²ε³))^{1/3}`` with ``Δγ/E* = πγ̃``; Maugis's λ with the law's peak as σ0
    is ``1.157 μ_T``; the zone the grid resolves is Dugdale's of the same peak and work."""
    lj = LennardJones(gamma=1e-3, range=0.02)
    radius = 4.0
    dgamma = np.pi * 1e-3                       # Δγ/E*, q0 = 1
    assert lj.tabor(radius) == pytest.approx((radius * dgamma**2 / 0.02**3) ** (1 / 3))
    sigma0 = lj.strength(1.0) / 2               # σ_max/E*: σ̃ = 2σ/(E*Λ̃)
    lam = 2 * sigma0 * (radius / (np.pi * dgamma * (4 / 3) ** 2)) ** (1 / 3)
    assert lam / lj.tabor(radius) == pytest.approx(1.1570, abs=1e-4)
    h = dgamma / sigma0                         # Δγ/σ_max
    assert lj.quasi_static_zone == pytest.approx(h * h / (4 * 1e-3))


def test_registered_as_lennard_jones_in_pyproject():
    eps = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["entry-points"]
    value = eps["viscocontact.adhesion"]["lennard-jones"]
    ep = metadata.EntryPoint(name="lennard-jones", group="viscocontact.adhesion", value=value)
    reg = _registry.Registry("viscocontact.adhesion", _registry._base("adhesion"),
                             entry_points=lambda: [ep])
    assert reg.get("lennard-jones") is LennardJones
    assert issubclass(LennardJones, AdhesionModel)


def test_the_boundary_element_method_refuses_the_law():
    """No edge condition: the residuals raise the limitation that names the grid methods."""
    with pytest.raises(AdhesionLimitation, match="spectral"):
        LennardJones(gamma=1e-3, range=0.01).residuals(None)
