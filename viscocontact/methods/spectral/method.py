r"""The :class:`Spectral` solution method: grids, solvers and the error estimate put together.

A solve runs a ladder of grids, each twice as fine as the one before and starting from its
solution (:func:`next_start`): from at most :data:`LADDER_START` cells (or, with a warm start,
from half the first trusted grid) up to the first trusted grid (:func:`first_points`), then on
until the estimate (:func:`changes`, :func:`estimate`) is within the tolerance or the next grid
would exceed ``max_points``. Closed contact and no contact are answered without a grid
(:mod:`~viscocontact.methods.spectral.closed`)."""
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
from ...problem import Prepared
from ...result import ContactResult, SolveStatus
from ..base import SolutionMethod
from .closed import ClosedContact, no_contact_result
from .cohesive import CELLS_PER_ZONE, GridLaw, cohesive_solve, law_violation, zone_cells
from .edges import contact_edges, runs
from .grid import UniformGrid, cells_inside, refine
from .operator import OperatorCache, convolve, power
from .solvers import GridSolution, grid_solve, violation

#: Fewest cells ``points`` may ask for.
MIN_POINTS = 64
#: Fewest cells of the coarsest grid of the ladder.
COARSEST = 32
#: Without a warm start the ladder begins at this many cells or fewer (nested iteration: each
#: grid starts from the solution on the previous one, so the coarse grids cost little).
LADDER_START = 256
#: Most cells a grid may have (``points`` and ``max_points`` are validated against it).
MAX_POINTS = 1 << 22
#: Cells per shortest wavelength of the profile at tolerance 1e-3 (scaled by
#: ``(1e-3/tolerance)^(1/ORDER_AREA)``) for the first fine grid.
CELLS_PER_WAVELENGTH = 32.0
#: Fewest cells of the first fine grid when the tolerance does not ask for more.
FIRST_POINTS = 256
#: Convergence order assumed by the Richardson estimate: the lowest observed on rough profiles
#: (module docstring of :mod:`viscocontact.methods.spectral`).
ORDER = 1.0
#: Expected convergence order of Ã, which sizes the first grid for a tolerance.
ORDER_AREA = 2.0


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


@attrs.frozen(kw_only=True, eq=False)
class GridMeasures:
    """What one grid solve gives: the solution, its contacts and the two integral measures."""

    grid: UniformGrid
    solution: GridSolution
    edges: np.ndarray
    area: float
    friction: float
    #: cells in contact (the loaded ones, ``p > 0``; a cohesive law's contact cells)
    contact: np.ndarray
    #: share of each cell under a cohesive law's stress (None: no law)
    weights: np.ndarray | None = None

    @property
    def closed(self) -> bool:
        return bool(np.all(self.contact))


def measure(grid: UniformGrid, solution: GridSolution, eigenvalues, workers: int = 1,
            law: GridLaw | None = None, contact=None, weights=None) -> GridMeasures:
    """Contacts, area (sub-cell edges) and friction (eq. 4.16) of a grid solution.

    With a cohesive ``law`` the contacts are the cells ``contact`` and their edges are located
    from the shifted pressure ``p + σ̃0``, which has the adhesionless square-root field at a
    Maugis–Dugdale edge (the gap outside rises as ``s^{3/2}`` there too); the friction counts the
    cohesive stress with the contact stress, and the load may be tensile.
    """
    p = solution.pressure
    pm = float(p.mean())
    if law is None:
        contact = p > 0
    # a cohesive law's load may be tensile
    defined = pm > 0 if law is None else pm != 0
    mu = float(-(p @ grid.rise) / (TWO_PI * pm)) if defined else float("nan")
    extra = dict(contact=contact, weights=weights)
    if np.all(contact):
        return GridMeasures(grid=grid, solution=solution, edges=np.zeros((0, 2)), area=TWO_PI,
                            friction=mu, **extra)
    gap = convolve(p, eigenvalues, workers) - (grid.heights - 1.0 + solution.penetration)
    shifted = p if law is None else np.where(contact, p + law.strength, 0.0)
    edges = contact_edges(grid.start, grid.cell, shifted, gap)
    area = float(min(np.sum(edges[:, 1] - edges[:, 0]), TWO_PI)) if edges.size else 0.0
    return GridMeasures(grid=grid, solution=solution, edges=edges, area=area, friction=mu,
                        **extra)


