"""Histories: named, stored, and independent of the recorded ζ; the speed ramp's step control
and events on a branch whose shape is known, and on the adhesive sinusoid."""
import math

import attrs
import numpy as np
import pytest

from viscocontact.errors import ValidationError
from viscocontact.methods.bem.relax import RelaxFrom
from viscocontact.studies import Sweep, run
from viscocontact.studies.history import Approach, SpeedRamp, history
from viscocontact.studies.ramp import Node, Ramp, RampState


@attrs.frozen
class Fake:
    """What the ramp reads of a result."""

    converged: bool
    edges: np.ndarray
    full_contact: bool = False
    function_evaluations: int = 1
    message: str = "converged"
    area: float = float("nan")


BIRTH, FOLD = 0.37, 0.8      # log10 ζ of a contact's birth and of the branch's end


def half_width(log_zeta):
    return 1.0 + 0.3 * math.tanh(2.0 * log_zeta)


def branch(log_zeta, start):
    """A contact whose half-width changes smoothly with ζ, a second contact born at BIRTH, a
    branch that ends at FOLD (a solve from a contact set past it fails) and the approach from
    edges' motion (the jump) that lands on a narrow contact there."""
    if isinstance(start, RelaxFrom):
        return Fake(True, np.array([-0.5, 0.5]), area=1.0)
    if start is not None and len(start) == 2 and abs(start[0] + 0.5) < 0.2:
        return Fake(True, np.array([-0.5, 0.5]), area=1.0)     # past the jump: stays there
    if log_zeta > FOLD:
        return Fake(False, np.zeros(0), message="no equilibrium near the start")
    a = half_width(log_zeta)
    edges = [-a, a] + ([2.0, 2.2 + 0.1 * (log_zeta - BIRTH)] if log_zeta > BIRTH else [])
    return Fake(True, np.array(edges))


def march(ramp, zetas, start=-1.0):
    calls = []

    def solve(zeta, edges):
        calls.append(zeta)
        return branch(math.log10(zeta), edges)

    first = Node.of(start, branch(start, np.zeros(2)))
    state = RampState(older=None, last=first, step=ramp.tolerance)
    out, events = [], []
    for zeta in zetas:
        steps = Ramp(history=ramp, solve=solve, direction=state.heading(math.log10(zeta)))
        state, result = steps.record(state, zeta)
        out.append(result)
        events += steps.events
    return out, events, calls


def test_history_names_and_their_errors():
    assert history("approach") == Approach() and history(Approach()) == Approach()
    ramp = history({"name": "speed-ramp", "tolerance": 0.01})
    assert ramp == SpeedRamp(tolerance=0.01) and history(ramp.params()) == ramp
    for bad, field in (("jump", "history"), ({"name": "speed-ramp", "step": 1}, "history"),
                       ({"name": "speed-ramp", "tolerance": 0.0}, "history.tolerance"),
                       ({"name": "speed-ramp", "largest_step": 3.0}, "history.largest_step")):
        with pytest.raises(ValidationError) as info:
            history(bad)
        assert info.value.field == field


def test_a_speed_ramp_needs_monotonic_positive_zetas(adhesive):
    for zetas in ([0.0, 1.0], [1.0, 0.1, 1.0]):
        with pytest.raises(ValidationError) as info:
            Sweep(scene=adhesive, zetas=zetas, history="speed-ramp")
        assert info.value.field == "sweep.zetas"
    assert Sweep(scene=adhesive, zetas=[1.0, 0.1], history="speed-ramp").history == SpeedRamp()


def test_files_written_before_histories_read_with_one(adhesive):
    old = {"zetas": [0.1, 1.0], "loads": [0.1], "control": "mean_pressure", "seeds": None,
           "pair": True, "fields": False, "discretization": None}
    assert Sweep.from_params(adhesive, {**old, "continuation": False}).history == Approach()
    assert Sweep.from_params(adhesive, {**old, "continuation": True, "zeta_step": 0.5}
                             ).history == SpeedRamp()


def test_the_ramp_locates_a_birth_within_its_tolerance():
    ramp = SpeedRamp(tolerance=0.02)
    results, events, _ = march(ramp, [1.0, 10 ** 0.5])
    births = [e for e in events if e["kind"] == "birth"]
    assert len(births) == 1 and births[0]["contacts"] == [1, 2]
    assert BIRTH < math.log10(births[0]["zeta"]) <= BIRTH + ramp.tolerance + 1e-12
    assert len(results[1].edges) == 4


def test_the_ramp_records_the_same_values_at_any_sampling():
    """The path does not depend on the recorded ζ: recorded every 0.05 or every 0.5 decades,
    the common points come from the same bracketing nodes, so they are the same."""
    ramp = SpeedRamp(tolerance=0.02)
    fine = list(np.logspace(-0.9, 0.6, 31))
    coarse = fine[8::10]
    a, _, calls_fine = march(ramp, fine)
    b, _, calls_coarse = march(ramp, coarse)
    for zeta, result in zip(coarse, b):
        i = int(np.argmin(np.abs(np.log10(fine) - np.log10(zeta))))
        assert np.array_equal(a[i].edges, result.edges)
    def path(calls):        # the path's solves: those not at a recorded ζ
        return [z for z in calls if np.min(np.abs(np.log10(fine) - np.log10(z))) > 1e-12]

    path_fine, path_coarse = path(calls_fine), path(calls_coarse)
    assert path_coarse == path_fine[:len(path_coarse)]


