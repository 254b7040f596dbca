"""The approach history: quasi-static loading from first touch to the target, with events.

The contact is pressed on at constant speed, slowly: its state follows a branch of equilibria
in the penetration ``Δ̃``, from the first contact at the highest peak to the target penetration,
or under load control to the target load. A continuation follows the branch:

* **steps** in the controlled quantity start from the branch's tangent (:meth:`Path.predicted`)
  and are solved at a fixed control with the contact set held; a step is accepted when its
  corrector stays within :attr:`jumped <ApproachOptions.jumped>` half-widths of the prediction
  and the contact set stays as it was, and the next step follows from the corrector's distance
  (:meth:`Path.next_step`).
* **events** are what ends the branch within a step: a *fold* (no equilibrium near the
  prediction however short the step; under load control also the *load peak*, past which the
  branch is unstable), a *birth* (the profile penetrates the solid outside the contacts), a
  *merge*, *detachment* or *split* of contacts, *closure* over the period, and the *target*.
  A step that meets one is shortened, towards the fold the branch's curvature predicts
  (:meth:`fold_ahead`) or the birth the smallest gap's secant predicts (:meth:`birth_ahead`),
  else by halves, until the event lies within :attr:`resolution <ApproachOptions.resolution>`
  of the path step.
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

from .path import STEP_REDUCTION, Path
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
        self.relax = Relaxation(path.eq, path.closed, tolerance=options.relax_tolerance)

    def run(self, target: Control) -> State:
        if not target.is_load and target.value <= 0:
            # approached from afar, the profile first touches at Δ̃ = 0 (adhesion acts only on
            # contact): no contact yet
            return State.no_contact()
        d0, edges = first_touch(self.eq.prep.shape)
        if not self.eq.adhesive:
            return self.pressed(edges, d0, target)
        touch = Control.penetration_of(d0)
        edges = self.with_field(edges, touch)
        state = self.relax.run(edges, touch, final=False)
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
            # the contact whose equations have no solution there): loaded at once, the target
            # solved from the first contact widened
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
            return self.relax.run(overlap, control, final=False)

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
            return State.no_contact() if not target.is_load else self.at_once(
                eq.checks.births_without_contact(Control.penetration_of(end)), target)
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
        if not landing.converged or self.reached(landing, target):
            return landing
        return self.climb(landing, target)

    def at_once(self, edges, target: Control) -> State:
        """The target solved directly from the first contact ``edges`` widened 1, 4 and 16
        times (the first that converges)."""
        x = np.asarray(edges, dtype=float)
        centre, half = 0.5 * (x[0] + x[1]), 0.5 * (x[1] - x[0])
        out = State(outcome=Outcome.NOT_CONVERGED, edges=x, message="no first contact")
        for factor in (1.0, 4.0, 16.0):
            w = min(factor * half, 0.45 * np.pi * 2)
            out = self.eq.solve(np.array([centre - w, centre + w]), target)
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
        """Follow the branch from ``state`` to ``target`` in steps of the controlled quantity.

        After a step that meets an event, the event lies between the state and that step's
        value (``bracket``): the following steps stay inside, aimed just short of the fold
        that the failed step's start predicts (:meth:`fold_ahead`), else at the middle, until
        the bracket is :attr:`ApproachOptions.smallest` wide; then the event acts from the
        state at the bracket's end."""
        eq, path, opt = self.eq, self.path, self.options
        # an adhesionless contact's load rises with the penetration (no folds): its steps are
        # in the penetration until the load passes the target, which is then solved between
        by_depth = target.is_load and not eq.adhesive
        kind, load = ("penetration", False) if by_depth else (target.kind, target.is_load)
        end = np.inf if by_depth else target.value
        below: State | None = None
        above: State | None = None                    # the last step that passed the target
        v = self.value(state, kind)
        step = opt.path_step                          # in units of the penetration
        # |d(control)/dΔ̃| of the first contact's branch, at least 1: the unit of the steps,
        # fixed for the solve (the events are located to ApproachOptions.smallest of the control)
        scale = max(1.0, self.scale(state, load, 1.0))
        bracket: tuple | None = None   # (value past the event, kind, width, gap there)
        aim: float | None = None                      # the fold predicted inside the bracket
        while True:
            if by_depth and state.fields.mean_pressure >= target.value:
                return self.at_load(state, below, target)
            if np.isfinite(end) and abs(end - v) <= 1e-14 * max(1.0, abs(end)):
                return state
            if bracket is not None and abs(bracket[0] - v) <= bracket[2] * (1 + 1e-9):
                if by_depth and bracket[1] in ("fold", "target"):
                    # the target load located; or a step that failed near it (an adhesionless
                    # contact has no folds: that failure is the solver's): the target load is
                    # solved from the states around it
                    return self.at_load(state, above if bracket[1] == "target" else below,
                                        target)
                landing = self.act(bracket[1], state, Control(kind, bracket[0]), target)
                if landing.outcome is not Outcome.CONVERGED or self.reached(landing, target):
                    return landing
                below, state, v = None, landing, bracket[0]
                step, bracket, aim = opt.path_step, None, None
                continue
            v_next = self.next_value(v, step * scale, end, bracket, aim)
            tangent = path.tangent(state, load)
            start = path.predicted(state, v_next - v, load=load, tangent=tangent)
            last = v_next == end
            logged = len(eq.log.records)
            trial = eq.solve(start, Control(kind, v_next), use_fallback=False,
                             budget=path.budget, refine=last, polish=last,
                             probation=path.probation, pace=path.pace,
                             reduction=0.0 if last else STEP_REDUCTION,
                             changes=not eq.adhesive)    # (an adhesionless root is unique)
            event = self.event(state, start, trial)
            if (event is None and by_depth and trial.fields.mean_pressure > target.value
                    and abs(v_next - v) > opt.smallest):
                # the step passed the target load: locate it like an event, so that the load is
                # solved from a state close to it
                event, above = "target", trial
            if event is None:
                step = path.next_step(abs(v_next - v) / scale, start, state.edges, trial.edges)
                below, state, v = state, trial, v_next
                if bracket is not None and bracket[1] == "birth":
                    aim = self.birth_ahead(state, v, bracket)
                continue
            del eq.log.records[logged:]     # (a step past an event is not on the path)
            if event == "fold" and not eq.adhesive and abs(v_next - v) > 2.0 * opt.smallest:
                # an adhesionless branch has no folds: the solver failed on a long step (many
                # births and merges at once), which a shorter one gets through
                step = 0.5 * abs(v_next - v) / scale
                continue
            bracket, aim = (v_next, event, opt.smallest, trial.gap), None
            if event == "fold" and eq.adhesive:
                aim = self.fold_ahead(state, tangent, start, Control(kind, v_next), v)
            elif event == "birth":
                aim = self.birth_ahead(state, v, bracket)

    @staticmethod
    def scale(state: State, load: bool, previous: float) -> float:
        """``|d(control)/dΔ̃|`` along the branch at ``state``: 1 in penetration control, the
        branch's stiffness ``|dp̃∞/dΔ̃|`` in load control (from the state's derivatives), so that
        a step of the load moves the contact about as far as the same step of the penetration
        would (a glassy solid's loads are β times larger). ``previous`` where the derivatives
        are missing or the branch is flat."""
        if not load:
            return 1.0
        system = state.system
        if system is None or np.size(state.edges) == 0:
            return previous
        d = system.derivatives(np.asarray(state.edges, dtype=float))
        if d is None:
            return previous
        try:
            t = -np.linalg.solve(d.jacobian, d.control)
        except np.linalg.LinAlgError:
            return previous
        px, pd = d.pressure[:-1], d.pressure[-1]
        if system.control.is_load:          # dx/dp̃∞: dΔ̃/dp̃∞ = (1 - ∂p/∂x·t)/(∂p/∂Δ̃)
            k = pd / (1.0 - float(px @ t)) if 1.0 != float(px @ t) else np.inf
        else:                                # dx/dΔ̃: dp̃∞/dΔ̃ = ∂p/∂x·t + ∂p/∂Δ̃
            k = float(px @ t) + pd
        k = abs(float(k))
        return k if np.isfinite(k) and k > 1e-3 * previous else previous

    def reached(self, state: State, target: Control) -> bool:
        """Whether a converged state is at the target (a closure solved there)."""
        value = self.value(state, target.kind)
        return abs(value - target.value) <= 1e-9 * max(1.0, abs(target.value))

    def at_load(self, state: State, below: State | None, target: Control) -> State:
        """The target load, passed by the last penetration step (from ``below`` to ``state``):
        solved from the closer of the two."""
        eq = self.eq
        starts = [state] if below is None else sorted(
            (state, below), key=lambda s: abs(float(s.fields.mean_pressure) - target.value))
        out = State(outcome=Outcome.NOT_CONVERGED, edges=state.edges, message="")
        for start in starts:
            change = target.value - float(start.fields.mean_pressure)
            for guess in (self.path.predicted(start, change, load=True), start.edges):
                out = eq.solve(guess, target)
                if out.outcome in (Outcome.CONVERGED, Outcome.FULL_CONTACT):
                    return out
        return out

    def next_value(self, v: float, step: float, end: float, bracket: tuple | None,
                   aim: float | None) -> float:
        """The next step's value: a step towards ``end``; inside the bracket of an event, just
        short of its predicted place ``aim``, then just past it (so that a good prediction
        locates the event in two steps), else at the bracket's middle."""
        if bracket is None:
            return v + float(np.clip(end - v, -step, step))
        past, width = bracket[0], bracket[2]
        if aim is not None:
            sign = np.sign(past - v)
            for value in (aim - 0.5 * sign * width, aim + 0.5 * sign * width):
                if min(sign * (value - v), sign * (past - value)) > 0.25 * width:
                    return float(value)
        return 0.5 * (v + past)

    def birth_ahead(self, state: State, v: float, bracket: tuple) -> float | None:
        """Where a contact is born inside ``bracket``: the secant root of the smallest gap
        outside the contacts, from ``state`` (at ``v``, no penetration) to the bracket's end
        (where the held contact set penetrates); None without both gaps."""
        past, gap_past = bracket[0], bracket[3]
        if state.fields is None or not gap_past < 0.0:
            return None
        _, gap = self.eq.checks.gap_outside(state.fields)
        here = float(np.min(gap)) if gap.size else np.nan
        if not here > 0.0:
            return None
        return v + (past - v) * here / (here - gap_past)

    def event(self, state: State, start, trial: State) -> str | None:
        """What ends the branch within a step to ``trial`` (None: the step is on the branch).

        Besides a fold and closure, an adhesive contact's set changes along the branch (a
        birth, a merge, a detachment, a split: the trial's :attr:`State.change`, which the
        trial's solve did not make). The state it lands in depends on where the set changes (a
        spot born later is born into a deformed neighbourhood): like a fold, the change is
        located to the resolution and made there, so the state reached does not depend on the
        step."""
        if trial.outcome is Outcome.FULL_CONTACT:
            return "closure"
        if trial.change:
            return trial.change
        if trial.outcome is not Outcome.CONVERGED:
            return "fold"
        if (self.eq.adhesive and np.shape(trial.edges) == np.shape(state.edges)
                and self._moved(start, trial.edges) > self.options.jumped):
            return "fold"
        return None

    @staticmethod
    def _moved(start, edges) -> float:
        start, edges = np.asarray(start, dtype=float), np.asarray(edges, dtype=float)
        if start.shape != edges.shape or not edges.size:
            return 0.0
        half = np.repeat(0.5 * (edges[1::2] - edges[0::2]), 2)
        return float(np.max(np.abs(edges - start) / half))

    def fold_ahead(self, state: State, tangent, start, control: Control,
                   v: float) -> float | None:
        """Where the branch through ``state`` (at ``v``) folds within the failed step to
        ``control`` that started from ``start = x + h·t`` along the tangent ``t``, or None.

        The tangent cancels the residual's linear part, so at the start the residual is
        ``½h²·r''``, and the branch's curvature is ``x'' = -J⁻¹r''`` (one residual evaluation
        and the state's Jacobian). On a parabola ``v* - v = a(x - x*)²`` an edge's
        ``x'/(2x'')`` is its distance to the fold; the earliest fold within the step is taken.
        None when the start was scaled down (:meth:`Path.predicted`), no edge folds within the
        step, or the derivatives are missing."""
        change = control.value - v
        ahead = self.path.fold_within(state, tangent, start, control, change)
        if ahead is None or not ahead[0] < abs(change):
            return None
        return v + float(np.sign(change)) * ahead[0]

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
                                  or self._moved(state.edges, landing.edges)
                                  > self.options.jumped):
            _record(log, "jump", area=float(np.sum(landing.fields.mesh.width)),
                    **{past.kind: past.value})
        return landing


__all__ = ["Approach", "ApproachOptions"]
