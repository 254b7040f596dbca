"""The analytic edge Jacobian (``viscocontact.contact.sensitivity``) against central differences
of the residuals it differentiates."""
from __future__ import annotations

import functools

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from viscocontact.adhesion import EnergyBalance, MaugisDugdale, NoAdhesion
from viscocontact.contact.cohesive import filled
from viscocontact.contact.sensitivity import FieldSensitivity
from viscocontact.kernels import ConfinedLayer, HalfPlane
from viscocontact.methods.bem.method import Solve
from viscocontact.methods.bem.sets import Control
from viscocontact.methods.bem.system import EdgeSystem
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.solvers import Newton
from viscocontact.methods.bem import BEM

SLS = StandardLinearSolid(beta=10.0)
ROUGH = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=11)
ADHESION = {"none": NoAdhesion(), "limit": EnergyBalance(gamma=1e-4, edge_perturbation=0.0),
            "finite": EnergyBalance(gamma=1e-4)}


@functools.cache
def _solve(profile, rheology, zeta, adhesion, elements=32, kernel=None):
    p = ContactProblem(method=BEM(),
                       profile=profile, rheology=rheology, solver=Newton(), adhesion=adhesion,
                       mean_pressure=0.1, zeta=zeta, kernel=kernel or HalfPlane(),
                       discretization=Discretization(elements=elements))
    return Solve(p, p.prepare())


def _system(edges, control, **kw) -> EdgeSystem:
    return _solve(**kw).equilibrium.system(control, np.asarray(edges, dtype=float))


def _with_control(system: EdgeSystem, value: float, x) -> np.ndarray:
    """The residual at ``x`` for another control value, with the same zones and counts."""
    other = EdgeSystem(system.prep, system.spec, system.adhesion,
                       Control(system.control.kind, value), x, system.counts)
    other.zones = system.zones
    return other.residual(x)


def _differences(system: EdgeSystem, x, rel: float):
    """Central differences of the residuals in every edge (step ``rel`` times the smallest
    half-width) and in the control value."""
    x = np.asarray(x, dtype=float)
    h = rel * np.min(0.5 * (x[1::2] - x[0::2]))
    J = np.empty((len(x), len(x)))
    for i in range(len(x)):
        e = np.zeros(len(x))
        e[i] = h
        J[:, i] = (system.residual(x + e) - system.residual(x - e)) / (2 * h)
    v = system.control.value
    hc = 1e-5 * max(abs(v), 0.1)
    c = (_with_control(system, v + hc, x) - _with_control(system, v - hc, x)) / (2 * hc)
    return J, c


def _assert_close(system, x, rel=1e-5, tol=2e-4):
    d = system.derivatives(np.asarray(x, dtype=float))
    J, c = d.jacobian, d.control
    J_fd, c_fd = _differences(system, x, rel)
    scale = np.max(np.abs(J_fd))
    assert np.max(np.abs(J - J_fd)) <= tol * scale, (J, J_fd)
    assert np.max(np.abs(c - c_fd)) <= tol * max(np.max(np.abs(c_fd)), 1e-3 * scale), (c, c_fd)
    return J, J_fd


# generic numbers (no calibration-table knot or zone threshold within the difference step)
_OFFSET = 0.0123456789


@settings(max_examples=12, deadline=None)
@given(left=st.floats(0.05, 1.4), right=st.floats(0.05, 1.4),
       zeta=st.sampled_from([1e-2, 1.0]), model=st.sampled_from(sorted(ADHESION)),
       load=st.booleans())
def test_one_contact_jacobian_equals_central_differences(left, right, zeta, model, load):
    """Sinusoid Λ̃ = 0.1, SLS β = 10, 32 elements with edge zones: every model, both controls.
    Central differences (step 1e-5 of the half-width) carry round-off of about 1e-10/h and a
    truncation error of O(h²); they agree with the analytic Jacobian to 2e-4 of its largest
    entry (measured: 1e-8 for the stress-intensity residuals, 1e-6 to 2e-5 for the finite-δX
    energy balance)."""
    edges = [-(left + _OFFSET), right + _OFFSET]
    control = Control.load_of(0.1) if load else Control.penetration_of(0.3)
    system = _system(edges, control, profile=Sinusoid(amplitude=0.1), rheology=SLS, zeta=zeta,
                     adhesion=ADHESION[model])
    _assert_close(system, edges)


