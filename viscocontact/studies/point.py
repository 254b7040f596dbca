"""The unit of work of every study: one equilibrium, a pure function of plain data.

:func:`solve_point` takes the complete scene of the point (a plain dict, as
:meth:`~viscocontact.scene.Scene.to_dict` writes it), a :class:`PointSpec` (bookkeeping and
discretization) and the contact set to start from, and returns one :data:`record <COLUMNS>` — a
flat dict of plain values with a fixed schema. Nothing else enters the computation, so a point gives
the same bits in this process, in a process pool or on a Dask worker (BLAS runs single-threaded
during the solve, see :func:`~viscocontact.studies.parallel.single_blas_thread`), and a resumed
study continues from the stored edges exactly as an uninterrupted one would.

A point that raises is not lost: its record has ``status = "error"`` and the exception as message.
"""
from __future__ import annotations

import collections
import functools
import json
import math
import threading
import time
from typing import Any, Iterable, Mapping

import attrs
import numpy as np

from ..errors import TimeLimitExceeded
from .certify import CERTIFY_COLUMNS

#: Record columns written for every point: name -> kind (``int``, ``float``, ``bool``, ``str`` or
#: ``edges``, a flattened ``[X̃_start, X̃_end, ...]`` array of variable length).
COLUMNS: dict[str, str] = {
    # where the point sits in the study
    "chain": "int", "step": "int", "phase": "str", "started_from": "str",
    "variant": "str", "seed": "int", "gamma": "float", "load": "float",
    "zeta": "float", "control": "str", "target": "float",
    # the result (ContactResult's scalar keys; status "error" when the solve raised)
    "status": "str", "converged": "bool", "message": "str",
    "area": "float", "mean_pressure": "float", "penetration": "float", "friction": "float",
    "reduced_friction": "float", "n_contacts": "int", "full_contact": "bool",
    "residual": "float", "iterations": "int", "function_evaluations": "int",
    "edge_perturbation": "float", "min_gap": "float", "seconds": "float", "edges": "edges",
    # the solution method that computed the point and its error estimate
    "method": "str", "error_estimate": "float",
    # the history that reached the point (studies.history), the events met on the way since the
    # chain's previous point (a JSON list of typed records) and the speed ramp's path state
    "history": "str", "events": "str", "ramp": "str",
    # areal scenes ([surface]; NaN, -1 or "" for a profile): area fraction, mean gap, dissipated
    # power, the contact patches (area-weighted means and the size distribution as JSON), the
    # cells per cohesive zone and the finest grid
    "area_fraction": "float", "mean_gap": "float", "dissipated_power": "float",
    "friction_dissipation": "float", "patch_mean_area": "float", "patch_largest_area": "float",
    "patch_elongation": "float", "patch_orientation": "float", "patch_alignment": "float",
    "percolating": "int", "cells_per_zone": "float", "grid": "str", "patch_areas": "str",
    # a study with certify=True (studies.certify): whether the point agrees with the same point
    # under its history with a tenth of the tolerance, that run's Ã and μ (NaN: not certified)
    # and a certifying speed ramp's path state
    "certified": "bool", "certified_area": "float", "certified_friction": "float",
    "certified_ramp": "str",
}

#: Columns added after the first study-file format, with the value a file written before them
#: reads as (``""``: the method was not recorded; it was the BEM).
LATER_COLUMNS: dict[str, Any] = {"method": "", "error_estimate": float("nan"), "history": "",
                                 "events": "[]", "ramp": "",
                                 **{k: float("nan") for k in (
                                     "area_fraction", "mean_gap", "dissipated_power",
                                     "friction_dissipation", "patch_mean_area",
                                     "patch_largest_area", "patch_elongation",
                                     "patch_orientation", "patch_alignment", "cells_per_zone")},
                                 "percolating": -1, "grid": "", "patch_areas": "[]",
                                 **CERTIFY_COLUMNS}

#: The columns only an areal scene fills.
AREAL_COLUMNS = tuple(k for k in LATER_COLUMNS if k not in (
    "method", "error_estimate", "history", "events", "ramp", *CERTIFY_COLUMNS))

#: Columns that depend on the machine's speed, not on the numerics (left out of comparisons).
TIMING_COLUMNS = ("seconds",)

