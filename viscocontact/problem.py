r"""The :class:`ContactProblem` orchestrator (thesis §4.4).

It reads like the algorithm: mesh every contact (eqs. 4.21-4.29) → influence matrix of the prepared
kernel (eq. 4.32) → stresses for the current edges (eq. 4.31, penetration or load control) → one
residual per edge from the adhesion model (eqs. 4.9-4.20) → a :class:`NonlinearSolver` moves the
edges → when contacts merge or vanish the solve restarts in the new dimension → once converged,
the gap is checked on a fine grid: where the profile would penetrate the solid a contact is born,
and an adhesionless contact carrying tension is split; the solve restarts until nothing changes.

Without an initial contact set the solve follows the approach path: first touch at the highest
peak, then quasi-static loading in steps of penetration up to the target (load control switches to
the target load once it is bracketed), so that the same scene always gives the same answer.
"""
from __future__ import annotations

import functools
import time

import attrs
import numpy as np

from ._validation import in_range, int_range
from .adhesion.base import AdhesionModel
from .adhesion.none import NoAdhesion
from .contact.edges import EdgeContext
from .contact.fields import NormalizedProfile, displacement, friction, solve_fields
from .contact.mesh import (MeshSpec, build_mesh, clustered_nodes, element_counts,
                           zone_patterns)
from .contact.topology import TWO_PI, TopologyChange, negative_regions, repair
from .kernels.half_plane import HalfPlane
from .result import ContactResult, SolveStatus
from .solvers.base import NonlinearSolver, Tolerances
from .solvers.bisection import Bisection


@attrs.frozen(kw_only=True)
class Discretization:
    """Mesh and checking resolution.

    Parameters
    ----------
    elements : int
        Elements per contact (eq. 4.21's N).
    clustering : float
        Exponent n of the node density of eq. 4.27 (>= 1/2).
    edge_resolution : float or None
        Size of the element at every edge relative to the smallest physical length below the
        contact scale: the memory length of each dissipative relaxation branch (``ζ τ_i/τ``) and
        the adhesion model's lengths (a finite δX). Geometric edge zones (ratio ``grading``) reach
        it (see :mod:`viscocontact.contact.mesh`). ``None`` meshes with eq. 4.22 alone, which
        resolves a length ℓ at an edge only when N ≳ √(α/ℓ).
    grading : float
        Ratio of consecutive element sizes in the edge zones.
    check_points : int
        Points of the uniform grid on which interpenetration is checked.
    path_step : float
        Largest penetration step ``Δ̃`` of the approach path.
    interior_resolution : float or None
        Elements per shortest wavelength of the profile (:attr:`Profile.shortest_wavelength`)
        inside a contact. The clustered mesh of eq. 4.22 puts its largest elements mid-contact
        (``≈ πα/N`` for a half-width α), so a wide contact on a multiscale profile does not
        follow the profile between its collocation points: on the thesis rough profile at
        p̃∞ = 0.6 a contact 1.1 wide with 32 elements departed from the profile by 8e-3 of
        its amplitude between collocation points, and a merged contact spanned a valley where
        the solid separates. A contact's elements are therefore doubled from ``elements`` (up
        to :data:`INTERIOR_CAP`) until its largest element is at most
        ``λ_min/interior_resolution``. ``None``: ``elements`` for every contact. The target does
        not scale with ``elements``: a mesh-convergence study that doubles ``elements`` must
        double ``interior_resolution`` too, or the wide contacts keep their counts (doubling
        ``elements`` alone gave an observed order of 0.85 on a crowded rough case, both
        together 2.0; ``docs/verification.md``).
    """

    elements: int = attrs.field(default=64, validator=int_range(8, 4096))
    clustering: float = attrs.field(default=1.0, validator=in_range(0.5, 4.0))
    edge_resolution: float | None = attrs.field(default=0.1, validator=attrs.validators.optional(
        in_range(1e-3, 1.0)))
    grading: float = attrs.field(default=1.15, validator=in_range(1.05, 2.0))
    check_points: int = attrs.field(default=2048, validator=int_range(64, 1 << 20))
    path_step: float = attrs.field(default=0.05, validator=in_range(1e-4, 1.0))
    interior_resolution: float | None = attrs.field(
        default=8.0, validator=attrs.validators.optional(in_range(1.0, 64.0)))


#: Most elements per contact that :attr:`Discretization.interior_resolution` refines to.
INTERIOR_CAP = 512
MIN_WIDTH = 1e-8
#: A merged adhesionless contact whose tension, at most this fraction of the largest pressure,
#: and split alternate is refined (the sign of a nearly vanishing pressure is below the mesh's
#: error: 1e-3 of the largest pressure measured at 64 elements across a narrow valley); a
#: larger tension that alternates is reported as a cycle.
REFINED_TENSION = 1e-2
MIN_GAP = 1e-8
#: A Jacobian request after the residual fell by less than this factor since the previous one
#: gets the full difference Jacobian instead of the grouped block-diagonal one ...
SLOW_CONTRACTION = 0.25
#: ... when there are at most this many edges (its cost is one evaluation per edge; at 14 edges
#: it doubled Newton's evaluations on the rough adhesionless case, 621 -> 1732).
FULL_JACOBIAN_EDGES = 8
#: Residual evaluations allowed to one solver call of an approach step (a converging step takes
#: 10-30; one that fails near a fold ran to 300 before the step was halved).
APPROACH_BUDGET = 80
#: Lengths below this (q0-scaled) are not resolved by the edge zones: a memory length ζτ_i/τ
#: below it changes areas by O(ζ/α) only, and resolving it costs elements at every edge.
SMALLEST_RESOLVED = 1e-6