@pytest.mark.parametrize("model", sorted(ADHESION))
def test_elastic_kernel_without_zones(model):
    """An elastic kernel meshes with eq. 4.22 alone (no zones without a finite advance): the
    nodes, the fit's element sizes and the calibration all move with the half-width."""
    edges = [-0.7, 0.45]
    system = _system(edges, Control.load_of(0.1), profile=Sinusoid(amplitude=0.1),
                     rheology=Elastic(), zeta=0.0, adhesion=ADHESION[model])
    _assert_close(system, edges)


def test_layer_kernel_with_a_correction():
    """A confined layer adds the spline of the geometry correction to the kernel's slopes."""
    edges = [-0.6, 0.5]
    system = _system(edges, Control.penetration_of(0.3), profile=Sinusoid(amplitude=0.1),
                     rheology=SLS, zeta=0.3, adhesion=ADHESION["finite"],
                     kernel=ConfinedLayer(thickness=0.7, poisson=0.3))
    _assert_close(system, edges)


ROUGH_EDGES = [4.47037, 4.62705, 4.70036, 5.09036, 5.16383, 5.20679, 5.31652, 5.39046]


@pytest.mark.parametrize("load", [False, True])
def test_four_rough_contacts_couple(load):
    """Four contacts of the thesis rough profile (seed 11, ζ = 1e-2, the default finite δX):
    the off-diagonal blocks (contacts interacting through the solid) are reproduced too."""
    control = Control.load_of(0.1) if load else Control.penetration_of(0.35)
    system = _system(ROUGH_EDGES, control, profile=ROUGH, rheology=SLS, zeta=1e-2,
                     adhesion=EnergyBalance(gamma=2.387e-7))
    J, _ = _assert_close(system, ROUGH_EDGES)
    off = np.abs(J[0:2, 2:4]).max()
    assert off > 1e-4 * np.abs(J).max()           # the coupling is there, and matched


@settings(max_examples=12, deadline=None)
@given(left=st.floats(-0.3, 0.3), right=st.floats(-0.3, 0.3),
       zeta=st.sampled_from([1e-2, 1.0]), h0=st.sampled_from([1e-3, 1e-2]),
       load=st.booleans())
def test_maugis_dugdale_jacobian_equals_central_differences(left, right, zeta, h0, load):
    """Maugis-Dugdale zones (γ̃ = 5e-4, h̃0 = 1e-3 or 1e-2) on the sinusoid Λ̃ = 0.1, SLS β = 10:
    the residual's derivatives along the zones' own equations (the zone lengths follow the
    edges, :func:`~viscocontact.contact.cohesive.zone_derivatives`), edges within 0.3 of the
    elastic equilibrium (zones at both edges, at one, or none), both controls. Measured on a
    grid of 60 such states: 1e-9 to 3e-7 of the largest entry where every edge has a zone, 2e-6
    to 3e-5 with a compressive edge without one; the tolerance is the other models' (2e-4).
    Left out: a zone whose tip closes below the surface (``g̃ < 0``: the residual is cut flat
    there, a kink no difference straddles; one such state at ζ = 30, a zone of 6e-9)."""
    edges = [-1.41860951 + left + _OFFSET, 1.41860951 + right]
    control = Control.load_of(0.01) if load else Control.penetration_of(0.9)
    system = _system(edges, control, profile=Sinusoid(amplitude=0.1), rheology=SLS, zeta=zeta,
                     adhesion=MaugisDugdale(gamma=5e-4, range=h0))
    fields, ctx, _ = system.evaluate(np.asarray(edges))
    assert fields is not None, system.limitation
    assume(np.all((fields.loads.width == 0) | (system.adhesion.tip_gaps(ctx) > 0)))
    _assert_close(system, edges)


