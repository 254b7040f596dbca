r"""Finite-range adhesion: a Dugdale (Maugis) cohesive zone at every contact edge.

A uniform tensile traction σ0 acts wherever the gap lies in ``(0, h0)``, ``σ0·h0 = Δγ``. In the
units of thesis eq. 4.17 (``γ̃`` as for :class:`EnergyBalance`, the range ``h̃0 = q0h0``):

.. math:: \tilde\sigma_0 = \frac{2\pi\tilde\gamma}{\tilde h_0\tilde\Lambda},\qquad
          \eta = \tilde h_0/\tilde\Lambda,\qquad \tilde\sigma_0\,\eta = 2\pi\tilde\gamma/\tilde\Lambda^2
          \ \text{(the right-hand side of eq. 4.20)},\qquad \sigma_0/E^* = \pi\tilde\gamma/\tilde h_0 .

Formulation. Each contact ``[X_{2j-1}, X_{2j}]`` carries a zone outside each edge where the stress
is the known ``σ̃0``; inside the contact the gap vanishes. The zones enter the field solve as
known loads (:mod:`viscocontact.contact.cohesive`): for given edges their lengths make the stress
bounded at every edge (``K̃_i = 0``, the Maugis–Dugdale condition) — mixed with the tip condition,
``K̃_i = W(g̃(c_i) - η)`` (:meth:`tip_condition`), so that long zones have one root at fixed edges
— solved per evaluation by an inner Newton iteration on the factorisation at hand
(:meth:`field_solution`). The edge residual
is the tip condition ``g̃(c_i) = η`` (:meth:`residuals`; the module docstring of
:mod:`~viscocontact.contact.cohesive` says why the split is this way round), so the outer
unknowns stay the edges and every solver, path and contact-set rule of the BEM applies
unchanged. Viscoelastic dissipation around the zones comes out of the kernel: there is no
virtual edge advance.

The zones must be resolved by the edge mesh: the stress next to the edge is
``σ̃0 + c1 r^{1/2} + c2 r^{3/2} + ...`` only within a fraction of the zone length, and the
stress-intensity fit uses the eight elements next to the edge.
:meth:`resolved_lengths` asks for edge zones graded down to a sixteenth of the quasi-static
Dugdale zone ``q0a0 = h̃0²/(4γ̃)`` (relaxed modulus; a viscoelastic zone lies within
``[a0/2, βa0]``), so that with the default ``edge_resolution = 0.1`` the fit's elements span
``a0/20``.

Necks held by the cohesive traction alone. Where the gap stays below the range across the
whole neck between two contacts (or across the rest of the period beside one contact), the two
zones fill it: there are no tips, the residual of the neck's edges is their ``K̃``, and the
equilibrium is bounded stress at both (:meth:`field_solution`, :meth:`residuals`). A filled
neck whose gap exceeds the range somewhere is not admissible; zones that would meet across such
a neck have no lengths for these edges (a point the solver steps back from).

Tension without contact. A gap that falls below the range outside every zone and contact (the
law would act there without a contact edge) snaps the peak into contact (:meth:`snap_in`, the
jump-in of a JKR-like interface); a stable patch of traction without contact (DMT-like) is not
modelled in the BEM. :meth:`gap_violation` reports such a gap where no contact is born.
"""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import in_range
from ..contact.cohesive import (TipCondition, ZoneError, filled, intensity, neck_ends, partner,
                                room, tips, zone_derivatives, zone_fields, zone_widths)
from .base import AdhesionLimitation, AdhesionModel, EdgeTerms

#: Resolved length of the edge mesh as a fraction of the quasi-static zone ``h̃0²/(4γ̃)``.
ZONE_RESOLUTION = 1.0 / 16.0
#: A gap below ``(1 - GAP_MARGIN)·η`` outside the zones is a violation (:meth:`gap_violation`).
GAP_MARGIN = 1e-3
#: Weight of the free fraction of a neck in the residual of zones about to fill it
#: (:meth:`MaugisDugdale.residuals`).
SLACK = 10.0
#: Points across a neck at which its gap is sampled (:func:`_reclassified_necks`).
NECK_POINTS = 48
#: Maugis's transition parameter λ above which a scene is JKR-like, below which DMT-like.
JKR_LIKE, DMT_LIKE = 5.0, 0.1


