"""Mesh policy of the boundary-element method: the discretisation a user chooses and the element
counts that each contact of an equilibrium solve gets from it.

* :class:`Discretization`: elements per contact (eq. 4.21), clustering (eq. 4.27), edge zones,
  interior resolution, the check grid and the approach step.
* :func:`mesh_spec`: the :class:`~viscocontact.contact.mesh.MeshSpec` of a problem (eq. 4.22 plus
  edge zones down to the smallest physical length).
* :class:`MeshPolicy`: the element count of each contact of a contact set, from the interior rule
  and the refinements recorded during a solve.
"""
from __future__ import annotations

import attrs
import numpy as np

from ..._validation import in_range, int_range
from ...contact.mesh import MeshSpec, clustered_nodes
from ...contact.topology import TWO_PI
from .sets import inside


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
        it (see :mod:`viscocontact.contact.mesh`); the element at the edge is never wider than
        the shortest relaxation length (:func:`mesh_spec`). ``None`` meshes with eq. 4.22 alone,
        which resolves a length ℓ at an edge only when N ≳ √(α/ℓ).
    grading : float
        Ratio of consecutive element sizes in the edge zones.
    check_points : int
        Points of the uniform grid on which interpenetration is checked.
    path_step : float
        Largest step of the approach path (in the penetration ``Δ̃``; under load control, in
        the load that moves the first contact as far). Its events (folds, births, merges) are
        located to 1/256 of it (:mod:`~viscocontact.methods.bem.approach`), so the state reached
        is converged in the step: a smaller step reaches the same equilibrium
        (``benchmarks/approach_paths.py``).
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
    # (attrs' stubs type a field by its default, a float, not by its float | None annotation)
    edge_resolution: float | None = attrs.field(default=0.1, validator=attrs.validators.optional(
        in_range(1e-3, 1.0)))  # type: ignore[arg-type]
    grading: float = attrs.field(default=1.15, validator=in_range(1.05, 2.0))
    check_points: int = attrs.field(default=2048, validator=int_range(64, 1 << 20))
    path_step: float = attrs.field(default=0.05, validator=in_range(1e-4, 1.0))
    interior_resolution: float | None = attrs.field(
        default=8.0,
        validator=attrs.validators.optional(in_range(1.0, 64.0)))  # type: ignore[arg-type]


#: Most elements per contact that :attr:`Discretization.interior_resolution` refines to.
INTERIOR_CAP = 512
#: Lengths below this (q0-scaled) are not resolved by the edge zones: a memory length ζτ_i/τ
#: below it changes areas by O(ζ/α) only, and resolving it costs elements at every edge.
SMALLEST_RESOLVED = 1e-6
#: Smallest edge element of a sharp edge (the closed form δX = 0 with adhesion), which resolves
#: the relaxation lengths of the branches whose memory length is resolved: its glassy K̃ is set
#: below them (wavy thesis scene, p̃∞ = 0.3, ζ = 1e-5: Ã = 2.6623 with edge elements of 1e-6, a
#: whole relaxation length, 2.6487 with 1e-7 and 1e-8).
SHARP_SMALLEST = 1e-8
#: With a finite edge advance δX, memory lengths shorter than this fraction of δX are not
#: resolved either (nor the relaxation lengths of their branches): the energy balance over the
#: advance sees the solid relaxed beyond a glassy layer that thin. On the adhesive wavy contact
#: (Γ̃ = 0.01, β = 10, δX = 1e-4) the area moves by 1.7e-6, 2.3e-6 and 3.2e-5 at ζ = 1e-6, 3e-6
#: and 8e-6 when such a layer is left unresolved, against the 6e-4 of the default grading; a
#: layer of a third of δX (ζ = 3e-5) left unresolved moved it by 3e-4, so thicker layers stay
#: resolved. At ζ = 1e-6 the edge element is then a tenth of δX instead of the 1e-6 floor:
#: aligned with the advance, ten border elements instead of thirty graded ones
#: (``docs/edges.md``, "Meshing the edge").
THIN_MEMORY = 0.1


#: Elements per contact at which a sharp edge's zone resolves its model's length as given
#: (:data:`~viscocontact.adhesion.energy_balance.TIP_ZONE`); with N elements it resolves that
#: length times ``(SHARP_ELEMENTS/N)²``, as the clustered mesh's own edge element scales.
SHARP_ELEMENTS = 64