@settings(max_examples=8, deadline=None)
@given(left=st.floats(-0.3, 0.3), right=st.floats(-0.3, 0.3),
       zeta=st.sampled_from([1e-2, 1.0]), load=st.booleans())
def test_a_filled_neck_jacobian_equals_central_differences(left, right, zeta, load):
    """A range beyond the deepest gap (h̃0 = 0.3 on Λ̃ = 0.1): the zones fill the rest of the
    period, whose length follows the two edges (each zone keeps its share), and the residual is
    the edges' ``K̃``. SLS β = 10, edges within 0.3 of ±1, both controls, at a load and a
    penetration whose adhesionless contact is narrower (half-widths 0.45 and 0.63): the edges
    are then tensile, no zones shorter than the neck bound them, and the zones fill it.
    Measured on 36 such states: 7.5e-9 to 2.2e-7 of the largest entry."""
    edges = [-1.0 + left + _OFFSET, 1.0 + right]
    control = Control.load_of(0.05) if load else Control.penetration_of(0.3)
    system = _system(edges, control, profile=Sinusoid(amplitude=0.1), rheology=SLS, zeta=zeta,
                     adhesion=MaugisDugdale(gamma=1e-5, range=0.3))
    fields, ctx, _ = system.evaluate(np.asarray(edges))
    assert fields is not None, system.limitation
    assert np.all(filled(fields.mesh.edges, fields.loads.width))
    _assert_close(system, edges)


def test_maugis_dugdale_with_singular_zone_equations_is_differenced(monkeypatch):
    """Where the zone lengths do not follow the edges (``∂K̃/∂d`` singular) the model gives no
    derivatives and the orchestrator differences the residuals."""
    import viscocontact.adhesion.maugis_dugdale as md

    def singular(*args, **kwargs):
        raise np.linalg.LinAlgError("singular")

    monkeypatch.setattr(md, "zone_derivatives", singular)
    edges = np.array([-1.41860951 + 0.1, 1.41860951])
    system = _system(edges, Control.penetration_of(0.9), profile=Sinusoid(amplitude=0.1),
                     rheology=SLS, zeta=1.0, adhesion=MaugisDugdale(gamma=5e-4, range=1e-3))
    assert system.derivatives(edges) is None
    assert np.all(np.isfinite(system.jacobian(edges)))


@pytest.mark.parametrize("h0, zeta, load", [(1e-6, 1e-2, False), (1e-6, 1.0, True),
                                             (1e-5, 1e-2, True)])
def test_four_rough_contacts_with_zones_couple(h0, zeta, load):
    """The four rough contacts above with Maugis-Dugdale zones (γ̃ = 2.387e-7; h̃0 = 1e-6 is the
    thesis's 1 nm): the zones of every contact move with all the edges. Measured: 6e-7 to 6e-5
    of the largest entry, the coupling 0.14-0.42 of it."""
    control = Control.load_of(0.1) if load else Control.penetration_of(0.35)
    system = _system(ROUGH_EDGES, control, profile=ROUGH, rheology=SLS, zeta=zeta,
                     adhesion=MaugisDugdale(gamma=2.387e-7, range=h0))
    assert np.any(system.evaluate(np.array(ROUGH_EDGES))[0].loads.width > 0)
    J, _ = _assert_close(system, ROUGH_EDGES)
    assert np.abs(J[0:2, 2:4]).max() > 1e-2 * np.abs(J).max()


@pytest.mark.parametrize("gap", [1.9e-4, 3e-4])
def test_an_advance_limited_by_the_gap(gap):
    """Two contacts closer than 2δX: the advance is half the gap and moves with both edges."""
    edges = [4.47037, 4.62705, 4.62705 + gap, 5.09036]
    system = _system(edges, Control.penetration_of(0.35), profile=ROUGH, rheology=SLS, zeta=1e-2,
                     adhesion=EnergyBalance(gamma=2.387e-7))
    _assert_close(system, edges)


