"""The climb of an approach: a branch of equilibria followed in steps, its events located.

Steps in the controlled quantity start from the branch's tangent (:meth:`Path.predicted`) and
are solved at a fixed control with the contact set held; a step ends next to a fold or a birth
that the fields at its predicted start foresee within it (:meth:`Climb.looked_ahead`). A step
that meets an event (a fold, a contact-set change, closure, the target load passed) brackets
it: the next steps stay inside, aimed at the event's predicted place (:meth:`Climb.fold_ahead`,
:meth:`Climb.birth_ahead`), else at the bracket's middle, until the bracket is
:attr:`ApproachOptions.smallest` wide; then the event acts (:meth:`Approach.act
<.approach.Approach.act>`) from the state at its end.
"""
from __future__ import annotations

import numpy as np

from .path import STEP_REDUCTION
from .sets import Control, necks
from .state import Outcome, State


class Climb:
    """The climb of ``approach`` from ``state`` to ``target``: :meth:`run` returns the state
    there (or where the path ended)."""

    def __init__(self, approach, state: State, target: Control):
        self.approach = approach
        self.eq, self.path, self.options = approach.eq, approach.path, approach.options
        self.target = target
        # an adhesionless contact's load rises with the penetration (no folds): its steps are
        # in the penetration until the load passes the target, which is then solved between
        self.by_depth = by_depth = target.is_load and not self.eq.adhesive
        self.kind, self.load = (("penetration", False) if by_depth
                                else (target.kind, target.is_load))
        self.end = np.inf if by_depth else target.value
        self.below: State | None = None
        self.above: State | None = None              # the last step that passed the target
        self.state = state
        self.v = approach.value(state, self.kind)
        self.step = self.options.path_step           # in units of the penetration
        # |d(control)/dΔ̃| of the first contact's branch, at least 1: the unit of the steps,
        # fixed for the solve (the events are located to ApproachOptions.smallest of the control)
        self.unit = max(1.0, self.scale(state, self.load, 1.0))
        self.bracket: tuple | None = None  # (value past the event, kind, width)
        self.aim: float | None = None                # the event's predicted place inside it
        # a birth's bracket: the check point where the gap closes and the gap there, (value,
        # gap), at the bracket's far end and the branch's states since its start
        self.point = np.nan
        self.gaps: list[tuple[float, float]] = []

    def run(self) -> State:
        """Follow the branch to the target in steps of the controlled quantity."""
        target = self.target
        while True:
            state, v, bracket = self.state, self.v, self.bracket
            if self.by_depth and state.fields.mean_pressure >= target.value:
                return self.at_load(state, self.below, target)
            if np.isfinite(self.end) and abs(self.end - v) <= 1e-14 * max(1.0, abs(self.end)):
                return state
            if bracket is not None and abs(bracket[0] - v) <= bracket[2] * (1 + 1e-9):
                out = self.acted(bracket)
                if out is not None:
                    return out
                continue
            self.tried()

    def acted(self, bracket: tuple) -> State | None:
        """The action of the event located in ``bracket``: the state that ends the climb, or
        None when the climb goes on from the landing."""
        state, target = self.state, self.target
        if self.by_depth and bracket[1] in ("fold", "target"):
            # the target load located; or a step that failed near it (an adhesionless
            # contact has no folds: that failure is the solver's): the target load is
            # solved from the states around it
            return self.at_load(state, self.above if bracket[1] == "target" else self.below,
                                target)
        landing = self.approach.act(bracket[1], state, Control(self.kind, bracket[0]), target)
        if landing.outcome is not Outcome.CONVERGED or self.approach.reached(landing, target):
            return landing
        self.below, self.state, self.v = None, landing, bracket[0]
        self.step, self.bracket, self.aim = self.options.path_step, None, None
        return None

    def tried(self) -> None:
        """One step: on the branch (the climb moves on), or past an event (the event is
        bracketed, or the bracket narrowed)."""
        eq, path, opt = self.eq, self.path, self.options
        state, v, kind, load = self.state, self.v, self.kind, self.load
        v_next = self.next_value(v, self.step * self.unit, self.end, self.bracket, self.aim)
        tangent = path.tangent(state, load)
        if self.bracket is None and eq.adhesive:
            v_next = self.looked_ahead(state, v, v_next, tangent)
        start = path.predicted(state, v_next - v, load=load, tangent=tangent)
        last = v_next == self.end
        logged = len(eq.log.records)
        trial = eq.solve(start, Control(kind, v_next), use_fallback=False,
                         budget=path.budget, refine=last, polish=last,
                         probation=path.probation, pace=path.pace,
                         reduction=0.0 if last else STEP_REDUCTION,
                         changes=not eq.adhesive,    # (an adhesionless root is unique)
                         corrector=True)
        event = self.event(state, start, trial)
        if (event is None and self.by_depth and trial.fields.mean_pressure > self.target.value
                and abs(v_next - v) > opt.smallest):
            # the step passed the target load: locate it like an event, so that the load is
            # solved from a state close to it
            event, self.above = "target", trial
        if event is None:
            self.step = path.next_step(abs(v_next - v) / self.unit, start, state.edges,
                                       trial.edges)
            self.below, self.state, self.v = state, trial, v_next
            if self.bracket is not None and self.bracket[1] == "birth":
                self.sampled(trial, v_next)
                self.aim = self.birth_ahead(v_next, self.bracket[0])
            return
        del eq.log.records[logged:]     # (a step past an event is not on the path)
        if event == "fold" and not eq.adhesive and abs(v_next - v) > 2.0 * opt.smallest:
            # an adhesionless branch has no folds: the solver failed on a long step (many
            # births and merges at once), which a shorter one gets through
            self.step = 0.5 * abs(v_next - v) / self.unit
            return
        self.bracket, self.aim, self.gaps = (v_next, event, opt.smallest), None, []
        if event == "fold" and eq.adhesive:
            self.aim = self.fold_ahead(state, tangent, start, Control(kind, v_next), v)
        elif event == "birth" and trial.fields is not None:
            # the gap is followed at the check point where the held set penetrates deepest
            xs, gap = eq.checks.gap_outside(trial.fields)
            self.point, self.gaps = xs[int(np.argmin(gap))], [(v_next, float(np.min(gap)))]
            for sample, at in ((self.below, None), (state, v)):
                if sample is not None:
                    self.sampled(sample, self.value_of(sample) if at is None else at)
            self.aim = self.birth_ahead(v, v_next)

    def looked_ahead(self, state: State, v: float, v_next: float, tangent) -> float:
        """The end of the step from ``state`` (at ``v``) towards ``v_next``, shortened where an
        event is predicted within it. The fields at the step's predicted start (the corrector's
        first evaluation, which its solve then takes from the shared ones) give where the gap
        outside the contacts closes (a birth; :meth:`Checks.closing <.checks.Checks.closing>`)
        and where the branch folds (:meth:`Path.fold_within <.path.Path.fold_within>`); the
        step ends a quarter of the resolution short of the earlier, or as far past it once it
        lies within half the resolution, so that an event predicted well is bracketed by two
        steps instead of a failed long one and its halvings."""
        change, width = v_next - v, self.options.smallest
        if tangent is None or state.fields is None or abs(change) <= width:
            return v_next
        control = Control(self.kind, v_next)
        start = self.path.predicted(state, change, load=self.load, tangent=tangent)
        fields = self.eq.fields_at(start, control)
        if fields is None:
            return v_next
        places = [self.eq.checks.closing(state.fields, fields),
                  merging(state.edges, tangent * change)]
        fold = self.path.fold_within(state, tangent, start, control, change)
        if fold is not None:
            places.append(fold[0] / abs(change))
        place = min((p for p in places if p is not None and 0.0 <= p < 1.0), default=None)
        if place is None:
            return v_next
        distance, sign = place * abs(change), float(np.sign(change))
        return v + sign * (distance + (0.25 if distance <= 0.5 * width else -0.25) * width)

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

    @staticmethod
    def next_value(v: float, step: float, end: float, bracket: tuple | None,
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

    def value_of(self, state: State) -> float:
        """The state's value of the climb's control."""
        return self.approach.value(state, self.kind)

    def sampled(self, state: State, v: float) -> None:
        """The gap of ``state`` (at ``v``) at the birth's check point, kept (where that point
        lies outside its contacts)."""
        if state.fields is None:
            return
        _, gap = self.eq.checks.gap_at(state.fields, [self.point])
        if gap.size and np.isfinite(gap[0]):
            self.gaps.append((v, float(gap[0])))

    def birth_ahead(self, v: float, past: float) -> float | None:
        """Where a contact is born between ``v`` and the bracket's far end ``past``: the root of
        the gap at the birth's check point, of the parabola through its samples at the far end
        and the branch's last two states (else of the secant through the state's and the far
        end's). It converges superlinearly where the false position of the bracket's ends
        converges linearly on a curved gap (four to six steps a birth on the rough profile).
        None without a sample of each sign."""
        # the far end (the first sample) and the branch's last two states
        samples = sorted(self.gaps[:1] + self.gaps[1:][-2:], key=lambda s: s[0])
        values = np.array([s[0] for s in samples])
        gaps = np.array([s[1] for s in samples])
        if not (np.any(gaps > 0) and np.any(gaps < 0)):
            return None
        lo, hi = min(v, past), max(v, past)
        if len(samples) == 3 and len(set(values)) == 3:
            roots = np.roots(np.polyfit(values - v, gaps, 2)) + v
            roots = roots[np.isreal(roots)].real
            inside = roots[(roots > lo) & (roots < hi)]
            if inside.size == 1:
                return float(inside[0])
        k = int(np.argmin(np.abs(values - v)))      # the state, and the far end
        i = int(np.argmin(np.abs(values - past)))
        if gaps[k] <= 0 or gaps[i] >= 0:
            return None
        return float(values[k] + (values[i] - values[k]) * gaps[k] / (gaps[k] - gaps[i]))

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
                and moved(start, trial.edges) > self.options.jumped):
            return "fold"
        return None

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


def merging(edges, move) -> float | None:
    """The fraction of the move ``move`` of ``edges`` (a step along the branch's tangent) at
    which two neighbouring contacts meet, the earliest; None where no neck closes within it."""
    if np.size(edges) < 4 or np.shape(move) != np.shape(edges):
        return None
    width, closing = necks(edges, move)
    meets = closing > 0.0
    if not np.any(meets):
        return None
    place = float(np.min(width[meets] / closing[meets]))
    return place if place < 1.0 else None


def moved(start, edges) -> float:
    """The largest move from ``start`` to ``edges``, in half-widths of its contact (0 when
    the contact sets differ)."""
    start, edges = np.asarray(start, dtype=float), np.asarray(edges, dtype=float)
    if start.shape != edges.shape or not edges.size:
        return 0.0
    half = np.repeat(0.5 * (edges[1::2] - edges[0::2]), 2)
    return float(np.max(np.abs(edges - start) / half))


__all__ = ["Climb", "merging", "moved"]