def mesh_spec(disc: Discretization, kernel, adhesion) -> MeshSpec:
    """The mesh of a problem: eq. 4.22 plus edge zones down to ``edge_resolution`` times the
    smallest physical length (memory lengths of the dissipative branches, adhesion lengths).

    Without a finite edge advance, an elastic kernel (no dissipative branch) gets no zones: its
    edge fields are self-similar square-root fields, which eq. 4.22 with the calibrated fit
    already resolves. Neither does a kernel whose memory lengths are all below
    ``SMALLEST_RESOLVED`` or above the period. A finite advance δX always gets zones aligned with
    it, so that the enlarged contact of the energy balance is the bordered base mesh
    (:meth:`~viscocontact.contact.edges.EdgeContext.bordered_release`).
    """
    memory = [float(z) for z in getattr(kernel, "zetas", ())]
    advance = [ell for ell in adhesion.resolved_lengths() if ell > 0]
    if disc.edge_resolution is None or not (memory or advance):
        return MeshSpec(elements=disc.elements, exponent=disc.clustering, grading=disc.grading)
    # memory lengths below SMALLEST_RESOLVED are not resolved, longer than the period need no zone
    lengths = ([ell for ell in memory if SMALLEST_RESOLVED <= ell < TWO_PI]
               + [ell for ell in advance if ell < TWO_PI])
    smallest = None
    if lengths:
        smallest = max(disc.edge_resolution * min(lengths), SMALLEST_RESOLVED)
    return MeshSpec(elements=disc.elements, exponent=disc.clustering, grading=disc.grading,
                    smallest=smallest, advance=min(advance) if advance and smallest else None)


def residual_scale(kernel) -> float:
    """``max(1, E_eff/E0)``: the factor on the edge residual tolerance for a prepared kernel.

    ``E_eff = 1/|K(1)|`` is the modulus the solid shows at the fundamental wavelength (``E0`` in
    the relaxed limit, ``E∞`` in the glassy one). Edge residuals scale with the stresses, and so
    does their round-off: at ``ζ → ∞`` with ``β = 1e4`` an absolute tolerance of 1e-9 lies below
    what double precision can resolve.
    """
    k1 = abs(complex(kernel.compliance(1.0)))
    return max(1.0, 1.0 / k1) if k1 > 0 and np.isfinite(k1) else 1.0


@attrs.frozen(kw_only=True, eq=False)
class Prepared:
    """What a problem precomputes once: kernel tables, normalised profile, m2."""

    kernel: object
    shape: NormalizedProfile
    m2: float


