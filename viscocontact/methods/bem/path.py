"""The predictor of a path through equilibria: the branch's tangent, the predicted start of a
step, the step control, the fold estimate, and the solver budgets of a path's steps.

The approach history that uses them is :mod:`~viscocontact.methods.bem.approach`; its jumps are
:mod:`~viscocontact.methods.bem.relax`.
"""
from __future__ import annotations

import numpy as np

from ...contact.topology import repair
from .sets import MIN_GAP, MIN_WIDTH, Control, necks
from .state import State

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
#: adhesionless solve at ζ = 1e-2 3.7 times the evaluations.
APPROACH_PROBATION = 4
#: Earlier checkpoints of that probation (:attr:`Tolerances.pace`): after one evaluation past
#: the first the best ``max|r|`` must be below 0.9 of the first, after two below 0.6. On the
#: crowded corners (seeds 0-2) and the rough point (seeds 11-13), 372 solves of adhesive
#: approach steps: the 307 that converged had at most 0.81 and 0.50 there, the 65 that failed a
#: median of 0.93 and 0.91; the checkpoints would stop 57 of these one to three evaluations
#: sooner (160 evaluations) and no converging one. They apply to a step's first solver call
#: (:meth:`Equilibrium.solve`).
APPROACH_PACE = (0.9, 0.6)
#: The corrector of an intermediate approach step (not the last, at the target) converges
#: once ``max|r|`` is this fraction of its value at the predicted start, or at the tolerance
#: (:meth:`Equilibrium.solve`'s ``reduction``): the state then lies within a ten-thousandth of
#: the predictor's error from the branch, while the next step's prediction errs by about
#: :data:`PREDICTOR_ERROR` of the half-widths. It saves the last one or two of the three to
#: five evaluations of a converging step.
STEP_REDUCTION = 1e-4
#: Largest correction of a predicted edge, relative to its contact's half-width, that the step
#: control aims at (:meth:`Path.next_step`).
PREDICTOR_ERROR = 0.02


class Path:
    """The predictor and step control of a path through one solve's equilibria.

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

    def fold_within(self, state: State, tangent, start, control: Control,
                    change: float) -> tuple[float, int] | None:
        """``(distance, edge)``: how far along the branch through ``state`` its earliest edge
        folds, from the residual at the start ``x + change·t`` of a step to ``control`` along the
        tangent ``t``, or None when the start is not the tangent's or the derivatives are
        missing.

        The tangent cancels the residual's linear part, so at the start the residual is
        ``½h²·r''``, and the branch's curvature is ``x'' = -J⁻¹r''`` (one residual evaluation
        and the state's Jacobian). On a parabola ``v* - v = a(x - x*)²`` an edge's ``x'/(2x'')``
        is its distance to the fold, positive for an edge that speeds up; the earliest is
        taken."""
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

    @property
    def budget(self) -> int:
        """Residual evaluations allowed to one solver call of an approach step that can still be
        halved: fewer when the step starts from the predicted state with analytic Jacobians (a
        converging step of Newton or Broyden then takes 3-10, and one near a fold fails
        sooner; :attr:`quick`)."""
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
        """Whether approach steps start from predictions and their corrector
        (:attr:`Equilibrium.corrector <.equilibrium.Equilibrium.corrector>`) uses the analytic
        Jacobians: then a solve that has not converged in a few evaluations is near a fold. A
        march without Jacobians (bisection, the corrector of a model without derivatives)
        takes 20-60 evaluations a step and keeps the full budgets."""
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
        gaps, closing = necks(x, move)
        closing = np.maximum(closing, 0.0)
        limits = [1.0]
        with np.errstate(divide="ignore"):
            limits.append(float(np.min(half / np.abs(move))))
            limits.append(float(np.min(0.5 * gaps / closing)))
        out = x + min(limits) * move
        _, changed, _, _ = repair(out, MIN_WIDTH, MIN_GAP)
        return x if changed else out


__all__ = ["Path"]
