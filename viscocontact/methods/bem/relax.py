"""The jump of a contact whose branch of equilibria has ended: overdamped edge motion.

Past a fold (a speed or a load at which its contact set has no equilibrium nearby) a contact moves
on its own until it finds one. A steady-state model has no dynamics of that motion, so the rule is
stated: every edge moves outward at a speed proportional to minus its residual (the imbalance of
its energy release rate against the work of adhesion, the residual of the Griffith balance), at
fixed speed ζ and fixed control, until the edges stop,

    dX_i/dt = -o_i r_i(X),   o_i = +1 for a right edge, -1 for a left one,

so that an edge whose residual is negative (it would advance) advances, and one with a positive
residual recedes. The flow is integrated by linearly implicit Euler steps, ``(I/h + O J) δ = -O r``
(``J`` refreshed after a rejected step and every :data:`JACOBIAN_AGE` steps), with the step ``h``
chosen so that each step's local error, ``h²/2·Ẍ`` estimated as ``h/2`` times the change of the
edges' speed over the step (one residual a step), is within ``tolerance`` of its contact's
half-width (or of the mean half-width, when that is larger; a step after a rejected one does not
grow, and the growth of the error over the last step is taken to go on), and so that no edge moves
further than ``√(2·tolerance)`` of that scale (the error of a move over which the speed changes
within a half-width; the ends alone do not see a residual that is flat between them); contacts that
meet merge, contacts that narrow below the shortest length the mesh resolves detach, contacts that
close over the period close where full contact can be the state
(:meth:`~.closed.ClosedContact.possible`; elsewhere the step that closed it is shortened: on an
incompressible solid below its closing penetration a gap of the volume the penetration fixes stays
open), and the mesh zones are remade in the first steps (each evaluated at its end on the zones
made for that end), at rest, where a contact shrank to less than half the width its zones fit, and
for a step whose end has no field on the zones it was taken with (a cohesive zone's equations past
their reach). As the edges slow down the steps grow and become Newton's; once every mode of the
motion decays and Newton's iteration from the state contracts (its second step at most
:data:`NEWTON_CONTRACTION` of its first, which is within :data:`NEWTON_REACH` half-widths: the
state lies where the linearised motion holds, and the flow ends at Newton's root), or ``max|r|``
has fallen to :data:`SETTLED` times the solver's tolerance, the equilibrium solve finishes from
there with the contact set held, on the trial budgets of an approach step (at a fold, where the
root is gone, it fails fast and the motion goes on). Just past a fold the edges slow down where the
root has vanished (a bottleneck whose residual can fall below the rest level); where the
equilibrium solve finds no root at rest, the motion goes on through it. Where the profile
penetrates at its root, contacts are born there, at zero size, and the motion goes on with them (a
born contact grows as every edge moves); where a contact at rest carries more tension than the
interface holds (any, without adhesion; the cohesive stress σ̃0 under a cohesive law), it splits
there and the motion goes on with its parts. Where the parts merge again and split at the same
place a third time, the tension is a nearly vanishing stress whose sign the mesh does not resolve:
the contact is refined there, as the equilibrium solve refines it
(:func:`~.restarts.refined_where_alternating`; in an intermediate motion too, which has no shorter
step to get past it), and the motion goes on. Where every contact detaches while the profile
penetrates the undeformed solid, contacts are born there and the motion goes on; born again where
they were, the motion is periodic (no steady state); so it is where contacts born at a rest
state are born again at the same rest state, the motion having come back to it (the contacts
vanished, or merged and receded; campaign seed 225, a thin confined Prony layer, cycled so past
600 s), and where they were born because the gap fell below a cohesive range, the state is a
cohesive zone without a contact, which zones at contact edges do not represent: the motion ends
and says which (a confined rough Maugis-Dugdale scene cycled one contact a step, 1000 births).
Where the steps creep to the end of the model's reach (no field past it; :data:`WALL`), the
motion ends there, not converged; where an edge is held at a jump of its residual across zero
(:func:`_held`: no root, the flow on both sides points at it), it ends there too, saying that
the balance has no root (outside the model); and where the steps cross back and forth where the
zones of a neck switch between stopping short of each other and filling it (:func:`_slides`:
the flow slides along the switch, on which a zone apart from the contacts fills the neck in
part, a state these zones do not represent), it ends saying so. So merges, detachments, births
and splits all happen on the way, as the motion makes them.

The landing is the equilibrium at the end of this flow: a property of the state the jump starts
from, not of a search order; a tenth of the tolerance gives the same landing (tested).
"""
from __future__ import annotations

from typing import Any, Callable

import attrs
import numpy as np

from ...contact.cohesive import filled
from ...contact.mesh import same_zones, squeezed, zone_patterns
from ...contact.topology import TWO_PI, TopologyChange, repair
from .checks import tensile_split
from .meshing import SMALLEST_RESOLVED
from .path import STEP_REDUCTION
from .restarts import refined_where_alternating, split_strength
from .sets import MIN_GAP, MIN_WIDTH, Control
from .state import Outcome, State

