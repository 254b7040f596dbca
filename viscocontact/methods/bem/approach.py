"""The approach history: quasi-static loading from first touch to the target, with events.

The contact is pressed on at constant speed, slowly: its state follows a branch of equilibria
in the penetration ``Δ̃``, from the first contact at the highest peak to the target penetration,
or under load control to the target load. A continuation follows the branch:

* **steps** in ``Δ̃`` start from the branch's tangent (:meth:`Path.predicted`) and are solved at
  fixed penetration; a step is accepted when its corrector stays within :attr:`jumped
  <ApproachOptions.jumped>` half-widths of the prediction, and the next step follows from the
  corrector's distance (:meth:`Path.next_step`). A step that fails is halved.
* **events** are what ends the branch within a step: a *fold* in ``Δ̃`` (no equilibrium
  near the prediction however short the step), a *load peak* under load control (the load
  falls along the branch before it reaches the target: under load control the branch is
  unstable past its peak), *closure* over the period, and the *target*. A step that meets a
  fold, a peak or closure is halved until it is :attr:`resolution <ApproachOptions.resolution>`
  of the path step long, which locates the event to that resolution; births, merges and
  detachments within a step are handled by the equilibrium solve (its restarts) and recorded.
* every **jump** (the first contact settling, a fold, a load peak) follows one stated rule: the
  overdamped motion of the edges (:mod:`~viscocontact.methods.bem.relax`) from the last state on
  the branch, at the control just past the event, until the edges stop.

So the state reached is a property of the scene and of this history, converged as the path
step and the resolution shrink (``benchmarks/approach_paths.py`` compares a four times finer
path), not of a search order.
"""
from __future__ import annotations

import attrs
import numpy as np

from .path import APPROACH_BUDGET, STEP_REDUCTION, Path
from .relax import Relaxation
from .sets import Control, first_touch
from .state import Outcome, State


@attrs.frozen(kw_only=True)
class ApproachOptions:
    """The settings of the approach's continuation (one frozen object).

    Parameters
    ----------
    path_step : float
        Largest step of ``Δ̃`` (:attr:`Discretization.path_step`).
    resolution : float
        An event is located to this fraction of the path step.
    jumped : float
        A converged step whose corrector moved an edge more than this many half-widths of its
        contact from the prediction left its branch: it is halved like a failed one.
    relax_tolerance : float
        The jumps' local error bound (:class:`~viscocontact.methods.bem.relax.Relaxation`).
    """

    path_step: float
    resolution: float = 1.0 / 16.0
    jumped: float = 0.25
    relax_tolerance: float = 0.02

    @property
    def smallest(self) -> float:
        return self.path_step * self.resolution


def _record(log, kind: str, **values) -> None:
    """A typed event in the solve's log (``log.records``) and its prose (``log.events``)."""
    log.records.append({"kind": kind, **{k: float(v) for k, v in values.items()}})
    log.event(f"{kind} at " + ", ".join(f"{k} = {v:.6g}" for k, v in values.items()))


