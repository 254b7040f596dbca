"""Certification: a point is converged in the step of the continuation that reached it.

The continuation that realises a history chooses its own steps from an error control,
independent of the ζ or loads a study records: the approach's largest penetration step
(:attr:`~viscocontact.problem.Discretization.path_step`) and the speed ramp's step tolerance
(:attr:`~viscocontact.studies.history.SpeedRamp.tolerance`). A study with ``certify=True``
solves every adhesive point a second time under the same history with a tenth of that
tolerance and records whether the two agree (the ``certified`` column) and the finer run's area
and friction (``certified_area``, ``certified_friction``):

* approach: the point's problem with ``path_step / 10``, from first touch;
* speed ramp: a second ramp over the same recorded ζ with :meth:`SpeedRamp.refined` ``(10)``,
  from the chain's first point reached by the approach with ``path_step / 10``; its path state
  between recorded points is the ``certified_ramp`` column, so a resumed study continues it.

Adhesionless equilibria are unique (their history does not change them): they are not certified.
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping

import attrs

#: The finer run's tolerance is the history's divided by this.
REFINEMENT = 10.0

#: The acceptance tolerances of the project for a published curve: the contact length Ã to 1e-3
#: of itself, relative to max(Ã, 0.1) so that a vanishing contact is held to an absolute 1e-4
#: (a tenth of a percent of a contact of 0.1, the smallest the figures resolve) ...
AREA_TOLERANCE = 1e-3
AREA_FLOOR = 0.1
#: ... and the friction coefficient μ to 1e-2 of itself, relative to max(|μ|, 0.01) (μ vanishes
#: in the elastic limits, where an absolute 1e-4 is below what a curve of μ shows).
FRICTION_TOLERANCE = 1e-2
FRICTION_FLOOR = 0.01

#: The record columns of a certification, with their values for a point not certified.
CERTIFY_COLUMNS: dict[str, Any] = {"certified": False, "certified_area": math.nan,
                                   "certified_friction": math.nan, "certified_ramp": ""}


#: ``reach(problem, history, ramp_state) -> (result, ramp_state)`` (:func:`certification`).
Reach = Callable[[Any, Any, str], tuple[Any, str]]


def agrees(area: float, friction: float, fine_area: float, fine_friction: float) -> bool:
    """Whether a point (``area``, ``friction``) agrees with its finer run within
    :data:`AREA_TOLERANCE` and :data:`FRICTION_TOLERANCE` (relative to the finer run's values,
    floored at :data:`AREA_FLOOR` and :data:`FRICTION_FLOOR`); False for a non-finite value.

    >>> agrees(1.0, 0.2, 1.0005, 0.201)
    True
    >>> agrees(1.0, 0.2, 1.002, 0.2)
    False
    """
    values = (area, friction, fine_area, fine_friction)
    if not all(math.isfinite(float(v)) for v in values):
        return False
    return (abs(area - fine_area) <= AREA_TOLERANCE * max(abs(fine_area), AREA_FLOOR)
            and abs(friction - fine_friction)
            <= FRICTION_TOLERANCE * max(abs(fine_friction), FRICTION_FLOOR))


def finer(problem):
    """``problem`` with a tenth of its approach's path step."""
    disc = problem.discretization
    return attrs.evolve(problem, discretization=attrs.evolve(
        disc, path_step=disc.path_step / REFINEMENT))


def certification(problem, spec, result, reach: Reach) -> dict[str, Any]:
    """The certification columns of a point (``result`` of ``problem``, reached under
    ``spec.history``) and ``note``: why it is not certified (empty when it is).

    ``reach(problem, history, ramp_state)`` is ``(result, state)``: the point of ``problem``
    reached under ``history`` (a speed ramp continued from ``ramp_state``, empty for the
    chain's first point) and the ramp's state after it. A speed ramp's finer run goes on even
    when the point failed, so that the certifying chain continues with the next point.
    """
    from .history import SpeedRamp, history

    out = dict(CERTIFY_COLUMNS)
    stated = history(dict(spec.history))
    if not isinstance(stated, SpeedRamp) and not result.converged:
        return out | {"note": ""}
    tighter = stated.refined(REFINEMENT) if isinstance(stated, SpeedRamp) else stated
    try:
        fine, out["certified_ramp"] = reach(finer(problem), tighter, spec.certified_ramp)
    except Exception as exc:      # the point stands; its certification says why it failed
        return out | {"note": f"not certified: the finer run raised {type(exc).__name__}: {exc}"}
    if not result.converged:
        return out | {"note": ""}
    if not fine.converged:
        return out | {"note": f"not certified: the finer run did not converge ({fine.message})"}
    area, friction = float(fine.area), float(fine.friction)
    ok = agrees(float(result.area), float(result.friction), area, friction)
    out.update(certified=ok, certified_area=area, certified_friction=friction)
    note = "" if ok else (f"not certified: with a tenth of the history's tolerance Ã = "
                          f"{area:.6g} (here {float(result.area):.6g}), μ = {friction:.6g} "
                          f"(here {float(result.friction):.6g})")
    return out | {"note": note}


def failed(record: Mapping[str, Any], certify: bool) -> bool:
    """Whether a record of a study with ``certify`` is an adhesive point that converged but was
    not certified."""
    return (bool(certify) and record.get("variant") == "adhesive"
            and bool(record.get("converged")) and not bool(record.get("certified", False)))