#: ``started_from`` values.
FIRST_TOUCH, NEIGHBOUR, NO_CONTACT, RAMP = "first touch", "neighbour", "no contact", "speed ramp"

ERROR = "error"

#: The former name of the time-limit error (0.1.0); a point past its limit raises
#: :class:`~viscocontact.errors.TimeLimitExceeded`, recorded as its message.
PointTimeout = TimeLimitExceeded


def _as_tuple(values: Iterable[float]) -> tuple:
    """A typed ``tuple`` converter (mypy reads a bare ``tuple`` as ``Iterable[_T_co]``)."""
    return tuple(values)


@attrs.frozen(kw_only=True)
class PointSpec:
    """What a point needs besides its scene.

    Parameters
    ----------
    chain, step : int
        Position of the point: index of its chain in the study and of the point along the chain.
    phase : str
        ``"sweep"``, ``"approach"`` or ``"retract"``.
    started_from : str
        ``"first touch"`` (the approach path of :meth:`ContactProblem.solve` with no initial
        contact set), ``"neighbour"`` (the edges of the previous point of the chain) or
        ``"no contact"`` (an empty contact set: contacts are born where the profile penetrates)
        or ``"speed ramp"`` (recorded from the path of a speed ramp, see ``ramp``).
    fields : bool
        Also return pressure, displacement and gap on the check grid.
    discretization : dict or None
        Keyword arguments of :class:`~viscocontact.problem.Discretization` (default mesh if None).
    labels : dict
        The chain's labels copied into the record (``variant``, ``seed``, ``gamma``, ``load``).
    history : dict
        The history that reaches the point (:func:`~viscocontact.studies.history.history`
        params): ``{"name": "approach"}`` or a speed ramp with its tolerance.
    ramp : str
        The speed ramp's path state after the chain's previous point (JSON of
        :class:`~viscocontact.studies.ramp.RampState`; empty for the chain's first point).
    certify : bool
        Also solve the point under its history with a tenth of the tolerance
        (:mod:`~viscocontact.studies.certify`).
    certified_ramp : str
        The certifying speed ramp's path state after the chain's previous point.
    """

    chain: int
    step: int
    phase: str
    started_from: str = FIRST_TOUCH
    fields: bool = False
    discretization: Mapping[str, Any] | None = None
    labels: Mapping[str, Any] = attrs.field(factory=dict)
    history: Mapping[str, Any] = attrs.field(factory=lambda: {"name": "approach"})
    ramp: str = ""
    certify: bool = False
    certified_ramp: str = ""


def solve_point(scene: Mapping[str, Any], spec: PointSpec,
                initial=None,
                time_limit: float | None = None) -> dict[str, Any]:
    """Solve one point; never raises for a failing solve.

    Parameters
    ----------
    scene : dict
        The full scene of this point (``Scene.to_dict()`` form, with its own ζ and load).
    spec : PointSpec
    initial : ndarray, ContinueFrom or None
        Contact set to start from, shape ``(n, 2)`` or flat ``(2n,)``; an empty array starts from
        no contact, ``None`` follows the approach path from first touch; a
        :class:`~viscocontact.methods.bem.approach.ContinueFrom` continues the branch through a
        neighbour's equilibrium (a cycle's points).
    time_limit : float or None
        Seconds of wall time after which the solve is abandoned and the point recorded as an
        error with the reason ("TimeLimitExceeded: time limit of ... s reached"). The limit is a
        cooperative :func:`~viscocontact.deadline.deadline`, checked at every residual
        evaluation: it holds in any thread (serial runner, worker processes, Dask worker
        threads) and within an enclosing deadline, but not inside the kernel-table
        precomputation, which runs to its end.

    Returns
    -------
    dict
        One value per :data:`COLUMNS` key, plus ``"fields"`` (a dict of arrays or None).
    """
    from .._blas import single_blas_thread
    from ..deadline import deadline
    from ..errors import ModelValidityWarning, held

    t0 = time.perf_counter()
    record = _skeleton(scene, spec)
    try:
        # a point's doubts are in its message (outside the model: why), not one warning per
        # solve of its path; the study says once how many points have them
        with single_blas_thread(), deadline(time_limit), held(ModelValidityWarning):
            if "surface" in scene:
                result, started_from, path = _solve_areal(scene, spec)
            else:
                result, started_from, path = _solve(scene, spec, initial)
    except Exception as exc:  # stored with its reason; the study goes on
        record.update(status=ERROR, converged=False, message=f"{type(exc).__name__}: {exc}")
        record["seconds"] = time.perf_counter() - t0
        return record
    record["started_from"] = started_from
    # the speed ramp's events since the previous point, or the approach's own (folds, jumps,
    # births, merges, closure: ``extras["path_events"]`` of the BEM)
    events = path.events or list(result.extras.get("path_events", []))
    record.update(events=json.dumps(events), ramp=path.state)
    if path.certification:
        certification = dict(path.certification)
        note = certification.pop("note")
        record.update(certification)
        if note:
            result = attrs.evolve(result, message=f"{result.message}; {note}")
    out = result.to_dict()
    if "surface" in scene:
        from ..areal.report import areal_fields, areal_quantities

        out.update(areal_quantities(result))
        result = attrs.evolve(result, fields=areal_fields(result) if spec.fields else None)
    for key in COLUMNS:
        if key in out and key not in ("edges", "zeta"):
            record[key] = out[key]
    record["edges"] = np.asarray(result.edges, dtype=float).ravel()
    record["fields"] = ({k: np.asarray(v, dtype=float) for k, v in result.fields.items()}
                        if spec.fields and result.fields is not None else None)
    record["seconds"] = time.perf_counter() - t0
    return record


