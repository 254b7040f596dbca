"""One equilibrium solve: solver calls, and the contact-set changes that restart them.

From a contact set the :class:`NonlinearSolver` moves the edges until every edge residual
vanishes (:meth:`Restarts.call`); when contacts merge or vanish on the way the solve restarts
in the new dimension (:meth:`Restarts.changed`); once converged, the gap is checked on the check
grid (:meth:`Restarts.checked`): where the profile would penetrate the solid a contact is born
(:meth:`Restarts.births`), a contact carrying more tension than the interface holds is split
(:meth:`Restarts.split`), and a contact that grew past what its mesh resolves inside gets more
elements; the solve restarts until nothing changes (thesis §4.4).
"""
from __future__ import annotations

import attrs
import numpy as np

from ...adhesion.none import NoAdhesion
from ...contact.mesh import element_counts, same_zones, zone_patterns
from ...contact.topology import TopologyChange, repair
from ...solvers.base import Status
from .checks import tensile_split
from .meshing import SMALLEST_RESOLVED
from .sets import MIN_GAP, MIN_WIDTH, Control
from .state import Outcome, State

#: A merged adhesionless contact whose tension, at most this fraction of the largest pressure,
#: and split alternate is refined (the sign of a nearly vanishing pressure is below the mesh's
#: error: 1e-3 of the largest pressure measured at 64 elements across a narrow valley); a
#: larger tension that alternates is reported as a cycle.
REFINED_TENSION = 1e-2


