r"""The :class:`AdhesionModel` interface: the closing condition at every contact edge.

Contract for implementers
-------------------------
1. A frozen attrs class; the field ``gamma`` (γ̃ of eq. 4.17) if the model has an adhesion energy.
2. :meth:`residuals` returns one value per edge (order ``X_1, X_2, ...``) that vanishes at
   equilibrium, is increasing in the stress-intensity factor of the edge (positive means "this edge
   is too far out, move it inward") and has the units of a stress-intensity factor ``K̃``
   (``σ̃√(2π r̃)``), so that one tolerance means the same thing for every model.
3. :meth:`edge_terms` reports, per edge, ``δŨ/δX̃`` and ``δL̃_P/δX̃`` (stored-energy sign; they add
   up to ``2πγ̃/Λ̃²`` at equilibrium, eq. 4.20) and the effective work of adhesion (eq. 4.56).
4. Optionally, :meth:`residual_derivatives` returns the derivatives of the residuals with respect
   to every edge (at fixed penetration) and to the penetration (at fixed edges), an array of
   shape ``(n_edges, n_edges + 1)``. It receives the context and a
   :class:`~viscocontact.contact.sensitivity.FieldSensitivity` (``dfields``), which
   differentiates the stress-intensity factors (``dfields.stress_intensity()``), the finite-δX
   energy release (``dfields.energy_release(ctx, i, dx, ddx)``) and any linear functional of the
   stresses (``dfields.linear``) through the factorisation already at hand. The solvers then get
   the Jacobian for about the cost of one residual; the default (``None``) makes the orchestrator
   difference the residuals instead (two to ``n_edges`` extra evaluations per Jacobian). A model
   whose own loads (item 5) count in the load also gives :meth:`pressure_derivatives`, so that
   load control and the path's tangent hold the right load.

5. Optionally, :meth:`field_solution` computes the field of a contact mesh itself (the default is
   :func:`~viscocontact.contact.fields.solve_fields`, contact stresses only). A finite-range model
   adds its stresses outside the contacts there as
   :class:`~viscocontact.contact.fields.KnownLoads` (cohesive zones, whose lengths it solves for),
   reusing ``previous``, the field of the last evaluation of the same contact set, as a start. A
   start may change how fast the model's own solve converges, never which solution it finds:
   where that solve has more than one, the field must not depend on ``previous`` (the built-in
   Maugis-Dugdale zones do not use it), or the residual at given edges depends on the order of
   evaluations. It raises :class:`AdhesionLimitation` for a contact set it cannot handle; the
   orchestrator then treats the point as invalid (a solver steps back) and reports the reason if
   the solve fails.
6. Optionally, :meth:`gap_violation` returns a message when the gap outside the contacts (and
   outside the model's own loads) breaks the model's assumptions at an equilibrium; the
   orchestrator then reports the solve as not converged with that message. Before that,
   :meth:`snap_in` may name regions where the interface jumps into contact although the
   profile does not penetrate (a finite-range law whose traction would act there): the
   orchestrator gives birth to contacts there, as where the profile penetrates.
7. Optionally, :meth:`closed_strength` bounds the tension a closed (full-contact) interface
   carries (default: unbounded with adhesion, 0 without); a finite-range law returns its
   strength, and full contact with a larger tension is not an equilibrium.
8. Optionally, :meth:`cohesive_law` gives the model's traction-separation law as a uniform
   cohesive stress acting below a gap (Dugdale); the spectral method's uniform grid applies it
   cell by cell (:mod:`viscocontact.methods.spectral.cohesive`). A model without one (the
   default, ``None``) has no grid form: its adhesive scenes need the boundary-element method.
9. Optionally, :meth:`bordered_advances` names the edge advances ``(edge, δX)`` whose bordered
   fields (:meth:`EdgeContext.border <viscocontact.contact.edges.EdgeContext.border>`)
   :meth:`residuals` will ask for on a mesh; on two cores their new rows and columns are then
   computed while the influence matrix is factorised. The result is the same either way; the
   default names none.
10. Optionally, :meth:`outside_model` says why an equilibrium lies where the model does not
    hold, from its edges and the two parts of its friction (the bulk dissipation and the net
    energy flux into the edges' singularities,
    :func:`~viscocontact.contact.fields.edge_flux_friction`); the orchestrator adds the reason
    to the result's message and ``extras["outside_model"]`` and issues a
    :class:`~viscocontact.errors.ModelValidityWarning`. The default: the model holds.

11. Optionally, :meth:`traction` gives the model's traction-separation law itself: the tension
    (``2σ/(E*q0)``, i.e. ``σ̃Λ̃`` in eq. 4.17 units) at a gap ``q0·g >= 0`` beyond contact,
    with :meth:`strength` its peak over ``Λ̃`` and :attr:`quasi_static_zone` the length the
    grid must resolve. The grids apply it cell by cell
    (:func:`~viscocontact.methods.spectral.traction.grid_law`): by the tips of item 8 when the
    model has a Dugdale form, else through the traction itself. The default (``None``): none.
12. Optionally, :meth:`singular_edges` says whether the edges carry a stress singularity at
    equilibrium, through whose tips energy flows (the JKR-like energy balance), or not (no
    adhesion, or a cohesive zone that bounds the stress). Without that flux the friction and
    the dissipated power are two discretisations of one quantity, and the BEM's error estimate
    bounds their estimates by their misfit (:func:`~viscocontact.methods.bem.estimate.estimate`).
    The default: singular wherever there is a work of adhesion and no finite-range law
    (items 8 and 11).

Every method receives an :class:`~viscocontact.contact.edges.EdgeContext`, which computes
stress-intensity factors and the energy terms of eqs. 4.12-4.14 for any edge advance.
"""
from __future__ import annotations

