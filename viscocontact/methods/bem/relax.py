"""The jump of a contact whose branch of equilibria has ended: overdamped edge motion.

Past a fold (a speed or a load at which its contact set has no equilibrium nearby) a contact
moves on its own until it finds one. A steady-state model has no dynamics of that motion, so the
rule is stated: every edge moves outward at a speed proportional to minus its residual (the
imbalance of its energy release rate against the work of adhesion, the residual of the
Griffith balance), at fixed speed ζ and fixed control, until the edges stop,

    dX_i/dt = -o_i r_i(X),   o_i = +1 for a right edge, -1 for a left one,

so that an edge whose residual is negative (it would advance) advances, and one with a
positive residual recedes. The flow is integrated by linearly implicit Euler steps,
``(I/h + O J) δ = -O r`` (``J`` refreshed after a rejected step and every
:data:`JACOBIAN_AGE` steps), with the step ``h`` chosen so that each step's local error,
``h²/2·Ẍ`` estimated as ``h/2`` times the change of the edges' speed over the step (one
residual a step), is within ``tolerance`` of its contact's half-width (or of the mean
half-width, when that is larger); contacts that meet merge, contacts that vanish detach,
contacts that close over the period close. As the edges slow down the steps grow and become
Newton's; once every mode of the motion decays and Newton's step to the root is within the
tolerance (or ``max|r|`` has fallen to :data:`SETTLED` times the solver's tolerance), the
equilibrium solve finishes from there with the contact set held. Where the profile penetrates
at its root, contacts are born there, at zero size, and the motion goes on with them (a born
contact grows as every edge moves), so that merges, detachments and births all happen on the
way, as the motion makes them.

The landing is the equilibrium at the end of this flow: a property of the state the jump starts
from, not of a search order; a tenth of the tolerance gives the same landing (tested).
"""
from __future__ import annotations

import attrs
import numpy as np

from ...contact.mesh import same_zones, zone_patterns
from ...contact.topology import TWO_PI, TopologyChange, repair
from .path import STEP_REDUCTION
from .sets import MIN_GAP, MIN_WIDTH, Control
from .state import Outcome, State

#: The flow ends, and the equilibrium solve finishes, once ``max|r|`` is below this many times
#: the solver's residual tolerance.
SETTLED = 1e3
#: The largest step times the fastest growth rate of an unstable mode of the motion.
UNSTABLE_STEP = 0.5
#: The motion's mesh zones are remade for its edges at most this many times in one motion, when
#: the motion nears its end (the equilibrium solve would remake them).
REZONED = 4
#: Accepted steps taken with one Jacobian (linearly implicit Euler stays consistent with an
#: older one; a rejected step or a new contact set takes a fresh one).
JACOBIAN_AGE = 8


@attrs.frozen
class RelaxFrom:
    """An initial contact set that asks a solve for the jump: the overdamped edge motion from
    ``edges`` at the problem's control (:class:`Relaxation`), then the equilibrium there.
    Pass it as ``ContactProblem.solve(initial=RelaxFrom(edges))``."""

    edges: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float).ravel())
    tolerance: float = 0.02


def _scale(x: np.ndarray) -> np.ndarray:
    half = 0.5 * (x[1::2] - x[0::2])
    return np.repeat(np.maximum(half, half.mean()), 2)