class Restarts:
    """One solve of :meth:`Equilibrium.solve <.equilibrium.Equilibrium.solve>` at ``control``
    (its parameters are that method's): :meth:`run` returns the state."""

    def __init__(self, eq, control: Control, *, use_fallback: bool, budget: int | None,
                 refine: bool, polish: bool, fallback_budget: int | None, probation: int,
                 pace: tuple[float, ...], reduction: float, changes: bool,
                 corrector: bool = False):
        self.eq = eq
        self.solver = eq.corrector if corrector else eq.solver
        self.control = control
        self.use_fallback = use_fallback
        self.refine = refine
        self.pace = pace
        self.reduction = reduction
        self.changes = changes
        tolerances = eq.tolerances
        fallback_tolerances = tolerances
        if fallback_budget is not None:
            fallback_tolerances = attrs.evolve(
                tolerances, max_evaluations=min(fallback_budget, tolerances.max_evaluations))
        if budget is not None:
            tolerances = attrs.evolve(tolerances, max_evaluations=min(budget,
                                                                      tolerances.max_evaluations))
            if fallback_budget is None:
                fallback_tolerances = tolerances
        if probation:
            tolerances = attrs.evolve(tolerances, probation=probation)
        self.tolerances = tolerances
        self.fallback_tolerances = fallback_tolerances
        self.fallback_first = False
        self.converged_before_births: list[np.ndarray] = []
        self.polished = not polish
        self.rezoned = False        # zones remade to judge a cohesive contact's tension
        self.just_born = False      # contacts were just born and pulled open by adhesion
        self.splits: list[np.ndarray] = []
        self.called = False         # a solver call was made (the pace is for the first one)

    def run(self, edges) -> State:
        eq, control = self.eq, self.control
        edges = np.asarray(edges, dtype=float)
        for _ in range(eq.max_restarts):
            if edges.size == 0:
                born = eq.checks.births_without_contact(control)
                if born is None:
                    return State.no_contact()
                edges = born
                continue
            system = eq.system(control, edges)
            try:
                res = self.call(system, edges)
            except TopologyChange as change:
                out = self.changed(change, system, edges)
            else:
                eq.log.count(system, res)
                out = self.stopped(system, res) if not res.converged else self.checked(
                    system, res.x)
            if isinstance(out, State):
                return out
            edges = out
        return State(outcome=Outcome.NOT_CONVERGED, edges=edges, residual=np.inf,
                     message=f"contact set still changing after {eq.max_restarts} restarts")

    def call(self, system, edges):
        """The solver's result from ``edges`` (the primary solver, then the fallback from where
        it stopped when that is allowed)."""
        eq = self.eq
        self.tolerances = eq.noise_floor(system, edges, self.tolerances)
        call = eq.reduced(system, edges, self.tolerances, self.reduction)
        if self.pace and not self.called:
            call = attrs.evolve(call, pace=self.pace)
        self.called = True
        self.fallback_tolerances = attrs.evolve(self.fallback_tolerances,
                                                residual=call.residual)
        if self.fallback_first and eq.fallback is not None:
            self.fallback_first = False
            return eq.fallback.solve(system, edges, self.fallback_tolerances)
        res = self.solver.solve(system, edges, call)
        if not res.converged and eq.fallback is not None and (self.use_fallback
                                                               or self.just_born):
            eq.log.iterations += res.iterations
            eq.log.event(f"{type(self.solver).__name__} stopped ({res.status.value}); "
                         f"{type(eq.fallback).__name__} takes over")
            start = res.x if np.all(np.isfinite(res.x)) else edges
            res = eq.fallback.solve(system, start, self.fallback_tolerances)
        if not res.converged and res.status is Status.STALLED and not call.probation:
            # (a solve on probation stops early by design: near a fold, far above the floor)
            raised = eq.stalled_at_floor(system, res.x, res.residual_norm, self.tolerances)
            if raised is not None:
                # stalled within what the residuals resolve there: converged at that floor
                self.tolerances = raised
                res = attrs.evolve(res, converged=True, status=Status.CONVERGED,
                                   message=f"{res.message}; within the round-off floor "
                                           f"{raised.residual:.2g} measured there")
        return res

    def changed(self, change: TopologyChange, system, edges) -> State | np.ndarray:
        """After a solver call from ``edges`` that merged, detached or closed contacts: the
        state, or the edges to restart from."""
        eq, log = self.eq, self.eq.log
        log.evaluations += system.evaluations
        if not self.changes and not change.full_contact:
            return State(outcome=Outcome.NOT_CONVERGED, edges=edges,
                         message=change.reason, change=(
                             "merge" if "merge" in change.reason else "detachment"))
        log.event(change.reason)
        for kind in ("merge", "detach"):
            if kind in change.reason:
                log.records.append({"kind": "merge" if kind == "merge"
                                    else "detachment", "control": self.control.value})
        if change.full_contact:
            # accept closure only if a small-step march closes the contact too (a Newton
            # trial step may overshoot across the period)
            start = system.last_valid
            if start is None or eq.fallback is None or eq.closes(start, self.control):
                return State.full_contact()
            log.event("closure rejected: a step overshot the period")
            self.fallback_first = True
            return start
        return change.edges

    @staticmethod
    def stopped(system, res) -> State:
        """The state where the solver stopped without converging."""
        fields, ctx, r = system.evaluate(res.x)
        why = ("" if system.limitation is None
               else f" (the adhesion model rejected a trial point: {system.limitation})")
        return State(outcome=Outcome.NOT_CONVERGED, edges=res.x, fields=fields, ctx=ctx,
                     residual=float(np.max(np.abs(r))),
                     message=f"edge solve did not converge: {res.status.value}: "
                             f"{res.message}{why}")

    def checked(self, system, x) -> State | np.ndarray:
        """The converged edges ``x`` checked: births, splits, meshes inside the contacts, and
        the zones of its own edges (``polish``); the state, or the edges to restart from."""
        eq = self.eq
        kept = resolved_contacts(x)
        if kept is not None:
            reason = (f"{(len(x) - len(kept)) // 2} contact(s) narrower than the mesh resolves "
                      f"({SMALLEST_RESOLVED:g}) detached")
            if not self.changes:
                return State(outcome=Outcome.NOT_CONVERGED, edges=x, message=reason,
                             change="detachment")
            eq.log.event(reason)
            eq.log.records.append({"kind": "detachment", "control": self.control.value})
            return kept
        fields, ctx, r = system.evaluate(x)
        size = float(np.max(np.abs(r)))
        xs, gap = eq.checks.gap_outside(fields)          # once, for both checks
        out = self.births(system, x, fields, ctx, size, (xs, gap))
        if out is not None:
            return out
        out = self.split(system, x, fields, ctx, size)
        if out is not None:
            return out
        finer = eq.policy.counts_for(x)
        if finer is not None and (system.counts is None
                                  or any(a > b for a, b in zip(finer, system.counts))):
            # contacts grew past what their meshes in this solve resolve inside them
            eq.log.event(f"mesh refined inside contacts (up to {max(finer)} elements) "
                         "to resolve the profile between collocation points")
            return x
        if not self.polished and not same_zones(system.zones,
                                                zone_patterns(x, eq.spec, system.counts)):
            self.polished = True
            return x
        return State(outcome=Outcome.CONVERGED, edges=x, fields=fields, ctx=ctx,
                     residual=size, message="converged", system=system)

    def births(self, system, x, fields, ctx, size, outside) -> State | np.ndarray | None:
        """Contacts born where the profile penetrates (:meth:`Equilibrium.born`): the state or
        the edges to restart from; None when none is born."""
        eq, log = self.eq, self.eq.log
        regions, snapped = eq.born(fields, outside)
        if not regions:
            violation = eq.adhesion.gap_violation(*outside, fields)
            return None if violation is None else _not_converged(x, fields, ctx, size,
                                                                 violation)
        if any(len(x) == len(y) and np.allclose(x, y, rtol=0, atol=1e-7)
               for y in self.converged_before_births):
            # the same equilibrium again: the contacts born from it last time vanished
            # (detached or turned inside out) and would be born again, endlessly
            where = ("below the cohesive range" if snapped else "negative")
            return _not_converged(
                x, fields, ctx, size,
                f"contact set cycles: contacts born where the gap is {where} on the check "
                f"grid ({len(regions)} region(s)) detach again; a finer check grid "
                "(Discretization.check_points) or mesh may settle it")
        if not self.changes:
            return State(outcome=Outcome.CONVERGED, edges=x, fields=fields, ctx=ctx,
                         residual=size, message="a contact is born", system=system,
                         change="birth")
        self.converged_before_births.append(x.copy())
        new = [v for (a, b, _) in regions for v in (a, b)]
        merged, _, _, full = repair(np.concatenate([x, new]), MIN_WIDTH, MIN_GAP)
        log.event(f"{len(regions)} contact(s) born" + (
            " where the gap fell below the cohesive range" if snapped else ""))
        log.records.append({"kind": "birth", "control": self.control.value,
                            "contacts": float(len(regions))})
        if full:
            return State.full_contact()
        if eq.adhesive:
            # an adhesive contact is born far from its equilibrium, often next to a
            # neighbour it then merges with across a closing neck, which is where
            # Newton-type steps stall and the fallback march gets through
            merged = eq.grow(merged, self.control, [(a, b) for (a, b, _) in regions])
            if merged is None:
                return State.full_contact()
            self.just_born = True
        return merged

    def split(self, system, x, fields, ctx, size) -> State | np.ndarray | None:
        """A contact opened where its tension exceeds what the interface holds: nowhere for
        adhesion of vanishing range (no flaw to open from), beyond σ̃0 for a cohesive law. The
        state or the edges to restart from; None when no contact opens."""
        eq, log = self.eq, self.eq.log
        strength = split_strength(eq)
        split, where, tension = ((None, [], 0.0) if not np.isfinite(strength)
                                 else tensile_split(fields, strength=strength))
        if split is None:
            return None
        if (strength > 0.0 and not self.rezoned
                and not same_zones(system.zones, zone_patterns(x, eq.spec, system.counts))):
            # the edge zones were made for the contacts where this solve began: a contact
            # that grew far has its zone's last element many times smaller than the
            # clustered one beside it, and the stress spikes there (2.4 % above σ̃0 on a
            # sinusoid at ζ = 0.3, λ = 5), so the cohesive law's tension is judged again on
            # zones made for these contacts before the contact is split
            self.rezoned = True
            return x
        if sum(len(split) == len(y) and np.allclose(split, y, rtol=0, atol=1e-3)
               for y in self.splits) >= 2:
            return self.alternating(system, x, fields, ctx, size, where, tension)
        if not self.changes:
            return State(outcome=Outcome.NOT_CONVERGED, edges=x, fields=fields, ctx=ctx,
                         residual=size, message="a contact splits", change="split",
                         system=system)
        self.splits.append(split)
        if any(len(split) == len(y) and np.allclose(split, y, rtol=0, atol=1e-3)
               for y in self.splits[:-1]):
            # the parts of the last split merged again: their solve went to the
            # degenerate root where the gap closes (the stress intensity of both inner
            # edges vanishes as the gap does); start the parts further apart
            split = tensile_split(fields, widen=True, strength=strength)[0]
            log.event("split again with the gap widened")
        log.event("adhesionless contact split where it carried tension "
                  f"(up to {tension:.2g} of the largest pressure)" if strength == 0.0
                  else "contact split where its tension exceeded the cohesive stress "
                       f"(by up to {tension:.2g} of the largest stress)")
        return split

    def alternating(self, system, x, fields, ctx, size, where, tension) -> State | np.ndarray:
        """Split -> the parts merge -> the same tension, twice: the contact is refined where
        it splits (:func:`refined_where_alternating`; the edges to restart from), else a
        cycle."""
        why = ("" if not self.refine else
               refined_where_alternating(self.eq, system.counts, len(x) // 2, where, tension))
        if why is None:
            self.splits.clear()
            return x
        return _not_converged(x, fields, ctx, size, why or (
            "contact set cycles: a merged contact carries tension "
            f"({tension:.2g} of the largest pressure), and the parts it is split into merge "
            "again"))


def refined_where_alternating(eq, counts, n_contacts: int, where, tension: float) -> str | None:
    """A contact whose tension and split alternate (its parts merge again): a small tension
    (at most :data:`REFINED_TENSION` of the largest stress beyond what the interface holds)
    means the stress nearly vanishes inside it with a sign below what the mesh resolves, so
    the contacts holding ``where`` (``(index, point)`` of :func:`~.checks.tensile_split`) get
    twice their elements for the rest of the solve: None. Else why the contact set cycles."""
    if tension > REFINED_TENSION:
        return ("contact set cycles: a merged contact carries tension "
                f"({tension:.2g} of the largest stress), and the parts it is split into "
                "merge again")
    counts = element_counts(eq.spec, counts, n_contacts)
    if not eq.policy.refine_at([c for _, c in where], [counts[j] for j, _ in where]):
        return ("contact set cycles: a merged contact carries tension, and the parts it is "
                f"split into merge again, with {eq.policy.cap} elements in the contact")
    eq.log.event(
        "mesh refined in a contact whose tension and split alternate (up to "
        f"{max(m for _, m in eq.policy.refined)} elements): its tension, {tension:.2g} of "
        "the largest stress, is a nearly vanishing stress whose sign the mesh does not "
        "resolve")
    return None


def resolved_contacts(x) -> np.ndarray | None:
    """The edges ``x`` without the contacts narrower than the shortest length the mesh resolves
    (:data:`~.meshing.SMALLEST_RESOLVED`), or None when every contact is wider. A solve can
    converge on such a contact: an adhesionless one closing to a point at zero load, whose
    residuals vanish with its width, stopped at Ã = 2e-8 once each overloaded stretch of a
    contact opened on its own (the edges' motion detaches such contacts too,
    :func:`~.relax._vanishing`)."""
    gone = (x[1::2] - x[0::2]) < SMALLEST_RESOLVED
    return np.asarray(x)[np.repeat(~gone, 2)] if np.any(gone) else None


def split_strength(eq) -> float:
    """The tension inside a contact beyond which it splits: none for adhesion of vanishing
    range (0 without adhesion; infinite for the energy balance, whose closed interface has no
    flaw to open from), the cohesive stress σ̃0 for a cohesive law."""
    if isinstance(eq.adhesion, NoAdhesion):
        return 0.0
    return eq.adhesion.closed_strength(eq.prep.shape.amplitude)


def _not_converged(x, fields, ctx, size, message) -> State:
    return State(outcome=Outcome.NOT_CONVERGED, edges=x, fields=fields, ctx=ctx,
                 residual=size, message=message)


__all__ = ["REFINED_TENSION", "Restarts", "refined_where_alternating", "resolved_contacts"]
