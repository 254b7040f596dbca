"""Scenes of the scene space that once ended wrongly, each held to the campaign's checks
(``viscocontact.testing.campaign``): converged, or not converged for a property of the scene,
and a converged result meets its load, does not interpenetrate, has μ >= 0 on a lossy solid and
friction equal to the dissipated power unless it says that it lies outside the model.

The scenes are given in the dimensionless groups of ``docs/scene.md``: ``amplitude`` is Λ̃,
``rms`` is q0·r_rms, ``gamma`` is γ̃, ``range`` is h̃0, ``mean_pressure`` p̃∞, ``penetration`` Δ̃.
"""
import math

import pytest

import viscocontact as vc

from viscocontact.testing.campaign import run_scene

# A limit well past each scene's solve time, so that a scene that runs away fails instead of
# holding the suite (the deadline is checked at every residual evaluation).
LIMIT = 300.0

ROUGH_GLASSY_EB = {
    "profile": {"kind": "self-affine", "hurst": 0.93, "scales": 100, "rms": 0.007,
                "seed": 5633},
    "rheology": {"kind": "standard-linear-solid", "beta": 4282.0},
    "adhesion": {"kind": "energy-balance", "gamma": 2.68e-7},
    "load": {"mean_pressure": 0.497}, "sliding": {"zeta": 1.9e-4},
    "solver": {"kind": "broyden"}}

THIN_FREE_LAYER_MD = {
    "profile": {"kind": "sinusoid", "amplitude": 0.015},
    "rheology": {"kind": "standard-linear-solid", "beta": 9341.0},
    "kernel": {"kind": "free-layer", "thickness": 0.19},
    "adhesion": {"kind": "maugis-dugdale", "gamma": 1.66e-6, "range": 4.5e-4},
    "load": {"mean_pressure": 0.655}, "sliding": {"zeta": 5768.0}}

CONFINED_ROUGH_MD = {
    "profile": {"kind": "self-affine", "hurst": 0.59, "scales": 50, "rms": 0.0228},
    "rheology": {"kind": "standard-linear-solid", "beta": 4.58},
    "kernel": {"kind": "confined-layer", "thickness": 12.7},
    "adhesion": {"kind": "maugis-dugdale", "gamma": 4.6e-6, "range": 1.5e-3},
    "load": {"mean_pressure": 0.53}, "sliding": {"zeta": 1.4e-3}}

# campaign seed 84 (drawn values): near the target load the held solve at the edges' rest
# stalled at max|r| = 4e-8, within the residuals' round-off there (a one-ulp move of an edge
# changes its residual by up to 2.7e-7) but far above the floor measured at the first contact
# (below 1e-9), and the motion went on for 2000 steps
GLASSY_WAVY_EB_BISECTION = {
    "profile": {"kind": "sinusoid", "amplitude": 0.05194425828260963},
    "rheology": {"kind": "standard-linear-solid", "beta": 424.94419545491996},
    "adhesion": {"kind": "energy-balance", "gamma": 6.165816817570425e-07},
    "load": {"mean_pressure": 0.7993180485742702}, "sliding": {"zeta": 3.379356783004704e-05},
    "solver": {"kind": "bisection"}}

WAVY_EB_PENETRATION_CG = {
    "profile": {"kind": "sinusoid", "amplitude": 0.038},
    "rheology": {"kind": "standard-linear-solid", "beta": 78.0},
    "adhesion": {"kind": "energy-balance", "gamma": 4.3e-6},
    "load": {"penetration": 0.272}, "sliding": {"zeta": 0.275},
    "solver": {"kind": "nonlinear-cg"}}


def _stiff_rough(beta, zeta, seed):
    return {"profile": {"kind": "self-affine", "hurst": 0.8, "scales": 50, "rms": 0.01,
                        "seed": seed},
            "rheology": {"kind": "standard-linear-solid", "beta": beta},
            "load": {"mean_pressure": 0.3}, "sliding": {"zeta": zeta}}


def _passes(table, limit=LIMIT):
    outcome = run_scene(table, time_limit=limit)
    assert outcome.passed, (outcome.outcome, outcome.failures)
    return outcome


