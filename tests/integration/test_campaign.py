"""A short, fixed sample of the randomised campaign (``viscocontact.testing.campaign``): every
drawn scene converges or ends for a property of the scene, and every converged result passes
its identities (load met, no interpenetration, friction against the sliding on a lossy solid,
friction equal to the dissipated power within the result's error estimate).

The full campaign (300 scenes over every component kind and range, with its table by
component) is ``benchmarks/campaign.py`` (``docs/verification.md``, "Randomised campaign").
The seeds here are not chosen by outcome: for each adhesion model they are the first seeds of
the campaign whose scene solved in under 3 s there (three without adhesion, three with the
energy balance, two with Maugis-Dugdale). The ones that fail are kept as strict xfails naming
the defect they show.
"""
import pytest

from viscocontact.testing.campaign import describe, draw, run_scene

# A limit far past these scenes' solve times (0.3-1.8 s), so that a scene that runs away fails
# instead of holding the suite.
LIMIT = 60.0

SPECTRAL_LOW_ZETA = (
    "the spectral method's error estimate (5e-4 to 8e-4) does not cover its power-balance "
    "misfit on a standard linear solid at small ζ (friction against bulk dissipation: 4.3e-2 "
    "at ζ = 2.7e-6, 8.1e-3 at 9.3e-4, 1.2e-3 at 8.6e-5): the grid does not resolve the "
    "relaxation at the contact edges, and the estimate compares two grids that both miss it")
HALF_PERIOD_FIRST_CONTACT = (
    "the first contact's motion (Prony solid at ζ = 8.3e-6, relaxation lengths far below δX = "
    "1e-4) spreads it over half the period and slows down where the equilibrium solve finds no "
    "root (it stalls at max|r| = 0.834), then does not stop within 2000 steps; with the edge "
    "zones remade at every step the contact travels round the period instead: the motion's end "
    "depends on the mesh zones here")
MD_ZONES_AT_X0 = (
    "the Maugis-Dugdale zones' bounded-stress equations do not converge in 60 Newton "
    "iterations at the first edge set, so the residual at x0 is not finite and the solve "
    "fails (a solver-path failure)")

SEEDS = [
    pytest.param(0, marks=pytest.mark.xfail(strict=True, reason=SPECTRAL_LOW_ZETA)),
    pytest.param(7, marks=pytest.mark.xfail(strict=True, reason=SPECTRAL_LOW_ZETA)),
    pytest.param(12, marks=pytest.mark.xfail(strict=True, reason=SPECTRAL_LOW_ZETA)),
    31,
    pytest.param(56, marks=pytest.mark.xfail(strict=True, reason=HALF_PERIOD_FIRST_CONTACT)),
    # no contact holds under the edges' motion below Δ̃ = 0.974 (SLS β = 376, confined layer,
    # γ̃ = 5.2e-7, ζ = 0.38), and the closed contact travels under the target load: "no steady
    # state at this control", a property of the scene under its history (the former search
    # rules reported closure at once)
    63,
    pytest.param(3, marks=pytest.mark.xfail(strict=True, reason=MD_ZONES_AT_X0)),
    8,
]


@pytest.mark.parametrize("seed", SEEDS)
def test_drawn_scene_passes_its_checks(seed):
    table = draw(seed)
    outcome = run_scene(table, time_limit=LIMIT)
    assert outcome.passed, (describe(table), outcome.outcome, outcome.failures)
    assert outcome.outcome in ("converged", "outside-model", "scene", "refused")