def test_the_ramp_state_keeps_its_direction_past_a_recorded_zeta():
    """A path that has stepped past the next recorded ζ records it behind itself and goes on
    in its own direction; a state written without a direction reads it from its step."""
    first = Node(log_zeta=0.0, edges=(-1.0, 1.0), full=False)
    ahead = Node(log_zeta=0.3, edges=(-1.1, 1.1), full=False)
    assert RampState(older=None, last=first, step=0.02).heading(-0.5) == -1.0
    state = RampState(older=first, last=ahead, step=-0.04, direction=-1.0)
    assert state.heading(1.0) == -1.0 and RampState.from_json(state.to_json()) == state
    old = '{"older": [0.0, [-1.0, 1.0], false], "last": [0.3, [-1.1, 1.1], false], "step": 0.04}'
    assert RampState.from_json(old).heading(0.2) == 1.0
    first_only = '{"older": null, "last": [0.3, [-1.1, 1.1], false], "step": 0.02}'
    assert RampState.from_json(first_only).heading(0.2) == -1.0


def test_the_step_control_keeps_the_secant_error_within_the_tolerance():
    """Every accepted node's edges lie within the tolerance (in half-widths) of the secant
    through the two before it; a tighter tolerance takes more steps."""
    counts = []
    for tol in (0.02, 0.002):
        ramp = SpeedRamp(tolerance=tol)
        steps = Ramp(history=ramp, solve=lambda z, e: branch(math.log10(z), e), direction=1.0)
        state = RampState(older=None, last=Node.of(-1.0, branch(-1.0, None)), step=tol)
        nodes = [state.last]
        while state.last.log_zeta < 0.3:
            state, _ = steps.advance(state)
            nodes.append(state.last)
        for older, before, node in zip(nodes, nodes[1:], nodes[2:]):
            t = (node.log_zeta - before.log_zeta) / (before.log_zeta - older.log_zeta)
            guess = before.edges[1] + t * (before.edges[1] - older.edges[1])
            assert abs(guess - node.edges[1]) / node.edges[1] <= tol * (1 + 1e-9)
        counts.append(len(nodes))
    assert counts[1] > 2 * counts[0]


LOSS, CLOSURE = 0.2, 0.55     # log10 ζ where a second contact detaches and the contact closes


def closing(log_zeta, start):
    """Two contacts up to LOSS, one up to CLOSURE, full contact past it (either way in ζ)."""
    if log_zeta > CLOSURE:
        return Fake(True, np.zeros(0), full_contact=True)
    a = half_width(log_zeta)
    return Fake(True, np.array([-a, a] + ([2.0, 2.3] if log_zeta < LOSS else [])))


@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_the_ramp_locates_a_loss_a_closure_and_an_opening_within_its_tolerance(direction):
    """Up in ζ: a contact lost, then closure; down: the contact opens, then one is born. Each
    event is located within the tolerance past its ζ, in the ramp's direction."""
    ramp = SpeedRamp(tolerance=0.02)
    steps = Ramp(history=ramp, solve=lambda z, e: closing(math.log10(z), e), direction=direction)
    start = 0.0 if direction > 0 else 0.8
    state = RampState(older=None, last=Node.of(start, closing(start, None)), step=ramp.tolerance)
    state, _ = steps.record(state, 10 ** (start + direction * 0.8))
    found = [(e["kind"], math.log10(e["zeta"]), e["contacts"]) for e in steps.events]
    expected = ([("loss", LOSS, [2, 1]), ("closure", CLOSURE, [1, -1])] if direction > 0
                else [("opening", CLOSURE, [-1, 1]), ("birth", LOSS, [1, 2])])
    assert [(k, c) for k, _, c in found] == [(k, c) for k, _, c in expected]
    for (_, at, _), (_, where, _) in zip(found, expected):
        assert 0 <= direction * (at - where) <= ramp.tolerance + 1e-12


@pytest.mark.parametrize("tol", [0.02, 0.005])
def test_the_branch_end_jumps_by_the_stated_rule_at_any_tolerance(tol):
    """Past the fold no step converges: the ramp jumps (the edges' motion) at the ζ just past
    it, located within the smallest step, and the state after the jump is the same at any
    tolerance."""
    ramp = SpeedRamp(tolerance=tol)
    results, events, _ = march(ramp, [10 ** 0.5, 10.0])
    jumps = [e for e in events if e["kind"] == "jump"]
    assert len(jumps) == 1 and jumps[0]["area"] == [None, 1.0]
    assert FOLD < math.log10(jumps[0]["zeta"]) <= FOLD + ramp.smallest_step + ramp.tolerance
    assert np.array_equal(results[1].edges, [-0.5, 0.5])


def test_the_adhesive_sinusoid_swept_at_one_and_three_points_per_decade(tmp_path, adhesive,
                                                                       mesh):
    """Both histories, recorded at 1 and 3 points per decade: the same values at the common ζ
    (the approach's points are single solves, the ramp's come from one path); every point
    stores its history."""
    for name in ("approach", "speed-ramp"):
        tables = []
        for per in (1, 3):
            zetas = np.logspace(-1, 1, 2 * per + 1)
            data = run(Sweep(scene=adhesive, zetas=zetas, pair=False, history=name,
                             discretization=mesh), tmp_path / f"{name}{per}.h5", progress=None)
            assert data.points["converged"].all()
            assert set(data.points["history"]) == {name}
            order = np.argsort(data.points["zeta"])
            tables.append(np.column_stack([data.points[k][order]
                                           for k in ("zeta", "area", "friction")]))
        coarse, fine = tables
        assert np.allclose(fine[::3, 0], coarse[:, 0], rtol=1e-12)
        assert np.array_equal(fine[::3, 1:], coarse[:, 1:])
