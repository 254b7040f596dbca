r"""The approach history of a cohesive grid solve: quasi-static loading from first touch.

A cohesive law is non-convex (its traction jumps at ``g = η``), so a scene can have several
equilibria; which one a solid is in depends on how it got there. The project's default history
is the approach: the solid pressed on slowly from first touch to the target, as the
boundary-element method follows it (:mod:`viscocontact.methods.bem.approach`). On the grid the
approach is a continuation in the penetration ``Δ̃``:

* it starts where the law first acts, ``Δ̃ = -η`` (the highest peak's gap at the range, no
  stress: the solid is flat and unloaded there);
* each **step** is a cohesive grid solve (:func:`~.cohesive.cohesive_solve`) at the next ``Δ̃``
  started from the last accepted state; it is accepted when it converged and kept the
  **structure** of the state (the runs of cells in contact and of cells in range), and the next
  step is then twice as long, up to :attr:`ApproachSettings.path_step`;
* a step that fails, or that changed the structure (a contact born, contacts merged, a zone
  born or gone, a snap into contact), is halved, until it is
  :attr:`ApproachSettings.smallest` long: the change is then an **event**, located to that
  resolution and recorded (:class:`PathEvent`), and the state past it is accepted;
* under load control the path goes on in ``Δ̃`` until the load reaches the target, and a
  load-controlled solve from the last state below it and the first at or above it, each a
  step away, ends it at the target load.

So the state reached is that of the history, converged as the path step shrinks (the same
answer at half the step: ``tests/unit/methods/test_spectral_approach.py``), not of a search
order. The states accepted along the way are the history (:class:`PathState`).
"""
from __future__ import annotations

from typing import Callable

import attrs
import numpy as np

from ..._validation import in_range, int_range
from .cohesive import CohesiveSolution, GridLaw
from .edges import runs
from .solvers import GridSolution


@attrs.frozen(kw_only=True)
class ApproachSettings:
    """The settings of the approach's continuation (one frozen object).

    Parameters
    ----------
    path_step : float
        Largest step of ``Δ̃`` (in units of the amplitude), in ``[1e-4, 1]``.
    resolution : float
        An event is located to this fraction of ``path_step``, in ``[1e-6, 1]``.
    max_steps : int
        Most grid solves along the path (a path that needs more fails and says so).
    """

    path_step: float = attrs.field(default=0.05, validator=in_range(1e-4, 1.0))
    resolution: float = attrs.field(default=1.0 / 256.0, validator=in_range(1e-6, 1.0))
    max_steps: int = attrs.field(default=2000, validator=int_range(1, 10**6))

    @property
    def smallest(self) -> float:
        """The shortest step: an event's location to this length of ``Δ̃``."""
        return self.path_step * self.resolution


@attrs.frozen(kw_only=True)
class PathState:
    """One accepted state of the path: control, load and structure."""

    penetration: float
    mean_pressure: float
    contacts: int       # runs of cells in contact
    zones: int          # runs of cells in range (contact with its zones, or a zone alone)
    contact_cells: int
    cohesive_cells: int

    def to_dict(self) -> dict:
        return attrs.asdict(self)


@attrs.frozen(kw_only=True)
class PathEvent:
    """A change of structure within a step of ``smallest`` length: ``before`` → ``after``."""

    penetration: float
    step: float
    before: PathState
    after: PathState

    @property
    def kind(self) -> str:
        b, a = self.before, self.after
        if a.contact_cells == 0 and b.contact_cells == 0:
            return "zone change"
        if b.contacts == a.contacts and b.zones == a.zones:
            return "jump"
        if a.contacts > b.contacts:
            return "contact born"
        if a.contacts < b.contacts:
            return "contacts merged" if a.contact_cells >= b.contact_cells else "contact lost"
        return "zones merged" if a.zones < b.zones else "zone born"

    def to_dict(self) -> dict:
        return {"kind": self.kind, "penetration": self.penetration, "step": self.step,
                "before": self.before.to_dict(), "after": self.after.to_dict()}

    def text(self) -> str:
        b, a = self.before, self.after
        return (f"approach: {self.kind} at Δ̃ = {self.penetration:.6g} (located to "
                f"{self.step:.2g}): contacts {b.contacts} → {a.contacts}, runs in range "
                f"{b.zones} → {a.zones}, contact cells {b.contact_cells} → {a.contact_cells}")


@attrs.frozen(kw_only=True, eq=False)
class ApproachOutcome:
    """The state at the target, the history and the events, the counts over every solve."""

    solved: CohesiveSolution
    history: tuple
    events: tuple
    solves: int
    iterations: int
    applications: int


def state_of(solved: CohesiveSolution) -> PathState:
    """The :class:`PathState` of a cohesive grid solution."""
    sol = solved.solution
    inside = solved.weights > 0
    return PathState(penetration=float(sol.penetration), mean_pressure=float(sol.pressure.mean()),
                     contacts=len(runs(solved.contact)) if solved.contact.any() else 0,
                     zones=len(runs(inside)) if inside.any() else 0,
                     contact_cells=int(solved.contact.sum()),
                     cohesive_cells=int(np.sum(inside & ~solved.contact)))


def _same_structure(a: PathState, b: PathState) -> bool:
    return a.contacts == b.contacts and a.zones == b.zones


Solve = Callable[..., CohesiveSolution]


