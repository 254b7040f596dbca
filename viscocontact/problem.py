r"""The :class:`ContactProblem`: one steady-sliding contact problem as a value, and its solve.

A problem holds the components (profile, rheology, kernel, adhesion, solver), the load (p̃∞ or
Δ̃), ζ and the discretization; :meth:`ContactProblem.solve` hands it to a
:class:`~viscocontact.methods.base.SolutionMethod`. The boundary-element method
(:mod:`viscocontact.methods.bem`) follows the algorithm of thesis §4.4: mesh every contact
(eqs. 4.21-4.29) → influence matrix of the prepared kernel (eq. 4.32) → stresses for the current
edges (eq. 4.31, penetration or load control) → one residual per edge from the adhesion model
(eqs. 4.9-4.20) → a :class:`NonlinearSolver` moves the edges → contact-set changes → the
approach path from first touch when no contact set is given.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import attrs

from . import _events
from ._validation import in_range, int_range
from .adhesion.base import AdhesionModel
from .adhesion.none import NoAdhesion
from .contact.fields import NormalizedProfile
from .kernels.half_plane import HalfPlane
from .methods.base import Prepared, SolutionMethod
from .methods.bem.meshing import INTERIOR_CAP, SMALLEST_RESOLVED, Discretization, mesh_spec
from .methods.bem.system import residual_scale
from .result import ContactResult
from .solvers.base import NonlinearSolver, Tolerances
from .solvers.bisection import Bisection

__all__ = ["ContactProblem", "Discretization", "Prepared", "solve", "mesh_spec",
           "residual_scale", "INTERIOR_CAP", "SMALLEST_RESOLVED"]


def _component(kind: str):
    """Validator of a component field: an instance of the kind's base class, or an object with
    the base's abstract methods (a duck-typed component); a registered name, a mapping or
    anything else is a :class:`~viscocontact.errors.ValidationError` naming the field."""
    def check(inst, attribute, value):
        from ._registry import _base
        from .errors import ValidationError

        base = _base(kind)()
        if isinstance(value, base) or (
                not isinstance(value, (str, bytes, Mapping)) and value is not None
                and all(hasattr(value, m) for m in getattr(base, "__abstractmethods__", ()))):
            return
        hint = _name_hint(kind, value) if isinstance(value, str) else ""
        raise ValidationError(f"ContactProblem.{attribute.name}", value,
                              f"an instance of {base.__module__}.{base.__qualname__}{hint}")
    return check


def _name_hint(kind: str, name: str) -> str:
    """What to pass instead of a registered name: the object it names."""
    from ._registry import REGISTRIES
    from .errors import PluginError

    try:
        cls = REGISTRIES[kind].get(name)
    except PluginError:
        return (f" (names such as {name!r} are for scene files; the registered {kind} are "
                f"{REGISTRIES[kind].names()})")
    return (f" (the name {name!r} is for scene files: pass the object, "
            f"{cls.__module__}.{cls.__qualname__}(...))")


@attrs.frozen(kw_only=True)
class ContactProblem:
    """A rigid periodic profile sliding on a viscoelastic solid (dimensionless, equation 4.17).

    Parameters
    ----------
    profile, rheology : Profile, Rheology
        The rigid profile and the solid (component objects, e.g. ``Sinusoid(amplitude=0.1)``,
        ``StandardLinearSolid(beta=10.0)``; a registered name is for scene files).
    kernel, adhesion, solver : optional
        Default the half-plane, no adhesion, and the solver :mod:`viscocontact.defaults` picks
        (Broyden for an adhesive problem, bisection otherwise): the defaults of a
        :class:`~viscocontact.scene.Scene`.
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
        next contact), where Newton-type steps stall; once it has brought ``max|r|`` a
        hundredfold below its largest, it finishes with Newton steps (``newton_below``).
    method : SolutionMethod
        How the equilibrium is computed (default ``"auto"``, as a scene's: the spectral method
        for an adhesionless problem, the boundary-element method,
        :class:`~viscocontact.methods.bem.BEM`, for an adhesive one).

    Examples
    --------
    >>> from viscocontact import ContactProblem, Sinusoid, StandardLinearSolid
    >>> problem = ContactProblem(profile=Sinusoid(amplitude=0.1),
    ...                          rheology=StandardLinearSolid(beta=10.0), mean_pressure=0.3,
    ...                          zeta=1.0)
    >>> problem.method.name, type(problem.solver).__name__
    ('auto', 'Bisection')
    """

    # duck-typed components: an instance of the kind's base, or anything with its methods
    profile: Any = attrs.field(validator=_component("profiles"))
    rheology: Any = attrs.field(validator=_component("rheologies"))
    kernel: Any = attrs.field(factory=HalfPlane, validator=_component("kernels"))
    adhesion: AdhesionModel = attrs.field(factory=NoAdhesion, validator=_component("adhesion"))
    solver: NonlinearSolver = attrs.field(
        default=attrs.Factory(lambda self: _default_solver(self.adhesion), takes_self=True),
        validator=_component("solvers"))
    mean_pressure: float | None = None
    penetration: float | None = None
    zeta: float = attrs.field(default=0.0, validator=in_range(0.0))
    discretization: Discretization = attrs.field(factory=Discretization)
    tolerances: Tolerances = attrs.field(factory=lambda: Tolerances(residual=1e-9))
    max_restarts: int = attrs.field(default=200, validator=int_range(1))
    kernel_tolerance: float | None = attrs.field(
        default=None, validator=attrs.validators.optional(in_range(0.0, 1e-2, lo_open=True)))
    fallback: NonlinearSolver | None = attrs.field(
        factory=lambda: Bisection(initial_step=2e-3, growth=1.5, newton_below=1e-2))
    method: SolutionMethod = attrs.field(factory=lambda: _default_method(),
                                         validator=_component("methods"))

    def __attrs_post_init__(self):
        from .load import Load

        Load(mean_pressure=self.mean_pressure, penetration=self.penetration)  # validates

    @classmethod
    def from_scene(cls, scene, **options) -> "ContactProblem":
        """The problem a :class:`~viscocontact.scene.Scene` describes (``options`` set or
        override fields, e.g. ``method=BEM()`` or ``discretization=...``)."""
        scene = scene.resolve()
        values = dict(profile=scene.profile, rheology=scene.rheology, kernel=scene.kernel,
                      adhesion=scene.adhesion, solver=scene.solver, method=scene.method,
                      mean_pressure=scene.load.mean_pressure,
                      penetration=scene.load.penetration, zeta=scene.zeta)
        return cls(**{**values, **options})

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
            result = self.method.solve(self, initial, fields=fields, prepared=prepared)
        _log(result)
        from .errors import warn_accuracy

        warn_accuracy(result)
        if raise_on_failure and not result.converged:
            from .errors import ConvergenceError

            raise ConvergenceError(result.message, result)
        return result


#: Solver events (contact births, merges, refinements, the method chosen) are logged here at
#: INFO as they happen (:mod:`viscocontact._events`); a solve that does not converge logs a
#: WARNING when it ends.
logger = _events.logger


def _log(result: ContactResult) -> None:
    if not result.converged:
        logger.warning("%s: %s (%s)", result.method or "solve", result.status.value,
                       result.message)


def _default_method() -> SolutionMethod:
    from .defaults import METHOD, build

    return build("methods", METHOD)


def _default_solver(adhesion) -> NonlinearSolver:
    from .defaults import build, solver_name

    return build("solvers", solver_name(not isinstance(adhesion, NoAdhesion)))


def solve(scene, **options) -> ContactResult:
    """Solve a :class:`~viscocontact.scene.Scene` (``options`` go to :class:`ContactProblem`)."""
    return ContactProblem.from_scene(scene, **options).solve()