def test_forward_stresses_and_load_equal_differences():
    """``σ̇`` (forward mode) and ``dp̃∞/dx`` against central differences of the field solution."""
    edges = np.array([-0.8, 0.55])
    system = _system(edges, Control.penetration_of(0.3), profile=Sinusoid(amplitude=0.1),
                     rheology=SLS, zeta=0.1, adhesion=ADHESION["none"])
    fields = system.evaluate(edges)[0]
    sens = FieldSensitivity(fields, system.prep.kernel, system.prep.shape, system.spec,
                            system.zones, system.counts)
    ds, dp = sens.stresses(), sens.pressure()
    h = 1e-6
    for i in range(2):
        e = np.zeros(2)
        e[i] = h
        fp, fm = system.evaluate(edges + e)[0], system.evaluate(edges - e)[0]
        fd = (fp.sigma - fm.sigma) / (2 * h)
        assert np.max(np.abs(ds[:, i] - fd)) <= 1e-5 * np.max(np.abs(fd))
        assert dp[i] == pytest.approx((fp.mean_pressure - fm.mean_pressure) / (2 * h), rel=1e-6)
    # the penetration direction: σ̇ = B⁻¹1
    assert np.allclose(ds[:, -1], np.linalg.solve(fields.matrix, np.ones(len(fields.sigma))))


class _Opaque(EnergyBalance):
    """An adhesion model that gives no derivatives (the interface's default)."""

    def residual_derivatives(self, ctx, dfields):
        return None


def test_a_model_without_derivatives_is_differenced():
    edges = np.array([-0.8, 0.55])
    kw = {"profile": Sinusoid(amplitude=0.1), "rheology": SLS, "zeta": 0.1}
    opaque = _system(edges, Control.penetration_of(0.3), adhesion=_Opaque(gamma=1e-4), **kw)
    analytic = _system(edges, Control.penetration_of(0.3), adhesion=ADHESION["finite"], **kw)
    opaque.residual(edges)
    before = opaque.evaluations
    J_fd = opaque.jacobian(edges)
    assert opaque.evaluations == before + 2          # grouped forward differences
    assert opaque.derivatives(edges) is None
    analytic.residual(edges)
    before = analytic.evaluations
    J = analytic.jacobian(edges)
    assert analytic.evaluations == before            # no residual evaluation
    # forward differences with steps of 1e-7 of the half-width carry the residuals' round-off
    # (about 1e-10) over the step: 2e-4 of the largest entry here
    assert np.allclose(J, J_fd, rtol=0, atol=1e-3 * np.abs(J).max())


def test_batched_energy_releases_equal_one_edge_at_a_time():
    """``energy_releases`` (all edges' solves and products at once) against ``energy_release``
    of each edge alone, on the four rough contacts."""
    adhesion = EnergyBalance(gamma=2.387e-7)
    system = _system(ROUGH_EDGES, Control.penetration_of(0.35), profile=ROUGH, rheology=SLS,
                     zeta=1e-2, adhesion=adhesion)
    x = np.asarray(ROUGH_EDGES)
    fields, ctx, _ = system.evaluate(x)
    sens = FieldSensitivity(fields, system.prep.kernel, system.prep.shape, system.spec,
                            system.zones, system.counts)
    advances = []
    for i in range(len(x)):
        dx, slope = adhesion._advance_and_slope(ctx, i)
        advances.append((i, dx, np.append(slope, 0.0)))
    batched = sens.energy_releases(ctx, advances)
    single = np.array([sens.energy_release(ctx, *a) for a in advances])
    assert batched.shape == (len(x), len(x) + 1)
    # the two differ in the order of the sums of their products and solves only: to the
    # rounding of a solve with B, eps·κ(B) (3.9e-10 here; measured 1e-10)
    rounding = np.finfo(float).eps * np.linalg.cond(fields.matrix)
    assert np.max(np.abs(batched - single)) < rounding * np.max(np.abs(single))