def approach(solve: Solve, law: GridLaw, heights, *, penetration=None, mean_pressure=None,
             settings: ApproachSettings = ApproachSettings()) -> ApproachOutcome:
    """The approach from first touch to the target (module docstring).

    Parameters
    ----------
    solve : callable
        ``solve(start, start_penetration, penetration=..., mean_pressure=..., contact=None)``: a
        cohesive grid solve (:func:`~.cohesive.cohesive_solve` on the grid) from the pressure
        ``start`` (and, for a snap, from the contact set ``contact``).
    law : GridLaw
    heights : ndarray
        ``r̃`` at the cell centres.
    penetration, mean_pressure : float
        Exactly one: the target ``Δ̃`` or ``p̃∞``.
    settings : ApproachSettings
    """
    return _Approach(solve, law, heights, settings).run(penetration, mean_pressure)


class _Approach:
    """The continuation of one :func:`approach`: the last accepted state, the history, the
    events and the counts of the grid solves."""

    def __init__(self, solve: Solve, law: GridLaw, heights, settings: ApproachSettings):
        self.solve, self.law, self.settings = solve, law, settings
        start = -law.opening
        r = np.asarray(heights, dtype=float)
        n = r.size
        first = GridSolution(pressure=np.zeros(n), penetration=start, converged=True,
                             residual=0.0, iterations=0, applications=0, solver="none",
                             message="first touch")
        self.current = CohesiveSolution(solution=first, contact=np.zeros(n, bool),
                                        weights=np.zeros(n), gap=1.0 - r - start, sets=0)
        self.state = state_of(self.current)
        self.history: list[PathState] = [self.state]
        self.events: list[PathEvent] = []
        self.counts = [0, 0, 0]

    def _counted(self, out: CohesiveSolution) -> CohesiveSolution:
        self.counts[0] += 1
        self.counts[1] += out.solution.iterations
        self.counts[2] += out.solution.applications
        return out

    def _from(self, start: CohesiveSolution, **control) -> CohesiveSolution:
        sol = start.solution
        return self._counted(self.solve(sol.pressure, sol.penetration, **control))

    def _snap(self, aim: float) -> CohesiveSolution:
        """No equilibrium near the branch: the cells that the step brings within the range
        snap into contact (the boundary-element method's rule), and the zones grow from them."""
        sol = self.current.solution
        reach = self.current.contact | (self.current.gap - (aim - sol.penetration)
                                        < self.law.opening)
        return self._counted(self.solve(sol.pressure, sol.penetration, penetration=aim,
                                        contact=reach))

    def _outcome(self, solved, message=None) -> ApproachOutcome:
        if message is not None:
            sol = solved.solution
            solved = attrs.evolve(solved, solution=attrs.evolve(
                sol, converged=False, message=f"approach: {message}"))
        return ApproachOutcome(solved=solved, history=tuple(self.history),
                               events=tuple(self.events), solves=self.counts[0],
                               iterations=self.counts[1], applications=self.counts[2])

    def _shorter(self, step: float) -> float | None:
        """Half the step, or None when it is already the shortest."""
        smallest = self.settings.smallest
        return None if step <= smallest * (1.0 + 1e-9) else max(0.5 * step, smallest)

    def run(self, penetration, mean_pressure) -> ApproachOutcome:
        load = mean_pressure is not None
        step = self.settings.path_step
        while True:
            here = self.state.penetration
            if not load and here >= penetration:
                return self._outcome(self.current)
            aim = here + step if load else min(here + step, float(penetration))
            trial = self._from(self.current, penetration=aim)
            if self.counts[0] >= self.settings.max_steps:
                return self._outcome(trial, f"{self.settings.max_steps} solves before the "
                                            "target")
            new = state_of(trial) if trial.solution.converged else None
            smooth = new is not None and _same_structure(self.state, new)
            shorter = None if smooth else self._shorter(step)
            if shorter is not None:
                step = shorter
                continue
            if new is None:
                trial = self._snap(aim)
                if not trial.solution.converged:
                    return self._outcome(trial, f"no equilibrium at Δ̃ = {aim:.6g} within a "
                                                f"step of {step:.2g}, nor after a snap into "
                                                f"contact: {trial.solution.message}")
                new = state_of(trial)
            if not smooth:
                self.events.append(PathEvent(penetration=aim, step=step, before=self.state,
                                             after=new))
            if load and new.mean_pressure >= mean_pressure:
                final = self._to_load(trial, new, mean_pressure)
                shorter = self._shorter(step)
                if final.solution.converged or shorter is None:
                    return self._outcome(final, None if final.solution.converged else
                                         f"no equilibrium at p̃∞ = {mean_pressure:g} from the "
                                         f"states at Δ̃ = {here:.6g} and {aim:.6g}")
                step = shorter
                continue
            self.current, self.state = trial, new
            self.history.append(new)
            if smooth:
                step = min(2.0 * step, self.settings.path_step)

    def _to_load(self, trial, new: PathState, load: float) -> CohesiveSolution:
        """The target load lies within the last step: a load-controlled solve from the nearer
        of the states on either side (into the history when it converges)."""
        nearer = (self.current if load - self.state.mean_pressure < new.mean_pressure - load
                  else trial)
        final = self._from(nearer, mean_pressure=load)
        if final.solution.converged:
            self.history.append(state_of(final))
        return final