import abc

import attrs
import numpy as np

from ..errors import ViscoContactError


class AdhesionLimitation(ViscoContactError):
    """A contact set that an adhesion model does not handle (contract item 5)."""


@attrs.frozen(kw_only=True)
class EdgeTerms:
    """Energy terms at every edge (dimensionless, equation 4.20 units).

    Attributes
    ----------
    stored : ndarray
        ``δŨ/δX̃`` (stored elastic energy per unit outward edge advance).
    nonconservative : ndarray
        ``δL̃_P/δX̃`` (non-conservative work, eq. 4.14, stored-energy sign).
    target : float
        ``2πγ̃/Λ̃²`` (right-hand side of eq. 4.20).
    effective_work : ndarray
        ``Δγ_eff/Δγ = (δŨ/δX̃)/target`` (eq. 4.56); NaN without adhesion.
    stress_intensity : ndarray
        ``K̃`` at every edge.
    edge_perturbation : float
        The ``q0·δX`` used (0: the δX → 0 limit).
    """

    stored: np.ndarray
    nonconservative: np.ndarray
    target: float
    effective_work: np.ndarray
    stress_intensity: np.ndarray
    edge_perturbation: float


class AdhesionModel(abc.ABC):
    """Edge closing condition; see the module docstring for the contract."""

    def resolved_lengths(self) -> tuple[float, ...]:
        """Lengths (q0-scaled) of the model that the mesh must resolve at every edge, such as a
        finite virtual edge advance; the orchestrator grades the edge zones below the smallest."""
        return ()

    def sharp_edge(self) -> bool:
        """Whether the edge condition is the release rate of the square-root singularity itself
        (``K_e K̃²/4`` with the instantaneous compliance: the δX → 0 energy balance), so that
        the edge zones resolve the solid's relaxation lengths, below which that K̃ is set
        (:func:`~viscocontact.methods.bem.meshing.mesh_spec`). False by default."""
        return False

    def edge_advance(self) -> float:
        """The virtual edge advance ``q0·δX`` the model's balance uses (0: none, or the limit
        δX → 0); reported with every result."""
        return 0.0

    def bordered_advances(self, mesh) -> list[tuple[int, float]]:
        """The ``(edge, δX)`` whose bordered fields (:meth:`EdgeContext.border
        <viscocontact.contact.edges.EdgeContext.border>`) :meth:`residuals` will ask for on
        ``mesh``; none by default (contract item 9). On two cores, what is named here is
        prepared while the influence matrix is factorised, and anything else when asked for,
        with the same result: a wrong list costs time, never a number."""
        return []

    @property
    def work_of_adhesion(self) -> float:
        """γ̃ (0 without adhesion)."""
        return float(getattr(self, "gamma", 0.0))

    def target(self, amplitude: float) -> float:
        """``2πγ̃/Λ̃²`` (eq. 4.20)."""
        return 2.0 * np.pi * self.work_of_adhesion / amplitude**2

    def closed_strength(self, amplitude: float) -> float:
        """The largest tension ``σ̃`` (eq. 4.17 units) that a closed interface carries without
        opening: 0 without adhesion, unbounded for adhesion of vanishing range (a closed
        interface has no flaw to open from); a finite-range law overrides it with its strength."""
        return np.inf if self.work_of_adhesion > 0 else 0.0

    def cohesive_law(self, amplitude: float) -> tuple[float, float, float] | None:
        """``(σ̃0, η, a0)``: a uniform tension σ̃0 (eq. 4.17 units) wherever the gap, in units
        of the amplitude, is below η, and the length ``q0a0`` that its zones span at least
        (the grid must resolve it); None when the model has no such law (contract item 8)."""
        return None

    def traction(self, gap) -> np.ndarray | None:
        """The tension ``σ̃Λ̃ = 2σ/(E*q0)`` at the gaps ``gap`` (``q0·g >= 0`` beyond contact),
        or None when the model has no traction-separation law (contract item 11)."""
        return None

    @abc.abstractmethod
    def residuals(self, ctx) -> np.ndarray:
        """One residual per edge, in stress-intensity units (see the contract)."""

    def residual_derivatives(self, ctx, dfields) -> np.ndarray | None:
        """``∂r_i/∂X_j`` at fixed penetration and ``∂r_i/∂Δ̃`` at fixed edges, shape
        ``(n_edges, n_edges + 1)`` (the penetration last), or None when the model does not
        provide them (contract item 4)."""
        return None

    def pressure_derivatives(self, ctx, dfields) -> np.ndarray | None:
        """``∂p̃∞/∂X_j`` at fixed penetration and ``∂p̃∞/∂Δ̃`` at fixed edges (``n_edges + 1``)
        when the model's own loads (contract item 5) count in the load and change with the
        edges; None (the default): the contact stresses' alone (``dfields.pressure()``)."""
        return None

    def field_solution(self, mesh, kernel, shape, control: dict, *, antisymmetric: bool = False,
                       previous=None):
        """The :class:`~viscocontact.contact.fields.FieldSolution` on ``mesh`` at ``control``
        (``{"penetration": Δ̃}`` or ``{"mean_pressure": p̃∞}``); contract item 5."""
        from ..contact.fields import solve_fields

        return solve_fields(mesh, kernel, shape, antisymmetric=antisymmetric, **control)

    def gap_violation(self, x, gap, fields) -> str | None:
        """A message when the gap ``gap`` at points ``x`` outside the contacts breaks the model at
        an equilibrium (contract item 6); None when it does not."""
        return None

    def snap_in(self, x, gap, fields) -> list[tuple[float, float, float]]:
        """Regions ``(a, b, depth)`` of the points ``x`` outside the contacts (gap ``gap``)
        where a contact is born although the profile does not penetrate (contract item 6);
        none by default."""
        return []

    def outside_model(self, ctx, friction: float, dissipation: float,
                      edge_flux: float) -> str | None:
        """Why the equilibrium of ``ctx`` lies where the model does not hold (contract item
        10), given its friction ``μ = ∫ p r' dx/(λ0 p∞)`` and the parts of the power balance
        in the same units: the bulk ``dissipation`` and the net ``edge_flux`` into the edges'
        singularities; None (the default) when it holds."""
        return None

    def singular_edges(self, amplitude: float) -> bool:
        """Whether the edges carry a stress singularity at equilibrium, through whose tips
        energy flows, for a profile of amplitude ``amplitude`` (contract item 12): a work of
        adhesion without a finite-range law (cohesive or traction-separation)."""
        return (self.work_of_adhesion > 0.0 and self.cohesive_law(amplitude) is None
                and self.traction(0.0) is None)

    @abc.abstractmethod
    def edge_terms(self, ctx) -> EdgeTerms:
        """Energy terms at every edge of an equilibrium (for reporting)."""