class Approach:
    """The approach of one solve; :meth:`run` returns the state at the target."""

    def __init__(self, path: Path, options: ApproachOptions):
        self.path = path
        self.eq = path.eq
        self.options = options
        self.relax = Relaxation(path.eq, path.closed, tolerance=options.relax_tolerance)

    def run(self, target: Control) -> State:
        if not target.is_load and target.value <= 0:
            # approached from afar, the profile first touches at Δ̃ = 0 (adhesion acts only on
            # contact): no contact yet
            return State.no_contact()
        d0, edges = first_touch(self.eq.prep.shape)
        touch = Control.penetration_of(d0)
        state = self.relax.run(edges, touch, final=False)   # the first contact settles
        if state.outcome is Outcome.FULL_CONTACT:
            return self.closed(state, None, target)
        if not state.converged:
            return state
        return self.climb(state, d0, target)

    def closed(self, state: State, before: State | None, target: Control) -> State:
        """The contact closed over the period on the way to ``target``."""
        _record(self.eq.log, "closure", penetration=np.nan if before is None
                else before.fields.penetration)
        if target.is_load and not self.path.closed.supports(target.value):
            start = before.edges if before is not None else state.edges
            return self.eq.solve(start, target)
        return state

    def climb(self, state: State, d: float, target: Control) -> State:
        """Follow the branch from ``state`` at penetration ``d`` to the target.

        After a step that meets an event, the event lies between the state and that step's
        penetration (``bracket``): the following steps stay inside, aimed just short of the
        fold that the failed step's start predicts (:meth:`Path.fold_from_start`), else at the
        middle, until the bracket is :attr:`ApproachOptions.smallest` wide; then the event
        acts from the state, at the bracket's end."""
        eq, path, opt = self.eq, self.path, self.options
        step, below = opt.path_step, None
        bracket: tuple[float, str] | None = None      # (penetration past the event, its kind)
        aim: float | None = None                      # the fold predicted inside the bracket
        d_end = None if target.is_load else target.value
        while True:
            load = float(state.fields.mean_pressure)
            if d_end is None and load >= target.value:
                return self.at_load(state, below, target)
            if d_end is not None and abs(d_end - d) <= 1e-15:
                return state
            if bracket is not None and bracket[0] - d <= opt.smallest * (1 + 1e-9):
                landing = self.act(bracket[1], state, below, bracket[0], target)
                if landing.outcome is not Outcome.CONVERGED:
                    return landing
                below, state, d = None, landing, float(landing.fields.penetration)
                step, bracket, aim = opt.path_step, None, None
                continue
            d_next = self.next_penetration(d, step, d_end, bracket, aim)
            tangent = path.tangent(state, False)
            start = path.predicted(state, d_next - d, tangent=tangent)
            last = d_next == d_end
            trial = eq.solve(start, Control.penetration_of(d_next), use_fallback=False,
                             budget=path.budget, refine=last, polish=last,
                             probation=path.probation, pace=path.pace,
                             reduction=0.0 if last else STEP_REDUCTION)
            event = self.event(state, start, trial, d_end is None)
            if event is None:
                step = path.next_step(d_next - d, start, state.edges, trial.edges)
                below, state, d = state, trial, d_next
                continue
            bracket, aim = (d_next, event), None
            if event == "fold" and eq.adhesive:
                ahead = path.fold_from_start(state, tangent, start, d, d_next - d)
                aim = None if ahead is None else ahead[0]

    def next_penetration(self, d: float, step: float, d_end: float | None,
                         bracket: tuple[float, str] | None, aim: float | None) -> float:
        """The next step's penetration: a path step (up to the target penetration), or inside
        the bracket of an event, just short of its predicted fold or at its middle."""
        if bracket is None:
            return d + step if d_end is None else d + float(np.clip(d_end - d, -step, step))
        end, half = bracket[0], 0.5 * self.options.smallest
        if aim is not None and d + half < aim - half < end:
            return aim - half
        return 0.5 * (d + end)

    def act(self, event: str, state: State, below: State | None, past: float,
            target: Control) -> State:
        """The event's action, located between ``state`` and the penetration ``past``."""
        if event == "closure":
            return self.closed(State.full_contact(), state, target)
        landing = self.jump(event, state, below, past)
        if landing.outcome is Outcome.FULL_CONTACT:
            return self.closed(landing, state, target)
        return landing

    def event(self, state: State, start, trial: State, load_control: bool) -> str | None:
        """What ends the branch within a step to ``trial`` (None: the step is on the branch)."""
        if trial.outcome is Outcome.FULL_CONTACT:
            return "closure"
        if trial.outcome is not Outcome.CONVERGED:
            return "fold"
        if (self.eq.adhesive and np.shape(trial.edges) == np.shape(state.edges)
                and self._moved(start, trial.edges) > self.options.jumped):
            return "fold"
        if load_control and trial.fields.mean_pressure < state.fields.mean_pressure:
            return "load peak"
        return None

    @staticmethod
    def _moved(start, edges) -> float:
        start, edges = np.asarray(start, dtype=float), np.asarray(edges, dtype=float)
        if start.shape != edges.shape or not edges.size:
            return 0.0
        half = np.repeat(0.5 * (edges[1::2] - edges[0::2]), 2)
        return float(np.max(np.abs(edges - start) / half))

    def jump(self, event: str, state: State, below: State | None, d_next: float) -> State:
        """The branch ends at ``state`` (an ``event`` located within the resolution): the edges'
        motion from there, at the penetration ``d_next`` past a fold, or under load control at
        the load just past the peak (the last increment's half beyond the state's load)."""
        log = self.eq.log
        if event == "load peak":
            load = float(state.fields.mean_pressure)
            rise = 0.0 if below is None else load - float(below.fields.mean_pressure)
            control = Control.load_of(load + 0.5 * max(rise, 0.0))
            _record(log, "load peak", penetration=state.fields.penetration, load=load)
        else:
            control = Control.penetration_of(d_next)
            _record(log, "fold", penetration=state.fields.penetration)
        landing = self.relax.run(state.edges, control, final=False)
        if landing.converged:
            _record(log, "jump", area=float(np.sum(landing.fields.mesh.width)),
                    penetration=landing.fields.penetration)
        return landing

    def at_load(self, state: State, below: State | None, target: Control) -> State:
        """The target load, reached within the last step (from ``below`` to ``state``): solved
        from the closer of the two, predicted along the branch in load."""
        eq, path = self.eq, self.path
        p = float(state.fields.mean_pressure)
        candidates = [state] if below is None else sorted(
            (state, below), key=lambda s: abs(float(s.fields.mean_pressure) - target.value))
        out = None
        for start in candidates:
            guess = path.predicted(start, target.value - float(start.fields.mean_pressure),
                                   load=True)
            out = eq.solve(guess, target)
            if out.outcome in (Outcome.CONVERGED, Outcome.FULL_CONTACT):
                return out
        _record(eq.log, "target not solved", load=p)
        assert out is not None
        return out


__all__ = ["APPROACH_BUDGET", "Approach", "ApproachOptions"]