def changes(coarse: GridMeasures, fine: GridMeasures, m2: float,
            friction_floor: float) -> tuple[float, float]:
    """Relative changes of ``Ã`` and ``μ`` from the coarse to the fine grid (``μ`` relative to
    ``max(|μ|, friction_floor·√m2)``)."""
    d_area = abs(fine.area - coarse.area) / max(fine.area, 1e-300)
    scale = max(abs(fine.friction), friction_floor * math.sqrt(max(m2, 0.0)), 1e-300)
    d_mu = abs(fine.friction - coarse.friction) / scale
    if not np.isfinite(d_mu):
        d_mu = 0.0 if not (np.isfinite(fine.friction) or np.isfinite(coarse.friction)) else np.inf
    return float(d_area), float(d_mu)


def estimate(change: tuple[float, float], previous: tuple[float, float] | None = None
             ) -> tuple[float, float]:
    """Relative error estimates of ``Ã`` and ``μ`` on the finer of two grids (ratio 2).

    Richardson: the change between the two grids over ``2^p - 1`` (``p = ORDER``), and at least
    the change between the two grids before over ``2^p (2^p - 1)`` (``previous``), so that a
    change that happens to be small does not hide a larger error seen one level down.
    """
    factor = 2.0**ORDER - 1.0
    out = [c / factor for c in change]
    if previous is not None:
        out = [max(o, c / (factor * 2.0**ORDER)) for o, c in zip(out, previous)]
    return float(out[0]), float(out[1])


def next_start(grid: UniformGrid, coarse: GridMeasures) -> np.ndarray:
    """The starting pressure on ``grid`` (twice as fine as ``coarse``'s): the coarse pressure
    carried over (:func:`~viscocontact.methods.spectral.grid.refine`) on the cells whose centres
    lie inside the coarse contacts' sub-cell edges, zero elsewhere, so that the first loaded set
    is already the fine grid's to within the edge estimates."""
    p = refine(coarse.solution.pressure)
    if coarse.closed or coarse.edges.size == 0:
        return p
    inside = cells_inside(grid, coarse.edges)
    floor = 1e-3 * float(np.mean(p[p > 0])) if np.any(p > 0) else 1.0
    return np.where(inside, np.maximum(p, floor), 0.0)


