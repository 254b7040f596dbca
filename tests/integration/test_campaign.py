"""A short, fixed sample of the randomised campaign (``viscocontact.testing.campaign``): every
drawn scene converges or ends for a property of the scene, and every converged result passes
its identities (load met, no interpenetration, friction against the sliding on a lossy solid,
friction equal to the dissipated power within the error estimates of the two sides).

The full campaign (300 scenes over every component kind and range, with its table by
component) is ``benchmarks/campaign.py`` (``docs/verification.md``, "Randomised campaign").
The seeds here are not chosen by outcome: for each adhesion model they are the first seeds of
the campaign whose scene solved in under 3 s there (three without adhesion, three with the
energy balance, two with Maugis-Dugdale; the campaign at 865c898), and two of an earlier such
draw. The scenes of that earlier draw that now take 8-16 s in the campaign (30-40 s with their
checks on a slow two-core machine) are slow tests. The ones that fail are kept as strict xfails
naming the defect they show.
"""
import pytest

from viscocontact.testing.campaign import describe, draw, run_scene

# A limit far past these scenes' times (under 7 s with their checks), so that a scene that
# runs away fails instead of holding the suite.
LIMIT = 60.0

SEEDS = [
    0, 4, 7,        # no adhesion
    2, 20, 22,      # the energy balance (20 says it lies outside the δX model)
    10, 17,         # Maugis-Dugdale
    # of the earlier draw, spectral, SLS at ζ = 9.3e-4 and 8.6e-5: μ and the dissipation
    # 8.1e-3 and 1.2e-3 apart, each side within its estimate on the scale max(|μ|, 0.01·√m2)
    12,
    31,
]

SLOW_SEEDS = [
    # Prony solid at ζ = 8.3e-6 (relaxation lengths far below δX = 1e-4): the first contact
    # spreads over half the period, and the contact travels round it (no steady state)
    56,
    # no contact holds under the edges' motion below Δ̃ = 0.974 (SLS β = 376, confined layer,
    # γ̃ = 5.2e-7, ζ = 0.38), and the closed contact travels under the target load: "no steady
    # state at this control", a property of the scene under its history (the former search
    # rules reported closure at once)
    63,
    3,          # Maugis-Dugdale on a free layer: solved by the spectral method
    8,
]


@pytest.mark.parametrize("seed", SEEDS + [pytest.param(s, marks=pytest.mark.slow)
                                          for s in SLOW_SEEDS])
def test_drawn_scene_passes_its_checks(seed):
    table = draw(seed)
    outcome = run_scene(table, time_limit=LIMIT)
    assert outcome.passed, (describe(table), outcome.outcome, outcome.failures)
    assert outcome.outcome in ("converged", "outside-model", "scene", "refused")