@pytest.mark.slow
def test_glassy_rough_energy_balance_says_it_is_outside_the_model():
    """Converged with μ = 8.3e-4 while the bulk dissipation was 0.208 (250 times μ): the result
    must say that it lies outside the model, or close its power balance (40-95 s)."""
    outcome = _passes(ROUGH_GLASSY_EB)
    if outcome.outcome == "converged":
        assert outcome.power_tolerance in ("estimate", "fallback")
    else:
        assert outcome.outcome == "outside-model" and "outside the model" in outcome.message


@pytest.mark.slow
def test_thin_free_layer_maugis_dugdale():
    """Maugis-Dugdale zones on a thin free layer at the glassy end: the BEM stalls where its
    zones meet across a neck whose gap exceeds the range (the zones' representation, not the
    scene), and ``auto`` solves the scene on the grid, which converges (estimate 4.9e-4,
    friction equal to the dissipated power to 1.6e-6; 10 s on two cores)."""
    outcome = _passes(THIN_FREE_LAYER_MD)
    assert outcome.outcome == "converged" and outcome.method == "spectral"


@pytest.mark.slow     # 60 s on two loaded cores
def test_confined_rough_maugis_dugdale():
    """Rough Maugis-Dugdale contact on a thick confined layer at ζ = 1.4e-3: the BEM ends where
    a cohesive zone without a contact forms (its zones sit at contact edges), and ``auto``
    solves the scene on the grid. There the zone is born narrower than a cell at a local
    minimum of the gap and grows under its own stress; its tips' secant pointed back across it
    and the zone cycled until the approach's solves ran out. Moved out, the way their residual
    says, the tips settle and the grid converges (estimate 3.3e-4)."""
    outcome = _passes(CONFINED_ROUGH_MD, limit=150.0)
    assert outcome.outcome == "converged" and outcome.method == "spectral"


@pytest.mark.slow     # 25 s on a two-core machine
def test_a_contact_born_again_where_it_vanished_ends_the_motion():
    """On the confined rough Maugis-Dugdale scene the gap falls below the cohesive range away
    from the contacts: the contact born there (7e-6 wide) narrows to nothing in the next step of
    the edges' motion and is born again at the same rest state. The motion ends there and says
    why (it went on cycling past 600 s, 1000 births, before), in well under the time limit."""
    scene = vc.Scene.from_dict({**CONFINED_ROUGH_MD, "method": {"kind": "bem"}})
    result = vc.solve(scene, time_limit=150.0)
    assert not result.converged
    assert "born there again" in result.message
    assert "cohesive zone" in result.message
    births = [r for r in result.extras["path_events"] if r["kind"] == "birth"]
    assert births        # the births before the cycle are recorded, the cycle's second is not


@pytest.mark.slow     # 19 s on a two-core machine whose dense 2000² solve takes 0.14 s
def test_wavy_energy_balance_penetration_nonlinear_cg():
    """Nonlinear CG on the wavy energy-balance contact in penetration control: the former
    approach rules stopped its edge solve at the budget of 80 residual evaluations; the
    approach with located events converges."""
    _passes(WAVY_EB_PENETRATION_CG)


def test_a_stall_within_the_round_off_at_the_rest_state_ends_the_motion():
    """The solve at the edges' rest judges its stall against the round-off floor measured
    where it stalled: the scene converges (it lies outside the δX model at this ζ, and says
    so)."""
    outcome = _passes(GLASSY_WAVY_EB_BISECTION)
    assert outcome.outcome == "outside-model"


# campaign seed 104 (drawn values): adhesionless, glassy free layer; at the edges' rest the contact
# carries a tension of 3e-4 of the largest stress, split there its parts merge again, and the
# motion ended "contact set cycles"
GLASSY_FREE_LAYER_SPLITS = {
    "profile": {"kind": "sinusoid", "amplitude": 0.015886679470924137},
    "rheology": {"kind": "standard-linear-solid", "beta": 8673.777606450556},
    "kernel": {"kind": "free-layer", "thickness": 2.263549054779695},
    "load": {"penetration": 0.7588952523120229}, "sliding": {"zeta": 0.2864907880720115},
    "solver": {"kind": "broyden"}}