def _skeleton(scene: Mapping[str, Any], spec: PointSpec) -> dict[str, Any]:
    load = scene["load"]
    control = next(iter(load))
    record: dict[str, Any] = {
        "chain": spec.chain, "step": spec.step, "phase": spec.phase,
        "started_from": spec.started_from, "variant": "", "seed": -1, "gamma": np.nan,
        "load": np.nan, "zeta": float(scene["sliding"]["zeta"]), "control": control,
        "target": float(load[control]), "status": ERROR, "converged": False, "message": "",
        "method": "", "history": str(spec.history.get("name", "")), "events": "[]", "ramp": "",
        "n_contacts": 0, "full_contact": False, "iterations": 0, "function_evaluations": 0,
        "edges": np.zeros(0), "fields": None,
        **{k: v for k, v in LATER_COLUMNS.items() if k in AREAL_COLUMNS}, **CERTIFY_COLUMNS}
    for key, kind in COLUMNS.items():
        if kind == "float" and key not in record:
            record[key] = np.nan
    record.update(spec.labels)
    return record


@attrs.define
class _Path:
    """What a point's solve leaves for the record besides its result: the events met since the
    chain's previous point, the speed ramp's state (JSON; empty for the approach) and the
    certification's columns (:func:`~viscocontact.studies.certify.certification`; empty when
    the point is not certified)."""

    events: list = attrs.Factory(list)
    state: str = ""
    certification: dict = attrs.Factory(dict)


def _solve(scene: Mapping[str, Any], spec: PointSpec, initial):
    """``(result, started_from, path)`` of one point under its history (and its certification
    when ``spec.certify``)."""
    from ..problem import ContactProblem, Discretization
    from ..scene import Scene
    from .certify import certification

    options = {}
    if spec.discretization:
        options["discretization"] = Discretization(**spec.discretization)
    problem = ContactProblem.from_scene(Scene.from_dict(scene), **options)
    result, started_from, path = _reached(problem, spec, initial)
    if spec.certify:
        path.certification = certification(problem, spec, result,
                                           functools.partial(_reached_again, spec))
    return result, started_from, path


def _reached_again(spec: PointSpec, problem, stated, ramp_state: str):
    """``(result, ramp state)``: the point of ``problem`` (a finer one) reached under the
    history ``stated``, a speed ramp continued from ``ramp_state``; for a certification."""
    from .history import SpeedRamp

    if isinstance(stated, SpeedRamp):
        path = _Path()
        result = _ramped(problem, stated, attrs.evolve(spec, ramp=ramp_state), path)
        return result, path.state
    return _solve_at(problem, None, None), ""


