r"""The history of a cohesive spectral solve: the approach from first touch on the first grid of
the ladder, the finer grids from the coarser one's solution (:func:`cohesive_grid_solve`), and
the approach's record in the result (:func:`record_approach`)."""
from __future__ import annotations

import attrs

from .approach import ApproachSettings, approach
from .cohesive import CohesiveSolution, GridLaw, cohesive_solve
from .grid import UniformGrid


def cohesive_grid_solve(op, grid: UniformGrid, law: GridLaw, load, pen, start,
                        start_penetration, *, options: dict, settings: ApproachSettings,
                        first: bool, warm: bool = False,
                        history: dict | None = None) -> CohesiveSolution:
    """A cohesive grid solve of the ladder (:func:`~.cohesive.cohesive_solve`).

    On the first grid it follows the approach from first touch (:func:`~.approach.approach`;
    its states and events into ``history``); with a warm start, it starts from its contacts
    under the cohesive stress, whose zones then grow (so that another method's equilibrium, a
    merged contact that adhesion holds, is checked as it is); on the finer grids, from the
    coarser grid's solution carried over.

    Parameters
    ----------
    op : Circulant
        The grid's operator.
    grid : UniformGrid
    law : GridLaw
    load, pen : float or None
        The control: ``p̃∞`` or ``Δ̃`` (the other None).
    start : ndarray
        Starting cell pressure (a warm start's loaded cells, or the coarser grid's pressure).
    start_penetration : float or None
        ``Δ̃`` of the coarser grid's solution.
    options : dict
        The options of every grid solve (tolerances, iteration counts, workers).
    settings : ApproachSettings
        The approach's step and event settings.
    first : bool
        Whether this is the ladder's first grid.
    warm : bool
        Whether ``start`` is a warm start's.
    history : dict, optional
        Receives the approach's states, events, solves, cells and event texts.
    """
    def solve(p, delta, penetration=None, mean_pressure=None, contact=None):
        return cohesive_solve(op, grid.heights, law, mean_pressure=mean_pressure,
                              penetration=penetration, start=p, start_penetration=delta,
                              start_contact=contact, **options)

    control = dict(mean_pressure=load) if load is not None else dict(penetration=pen)
    if first and warm:
        return solve(start, None, contact=start > 0, **control)
    if not first:
        return solve(start, start_penetration, **control)
    path = approach(solve, law, grid.heights, settings=settings, **control)
    if history is not None:
        history.update(states=[s.to_dict() for s in path.history],
                       events=[e.to_dict() for e in path.events], solves=path.solves,
                       points=grid.points, texts=[e.text() for e in path.events])
    sol = path.solved.solution
    return attrs.evolve(path.solved, solution=attrs.evolve(
        sol, iterations=path.iterations, applications=path.applications))


def record_approach(history: dict, events, extras: dict) -> None:
    """The approach's events into the event log, its states and typed events into
    ``extras["history"]`` and ``extras["path_events"]``."""
    for text in history.pop("texts"):
        events.append(text)
    events.append(f"approach from first touch on {history['points']} cells: "
                  f"{history['solves']} steps, {len(history['events'])} events")
    extras["history"] = history.pop("states")
    extras["path_events"] = history.pop("events")