#: Relative margin by which the shortest relaxation length must undercut ``edge_resolution`` times
#: the shortest memory length to set the edge element (round-off: a standard linear solid with
#: ``β = 1/edge_resolution`` has the two equal).
RELAXATION_MARGIN = 1e-9


def relaxation_lengths(kernel) -> np.ndarray:
    """The prepared kernel's relaxation lengths (none for a kernel that does not give them)."""
    lengths = getattr(kernel, "relaxation_lengths", None)
    return np.asarray(lengths(), dtype=float) if lengths is not None else np.empty(0)


def branch_relaxation_lengths(kernel, floor: float) -> np.ndarray:
    """The relaxation lengths of the branches whose memory length is resolved (at least
    ``floor``). A creep spectrum's relaxation lengths interlace with its memory lengths, each
    below its own (``r_1 < ζ_1 < r_2 < ζ_2 < ...``; a standard linear solid's ``ζ/β < ζ``), so
    the i-th shortest belongs to the i-th shortest memory length. All of them when the kernel
    gives a different number of each (they cannot be paired)."""
    relaxation = np.sort(relaxation_lengths(kernel))
    memory = np.sort(np.asarray(getattr(kernel, "zetas", ()), dtype=float))
    if relaxation.size != memory.size:
        return relaxation
    return relaxation[memory >= floor]


def memory_floor(adhesion) -> float:
    """Shortest memory length the edge zones resolve: ``SMALLEST_RESOLVED``, or
    ``THIN_MEMORY·δX`` with a finite edge advance δX when that is longer."""
    return max(SMALLEST_RESOLVED, THIN_MEMORY * float(adhesion.edge_advance()))


def mesh_spec(disc: Discretization, kernel, adhesion) -> MeshSpec:
    """The mesh of a problem: eq. 4.22 plus edge zones down to ``edge_resolution`` times the
    smallest physical length (memory lengths of the dissipative branches, adhesion lengths), and
    no coarser than the shortest relaxation length ``ζ τ_r/τ`` (a standard linear solid's
    ``ζ/β``).

    A stiff solid (``β`` above ``1/edge_resolution``) carries most of its compliance in the slow
    branches; at a trailing edge the stress they carry falls to zero across a layer of the
    relaxation length. Edge elements wider than it alternate in sign there (β = 1e4 at ζ = 1:
    elements of 8e-4 across a layer of 1e-4 gave a spurious tension of 1e-3 of the largest
    pressure, and the adhesionless contact was split and merged again endlessly); one element
    per relaxation length gives a smooth layer. Up to ``β = 1/edge_resolution`` the memory
    rule is the finer one and the mesh does not change.

    Without a finite edge advance, an adhesionless elastic kernel (no dissipative branch) gets
    no zones: its edge fields are self-similar square-root fields, which eq. 4.22 with the
    calibrated fit already resolves. A sharp edge (:meth:`~viscocontact.adhesion.base.
    AdhesionModel.sharp_edge`: the closed form δX = 0, whose balance is the fitted K̃ itself)
    gets the zone of its model's length (``TIP_ZONE``) and resolves the relaxation lengths
    with ``edge_resolution`` too, since its K̃ is the glassy one, set below them (on the wavy
    thesis scene, p̃∞ = 0.3, ζ = 1e-4: Ã = 2.6622 with one element per relaxation length,
    2.6509 and 2.6486 with a third and a tenth of one). Neither does a kernel whose memory lengths are all below
    ``SMALLEST_RESOLVED`` or above the period. With a finite advance δX, memory lengths below
    ``THIN_MEMORY·δX`` are not resolved either, nor the relaxation lengths of their branches
    (:func:`branch_relaxation_lengths`). A finite advance δX always gets zones aligned with
    it, so that the enlarged contact of the energy balance is the bordered base mesh
    (:meth:`~viscocontact.contact.edges.EdgeContext.bordered_release`); other adhesion lengths
    (a cohesive zone) only set the smallest element.

    A sharp edge's length is numerical (the closed form has no length of its own): it scales
    with ``(SHARP_ELEMENTS/N)²`` for N ``elements``, as the clustered mesh's edge element does,
    so that doubling N refines the whole mesh. With a zone of fixed size the error of the fitted
    K̃ stayed while the rest fell: Johnson's wavy contact (Γ̃ = 0.05, p̃∞ = 0) was -2.3e-4,
    -3.5e-5, -1.4e-5, -7.5e-6 and -5.2e-6 off at 16 to 256 elements (observed order 1.6), and is
    -2.4e-4, -4.9e-5, -1.4e-5, -4.7e-6 and +5.7e-7 with the scaled zone.
    """
    memory = [float(z) for z in getattr(kernel, "zetas", ())]
    advance = [ell for ell in adhesion.resolved_lengths() if ell > 0]
    if adhesion.sharp_edge():
        advance = [ell * (SHARP_ELEMENTS / disc.elements) ** 2 for ell in advance]
    if disc.edge_resolution is None or not (memory or advance):
        return MeshSpec(elements=disc.elements, exponent=disc.clustering, grading=disc.grading)
    edge_advance = float(adhesion.edge_advance())
    # memory lengths below SMALLEST_RESOLVED, or well below a finite advance (THIN_MEMORY), are
    # not resolved; longer than the period they need no zone
    floor = memory_floor(adhesion)
    lengths = ([ell for ell in memory if floor <= ell < TWO_PI]
               + [ell for ell in advance if ell < TWO_PI])
    smallest = None
    if lengths:
        relaxation = [ell for ell in branch_relaxation_lengths(kernel, floor) if ell < TWO_PI]
        sharp = relaxation if adhesion.sharp_edge() else []
        smallest = disc.edge_resolution * min(lengths + sharp)
        if relaxation and min(relaxation) < smallest * (1.0 - RELAXATION_MARGIN):
            # no edge element wider than the shortest relaxation length: the stress the slow
            # branches carry drops to zero across it at a trailing edge
            smallest = min(relaxation)
        smallest = max(smallest, SHARP_SMALLEST if sharp else SMALLEST_RESOLVED)
    return MeshSpec(elements=disc.elements, exponent=disc.clustering, grading=disc.grading,
                    smallest=smallest, advance=edge_advance if edge_advance > 0 and smallest
                    else None)