@pytest.mark.slow     # 20 s on a two-core machine whose dense 2000² solve takes 0.14 s
def test_a_split_that_cycles_in_the_motion_refines_the_contact():
    """A contact whose tension and split alternate in the edges' motion is refined there, as
    in the equilibrium solve, and the motion ends on one contact: the equilibrium that 256
    elements a contact give from the start (without a refinement) to about ten times that
    solve's error estimate (1.8e-7)."""
    from viscocontact.methods.bem import BEM
    from viscocontact.methods.bem.meshing import Discretization

    outcome = _passes(GLASSY_FREE_LAYER_SPLITS)
    assert outcome.outcome == "converged"
    scene = vc.Scene.from_dict(GLASSY_FREE_LAYER_SPLITS)
    refined = vc.solve(scene, method=BEM())
    assert refined.converged and refined.n_contacts == 1
    assert any(e.startswith("mesh refined in a contact whose tension and split alternate")
               for e in refined.extras["events"])
    fine = vc.solve(scene, method=BEM(), discretization=Discretization(elements=256))
    assert fine.converged and fine.n_contacts == 1
    assert refined.area == pytest.approx(fine.area, rel=2e-6)
    assert refined.friction == pytest.approx(fine.friction, rel=2e-6)


# campaign seed 281 (drawn values): the contact at the target travels down the asperity and
# vanishes; the motion reported that as "no contact" at Δ̃ = 0.19, where the profile penetrates
# the solid (the campaign took it for an answer)
TRAVELLING_CONTACT = {
    "profile": {"kind": "sinusoid", "amplitude": 0.03227198428447506},
    "rheology": {"kind": "standard-linear-solid", "beta": 353.1039640202087},
    "kernel": {"kind": "confined-layer", "thickness": 0.4830313352282042},
    "adhesion": {"kind": "energy-balance", "gamma": 7.545006992194638e-06},
    "load": {"penetration": 0.19080593611224267}, "sliding": {"zeta": 0.023300424920644085},
    "solver": {"kind": "newton"}}


def test_a_contact_that_vanishes_where_the_profile_penetrates_is_born_again():
    """Where every contact detaches at a positive penetration, contacts are born where the
    profile penetrates; where none holds up to the target (they travel off and vanish, and are
    born again), the solve says there is no steady state, not "no contact"."""
    outcome = _passes(TRAVELLING_CONTACT)
    assert outcome.outcome == "scene"
    assert "born again (no steady state at this control)" in outcome.message




# campaign seed 220 (drawn values): the first contact spreads over nearly the whole period; a
# step of its motion that crossed the last gap ended in full contact at Δ̃ = 0.001, which on a
# half-plane (c0 = 0) exists only at the closing penetration 1 - r̂0: the mean gap, fixed by Δ̃,
# stays open somewhere
SPREADING_ROUGH_EB = {
    "profile": {"kind": "self-affine", "hurst": 0.7981365011148809, "scales": 21,
                "rms": 0.00678163732190614, "seed": 5099},
    "rheology": {"kind": "prony", "moduli": [482.48269147614695, 14.032665282804533],
                 "times": [2.7856857384859204, 21.189752712795006]},
    "adhesion": {"kind": "energy-balance", "gamma": 1.7617528210339794e-06},
    "load": {"penetration": 0.5975653754517113}, "sliding": {"zeta": 2.3595792013485563e-06},
    "solver": {"kind": "nonlinear-cg"}}


@pytest.mark.slow     # 33 s on a two-core machine whose dense 2000² solve takes 0.14 s
def test_the_motion_does_not_close_a_gap_that_the_penetration_keeps_open():
    outcome = run_scene(SPREADING_ROUGH_EB, time_limit=LIMIT)
    assert "full contact" not in outcome.message
    assert outcome.passed, (outcome.outcome, outcome.message)


def _converges(scene: dict) -> None:
    """The scene converges and passes its checks."""
    outcome = run_scene(scene, time_limit=LIMIT)
    assert outcome.passed and outcome.outcome == "converged", (outcome.outcome, outcome.message)