def _reached(problem, spec: PointSpec, initial):
    """``(result, started_from, path)`` of the point of ``problem`` under its history."""
    from .history import SPEED_RAMP, history

    path = _Path()
    if spec.history.get("name") == SPEED_RAMP:
        result = _ramped(problem, history(dict(spec.history)), spec, path)
        return result, spec.started_from, path
    start = (initial if initial is None or hasattr(initial, "penetration")
             else np.asarray(initial, dtype=float).reshape(-1))
    result = _solve_at(problem, None, start, fields=spec.fields)
    if result.converged or spec.started_from != NEIGHBOUR:
        return result, spec.started_from, path
    # a warm start from the neighbour (adhesionless: the equilibrium is unique) that failed:
    # the point's own history, the approach from first touch
    fresh = _solve_at(problem, None, None, fields=spec.fields)
    why = f"{fresh.message} (from first touch; from the neighbour's contact set: {result.message})"
    counts = dict(function_evaluations=result.function_evaluations + fresh.function_evaluations,
                  iterations=result.iterations + fresh.iterations)
    return attrs.evolve(fresh, message=why, **counts), FIRST_TOUCH, path


def _solve_areal(scene: Mapping[str, Any], spec: PointSpec):
    """``(result, started_from, path)`` of an areal point: the scene's own solve (each grid of
    the ladder from the coarser one's solution), with the fields for the patches."""
    from ..areal.scene import ArealScene

    return ArealScene.from_dict(scene).solve(fields=True), FIRST_TOUCH, _Path()


def _ramped(problem, ramp, spec: PointSpec, path: _Path):
    """The point of a speed ramp: the chain's first point by the approach, the others recorded
    from the ramp's path continued from the previous point's state."""
    from .ramp import Node, Ramp, RampFailed, RampState

    zeta = float(problem.zeta)

    def solve(z, start):
        return _solve_at(problem, z, start, fields=spec.fields)

    if not spec.ramp:
        result = solve(zeta, None)
        if result.converged:
            path.state = RampState(older=None, last=Node.of(math.log10(zeta), result),
                                   step=ramp.tolerance).to_json()
        return result
    state = RampState.from_json(spec.ramp)
    direction = state.heading(math.log10(zeta))
    march = Ramp(history=ramp, solve=solve, direction=direction)
    try:
        state, result = march.record(state, zeta)
    except RampFailed as failed:
        path.events = march.events
        from ..result import SolveStatus

        return attrs.evolve(failed.result, converged=False, status=SolveStatus.NOT_CONVERGED,
                            message=str(failed), function_evaluations=march.evaluations)
    path.events, path.state = march.events, state.to_json()
    why = (f"{result.message} (speed ramp: {march.solves} solves since the previous point"
           + (f", events: {', '.join(e['kind'] for e in march.events)}" if march.events else "")
           + ")")
    return attrs.evolve(result, message=why, function_evaluations=march.evaluations)


def _solve_at(problem, zeta: float | None, start, *, fields: bool = False):
    """The equilibrium of ``problem`` (at ``zeta`` instead of its own ζ when given) from
    ``start`` (None: the approach from first touch)."""
    at = problem if zeta is None else attrs.evolve(problem, zeta=float(zeta))
    return at.solve(initial=start, fields=fields, prepared=_prepared(at))


# kernel tables depend only on profile, rheology, kernel and ζ: a small cache keyed by exactly
# these inputs serves the many points of a cycle (fixed ζ) without any effect on the numbers;
# the lock keeps it whole when threads share it (a Dask worker with several threads)
_PREPARED: collections.OrderedDict = collections.OrderedDict()
_PREPARED_SIZE = 4
_PREPARED_LOCK = threading.Lock()


def _prepared(problem):
    key = (repr(problem.profile), repr(problem.rheology), repr(problem.kernel),
           repr(getattr(problem, "poisson", None)), float(problem.zeta))
    with _PREPARED_LOCK:
        if key in _PREPARED:
            _PREPARED.move_to_end(key)
            return _PREPARED[key]
    prepared = problem.prepare()
    with _PREPARED_LOCK:
        _PREPARED[key] = prepared
        while len(_PREPARED) > _PREPARED_SIZE:
            _PREPARED.popitem(last=False)
    return prepared


def has_contact(record: Mapping[str, Any]) -> bool:
    """Whether a record is a converged equilibrium with at least one contact (or full contact)."""
    return bool(record["converged"]) and (record["n_contacts"] > 0 or bool(record["full_contact"]))


def carried_edges(record: Mapping[str, Any]) -> np.ndarray | None:
    """The contact set a following point can start from (None: full contact cannot be carried)."""
    if not has_contact(record) or record["full_contact"]:
        return None
    return np.asarray(record["edges"], dtype=float)
