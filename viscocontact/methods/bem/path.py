"""Paths to an equilibrium: the approach from first touch, jumps past folds, and the search for
the root that is stable under load control.

Without an initial contact set a solve follows the approach path: first touch at the highest
peak, then quasi-static loading in steps of penetration up to the target (load control switches
to the target load once it is bracketed), so that the same scene always gives the same answer.
"""
from __future__ import annotations

import numpy as np

from ..._stepping import march
from ...contact.topology import TWO_PI, repair
from .sets import MIN_GAP, MIN_WIDTH, Control, first_touch
from .state import Outcome, State

#: Residual evaluations allowed to one solver call of an approach step (a converging step takes
#: 10-30; one that fails near a fold ran to 300 before the step was halved).
APPROACH_BUDGET = 80
#: ... with analytic Jacobians and the predicted start (a converging step takes 3-10).
APPROACH_BUDGET_ANALYTIC = 15
#: Residual evaluations after its first within which the solve of an adhesive approach step
#: that can still be halved must have reduced ``max|r|`` a hundredfold
#: (:attr:`Tolerances.probation`; with analytic Jacobians and a predicted start). On the thesis
#: rough profile (seeds 11-13 at p̃∞ = 0.1, seed 0 at p̃∞ = 0.6: 155 such solves) every
#: converging one met it but one, which had taken 12 evaluations; the 45 failing ones had run to
#: the budget of 15 at residuals of 1e-3-1e-1, oscillating near a fold (a neck about to close).
#: Adhesionless steps do not get it: one that starts far from its root (after a birth or a
#: split) progresses steadily but slowly while its steps are bounded, and the rule cost the rough
#: adhesionless solve at ζ = 1e-2 3.7 times the evaluations. The solve that lands a fold's
#: crossing (:meth:`Path.cross`) gets it too, and hands over to the fallback march instead.
APPROACH_PROBATION = 4
#: Earlier checkpoints of that probation (:attr:`Tolerances.pace`): after one evaluation past
#: the first the best ``max|r|`` must be below 0.9 of the first, after two below 0.6. On the
#: crowded corners (seeds 0-2) and the rough point (seeds 11-13), 372 solves of adhesive
#: approach steps: the 307 that converged had at most 0.81 and 0.50 there, the 65 that failed a
#: median of 0.93 and 0.91; the checkpoints would stop 57 of these one to three evaluations
#: sooner (160 evaluations) and no converging one. They apply to a step's first solver call
#: (:meth:`Equilibrium.solve`), and not on the smallest step, whose failure hands the point it
#: reached on to the fallback march: 15-47 evaluations fewer a crowded corner
#: (``benchmarks/results`` §16).
APPROACH_PACE = (0.9, 0.6)
#: The corrector of an intermediate approach step (not the last, at the target) converges
#: once ``max|r|`` is this fraction of its value at the predicted start, or at the tolerance
#: (:meth:`Equilibrium.solve`'s ``reduction``): the state then lies within a ten-thousandth of
#: the predictor's error from the branch, while the next step's prediction errs by about
#: :data:`PREDICTOR_ERROR` of the half-widths. It saves the last one or two of the three to
#: five evaluations of a converging step (``benchmarks/results`` §16).
STEP_REDUCTION = 1e-4
#: Growth per converged step of the largest step allowed after a failed one on an adhesive
#: approach (:meth:`Path.approach`). Adhesionless approaches keep growing as before: with the
#: ceiling, nonlinear CG on the thesis rough profile at ζ = 1e-2 reached its final load on
#: another path, where a contact had to be refined (2103 evaluations instead of 962, Ã 3e-7 off
#: Broyden's; ``tests/integration/test_rough.py``).
CEILING_GROWTH = 1.25
#: Smallest step of :meth:`Path.in_load_steps`, as a fraction of the way to the target load,
#: and the most solves it makes.
LOAD_STEP_SMALLEST = 1.0 / 64.0
LOAD_STEP_SOLVES = 24
#: Largest correction of a predicted edge, relative to its contact's half-width, that the step
#: control aims at (:meth:`Path.next_step`).
PREDICTOR_ERROR = 0.02
#: A crossing of a fold (:meth:`Path.cross`) lands this fraction of the path step past the fold's
#: estimated penetration (:meth:`Path.fold_ahead`), so that an estimate a little short of the
#: fold still crosses it.
FOLD_MARGIN = 1.0 / 64.0
#: First and largest move of the leading edge along the tangent in a crossing, in half-widths of
#: its contact (the move doubles from the first).
CROSS_FIRST = 1.0 / 16.0
CROSS_REACH = 8.0
#: A converged approach step whose corrector moved an edge by more than this many half-widths of
#: its contact from the prediction has jumped past a fold (the fallback march of the smallest
#: step): the ceiling left by the failures before it is lifted.
JUMPED = 0.25
#: How far the load must have fallen past its peak, relative to the target's distance above the
#: peak, for :meth:`Path.closed_past_peak` to take the peak for the branch's load maximum.
PEAK_FALL = 0.1