@attrs.frozen(kw_only=True)
class MaugisDugdale(AdhesionModel):
    """Maugis–Dugdale (uniform cohesive stress) adhesion of finite range.

    Parameters
    ----------
    gamma : float
        γ̃ = (1-ν²) q0 Δγ/(π E0), finite and >= 0 (eq. 4.17); 0 is no adhesion.
    range : float
        h̃0 = q0·h0, the gap up to which the cohesive stress acts, in ``(0, 10]``.

    Examples
    --------
    >>> m = MaugisDugdale(gamma=5e-4, range=1e-3)
    >>> round(m.strength(0.1), 6), round(m.quasi_static_zone, 6)
    (31.415927, 0.0005)
    """

    gamma: float = attrs.field(validator=in_range(0.0))
    range: float = attrs.field(validator=in_range(0.0, 10.0, lo_open=True))

    def strength(self, amplitude: float) -> float:
        """``σ̃0 = 2πγ̃/(h̃0 Λ̃)`` (tensile)."""
        return 2.0 * np.pi * self.gamma / (self.range * amplitude)

    def closed_strength(self, amplitude: float) -> float:
        """``σ̃0``: a closed interface opens where its tension exceeds the cohesive stress (the
        law's traction at a vanishing gap); 0 without adhesion."""
        return self.strength(amplitude) if self.gamma > 0 else 0.0

    def opening(self, amplitude: float) -> float:
        """``η = h̃0/Λ̃``: the gap at the zone tips, in units of the amplitude."""
        return self.range / amplitude

    def transition_parameter(self, length: float, modulus_ratio: float = 1.0) -> float:
        """Maugis's ``λ = 2σ0 (R/(πE²Δγ))^{1/3} = 2π^{1/3}γ̃^{2/3}/(h̃0 L̃^{1/3} β^{2/3})`` for
        the crest radius ``R = 1/(q0²L)`` (``L̃ = q0L``: the amplitude Λ̃ of a sinusoid, as
        :attr:`~viscocontact.reference.MaugisDugdaleWavy.transition_parameter`) and the modulus
        ``E = βE*``; JKR-like for λ → ∞, DMT-like (rigid) for λ → 0."""
        return (2.0 * np.pi ** (1 / 3) * (self.gamma / modulus_ratio) ** (2 / 3)
                / (self.range * length ** (1 / 3)))

    def tabor(self, length: float, modulus_ratio: float = 1.0) -> float:
        """The Tabor parameter ``μ_T = (RΔγ²/(E²Z0³))^{1/3} = (π²γ̃²/(β²L̃))^{1/3}/(q0Z0)`` with
        Maugis's ``Z0 = 16h0/(9√3)`` (σ0 the Lennard-Jones maximum stress) and ``R`` as in
        :meth:`transition_parameter`; ``λ ≈ 1.401 μ_T``."""
        z0 = 16.0 / (9.0 * np.sqrt(3.0)) * self.range
        return (np.pi**2 * (self.gamma / modulus_ratio) ** 2 / length) ** (1 / 3) / z0

    @property
    def quasi_static_zone(self) -> float:
        """``q0a0 = h̃0²/(4γ̃)``: the zone of an elastic (relaxed) edge much wider than it
        (Dugdale, ``d = πK²/(8σ0²)`` with ``G = Δγ``); ``inf`` without adhesion."""
        return self.range**2 / (4.0 * self.gamma) if self.gamma > 0 else np.inf

    def traction(self, gap) -> np.ndarray:
        """Dugdale's step: ``σ̃0Λ̃ = 2πγ̃/h̃0`` where ``0 <= q0·g < h̃0``, 0 beyond (contract
        item 11; the grids apply it by its tips, :meth:`cohesive_law`)."""
        g = np.asarray(gap, dtype=float)
        return np.where(g < self.range, 2.0 * np.pi * self.gamma / self.range, 0.0)

    def cohesive_law(self, amplitude: float) -> tuple[float, float, float] | None:
        """``(σ̃0, η, q0a0)`` for the spectral method's grid (:meth:`strength`,
        :meth:`opening`, :attr:`quasi_static_zone`); None without adhesion."""
        if self.gamma <= 0:
            return None
        return self.strength(amplitude), self.opening(amplitude), self.quasi_static_zone

    def resolved_lengths(self) -> tuple[float, ...]:
        return (ZONE_RESOLUTION * self.quasi_static_zone,) if self.gamma > 0 else ()

    def field_solution(self, mesh, kernel, shape, control: dict, *, antisymmetric: bool = False,
                       previous=None):
        """The field with the zones that bound the stress at every edge
        (:func:`~viscocontact.contact.cohesive.zone_fields`). A neck may be filled only where its
        gap stays below the range; an open neck whose gap stays between 0 and the range between
        the tips is filled (the law acts across it). Raises :class:`AdhesionLimitation` where no
        zones bound the stress.

        The zones are solved from the same short start at every call, and ``previous`` is not
        used: at fixed edges the zones' equations can have more than one root (a short zone and
        a long one past the minimum of ``K̃(d)``, an open neck and a filled one), so a start
        taken from the last evaluation made the residual at given edges depend on the order of
        evaluations. On campaign seed 189 (sinusoid, SLS β = 3993, confined layer) 83 of the
        135 evaluations of a solve gave another residual from that start than from this one,
        1.8e4 apart (a filled neck against an open one), and where the overdamped motion
        landed changed with how many evaluations it took. So the field is a function of the
        edges and the mesh: a neck fills only where the open zones have no root short of
        meeting or its free interval stays within the range."""
        from ..contact.fields import solve_fields

        base = solve_fields(mesh, kernel, shape, antisymmetric=antisymmetric, **control)
        if self.gamma == 0:
            return base
        n = len(mesh.edges)
        start = np.full(n, min(self.quasi_static_zone, 0.1 * float(np.min(np.diff(
            mesh.edges)[0::2]))))
        stress = self.strength(shape.amplitude)

        eta = self.opening(shape.amplitude)

        def admissible(fields, necks):
            return not np.any(_reclassified_necks(fields, kernel, shape, eta, necks)[1])

        tip = self.tip_condition(shape)
        try:
            fields = zone_fields(base, kernel, stress=stress, control=control, start=start,
                                 admissible=admissible, tip=tip)
            # open zones whose free interval between the tips has no gap beyond the range (and
            # none below the surface): the law acts across it, so the zones fill the neck
            narrow = _reclassified_necks(fields, kernel, shape, eta)[0]
            if np.any(narrow):
                fields = zone_fields(base, kernel, stress=stress, control=control,
                                     start=zone_widths(fields),
                                     full=narrow | filled(mesh.edges, zone_widths(fields)),
                                     admissible=admissible, tip=tip)
            return fields
        except ZoneError as exc:
            raise AdhesionLimitation(f"Maugis-Dugdale zones: {exc}") from exc

    def tip_condition(self, shape) -> TipCondition:
        """The tips' closing condition mixed into the zones' equations (:class:`~viscocontact.
        contact.cohesive.TipCondition`): ``W = K̃_c/(2η)``, the slope of :meth:`residuals`'s
        tip term at its root."""
        eta = self.opening(shape.amplitude)
        return TipCondition(shape=shape, opening=eta,
                            weight=self.critical_intensity(shape.amplitude) / (2.0 * eta))

    def critical_intensity(self, amplitude: float) -> float:
        """``K̃_c = √(4·2πγ̃/Λ̃²)``: the stress-intensity factor whose Irwin energy release
        (relaxed) is the work of adhesion (eq. 4.20); the residuals' scale."""
        return float(np.sqrt(4.0 * self.target(amplitude)))

    def intensity(self, ctx) -> np.ndarray:
        """``K̃`` at every edge (fit with a constant: :func:`~viscocontact.contact.cohesive.
        intensity`); ≈ 0 where a zone is."""
        return intensity(ctx.fields)

    def tip_gaps(self, ctx) -> np.ndarray:
        """``g̃(c_i)/η`` at every zone tip (0 where an edge has no zone)."""
        f = ctx.fields
        if f.loads is None:
            return np.zeros(ctx.n_edges)
        c = tips(f.mesh.edges, f.loads.width)
        g = f.displacement(ctx.kernel, c) - (ctx.shape.heights(c) - 1.0 + f.penetration)
        return np.where(f.loads.width > 0, g, 0.0) / self.opening(ctx.amplitude)

    def residuals(self, ctx) -> np.ndarray:
        """``K̃_c(√(g̃(c_i)/η) - 1) + min(K̃_i, 0)``: the tip condition in stress-intensity units
        (``g̃/η ≈ (K_app/K_c)²`` for a short zone), continued by the compressive ``K̃`` of an edge
        without a zone; increasing as the edge moves out.

        A neck filled by its two zones (:func:`~viscocontact.contact.cohesive.filled`; only
        where its gap stays within the range, :meth:`field_solution`) has no tips: its edges'
        residual is their ``K̃``. Zones about to fill their neck take
        ``max(tip condition, -S K̃_c s)`` with ``s`` the free fraction of the neck
        (:data:`SLACK`), which tends to the filled neck's residual where the zones meet, so that
        the residual is continuous across the switch (both vanish there only if the gap where
        they meet is below the range)."""
        if self.gamma == 0:
            return ctx.stress_intensity()
        e = self._edge_state(ctx)
        r = np.where(e.zone, np.maximum(e.tip, -SLACK * e.kc * e.slack),
                     e.tip + np.minimum(e.k, 0.0))
        return np.where(e.full, e.k, r)

    def _edge_state(self, ctx) -> "_EdgeState":
        """What :meth:`residuals` and :meth:`residual_derivatives` both need of every edge."""
        f = ctx.fields
        edges = f.mesh.edges
        d = zone_widths(f)
        g = self.tip_gaps(ctx)
        kc = self.critical_intensity(ctx.amplitude)
        return _EdgeState(d=d, g=g, k=self.intensity(ctx), kc=kc, zone=d > 0,
                          tip=kc * (np.sqrt(np.maximum(g, 0.0)) - 1.0),
                          slack=1.0 - (d + d[partner(len(d))]) / room(edges),
                          full=filled(edges, d))

    def residual_derivatives(self, ctx, dfields) -> np.ndarray | None:
        """The derivatives of :meth:`residuals` in every edge and the penetration along the
        zones' own equations (:func:`~viscocontact.contact.cohesive.zone_derivatives`): at a
        zone ``K̃_c ġ/(2√(g̃ η))`` (or the slack term's, ``S K̃_c (ḋ_i + ḋ_j - (d_i + d_j)
        Ẇ/W)/W`` for a neck of room ``W``), at an edge without a zone its compressive ``K̃``'s,
        at a filled neck its ``K̃``'s. None where the zone lengths do not follow the edges."""
        if self.gamma == 0:
            return dfields.stress_intensity()
        z = self._zone_derivatives(ctx, dfields)
        if z is None:
            return None
        e = self._edge_state(ctx)
        eta = self.opening(ctx.amplitude)
        root = np.sqrt(np.where(e.zone & (e.g > 0), e.g, 1.0))
        rate = np.where(e.zone & (e.g > 0), e.kc / (2 * root * eta), 0.0)
        out = np.where(e.zone[:, None], rate[:, None] * z.gaps,
                       np.where((e.k < 0)[:, None], z.intensity, 0.0))
        bound = e.zone & (-SLACK * e.kc * e.slack > e.tip)
        if np.any(bound):
            out = np.where(bound[:, None], -SLACK * e.kc * _slack_derivatives(
                ctx.fields.mesh.edges, e.d, z.lengths, out.shape[1]), out)
        return np.where(e.full[:, None], z.intensity, out)

    def pressure_derivatives(self, ctx, dfields) -> np.ndarray | None:
        """``∂p̃∞`` with the zones' force, their lengths following the edges."""
        if self.gamma == 0 or ctx.fields.loads is None:
            return None
        z = self._zone_derivatives(ctx, dfields)
        return None if z is None else z.pressure

    def _zone_derivatives(self, ctx, dfields):
        """:func:`~viscocontact.contact.cohesive.zone_derivatives` once per point (shared by the
        residuals' and the load's derivatives); None where the zone lengths do not follow the
        edges (a singular ``∂K̃/∂d``: the orchestrator differences instead)."""
        key = "maugis-dugdale zones"           # dfields is of this point's field only
        if key not in dfields.memo:
            try:
                f = ctx.fields
                weights = self.tip_condition(ctx.shape).weights(f, ctx.kernel, zone_widths(f))
                dfields.memo[key] = zone_derivatives(f, dfields,
                                                     stress=self.strength(ctx.amplitude),
                                                     tip_weights=weights)
            except np.linalg.LinAlgError:
                dfields.memo[key] = None
        return dfields.memo[key]

    def zone_lengths(self, ctx) -> np.ndarray:
        """Length of the zone at every edge (zeros without adhesion)."""
        loads = ctx.fields.loads
        return np.zeros(ctx.n_edges) if loads is None else np.array(loads.width)

    def snap_in(self, x, gap, fields) -> list[tuple[float, float, float]]:
        """Where the gap outside the zones falls below the range: the interface jumps into
        contact there (the regions, with the gap less the range as ``depth``).

        Inside the range the cohesive traction would act without a contact edge (tension without
        contact), which the BEM does not model. Under a uniform traction a peak that comes
        within the range is pulled towards the solid; for a JKR-like interface (Maugis's λ well
        above 1: about 100 at 5 nm on the thesis's rough profile) that pull is unstable and the
        peak jumps into contact (Maugis 1992's jump-in), so the BEM gives birth to a contact
        there. Where a patch of traction without contact is stable (DMT-like, λ ≲ 1), that is a
        different equilibrium from the one the spectral method's grid finds
        (``docs/cohesive.md``)."""
        from ..contact.topology import negative_regions

        low = self._below_range(x, gap, fields)
        if low is None or not np.any(low):
            return []
        eta = self._eta_of(fields)
        return negative_regions(x, np.where(low, gap - eta, eta), 0.0)

    def _below_range(self, x, gap, fields) -> np.ndarray | None:
        """Which points ``x`` outside the zones have a gap below ``(1 - GAP_MARGIN)·η``."""
        loads = fields.loads
        if self.gamma == 0 or loads is None or len(x) == 0:
            return None
        keep = np.ones(len(x), bool)
        for lo, hi in zip(loads.left, loads.right):
            for shift in (-2 * np.pi, 0.0, 2 * np.pi):
                keep &= ~((x + shift >= lo - 1e-9) & (x + shift <= hi + 1e-9))
        return keep & (gap < (1.0 - GAP_MARGIN) * self._eta_of(fields))

    def gap_violation(self, x, gap, fields) -> str | None:
        low = self._below_range(x, gap, fields)
        if low is None or not np.any(low):
            return None
        eta = self._eta_of(fields)
        where = x[low]
        return (f"the gap falls below the range h0 outside the cohesive zones (at {low.sum()} "
                f"check point(s), x̃ from {where.min():.4g} to {where.max():.4g}; smallest gap "
                f"{gap[low].min() / eta:.3g} h0): the Dugdale law would act there without a "
                "contact edge, which this model does not handle")

    def _eta_of(self, fields) -> float:
        """η of a field with zones: ``σ̃0 = 2πγ̃/(h̃0Λ̃)`` gives ``η = h̃0/Λ̃ = h̃0²σ̃0/(2πγ̃)``."""
        return self.range**2 * float(fields.loads.stress[0]) / (2.0 * np.pi * self.gamma)

    def edge_terms(self, ctx) -> EdgeTerms:
        """Per edge: ``stress_intensity`` the residual's ``K̃`` (≈ 0 at equilibrium);
        ``effective_work`` the zone length over the quasi-static one, ``d/a0`` — at a
        trailing (opening) edge, the apparent toughness ``G/Δγ`` of a zone much shorter than
        the contact (``G = K_app²/(2E*)`` with Dugdale's ``K_app = σ0√(8d/π)``); at a leading
        (closing) edge the far field is ``σ0√(8d/π)·m`` (:mod:`viscocontact.reference.
        dugdale_crack`), so ``G/Δγ = m²·d/a0`` there and ``d/a0`` is the zone length only
        (``docs/cohesive.md``, apparent toughness against ζ); ``stored``
        ``= effective_work·target`` and ``nonconservative = target - stored`` (eq. 4.20 split
        as an energy balance would: what the bulk dissipates around the zone per unit advance,
        stored-energy sign)."""
        target = self.target(ctx.amplitude)
        k = self.intensity(ctx)
        n = ctx.n_edges
        if self.gamma == 0:
            return EdgeTerms(stored=np.zeros(n), nonconservative=np.zeros(n), target=0.0,
                             effective_work=np.full(n, np.nan), stress_intensity=k,
                             edge_perturbation=0.0)
        eff = self.zone_lengths(ctx) / self.quasi_static_zone
        stored = eff * target
        return EdgeTerms(stored=stored, nonconservative=target - stored, target=target,
                         effective_work=eff, stress_intensity=k, edge_perturbation=0.0)


