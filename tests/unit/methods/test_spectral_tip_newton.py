"""Newton's step of the cohesive tips of a 1D grid (``methods/spectral/tip_newton.py``): the
gap's responses to a cell's cohesive share hold the contact cells' gaps at zero and agree with a
dense computation written here, the dense and the Krylov paths agree, and the step is taken only
where it holds."""
import numpy as np
import pytest

from viscocontact.methods.spectral import tip_newton
from viscocontact.methods.spectral.operator import Circulant, convolve, invert
from viscocontact.methods.spectral.tip_newton import TipResponses, newton_tips

N = 64
STRENGTH = 0.7


def _circulant():
    k = np.arange(N // 2 + 1)
    lam = (1.0 / (1.0 + k)) * (1.0 + 0.3j * k / (1.0 + k))   # a lossy, nonsymmetric operator
    lam[0], lam[-1] = lam[0].real, lam[-1].real
    return Circulant(points=N, eigenvalues=lam, inverse=invert(lam), symmetric=False)


def _dense(circulant):
    return np.column_stack([convolve(np.eye(N)[j], circulant.eigenvalues) for j in range(N)])


CONTACT = np.zeros(N, bool)
CONTACT[20:31] = True


@pytest.mark.parametrize("load", [False, True])
def test_a_cell_share_moves_no_contact_gap_and_matches_a_dense_solve(load):
    circulant = _circulant()
    A = _dense(circulant)
    C = np.flatnonzero(CONTACT)
    m = 33
    column = TipResponses(circulant, STRENGTH, load).column(CONTACT, m)
    assert np.max(np.abs(column[C])) < 1e-12
    # independently: δp = δq - σ̃0 e_m with A_CC δq_C - δΔ 1 = σ̃0 (A e_m)_C (and Σ δq = σ̃0)
    k = C.size
    if load:
        M = np.block([[A[np.ix_(C, C)], -np.ones((k, 1))], [np.ones((1, k)), np.zeros((1, 1))]])
        sol = np.linalg.solve(M, np.append(STRENGTH * A[C, m], STRENGTH))
        dq, dd = sol[:k], sol[k]
    else:
        dq, dd = np.linalg.solve(A[np.ix_(C, C)], STRENGTH * A[C, m]), 0.0
    dp = -STRENGTH * np.eye(N)[m]
    dp[C] += dq
    assert column == pytest.approx(A @ dp - dd, abs=1e-12)


@pytest.mark.parametrize("load", [False, True])
def test_the_krylov_responses_are_the_dense_ones(load, monkeypatch):
    circulant = _circulant()
    dense = TipResponses(circulant, STRENGTH, load).column(CONTACT, 33)
    monkeypatch.setattr(tip_newton, "DENSE", 0)
    krylov = TipResponses(circulant, STRENGTH, load).column(CONTACT, 33)
    assert krylov == pytest.approx(dense, abs=1e-7 * np.max(np.abs(dense)))


def _linear_case(strength):
    """A row whose gap is linear in the tips (no contact: the responses are the operator's
    columns), with residuals built from a known root."""
    circulant = _circulant()
    responses = TipResponses(circulant, strength, False)
    gap = 0.05 + 0.01 * (np.arange(N) - 40.0) ** 2          # a minimum at cell 40
    root = [(39.2, 40.9)]
    return responses, gap, root


def test_newton_lands_on_the_root_of_a_linear_row():
    """With the gap's own slope only (no cohesive stress), the residual of each tip is the
    linear interpolant of the gap less its value at the root: one step from within the cells
    lands on the root."""
    responses, gap, root = _linear_case(0.0)

    def interp(x):
        k = int(np.floor(x))
        return (1 - (x - k)) * gap[k] + (x - k) * gap[k + 1]

    eta = [interp(v) for v in root[0]]
    start = [(39.5, 40.6)]
    residuals = [(interp(start[0][0]) - eta[0], interp(start[0][1]) - eta[1])]
    moved = newton_tips(start, residuals, gap, np.zeros(N, bool), responses)
    assert moved is not None
    assert moved[0] == pytest.approx(root[0], abs=1e-12)


def test_no_step_where_the_zone_grows_under_its_own_stress():
    """A strong cohesive stress on a flat gap: the residuals fall as the zone grows, the tips'
    motion has no stable root nearby, and Newton's step is not taken (None: the tips move by
    their own residuals, out)."""
    circulant = _circulant()
    responses = TipResponses(circulant, 50.0, False)
    gap = np.full(N, 0.05)
    gap[40] = 0.049
    moved = newton_tips([(39.8, 40.2)], [(-1e-3, -1e-3)], gap, np.zeros(N, bool), responses)
    assert moved is None


# the thesis's rough profile (seed 0) with a Maugis-Dugdale law at ζ = 1: on the approach's
# first grid two zones face each other across a neck of 1.6 cells, and their tips, moved one
# by one, crept until the approach's 60 inner solves ran out
ROUGH_MD = {
    "profile": {"kind": "self-affine", "hurst": 0.8, "scales": 50, "rms": 0.01, "seed": 0},
    "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
    "adhesion": {"kind": "maugis-dugdale", "gamma": 2.4e-5, "range": 3e-3},
    "load": {"mean_pressure": 0.3}, "sliding": {"zeta": 1.0},
    "method": {"kind": "spectral"}}


@pytest.mark.slow      # 12 s on two loaded cores
def test_coupled_tips_settle_on_the_thesis_rough_profile():
    from viscocontact.testing.campaign import run_scene

    outcome = run_scene(ROUGH_MD, time_limit=300.0)
    assert outcome.outcome == "converged" and outcome.passed, (outcome.message, outcome.failures)
    assert outcome.values["error_estimate"] < 1e-3
