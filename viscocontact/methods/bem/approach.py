"""The approach history: quasi-static loading from first touch to the target, with events.

The contact is pressed on at constant speed, slowly: its state follows a branch of equilibria
in the penetration ``Δ̃``, from the first contact at the highest peak to the target penetration,
or under load control to the target load. The first contact snaps in at the penetration of the
first touch, or under load control at zero load (the load rises from zero). A continuation
follows the branch:

* **steps** in the controlled quantity start from the branch's tangent (:meth:`Path.predicted`)
  and are solved at a fixed control with the contact set held; a step is accepted when its
  corrector stays within :attr:`jumped <ApproachOptions.jumped>` half-widths of the prediction
  and the contact set stays as it was, and the next step follows from the corrector's distance
  (:meth:`Path.next_step`).
* **events** are what ends the branch within a step: a *fold* (no equilibrium near the
  prediction however short the step; under load control also the *load peak*, past which the
  branch is unstable), a *birth* (the profile penetrates the solid outside the contacts), a
  *merge*, *detachment* or *split* of contacts, *closure* over the period, and the *target*.
  Before a step is solved, the fields at its predicted start predict a fold or a birth within
  it, and the step ends next to the earlier (:meth:`Climb.looked_ahead
  <.climb.Climb.looked_ahead>`). A step that meets one is shortened, towards the fold the
  branch's curvature predicts (:meth:`Climb.fold_ahead <.climb.Climb.fold_ahead>`) or the
  root of the gap where the contact is born (:meth:`Climb.birth_ahead
  <.climb.Climb.birth_ahead>`), else by halves, until the event lies within
  :attr:`resolution <ApproachOptions.resolution>` of the path step.
* every **action** that leaves the branch (the first contact settling, a fold, a contact-set
  change) follows one stated rule: the overdamped motion of the edges
  (:mod:`~viscocontact.methods.bem.relax`) from the last state on the branch, at the control
  just past the event, until the edges stop; contacts are born, merge and detach on the way.

An adhesionless contact (whose equilibrium is unique) is followed in the penetration from just
past first touch, its steps halved where the solver fails; where no adhesive contact holds at
first touch, the first penetration at which one holds is located (:meth:`Approach.held`).

So the state reached is a property of the scene and of this history, converged as the path
step and the resolution shrink (``benchmarks/approach_paths.py`` compares a four times finer
path), not of a search order.
"""
from __future__ import annotations

import attrs
import numpy as np

from .climb import Climb, moved
from .path import Path
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
    resolution: float = 1.0 / 256.0
    jumped: float = 0.25
    relax_tolerance: float = 0.02

    @property
    def smallest(self) -> float:
        return self.path_step * self.resolution


@attrs.frozen
class ContinueFrom:
    """An initial state that asks a solve to continue the branch through a known equilibrium:
    the equilibrium at ``edges`` under its own penetration ``penetration`` (a neighbouring
    point of a cycle), followed to the problem's target with its events located, as the
    approach follows it from first touch (:meth:`Approach.continued`). Pass it as
    ``ContactProblem.solve(initial=ContinueFrom(edges, penetration))``; other methods start
    from its ``edges``."""

    edges: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float).ravel())
    penetration: float = attrs.field(converter=float)


def _record(log, kind: str, **values) -> None:
    """A typed event in the solve's log (``log.records``) and its prose (``log.events``)."""
    log.records.append({"kind": kind, **{k: float(v) for k, v in values.items()}})
    where = ", ".join(f"{k} = {v:.6g}" for k, v in values.items())
    log.event(f"{kind} at {where}" if where else kind)