#: The flow ends, and the equilibrium solve finishes, once ``max|r|`` is below this many times
#: the solver's residual tolerance (or the residuals' round-off floor, where that is higher).
SETTLED = 1e3
#: The largest step times the fastest growth rate of an unstable mode of the motion.
UNSTABLE_STEP = 0.5
#: Shortenings of a proposed step to keep its move within reach before it counts as a try.
REACH_TRIES = 8
#: The motion's mesh zones are remade for its edges in its first this many steps, which move the
#: edges the most (a residual on the new zones at the step's end), and at most this
#: many times when it nears its end (the equilibrium solve there remakes them: the motion must
#: come to rest on the zones of its rest state, whose residual can differ from the one on the
#: zones it moved with by far more than the solver's tolerance).
REZONED = 4
#: Newton's step from a state of the motion is tested for the root the motion heads for when
#: it moves no edge more than this many half-widths of its contact.
NEWTON_REACH = 0.25
#: ... and that root is taken when the simplified Newton step after it is at most this
#: fraction of it (the contraction of Newton's iteration there; at a fold it tends to 1).
NEWTON_CONTRACTION = 0.25
#: A step whose end has no field, shorter than this many half-widths, ends the motion (the
#: round-off of the edges' positions: the motion has come to the end of the model's reach).
WALL = 1e-12
#: Accepted steps taken with one Jacobian (linearly implicit Euler stays consistent with an
#: older one; a rejected step or a new contact set takes a fresh one).
JACOBIAN_AGE = 8
#: A change of an edge's residual over an accepted step larger than this many times the change
#: its Jacobian predicts, across zero, is a jump of the residual (:func:`_held`), not a root.
JUMP = 10.0
#: ... and it is a jump where the residual's change across it stays (at least half) while
#: its bracket is narrowed this many times (:func:`_jump`; a root's change shrinks with it).
NARROWED = 1024.0


@attrs.frozen
class RelaxFrom:
    """An initial contact set that asks a solve for the jump: the overdamped edge motion from
    ``edges`` at the problem's control (:class:`Relaxation`), then the equilibrium there.
    Pass it as ``ContactProblem.solve(initial=RelaxFrom(edges))``."""

    edges: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float).ravel())
    tolerance: float = 0.02


class _Systems:
    """The edge systems of one motion, for their residual evaluations: a system's count is
    taken when the next one replaces it, and the system is let go (each holds its last field and
    factorisation, megabytes a contact set; a motion can make hundreds)."""

    def __init__(self):
        self._done = 0
        self._current = None

    def append(self, system) -> None:
        if self._current is not None:
            self._done += self._current.evaluations
        self._current = system

    def discard(self, system) -> None:
        """Count the evaluations of a system the motion did not take."""
        self._done += system.evaluations

    @property
    def evaluations(self) -> int:
        return self._done + (0 if self._current is None else self._current.evaluations)