# campaign seed 189 (drawn values): past a fold the one contact grows towards closure, and its
# steps land where the Maugis-Dugdale zones' equations have no field on the zones the motion
# moved with; quartered again and again, the steps fell to 1e-15 and the motion ran for 2000
# steps. Evaluated on zones made for the step's end, it closes the contact (as at 697cd18)
GROWING_WAVY_MD_LAYER = {
    "profile": {"kind": "sinusoid", "amplitude": 0.031313841035190956},
    "rheology": {"kind": "standard-linear-solid", "beta": 3992.608036140502},
    "kernel": {"kind": "confined-layer", "thickness": 4.382917419291747},
    "adhesion": {"kind": "maugis-dugdale", "gamma": 3.332913084411843e-06,
                 "range": 0.0007855791308794556},
    "load": {"mean_pressure": 0.7008081220180079}, "sliding": {"zeta": 0.812037202727584},
    "solver": {"kind": "bisection"}}


def test_a_motion_step_without_a_field_on_its_zones_is_evaluated_on_new_ones():
    _converges(GROWING_WAVY_MD_LAYER)


# campaign seed 234 (drawn values): the Maugis-Dugdale zone iteration meets zones whose
# diagonal says "past the minimum of K̃" within a tenth of their root (19 times in this solve),
# and shortened them away from it; the solve ran past 45 s at 41380a7. With Newton's step taken
# there it converges in about 20 s. On other machines' round-off its first contact's motion
# meets a zone with no root short of its neighbour, which cycled for 60 iterations (no field:
# the motion's steps fell to 1e-15, past 300 s); that neck now fills, and it converges in 25 s
LONG_ROUGH_MD_ZONES = {
    "profile": {"kind": "self-affine", "hurst": 0.6711639498056313, "scales": 67,
                "rms": 0.0037513202871212294, "seed": 6901},
    "rheology": {"kind": "standard-linear-solid", "beta": 165.66798150699552},
    "kernel": {"kind": "half-plane"},
    "adhesion": {"kind": "maugis-dugdale", "gamma": 1.4338037268639676e-06,
                 "range": 0.00027613673321702807},
    "load": {"mean_pressure": 0.20074348640697504}, "sliding": {"zeta": 0.006266912031851358},
    "solver": {"kind": "broyden"}}


@pytest.mark.slow     # 70 s with auto's grid finish; the zones' mechanisms have unit tests
def test_zones_at_a_root_past_the_minimum_stay_there():
    _converges(LONG_ROUGH_MD_ZONES)


@pytest.mark.parametrize("beta, zeta, seed", [
    # the spectral method converges in 0.3 s (16384 cells); its power-balance misfit (2.2e-3 of
    # μ) was 1.1 times the two sides' two-grid estimates, which the power balance's bound now
    # raises to add up to it
    (600.0, 1e-3, 1),
    # the grid at 1024 cells did not converge (100 active-set steps, 22 s) and the BEM from
    # first touch had no answer at 150 s; now the stalled grid stops and the coarser one's
    # answer stands, short of the tolerance and saying so (estimate 0.12, about 18 s)
    pytest.param(5000.0, 0.1, 2, marks=pytest.mark.slow)])
def test_stiff_rough_adhesionless(beta, zeta, seed):
    """Adhesionless rough contact on a stiff solid (β 600-5000, ζ 1e-3 to 0.1): once 'contact
    set still changing after 200 restarts' or past 150 s."""
    outcome = run_scene(_stiff_rough(beta, zeta, seed), time_limit=150.0)
    assert outcome.passed, (outcome.outcome, outcome.failures)
    assert outcome.outcome == "converged" and math.isfinite(outcome.values["friction"])
    assert outcome.method == "spectral"
    if beta == 5000.0:
        assert "tolerance 0.001 not met" in outcome.message


# campaign seed 89 (drawn values): the grid reaches an estimate of 1.8e-3 at its largest grid
# (131072 cells), and the BEM asked to finish from its contact set cycles (a merged contact
# carrying 0.63 of the largest pressure); that failure was the answer. Now the grid's converged
# answer stands, with its estimate
THIN_FREE_LAYER_ROUGH = {
    "profile": {"kind": "self-affine", "hurst": 0.6855362721646882, "scales": 49,
                "rms": 0.003503590458078291, "seed": 6622},
    "rheology": {"kind": "standard-linear-solid", "beta": 1134.4471915927506},
    "kernel": {"kind": "free-layer", "thickness": 0.12280345221473729},
    "load": {"penetration": 0.4162000852374413}, "sliding": {"zeta": 4.55358758460941e-05},
    "solver": {"kind": "nonlinear-cg"}}

