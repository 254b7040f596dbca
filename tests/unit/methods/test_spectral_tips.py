"""The tips of the cohesive zones on the spectral grid (``methods/spectral/tips.py``): each tip
moves in its outward coordinate by its own residual, and a root once bracketed is not left."""
import numpy as np
import pytest

from viscocontact.methods.spectral.tips import BRACKET_AGE, TipTrack, _tip_step, moved_tips


def test_a_tip_moves_the_way_its_residual_says_until_a_sample_of_each_sign_brackets_it():
    track = TipTrack()
    s, track = _tip_step(track, 0.0, -1.0, 0.5, 1.0)      # no slope yet: the fixed point
    assert s == 0.5 and track.inner == (0.0, -1.0, 1) and track.outer is None
    # a residual that rises with the gap's slope: the secant lands on its root
    s, track = _tip_step(track, 0.5, -0.5, 0.75, 1.0)
    assert s == pytest.approx(1.0)
    s, track = _tip_step(track, 1.0, 2.0, 0.9, 1.0)       # past the root: now bracketed
    assert track.inner[:2] == (0.5, -0.5) and track.outer[:2] == (1.0, 2.0)
    assert 0.5 < s < 1.0


def test_a_zone_growing_under_its_own_stress_grows_at_a_minimum_of_the_gap():
    """A zone narrower than a cell around a local minimum of the gap (a zone without contact
    just born): the gap's own slope at its tip is about zero, here slightly negative, and the
    residual falls as the zone grows (its own stress pulls the gap down). The tip moves out, the
    way its residual says, not to the secant's root back across the run (samples from a
    confined rough Maugis-Dugdale approach, whose zone cycled so until its solves ran out)."""
    track = TipTrack()
    s, track = _tip_step(track, 0.0091, -2.688e-4, 0.0215, -1e-5)
    assert s == pytest.approx(0.0215)
    s, track = _tip_step(track, 0.0215, -3.673e-4, 0.0384, -1e-5)
    assert s > 0.0384              # twice its last move out, past the creeping fixed point


def test_a_bracketed_tip_stays_inside_its_bracket_on_a_kinked_residual():
    """A residual with a kink (a cell centre's, or the zone's own pull) where the secant of the
    last two samples points far outside the bracket: the false position, else the middle, keeps
    the tip inside, and it converges to the root."""
    def residual(s):                                     # root at 2.0, slopes 0.01 and 100
        return 0.01 * (s - 2.0) if s < 2.0 else 100.0 * (s - 2.0)

    track, s = TipTrack(), 0.0
    samples = []
    for _ in range(40):
        r = residual(s)
        samples.append(s)
        if abs(r) < 1e-12:
            break
        s, track = _tip_step(track, s, r, s + 0.5 if r < 0 else s - 0.5, 1.0)
    assert abs(residual(s)) < 1e-10
    bracketed = [k for k in range(len(samples)) if samples[k] > 2.0]
    assert bracketed, "the moves must pass the root once"
    first = bracketed[0]
    assert all(samples[first - 1] - 1e-12 <= x <= samples[first] + 1e-12
               for x in samples[first + 1:])


def test_a_side_the_root_has_left_is_let_go():
    """The tip's residual shares the other tips' moves: a sample nearer to the outer side than
    the inner one and yet no smaller says the root moved out; an old side lapses."""
    track = TipTrack().sampled(1.0, -1.0).sampled(2.0, 1.0)
    assert track.inner is not None and track.outer is not None
    moved = track.sampled(1.5, -2.0)
    assert moved.outer is None and moved.inner[:2] == (1.5, -2.0)
    aged = track
    for _ in range(BRACKET_AGE):
        aged = aged.sampled(1.9, 0.5)
    assert aged.inner is None and aged.outer[:2] == (1.9, 0.5)


def test_two_tips_of_a_run_do_not_cross():
    gap = np.linspace(0.0, 1.0, 16)
    (lo, hi), = moved_tips([(4.0, 4.2)], [(5.0, 5.0)], [(5.0, 3.0)], gap, None)[0]
    assert lo == hi


def test_a_zone_that_snaps_over_many_cells_at_first_touch_settles():
    """Just past first touch on a rough profile with a strong, short-range law (campaign seed
    33, a JKR-like scene: the zone spans about six cells of this grid), the zone's pull brings
    a tenth of the period into contact within one step: its tips move by hundreds of cells.
    Held in their brackets they settle where the law holds (with the secant of the last two
    samples alone they cycled between the two sides of the kinked residual for the 60 solves
    allowed)."""
    import viscocontact as vc
    from viscocontact.methods.spectral import Spectral
    from viscocontact.methods.spectral.cohesive import cohesive_solve, law_violation
    from viscocontact.methods.spectral.grid import UniformGrid
    from viscocontact.methods.spectral.ladder import grid_options

    scene = vc.Scene.from_dict({
        "profile": {"kind": "self-affine", "hurst": 0.5874090058901738, "scales": 50,
                    "rms": 0.0036102483646738006, "seed": 3034},
        "rheology": {"kind": "standard-linear-solid", "beta": 7780.699368740201},
        "adhesion": {"kind": "maugis-dugdale", "gamma": 3.909650717106895e-06,
                     "range": 0.00018827295623187815},
        "load": {"mean_pressure": 0.3309714626904658},
        "sliding": {"zeta": 1.7268126239927188e-05}})
    problem = vc.ContactProblem.from_scene(scene)
    method = Spectral()
    prep = method.prepare(problem)
    law = method.law(problem, prep.shape.amplitude)
    points = 16384
    grid = UniformGrid.of(prep.shape, points)
    op = prep.operators.circulant(prep.kernel, points)
    options = grid_options(method)
    out = cohesive_solve(op, grid.heights, law, penetration=-law.opening + 2e-4,
                         start=np.zeros(points), start_penetration=-law.opening, **options)
    assert out.solution.converged, out.solution.message
    assert out.contact.sum() > 0.05 * points               # the snap into contact
    assert law_violation(out.solution.pressure, out.gap, out.contact, out.weights,
                         law) <= 10 * options["tolerance"]