class Path:
    """The approach path and its companions for one solve.

    Parameters
    ----------
    equilibrium : Equilibrium
    closed : ClosedContact
    path_step : float
        Largest penetration step of the approach (:attr:`Discretization.path_step`).
    predict : bool
        Start each step's solve from the state predicted along the tangent of the last one
        (:meth:`predicted`; needs analytic derivatives), else from the last state's edges.
    """

    def __init__(self, equilibrium, closed, path_step: float, predict: bool = True):
        self.eq = equilibrium
        self.closed = closed
        self.path_step = path_step
        self.predict = predict
        self.log = equilibrium.log

    def approach(self, target: Control) -> State:
        """The equilibrium at ``target`` reached from first touch."""
        eq, log = self.eq, self.log
        if not target.is_load and target.value <= 0:
            # approached from afar, the profile first touches at Δ̃ = 0 (adhesion acts only on
            # contact), so no contact exists yet; only a retraction path reaches Δ̃ <= 0 in contact
            return State.no_contact()
        d0, edges = first_touch(eq.prep.shape)
        touch = Control.penetration_of(d0)
        # with analytic Jacobians a first contact that has an equilibrium near the first-touch
        # guess converges in 5-15 evaluations; one that jumps open ran 200 iterations before
        first = ({"budget": APPROACH_BUDGET, "polish": False} if self.quick
                 else {"polish": False})
        if self.wants_to_grow(edges, touch):
            # adhesion pulls the first contact open at once (a JKR-like jump): look for the state
            # it lands on instead of asking an equilibrium solver for one that does not exist
            jump = self.snap(edges, touch, polish=False)
            if jump is not None:
                log.event("first contact jumped")
                out = jump
            else:
                out = eq.solve(edges, touch, **first)
        else:
            out = eq.solve(edges, touch, **first)
        if out.outcome is Outcome.NOT_CONVERGED:
            # adhesion can make the first contact jump to a larger size at once
            jump = self.snap(edges, touch, polish=False)
            if jump is not None:
                log.event("first contact jumped")
                out = jump
        if out.outcome is Outcome.NOT_CONVERGED and target.is_load:
            direct = self.at_target_from_first_touch(edges, target)
            if direct is not None:
                return direct
        if out.outcome is not Outcome.CONVERGED:
            return out
        state = out
        d_prev = d0
        d_end = None if target.is_load else target.value
        step = self.path_step
        peak = (-np.inf, d0)              # the largest load along the branch, and where
        below = None                      # the converged state before the last one
        ceiling = np.inf                  # largest step allowed since the last failed one
        trend = None                      # (Δ̃, edge speed, edges) of the last state
        fold = None                       # the fold estimated ahead of the current state
        fold_edge = None                  # the edge that folds there (None: the fastest)
        failed = None                     # the penetration of the last failed step
        fresh = True                      # the current state is new (its trend not taken)
        crossed = False                   # a crossing was tried from the current state
        leap = False                      # the current state was reached past a fold
        while True:
            fields = state.fields
            if fields.mean_pressure > peak[0]:
                peak = (fields.mean_pressure, d_prev)
            if d_end is None and fields.mean_pressure >= target.value:
                if (leap and below is not None and below.fields is not None
                        and below.fields.mean_pressure < target.value):
                    # the load rose past the target across a fold: the branch before it may
                    # reach the target first (in load control the contact stops there)
                    begin = self.predicted(below, target.value - below.fields.mean_pressure,
                                           load=True)
                    early = eq.solve(begin, target)
                    if (early.outcome is Outcome.CONVERGED
                            and not self.jumped(begin, below.edges, early.edges)):
                        log.event("the target load solved from the state before the last step, "
                                  "which passed a fold")
                        return early
                final = eq.solve(self.predicted(state, target.value - fields.mean_pressure,
                                                load=True), target)
                if final.outcome is Outcome.NOT_CONVERGED:
                    jump = self.snap(state.edges, target)
                    if jump is not None:
                        log.event("contact jumped at the target load")
                        return jump
                if final.outcome is Outcome.NOT_CONVERGED and below is not None:
                    # the last step overshot the target load to edges where the model has no
                    # field at the target (Maugis-Dugdale: no zone lengths bound the stress
                    # under the target load at edges wider than its equilibrium); the state
                    # below the target brackets it from the other side
                    retry = eq.solve(below.edges, target)
                    if retry.outcome is Outcome.CONVERGED:
                        log.event("the target load solved from the last state below it")
                        return retry
                return final
            if d_end is not None and abs(d_end - d_prev) <= 1e-15:
                return state
            if d_end is None:
                d_next = d_prev + step
            else:
                d_next = d_prev + np.clip(d_end - d_prev, -step, step)
            # a fold ahead (the edges' speed along the branch grows as 1/√(Δ̃* - Δ̃)): cross it
            # instead of failing at it and halving the step down to it
            if fresh:
                fresh = False
                tangent = self.tangent(state, False) if self.quick and eq.adhesive else None
                speed = self.edge_speed(state, tangent)
                sample = (d_prev, speed, np.size(state.edges))
                fold_edge, failed = None, None
                fold = (self.fold_ahead(trend[:2], sample[:2])
                        if trend is not None and trend[2] == sample[2] else None)
                trend = None if speed is None else sample
            if fold is not None and d_prev < fold < d_next and not crossed:
                crossed = True
                d_cross = min(d_next, fold + FOLD_MARGIN * self.path_step)
                jump = self.cross(state, tangent, Control.penetration_of(d_cross),
                                  polish=d_cross == d_end, lead=fold_edge)
                if jump is None and failed == d_next:
                    # the fold estimated after a failed step was not crossed: halve the step
                    # rather than fail at the same penetration again
                    step = self.halved(step)
                    ceiling = step
                    continue
                if jump is not None:
                    if jump.outcome is Outcome.FULL_CONTACT:
                        if d_end is None and not self.closed.supports(target.value):
                            return eq.solve(state.edges, target)   # as after a closing step
                        return jump
                    if self.jumped(state.edges + tangent * (d_cross - d_prev), state.edges,
                                   jump.edges):
                        # a new branch: its own trend; its steps grow from the one that
                        # led to the fold
                        log.event(f"approach branch folds near penetration {fold:.6g}; its "
                                  f"fastest edge jumped at {d_cross:.6g}")
                        trend = None
                    below = state
                    state, d_prev = jump, d_cross
                    ceiling, fresh, crossed, leap = np.inf, True, False, True
                    continue
            # the fallback march only once the step is small enough for a fold to be likely
            last = step < self.path_step / 16
            start = self.predicted(state, d_next - d_prev, tangent=tangent)
            trial = eq.solve(start, Control.penetration_of(d_next), use_fallback=last,
                             budget=self.budget, fallback_budget=APPROACH_BUDGET,
                             refine=d_next == d_end, polish=d_next == d_end,
                             probation=self.probation, pace=() if last else self.pace,
                             reduction=0.0 if d_next == d_end else STEP_REDUCTION)
            if trial.outcome is Outcome.CONVERGED:
                leap = last
                if eq.adhesive and self.jumped(start, state.edges, trial.edges):
                    # the fallback march crossed a fold: the failures before it say nothing
                    # of the landing branch, whose steps grow from this one
                    ceiling, trend, leap = np.inf, None, True
                else:
                    # a step size that failed is not tried again at once: the steps after a
                    # failure grow from the halved one by CEILING_GROWTH at most (the
                    # penetration that failed can be tried again, from a state closer to it)
                    step = min(self.next_step(step, start, state.edges, trial.edges), ceiling)
                    ceiling *= CEILING_GROWTH
                below = state
                state, d_prev, fresh, crossed = trial, d_next, True, False
                continue
            if trial.outcome is Outcome.FULL_CONTACT:
                if d_end is None and not self.closed.supports(target.value):
                    return eq.solve(state.edges, target)   # finish in load control
                return trial
            if step < self.path_step / 16:
                # the branch ends (a fold): the contact jumps; look for the state it lands on
                jump = self.snap(state.edges, Control.penetration_of(d_next),
                                 polish=d_next == d_end)
                if jump is None and d_end is None:
                    return self.past_branch_end(state, d_prev, peak, target)
                if jump is None:
                    return trial
                if jump.outcome is Outcome.FULL_CONTACT:
                    return jump
                log.event(f"contact jumped at penetration {d_next:.6g}")
                below, leap = state, True
                state, d_prev = jump, d_next
                step, ceiling, trend, fresh, crossed = self.path_step, np.inf, None, True, False
                continue
            if eq.adhesive and not crossed and (fold is None or not d_prev < fold < d_next):
                ahead = self.fold_from_start(state, tangent, start, d_prev, d_next - d_prev)
                if (ahead is not None and d_prev < ahead[0] < d_next
                        and (d_end is not None or not self.load_before(state, ahead[0], target))):
                    # the failed step's start says where the branch folds (before the target
                    # load): cross there instead of halving the step down to it
                    fold, fold_edge, failed = ahead[0], ahead[1], d_next
                    log.event(f"approach step to {d_next:.6g} failed; its start's residual puts "
                              f"the branch's fold at {fold:.6g}")
                    continue
            step = self.halved(step)
            if eq.adhesive:
                ceiling = step

    def past_branch_end(self, end: State, penetration: float, peak: tuple[float, float],
                        target: Control) -> State:
        """The equilibrium at the target load when the approach branch ends (a fold at
        ``penetration``, the last converged state ``end``) below the target load and no contact
        set lands past the fold in penetration control (:meth:`snap`). Tried in turn:

        1. the target load solved from ``end`` in load control;
        2. full contact, when the branch's load peaked (``peak``) below the target and has
           fallen since (:meth:`closed_past_peak`);
        3. the target load reached from ``end`` in steps of load (:meth:`in_load_steps`);

        else the failure of the first.
        """
        self.log.event(f"the approach branch ends at penetration {penetration:.6g} below the "
                       "target load; solved in load control from there")
        final = self.eq.solve(end.edges, target)
        if final.outcome is not Outcome.NOT_CONVERGED:
            return final
        return (self.closed_past_peak(peak, end, target) or self.in_load_steps(end, target)
                or final)

    def in_load_steps(self, state: State, target: Control) -> State | None:
        """The equilibrium at the target load reached from ``state`` in steps of load, or None.

        Where the approach branch ends below the target load and the solve at the target from
        its last state fails, the load is raised from the last state's towards the target: a
        step that converges hands its contact set on and the next one doubles (up to the rest
        of the way), one that fails is halved, down to :data:`LOAD_STEP_SMALLEST` of the way
        (at most :data:`LOAD_STEP_SOLVES` solves). Full contact on the way is the answer if the
        closed interface holds the target (:meth:`ClosedContact.supports`).
        """
        if state.fields is None:
            return None
        start = float(state.fields.mean_pressure)
        current, closed, stopped = state, None, False

        def attempt(to: float) -> bool | None:
            nonlocal current, closed, stopped
            trial = self.eq.solve(current.edges,
                                  Control.load_of(start + to * (target.value - start)))
            if trial.outcome is Outcome.FULL_CONTACT:
                stopped = True
                closed = trial if self.closed.supports(target.value) else None
                return None
            if trial.outcome is not Outcome.CONVERGED:
                return False
            current = trial
            return True

        done, solves = march(attempt, smallest=LOAD_STEP_SMALLEST, most=LOAD_STEP_SOLVES)
        if stopped:
            return closed
        if not done:
            self.log.event(f"no steps of load from p̃∞ = {start:.6g} reach the target ({solves} "
                           "solves)")
            return None
        self.log.event(f"the target load reached from there in {solves} steps of load")
        return current

    def closed_past_peak(self, peak: tuple[float, float], end: State,
                         target: Control) -> State | None:
        """Full contact when the approach branch under a target load has ended (at ``end``)
        without an equilibrium at the target (or None): an adhesive contact on a profile with
        one asperity per period, whose load along the branch peaked (``peak``: ``(p̃∞, Δ̃)``)
        below the target and then fell by at least :data:`PEAK_FALL` of the target's distance
        from it, and a closed interface that holds the target (:meth:`ClosedContact.supports`).

        Past the largest load of its branch (where the load falls as the contact grows) a
        contact under load control has no equilibrium on that branch: it grows unstably, and
        with one asperity per period no other contact can be born, so it closes over the
        period — as when a branch ends in a fold (:meth:`snap`). The snap cannot always follow
        it there: with Maugis-Dugdale zones the growing contact reaches contact sets the model
        does not evaluate (zones that meet across the period, or no zone lengths that bound the
        stress) before it closes (sinusoid Λ̃ = 0.1, Γ̃ = 0.05, λ = 5, β = 10, ζ = 1: the load
        peaks at p̃∞ = -0.19 and falls to -0.86 before the branch ends; a least-squares solve of
        edges and zones together finds no partial equilibrium at p̃∞ = 0.1;
        ``docs/cohesive.md``). A branch that ends while its load still rises, or on a profile
        with several asperities (or whose maxima are unknown), stays a failure. The event log
        says which load the branch peaked at.
        """
        shape = self.eq.prep.shape
        if (not self.eq.adhesive or not peak[0] < target.value
                or len(shape.maxima) != 1 or end.fields is None
                or not end.fields.mean_pressure
                <= peak[0] - PEAK_FALL * (target.value - peak[0])
                or not self.closed.supports(target.value)):
            return None
        self.log.event(f"no equilibrium at the target load on the approach branch: its load "
                       f"peaks at {peak[0]:.4g} (penetration {peak[1]:.4g}); the contact grows "
                       "past the branch's end and closes over the period (the closed interface's "
                       f"largest tension {self.closed.largest_tension(target.value):.3g} is "
                       "within its strength)")
        return State.full_contact(message="contact closed over the period: the load along the "
                                          f"approach branch peaks at {peak[0]:.4g}, below the "
                                          "target")

    def next_step(self, step: float, predicted, before, after) -> float:
        """The step after a converged one, from how far the corrector moved the predicted edges
        relative to the half-widths (``ρ``): ``step·√(ρ*/ρ)`` with ``ρ* =``
        :data:`PREDICTOR_ERROR`, between half and twice the step (the error of a tangent
        predictor is quadratic in the step) and at most the path step, at least a sixteenth of it.
        The path bends where a fold is coming, so the steps shrink before the corrector fails
        there. Without a prediction (no derivatives, or the contact set changed) the step grows
        1.5 times, as it always did."""
        predicted, before, after = (np.asarray(v, dtype=float) for v in (predicted, before, after))
        if not self.predict or predicted.shape != after.shape or np.array_equal(predicted, before):
            return min(1.5 * step, self.path_step)
        half = np.repeat(0.5 * (after[1::2] - after[0::2]), 2)
        rho = float(np.max(np.abs(after - predicted) / half)) if after.size else 0.0
        factor = np.sqrt(PREDICTOR_ERROR / rho) if rho > 0 else 2.0
        return float(np.clip(step * np.clip(factor, 0.5, 2.0), self.path_step / 16,
                             self.path_step))

    @staticmethod
    def jumped(predicted, before, after) -> bool:
        """Whether the corrector of a converged step moved the edges from the prediction by more
        than :data:`JUMPED` half-widths: the step crossed a fold (a step in which contacts were
        born or merged is not taken for one)."""
        predicted, before, after = (np.asarray(v, dtype=float) for v in (predicted, before, after))
        if after.shape != before.shape or predicted.shape != after.shape or after.size == 0:
            return False            # the step control of the new contact set as before
        half = np.repeat(0.5 * (after[1::2] - after[0::2]), 2)
        return bool(np.max(np.abs(after - predicted) / half) > JUMPED)

    @staticmethod
    def edge_speed(state: State, tangent) -> float | None:
        """``max_i |dx_i/dΔ̃| / α_i``: how fast the fastest edge of a converged state moves
        along the branch, in half-widths α of its contact per unit penetration (None without a
        tangent)."""
        if tangent is None:
            return None
        x = np.asarray(state.edges, dtype=float)
        half = np.repeat(0.5 * (x[1::2] - x[0::2]), 2)
        speed = float(np.max(np.abs(tangent) / half))
        return speed if np.isfinite(speed) and speed > 0 else None

    @staticmethod
    def fold_ahead(before: tuple, after: tuple) -> float | None:
        """The penetration at which the branch through two converged states ``(Δ̃, speed)``
        folds (:meth:`edge_speed`), or None when the edges do not speed up.

        Near a fold ``Δ̃*`` the branch is a parabola in the edges, ``Δ̃* - Δ̃ ∝ (x - x*)²``, so
        the edges' speed grows as ``(Δ̃* - Δ̃)^{-1/2}`` and ``1/speed²`` falls linearly to 0 at
        the fold: its line through the two states gives ``Δ̃*``. Far from a fold the edges also
        speed up now and then (a neighbour's pull, a slope of the profile): then the estimate
        lies beyond the next step, or the crossing finds the branch's continuation
        (:meth:`cross`). The fastest edge is the one taken: the first fold of each edge
        separately (tried too) took other branches on 4 of 15 points of the thesis rough
        profile where the fastest edge took them on 2 (``benchmarks/results`` §12).
        """
        (d0, s0), (d1, s1) = before, after
        if s0 is None or s1 is None or not (s1 > s0 > 0) or not d1 > d0:
            return None
        a, b = 1.0 / s0**2, 1.0 / s1**2
        return float(d1 + (d1 - d0) * b / (a - b))

    def halved(self, step: float) -> float:
        """Half the approach step, with an event in the log."""
        self.log.event(f"approach step halved to {0.5 * step:.3g}")
        return 0.5 * step

    @staticmethod
    def load_before(state: State, penetration: float, target: Control) -> bool:
        """Whether the branch through ``state`` reaches the target load before ``penetration``
        by its stiffness (:meth:`branch_stiffness`; True when that is unknown)."""
        k = Path.branch_stiffness(state)
        if k is None:
            return True
        gain = k * (penetration - float(state.fields.penetration))
        return bool(float(state.fields.mean_pressure) + gain >= target.value)

    def fold_from_start(self, state: State, tangent, start, penetration: float,
                        change: float) -> tuple[float, int] | None:
        """Where the branch through ``state`` (at ``penetration``) folds within a failed step
        of ``change`` that started from ``start``, predicted along the ``tangent``:
        ``(Δ̃*, edge)``, or None.

        The tangent cancels the residual's linear part, so at the start ``x0 + h·t`` the
        residual is ``½h²·r''`` with ``r'' = D²r[(t, 1), (t, 1)]``, and the branch's curvature
        is ``x'' = -J⁻¹r''`` (``J x'' + r'' = 0`` along the branch; one residual evaluation and
        the state's Jacobian). On a parabola ``Δ̃* - Δ̃ = a(x - x*)²`` an edge's ``x'/(2x'')``
        is its distance to the fold, positive for an edge that speeds up. The earliest fold
        within the step is taken, and its edge leads the crossing (:meth:`cross`): on the thesis
        rough profile the edge that folds first is often not the fastest one, whose own fold
        lies beyond the step (``benchmarks/results`` §21). One state gives it, where
        :meth:`fold_ahead` needs two of the same contact set (none right after a crossing, a
        birth or a merge). None when the start was scaled down (:meth:`predicted`), no edge
        folds within the step, or the derivatives are missing.
        """
        if change <= 0:
            return None
        ahead = self.fold_within(state, tangent, start,
                                 Control.penetration_of(penetration + change), change)
        if ahead is None or not ahead[0] < change:
            return None
        return penetration + ahead[0], ahead[1]

    def fold_within(self, state: State, tangent, start, control: Control,
                    change: float) -> tuple[float, int] | None:
        """``(distance, edge)``: how far along the branch through ``state`` its earliest edge
        folds, from the residual at the start ``x + change·t`` of a step to ``control`` along the
        tangent ``t`` (``x'' = -J⁻¹·2r/change²``, an edge's ``x'/(2x'')``; see
        :meth:`fold_from_start`), or None when the start is not the tangent's or the derivatives
        are missing."""
        x0 = np.asarray(state.edges, dtype=float)
        system = state.system
        if tangent is None or system is None or x0.size == 0 or change == 0:
            return None
        if not np.array_equal(np.asarray(start, dtype=float), x0 + tangent * change):
            return None
        d = system.derivatives(x0)
        r = self.eq.residual_at(start, control)
        if d is None or r is None or not np.all(np.isfinite(r)):
            return None
        try:
            curvature = -np.linalg.solve(d.jacobian, 2.0 * np.asarray(r) / change**2)
        except np.linalg.LinAlgError:
            return None
        with np.errstate(divide="ignore", invalid="ignore"):
            ahead = np.where(tangent * curvature > 0, tangent / (2.0 * curvature), np.inf)
        lead = int(np.argmin(ahead))
        return float(ahead[lead]), lead

    def cross(self, state: State, tangent, control: Control, polish: bool = False,
              lead: int | None = None) -> State | None:
        """The equilibrium at ``control`` past a fold of the branch through ``state``, reached by
        the fastest edge of the branch's tangent (or by the edge ``lead``, the one found to fold
        first by :meth:`fold_from_start`); None when none is found.

        Past a fold the edges have no equilibrium near their last one: the edge that ran fastest
        towards the fold goes on (a neck closing, a contact spreading over a valley) until it
        lands on another branch, merges with its neighbour or the contact closes. That edge
        alone moves on from ``state`` (the others are held), by :data:`CROSS_FIRST` of its
        contact's half-width at first and twice as far each time, until its residual changes
        sign (it no longer wants to move on: the landing is bracketed) or the contact set
        changes; the equilibrium is solved from the middle of the bracket or from the new
        contact set. Where the estimate of the fold was short and the branch goes on, the first
        move brackets its continuation.

        Moving the other edges along the tangent too, by as much, took other branches on 4 of 15
        points of the thesis rough profile (against 2 of the path without crossings): their
        linear moves, many half-widths long, closed gaps the fastest edge's jump does not close.

        The landing's solve is on the approach steps' :attr:`probation`. Where the contact set
        has no equilibrium near the landing (a neck about to close), Broyden found none in 30
        iterations (35-47 evaluations, 14 s on a crowded corner's ten contacts) before the
        fallback march merged the contacts in a few evaluations; on probation it hands over
        after five (``benchmarks/results`` §18). Unless the landing is the end of the path
        (``polish``), it is an intermediate state, solved to :data:`STEP_REDUCTION` of its start's
        residual as the approach steps are (§21).
        """
        x0 = np.asarray(state.edges, dtype=float)
        if tangent is None or x0.size == 0:
            return None
        half = 0.5 * (x0[1::2] - x0[0::2])
        if lead is None:
            lead = int(np.argmax(np.abs(tangent) / np.repeat(half, 2)))
        direction = float(np.sign(tangent[lead]))
        if direction == 0.0:
            return None
        # an edge wants to move on while -sign(r)·(-1 left, +1 right) is the sign of its move
        outward = -1.0 if lead % 2 == 0 else 1.0
        unit = np.zeros_like(x0)
        unit[lead] = direction * half[lead // 2]
        previous, s = 0.0, CROSS_FIRST
        start = None
        while s <= CROSS_REACH:
            trial, changed, _, full = repair(x0 + s * unit, MIN_WIDTH, MIN_GAP)
            if full:
                if not control.is_load or self.closed.supports(control.value):
                    return State.full_contact()
                return None
            if changed:
                start = trial                 # it met its neighbour, or its contact vanished
                break
            r = self.eq.residual_at(trial, control)
            if r is None or not np.all(np.isfinite(r)):
                return None
            if -np.sign(r[lead]) * outward != direction:
                start = x0 + 0.5 * (previous + s) * unit
                break
            previous, s = s, 2.0 * s
        if start is None:
            return None
        out = self.eq.solve(start, control, polish=polish, budget=APPROACH_BUDGET,
                            probation=self.probation, reduction=0.0 if polish else STEP_REDUCTION)
        return out if out.outcome in (Outcome.CONVERGED, Outcome.FULL_CONTACT) else None

    @property
    def budget(self) -> int:
        """Residual evaluations allowed to one solver call of an approach step that can still be
        halved: fewer when the step starts from the predicted state with analytic Jacobians (a
        converging step of Newton or Broyden then takes 3-10, and one near a fold fails
        sooner; :attr:`quick`). The fallback march of the smallest step, whose failure sends the
        contact jumping, always gets :data:`APPROACH_BUDGET`."""
        return APPROACH_BUDGET_ANALYTIC if self.quick else APPROACH_BUDGET

    @property
    def probation(self) -> int:
        """:attr:`Tolerances.probation` of an approach step that can still be halved:
        :data:`APPROACH_PROBATION` for an adhesive scene solved :attr:`quick`, else 0."""
        return APPROACH_PROBATION if self.quick and self.eq.adhesive else 0

    @property
    def pace(self) -> tuple[float, ...]:
        """:attr:`Tolerances.pace` of those steps: :data:`APPROACH_PACE` with the probation."""
        return APPROACH_PACE if self.probation else ()

    @property
    def quick(self) -> bool:
        """Whether approach steps start from predictions and the solver uses the analytic
        Jacobians (Newton, Broyden, nonlinear CG): then a solve that has not converged in a few
        evaluations is near a fold. A march without Jacobians (bisection) takes 20-60
        evaluations a step and keeps the full budgets."""
        return self.predict and self.eq.analytic and self.eq.jacobian_solver

    def tangent(self, state: State, load: bool) -> np.ndarray | None:
        """The path's predictor: :meth:`branch_tangent` when the path predicts, else None."""
        return self.branch_tangent(state, load) if self.predict else None

    @staticmethod
    def branch_tangent(state: State, load: bool) -> np.ndarray | None:
        """``dx/dΔ̃`` (``load``: ``dx/dp̃∞``) at a converged state, from the derivatives of the
        state's own edge system (``J dx = -∂r/∂Δ̃``; under a load change the penetration follows
        from the bordered system ``[[J, ∂r/∂Δ̃], [∂p̃∞/∂x, ∂p̃∞/∂Δ̃]]``); None without analytic
        derivatives or when the system is singular."""
        system = state.system
        if system is None or np.size(state.edges) == 0:
            return None
        d = system.derivatives(np.asarray(state.edges, dtype=float))
        if d is None:
            return None
        n = len(d.control)
        if system.control.is_load == load:
            A, b = d.jacobian, -d.control
        elif load:                    # a penetration-controlled state, a change of load
            A = np.zeros((n + 1, n + 1))
            A[:n, :n], A[:n, n], A[n] = d.jacobian, d.control, d.pressure
            b = np.zeros(n + 1)
            b[n] = 1.0
        else:
            return None
        try:
            t = np.linalg.solve(A, b)[:n]
        except np.linalg.LinAlgError:
            return None
        return t if np.all(np.isfinite(t)) else None

    def predicted(self, state: State, change: float, load: bool = False,
                  tangent=None) -> np.ndarray:
        """The edges predicted for a change of the penetration (``load``: of the mean pressure)
        from a converged state along its tangent (:meth:`tangent`), scaled down so that no edge
        moves by more than its contact's half-width and no gap closes by more than half; the
        state's edges when there is no tangent or the prediction is no valid contact set.
        ``tangent``: the state's tangent when the caller has it already."""
        x = np.asarray(state.edges, dtype=float)
        t = self.tangent(state, load) if tangent is None else tangent
        if t is None:
            return x
        move = t * change
        half = np.repeat(0.5 * (x[1::2] - x[0::2]), 2)
        gaps = np.roll(x, -1)[1::2] - x[1::2]            # right edge j to left edge j + 1
        gaps[-1] += TWO_PI
        closing = np.maximum(move[1::2] - np.roll(move, -1)[1::2], 0.0)
        limits = [1.0]
        with np.errstate(divide="ignore"):
            limits.append(float(np.min(half / np.abs(move))))
            limits.append(float(np.min(0.5 * gaps / closing)))
        out = x + min(limits) * move
        _, changed, _, _ = repair(out, MIN_WIDTH, MIN_GAP)
        return x if changed else out

    def at_target_from_first_touch(self, edges, target: Control) -> State | None:
        """The target load solved directly from the first contact widened 4 and 16 times, when
        the first contact has no equilibrium at first touch (or None).

        With strong adhesion at ζ where the trailing edge is toughened, the first contact can
        have no steady equilibrium at the first-touch penetration: its edges run round the
        period together (sinusoid Λ̃ = 0.1, β = 10, γ̃ = 5e-4, ζ = 1: the contact translated
        by two periods before the solver gave up). Under load control the target still has an
        answer (there: full contact); the event log says that the path was cut short.
        """
        centre = 0.5 * (edges[0] + edges[1])
        half = 0.5 * (edges[1] - edges[0])
        for factor in (4.0, 16.0):
            w = min(factor * half, 0.45 * TWO_PI)
            out = self.eq.solve(np.array([centre - w, centre + w]), target)
            if out.outcome in (Outcome.CONVERGED, Outcome.FULL_CONTACT):
                self.log.event("no equilibrium at first touch; the target load was solved "
                               f"from the first contact widened {factor:g} times")
                return out
        return None

    def wants_to_grow(self, edges, control: Control) -> bool:
        """Whether every edge of ``edges`` has a negative residual (would advance outward)."""
        r = self.eq.residual_at(edges, control)
        return bool(r is not None and np.all(np.isfinite(r)) and np.all(r < 0))

    def snap(self, edges, control: Control, polish: bool = True) -> State | None:
        """Equilibrium reached by an unstable growth of the contacts (or None).

        Every edge that wants to grow (negative residual) is moved outward by a step that
        doubles each time, edges that do not are held; one residual evaluation per step decides.
        Once no edge wants to grow the equilibrium is solved from there, and contacts that meet
        across the period give full contact.
        """
        x = np.asarray(edges, dtype=float).copy()
        grow = np.ones(len(x), dtype=bool)
        factor = 0.5
        while factor < 1e4:
            half = np.repeat(0.5 * (x[1::2] - x[0::2]), 2)
            trial = x + np.where(grow, factor * half, 0.0) * np.tile([-1.0, 1.0], len(x) // 2)
            factor *= 2.0
            merged, changed, _, full = repair(trial, MIN_WIDTH, MIN_GAP)
            if full:
                if not control.is_load or self.closed.supports(control.value):
                    return State.full_contact()
                return None
            r = self.eq.residual_at(merged, control)
            if r is None:
                continue
            if not np.all(np.isfinite(r)):
                return None
            x, grow = merged, r < 0
            if np.any(grow):
                continue                  # some edge still wants to grow: widen it further
            out = self.eq.solve(merged, control, polish=polish)
            if out.outcome in (Outcome.CONVERGED, Outcome.FULL_CONTACT):
                return out
            return None
        return None

    def release(self, edges, control: Control) -> State | None:
        """Equilibrium reached by an unstable recession of the contacts (or None): the pull-off
        counterpart of :meth:`snap`.

        Retracted past the fold of its branch, an adhesive contact has no equilibrium near its
        last one: it shrinks and detaches at once (the end of the displacement-controlled branch,
        point B of the thesis's Fig. 1.6). Every edge that wants to recede (positive residual)
        is moved inward by a step that doubles each time, from a quarter of its contact's
        half-width; edges that do not are held; contacts that vanish detach. Once no edge wants
        to recede the equilibrium is solved from there (with no contact left: the state without
        contact, births checked); None when no edge recedes at the start. Without this, solvers
        chased a contact shrunk to a few thousandths that no longer shrinks but slides along the
        profile (its trailing edge advancing, its leading edge receding) until their budgets ran
        out.
        """
        x = np.asarray(edges, dtype=float).copy()
        factor = 0.25
        moved = False
        while x.size and factor < 1e4:
            r = self.eq.residual_at(x, control)
            if r is None or not np.all(np.isfinite(r)):
                return None
            recede = r > 0
            if not np.any(recede):
                break
            moved = True
            half = np.repeat(0.5 * (x[1::2] - x[0::2]), 2)
            trial = x + np.where(recede, factor * half, 0.0) * np.tile([1.0, -1.0], len(x) // 2)
            factor *= 2.0
            x, changed, _, _ = repair(trial, MIN_WIDTH, MIN_GAP)
            if changed:
                factor = 0.25           # a contact detached (or two merged): start again
        if not moved:
            return None                 # no edge recedes: not a pull-off
        out = self.eq.solve(x, control)
        if out.outcome in (Outcome.CONVERGED, Outcome.NO_CONTACT, Outcome.FULL_CONTACT):
            self.log.event("contacts released past the fold of their branch"
                           + (": detached" if out.outcome is Outcome.NO_CONTACT else ""))
            return out
        return None

    # ---- stability under load control ----------------------------------------------------------
    def load_stiffness(self, state: State, eps: float) -> float:
        """``dp̃∞/dΔ̃`` along the branch at a converged state: from the derivatives of the
        state's own edge system (:meth:`branch_stiffness`) when the adhesion model gives them,
        else by one penetration-controlled solve at ``Δ̃ - eps`` (NaN when that solve does not
        converge)."""
        k = self.branch_stiffness(state)
        if k is not None:
            return k
        fields = state.fields
        trial = self.eq.solve(state.edges, Control.penetration_of(fields.penetration - eps),
                              use_fallback=False, budget=APPROACH_BUDGET, polish=False)
        if trial.outcome is not Outcome.CONVERGED:
            return np.nan
        return (fields.mean_pressure - trial.fields.mean_pressure) / eps

    @staticmethod
    def branch_stiffness(state: State) -> float | None:
        """``dp̃∞/dΔ̃`` along the equilibrium branch through a converged state, from the analytic
        derivatives of its edge system (:meth:`EdgeSystem.derivatives`); None without them or
        when the system is singular.

        With the edges in equilibrium, ``dp̃∞/dΔ̃ = ∂p̃∞/∂Δ̃ + ∂p̃∞/∂x · dx/dΔ̃``. A state solved
        in penetration control has ``J = ∂r/∂x`` and ``c = ∂r/∂Δ̃``, so ``dx/dΔ̃ = -J⁻¹c``. One
        solved in load control has ``J = ∂r/∂x`` at fixed load and ``c = ∂r/∂p̃∞``, so
        ``dx/dp̃∞ = -J⁻¹c`` and ``dΔ̃/dp̃∞ = (1 - ∂p̃∞/∂x · dx/dp̃∞)/(∂p̃∞/∂Δ̃)`` (the
        penetration that holds the load as the edges move), whose inverse is the stiffness.
        It replaces the perturbed solve of :meth:`load_stiffness` (its secant over ``eps``):
        the same quantity for about one residual evaluation instead of a solve of three to
        five at the largest mesh of the path.
        """
        system = state.system
        if system is None or state.fields is None:
            return None
        # dx/dΔ̃ or dx/dp̃∞, the system's own control (its derivatives are cached at the edges)
        t = Path.branch_tangent(state, system.control.is_load)
        if t is None:
            return None
        d = system.derivatives(np.asarray(state.edges, dtype=float))
        p_x, p_d = d.pressure[:-1], float(d.pressure[-1])
        if system.control.is_load:
            with np.errstate(divide="ignore"):
                k = p_d / (1.0 - float(p_x @ t))
        else:
            k = p_d + float(p_x @ t)
        return float(k) if np.isfinite(k) else None

    def stable_under_load(self, out: State, target: Control) -> State:
        """The approach's load-controlled root if it is stable, else the stable one below it.

        An adhesive contact has roots of ``p̃∞(Ã) = target`` on a branch where the load falls as
        the contact grows (``dp̃∞/dΔ̃ < 0``; Johnson's wavy contact between its load maximum and
        closure). Under load control such a root is unstable: approached from first touch at a
        fixed load, the contact stops growing at the first stable root, which has a smaller area.
        The approach can still land on the unstable one when a jump overshoots the load maximum.
        Then the penetration is lowered step by step, over the load maximum, until the load falls
        below the target on the stable side (``dp̃∞/dΔ̃ > 0``), and the load-controlled root is
        solved from the closer bracket. A root whose stiffness cannot be decided stays as it is
        (an event says so); when no stable root is found the solve fails with the reason.
        """
        eq, log = self.eq, self.log
        eps = 1e-3 * self.path_step
        k = self.load_stiffness(out, eps)
        if not np.isfinite(k):
            log.event("stability under load control not decided: the perturbed "
                      "penetration-controlled solve did not converge")
            return out
        if k >= 0:
            return out
        log.event(f"root unstable under load control (dp/dΔ = {k:.3g}); "
                  "looking for the stable root at a smaller penetration")
        goal = target.value
        state, step = out, 0.125 * self.path_step
        p_prev = out.fields.mean_pressure
        for _ in range(400):                            # a guard; the march ends well before
            if step < 1e-6 * self.path_step:
                break
            d_next = state.fields.penetration - step
            trial = eq.solve(state.edges, Control.penetration_of(d_next), budget=APPROACH_BUDGET,
                             polish=False)
            if trial.outcome is not Outcome.CONVERGED:
                step *= 0.5
                continue
            p_next = trial.fields.mean_pressure
            if p_next < goal and p_next < p_prev:       # crossed the target on the stable side
                start = trial if goal - p_next < p_prev - goal else state
                final = eq.solve(start.edges, target)
                if final.outcome is Outcome.CONVERGED and self.load_stiffness(final, eps) >= 0:
                    return final
                break
            state, p_prev = trial, p_next
            step = min(1.5 * step, 0.5 * self.path_step)
        return State(outcome=Outcome.NOT_CONVERGED, edges=out.edges, fields=out.fields,
                     ctx=out.ctx, residual=out.residual,
                     message="the equilibrium found is unstable under load control (dp̃∞/dΔ̃ = "
                             f"{k:.3g} < 0) and no stable root was found at smaller penetration")

    def from_full_contact(self, target: Control) -> State:
        """Continue from a closed contact. With infinitely short-range adhesion a closed
        interface has no flaw to open from (the energy release of a vanishing gap is zero), so
        it stays closed at any load; without adhesion it stays closed while it carries no
        tension, and otherwise the contact is found afresh along the approach path."""
        if self.closed.holds(target):
            return State.full_contact()
        return self.approach(target)