@attrs.frozen(kw_only=True, eq=False)
class _EdgeState:
    """Per edge (:meth:`MaugisDugdale._edge_state`): zone lengths ``d``, tip gaps ``g`` (over
    η), ``K̃``, the scale ``K̃_c``, which edges have a zone, the tip condition, the free
    fraction of each neck and which necks are filled."""

    d: np.ndarray
    g: np.ndarray
    k: np.ndarray
    kc: float
    zone: np.ndarray
    tip: np.ndarray
    slack: np.ndarray
    full: np.ndarray


def _slack_derivatives(edges: np.ndarray, d: np.ndarray, dd: np.ndarray,
                       n_dirs: int) -> np.ndarray:
    """The derivatives (n_edges, D) of every edge's free fraction of its neck,
    ``s = 1 - (d_i + d_j)/W`` with the room ``W = X_L - X_R`` (:func:`~viscocontact.contact.
    cohesive.room`), which moves with the neck's two edges: ``-(ḋ_i + ḋ_j)/W + (d_i + d_j)
    Ẇ/W²``, from the zone lengths ``d`` and their derivatives ``dd`` (n_edges, D)."""
    n = len(d)
    right, left = neck_ends(n)
    unit = np.eye(n_dirs)
    d_room = unit[left] - unit[right]
    facing = partner(n)
    space = room(edges)
    return (-(dd + dd[facing]) / space[:, None]
            + ((d + d[facing]) / space**2)[:, None] * d_room)


