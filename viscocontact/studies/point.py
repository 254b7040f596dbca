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
import json
import math
import threading
import time
from typing import Any, Iterable, Mapping

import attrs
import numpy as np

from .._stepping import march
from ..errors import TimeLimitExceeded

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
}

#: Columns added after the first study-file format, with the value a file written before them
#: reads as (``""``: the method was not recorded; it was the BEM).
LATER_COLUMNS: dict[str, Any] = {"method": "", "error_estimate": float("nan")}

#: Columns that depend on the machine's speed, not on the numerics (left out of comparisons).
TIMING_COLUMNS = ("seconds",)

#: ``started_from`` values.
FIRST_TOUCH, NEIGHBOUR, NO_CONTACT = "first touch", "neighbour", "no contact"

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
        ``"no contact"`` (an empty contact set: contacts are born where the profile penetrates).
    fields : bool
        Also return pressure, displacement and gap on the check grid.
    discretization : dict or None
        Keyword arguments of :class:`~viscocontact.problem.Discretization` (default mesh if None).
    labels : dict
        The chain's labels copied into the record (``variant``, ``seed``, ``gamma``, ``load``).
    path : tuple of float
        ζ of intermediate equilibria to pass through, in order, before the point's own ζ (a
        continuation in bounded steps; they are solved, not recorded). A converged one hands its
        contact set on; one that does not converge is passed over.
    origin : float or None
        ζ of the converged neighbour the point is continued from (sweeps; None otherwise).
    origin_edges : tuple of float
        That neighbour's contact set, flattened. A point continued from it (``started_from``
        ``"neighbour"``) that does not converge is approached again from it in smaller steps of
        ζ (:func:`refined`), and when no step reaches it, solved from first touch
        (:func:`branch_ended`); its message says so.
    """

    chain: int
    step: int
    phase: str
    started_from: str = FIRST_TOUCH
    fields: bool = False
    discretization: Mapping[str, Any] | None = None
    labels: Mapping[str, Any] = attrs.field(factory=dict)
    path: tuple = attrs.field(default=(), converter=_as_tuple)
    origin: float | None = None
    origin_edges: tuple = attrs.field(default=(), converter=_as_tuple)


def solve_point(scene: Mapping[str, Any], spec: PointSpec,
                initial: np.ndarray | None = None,
                time_limit: float | None = None) -> dict[str, Any]:
    """Solve one point; never raises for a failing solve.

    Parameters
    ----------
    scene : dict
        The full scene of this point (``Scene.to_dict()`` form, with its own ζ and load).
    spec : PointSpec
    initial : ndarray or None
        Contact set to start from, shape ``(n, 2)`` or flat ``(2n,)``; an empty array starts from
        no contact, ``None`` follows the approach path from first touch.
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

    t0 = time.perf_counter()
    record = _skeleton(scene, spec)
    try:
        with single_blas_thread(), deadline(time_limit):
            result, started_from = _solve(scene, spec, initial)
    except Exception as exc:  # stored with its reason; the study goes on
        record.update(status=ERROR, converged=False, message=f"{type(exc).__name__}: {exc}")
        record["seconds"] = time.perf_counter() - t0
        return record
    record["started_from"] = started_from
    out = result.to_dict()
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
        "method": "",
        "n_contacts": 0, "full_contact": False, "iterations": 0, "function_evaluations": 0,
        "edges": np.zeros(0), "fields": None}
    for key, kind in COLUMNS.items():
        if kind == "float" and key not in record:
            record[key] = np.nan
    record.update(spec.labels)
    return record


def _solve(scene: Mapping[str, Any], spec: PointSpec, initial):
    """``(result, started_from)``: the point's result and where its solve started (the spec's
    ``started_from``, or :data:`FIRST_TOUCH` for a point whose branch ended before it)."""
    from ..problem import Discretization

    options = {}
    if spec.discretization:
        options["discretization"] = Discretization(**spec.discretization)
    start = None if initial is None else np.asarray(initial, dtype=float).reshape(-1)
    origin, origin_start = spec.origin, (np.asarray(spec.origin_edges, dtype=float)
                                         if spec.origin_edges else None)
    for zeta in spec.path:      # intermediate equilibria of a bounded continuation
        result = _solve_at(scene, zeta, start, options)
        if result.converged:
            # full contact has no edges to carry: the next step follows the approach path
            start = None if result.full_contact else np.asarray(result.edges, float).reshape(-1)
            origin, origin_start = float(zeta), start
    result = _solve_at(scene, None, start, options, fields=spec.fields)
    if (result.converged or spec.started_from != NEIGHBOUR or origin is None
            or origin_start is None):
        return result, spec.started_from
    result = refined(scene, options, origin, origin_start, result, fields=spec.fields)
    if result.converged:
        return result, spec.started_from
    ended = branch_ended(scene, options, result, fields=spec.fields)
    # a point that converged from first touch starts its chain afresh; one that failed keeps
    # the spec's own start
    return ended, FIRST_TOUCH if ended.converged else spec.started_from