@attrs.define
class _Motion:
    """The integrator's state of one motion of a contact set."""

    system: Any                         # the EdgeSystem the motion is evaluated on
    x: np.ndarray
    r: np.ndarray | None = None
    h: float | None = None              # the next step
    J: np.ndarray | None = None         # the steps' Jacobian, kept while they are accepted
    age: int = 0                        # accepted steps taken with it
    rezoned: int = 0
    moved: int = 0                      # accepted steps
    rejected: bool = False              # the last step was rejected
    last: tuple | None = None           # (local error, length) of the last accepted step
    ghost: float = np.inf               # max|r| below which the motion is at rest again
    early: bool = True                  # no equilibrium solve tried yet: zones are remade
    #                                     (the motion's first steps move edges the most)
    tested: float = np.inf              # Newton's contraction is tested again below this max|r|
    track: list = attrs.Factory(list)   # (total width, mean edge position, edges) since the
    #                                     last change of the contact set
    crossed: tuple | None = None        # (x, r) before the last accepted step, when that
    #                                     step crossed a jump of the residuals (:func:`_slides`)
    jumps: dict = attrs.Factory(dict)   # edge -> the signs its residual jumped to across
    #                                     zero (:func:`_held`)


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
    trial : dict
        Solver budgets (``budget``, ``probation``, ``pace`` of :meth:`Equilibrium.solve`) of
        the equilibrium solve that the motion tries where Newton's step to a stable root is
        short: a state at a fold, whose root is gone, passes that test too, and its solve
        must fail as fast as an approach step near a fold does (:attr:`Path.budget`).
    """

    def __init__(self, equilibrium, closed, tolerance: float = 0.02, max_steps: int = 2000,
                 trial: dict | None = None):
        self.eq = equilibrium
        self.closed = closed
        self.tolerance = tolerance
        self.max_steps = max_steps
        self.trial = dict(trial or {})
        self._finish: dict = {}
        self._splits: list = []      # the contact sets made by splits in the current motion
        # (rest state, born regions) of the births of the current motion: at its rest states,
        # and with no contact (an empty rest state) after every contact detached
        self._births: list = []
        self._bear = True            # contacts are born where every contact detached

    def run(self, edges, control: Control, final: bool = True, births: bool = True) -> State:
        """The state the edges' motion from ``edges`` ends in (not converged, with the reason,
        when the motion does not end). ``final = False``: an intermediate state of a path,
        solved to :data:`~.path.STEP_REDUCTION` of its start's residual and not polished.
        ``births = False``: where every contact detaches, the motion ends with no contact even
        where the profile penetrates (the approach's search for the first contact that holds,
        for which that is the answer "none holds here")."""
        systems = _Systems()
        self._splits, self._births, self._bear = [], [], births
        self._finish = ({} if final else
                        {"polish": False, "refine": False, "reduction": STEP_REDUCTION})
        x = np.asarray(edges, dtype=float).copy()
        try:
            for _ in range(self.max_steps):
                out = self._run(x, control, systems)
                if isinstance(out, State):
                    return out
                x = out             # contacts were born or split: the motion goes on with them
            return self._failed(x, f"met more than {self.max_steps} births and splits")
        finally:
            self.eq.log.evaluations += systems.evaluations

    def _failed(self, x, why: str) -> State:
        return State(outcome=Outcome.NOT_CONVERGED, edges=x, message=f"the edges' overdamped "
                     f"motion {why}")

    def _settle(self, x: np.ndarray, control: Control,
                trial: bool = False) -> State | np.ndarray | None:
        """The equilibrium solve from ``x`` with its contact set held: the state; or, where
        the profile penetrates at that state's root, the edges with the contacts born there
        added, or where a contact's tension exceeds what the interface holds, the edges with it
        split there (the new edges move by the motion, like every edge; a split whose parts
        merged again twice refines the contact, and the merged edges go on, or, where the
        tension is too large or the contact at its cap, is a cycle, a failed state); or None
        when the solve met a merge (the motion makes those). ``trial``: with the
        :attr:`trial` budgets."""
        eq = self.eq
        out = eq.solve(x, control, use_fallback=False, changes=False, corrector=True,
                       **self._finish, **(self.trial if trial else {}))
        if out.change == "birth":
            regions, snapped = eq.born(out.fields)
            again = _born_again(self._births, out.edges, regions, snapped)
            if again is not None:
                return attrs.evolve(self._failed(out.edges, again), change="reborn")
            new = [v for (a, b, _) in regions for v in (a, b)]
            edges, _, _, full = repair(np.concatenate([out.edges, new]), MIN_WIDTH, MIN_GAP)
            eq.log.event(f"{len(regions)} contact(s) born" + (
                " where the gap fell below the cohesive range" if snapped else ""))
            eq.log.records.append({"kind": "birth", "control": control.value,
                                   "contacts": float(len(regions))})
            return State.full_contact() if full else edges
        if out.change == "split" and out.fields is not None:
            strength = split_strength(eq)
            split, where, tension = tensile_split(out.fields, strength=strength)
            place = ("where they carried tension" if strength == 0.0
                     else "where their tension exceeded the cohesive stress")
            if split is not None:
                edges, _, _, full = repair(split, MIN_WIDTH, MIN_GAP)
                if sum(len(edges) == len(y) and np.allclose(edges, y, rtol=0, atol=1e-3)
                       for y in self._splits) >= 2:
                    # the parts merged again, and the merged contact splits at the same
                    # place: refined there, the motion goes on from the merged contact (a
                    # tension below the mesh's error); else it has no state to end in
                    counts = None if out.system is None else out.system.counts
                    why = refined_where_alternating(eq, counts, len(out.edges) // 2, where,
                                                    tension)
                    if why is None:
                        self._splits = []
                        return np.asarray(out.edges, dtype=float)
                    return State(outcome=Outcome.NOT_CONVERGED, edges=out.edges,
                                 change="cycle", message=f"{why} (split {place}, three times)")
                self._splits.append(edges)
                if not full and len(edges) > len(out.edges):
                    eq.log.event(f"contacts opened at {len(where)} place(s) {place} (up "
                                 f"to {tension:.2g} of the largest stress)")
                    eq.log.records.append({"kind": "split", "control": control.value,
                                           "contacts": float(len(where))})
                    return edges
        return None if out.change else out

    def _run(self, x: np.ndarray, control: Control,
             systems: "_Systems") -> State | np.ndarray:
        """One motion of the contact set ``x``: steps until the edges come to rest (the
        state there, or the edges with contacts born there), or until the motion ends
        otherwise (closure, detachment, a failure)."""
        m = _Motion(system=self.eq.system(control, x), x=x)
        systems.append(m.system)
        m.r = _valid(m.system.residual, x)
        for _ in range(self.max_steps):
            if m.r is None:
                return self._failed(m.x, "met a contact set without a valid field")
            size = float(np.max(np.abs(m.r)))
            near = size <= min(SETTLED * self._resolved(m), m.ghost)
            # the zones of a contact that shrank to less than half the width they fit are
            # remade, and those of the rest state, on a budget of their own (the first steps
            # end on zones made for their ends: :func:`_end`)
            if ((near and m.rezoned < REZONED) or squeezed(m.system.zones, m.x)) \
                    and self._rezone(m, control, systems):
                m.rezoned += int(near)
                continue
            if near:
                rest = self._at_rest(m, control)
                if not (isinstance(rest, State) and rest.outcome is Outcome.NOT_CONVERGED
                        and not rest.change):
                    return rest
                # no root where the edges slowed down: the bottleneck just past a fold, where
                # the residual is small but the root has gone; the motion goes on through it
                m.ghost = 0.5 * size
                self.eq.log.event("the edges' motion slowed down past a fold, where no "
                                  "equilibrium is: it goes on")
            if m.J is None or m.age >= JACOBIAN_AGE:
                m.J, m.age = _valid(m.system.jacobian, m.x), 0
                if m.J is None:
                    return self._failed(m.x, "met a contact set without derivatives")
            out = self._shortcut(m, control)
            if out is None:
                out = self._advance(m, control, systems)
            if out is not None:
                return out
        return self._failed(m.x, f"did not stop within {self.max_steps} steps")

    def _resolved(self, m: "_Motion") -> float:
        """The smallest ``max|r|`` the residuals of the motion's system resolve: the solver's
        tolerance, or their round-off floor where that is higher (:meth:`Equilibrium.
        noise_floor`; energy balances over δX on a glassy solid carry 1e-10 to 1e-8), as the
        equilibrium solve that finishes the motion takes it: below it the edges stand still
        at a residual of noise."""
        return self.eq.noise_floor(m.system, m.x, self.eq.tolerances).residual

    def _rezone(self, m: "_Motion", control: Control, systems: "_Systems") -> bool:
        """Whether the edges have moved out of the mesh zones they were solved with (which the
        equilibrium solve would remake): then the motion goes on, on new ones (the caller
        counts a rest state's rezones against their budget)."""
        fresh = _fresh(self.eq, m.system, m.x, control)
        if fresh is None:
            return False
        m.system, m.J = fresh, None
        systems.append(fresh)
        m.r = _valid(fresh.residual, m.x)
        return True

    def _at_rest(self, m: "_Motion", control: Control) -> State | np.ndarray:
        """The equilibrium where the edges came to rest."""
        self.eq.log.event(f"the edges moved in {m.moved} steps of their overdamped motion")
        out = self._settle(m.x, control)
        if out is None:
            # at rest, the held solve meets a merge (or a split that the tension check does not
            # confirm): the equilibrium solve makes it
            self.eq.log.event("the edges came to rest next to a change of the contact set")
            return self.eq.solve(m.x, control, use_fallback=False, **self._finish)
        return out

    def _shortcut(self, m: "_Motion", control: Control) -> State | np.ndarray | None:
        """The equilibrium the motion heads for, when Newton's iteration from here reaches it
        (:func:`_newton_start`; tested again once ``max|r|`` has halved); else None."""
        if m.r is None or m.J is None:
            return None
        size = float(np.max(np.abs(m.r)))
        if size > m.tested:
            return None
        m.tested = 0.5 * size
        if m.age > 0:
            # Newton's iteration from here contracts with the Jacobian here: one aged over
            # the motion's steps (a newborn contact stiffens as it grows) tests another one
            m.J, m.age = _valid(m.system.jacobian, m.x), 0
            if m.J is None:
                return None
        start = _newton_start(m.system, m.r, m.J, m.x)
        if start is None:
            return None
        out = self._settle(start, control, trial=True)
        if out is None or (isinstance(out, State) and out.outcome is Outcome.NOT_CONVERGED):
            m.early = False
            return None
        self.eq.log.event(f"the edges moved in {m.moved} steps of their overdamped motion")
        return out

    def _advance(self, m: "_Motion", control: Control,
                 systems: "_Systems") -> State | np.ndarray | None:
        """One step of the motion, accepted or rejected by its local error; a state when the
        step ends the motion (closure, every contact detached, a contact that travels), or
        the contacts born where every contact detached and the profile penetrates."""
        if m.r is None or m.J is None:
            return self._failed(m.x, "met a contact set without a valid field")
        proposed = _proposed(m, m.r, m.J, self.tolerance)
        if proposed is None:
            return None
        move, h = proposed
        landed, changed, reason, full = repair(_vanishing(m.x, m.x + move), MIN_WIDTH, MIN_GAP)
        if full and not self.closed.possible(control):
            # full contact is no state here (the load it cannot carry, or the gap volume that a
            # penetration fixes on an incompressible solid): the step overshot a gap that the
            # motion narrows towards its equilibrium width
            m.h, m.J, m.rejected = 0.25 * h, None, True
            return None
        if full or not landed.size:
            return self._ended(landed, full, control)
        after, r, as_is = _end(self.eq, m, landed, changed, control)
        # the local error of an implicit Euler step, h²/2·X'', is h/2 times the change of
        # the speed -O r over the step (one residual a step: the one the next step needs);
        # a step taken as it is (:func:`_end`) changes the contact set: the motion's event
        error = np.inf if r is None else _local_error(m, r, as_is)
        if error > self.tolerance:
            if after is not m.system:
                systems.discard(after)      # a step not taken: its new system is let go
            if r is None and float(np.max(np.abs(move) / _scale(m.x))) <= WALL:
                # the edges have come to the edge of the model's reach (a Maugis-Dugdale zone
                # that runs across the neck to the facing edge, where the gap exceeds the
                # range): steps that creep towards it shrink to round-off
                return self._failed(m.x, "met a contact set without a valid field ("
                                         f"{self.eq.limitation or 'no field'})")
            # no field at the step's end (a Maugis-Dugdale zone's equations): a quarter step
            m.h = h * (0.25 if r is None else max(0.2, 0.9 * np.sqrt(self.tolerance / error)))
            m.J, m.rejected = None, r is not None
            return None
        _accepted(m, h, error, self.tolerance)
        held = (_held(m, r, landed, changed or after is not m.system, self._resolved)
                or _slides(m, r, landed, changed or after is not m.system))
        m.moved, m.age, m.x, m.r = m.moved + 1, m.age + 1, landed, r
        for kind, word in (("merge", "merge"), ("detachment", "detach")):
            if changed and word in reason:
                self.eq.log.records.append({"kind": kind, "control": control.value})
        _tracked(m, landed, changed)
        if after is not m.system:
            m.system, m.J = after, None
            systems.append(after)
        if held is not None:
            return self._failed(m.x, held)
        if _travels(m.track):
            return self._failed(m.x, "carries the contacts round the period: no steady "
                                     "state at this control")
        return None

    def _ended(self, landed: np.ndarray, full: bool, control: Control) -> State | np.ndarray:
        """A step that closed the contact over the period (``full``) or detached every
        contact: the state, or, where the profile still penetrates the undeformed solid at
        this penetration, the contacts born there (the motion goes on with them)."""
        if full:
            self.eq.log.event("the edges' motion closed the contact")
            return State.full_contact()
        self.eq.log.event("the edges' motion detached every contact")
        self.eq.log.records.append({"kind": "detachment", "control": control.value,
                                    "contacts": 0.0})
        if control.is_load and control.value > 0:
            # a compressive load needs a contact: found afresh from the first touch
            return self.eq.solve(landed, control, use_fallback=False, **self._finish)
        born = (None if control.is_load or not self._bear
                else self.eq.checks.births_without_contact(control))
        if born is not None:
            # no contact is no state where the profile penetrates the solid: contacts are born
            # where it does, as at any rest state of the motion (and end it the same way where
            # they were born before: they travel and vanish again)
            regions = [(a, b, None) for a, b in zip(born[0::2], born[1::2])]
            again = _born_again(self._births, np.zeros(0), regions, False)
            if again is not None:
                return attrs.evolve(self._failed(landed, again), change="reborn")
            self.eq.log.event(f"{len(born) // 2} contact(s) born where the profile penetrates "
                              "the undeformed solid")
            self.eq.log.records.append({"kind": "birth", "control": control.value,
                                        "contacts": float(len(born) // 2)})
            return born
        return State.no_contact()


def _born_again(births: list, edges, regions, snapped: bool) -> str | None:
    """Why a motion ends whose contacts, born at a rest state ``edges`` (empty: after every
    contact detached), are born again at the same rest state where they were born before (the
    motion came back to it), else None (the births are recorded in ``births``, ``(rest state,
    regions)`` pairs). Born where the gap falls below a cohesive range (``snapped``), the state
    is a cohesive zone without a contact, which the zones of this method (at the edges of
    contacts) do not represent; born where the profile penetrates, the motion is periodic: no
    steady state."""
    edges = np.asarray(edges, dtype=float)
    for rest, born in births:
        if (len(rest) == len(edges) and np.allclose(rest, edges, rtol=0, atol=1e-6)
                and any(a < b2 and a2 < b for (a, b, _) in regions for (a2, b2, _) in born)):
            return ("cycles: a contact born where the gap falls below the cohesive range does "
                    "not hold and is born there again (the gap stays within the range without "
                    "a contact: a cohesive zone that this method's zones, at the edges of "
                    "contacts, do not represent)" if snapped else
                    "comes back to a state that it left by contacts born where the profile "
                    "penetrates, and they are born there again: the motion is periodic, no "
                    "steady state at this control")
    births.append((edges, regions))
    return None


def _proposed(m: "_Motion", r: np.ndarray, J: np.ndarray,
              tolerance: float) -> tuple[np.ndarray, float] | None:
    """The move of the motion's next step from its residual ``r`` and Jacobian ``J``, and its
    length (also ``m.h``); None when the step is to be tried again shorter (``m.h``
    shortened: its linear solve failed, or its move stayed out of reach after
    :data:`REACH_TRIES` shortenings).

    The move is shortened here, without an evaluation, until it keeps within the reach the
    tolerance allows: a proposal is not a step, and only steps count against the motion's
    budget (on campaign seed 220 a contact that narrows to nothing took three proposals for
    each step, 18491 in all, and spent the budget of 2000 on them)."""
    scale = _scale(m.x)
    h = (0.05 * float(np.min(scale / np.maximum(np.abs(r), 1e-300))) if m.h is None
         else m.h)          # the first step moves the fastest edge a twentieth of a scale
    # implicit Euler damps a growing mode whose rate exceeds 1/h (and flips its sign past
    # 2/h): the step resolves the growth of every unstable mode of the motion
    h = min(h, UNSTABLE_STEP / _growth(J))
    for _ in range(REACH_TRIES):
        m.h = h
        move = _step(r, J, h)
        if move is None:
            m.h, m.J = 0.25 * h, None
            return None
        reach = float(np.max(np.abs(move) / scale)) / np.sqrt(2.0 * tolerance)
        if reach <= 1.0:
            return move, h
        # the local error h/2·|Δr| sees the residual at the step's ends only: where it is flat
        # (a Maugis-Dugdale tip below the profile holds it at -K̃c) the step would grow past
        # the equilibrium between. Speeds that change over a half-width leave a move of δ an
        # error of δ²/2 half-widths: the tolerance bounds the move itself
        h = h / reach
    m.h = h
    return None


def _end(eq, m: "_Motion", landed: np.ndarray, changed: bool, control: Control):
    """``(system, r, as_is)``: the system a step's end ``landed`` is evaluated on, the residual
    there (None: no valid field) and whether the step is taken as it is, without a local error.
    A new contact set (``changed``) gets its own system, taken as it is; the motion's first
    steps, which move the edges the most, end on the zones made for their ends (one evaluation
    where a remake after the step took a second); a step whose end has no field on the zones
    it was taken with (a cohesive zone's equations past their reach) is evaluated on zones
    made for it, if they differ, and taken as it is."""
    if changed:
        after = eq.system(control, landed)
        return after, _valid(after.residual, landed), True
    early = m.early and m.moved < REZONED
    fresh = _fresh(eq, m.system, landed, control) if early else None
    after = m.system if fresh is None else fresh
    r = _valid(after.residual, landed)
    if r is None and not early:
        fresh = _fresh(eq, m.system, landed, control)
        if fresh is not None:
            return fresh, _valid(fresh.residual, landed), True
    return after, r, False


def _fresh(eq, system, x: np.ndarray, control: Control):
    """A new edge system for ``x`` when the mesh zones or element counts of ``system``
    are not those ``x`` is given (the edges moved out of them), else None."""
    counts = eq.policy.counts_for(x)
    if (counts is None or system.counts is None or tuple(counts) == tuple(system.counts)) \
            and same_zones(system.zones, zone_patterns(x, eq.spec, system.counts)):
        return None
    return eq.system(control, x)


def _newton_start(system, r, J, x) -> np.ndarray | None:
    """Newton's step from ``x`` when the motion ends at the root it heads for: every mode
    of the motion decays, the step is within :data:`NEWTON_REACH` half-widths and keeps
    the contact set, and a second (simplified) step from there is at most
    :data:`NEWTON_CONTRACTION` times the first, so that the state lies where the
    linearisation holds and the flow, like Newton's iteration, converges to that root; a
    state at a fold, whose root is gone, fails the contraction. One residual evaluation;
    None when the test fails."""
    if _growth(J) > 1e-300:
        return None
    try:
        first = np.linalg.solve(J, -r)
    except np.linalg.LinAlgError:
        return None
    scale = _scale(x)
    step = float(np.max(np.abs(first) / scale))
    if not step <= NEWTON_REACH:
        return None
    landed, changed, _, full = repair(x + first, MIN_WIDTH, MIN_GAP)
    if changed or full:
        return None
    r1 = _valid(system.residual, landed)
    if r1 is None:
        return None
    try:
        second = np.linalg.solve(J, -r1)
    except np.linalg.LinAlgError:
        return None
    if float(np.max(np.abs(second) / scale)) > NEWTON_CONTRACTION * step:
        return None
    return landed


def _vanishing(before: np.ndarray, after: np.ndarray) -> np.ndarray:
    """``after``, with every contact that narrowed to less than the shortest length the mesh
    resolves (:data:`~.meshing.SMALLEST_RESOLVED`) collapsed to its middle, where
    :func:`~viscocontact.contact.topology.repair` detaches it. Below that width the residuals
    are not resolved: on a glassy solid (campaign seed 150) a contact 2e-7 wide gave residuals
    of the wrong sign, one 6e-8 wide residuals that a move of 1e-13 of its position changed by
    171, and the motion wandered there for 2000 steps. A contact born that narrow is kept while
    it grows."""
    out = after.copy()
    width = after[1::2] - after[0::2]
    gone = (width < SMALLEST_RESOLVED) & (width < before[1::2] - before[0::2])
    middle = 0.5 * (after[0::2] + after[1::2])
    out[0::2][gone] = middle[gone]
    out[1::2][gone] = middle[gone]
    return out


def _accepted(m: "_Motion", h: float, error: float, tolerance: float) -> None:
    """The step after an accepted one, ``h`` long, of local error ``error``. It does not grow
    after a rejected one (Hairer, Nørsett & Wanner I, II.4: while the edges accelerate, a grown
    step is rejected again), and the error's growth since the last step is taken to go on
    (Gustafsson's predictive controller, Hairer & Wanner IV.8): past a fold the edges
    accelerate for several steps."""
    grow = 0.9 * np.sqrt(tolerance / max(error, 1e-300))
    if m.last is not None and error > 0.0:
        grow = min(grow, grow * (h / m.last[1]) * np.sqrt(m.last[0] / error))
    m.last = (error, h) if error > 0.0 else None
    m.h, m.rejected = h * min(1.0 if m.rejected else 4.0, grow), False


def _local_error(m: "_Motion", r: np.ndarray, changed: bool) -> float:
    """The local error of the step to the residual ``r``, in half-widths (0 for a step
    that changes the contact set)."""
    if changed or m.h is None or m.r is None:
        return 0.0
    return float(np.max(0.5 * m.h * np.abs(r - m.r) / _scale(m.x)))


def _tracked(m: "_Motion", landed: np.ndarray, changed: bool) -> None:
    """The accepted state's total width, mean edge position and edge count appended to the
    motion's track (which starts again with a new contact set)."""
    m.track.append((float(np.sum(landed[1::2] - landed[0::2])), float(np.mean(landed)),
                    len(landed)))
    if changed:
        m.track = m.track[-1:]


def _held(m: "_Motion", r: np.ndarray, landed: np.ndarray, changed: bool,
          resolved: Callable[["_Motion"], float]) -> str | None:
    """Why the motion stops at an edge held at a jump of its residual across zero, or None.

    A step that changes the sign of an edge's residual by more than :data:`JUMP` times the
    change its Jacobian predicts may have crossed a discontinuity instead of a root. Once the
    same edge has crossed it both ways while every other edge is at rest (``max|r|`` within
    :data:`SETTLED` times ``resolved(m)``, where the motion ends), the last crossing is
    narrowed down (:func:`_jump`); where the residual keeps its change across a bracket a
    thousand times narrower, the flow on either side points at a jump (a Filippov equilibrium
    of the discontinuous motion): the edge stays there, at a residual that does not vanish,
    and the motion cycles round it. The balance has no root there. With the energy balance
    over a finite advance δX this is where ``K̃`` changes sign: the residual is signed with
    ``K̃`` and the release over δX does not vanish with it, and where it reaches the work of
    adhesion the edge holds there (``docs/edges.md``). The record starts again with each
    contact set or mesh (``changed``)."""
    if changed or m.r is None or m.J is None or np.shape(r) != np.shape(m.r):
        m.jumps = {}
        return None
    crossed = _crossed(m, r, landed)
    for i in np.flatnonzero(crossed):
        sides = m.jumps.setdefault(int(i), set())
        sides.add(float(np.sign(r[i])))
        others = float(np.max(np.abs(np.delete(r, i)), initial=0.0))
        if len(sides) < 2 or others > SETTLED * resolved(m):
            continue
        with m.system.probing():
            ends = _jump(m.system, landed, int(i), float(m.x[i]))
        if ends is not None:
            return (f"holds edge {i + 1} at {landed[i]:.8g}, where its residual jumps across "
                    f"zero (from {min(ends):.3g} to {max(ends):.3g}) instead of passing "
                    "through it: its balance has no root there, outside the model "
                    "(docs/edges.md)")
    return None


def _crossed(m: "_Motion", r: np.ndarray, landed: np.ndarray) -> np.ndarray:
    """The edges whose residual changed sign over the step from ``m.x`` to ``landed`` by more
    than :data:`JUMP` times the change the motion's Jacobian predicts: a jump crossed, or a
    root the Jacobian misjudged."""
    assert m.r is not None and m.J is not None
    linear = np.abs(m.J @ (landed - m.x))
    return (np.sign(r) != np.sign(m.r)) & (np.abs(r - m.r) > JUMP * linear)


def _slides(m: "_Motion", r: np.ndarray, landed: np.ndarray, changed: bool) -> str | None:
    """Why the motion stops where it slides along the filling of a neck by cohesive zones, or
    None.

    Zones at the edges of contacts (Maugis-Dugdale) either stop short of each other or fill
    their neck together; where the zones' equations switch from one to the other as the edges
    move, every edge's residual jumps. A step across which an edge's residual changes sign by
    more than :data:`JUMP` times the change the Jacobian predicts, and the necks filled change,
    crossed that switch; when the next accepted step crosses back, the same edge's residual
    returning to its sign before, the flow on each side points at the switch and the motion
    slides along it (a Filippov sliding mode, which the steps follow by crossing back and
    forth at a crawl: 2000 steps on the thesis rough profile at ζ = 1e-2, p̃∞ = 0.3, range
    1e-7 m). A state on the switch is a neck that a cohesive zone apart from the contacts fills
    in part, which zones at the edges of contacts do not represent: the motion ends there,
    where the crossing back is a jump (:func:`_jump_between`: the change stays while its
    bracket is narrowed :data:`NARROWED` times), not a steep root."""
    before, m.crossed = m.crossed, None
    if changed or m.r is None or m.J is None or np.shape(r) != np.shape(m.r):
        return None
    crossing = _crossed(m, r, landed)
    if not np.any(crossing):
        return None
    with m.system.probing():
        necks = [_filled_necks(m.system, y) for y in (m.x, landed)]
    if necks[0] is None or necks[1] is None or np.array_equal(necks[0], necks[1]):
        return None
    m.crossed = (m.x.copy(), m.r.copy())
    if before is None or np.shape(before[1]) != np.shape(r):
        return None
    back = crossing & (np.sign(r) == np.sign(before[1]))
    for i in np.flatnonzero(back):
        with m.system.probing():
            ends = _jump_between(m.system, m.x, landed, int(i))
        if ends is not None:
            return (f"slides along the filling of a neck by cohesive zones (edge {i + 1} at "
                    f"{landed[i]:.8g}, its residual jumping from {min(ends):.3g} to "
                    f"{max(ends):.3g}), where the flow on both sides points at it: the state "
                    "there is a neck that a cohesive zone apart from the contacts fills in "
                    "part, which zones at the edges of contacts do not represent")
    return None


def _filled_necks(system, x: np.ndarray) -> np.ndarray | None:
    """Which zones fill their neck in the field at the edges ``x`` (None: no zones there)."""
    fields = system.evaluate(x)[0]
    if fields is None or fields.loads is None:
        return None
    return filled(fields.mesh.edges, np.asarray(fields.loads.width, dtype=float))


def _jump_between(system, a: np.ndarray, b: np.ndarray, i: int) -> tuple[float, float] | None:
    """The residuals of edge ``i`` either side of the jump on the segment from the edges ``a``
    to ``b`` (all edges move), or None where it is a root (:func:`_bisected`)."""
    return _bisected(system, lambda s: a + s * (b - a), i)


def _jump(system, x: np.ndarray, i: int, other: float) -> tuple[float, float] | None:
    """The residuals of edge ``i`` either side of the jump between its positions ``x[i]`` and
    ``other`` (the other edges at ``x``), or None where it is a root (:func:`_bisected`)."""
    start = float(x[i])

    def point(s: float) -> np.ndarray:
        y = x.copy()
        y[i] = start + s * (other - start)
        return y
    return _bisected(system, point, i)


def _bisected(system, point: Callable[[float], np.ndarray],
              i: int) -> tuple[float, float] | None:
    """The residuals of edge ``i`` either side of the sign change of its residual between the
    edges ``point(0)`` and ``point(1)``, or None where it is a root: the sign change is
    bisected to a :data:`NARROWED` th of the path, over which a residual with a slope changes
    by as much less, while a jump keeps at least half its change. None also where an
    evaluation fails or the ends have the same sign."""
    lo, hi, values = 0.0, 1.0, []
    for s in (lo, hi):
        r = _valid(system.residual, point(s))
        if r is None:
            return None
        values.append(float(r[i]))
    change = values[1] - values[0]
    if values[0] * values[1] >= 0.0:
        return None
    while hi - lo > 1.0 / NARROWED and np.any(
            np.abs(point(hi) - point(lo)) > 4 * np.spacing(np.abs(point(hi)))):
        mid = 0.5 * (lo + hi)
        r = _valid(system.residual, point(mid))
        if r is None or r[i] == 0.0:
            return None
        if (r[i] < 0.0) == (values[0] < 0.0):
            lo, values[0] = mid, float(r[i])
        else:
            hi, values[1] = mid, float(r[i])
    return (values[0], values[1]) if abs(values[1] - values[0]) >= 0.5 * abs(change) else None


def _travels(track: list) -> bool:
    """Whether the contacts have moved round a whole period of the profile without
    settling: a contact that travels along the profile (a trailing edge that drags it), which
    a steady state does not do."""
    return len(track) > 1 and abs(track[-1][1] - track[0][1]) > TWO_PI


def _valid(evaluate, x):
    """``evaluate(x)`` (a system's residual or Jacobian), or None where ``x`` is no valid
    contact set or the value is not finite."""
    try:
        value = evaluate(x)
    except TopologyChange:
        return None
    return value if value is not None and np.all(np.isfinite(value)) else None


def _growth(J) -> float:
    """The fastest growth rate of the linearised motion ``dδ/dt = -O J δ`` (0 when every
    mode decays)."""
    o = np.tile([-1.0, 1.0], len(J) // 2)
    try:
        rates = -np.linalg.eigvals(o[:, None] * J).real
    except np.linalg.LinAlgError:
        return 0.0
    return float(max(rates.max(initial=0.0), 1e-300))


def _step(r, J, h):
    """The linearly implicit Euler move ``δ`` of ``dX/dt = -O r`` over ``h``."""
    o = np.tile([-1.0, 1.0], len(r) // 2)
    a = np.eye(len(r)) / h + o[:, None] * J
    try:
        move = np.linalg.solve(a, -o * r)
    except np.linalg.LinAlgError:
        return None
    return move if np.all(np.isfinite(move)) else None