class Relaxation:
    """The overdamped edge motion of one solve (see the module docstring).

    Parameters
    ----------
    equilibrium : Equilibrium
    closed : ClosedContact
    tolerance : float
        Largest local error of a step, in half-widths.
    max_steps : int
        Accepted and rejected steps allowed before the motion is given up (a failed state). A
        contact that travels is found once it has gone round the period, which can take more
        than a thousand steps (campaign seeds 196 and 213: 400 steps ended them unexplained).
    """

    def __init__(self, equilibrium, closed, tolerance: float = 0.02, max_steps: int = 2000):
        self.eq = equilibrium
        self.closed = closed
        self.tolerance = tolerance
        self.max_steps = max_steps
        self._finish: dict = {}

    def run(self, edges, control: Control, final: bool = True) -> State:
        """The state the edges' motion from ``edges`` ends in (not converged, with the reason,
        when the motion does not end). ``final = False``: an intermediate state of a path,
        solved to :data:`~.path.STEP_REDUCTION` of its start's residual and not polished."""
        systems: list = []
        self._finish = ({} if final else
                        {"polish": False, "refine": False, "reduction": STEP_REDUCTION})
        x = np.asarray(edges, dtype=float).copy()
        try:
            for _ in range(self.max_steps):
                out = self._run(x, control, systems)
                if isinstance(out, State):
                    return out
                x = out             # contacts were born: the motion goes on with them
            return self._failed(x, f"met more than {self.max_steps} births")
        finally:
            self.eq.log.evaluations += sum(s.evaluations for s in systems)

    def _failed(self, x, why: str) -> State:
        return State(outcome=Outcome.NOT_CONVERGED, edges=x, message=f"the edges' overdamped "
                     f"motion {why}")

    def _settle(self, x: np.ndarray, control: Control) -> State | np.ndarray | None:
        """The equilibrium solve from ``x`` with its contact set held: the state; or, where
        the profile penetrates at that state's root, the edges with the contacts born there
        added (they grow by the motion, like every edge); or None when the solve met a merge
        or a split (the motion makes those)."""
        eq = self.eq
        out = eq.solve(x, control, use_fallback=False, changes=False, **self._finish)
        if out.change == "birth":
            regions, snapped = eq.born(out.fields)
            new = [v for (a, b, _) in regions for v in (a, b)]
            edges, _, _, full = repair(np.concatenate([out.edges, new]), MIN_WIDTH, MIN_GAP)
            eq.log.event(f"{len(regions)} contact(s) born" + (
                " where the gap fell below the cohesive range" if snapped else ""))
            eq.log.records.append({"kind": "birth", "control": control.value,
                                   "contacts": float(len(regions))})
            return State.full_contact() if full else edges
        return None if out.change else out

    def _run(self, x: np.ndarray, control: Control, systems: list) -> State | np.ndarray:
        system = self.eq.system(control, x)
        systems.append(system)
        settled = SETTLED * self.eq.tolerances.residual
        h = None
        shortcut = True         # finish with the equilibrium solve once Newton's step is short
        track: list = []        # (total width, mean edge position, edges) since the last
        #                         change of the contact set
        J = None                # the Jacobian of the steps: kept while they are accepted
        rezoned = 0
        age = 0
        moved = 0
        r = self._residual(system, x)
        for _ in range(self.max_steps):
            if r is None:
                return self._failed(x, "met a contact set without a valid field")
            near = np.max(np.abs(r)) <= settled
            if (near or shortcut) and rezoned < REZONED:
                fresh = self._fresh(system, x, control)
                if fresh is not None:
                    # the edges have moved out of the mesh zones they were solved with, which
                    # the equilibrium solve would remake: the motion goes on, on the new ones
                    system, J, rezoned = fresh, None, rezoned + 1
                    systems.append(system)
                    r = self._residual(system, x)
                    continue
            if near:
                break
            if J is None or age >= JACOBIAN_AGE:
                J, age = self._jacobian(system, x), 0
                if J is None:
                    return self._failed(x, "met a contact set without derivatives")
            if shortcut and self._near_stable_root(r, J, x):
                # Newton's step lands on the root the motion is heading for, unless the state
                # sits at a fold past which the root is gone: then the motion goes on
                out = self._settle(x, control)
                if out is not None and not (isinstance(out, State)
                                            and out.outcome is Outcome.NOT_CONVERGED):
                    self.eq.log.event(f"the edges moved in {moved} steps of their overdamped "
                                      "motion")
                    return out
                shortcut = False
            if h is None:       # the first step moves the fastest edge a twentieth of a scale
                h = 0.05 * float(np.min(_scale(x) / np.maximum(np.abs(r), 1e-300)))
            # implicit Euler damps a growing mode whose rate exceeds 1/h (and flips its sign
            # past 2/h): the step resolves the growth of every unstable mode of the motion
            h = min(h, UNSTABLE_STEP / self._growth(J))
            move = self._step(r, J, h)
            if move is None:
                h, J = 0.25 * h, None
                continue
            landed, changed, reason, full = repair(x + move, MIN_WIDTH, MIN_GAP)
            if full:
                if control.is_load and not self.closed.supports(control.value):
                    return self._failed(landed, "closed the contact, which does not carry "
                                                "this load")
                self.eq.log.event("the edges' motion closed the contact")
                return State.full_contact()
            if not landed.size:
                self.eq.log.event("the edges' motion detached every contact")
                if control.is_load and control.value > 0:
                    # a compressive load needs a contact: found afresh from the first touch
                    return self.eq.solve(landed, control, use_fallback=False, **self._finish)
                return State.no_contact()
            after = self.eq.system(control, landed) if changed else system
            r_new = self._residual(after, landed)
            if r_new is None:
                # no field at the step's end (a Maugis-Dugdale zone's equations): a shorter step
                h, J = 0.25 * h, None
                continue
            # the local error of an implicit Euler step, h²/2·X'', is h/2 times the change of
            # the speed -O r over the step (one residual a step: the one the next step needs);
            # a step that changes the contact set is taken as it is (the set's change is the
            # motion's event)
            error = (0.0 if changed else
                     float(np.max(0.5 * h * np.abs(r_new - r) / _scale(x))))
            if error > self.tolerance:
                h, J = h * max(0.2, 0.9 * np.sqrt(self.tolerance / error)), None
                continue
            h *= min(4.0, 0.9 * np.sqrt(self.tolerance / max(error, 1e-300)))
            moved, age, x, r = moved + 1, age + 1, landed, r_new
            for kind, word in (("merge", "merge"), ("detachment", "detach")):
                if changed and word in reason:
                    self.eq.log.records.append({"kind": kind, "control": control.value})
            track.append((float(np.sum(x[1::2] - x[0::2])), float(np.mean(x)), len(x)))
            if changed:
                track = track[-1:]
                system, J = after, None
                systems.append(system)
            if self._travels(track):
                return self._failed(x, "carries the contacts round the period: no steady "
                                       "state at this control")
        else:
            return self._failed(x, f"did not stop within {self.max_steps} steps")
        self.eq.log.event(f"the edges moved in {moved} steps of their overdamped motion")
        out = self._settle(x, control)
        if out is None:
            # at rest, the held solve meets a merge or a split (a tensile contact, which no edge
            # motion opens): the equilibrium solve makes it
            self.eq.log.event("the edges came to rest next to a change of the contact set")
            return self.eq.solve(x, control, use_fallback=False, **self._finish)
        return out

    def _fresh(self, system, x: np.ndarray, control: Control):
        """A new edge system for ``x`` when the mesh zones or element counts of ``system``
        are not those ``x`` is given (the edges moved out of them), else None."""
        eq = self.eq
        counts = eq.policy.counts_for(x)
        if (counts is None or system.counts is None or tuple(counts) == tuple(system.counts)) \
                and same_zones(system.zones, zone_patterns(x, eq.spec, system.counts)):
            return None
        return eq.system(control, x)

    @staticmethod
    def _travels(track: list) -> bool:
        """Whether the contacts have moved round a whole period of the profile without
        settling: a contact that travels along the profile (a trailing edge that drags it), which
        a steady state does not do."""
        return len(track) > 1 and abs(track[-1][1] - track[0][1]) > TWO_PI

    @staticmethod
    def _residual(system, x):
        """``r`` at ``x`` (None where ``x`` is no valid contact set)."""
        try:
            r = system.residual(x)
        except TopologyChange:
            return None
        return r if r is not None and np.all(np.isfinite(r)) else None

    @staticmethod
    def _jacobian(system, x):
        try:
            J = system.jacobian(x)
        except TopologyChange:
            return None
        return J if J is not None and np.all(np.isfinite(J)) else None

    def _near_stable_root(self, r, J, x) -> bool:
        """Whether every mode of the motion decays and Newton's step to the root is within the
        tolerance: the motion ends at that root, which the equilibrium solve finishes."""
        if self._growth(J) > 1e-300:
            return False
        try:
            newton = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            return False
        return bool(np.max(np.abs(newton) / _scale(x)) <= self.tolerance)

    @staticmethod
    def _growth(J) -> float:
        """The fastest growth rate of the linearised motion ``dδ/dt = -O J δ`` (0 when every
        mode decays)."""
        o = np.tile([-1.0, 1.0], len(J) // 2)
        try:
            rates = -np.linalg.eigvals(o[:, None] * J).real
        except np.linalg.LinAlgError:
            return 0.0
        return float(max(rates.max(initial=0.0), 1e-300))

    @staticmethod
    def _step(r, J, h):
        """The linearly implicit Euler move ``δ`` of ``dX/dt = -O r`` over ``h``."""
        o = np.tile([-1.0, 1.0], len(r) // 2)
        a = np.eye(len(r)) / h + o[:, None] * J
        try:
            move = np.linalg.solve(a, -o * r)
        except np.linalg.LinAlgError:
            return None
        return move if np.all(np.isfinite(move)) else None