# campaign seed 226 (drawn values): the active set of the 8192-cell grid takes steps that are
# no descent direction, at a thousandth of their length, for a hundred steps (the campaign
# killed it at 105 s); it now stops, the coarser grid's answer misses the tolerance, and the BEM
# finishes from its contact set in a few seconds
STALLING_GRID_ROUGH = {
    "profile": {"kind": "self-affine", "hurst": 0.8131746946149895, "scales": 92,
                "rms": 0.0053060460742537586, "seed": 3922},
    "rheology": {"kind": "standard-linear-solid", "beta": 30.815124915825095},
    "kernel": {"kind": "free-layer", "thickness": 0.11448386442831496},
    "load": {"penetration": 0.7616267538644754}, "sliding": {"zeta": 0.007285974545294931},
    "solver": {"kind": "nonlinear-cg"}}


def test_the_grid_answer_stands_where_the_bem_cannot_finish():
    outcome = run_scene(THIN_FREE_LAYER_ROUGH, time_limit=LIMIT)
    assert outcome.passed and outcome.outcome == "converged", (outcome.outcome, outcome.message)
    assert outcome.method == "spectral" and "tolerance 0.001 not met" in outcome.message


def test_a_stalling_grid_leaves_the_coarser_one():
    _converges(STALLING_GRID_ROUGH)


# campaign seed 29 (drawn values): the first contact, snapped in at the first touch's
# penetration, was left at p̃∞ = -0.18 on the branch that load control cannot hold; every load
# step from there failed, and the jump past that "fold" met Maugis-Dugdale zones with no field.
# Snapped in at zero load, as the load rises from zero, it converges in about 3 s
LOADED_WAVY_MD_FREE_LAYER = {
    "profile": {"kind": "sinusoid", "amplitude": 0.01851035050625423},
    "rheology": {"kind": "prony", "moduli": [211.28280313618015, 1058.0755483434177],
                 "times": [6.388963878236111, 77.00854336871096]},
    "kernel": {"kind": "free-layer", "thickness": 19.30593954644707},
    "adhesion": {"kind": "maugis-dugdale", "gamma": 7.690047019619966e-06,
                 "range": 0.0008513248725192845},
    "load": {"mean_pressure": 0.681225488507536}, "sliding": {"zeta": 0.00018571175829673744},
    "solver": {"kind": "newton"}}


def test_under_load_control_the_first_contact_snaps_in_at_zero_load():
    _converges(LOADED_WAVY_MD_FREE_LAYER)


@pytest.mark.slow     # 22-37 s on a two-core machine
def test_a_motion_that_comes_back_to_its_births_has_no_steady_state():
    """Campaign seed 225 (energy balance on a thin confined Prony layer, penetration control):
    a contact born at a rest state grows, merges with its neighbour and the merged contact
    recedes to the same rest state, where the profile penetrates again. The motion ran so past
    600 s; it now ends for that property of the motion (no steady state)."""
    from viscocontact.testing.campaign import draw

    outcome = run_scene(draw(225), time_limit=150.0)
    assert outcome.outcome == "scene", (outcome.outcome, outcome.message)
    assert "born there again" in outcome.message and "no steady state" in outcome.message


@pytest.mark.slow     # 54-72 s on two loaded cores
def test_a_contact_without_a_field_at_first_touch_is_solved_on_the_grid():
    """Campaign seed 115 (self-affine, elastic free layer q0·d = 0.15, Maugis-Dugdale with
    h̃0 = 2.5e-3, Δ̃ = 0.50): the BEM's zones have no field at the first contact, so the
    approach solves the target at once from it, which ran past 600 s on the solver's full
    budgets. On an approach step's budgets it fails fast, and ``auto`` solves the scene on the
    grid, which converges and says that its estimate is above the tolerance."""
    from viscocontact.testing.campaign import draw

    outcome = run_scene(draw(115), time_limit=LIMIT)
    assert not outcome.failures, (outcome.failures, outcome.message)
    assert outcome.outcome == "converged" and outcome.method == "spectral"
    assert "tolerance 0.001 not met" in outcome.message
