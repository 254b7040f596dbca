r"""The :class:`Spectral` solution method: grids, solvers and the error estimate put together.

A solve runs a ladder of grids (:mod:`~viscocontact.methods.spectral.ladder`), each twice as fine
as the one before and starting from its solution: from at most
:data:`~viscocontact.methods.spectral.ladder.LADDER_START` cells (or, with a warm start, from half
the first trusted grid) up to the first trusted grid
(:mod:`~viscocontact.methods.spectral.planning`), then on until the estimate
(:mod:`~viscocontact.methods.spectral.estimate`) is within the tolerance or the next grid would
exceed ``max_points``. A cohesive law's first grid follows the approach from first touch
(:mod:`~viscocontact.methods.spectral.history`); the final grid's result is assembled in
:mod:`~viscocontact.methods.spectral.assembly`. Closed contact and no contact are answered
without a grid (:mod:`~viscocontact.methods.spectral.closed`)."""
from __future__ import annotations

import math
import time
from typing import ClassVar

import attrs
import numpy as np

from ..._events import EventList
from ..._validation import in_range, int_range
from ...errors import ValidationError
from ...kernels.clausen import TWO_PI
from ..base import Prepared, SolutionMethod
from .approach import ApproachSettings
from .assembly import contact_result
from .closed import ClosedContact, no_contact_result
from .cohesive import CELLS_PER_ZONE, GridLaw
from .estimate import ORDER, changes, estimate
from .ladder import COARSEST, LADDER_START, Ladder, grid_options, next_start
from .measures import GridMeasures, measure
from .operator import OperatorCache
from .planning import CELLS_PER_WAVELENGTH, FIRST_POINTS, ORDER_AREA, first_points, plan
from .traction import grid_law

__all__ = ["Spectral", "SpectralPrepared", "GridMeasures", "measure", "changes", "estimate",
           "next_start", "first_points", "MIN_POINTS", "MAX_POINTS", "COARSEST", "LADDER_START",
           "CELLS_PER_WAVELENGTH", "FIRST_POINTS", "ORDER", "ORDER_AREA"]

#: Fewest cells ``points`` may ask for.
MIN_POINTS = 64
#: Most cells a grid may have (``points`` and ``max_points`` are validated against it).
MAX_POINTS = 1 << 22


@attrs.frozen(kw_only=True, eq=False)
class SpectralPrepared(Prepared):
    """A problem's prepared tables plus the circulant operators of the spectral method.

    Build with :meth:`Spectral.prepare` and pass as ``prepared=`` along a sweep at fixed rheology,
    kernel and ζ: the eigenvalues of every grid are then computed once.
    """

    operators: OperatorCache = attrs.field(factory=OperatorCache)


def _even_points(lo: int, hi: int):
    desc = f"an even integer in [{lo}, {hi}]"

    def check(inst, attribute, value):
        name = f"{type(inst).__name__}.{attribute.name}"
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise ValidationError(name, value, desc)
        if value % 2 or not lo <= value <= hi:
            raise ValidationError(name, value, desc)

    return check