class Approach:
    """The approach of one solve; :meth:`run` returns the state at the target."""

    def __init__(self, path: Path, options: ApproachOptions):
        self.path = path
        self.eq = path.eq
        self.options = options
        self.relax = Relaxation(path.eq, path.closed, tolerance=options.relax_tolerance,
                                trial={"budget": path.budget, "probation": path.probation,
                                       "pace": path.pace})

    def run(self, target: Control) -> State:
        if not target.is_load and target.value <= 0:
            # approached from afar, the profile first touches at Δ̃ = 0 (adhesion acts only on
            # contact): no contact yet
            return State.no_contact()
        d0, edges = first_touch(self.eq.prep.shape)
        if not self.eq.adhesive:
            return self.pressed(edges, d0, target)
        # the first contact snaps in under the history's control: at the touch's penetration,
        # or at zero load when the load rises from zero
        touch = Control.load_of(0.0) if target.is_load else Control.penetration_of(d0)
        edges = self.with_field(edges, touch)
        # (a first contact that travels off the asperity and vanishes: none holds at first
        # touch, and the profile is pressed on)
        state = self.relax.run(edges, touch, final=False, births=False)
        if state.outcome is Outcome.NOT_CONVERGED and "no steady state" in state.message:
            # the first contact travels along the profile (a toughened trailing edge drags it):
            # it never settles before it is loaded, so it is loaded at once, to the target
            _record(self.eq.log, "no steady first contact", penetration=d0)
            state = self.relax.run(edges, target)
            if state.outcome is Outcome.FULL_CONTACT:
                return self.closed(state, None, target)
            return state
        if state.outcome is Outcome.NOT_CONVERGED and "without a valid field" in state.message:
            # the model has no field at any first contact (Maugis-Dugdale zones longer than
            # the contact whose equations have no solution there), or the first contact's
            # motion runs to where it has none: loaded at once, the target solved from the
            # first contact widened
            _record(self.eq.log, "no first contact", penetration=d0)
            return self.at_once(edges, target)
        if state.outcome is Outcome.NO_CONTACT:
            # no contact holds at first touch (its advancing edge, toughened less than the
            # adhesion pulls, recedes until the contact vanishes): the profile is pressed on
            _record(self.eq.log, "no contact at first touch", penetration=d0)
            return self.held(d0, target)
        if state.outcome is Outcome.FULL_CONTACT:   # the first contact settles
            return self.closed(state, None, target)
        if not state.converged:
            return state
        return self.climb(state, target)

    def pressed(self, edges, d0: float, target: Control) -> State:
        """A contact pressed on from its first touch at ``Δ̃ = d0`` where none settles there
        (adhesionless: a point; its equilibrium is unique, so the path only gives each solve a
        close start). The contact just past the first touch is solved from it, then the branch is
        followed to the target in steps that are halved where the solver fails."""
        first = Control.penetration_of(d0 + self.options.smallest)
        if not target.is_load and target.value <= first.value:
            return self.eq.solve(edges, target)
        state = self.eq.solve(edges, first)
        if state.outcome is Outcome.FULL_CONTACT:
            return self.closed(state, None, target)
        if not state.converged:
            return state
        return self.climb(state, target)

    def held(self, d0: float, target: Control) -> State:
        """The first contact that holds as the profile is pressed on past ``d0``, where no
        contact holds at first touch: at each penetration the edges' motion starts from the
        overlap of the undeformed profile with the solid; the penetration where a contact first
        holds (or closes) is located between path steps to the resolution, and the approach goes
        on from there."""
        opt, eq = self.options, self.eq

        def motion(depth: float) -> State:
            control = Control.penetration_of(depth)
            overlap = eq.checks.births_without_contact(control)
            if overlap is None:
                return State.no_contact()
            return self.relax.run(overlap, control, final=False, births=False)

        end = target.value if not target.is_load else 1.0
        lo, hi, landing = d0, None, None
        depth = d0
        while depth < end:
            depth = min(depth + opt.path_step, end)
            landing = motion(depth)
            if landing.outcome is not Outcome.NO_CONTACT:
                hi = depth
                break
            lo = depth
        if hi is None or landing is None:
            if target.is_load:
                return self.at_once(eq.checks.births_without_contact(
                    Control.penetration_of(end)), target)
            # the profile penetrates the solid at the target, yet no contact holds there: the
            # contacts born there travel and vanish
            return State(outcome=Outcome.NOT_CONVERGED, edges=np.zeros(0), change="reborn",
                         message="no contact holds up to the target penetration: the contacts "
                                 "born where the profile penetrates travel off and vanish, "
                                 "and are born again (no steady state at this control)")
        while hi - lo > opt.smallest:
            middle = 0.5 * (lo + hi)
            out = motion(middle)
            if out.outcome is Outcome.NO_CONTACT:
                lo = middle
            else:
                hi, landing = middle, out
        _record(eq.log, "first hold", penetration=hi)
        if landing.outcome is Outcome.FULL_CONTACT:
            return self.closed(landing, None, target)
        if not landing.converged:
            return landing
        return self.climb(landing, target)

    def at_once(self, edges, target: Control) -> State:
        """The target solved directly from the first contact ``edges`` widened 1, 4 and 16
        times (the first that converges). Each is one approach step, from the first contact to
        the target, on the budgets of the approach's steps (a solve that fails near a fold
        fails fast there, without the fallback march): where none converges, the solve says so
        instead of wandering (campaign seed 115, a Maugis-Dugdale contact with no field at
        first touch, ran past 600 s on the full budgets)."""
        x = np.asarray(edges, dtype=float)
        centre, half = 0.5 * (x[0] + x[1]), 0.5 * (x[1] - x[0])
        out = State(outcome=Outcome.NOT_CONVERGED, edges=x, message="no first contact")
        for factor in (1.0, 4.0, 16.0):
            w = min(factor * half, 0.45 * np.pi * 2)
            out = self.eq.solve(np.array([centre - w, centre + w]), target, use_fallback=False,
                                **self.relax.trial)
            if out.outcome in (Outcome.CONVERGED, Outcome.FULL_CONTACT):
                return out
        return out

    def with_field(self, edges, touch: Control):
        """The first contact the edges' motion starts from: the first-touch guess, widened by
        doublings while the adhesion model has no field there (a Maugis–Dugdale zone longer than
        the contact: its bounded-stress equations have no solution), at most to half the
        period."""
        x = np.asarray(edges, dtype=float)
        centre, half = 0.5 * (x[0] + x[1]), 0.5 * (x[1] - x[0])
        while half < np.pi / 2:
            r = self.eq.residual_at(x, touch)
            if r is not None and np.all(np.isfinite(r)):
                break
            half *= 2.0
            x = np.array([centre - half, centre + half])
        return x

    def continued(self, start: ContinueFrom, target: Control) -> State:
        """The branch through the equilibrium at ``start`` followed to ``target`` (its events
        located, as from first touch): the equilibrium is solved again at its own penetration
        (where it converges at once), then climbed from. Where it is not an equilibrium there,
        the solve says so."""
        at = Control.penetration_of(start.penetration)
        state = self.eq.solve(start.edges, at) if start.edges.size else self.run(at)
        if state.outcome is Outcome.FULL_CONTACT:
            return self.from_full_contact(target)
        if not state.converged or self.reached(state, target):
            return state
        return self.climb(state, target)

    def from_full_contact(self, target: Control) -> State:
        """Continue from a closed contact. With infinitely short-range adhesion a closed
        interface has no flaw to open from (the energy release of a vanishing gap is zero), so
        it stays closed at any load; without adhesion it stays closed while it carries no
        tension, and otherwise the contact is found afresh by the approach."""
        if self.path.closed.holds(target):
            return State.full_contact()
        return self.run(target)

    @staticmethod
    def value(state: State, kind: str) -> float:
        """The state's value of the controlled quantity."""
        fields = state.fields
        return float(fields.mean_pressure if kind == "mean_pressure" else fields.penetration)

    def closed(self, state: State, before: State | None, target: Control) -> State:
        """The contact closed over the period on the way to ``target``."""
        _record(self.eq.log, "closure", **({} if before is None
                                           else {target.kind: self.value(before, target.kind)}))
        if target.is_load and not self.path.closed.supports(target.value):
            start = before.edges if before is not None else state.edges
            return self.eq.solve(start, target)
        return state

    def climb(self, state: State, target: Control) -> State:
        """Follow the branch from ``state`` to ``target`` (:class:`~.climb.Climb`). A state
        already at the target (a first contact that snapped in at a zero-load target, a first
        hold at the target penetration) is a motion's landing, an intermediate state: it is
        solved to the target's tolerance from there."""
        if self.reached(state, target):
            return self.eq.solve(state.edges, target)
        return Climb(self, state, target).run()

    @staticmethod
    def reached(state: State, target: Control) -> bool:
        """Whether a converged state is at the target (a closure solved there)."""
        value = Approach.value(state, target.kind)
        return abs(value - target.value) <= 1e-9 * max(1.0, abs(target.value))

    def act(self, event: str, state: State, past: Control, target: Control) -> State:
        """The event's action, located between ``state`` and the control value ``past``:
        closure, or the edges' motion from ``state`` at ``past`` (the jump; after a birth, the
        new contact's growth), recorded as a jump when it leaves the branch."""
        log = self.eq.log
        if event == "closure":
            return self.closed(State.full_contact(), state, target)
        if event == "fold":
            _record(log, "fold", **{past.kind: self.value(state, past.kind)})
        landing = self.relax.run(state.edges, past, final=False)
        if landing.outcome is Outcome.FULL_CONTACT:
            return self.closed(landing, state, target)
        if landing.converged and (np.shape(landing.edges) != np.shape(state.edges)
                                  or moved(state.edges, landing.edges)
                                  > self.options.jumped):
            _record(log, "jump", area=float(np.sum(landing.fields.mesh.width)),
                    **{past.kind: past.value})
        return landing


__all__ = ["Approach", "ApproachOptions", "ContinueFrom"]