def first_points(wavelength: float | None, tolerance: float, max_points: int) -> int:
    """The first fine grid: ``CELLS_PER_WAVELENGTH`` cells per shortest wavelength of the profile
    at tolerance 1e-3, scaled with ``tolerance^(-1/ORDER_AREA)``, rounded up to a power of two,
    at least :data:`FIRST_POINTS`, at most ``max_points``."""
    per = CELLS_PER_WAVELENGTH * (1e-3 / tolerance) ** (1.0 / ORDER_AREA)
    span = TWO_PI / wavelength if wavelength else 32.0
    want = max(per * span, FIRST_POINTS)
    n = 1 << int(math.ceil(math.log2(want)))
    return int(min(n, max_points - max_points % 2))


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
                    "grid starts from the adhesionless contact, which needs p̃∞ > 0; use "
                    "penetration control or the boundary-element method")
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
        law = problem.adhesion.cohesive_law(amplitude)
        return None if law is None else GridLaw(strength=float(law[0]), opening=float(law[1]),
                                                zone=float(law[2]))

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
                  "friction_edges": 0.0, "outside_model": ""}
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
                                 strength=0.0 if law is None else law.strength)
        return self._ladder(problem, prep, initial, fields, started, events, extras, closed, law)

    def plan_steps(self, problem, prepared) -> tuple:
        from ...plan import PlanStep

        why = self.unsupported(problem)
        if why is not None:
            return (PlanStep(stage="method", choice="spectral: not applicable", reason=why),)
        prep = self._prepared(problem, prepared)
        law = self.law(problem, prep.shape.amplitude)
        wavelength = prep.shape.wavelength
        if self.points is not None:
            grid = PlanStep(stage="grid", choice=f"{self.points} cells, estimate from "
                            f"{self.points // 2}", reason="points given")
            n = self.points
        else:
            n = first_points(wavelength, self.tolerance, self.max_points)
            if law is not None:
                n = min(max(n, self.zone_points(law)), self.max_points)
            per = CELLS_PER_WAVELENGTH * (1e-3 / self.tolerance) ** (1.0 / ORDER_AREA)
            why_grid = (f"{per:.3g} cells per shortest wavelength λ_min = {wavelength:.4g} for "
                        f"tolerance {self.tolerance:g}" if wavelength else
                        f"shortest wavelength unknown: at least {n} cells")
            grid = PlanStep(stage="grid",
                            choice=f"{n // 2} then {n} cells, doubled up to {self.max_points} "
                                   f"until the estimate is <= {self.tolerance:g}",
                            reason=why_grid)
        op = prep.operators.circulant(prep.kernel, n)
        lam = op.eigenvalues
        asym = float(np.max(np.abs(lam.imag)) / np.max(np.abs(lam)))
        operator = PlanStep(stage="operator",
                            choice="circulant by FFT: Clausen closed form of the instantaneous "
                                   "part + alias sums of the rest of the multiplier",
                            reason=f"{type(problem.kernel).__name__}, c0 = {prep.kernel.mean:.4g}")
        if op.symmetric:
            solver = PlanStep(stage="solver", choice="Polonsky-Keer conjugate gradients",
                              reason=f"the operator is symmetric (max|Im Λ|/max|Λ| = {asym:.2g})")
        else:
            solver = PlanStep(stage="solver",
                              choice="active set (semismooth Newton) + GMRES preconditioned by "
                                     "the inverse circulant; Polonsky-Keer on Re Λ to start",
                              reason=f"viscoelastic: the operator is not symmetric "
                                     f"(max|Im Λ|/max|Λ| = {asym:.2g})")
        control = ("load control, p̃∞ = " + f"{problem.mean_pressure:g}"
                   if problem.mean_pressure is not None
                   else "penetration control, Δ̃ = " + f"{problem.penetration:g}")
        cohesive = () if law is None else (PlanStep(
            stage="adhesion",
            choice=f"cohesive law cell by cell: tension σ̃0 = {law.strength:.4g} where the gap "
                   f"is below η = {law.opening:.4g}; tips between cells by the secant of the "
                   f"gap; {zone_cells(law, n):.0f} cells per quasi-static zone "
                   f"q0a0 = {law.zone:.3g} on the first trusted grid",
            reason=f"{type(problem.adhesion).__name__}: at least {CELLS_PER_ZONE:g} cells per "
                   "zone; from the adhesionless contact, not along a loading path (a JKR-like "
                   "scene with several equilibria may end on another one than the BEM's)"),)
        return (PlanStep(stage="method", choice="spectral: uniform grid, FFT products",
                         reason="adhesionless scene" if law is None else
                                "finite-range cohesive law (wide zones)"),
                grid, operator, solver, *cohesive,
                PlanStep(stage="control", choice=control,
                         reason="the closed contact is returned directly when it carries the "
                                "load without tension"),
                PlanStep(stage="edges", choice="sub-cell edges: left ones from the pressures of "
                                               "the two outermost loaded cells, right ones from "
                                               "the gaps of the two first free cells" + (
                                                   "" if law is None else " (pressures shifted "
                                                   "by σ̃0: the Maugis–Dugdale edge field)"),
                         reason="universal square-root edge field (adhesionless); the memory "
                                "of a viscoelastic solid spoils the other side"),
                PlanStep(stage="estimate",
                         choice=f"Richardson on Ã and μ between N/2 and N (order {ORDER:g}), "
                                "at least half the change one level down",
                         reason=f"tolerance {self.tolerance:g}; μ relative to max(|μ|, "
                                f"{self.friction_floor:g}·√m2)"),
                PlanStep(stage="reuse", choice="eigenvalues once per (kernel, N) in "
                                               "SpectralPrepared (pass prepared= along a sweep)",
                         reason="they depend on rheology, kernel and ζ only"),
                PlanStep(stage="fields", choice="pressure, displacement and gap on the final "
                                                "grid only when asked", reason="fields=True"))

    # ---- the ladder of grids ---------------------------------------------------------------
    def _prepared(self, problem, prepared) -> SpectralPrepared:
        if isinstance(prepared, SpectralPrepared):
            return prepared
        if prepared is None:
            return self.prepare(problem)
        return SpectralPrepared(kernel=prepared.kernel, shape=prepared.shape, m2=prepared.m2)

    def _ladder(self, problem, prep, initial, fields, started, events, extras, closed,
                law=None):
        load, pen = problem.mean_pressure, problem.penetration
        if self.points is not None:
            target = final = self.points
        else:
            target = first_points(prep.shape.wavelength, self.tolerance, self.max_points)
            if law is not None:                # the cohesive zones resolved from the start
                target = min(max(target, self.zone_points(law)), self.max_points)
            final = self.max_points
            # a warm start contributes its contact set only (not the grid it was computed on):
            # a result and its edges, as a study stores them, give the same answer
        # the ladder halves the target grid exactly down to its first grid, the first at or
        # below LADDER_START cells, with or without a warm start: a ladder that began one grid
        # below the target had a single change to estimate from, and along a ζ-path on the
        # thesis's rough profile (seed 1, p̃∞ = 0.3, ζ = 0.1) it stopped at 2048 cells with an
        # estimate of 8.4e-4 and an actual error of 3.9e-3; the warm start only seeds the first
        # grid's contact set, so a warm and a cold solve take the same grids
        n = target // 2
        while n % 4 == 0 and n // 2 >= COARSEST and n > LADDER_START:
            n //= 2
        grid = UniformGrid.of(prep.shape, n)
        start = None
        if initial is not None:
            start = self._warm_start(grid, initial, load)
            events.append(f"warm start: {int(np.sum(start > 0))} of {n} cells loaded")
        previous, current = None, None
        iterations = applications = 0
        errors, last = (np.inf, np.inf), None
        while True:
            op = prep.operators.circulant(prep.kernel, grid.points)
            start_penetration = None if previous is None else previous.solution.penetration
            if law is None:
                sol = self._solve_grid(op, grid, load, pen, start, start_penetration)
                current = measure(grid, sol, op.eigenvalues, self.workers or 1)
            else:
                solved = self._solve_cohesive(op, grid, load, pen, start, start_penetration,
                                              law, first=previous is None,
                                              warm=initial is not None)
                sol = solved.solution
                current = measure(grid, sol, op.eigenvalues, self.workers or 1, law=law,
                                  contact=solved.contact, weights=solved.weights)
            iterations += sol.iterations
            applications += sol.applications
            events.append(f"{grid.points} cells: {sol.solver}, {sol.message}")
            if not sol.converged:
                break
            if previous is not None:
                change = changes(previous, current, prep.m2, self.friction_floor)
                errors = estimate(change, last)
                last = change
            if previous is not None and grid.points >= target:
                if max(errors) <= self.tolerance or 2 * grid.points > final:
                    break
                events.append(f"estimate {max(errors):.2g} > tolerance at {grid.points} cells: "
                              "grid doubled")
            previous = current
            grid = UniformGrid.of(prep.shape, 2 * grid.points)
            start = next_start(grid, current) if law is None else refine(sol.pressure)
        error = float(max(errors))
        extras.update(error_estimate=error, points=current.grid.points,
                      tolerance_met=bool(error <= self.tolerance),
                      estimates={"area": float(errors[0]), "friction": float(errors[1])})
        if previous is not None:
            extras["coarse"] = {"points": previous.grid.points, "area": previous.area,
                                "friction": previous.friction}
        if current.solution.converged and error > self.tolerance:
            events.append(f"tolerance {self.tolerance:g} not met: estimate {error:.2g} at "
                          f"{current.grid.points} cells")
        result = self._assemble(problem, prep, current, iterations, applications, fields,
                                extras, closed, law)
        extras["seconds"] = time.perf_counter() - started
        return result

    def _warm_start(self, grid, initial, load) -> np.ndarray:
        if getattr(initial, "full_contact", False):
            mask = np.ones(grid.points, bool)
        else:
            edges = np.asarray(getattr(initial, "edges", initial), dtype=float)
            mask = cells_inside(grid, edges.ravel()) if edges.size else np.zeros(grid.points, bool)
        if not mask.any():
            mask[0] = True                               # the peak
        start = mask.astype(float)
        if load is not None:
            start *= load / start.mean()
        return start

    def _solve_grid(self, op, grid, load, pen, start, start_penetration) -> GridSolution:
        # the first grid starts from the solution for the operator's symmetric part
        return grid_solve(op, grid.heights, mean_pressure=load, penetration=pen, start=start,
                          start_penetration=start_penetration, presolve=start is None,
                          **self._grid_options())

    def _grid_options(self) -> dict:
        """The options of every grid solve (:func:`~.solvers.grid_solve`)."""
        return dict(tolerance=self.residual, krylov_tolerance=self.krylov_tolerance,
                    max_updates=self.max_updates, max_iterations=self.max_iterations,
                    workers=self.workers or 1)

    def _solve_cohesive(self, op, grid, load, pen, start, start_penetration, law, first,
                        warm=False):
        """A cohesive grid solve (:func:`~.cohesive.cohesive_solve`). On the first grid it
        starts from the adhesionless solution (load control) or from no load (penetration
        control); with a warm start, from its contacts under the cohesive stress, whose zones
        then grow (so that another method's equilibrium, a merged contact that adhesion holds,
        is checked as it is)."""
        its = apps = 0
        contact = None
        if first and warm:
            contact = start > 0
        elif first:
            if load is not None:
                bare = self._solve_grid(op, grid, load, None, start, None)
                its, apps = bare.iterations, bare.applications
                start, start_penetration = bare.pressure, bare.penetration
            else:
                start = np.zeros(grid.points)
        solved = cohesive_solve(op, grid.heights, law, mean_pressure=load, penetration=pen,
                                start=start, start_penetration=start_penetration,
                                start_contact=contact, **self._grid_options())
        sol = solved.solution
        return attrs.evolve(solved, solution=attrs.evolve(
            sol, iterations=sol.iterations + its, applications=sol.applications + apps))

    def _assemble(self, problem, prep, current: GridMeasures, iterations, applications, fields,
                  extras, closed, law=None) -> ContactResult:
        grid, sol = current.grid, current.solution
        workers = self.workers or 1
        common = dict(iterations=int(iterations), function_evaluations=int(applications),
                      zeta=float(problem.zeta), edge_perturbation=0.0, extras=extras)
        if current.closed:
            return closed.result(prep.m2, common, problem.mean_pressure, problem.penetration,
                                 fields, message="every cell loaded: contact closed over the "
                                                 "period to the grid's resolution",
                                 strength=0.0 if law is None else law.strength)
        p = sol.pressure
        op = prep.operators.circulant(prep.kernel, grid.points)
        u = convolve(p, op.eigenvalues, workers)
        gap = u - (grid.heights - 1.0 + sol.penetration)
        loaded = current.contact
        pm = float(p.mean())
        if law is not None:
            w = current.weights
            assert w is not None            # a cohesive law's measures carry its weights
            alone = sum(1 for f, n in runs(w > 0)
                        if not loaded[(f + np.arange(n)) % grid.points].any())
            extras["cohesive"] = {
                "strength": law.strength, "opening": law.opening, "zone": law.zone,
                "cells_per_zone": zone_cells(law, grid.points),
                "cohesive_cells": int(np.sum((w > 0) & ~loaded)),
                # the zones' share of p̃∞ (tensile)
                "load": float(-law.strength * np.sum(np.where(loaded, 0.0, w)) / grid.points),
                "tension_without_contact": int(alone)}
        loss = prep.operators.dissipation(prep.kernel, grid.points)
        extras["friction_dissipation"] = prep.shape.amplitude * power(p, loss, workers) / pm
        extras["solver"] = sol.solver
        mu = current.friction
        sqrt_m2 = math.sqrt(prep.m2) if prep.m2 > 0 else np.nan
        fld = ({"x": grid.x.copy(), "pressure": p.copy(), "displacement": u, "gap": gap}
               if fields else None)
        return ContactResult(
            area=current.area, mean_pressure=pm, penetration=float(sol.penetration), friction=mu,
            reduced_friction=mu / sqrt_m2, n_contacts=len(runs(loaded)),
            edges=current.edges, full_contact=False, converged=bool(sol.converged),
            status=SolveStatus.CONVERGED if sol.converged else SolveStatus.NOT_CONVERGED,
            message=("converged" if sol.converged else f"grid solve did not converge: "
                     f"{sol.message}") + ("" if extras["tolerance_met"] else
                                          f"; tolerance {self.tolerance:g} not met (estimate "
                                          f"{extras['error_estimate']:.2g})"),
            residual=(violation(gap, loaded) if law is None
                      else law_violation(p, gap, loaded, current.weights, law)),
            min_gap=float(np.min(gap[~loaded])) if (~loaded).any() else 0.0,
            fields=fld, **common)