@attrs.frozen(kw_only=True)
class Spectral(SolutionMethod):
    r"""Uniform-grid spectral method for adhesionless scenes and finite-range cohesive laws
    (:mod:`viscocontact.methods.spectral`).

    Parameters
    ----------
    tolerance : float
        Requested relative accuracy of ``Ã`` and ``μ`` (``μ`` relative to
        ``max(|μ|, friction_floor·√m2)``), in ``[1e-6, 0.1]``; the grid is doubled until the
        two-grid estimate is within it.
    points : int or None
        Cells of the final grid (even, ``[64, 2^22]``); ``None`` chooses them from the profile's
        shortest wavelength and ``tolerance``, and refines until the estimate meets it.
    max_points : int
        Most cells the automatic refinement may use (even, ``[64, 2^22]``).
    workers : int or None
        Threads of ``scipy.fft`` (``None``: 1).
    friction_floor : float
        ``μ`` is resolved relative to ``max(|μ|, friction_floor·√m2)``, i.e. to
        ``tolerance·friction_floor`` in the reduced friction ``μ/√m2`` when ``μ`` is smaller (it
        vanishes on an elastic solid), in ``[0, 1]``.
    residual : float
        Largest violation of the contact conditions (gap inside a contact, interpenetration
        outside), in units of the profile amplitude, at which a grid solve stops.
    krylov_tolerance : float
        Relative tolerance of the GMRES solves of the active-set method.
    max_iterations : int
        Conjugate-gradient steps per grid (Polonsky-Keer).
    max_updates : int
        Active-set updates per grid.
    approach : ApproachSettings
        The history of a cohesive solve: the continuation in ``Δ̃`` from first touch on the
        first grid (:mod:`~viscocontact.methods.spectral.approach`).

    Examples
    --------
    >>> from viscocontact.problem import ContactProblem
    >>> from viscocontact.profiles import Sinusoid
    >>> from viscocontact.reference import westergaard_area
    >>> from viscocontact.rheology import Elastic
    >>> from viscocontact.solvers import Bisection
    >>> prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
    ...                       solver=Bisection(), mean_pressure=0.3)
    >>> r = Spectral().solve(prob)
    >>> r.extras["method"], r.extras["tolerance_met"], r.n_contacts
    ('spectral', True, 1)
    >>> bool(abs(r.area / westergaard_area(0.3) - 1) < 1e-3)
    True
    """

    name: ClassVar[str] = "spectral"

    tolerance: float = attrs.field(default=1e-3, validator=in_range(1e-6, 0.1))
    points: int | None = attrs.field(
        default=None, validator=attrs.validators.optional(_even_points(MIN_POINTS, MAX_POINTS)))
    max_points: int = attrs.field(default=1 << 17, validator=_even_points(MIN_POINTS, MAX_POINTS))
    workers: int | None = attrs.field(
        default=None, validator=attrs.validators.optional(int_range(1, 1024)))
    friction_floor: float = attrs.field(default=1e-2, validator=in_range(0.0, 1.0))
    residual: float = attrs.field(default=1e-9, validator=in_range(1e-15, 1e-4))
    krylov_tolerance: float = attrs.field(default=1e-10, validator=in_range(1e-15, 1e-2))
    max_iterations: int = attrs.field(default=20000, validator=int_range(10, 10**7))
    max_updates: int = attrs.field(default=100, validator=int_range(2, 10**5))
    approach: ApproachSettings = attrs.field(
        factory=ApproachSettings, validator=attrs.validators.instance_of(ApproachSettings))

    def __attrs_post_init__(self):
        if self.points is not None and self.points > self.max_points:
            raise ValidationError("Spectral.points", self.points,
                                  f"an even integer in [{MIN_POINTS}, max_points = "
                                  f"{self.max_points}]")

    # ---- the interface ----------------------------------------------------------------------
    def unsupported(self, problem) -> str | None:
        gamma = float(problem.adhesion.work_of_adhesion)
        if not gamma > 0:
            return None
        law = self.law(problem)
        if law is None:
            return (f"adhesive scene (work of adhesion {gamma:g}): a uniform grid has no edge "
                    "energy balance; use the boundary-element method (or a finite-range law, "
                    "maugis-dugdale, which the grid applies cell by cell)")
        if problem.mean_pressure is not None and not problem.mean_pressure > 0:
            return (f"cohesive law under load control at p̃∞ = {problem.mean_pressure:g}: the "
                    "approach ends at the target load once it is reached, which needs p̃∞ > 0 "
                    "(a tensile load is met before the load's minimum, where load control is "
                    "unstable); use penetration control or the boundary-element method")
        need = self.zone_points(law)
        if need > self.max_points:
            return (f"the cohesive zone q0a0 = {law.zone:.3g} needs {need} cells "
                    f"({CELLS_PER_ZONE:g} per zone) > max_points = {self.max_points}: a short-"
                    "range law (high Tabor parameter) is for the boundary-element method")
        return None

    @staticmethod
    def law(problem, amplitude: float | None = None) -> GridLaw | None:
        """The scene's cohesive law on the grid (:meth:`AdhesionModel.cohesive_law`), None
        without one; ``amplitude``: Λ̃ when the caller has it prepared (else from the
        profile's peak)."""
        if not float(problem.adhesion.work_of_adhesion) > 0:
            return None
        if amplitude is None:
            amplitude = float(problem.profile.peak()[1])
        return grid_law(problem.adhesion, amplitude)

    @staticmethod
    def zone_points(law: GridLaw) -> int:
        """Cells (a power of two) that give the quasi-static zone :data:`CELLS_PER_ZONE`."""
        want = CELLS_PER_ZONE * TWO_PI / law.zone
        return 1 << int(math.ceil(math.log2(max(want, 2.0))))

    def prepare(self, problem) -> SpectralPrepared:
        """The problem's prepared tables with an empty operator cache (pass as ``prepared=``)."""
        base = problem.prepare()
        return SpectralPrepared(kernel=base.kernel, shape=base.shape, m2=base.m2)

    def solve(self, problem, initial=None, *, fields: bool = False, prepared=None):
        """The equilibrium of an adhesionless ``problem`` on uniform grids.

        Parameters
        ----------
        problem : ContactProblem
        initial : ContactResult or array of edges, optional
            Warm start: the first grid's loaded cells are those inside these contacts (shape
            (n, 2) or flat; a closed contact loads every cell).
        fields : bool
            Return ``x``, ``pressure``, ``displacement`` and ``gap`` on the final grid.
        prepared : Prepared, optional
            The problem's tables; a :class:`SpectralPrepared` also keeps the operators.

        Raises
        ------
        ValidationError
            For an adhesive problem (:meth:`unsupported`).
        """
        started = time.perf_counter()
        why = self.unsupported(problem)
        if why is not None:
            raise ValidationError("ContactProblem.adhesion", problem.adhesion,
                                  f"a scene the spectral method solves ({why})")
        prep = self._prepared(problem, prepared)
        law = self.law(problem, prep.shape.amplitude)
        load, pen = problem.mean_pressure, problem.penetration
        events: list[str] = EventList("spectral")      # logged as they happen
        extras = {"method": self.name, "error_estimate": 0.0, "points": 0, "tolerance_met": True,
                  "friction_dissipation": np.nan, "seconds": 0.0, "events": events,
                  # bounded stress at every edge (no adhesion, or a cohesive law): no energy
                  # flows into the edges, and the model holds wherever the grid converges
                  "friction_edges": 0.0, "outside_model": "",
                  # the approach's accepted states and typed events (a cohesive law's history;
                  # an adhesionless scene has one equilibrium and no history)
                  "history": [], "path_events": []}
        common = dict(iterations=0, function_evaluations=0, zeta=float(problem.zeta),
                      edge_perturbation=0.0, extras=extras)
        # a cohesive law acts from a gap below its range on: a penetration down to -η can
        # hold the solid by tension alone
        reach = 0.0 if law is None else -law.opening
        if (load is not None and not load > 0) or (pen is not None and not pen > reach):
            extras["seconds"] = time.perf_counter() - started
            return no_contact_result(common, pen)
        closed = ClosedContact.of(prep.shape, prep.kernel, 0)
        # closed at once only where it carries the load without tension: with a cohesive law a
        # closed contact that holds some tension is one equilibrium, the partial contact
        # reached from the adhesionless one another (the boundary-element method's, from first
        # touch), and the grid finds the latter
        if closed.closes(load, pen):
            extras["seconds"] = time.perf_counter() - started
            events.append("the closed contact carries the load without tension")
            return closed.result(prep.m2, common, load, pen, fields,
                                 strength=0.0 if law is None else law.strength,
                                 friction_floor=self.friction_floor)
        current, iterations, applications = Ladder(self, problem, prep, law, events,
                                                   extras).run(initial)
        result = contact_result(problem, prep, current, iterations=iterations,
                                applications=applications, fields=fields, extras=extras,
                                closed=closed, law=law, tolerance=self.tolerance,
                                workers=self.workers or 1)
        extras["seconds"] = time.perf_counter() - started
        return result

    def plan_steps(self, problem, prepared) -> tuple:
        """The steps of a solve of ``problem`` (:func:`~.planning.plan`), or why the method does
        not apply."""
        from ...plan import PlanStep

        why = self.unsupported(problem)
        if why is not None:
            return (PlanStep(stage="method", choice="spectral: not applicable", reason=why),)
        prep = self._prepared(problem, prepared)
        return plan(self, problem, prep, self.law(problem, prep.shape.amplitude))

    # ---- collaborators ----------------------------------------------------------------------
    def _prepared(self, problem, prepared) -> SpectralPrepared:
        """``prepared`` as :class:`SpectralPrepared` (prepared here when None)."""
        if isinstance(prepared, SpectralPrepared):
            return prepared
        if prepared is None:
            return self.prepare(problem)
        return SpectralPrepared(kernel=prepared.kernel, shape=prepared.shape, m2=prepared.m2)

    def _grid_options(self) -> dict:
        """The options of every grid solve (:func:`~.ladder.grid_options`)."""
        return grid_options(self)