def _solve_at(scene: Mapping[str, Any], zeta: float | None, start, options: dict, *,
              fields: bool = False):
    """The equilibrium of ``scene`` (at ``zeta`` instead of its own ζ when given) from ``start``."""
    from ..problem import ContactProblem
    from ..scene import Scene

    at = scene if zeta is None else {**scene, "sliding": {"zeta": float(zeta)}}
    problem = ContactProblem.from_scene(Scene.from_dict(at), **options)
    return problem.solve(initial=start, fields=fields, prepared=_prepared(at, problem))


#: Smallest step of :func:`refined`, as a fraction of the ζ gap in decades, and the most solves
#: it makes.
REFINE_SMALLEST = 1.0 / 64.0
REFINE_SOLVES = 24


def refined(scene: Mapping[str, Any], options: dict, origin: float, start: np.ndarray,
            failed, *, fields: bool = False):
    """A point that did not converge from its neighbour's contact set, approached again from the
    neighbour (at ζ = ``origin``, contact set ``start``) in steps of log ζ: a step that
    converges hands its contact set on and the next step doubles (up to the rest of the gap), one
    that fails is halved, down to :data:`REFINE_SMALLEST` of the gap (at most
    :data:`REFINE_SOLVES` solves). This is a slow change of speed over the gap instead of the
    jump: an adhesive equilibrium depends on the history, so the message says which one the
    point had. Returns the point's result (``failed``, with a longer message, when no step path
    reaches it); ``function_evaluations`` and ``iterations`` count every solve.
    """
    target = float(scene["sliding"]["zeta"])
    if not (origin > 0 and target > 0) or origin == target:
        return failed
    span = math.log(target / origin)
    current: np.ndarray | None = start
    result, evaluations, iterations = failed, failed.function_evaluations, failed.iterations
    furthest = origin

    def attempt(to: float) -> bool:
        nonlocal current, result, evaluations, iterations, furthest
        last = to >= 1.0
        zeta = origin * math.exp(to * span)
        result = _solve_at(scene, None if last else zeta, current, options,
                           fields=fields and last)
        evaluations += result.function_evaluations
        iterations += result.iterations
        if result.converged and not last:
            current = (None if result.full_contact
                       else np.asarray(result.edges, dtype=float).reshape(-1))
            furthest = zeta
        return bool(result.converged)

    reached, solves = march(attempt, smallest=REFINE_SMALLEST, most=REFINE_SOLVES)
    counts = dict(function_evaluations=evaluations, iterations=iterations)
    if reached:
        why = (f"{result.message}: reached from the neighbour at ζ = {origin:.6g} in "
               f"{solves} steps of ζ, the direct start having failed ({failed.message})")
        return attrs.evolve(result, message=why, **counts)
    reach = ("no step converged" if furthest == origin
             else f"the steps reached ζ = {furthest:.6g} and no further")
    why = (f"{failed.message}; approached again from the neighbour at ζ = {origin:.6g} in "
           f"steps of ζ down to {REFINE_SMALLEST:g} of the gap ({solves} solves, {reach}), it "
           f"did not converge either ({result.message})")
    return attrs.evolve(failed, message=why, **counts)


def branch_ended(scene: Mapping[str, Any], options: dict, failed, *, fields: bool = False):
    """The result of a continued point that :func:`refined` did not reach either: the branch
    of equilibria it was continued along ends before its ζ (a fold in ζ, where the contact set
    has to jump and no continuation leads), so the point is solved from first touch at its own
    ζ, as the first point of a chain is, and the chain goes on from there. The message says so
    and keeps why the continuation failed; ``function_evaluations`` and ``iterations`` count
    every solve. A point that does not converge from first touch either stays failed
    (``failed``, with both reasons)."""
    fresh = _solve_at(scene, None, None, options, fields=fields)
    counts = dict(function_evaluations=failed.function_evaluations
                  + fresh.function_evaluations,
                  iterations=failed.iterations + fresh.iterations)
    if fresh.converged:
        why = (f"{fresh.message}: from first touch at this ζ, the branch continued from the "
               f"neighbour having ended before it ({failed.message})")
        return attrs.evolve(fresh, message=why, **counts)
    why = f"{failed.message}; from first touch it did not converge either ({fresh.message})"
    return attrs.evolve(failed, message=why, **counts)


# kernel tables depend only on profile, rheology, kernel and ζ: a small cache keyed by exactly
# these inputs serves the many points of a cycle (fixed ζ) without any effect on the numbers;
# the lock keeps it whole when threads share it (a Dask worker with several threads)
_PREPARED: collections.OrderedDict = collections.OrderedDict()
_PREPARED_SIZE = 4
_PREPARED_LOCK = threading.Lock()


def _prepared(scene: Mapping[str, Any], problem):
    key = json.dumps([scene.get(s) for s in ("profile", "rheology", "kernel", "poisson")]
                     + [scene["sliding"]["zeta"]], sort_keys=True, default=str)
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