def _reclassified_necks(fields, kernel, shape, eta: float,
                       necks: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """``(narrow, wide)``: the edges of open necks whose gap stays between 0 and the range
    ``eta`` between the tips (they fill), and of filled necks with a gap beyond the range (they
    cannot be filled); of the edges ``necks`` only, when given.

    The gap is sampled at :data:`NECK_POINTS` points across each neck; an open neck is
    first tried at three (a neck much wider than the range exceeds it at once), all necks
    in one evaluation of the displacement per stage.

    Parameters
    ----------
    fields : FieldSolution
        A field with its zones (``loads``).
    kernel : PreparedKernel
    shape : NormalizedProfile
    eta : float
        ``η = h̃0/Λ̃`` (:meth:`MaugisDugdale.opening`).
    necks : (n_edges,) bool array, optional
        The edges whose necks to classify (every neck when None).
    """
    edges = fields.mesh.edges
    n = len(edges)
    d = np.asarray(fields.loads.width, dtype=float)
    narrow, wide = np.zeros(n, bool), np.zeros(n, bool)
    right = np.arange(1, n, 2)                  # each neck by its right edge
    left = (right + 1) % n
    if necks is not None:
        necks = np.asarray(necks, bool)
        keep = necks[right] | necks[left]
        right, left = right[keep], left[keep]
    full = filled(edges, d)[right]
    lo = np.where(full, edges[right], tips(edges, d)[right])
    width = np.where(full, room(edges)[right], room(edges)[right] - d[right] - d[left])

    def extremes(which, m):
        """Largest and smallest gap at ``m`` points across the necks ``which``."""
        x = (lo[which, None]
             + width[which, None] * (np.arange(1, m + 1) / (m + 1))[None, :]).ravel()
        gap = (fields.displacement(kernel, x)
               - (shape.heights(x) - 1.0 + fields.penetration)).reshape(-1, m)
        return gap.max(axis=1), gap.min(axis=1)

    top, bottom = np.full(len(right), -np.inf), np.full(len(right), np.inf)
    first = ~full
    if np.any(first):
        top[first], bottom[first] = extremes(first, 3)
    rest = full | ((top < eta) & (bottom >= 0.0))
    if np.any(rest):
        t, b = extremes(rest, NECK_POINTS)
        top[rest], bottom[rest] = np.maximum(top[rest], t), np.minimum(bottom[rest], b)
    over = full & (top > eta)
    within = ~full & (bottom >= 0.0) & (top < eta)   # (a penetrating profile: births)
    wide[right[over]] = wide[left[over]] = True
    narrow[right[within]] = narrow[left[within]] = True
    return narrow, wide