class _EdgeSystem:
    """The nonlinear system in the edge positions for a fixed contact set."""

    def __init__(self, owner: "_Run", control: dict, edges):
        self.owner = owner
        self.control = control
        self.spec = owner.spec
        # elements and zones are fixed in a solve: the residual is then smooth in the edges
        self.counts = owner.counts_for(edges)
        self.zones = zone_patterns(edges, self.spec, self.counts)
        self.cache = {}
        self.evaluations = 0
        self.last_valid = None      # last edge vector that was a valid contact set
        self._last_size = None      # max |r| where the previous Jacobian was taken

    def evaluate(self, x):
        from .deadline import check as check_deadline; check_deadline()  # noqa: E702
        key = x.tobytes()
        if key in self.cache:
            return self.cache[key]
        o = self.owner
        if not np.all(np.isfinite(x)):
            return None, None, np.full(len(x), np.inf)
        new, changed, reason, full = repair(x, MIN_WIDTH, MIN_GAP)
        if changed:
            raise TopologyChange(reason, new, full)
        mesh = build_mesh(x, self.spec, self.zones, self.counts)
        fields = solve_fields(mesh, o.prep.kernel, o.prep.shape, **self.control)
        ctx = EdgeContext(fields, o.prep.kernel, o.prep.shape, self.spec, o.prep.shape.amplitude,
                          self.zones, self.counts)
        r = o.problem.adhesion.residuals(ctx)
        self.evaluations += 1
        self.cache = {key: (fields, ctx, r)}
        self.last_valid = x.copy()
        return fields, ctx, r

    def residual(self, x):
        return self.evaluate(np.asarray(x, dtype=float))[2]

    def jacobian(self, x):
        """Forward-difference Jacobian: block-diagonal by grouping, full when that is too slow.

        Grouped: all left edges are moved together, then all right edges, two residual
        evaluations whatever the number of contacts (Curtis-Powell-Reid grouping), and the 2x2
        block of each contact kept. The coupling between contacts is left out, so Newton on it
        converges linearly when contacts interact (on the thesis rough profile at ζ = 1e-6,
        three contacts 0.05 apart: the residual fell by a factor 3 per iteration, 193
        evaluations for one approach step). So when the residual has fallen by less than a
        factor :data:`SLOW_CONTRACTION` since the previous Jacobian, and there are at most
        :data:`FULL_JACOBIAN_EDGES` edges, the full Jacobian is differenced instead (one
        evaluation per edge; the same step then took 29).
        """
        x = np.asarray(x, dtype=float)
        r0 = self.residual(x)
        n = len(x)
        half = 0.5 * (x[1::2] - x[0::2])
        h = 1e-7 * np.maximum(half, 1e-3)
        size = float(np.max(np.abs(r0))) if n else 0.0
        slow = self._last_size is not None and size > SLOW_CONTRACTION * self._last_size
        self._last_size = size
        if slow and n <= FULL_JACOBIAN_EDGES:
            J = np.empty((n, n))
            for i in range(n):
                xp = x.copy()
                xp[i] += h[i // 2]
                J[:, i] = (self.residual(xp) - r0) / h[i // 2]
            return J
        J = np.zeros((n, n))
        for parity in (0, 1):
            xp = x.copy()
            xp[parity::2] += h
            dr = self.residual(xp) - r0
            for j in range(n // 2):
                J[2 * j:2 * j + 2, 2 * j + parity] = dr[2 * j:2 * j + 2] / h[j]
        return J

    def orientation(self):
        n = self.owner.n_edges
        return np.tile([-1.0, 1.0], n // 2)

    def max_step(self, x):
        half = 0.5 * (x[1::2] - x[0::2])
        lim = np.maximum(0.3 * half, 1e-3)
        return np.repeat(lim, 2)


@attrs.frozen(kw_only=True)
class ContactProblem:
    """A rigid periodic profile sliding on a viscoelastic solid (dimensionless, eq. 4.17).

    Parameters
    ----------
    profile, rheology, kernel, adhesion, solver
        The components (``kernel`` default half-plane, ``adhesion`` default none, ``solver``
        required).
    mean_pressure, penetration : float
        Exactly one: load control (p̃∞) or penetration control (Δ̃).
    zeta : float
        ``ζ = q0 V τ >= 0``.
    discretization : Discretization
    tolerances : Tolerances
        Edge residual tolerance in stress-intensity units of the relaxed modulus ``E0``, scaled by
        the stiffness of the solid at this ζ (:func:`residual_scale`): a glassy solid's stresses,
        and the round-off in its edge residuals, are ``E∞/E0`` times larger.
    max_restarts : int
        Largest number of contact-set changes in one equilibrium solve.
    kernel_tolerance : float or None
        Memory branches whose relaxed or frozen limit changes the kernel by at most this much are
        taken in that limit (no memory table; see
        :func:`~viscocontact.kernels.prepared.branch_regimes`). ``None``: only outside
        ``ζ_i ∈ [1e-12, 1e12]``.
    fallback : NonlinearSolver or None
        Taken from where ``solver`` stopped when it does not converge. The default, a bisection
        march that grows its step until the residual changes sign (thesis §4.5.4), follows an edge
        past a fold of its balance (a trailing adhesive neck that runs until it merges with the
        next contact), where Newton-type steps stall.
    """

    profile: object
    rheology: object
    solver: NonlinearSolver
    kernel: object = attrs.field(factory=HalfPlane)
    adhesion: AdhesionModel = attrs.field(factory=NoAdhesion)
    mean_pressure: float | None = None
    penetration: float | None = None
    zeta: float = attrs.field(default=0.0, validator=in_range(0.0))
    discretization: Discretization = attrs.field(factory=Discretization)
    tolerances: Tolerances = attrs.field(factory=lambda: Tolerances(residual=1e-9))
    max_restarts: int = attrs.field(default=200, validator=int_range(1))
    kernel_tolerance: float | None = attrs.field(
        default=None, validator=attrs.validators.optional(in_range(0.0, 1e-2, lo_open=True)))
    fallback: NonlinearSolver | None = attrs.field(
        factory=lambda: Bisection(initial_step=2e-3, growth=1.5))

    def __attrs_post_init__(self):
        from .scene import Load

        Load(mean_pressure=self.mean_pressure, penetration=self.penetration)  # validates

    @classmethod
    def from_scene(cls, scene, **options) -> "ContactProblem":
        """The problem a :class:`~viscocontact.scene.Scene` describes."""
        scene = scene.resolve()
        return cls(profile=scene.profile, rheology=scene.rheology, kernel=scene.kernel,
                   adhesion=scene.adhesion, solver=scene.solver,
                   mean_pressure=scene.load.mean_pressure, penetration=scene.load.penetration,
                   zeta=scene.zeta, **options)

    def prepare(self) -> Prepared:
        """Kernel tables for this rheology and ζ, the normalised profile and its m2."""
        if self.kernel_tolerance is None:
            kernel = self.kernel.prepare(self.rheology, self.zeta)
        else:
            kernel = self.kernel.prepare(self.rheology, self.zeta, tolerance=self.kernel_tolerance)
        return Prepared(kernel=kernel,
                        shape=NormalizedProfile.of(self.profile),
                        m2=float(self.profile.statistics().m2))

    def plan(self, prepared: Prepared | None = None):
        """What a solve of this problem will compute and what it skips
        (:class:`~viscocontact.plan.SolvePlan`; ``viscocontact solve --explain`` prints it)."""
        from .plan import solve_plan

        return solve_plan(self, prepared or self.prepare())

    def solve(self, initial=None, *, fields: bool = False, prepared: Prepared | None = None,
              raise_on_failure: bool = False) -> ContactResult:
        """Equilibrium of the problem.

        Parameters
        ----------
        initial : ContactResult or array of edges, optional
            Contact set to start from (a previous solution along a loading path). Without it the
            approach path from first touch is followed.
        fields : bool
            Also return pressure, displacement and gap on the check grid.
        prepared : Prepared, optional
            Reuse kernel tables (e.g. along a load path at fixed ζ).
        raise_on_failure : bool
            Raise :class:`~viscocontact.errors.ConvergenceError` (carrying the result) instead of
            returning a result with ``converged = False``.

        Notes
        -----
        BLAS runs single-threaded during the solve: the dense systems are a few hundred to a few
        thousand unknowns, where a second thread costs more than it gains on a loaded machine,
        and the result is then the same to the last bit as in a study's worker processes.
        """
        from ._blas import single_blas_thread

        with single_blas_thread():      # small dense systems: threads cost more than they gain
            run = _Run(self, prepared or self.prepare())
            result = run.solve(initial, fields)
        if raise_on_failure and not result.converged:
            from .errors import ConvergenceError

            raise ConvergenceError(result.message, result)
        return result


def _inside(x, edges, closed: bool) -> np.ndarray:
    """Which of the points ``x`` lie in a contact ``[edges[2j], edges[2j+1]]`` (periodic;
    ``closed``: the edges count as inside)."""
    inside = np.zeros(np.shape(x), bool)
    for a, b in zip(edges[0::2], edges[1::2]):
        for shift in (-TWO_PI, 0.0, TWO_PI):
            xs = x + shift
            inside |= ((xs >= a) & (xs <= b)) if closed else ((xs > a) & (xs < b))
    return inside


class _Run:
    """State of one solve (counters, events)."""

    def __init__(self, problem: ContactProblem, prep: Prepared):
        self.problem = problem
        self.prep = prep
        self.disc = problem.discretization
        self.spec = mesh_spec(self.disc, prep.kernel, problem.adhesion)
        self.iterations = 0
        self.evaluations = 0
        self.events: list[str] = []
        self.history: list[float] = []
        self.n_edges = 0
        shape = prep.shape
        self.origin = shape.peak_position - np.pi
        tol = problem.tolerances
        self.tolerances = attrs.evolve(tol, residual=tol.residual * residual_scale(prep.kernel))
        self._noise: dict[tuple, float] = {}      # round-off floor per (edges, elements)
        # (point, elements): a contact holding the point gets at least that many elements
        self._refined: list[tuple[float, int]] = []

    # ---- mesh ---------------------------------------------------------------------------------
    def counts_for(self, edges) -> tuple | None:
        """Elements of each contact of an equilibrium solve starting from ``edges``: ``elements``
        doubled until the contact's largest element resolves the profile's shortest wavelength
        (:attr:`Discretization.interior_resolution`), at most :data:`INTERIOR_CAP`, and at least
        the count recorded for any point of the contact by :meth:`refine_at`; ``None`` when
        every contact keeps ``elements``."""
        spec, wavelength = self.spec, self.prep.shape.wavelength
        edges = np.asarray(edges, dtype=float)
        if edges.size < 2:
            return None
        target = (None if self.disc.interior_resolution is None or wavelength is None
                  else wavelength / self.disc.interior_resolution)
        counts = []
        for a, b in zip(edges[0::2], edges[1::2]):
            n = spec.elements
            while (target is not None and n < INTERIOR_CAP
                   and np.max(np.diff(clustered_nodes(0.5 * (b - a), n, spec.exponent))) > target):
                n = min(2 * n, INTERIOR_CAP)
            for point, m in self._refined:
                if _inside(np.array([point]), (a, b), closed=True)[0]:
                    n = max(n, m)
            counts.append(n)
        return None if all(n == spec.elements for n in counts) else tuple(counts)

    def refine_at(self, points, counts) -> bool:
        """Give the contacts holding ``points`` twice the elements they have (``counts``), at
        most ``max(INTERIOR_CAP, elements)``; ``False`` when every one is at that cap already."""
        cap = max(INTERIOR_CAP, self.spec.elements)
        grew = False
        for point, n in zip(points, counts):
            if n < cap:
                self._refined.append((float(point), min(2 * n, cap)))
                grew = True
        return grew

    # ---- checks -----------------------------------------------------------------------------
    def grid(self):
        return self.origin + TWO_PI * (np.arange(self.disc.check_points) + 0.5) / self.disc.check_points

    @functools.cached_property
    def check_x(self):
        """Where interpenetration is checked: the uniform grid and every local maximum of the
        profile, so that a contact narrower than the grid spacing is still born."""
        peaks = self.origin + np.mod(self.prep.shape.maxima - self.origin, TWO_PI)
        return np.unique(np.concatenate([self.grid(), peaks]))

    def gap_outside(self, fields):
        """Gap ``ũ - w`` at the check points outside the contacts (edges excluded by 1% width)."""
        x = self.check_x
        mesh = fields.mesh
        keep = np.ones(x.shape, bool)
        for j in range(mesh.n_contacts):
            a, b = mesh.edges[2 * j], mesh.edges[2 * j + 1]
            pad = 0.01 * (b - a) + 1e-9
            for shift in (-TWO_PI, 0.0, TWO_PI):
                keep &= ~((x + shift > a - pad) & (x + shift < b + pad))
        xs = x[keep]
        if mesh.n_contacts:
            u = displacement(self.prep.kernel, mesh, fields.sigma, xs)
        else:
            u = np.zeros_like(xs)
        w = self.prep.shape.heights(xs) - 1.0 + fields.penetration
        return xs, u - w

    def conformity(self, fields, grid_displacement=None) -> float:
        """Largest ``|ũ - w|`` at the check grid's points inside the contacts: how far the
        discrete solid departs from the profile between collocation points (zero at them), in
        units of the profile amplitude. A discretisation error; see
        :attr:`Discretization.interior_resolution`. ``grid_displacement``: ``ũ`` on the whole
        check grid when it is at hand (:meth:`fields_on_grid`)."""
        x = self.grid()
        mesh = fields.mesh
        inside = _inside(x, mesh.edges, closed=False)
        if not inside.any():
            return 0.0
        xs = x[inside]
        u = (displacement(self.prep.kernel, mesh, fields.sigma, xs) if grid_displacement is None
             else grid_displacement[inside])
        w = self.prep.shape.heights(xs) - 1.0 + fields.penetration
        return float(np.max(np.abs(u - w)))

    def tensile_split(self, fields):
        """Split adhesionless contacts that carry tension inside: the new edges, for each
        contact split its index and the middle of its tensile stretch, and the largest tension
        as a fraction of the largest pressure (``None, [], 0.0`` without tension)."""
        if not isinstance(self.problem.adhesion, NoAdhesion):
            return None, [], 0.0
        mesh = fields.mesh
        sig = fields.sigma
        scale = np.max(np.abs(sig)) if sig.size else 0.0
        out, where, tension = [], [], 0.0
        for j in range(mesh.n_contacts):
            sl = mesh.slice(j)
            s = sig[sl]
            inner = np.zeros(s.shape, bool)
            inner[3:-3] = s[3:-3] > 1e-6 * scale
            if inner.any():
                tension = max(tension, float(np.max(s[3:-3])) / scale)
                idx = np.flatnonzero(inner)
                lo, hi = mesh.left[sl][idx[0]], mesh.right[sl][idx[-1]]
                out += [mesh.edges[2 * j], lo, hi, mesh.edges[2 * j + 1]]
                where.append((j, 0.5 * (lo + hi)))
            else:
                out += [mesh.edges[2 * j], mesh.edges[2 * j + 1]]
        return (np.array(out), where, tension) if where else (None, [], 0.0)

    # ---- equilibrium at one control value ---------------------------------------------------
    def equilibrate(self, edges, control, use_fallback: bool = True, budget: int | None = None,
                    refine: bool = True):
        """Equilibrium at one control value from ``edges`` (contact-set changes included).

        ``use_fallback = False`` skips the fallback march when the primary solver stops, and
        ``budget`` caps the residual evaluations of each solver call: the approach path uses both
        for its trial steps, since a solve that fails near a fold costs hundreds of evaluations
        while a halved step (and at the end :meth:`snap`) finds the jump anyway.

        ``refine = False`` reports a contact whose small tension and split alternate as a cycle
        instead of refining it (:data:`REFINED_TENSION`): the approach's intermediate steps,
        where two contacts about to merge pass through a nearly vanishing pressure between them
        for a moment; a halved step gets past it, and a refinement would stay for the rest of
        the solve.
        """
        p = self.problem
        tolerances = self.tolerances
        if budget is not None:
            tolerances = attrs.evolve(tolerances, max_evaluations=min(budget,
                                                                      tolerances.max_evaluations))
        edges = np.asarray(edges, dtype=float)
        fallback_first = False
        converged_before_births: list[np.ndarray] = []
        splits: list[np.ndarray] = []
        for _ in range(p.max_restarts):
            if edges.size == 0:
                born = self.births_without_contact(control)
                if born is None:
                    return self.no_contact(control)
                edges = born
                continue
            self.n_edges = len(edges)
            system = _EdgeSystem(self, control, edges)
            try:
                tolerances = self.noise_floor(system, edges, tolerances)
                if fallback_first and p.fallback is not None:
                    fallback_first = False
                    res = p.fallback.solve(system, edges, tolerances)
                else:
                    res = p.solver.solve(system, edges, tolerances)
                if not res.converged and p.fallback is not None and use_fallback:
                    self.iterations += res.iterations
                    self.events.append(f"{type(p.solver).__name__} stopped ({res.status.value}); "
                                       f"{type(p.fallback).__name__} takes over")
                    start = res.x if np.all(np.isfinite(res.x)) else edges
                    res = p.fallback.solve(system, start, tolerances)
            except TopologyChange as change:
                self.evaluations += system.evaluations
                self.events.append(change.reason)
                if change.full_contact:
                    # accept closure only if a small-step march closes the contact too (a Newton
                    # trial step may overshoot across the period)
                    start = system.last_valid
                    if start is None or p.fallback is None or self._closes(start, control):
                        return self.full_contact(control)
                    self.events.append("closure rejected: a step overshot the period")
                    edges = start
                    fallback_first = True
                    continue
                edges = change.edges
                continue
            self.evaluations += system.evaluations
            self.iterations += res.iterations
            self.history.extend(float(v) for v in res.residual_history)
            if not res.converged:
                fields, ctx, r = system.evaluate(res.x)
                return ("not_converged", res.x, fields, ctx, float(np.max(np.abs(r))),
                        f"edge solve did not converge: {res.status.value}: {res.message}")
            x = res.x
            fields, ctx, r = system.evaluate(x)
            xs, gap = self.gap_outside(fields)
            regions = negative_regions(xs, gap, 1e-9)
            if regions and any(len(x) == len(y) and np.allclose(x, y, rtol=0, atol=1e-7)
                               for y in converged_before_births):
                # the same equilibrium again: the contacts born from it last time vanished
                # (detached or turned inside out) and would be born again, endlessly
                return ("not_converged", x, fields, ctx, float(np.max(np.abs(r))),
                        "contact set cycles: contacts born where the gap is negative on the "
                        f"check grid ({len(regions)} region(s)) detach again; a finer check grid "
                        "(Discretization.check_points) or mesh may settle it")
            if regions:
                converged_before_births.append(x.copy())
                new = [v for (a, b, _) in regions for v in (a, b)]
                merged, _, _, full = repair(np.concatenate([x, new]), MIN_WIDTH, MIN_GAP)
                self.events.append(f"{len(regions)} contact(s) born")
                if full:
                    return self.full_contact(control)
                edges = merged
                continue
            split, where, tension = self.tensile_split(fields)
            if split is not None and sum(len(split) == len(y)
                                         and np.allclose(split, y, rtol=0, atol=1e-3)
                                         for y in splits) >= 2:
                # split -> the parts merge -> the same tension, twice. A small tension means
                # the pressure nearly vanishes inside the contact, with a sign below what this
                # mesh resolves: refine that contact
                counts = element_counts(self.spec, system.counts, len(x) // 2)
                if tension > REFINED_TENSION or not refine:
                    return ("not_converged", x, fields, ctx, float(np.max(np.abs(r))),
                            "contact set cycles: a merged contact carries tension "
                            f"({tension:.2g} of the largest pressure), and the parts it is "
                            "split into merge again")
                if not self.refine_at([c for _, c in where], [counts[j] for j, _ in where]):
                    return ("not_converged", x, fields, ctx, float(np.max(np.abs(r))),
                            "contact set cycles: a merged contact carries tension, and the parts "
                            "it is split into merge again, with "
                            f"{max(INTERIOR_CAP, self.spec.elements)} elements in the contact")
                self.events.append(
                    "mesh refined in a contact whose tension and split alternate (up to "
                    f"{max(m for _, m in self._refined)} elements): its tension, "
                    f"{tension:.2g} of the largest pressure, is a nearly vanishing "
                    "pressure whose sign the mesh does not resolve")
                splits.clear()
                edges = x
                continue
            if split is not None:
                splits.append(split)
                self.events.append("adhesionless contact split where it carried tension "
                                   f"(up to {tension:.2g} of the largest pressure)")
                edges = split
                continue
            finer = self.counts_for(x)
            if finer is not None and (system.counts is None
                                      or any(a > b for a, b in zip(finer, system.counts))):
                # contacts grew past what their meshes in this solve resolve inside them
                self.events.append(f"mesh refined inside contacts (up to {max(finer)} elements) "
                                   "to resolve the profile between collocation points")
                edges = x
                continue
            return ("converged", x, fields, ctx, float(np.max(np.abs(r))), "converged")
        return ("not_converged", edges, None, None, np.inf,
                f"contact set still changing after {p.max_restarts} restarts")

    def noise_floor(self, system, x, tolerances):
        """``tolerances`` with the residual tolerance raised to the round-off floor of the edge
        residuals when that floor is higher.

        The floor is the largest change of any edge residual when every edge moves by a
        relative 1e-13 (far below any physical change), measured once per number of edges and
        elements per contact in a solve (one extra residual evaluation). Energy-balance residuals are differences of
        energies over δX and carry round-off of 1e-10 to 5e-9 on rough multi-contact meshes;
        asking a solver for less than that makes it wander at the floor until its budget runs
        out (200 evaluations for one approach step of the thesis rough profile at p̃∞ ≈ 0.4).
        The accepted floor is four times the measured change; the result reports the actual
        residual.
        """
        n = (len(x), system.counts)
        if n not in self._noise:
            xp = x * (1.0 + 1e-13)
            r1 = system.residual(xp)
            r0 = system.residual(x)           # last: the solver's first call finds it cached
            d = np.abs(r1 - r0)
            self._noise[n] = float(np.max(d)) if np.all(np.isfinite(d)) else 0.0
        floor = 4.0 * self._noise[n]
        if floor <= tolerances.residual:
            return tolerances
        if not any(e.startswith("residual tolerance raised") for e in self.events[-3:]):
            self.events.append(f"residual tolerance raised to the round-off floor {floor:.2g}")
        return attrs.evolve(tolerances, residual=floor)

    def _closes(self, edges, control) -> bool:
        """Whether the bisection march from ``edges`` closes the contact over the period."""
        system = _EdgeSystem(self, control, edges)
        self.n_edges = len(edges)
        try:
            self.problem.fallback.solve(system, edges, self.tolerances)
        except TopologyChange as change:
            self.evaluations += system.evaluations
            return change.full_contact
        self.evaluations += system.evaluations
        return False

    def births_without_contact(self, control):
        if "penetration" not in control:
            # load control with no contact: only a compressive target needs one
            return None if control["mean_pressure"] <= 0 else self.first_touch()[1]
        x = self.check_x
        w = self.prep.shape.heights(x) - 1.0 + control["penetration"]
        regions = negative_regions(x, -w, 0.0)
        if not regions:
            return None
        return np.array([v for (a, b, _) in regions for v in (a, b)])

    def no_contact(self, control):
        return ("no_contact", np.zeros(0), None, None, 0.0, "no contact at this load")

    def full_contact(self, control):
        return ("full_contact", np.zeros(0), None, None, 0.0, "contact closed over the period")

    # ---- the approach path ------------------------------------------------------------------
    def first_touch(self):
        shape = self.prep.shape
        xp = shape.peak_position
        kappa = max(-float(shape.profile.curvatures(xp)) / shape.amplitude, 1e-6)
        a0 = min(np.sqrt(2e-3 / kappa), np.pi / 8)
        d0 = max(1.0 - float(shape.heights(xp + a0)), 1e-9)
        return d0, np.array([xp - a0, xp + a0])

    def solve(self, initial, want_fields):
        t0 = time.perf_counter()
        p = self.problem
        target = ({"penetration": p.penetration} if p.penetration is not None
                  else {"mean_pressure": p.mean_pressure})
        if initial is not None and getattr(initial, "full_contact", False):
            out = self.from_full_contact(target)
        elif initial is not None:
            edges = np.asarray(getattr(initial, "edges", initial), dtype=float).ravel()
            out = self.equilibrate(edges, target)
            if out[0] == "not_converged" and p.adhesion.work_of_adhesion <= 0:
                # an adhesionless equilibrium does not depend on the path: start afresh
                self.events.append(f"no equilibrium from the given contact set ({out[5]}); "
                                   "solved from first touch")
                self._refined.clear()       # the same answer as a solve from first touch
                out = self.approach(target)
        else:
            out = self.approach(target)
            if "mean_pressure" in target and out[0] == "converged" and p.adhesion.work_of_adhesion > 0:
                out = self.stable_under_load(out, target)
        return self.assemble(out, target, want_fields, time.perf_counter() - t0)

    # ---- stability under load control ----------------------------------------------------------
    def load_stiffness(self, state, eps: float) -> float:
        """``dp̃∞/dΔ̃`` at a converged state, by one penetration-controlled solve at ``Δ̃ - eps``
        (NaN when that solve does not converge)."""
        fields = state[2]
        trial = self.equilibrate(state[1], {"penetration": fields.penetration - eps},
                                 use_fallback=False, budget=APPROACH_BUDGET)
        if trial[0] != "converged":
            return np.nan
        return (fields.mean_pressure - trial[2].mean_pressure) / eps

    def stable_under_load(self, out, target):
        """The approach's load-controlled root if it is stable, else the stable one below it.

        An adhesive contact has roots of ``p̃∞(Ã) = target`` on a branch where the load falls as
        the contact grows (``dp̃∞/dΔ̃ < 0``; Johnson's wavy contact between its load maximum and
        closure). Under load control such a root is unstable: approached from first touch at a
        fixed load, the contact stops growing at the first stable root, which has a smaller area.
        The approach can still land on the unstable one when a jump overshoots the load maximum.
        Then the penetration is lowered step by step, over the load maximum, until the load falls
        below the target on the stable side (``dp̃∞/dΔ̃ > 0``), and the load-controlled root is
        solved from the closer bracket. A root whose stiffness cannot be decided stays as it is
        (an event says so); when no stable root is found the solve fails with the reason.
        """
        eps = 1e-3 * self.disc.path_step
        k = self.load_stiffness(out, eps)
        if not np.isfinite(k):
            self.events.append("stability under load control not decided: the perturbed "
                               "penetration-controlled solve did not converge")
            return out
        if k >= 0:
            return out
        self.events.append(f"root unstable under load control (dp/dΔ = {k:.3g}); "
                           "looking for the stable root at a smaller penetration")
        goal = target["mean_pressure"]
        state, step = out, 0.125 * self.disc.path_step
        p_prev = out[2].mean_pressure
        for _ in range(400):                            # a guard; the march ends well before
            if step < 1e-6 * self.disc.path_step:
                break
            d_next = state[2].penetration - step
            trial = self.equilibrate(state[1], {"penetration": d_next}, budget=APPROACH_BUDGET)
            if trial[0] != "converged":
                step *= 0.5
                continue
            p_next = trial[2].mean_pressure
            if p_next < goal and p_next < p_prev:       # crossed the target on the stable side
                start = trial if goal - p_next < p_prev - goal else state
                final = self.equilibrate(start[1], target)
                if final[0] == "converged" and self.load_stiffness(final, eps) >= 0:
                    return final
                break
            state, p_prev = trial, p_next
            step = min(1.5 * step, 0.5 * self.disc.path_step)
        fields, ctx = out[2], out[3]
        return ("not_converged", out[1], fields, ctx, out[4],
                "the equilibrium found is unstable under load control (dp̃∞/dΔ̃ = "
                f"{k:.3g} < 0) and no stable root was found at smaller penetration")

    def from_full_contact(self, target):
        """Continue from a closed contact. With infinitely short-range adhesion a closed
        interface has no flaw to open from (the energy release of a vanishing gap is zero), so
        it stays closed at any load; without adhesion it stays closed while it carries no
        tension, and otherwise the contact is found afresh along the approach path."""
        if self.problem.adhesion.work_of_adhesion > 0:
            return self.full_contact(target)
        if "mean_pressure" in target and self.closure_supports(target["mean_pressure"]):
            return self.full_contact(target)
        if "penetration" in target:
            _, _, _, osc = self.closed_stress()
            if self.full_contact_mean_pressure(target["penetration"]) >= float(np.max(osc)):
                return self.full_contact(target)
        return self.approach(target)

    def full_contact_mean_pressure(self, penetration: float) -> float:
        """``p̃∞`` of the closed contact at a penetration (NaN on an incompressible solid)."""
        _, rh, _, _ = self.closed_stress()
        c0 = self.prep.kernel.mean
        return -(penetration - 1.0 + rh[0].real) / (2 * np.pi * c0) if c0 != 0 else np.nan

    def approach(self, target):
        if "penetration" in target and target["penetration"] <= 0:
            # approached from afar, the profile first touches at Δ̃ = 0 (adhesion acts only on
            # contact), so no contact exists yet; only a retraction path reaches Δ̃ <= 0 in contact
            return self.no_contact(target)
        d0, edges = self.first_touch()
        if self.wants_to_grow(edges, {"penetration": d0}):
            # adhesion pulls the first contact open at once (a JKR-like jump): look for the state
            # it lands on instead of asking an equilibrium solver for one that does not exist
            jump = self.snap(edges, {"penetration": d0})
            if jump is not None:
                self.events.append("first contact jumped")
                out = jump
            else:
                out = self.equilibrate(edges, {"penetration": d0})
        else:
            out = self.equilibrate(edges, {"penetration": d0})
        if out[0] == "not_converged":
            # adhesion can make the first contact jump to a larger size at once
            jump = self.snap(edges, {"penetration": d0})
            if jump is not None:
                self.events.append("first contact jumped")
                out = jump
        if out[0] == "not_converged" and "mean_pressure" in target:
            direct = self.at_target_from_first_touch(edges, target)
            if direct is not None:
                return direct
        if out[0] != "converged":
            return out
        state = out
        d_prev = d0
        if "penetration" in target:
            d_end = target["penetration"]
        else:
            d_end = None
        step = self.disc.path_step
        while True:
            fields = state[2]
            if d_end is None and fields.mean_pressure >= target["mean_pressure"]:
                final = self.equilibrate(state[1], target)
                if final[0] == "not_converged":
                    jump = self.snap(state[1], target)
                    if jump is not None:
                        self.events.append("contact jumped at the target load")
                        return jump
                return final
            if d_end is not None and abs(d_end - d_prev) <= 1e-15:
                return state
            if d_end is None:
                d_next = d_prev + step
            else:
                d_next = d_prev + np.clip(d_end - d_prev, -step, step)
            # the fallback march only once the step is small enough for a fold to be likely
            trial = self.equilibrate(state[1], {"penetration": d_next},
                                     use_fallback=step < self.disc.path_step / 16,
                                     budget=APPROACH_BUDGET, refine=d_next == d_end)
            if trial[0] == "converged":
                state, d_prev = trial, d_next
                step = min(step * 1.5, self.disc.path_step)
                continue
            if trial[0] == "full_contact":
                if d_end is None and not self.closure_supports(target["mean_pressure"]):
                    return self.equilibrate(state[1], target)   # finish in load control
                return trial
            if step < self.disc.path_step / 16:
                # the branch ends (a fold): the contact jumps; look for the state it lands on
                jump = self.snap(state[1], {"penetration": d_next})
                if jump is None:
                    return trial
                if jump[0] == "full_contact":
                    return jump
                self.events.append(f"contact jumped at penetration {d_next:.6g}")
                state, d_prev = jump, d_next
                step = self.disc.path_step
                continue
            step *= 0.5
            self.events.append(f"approach step halved to {step:.3g}")

    def at_target_from_first_touch(self, edges, target):
        """The target load solved directly from the first contact widened 4 and 16 times, when
        the first contact has no equilibrium at first touch (or None).

        With strong adhesion at ζ where the trailing edge is toughened, the first contact can
        have no steady equilibrium at the first-touch penetration: its edges run round the
        period together (sinusoid Λ̃ = 0.1, β = 10, γ̃ = 5e-4, ζ = 1: the contact translated
        by two periods before the solver gave up). Under load control the target still has an
        answer (there: full contact); the event log says that the path was cut short.
        """
        centre = 0.5 * (edges[0] + edges[1])
        half = 0.5 * (edges[1] - edges[0])
        for factor in (4.0, 16.0):
            w = min(factor * half, 0.45 * TWO_PI)
            out = self.equilibrate(np.array([centre - w, centre + w]), target)
            if out[0] in ("converged", "full_contact"):
                self.events.append("no equilibrium at first touch; the target load was solved "
                                   f"from the first contact widened {factor:g} times")
                return out
        return None

    def wants_to_grow(self, edges, control) -> bool:
        """Whether every edge of ``edges`` has a negative residual (would advance outward)."""
        self.n_edges = len(edges)
        system = _EdgeSystem(self, control, edges)
        try:
            r = system.residual(edges)
        except TopologyChange:
            return False
        self.evaluations += system.evaluations
        return bool(np.all(np.isfinite(r)) and np.all(r < 0))

    def snap(self, edges, control):
        """Equilibrium reached by an unstable growth of the contacts (or None).

        Every edge that wants to grow (negative residual) is moved outward by a step that
        doubles each time, edges that do not are held; one residual evaluation per step decides.
        Once no edge wants to grow the equilibrium is solved from there, and contacts that meet
        across the period give full contact.
        """
        x = np.asarray(edges, dtype=float).copy()
        grow = np.ones(len(x), dtype=bool)
        factor = 0.5
        while factor < 1e4:
            half = np.repeat(0.5 * (x[1::2] - x[0::2]), 2)
            trial = x + np.where(grow, factor * half, 0.0) * np.tile([-1.0, 1.0], len(x) // 2)
            factor *= 2.0
            merged, changed, _, full = repair(trial, MIN_WIDTH, MIN_GAP)
            if full:
                if ("mean_pressure" not in control
                        or self.closure_supports(control["mean_pressure"])):
                    return self.full_contact(control)
                return None
            self.n_edges = len(merged)
            system = _EdgeSystem(self, control, merged)
            try:
                r = system.residual(merged)
            except TopologyChange:
                continue
            self.evaluations += system.evaluations
            if not np.all(np.isfinite(r)):
                return None
            x, grow = merged, r < 0
            if np.any(grow):
                continue                  # some edge still wants to grow: widen it further
            out = self.equilibrate(merged, control)
            if out[0] in ("converged", "full_contact"):
                return out
            return None
        return None

    # ---- the result -------------------------------------------------------------------------
    def assemble(self, out, target, want_fields, elapsed):
        kind, edges, fields, ctx, resid, message = out
        p = self.problem
        sqrt_m2 = np.sqrt(self.prep.m2) if self.prep.m2 > 0 else np.nan
        adh = p.adhesion
        dx = float(getattr(adh, "edge_perturbation", 0.0))
        extras = {"events": list(self.events), "residual_history": list(self.history),
                  "seconds": elapsed}
        common = dict(iterations=self.iterations, function_evaluations=self.evaluations,
                      zeta=p.zeta, edge_perturbation=dx, extras=extras)
        if kind in ("converged", "not_converged") and fields is not None:
            mesh = fields.mesh
            area = float(np.sum(mesh.width))
            pm = fields.mean_pressure
            mu = friction(mesh, fields.sigma, self.prep.shape, pm)
            terms = adh.edge_terms(ctx) if kind == "converged" else None
            xs, gap = self.gap_outside(fields)
            fld = self.fields_on_grid(fields) if want_fields else None
            extras["conformity"] = self.conformity(
                fields, None if fld is None else fld["displacement"])
            return ContactResult(
                area=area, mean_pressure=pm, penetration=fields.penetration, friction=mu,
                reduced_friction=mu / sqrt_m2, n_contacts=mesh.n_contacts,
                edges=mesh.edges.reshape(-1, 2).copy(), full_contact=False,
                converged=kind == "converged",
                status=SolveStatus.CONVERGED if kind == "converged" else SolveStatus.NOT_CONVERGED,
                message=message, residual=resid, min_gap=float(gap.min()) if gap.size else np.inf,
                edge_terms=terms, fields=fld, **common)
        if kind == "full_contact":
            return self.full_contact_result(target, message, want_fields, common)
        if kind == "no_contact":
            pen = target.get("penetration", np.nan)
            return ContactResult(area=0.0, mean_pressure=0.0, penetration=pen, friction=np.nan,
                                 reduced_friction=np.nan, n_contacts=0, edges=np.zeros((0, 2)),
                                 full_contact=False, converged=True, status=SolveStatus.NO_CONTACT,
                                 message=message, residual=0.0, min_gap=np.inf, **common)
        return ContactResult(area=np.nan, mean_pressure=np.nan, penetration=np.nan, friction=np.nan,
                             reduced_friction=np.nan, n_contacts=0, edges=np.zeros((0, 2)),
                             full_contact=False, converged=False, status=SolveStatus.FAILED,
                             message=message, residual=np.inf, min_gap=np.nan, **common)

    def fields_on_grid(self, fields):
        x = self.grid()
        mesh = fields.mesh
        u = displacement(self.prep.kernel, mesh, fields.sigma, x)
        pres = np.zeros_like(x)
        for shift in (-TWO_PI, 0.0, TWO_PI):
            idx = np.searchsorted(mesh.right, x + shift)
            ok = idx < len(mesh.right)
            idx = np.minimum(idx, len(mesh.right) - 1)
            inside = ok & (x + shift >= mesh.left[idx])
            pres = np.where(inside, -fields.sigma[idx], pres)
        w = self.prep.shape.heights(x) - 1.0 + fields.penetration
        # inside the contacts the gap is zero by the contact condition (the discrete displacement
        # between collocation points differs from the profile by discretisation error only: the
        # result's extras["conformity"])
        inside = _inside(x, mesh.edges, closed=True)
        return {"x": x, "pressure": pres, "displacement": u, "gap": np.where(inside, 0.0, u - w)}

    def closed_stress(self):
        """Full contact: grid ``x``, profile spectrum and the zero-mean stress ``σ̃_osc``."""
        shape = self.prep.shape
        n = max(self.disc.check_points, 1024)
        x = self.origin + TWO_PI * np.arange(n) / n
        rh = np.fft.rfft(shape.heights(x)) / n       # r̃ = Σ rh_m e^{imx} + c.c.
        m = np.arange(len(rh), dtype=float)
        sig_h = np.zeros_like(rh)
        sig_h[1:] = -m[1:] * rh[1:] / self.prep.kernel.multiplier(m[1:])   # û = -(S K/m) σ̂
        return x, rh, sig_h, np.fft.irfft(sig_h * n, n)

    def closure_supports(self, mean_pressure: float) -> bool:
        """Whether full contact carries ``mean_pressure`` without tension (always with adhesion)."""
        if self.problem.adhesion.work_of_adhesion > 0:
            return True
        return mean_pressure >= float(np.max(self.closed_stress()[3]))

    def full_contact_result(self, target, message, want_fields, common):
        """Closed contact: ``u = w`` everywhere; stresses from the Fourier multiplier."""
        shape = self.prep.shape
        x, rh, sig_h, _ = self.closed_stress()
        n = len(x)
        c0 = self.prep.kernel.mean
        if "mean_pressure" in target:
            pm = target["mean_pressure"]
            pen = 1.0 - rh[0].real + 2 * np.pi * c0 * (-pm)
        else:
            pen = target["penetration"]
            if c0 == 0.0:
                if abs(pen - (1.0 - rh[0].real)) > 1e-9:
                    return ContactResult(
                        area=2 * np.pi, mean_pressure=np.nan, penetration=pen, friction=np.nan,
                        reduced_friction=np.nan, n_contacts=1, edges=np.zeros((0, 2)),
                        full_contact=True, converged=False, status=SolveStatus.FAILED,
                        message="full contact on an incompressible solid fixes the penetration "
                                f"at {1.0 - rh[0].real:.6g}; a larger one cannot be imposed",
                        residual=np.inf, min_gap=0.0, **common)
                pm = np.nan
            else:
                pm = -(pen - 1.0 + rh[0].real) / (2 * np.pi * c0)
        sig_h = sig_h.copy()
        sig_h[0] = -pm
        sigma = np.fft.irfft(sig_h * n, n)
        r = shape.heights(x)
        slopes = shape.profile.slopes(x)
        mu = (float(np.mean(sigma * slopes) / pm)
              if abs(pm) > 1e-12 * float(np.mean(np.abs(sigma))) else np.nan)
        sqrt_m2 = np.sqrt(self.prep.m2)
        adhesive = self.problem.adhesion.work_of_adhesion > 0
        ok = adhesive or bool(np.all(sigma <= 1e-9))
        fld = ({"x": x, "pressure": -sigma, "displacement": r - 1.0 + pen,
                "gap": np.zeros_like(x)} if want_fields else None)
        return ContactResult(
            area=2 * np.pi, mean_pressure=float(pm), penetration=float(pen), friction=mu,
            reduced_friction=mu / sqrt_m2, n_contacts=1, edges=np.zeros((0, 2)), full_contact=True,
            converged=ok, status=SolveStatus.CONVERGED if ok else SolveStatus.FAILED,
            message=message if ok else "full contact would carry tension without adhesion",
            residual=0.0, min_gap=0.0, fields=fld, **common)


def solve(scene, **options) -> ContactResult:
    """Solve a :class:`~viscocontact.scene.Scene` (``options`` go to :class:`ContactProblem`)."""
    return ContactProblem.from_scene(scene, **options).solve()