class MeshPolicy:
    """Element counts of the contacts of one solve.

    The interior rule (:attr:`Discretization.interior_resolution`) and the refinements recorded
    by :meth:`refine_at` (a contact whose nearly vanishing tension and split alternate) decide
    how many elements each contact gets; the refinements last for the rest of the solve unless
    :meth:`forget` is called (a restart from first touch).
    """

    def __init__(self, spec: MeshSpec, disc: Discretization, wavelength: float | None):
        self.spec = spec
        self.target = (None if disc.interior_resolution is None or wavelength is None
                       else wavelength / disc.interior_resolution)
        # (point, elements): a contact holding the point gets at least that many elements
        self.refined: list[tuple[float, int]] = []

    @property
    def cap(self) -> int:
        """Most elements a refinement gives a contact."""
        return max(INTERIOR_CAP, self.spec.elements)

    def counts_for(self, edges) -> tuple | None:
        """Elements of each contact of an equilibrium solve starting from ``edges``: ``elements``
        doubled until the contact's largest element resolves the profile's shortest wavelength
        (:attr:`Discretization.interior_resolution`), at most :data:`INTERIOR_CAP`, and at least
        the count recorded for any point of the contact by :meth:`refine_at`; ``None`` when
        every contact keeps ``elements``."""
        spec, target = self.spec, self.target
        edges = np.asarray(edges, dtype=float)
        if edges.size < 2:
            return None
        counts = []
        for a, b in zip(edges[0::2], edges[1::2]):
            n = spec.elements
            while (target is not None and n < INTERIOR_CAP
                   and np.max(np.diff(clustered_nodes(0.5 * (b - a), n, spec.exponent))) > target):
                n = min(2 * n, INTERIOR_CAP)
            for point, m in self.refined:
                if inside(np.array([point]), (a, b), closed=True)[0]:
                    n = max(n, m)
            counts.append(n)
        return None if all(n == spec.elements for n in counts) else tuple(counts)

    def refine_at(self, points, counts) -> bool:
        """Give the contacts holding ``points`` twice the elements they have (``counts``), at
        most :attr:`cap`; ``False`` when every one is at that cap already."""
        cap = self.cap
        grew = False
        for point, n in zip(points, counts):
            if n < cap:
                self.refined.append((float(point), min(2 * n, cap)))
                grew = True
        return grew

    def inherit(self, other: "MeshPolicy", ratio: float) -> None:
        """Take ``other``'s refinements with ``ratio`` times their elements (a coarser mesh of
        the same solve: a refined contact stays refined, by the same factor over this
        policy's elements)."""
        self.refined = [(point, max(self.spec.elements, int(round(m * ratio))))
                        for point, m in other.refined]

    def forget(self) -> None:
        """Drop the recorded refinements (a solve that starts afresh)."""
        self.refined.clear()
