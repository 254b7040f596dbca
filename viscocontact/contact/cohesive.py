r"""Cohesive zones of a Dugdale law at the contact edges: their lengths for given edges.

Every edge ``X_i`` of a contact carries a zone outside it, ``[X_i - d_i, X_i]`` at a left edge and
``[X_i, X_i + d_i]`` at a right one, where a known uniform tensile stress ``σ̃0`` acts (a
:class:`~viscocontact.contact.fields.KnownLoads` interval). For fixed edges and zone lengths the
problem is linear (:func:`~viscocontact.contact.fields.with_loads`, on the factorisation of the
contact mesh). :func:`zone_fields` sets the lengths so that the stress is bounded at every edge
(the Maugis–Dugdale condition ``K̃_i = 0``); the tip condition ``g̃(c_i) = η`` is the outer
system's residual (:class:`~viscocontact.adhesion.MaugisDugdale`).

Why that split and not the other: at fixed edges the tip gap is stationary in the zone length
exactly where the stress is bounded (Dugdale's opening at the zone end,
``δ = (8/E')(K√(d/2π) - σ0 d/π)``, is largest at ``d = πK²/(8σ0²)``, where ``K`` is cancelled),
so ``g̃(c_i) = η`` has a double root there and cannot fix ``d_i``; ``K̃_i(d)`` instead falls
monotonically with a short zone (like ``-σ̃0√(8d_i/π)``), and at fixed bounded stress the tip gap
rises monotonically as the edge moves out (``δ = K²/(σ0E')``). A zone as long as the contact
turns ``K̃_i(d)`` back up at fixed penetration, where the tip gap rises with the zone instead:
:class:`TipCondition` mixes the tip condition into the zones' equations, which keeps one root
in both regimes and the same equilibria.

A neck whose two zones have no roots before they meet (the facing edges need more traction
than the whole neck carries) is filled by them (:func:`filled`): the neck is then held by the
cohesive traction alone, without tips, and its edges keep the stress intensity they have, the
outer residual there. The caller says whether a neck may be filled (its gap stays below the
range across it).

Failures raise :class:`ZoneError` with the reason: zones that meet across a neck that may not be
filled, or the iteration does not converge.
"""
from __future__ import annotations

import functools
import weakref
from typing import Callable

import attrs
import numpy as np
from scipy.linalg import lu_solve

from ..errors import ViscoContactError
from .fields import (BOUNDED_POWERS, FieldSolution, KnownLoads, intensity_matrix, mesh_influence,
                     with_loads)

#: Accuracy of the bounded-stress condition, relative to ``σ̃0·√ℓ`` with ℓ the longest zone or
#: the mean contact half-width, whichever is longer (a zone's own K̃) ...
EDGE_TOLERANCE = 1e-11
#: ... or, once it stops decreasing, this (the round-off of the fit) ...
NOISE = 1e-8
#: ... or the largest change of ``√d`` relative to the largest ``√d`` that ends the iteration.
EDGE_STEP = 1e-12
#: Newton iterations before giving up.
ITERATIONS = 60
#: Largest growth factor of a zone's ``√d`` in one Newton iteration.
GROWTH = 1.5
#: A Newton step that changes no zone's ``√d`` by more than this fraction of it is taken even
#: where a zone lies past the minimum of its equation (the state is close to a root).
LOCAL_STEP = 0.1
#: Zones are kept this fraction of the free interval short of meeting their neighbour ...
ROOM = 1.0 - 1e-9
#: ... and zones that fill it (a filled neck) cover it to round-off.
FILL = 1.0 - 1e-12


class ZoneError(ViscoContactError):
    """The cohesive zones of a contact set have no admissible lengths (the reason says why)."""


@attrs.frozen(kw_only=True, eq=False)
class TipCondition:
    """The tips' closing condition ``g̃(c_i) = η`` as :func:`zone_fields` mixes it into the
    zones' equations: ``K̃_i - W (g̃(c_i) - η) = 0`` with ``W = K̃_c/(2η)``, the slope of the edge
    residual ``K̃_c(√(g̃/η) - 1)`` at its root (so that both terms are in stress-intensity units
    and weigh alike).

    At an equilibrium both terms vanish, so the mixture has the same roots as the edge system
    with ``K̃ = 0``; what it changes is the zone lengths at fixed edges away from it, which now
    have one root where ``K̃`` alone has two or none. (A tip below the profile counts as a zero
    opening, as in the edge residual: ``max(g̃, 0)``.) At fixed edges and penetration ``K̃`` is
    not monotonic in a zone's length: it falls like ``-σ̃0√(8d/π)`` while the zone is short
    against the contact, and rises again once a long zone's own load presses the contact (at
    fixed penetration its tension is carried by more contact pressure). Where zones are as long
    as the contact (Maugis's λ ≲ 1) the penetration-controlled equilibrium lies on that rising
    side, or at the minimum where the two roots merge (λ = 1, Δ̃ ≈ 0.65 on the sinusoid of
    ``tests/integration/test_maugis_dugdale_bem.py``), and the outer solve had no zone lengths
    at the edges around it. The tip gap rises with the zone there
    (:func:`tip_gap_jacobian`), so the mixture falls monotonically; for short zones the tip gap
    is stationary where ``K̃`` vanishes (the module docstring), and the mixture is ``K̃``.

    Attributes
    ----------
    shape : NormalizedProfile
        The profile whose gap the tips close on.
    opening : float
        ``η = h̃0/Λ̃``.
    weight : float
        ``W``.
    """

    shape: object
    opening: float
    weight: float

    def mixed(self, fields: FieldSolution, kernel, k: np.ndarray, lengths: np.ndarray,
              which: np.ndarray) -> np.ndarray:
        """``k`` (the edges' ``K̃``) with ``W (max(g̃(c_i), 0) - η)`` taken off at the zones
        ``which`` (a tip below the profile, as at a contact too small for its penetration, is
        the edge residual's zero opening too)."""
        if not np.any(which):
            return k
        c = tips(fields.mesh.edges, lengths)
        g = tip_gaps(fields, kernel, self.shape, c)
        return np.where(which, k - self.weight * (np.maximum(g, 0.0) - self.opening), k)

    def weights(self, fields: FieldSolution, kernel, lengths: np.ndarray) -> np.ndarray:
        """``∂(W max(g̃, 0))/∂g̃`` at every edge's tip: ``W`` where the tip gap is positive."""
        g = tip_gaps(fields, kernel, self.shape, tips(fields.mesh.edges, lengths))
        return np.where(g > 0.0, self.weight, 0.0)


def zone_loads(edges: np.ndarray, lengths: np.ndarray, stress: float) -> KnownLoads:
    """The zones of ``edges`` (order ``X_1, X_2, ...``) with lengths ``d_i``, as known loads."""
    edges = np.asarray(edges, dtype=float)
    d = np.asarray(lengths, dtype=float)
    left = np.where(np.arange(len(edges)) % 2 == 0, edges - d, edges)
    return KnownLoads(left=left, right=left + d, stress=np.full(len(edges), float(stress)))


def tips(edges: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    """Zone tips ``c_i``: left edges minus ``d_i``, right edges plus ``d_i``."""
    return np.asarray(edges, float) + np.tile([-1.0, 1.0], len(edges) // 2) * lengths


def room(edges: np.ndarray) -> np.ndarray:
    """Free length next to each edge, shared with the facing edge of the neighbouring contact
    (periodic): ``room[i]`` for a right edge and the next left edge is the same gap."""
    e = np.asarray(edges, dtype=float)
    gaps = np.roll(e, -1)[1::2] - e[1::2]           # right edge j to left edge j + 1
    gaps[-1] += 2 * np.pi
    out = np.empty(len(e))
    out[1::2] = gaps
    out[0::2] = np.roll(gaps, 1)
    return out


def zone_widths(fields: FieldSolution) -> np.ndarray:
    """The zone lengths of a field with zones (:func:`zone_fields`)."""
    if fields.loads is None:
        raise ValueError("fields without zones (loads is None)")
    return np.asarray(fields.loads.width, dtype=float)


def filled(edges: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    """Which zones fill their free interval together with the facing zone (a neck held by the
    cohesive traction alone, :func:`zone_fields`): their lengths add up to the room, where
    zones that stop short of meeting keep at least ``1 - ROOM`` of it free."""
    d = np.asarray(lengths, dtype=float)
    if d.size == 0:
        return np.zeros(0, bool)
    return d + d[partner(d.size)] >= FILL * room(edges)


def partner(n: int) -> np.ndarray:
    """Index of the edge facing each edge across its free interval (periodic)."""
    idx = np.arange(n)
    return np.where(idx % 2 == 1, (idx + 1) % n, (idx - 1) % n)


def neck_ends(n: int) -> tuple[np.ndarray, np.ndarray]:
    """``(R, L)``: for each edge, the right edge ``R`` and the left edge ``L`` of the neck beside
    it (``X_R`` ends one contact, ``X_L`` begins the next, periodic), whose room is
    ``X_L - X_R`` (:func:`room`)."""
    idx = np.arange(n)
    right = np.where(idx % 2 == 1, idx, (idx - 1) % n)
    return right, (right + 1) % n


def tip_gaps(fields: FieldSolution, kernel, shape, c: np.ndarray) -> np.ndarray:
    """``g̃(c_i)`` of a field with its zones."""
    return fields.displacement(kernel, c) - (shape.heights(c) - 1.0 + fields.penetration)


#: :func:`bounded_weights` of the meshes alive (a mesh is immutable; compared by identity)
_WEIGHTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def bounded_weights(mesh) -> np.ndarray:
    """``intensity_matrix(mesh, BOUNDED_POWERS)`` (read-only), computed once per mesh: the zone
    iteration, the residual and the edge terms of one evaluation all fit on the same mesh."""
    w = _WEIGHTS.get(mesh)
    if w is None:
        w = intensity_matrix(mesh, BOUNDED_POWERS)
        w.flags.writeable = False
        _WEIGHTS[mesh] = w
    return w


def intensity(fields: FieldSolution) -> np.ndarray:
    """``K̃`` at every edge of a contact stress that tends to a constant there (the zone's
    ``σ̃0`` once the zone is resolved, 0 without a zone): the fit of
    :func:`~viscocontact.contact.fields.stress_intensity` with a constant added
    (:data:`~viscocontact.contact.fields.BOUNDED_POWERS`), so that it is continuous in the zone
    length down to zero. Uncalibrated: only its root and sign matter."""
    return bounded_weights(fields.mesh) @ fields.sigma


def _kernel_slopes(kernel, x):
    """``G̃(x) = F̃'(x) + c0`` (the slopes of the tabulated antiderivative), 0 where ``x`` is 0: a
    zone's own end at its tip, where the callers' terms carry a vanishing velocity or are
    replaced."""
    zero = x == 0.0
    out = kernel.antiderivative_slope(np.where(zero, 1.0, x)) + kernel.mean
    return np.where(zero, 0.0, out)


def _growth_stresses(fields: FieldSolution, kernel, stress: float, c: np.ndarray) -> np.ndarray:
    """``-B⁻¹σ̃0G̃(ξ - c)`` (N, len(c)): the contact stresses per unit growth of zones whose tips
    are ``c``, at fixed edges and penetration, on the factorisation at hand."""
    g = _kernel_slopes(kernel, fields.mesh.mid[:, None] - np.asarray(c)[None, :])
    return -lu_solve(fields.lu, stress * g, check_finite=False)


def intensity_jacobian(fields: FieldSolution, kernel, *, stress: float, control: dict,
                       columns: np.ndarray) -> np.ndarray:
    """``∂K̃_i/∂d_j`` of :func:`intensity` at fixed edges, for the zones ``j`` in ``columns``.

    At fixed edges the field is linear in the zones' loads. A zone ``[X - d, X]`` (or
    ``[X, X + d]``) grows at its tip ``c``: its displacement at the collocation points changes by
    ``σ̃0·G̃(ξ - c)`` (``G̃ = F̃' + c0``, the slope of the tabulated antiderivative, so that this is
    the derivative of the computed influence coefficient), and the stress by
    ``-B⁻¹σ̃0G̃(ξ - c)`` on the factorisation at hand, plus in load control the penetration's
    change that keeps the load (the zone's own force ``σ̃0`` included). One solve with a column
    per zone, where differencing took one field solve per zone.
    """
    mesh = fields.mesh
    loads = fields.loads
    if loads is None:
        raise ValueError("intensity_jacobian: fields without zones (loads is None)")
    d = zone_widths(fields)
    ds = _growth_stresses(fields, kernel, stress, tips(mesh.edges, d)[columns])
    if control.get("mean_pressure") is not None:
        h = mesh.width
        unit = fields.unit
        if unit is None:
            unit = lu_solve(fields.lu, np.ones_like(h), check_finite=False)
        ds += np.outer(unit, (-(h @ ds) - stress) / (h @ unit))
    return bounded_weights(mesh) @ ds


def tip_gap_jacobian(fields: FieldSolution, kernel, shape, *, stress: float, control: dict,
                     columns: np.ndarray) -> np.ndarray:
    """``∂g̃(c_i)/∂d_j`` of :func:`tip_gaps` at fixed edges, for the zones ``j`` in ``columns``.

    A zone that grows moves its tip only: the contact stresses change as in
    :func:`intensity_jacobian` (in load control with the penetration that keeps the load, which
    the gap sees too), every other tip sees the zone's load grow at the moving tip
    (``σ̃0 G̃(c_i - c_j)``), and the zone's own tip moves along the gap's slope there (the contact
    stresses' and the other zones', less the profile's) while its own load, whose end moves
    with it, changes by its far end's ``σ̃0 G̃`` (the terms of :func:`zone_derivatives`).
    """
    mesh = fields.mesh
    d = zone_widths(fields)
    n = len(d)
    cols = np.asarray(columns, dtype=np.intp)
    sign = np.tile([-1.0, 1.0], n // 2)
    c = tips(mesh.edges, d)
    ds = _growth_stresses(fields, kernel, stress, c[cols])
    shift = np.zeros(len(cols))
    if control.get("mean_pressure") is not None:
        h = mesh.width
        unit = fields.unit
        if unit is None:
            unit = lu_solve(fields.lu, np.ones_like(h), check_finite=False)
        shift = (-(h @ ds) - stress) / (h @ unit)
        ds += np.outer(unit, shift)
    out = mesh_influence(kernel, mesh, c) @ ds - shift[None, :]
    out += stress * _kernel_slopes(kernel, c[:, None] - c[cols][None, :])
    loads = fields.loads
    if loads is None:
        raise ValueError("tip_gap_jacobian needs a field solved with its zones (known loads)")
    at = c[cols][:, None]
    contact = (_kernel_slopes(kernel, at - mesh.left[None, :])
               - _kernel_slopes(kernel, at - mesh.right[None, :])) @ fields.sigma
    # the other zones' slopes at the moving tips; a zone's own end at its tip moves with it, and
    # its far end (the edge) counts as the load growing there
    across = _kernel_slopes(kernel, at - loads.left[None, :]) - _kernel_slopes(
        kernel, at - loads.right[None, :])
    rows = np.arange(len(cols))
    far = np.where(sign[cols] < 0, loads.right[cols], loads.left[cols])
    own_far = _kernel_slopes(kernel, c[cols] - far)
    slope = contact + stress * (across.sum(axis=1) - across[rows, cols]) - shape.slopes(c[cols])
    out[cols, rows] += sign[cols] * slope + stress * own_far
    return out


def zone_fields(base: FieldSolution, kernel, *, stress: float, control: dict,
                start: np.ndarray, full: np.ndarray | None = None,
                admissible: Callable[[FieldSolution, np.ndarray], bool] | None = None,
                tip: TipCondition | None = None) -> FieldSolution:
    """The field of ``base``'s contacts with the zones that bound the stress at every edge.

    For fixed contact edges, each zone length ``d_i`` is set so that the stress is bounded at its
    edge, ``K̃_i(d) = 0`` (the zone's tension cancels the singularity). ``K̃_i`` falls like
    ``-σ̃0√(8d_i/π)`` with its own zone, so the equations are solved by Newton's method in
    ``t_i = √d_i`` (Jacobian from :func:`intensity_jacobian`: one solve with a column per zone
    on the factorisation at hand).
    An edge whose stress is compressive without any zone (``K̃_i < 0`` at ``d_i = 0``) gets none.
    The closing condition of the tips, ``g̃(c_i) = η``, is left to the outer (edge) system:
    at fixed edges the tip gap is stationary in the zone length exactly where ``K̃_i = 0``
    (Dugdale: ``δ = (8/E')(K√(d/2π) - σ0 d/π)``), so it cannot fix ``d_i`` itself.

    Parameters
    ----------
    base : FieldSolution
        The contact field without zones (its factorisation is reused).
    kernel
        Prepared kernel.
    stress : float
        ``σ̃0`` (tensile, > 0).
    control : dict
        ``{"penetration": Δ̃}`` or ``{"mean_pressure": p̃∞}``.
    start : (n_edges,) array
        Zone lengths to start from (>= 0).
    full : (n_edges,) bool array, optional
        Zones that filled their neck at the start (:func:`filled` of the previous field).
    admissible : callable, optional
        ``admissible(fields, necks)``: whether the necks of the edges ``necks`` may be filled
        in ``fields`` (the law acts across them: the gap stays below the range). Without it
        every neck may.
    tip : TipCondition, optional
        Solve ``K̃_i - W (g̃(c_i) - η) = 0`` at every zone that does not fill its neck instead
        of ``K̃_i = 0`` (the same equilibria, one root at fixed edges where the zones are long;
        :class:`TipCondition`).

    Returns
    -------
    FieldSolution
        With ``loads`` the zones (:func:`zone_loads`) at the solution.

    Raises
    ------
    ZoneError
        When the iteration does not converge, or zones meet across a neck that may not be
        filled.

    Notes
    -----
    Zones whose roots lie beyond their meeting point (the facing edges need more traction than
    the whole neck between them carries: no root before the zones meet) fill the neck
    together, if it is ``admissible``: the neck is then held by the cohesive traction alone,
    and its two edges are left with the stress intensity they have (their residual,
    :class:`~viscocontact.adhesion.MaugisDugdale`). Otherwise these edges have no zones
    (:class:`ZoneError`). A zone found past the minimum of its equation with its edge still
    tensile, twice, has no root short of the facing zone either: its neck fills too, if
    admissible. Zones filled at the start (``full``) stay filled while admissible.
    """
    return _ZoneNewton(base, kernel, stress=stress, control=control, admissible=admissible,
                       tip=tip).solve(start, full)


class _ZoneNewton:
    """The Newton iteration of :func:`zone_fields` in ``t = √d`` on one contact set.

    It holds the equations of the zones (:meth:`evaluate`), the filling of necks (:meth:`fill`,
    :meth:`allowed`) and the iteration's state: the current ``t``, its field and equations'
    values ``k``, the filled necks ``full``, the zones capped at their room in the last step,
    the last residual size, the last positive ``√d`` of each zone, and the zones that have
    screened their edge or whose necks were tried filled. :meth:`solve` runs it; each other
    method is one kind of step.
    """

    def __init__(self, base: FieldSolution, kernel, *, stress: float, control: dict,
                 admissible: Callable[[FieldSolution, np.ndarray], bool] | None,
                 tip: TipCondition | None):
        self.base, self.kernel, self.stress, self.control = base, kernel, stress, control
        self.admissible, self.tip = admissible, tip
        self.edges = edges = base.mesh.edges
        self.n = len(edges)
        self.space = room(edges)
        self.free = ROOM * self.space
        self.facing = partner(self.n)
        self.weights = bounded_weights(base.mesh)
        self.half = 0.5 * float(np.mean(edges[1::2] - edges[0::2]))
        self.width = np.repeat(edges[1::2] - edges[0::2], 2)       # of each edge's contact

    # ---- the zones' equations and the necks ----------------------------------------------------
    def evaluate(self, t: np.ndarray) -> tuple[FieldSolution, np.ndarray]:
        """The field with zones ``d = t²`` and its equations' values (``K̃``, mixed with the tip
        condition at the zones that do not fill their neck)."""
        d = t * t
        f = with_loads(self.base, self.kernel, zone_loads(self.edges, d, self.stress),
                       **self.control)
        k = self.weights @ f.sigma
        if self.tip is not None:
            k = self.tip.mixed(f, self.kernel, k, d, (d > 0.0) & ~filled(self.edges, d))
        return f, k

    def fill(self, t: np.ndarray, which: np.ndarray) -> np.ndarray:
        """``√d`` with the zones of ``which`` tiling their necks, in the ratio they had."""
        d = t * t
        total = d + d[self.facing]
        share = np.where(total > 0.0, d / np.where(total > 0.0, total, 1.0), 0.5)
        return np.sqrt(np.where(which, share * self.space, d))

    def allowed(self, f: FieldSolution, necks: np.ndarray) -> bool:
        """Whether the necks of the edges ``necks`` may be filled in ``f``."""
        return self.admissible is None or bool(self.admissible(f, necks))

    def finished(self, f: FieldSolution) -> FieldSolution:
        """``f``, once its filled necks are checked (the other zones' lengths moved since the
        necks were filled: are they still admissible?)."""
        necks = filled(self.edges, zone_widths(f))
        if np.any(necks) and not self.allowed(f, necks):
            raise ZoneError(_MEET)
        return f

    # ---- the iteration -------------------------------------------------------------------------
    def solve(self, start: np.ndarray, full: np.ndarray | None) -> FieldSolution:
        """Iterate from the zone lengths ``start`` and the necks ``full`` filled there."""
        self._start(start, full)
        best = None                           # (size, t, fields, k, full) of the best state
        for _ in range(ITERATIONS):
            active = _active(self.t, self.k, self.full)
            if self._converged(active):
                return self.finished(self.fields)
            if best is None or self.last < best[0]:
                best = (self.last, self.t, self.fields, self.k, self.full)
            if self._reopen():
                continue
            self.screened |= (self.t > 0.0) & (self.k < 0.0)
            idx = np.flatnonzero(active)
            step, beyond, wrong = self._newton_step(idx)
            if np.any(wrong) and self._fill_unscreened(idx, wrong):
                continue
            if np.any(beyond):
                if not self._fill_rootless(idx, beyond):
                    self._shrink(idx, beyond)
                continue
            if self._advance(idx, step):
                return self.finished(self.fields)
        return _run_out(self, best)

    def _start(self, start: np.ndarray, full: np.ndarray | None) -> None:
        """The state at the start: ``√d`` of ``start`` within half the room, the necks of
        ``full`` (of both their edges) filled while they are admissible."""
        n = self.n
        t = np.sqrt(np.clip(np.asarray(start, dtype=float), 0.0, 0.5 * self.free))
        full = np.zeros(n, bool) if full is None else np.asarray(full, bool)
        full = full & full[self.facing]
        self.screened = np.zeros(n, bool)        # zones that have made their edge's K̃ negative
        self.tested = np.zeros(n, bool)          # necks tried filled (once each)
        self.passed = np.zeros(n, int)           # times found past their minimum, still tensile
        if np.any(full):
            t = self.fill(t, full)
            if not self.allowed(self.evaluate(t)[0], full):
                # the necks filled before no longer hold: they open, from short zones
                t = np.where(full, np.sqrt(0.05 * self.space), t)
                full = np.zeros(n, bool)
        self.full = full
        # the last positive √d of each zone (a zone whose Newton step went past zero is closed
        # at once; if its edge is then tensile, it reopens at a fraction of this)
        self.before = t.copy()
        self.t = t
        self.fields, self.k = self.evaluate(t)
        self.capped = np.zeros(n, bool)
        self.last = np.inf

    def _converged(self, active: np.ndarray) -> bool:
        """Whether the ``active`` zones' equations hold to :data:`EDGE_TOLERANCE` or, stopped
        decreasing, to :data:`NOISE` or 4 times their :func:`_floor`; else their size is kept."""
        scale = self.stress * np.sqrt(max(float(np.max(self.t * self.t)), self.half))
        size = float(np.max(np.abs(self.k[active]))) if np.any(active) else 0.0
        if size <= EDGE_TOLERANCE * scale + 1e-15:
            return True
        if size > 0.5 * self.last and (size <= NOISE * scale
                                       or size <= 4.0 * _floor(self, self.t, self.k, active)):
            return True       # at the round-off: no longer decreasing
        self.last = size
        return False

    def _reopen(self) -> bool:
        """Open a zone at every edge without one whose stress is tensile; whether any did."""
        t, k = self.t, self.k
        reopen = (t == 0.0) & (k > 0.0) & ~self.full
        if not np.any(reopen):
            return False
        # an edge without a zone whose stress is tensile: its zone opens, at a fraction of
        # the zone it had (the root lies between) or else at Dugdale's short zone
        # d = πK²/(8σ0²). Newton cannot start from zero: ∂K̃/∂√d = 2√d ∂K̃/∂d vanishes.
        # At most a tenth of the contact: Dugdale's zone holds for zones short against it,
        # and K̃(d) has a second, long-zone root past its minimum (weak adhesion on a
        # sinusoid, σ̃0 = 3e-4: the short-zone seed, capped by the room only, landed on
        # zones of 1.97 where the answer was 0.43)
        before = self.before
        seed = np.where(before > 0.0, 0.3 * before, np.sqrt(np.pi / 8.0) * k / self.stress)
        t = np.where(reopen, np.minimum(seed, np.sqrt(np.minimum(0.5 * self.free,
                                                                 0.1 * self.width))), t)
        self.before = np.where(reopen, t, before)
        self.t = t
        self.fields, self.k = self.evaluate(t)
        return True

    def _jacobian(self, idx: np.ndarray) -> np.ndarray:
        """The equations' Jacobian in ``√d`` among the zones ``idx``."""
        fields, kernel, tip, t = self.fields, self.kernel, self.tip, self.t
        J = intensity_jacobian(fields, kernel, stress=self.stress, control=self.control,
                               columns=idx)[idx]
        if tip is not None:
            w = tip.weights(fields, kernel, t * t)[idx]
            J -= w[:, None] * tip_gap_jacobian(fields, kernel, tip.shape, stress=self.stress,
                                               control=self.control, columns=idx)[idx]
        J *= 2.0 * t[idx]
        return J

    def _newton_step(self, idx: np.ndarray):
        """``(step, beyond, wrong)`` among the zones ``idx``: the Newton step in ``√d`` (None
        when some zone is ``beyond`` the minimum of its equation, its diagonal >= 0, unless the
        step changes no zone by more than :data:`LOCAL_STEP` of it), and the zones told to go
        the wrong way (to shrink where they need to grow, or beyond)."""
        J = self._jacobian(idx)
        k, t = self.k, self.t
        beyond = np.diag(J) >= 0.0
        try:
            step = np.linalg.solve(J, -k[idx])
        except np.linalg.LinAlgError:
            step = None
        if np.any(beyond):
            # close to a root Newton's step is taken whatever the sign of the diagonal: a
            # zone at its root past the minimum of K̃ (a long zone under load control, where
            # K̃ does not fall as the zone grows at a fixed load) is not moved away from it
            if (step is not None and np.all(t[idx] > 0.0)
                    and np.all(np.abs(step) <= LOCAL_STEP * t[idx])):
                return step, np.zeros(len(idx), bool), np.zeros(len(idx), bool)
            return None, beyond, beyond
        if step is None:
            raise ZoneError("the bounded-stress equations of the zones are singular")
        if not np.all(np.isfinite(step)):
            raise ZoneError("the bounded-stress equations of the zones gave a non-finite step")
        # a zone that needs to grow (K̃ > 0) told to shrink: past the minimum of K̃, or held
        # back by its neighbours; only a filled neck is tried then
        wrong = (k[idx] > 0.0) & (step < 0.0) & (t[idx] > 0.0)
        return step, beyond, wrong

    def _fill_unscreened(self, idx: np.ndarray, wrong: np.ndarray) -> bool:
        """Fill the necks of zones told the wrong way that never screened their edge, if the
        equations stay >= 0 where the zones meet and the necks are admissible; whether they
        were filled.

        Past the minimum of K̃ in the zone length (zones long against the contact undo their
        own screening), a zone that never screened its edge (K̃ > 0 all along) may have no
        root: if K̃ stays positive at an edge with its neck filled, the neck fills; otherwise
        the step goes back towards the smallest root."""
        grow = np.zeros(self.n, bool)
        grow[idx[wrong]] = True
        unscreened = grow & (self.k > 0.0) & ~self.screened & ~self.tested
        if not np.any(unscreened):
            return False
        neck = unscreened | unscreened[self.facing]
        self.tested |= neck
        trial = self.fill(self.t, self.full | neck)
        f_try, k_try = self.evaluate(trial)
        # (mixed with the tip condition, the zones' equations at their meeting point:
        # continuous with theirs just before it, where the filled neck has no tips)
        k_met = (k_try if self.tip is None
                 else self.tip.mixed(f_try, self.kernel, k_try, trial * trial, neck))
        if np.any(neck & (k_met >= 0.0)) and self.allowed(f_try, neck):
            self._filled(neck, trial, f_try, k_try)
            return True
        return False

    def _fill_rootless(self, idx: np.ndarray, beyond: np.ndarray) -> bool:
        """Fill the necks of zones found past the minimum of their equation with their edge
        still tensile (``K̃ > 0``) for the second time; whether any was filled (a
        :class:`ZoneError` where such a neck is not admissible: no field).

        Shortened from there (:meth:`_shrink`), such a zone grows back past its minimum: the
        iteration cycles. ``K̃`` does not reach zero before the minimum, so the zone has no
        root short of the facing zone: it runs across the neck, which the cohesive traction
        then holds (a seed-234 scene of the campaign: a zone of 0.03 in a neck of 0.08 with
        ``K̃ = 0.008`` at its minimum, cycling for 60 iterations)."""
        past = np.zeros(self.n, bool)
        past[idx[beyond]] = True
        past &= (self.k > 0.0) & ~self.full
        self.passed += past
        rootless = past & (self.passed >= 2)
        if not np.any(rootless):
            return False
        neck = rootless | rootless[self.facing]
        trial = self.fill(self.t, self.full | neck)
        f_try, k_try = self.evaluate(trial)
        if not self.allowed(f_try, neck):
            # nor can the traction hold the neck: these edges have no field (shortened and
            # regrown, the zone cycled to the iterations' end: campaign seed 29, one contact
            # past a fold under load control, its neck across the period)
            raise ZoneError(_MEET)
        self._filled(neck, trial, f_try, k_try)
        return True

    def _filled(self, necks: np.ndarray, t: np.ndarray, fields: FieldSolution,
                k: np.ndarray) -> None:
        """Take the state with the necks ``necks`` filled: ``t``, its field and equations."""
        self.full = self.full | necks
        self.t, self.fields, self.k = t, fields, k
        self.capped = np.zeros(self.n, bool)
        self.last = np.inf

    def _shrink(self, idx: np.ndarray, beyond: np.ndarray) -> None:
        """Shorten the zones ``beyond`` the minimum of their equation to 0.3 of their √d."""
        t = self.t.copy()
        t[idx[beyond]] *= 0.3
        self.t = t
        self.fields, self.k = self.evaluate(t)

    def _advance(self, idx: np.ndarray, step: np.ndarray) -> bool:
        """Take the Newton ``step`` of the zones ``idx``, limited (:meth:`_limited`) and kept
        within the room; zones capped at the room twice running fill their neck instead.
        Whether the step was below :data:`EDGE_STEP` (converged)."""
        facing, full = self.facing, self.full
        new = self._limited(idx, step)
        d = new * new
        over = (d + d[facing] > self.free) & ~full
        if np.any(over & self.capped):
            # capped twice running: no root before the zones meet, so they fill the neck
            meet = over & self.capped
            trial = self.fill(new, full | meet | meet[facing])
            f_try, k_try = self.evaluate(trial)
            if not self.allowed(f_try, meet | meet[facing]):
                raise ZoneError(_MEET)
            self._filled(meet | meet[facing], trial, f_try, k_try)
            return False
        if np.any(over):
            total = np.where(over, d + d[facing], 1.0)     # (two closed zones: 0/0 otherwise)
            d = np.where(over, d / total * self.free, d)
            new = np.sqrt(d)
        self.capped = over
        t = self.t
        done = float(np.max(np.abs(new - t))) <= EDGE_STEP * max(float(np.max(new)), 1e-300)
        self.t = new
        self.fields, self.k = self.evaluate(new)
        return done

    def _limited(self, idx: np.ndarray, step: np.ndarray) -> np.ndarray:
        """``√d`` after the Newton ``step`` of the zones ``idx``: a zone stepped past zero
        closes (its last positive ``√d`` is kept), and no zone grows more than
        :data:`GROWTH` times in ``√d``."""
        t = self.t
        new = t.copy()
        new[idx] = t[idx] + step
        # a step past zero closes the zone: an edge whose stress is compressive without a zone
        # stays at zero through the active set, a tensile one reopens it (above). Shrinking it
        # by a factor per iteration instead left zones far below the edge element, where
        # K̃ no longer changes with them: the guard against long zones then took every iteration
        # (rough profile, an edge turning compressive at an approach step: 60 iterations spent)
        self.before = np.where(t > 0.0, t, self.before)
        new = np.where(new < 0.0, 0.0, new)
        # at most GROWTH times longer in √d per iteration: K̃ flattens towards its minimum in
        # the zone length, so a Newton step from short zones overshoots the root (sinusoid,
        # load control, Γ̃ = 1e-3, η = 0.2: √d from 0.50 to 1.38 against a root at 0.65, where
        # the zones filled the gap and were reported as meeting)
        return np.where(t > 0.0, np.minimum(new, GROWTH * t), new)


@attrs.frozen(kw_only=True, eq=False)
class ZoneDerivatives:
    """Derivatives of a field with zones along the zones' own equations (``K̃_i = 0`` at every
    zone kept, its length following the edges; a filled neck's zones keep their shares of
    it), in the directions of a
    :class:`~viscocontact.contact.sensitivity.FieldSensitivity`: every edge at fixed
    penetration, then the penetration at fixed edges (``D`` columns).

    Attributes
    ----------
    lengths : (n_edges, D)
        ``∂d_i``; 0 at an edge without a zone (it stays closed).
    intensity : (n_edges, D)
        ``∂K̃_i`` of :func:`intensity` (0 to round-off at a zone whose length keeps ``K̃ = 0``;
        a filled neck's edges keep theirs).
    gaps : (n_edges, D)
        ``∂g̃(c_i)``, the tip gaps of :func:`tip_gaps`; 0 at an edge without a zone.
    pressure : (D,)
        ``∂p̃∞`` with the zones' own force.
    """

    lengths: np.ndarray
    intensity: np.ndarray
    gaps: np.ndarray
    pressure: np.ndarray


def _active(t: np.ndarray, k: np.ndarray, full: np.ndarray) -> np.ndarray:
    """The zones whose equations the iteration solves at ``√d = t`` with values ``k``: all but
    the closed zones whose edge is compressive and the zones of filled necks (``full``)."""
    return ~((t == 0.0) & (k <= 0.0)) & ~full


def _floor(zn: "_ZoneNewton", t: np.ndarray, k: np.ndarray, active: np.ndarray) -> float:
    """The round-off floor of the equations ``k`` of ``zn`` at ``√d = t`` (``active``: those
    solved, :func:`_active`): the largest change of one when every zone's ``√d`` moves by a
    relative 1e-13, far below any physical change (one evaluation; inf where not finite).
    Newton's iteration reaches it in four or five steps and then wanders on it (on a thin
    elastic layer at 3-15e-10, above :data:`NOISE` of its scale)."""
    _, moved = zn.evaluate(t * (1.0 + 1e-13))
    with np.errstate(invalid="ignore"):
        floor = float(np.max(np.abs(moved - k)[active])) if np.any(active) else 0.0
    return floor if np.isfinite(floor) else np.inf


def _run_out(zn: "_ZoneNewton", best: tuple | None) -> FieldSolution:
    """The field of an iteration ``zn`` that ran out of iterations: its best state ``(size, t,
    fields, k, full)`` where that holds its equations to four times their round-off floor
    (:func:`_floor`); else a :class:`ZoneError`. On a contact
    1.5e-4 wide born between zones of 0.002-0.009 (campaign seed 273) ``K̃`` wandered at
    1-6e-9 for 60 iterations, five times :data:`NOISE` of its scale."""
    if best is not None:
        size, t, fields, k, full = best
        if size <= 4.0 * _floor(zn, t, k, _active(t, k, full)):
            zn.t, zn.fields, zn.k, zn.full = t, fields, k, full
            return zn.finished(fields)
    raise ZoneError(f"the bounded-stress equations of the zones did not converge in "
                    f"{ITERATIONS} Newton iterations (largest K̃ {np.max(np.abs(zn.k)):.3g})")


def zone_derivatives(fields: FieldSolution, dfields, *, stress: float,
                     tip_weights: np.ndarray | None = None) -> ZoneDerivatives:
    r"""The derivatives of a field with zones (:func:`zone_fields`) in every edge and the
    penetration, from solves with a column per direction and per zone on its factorisation.

    At fixed zone lengths each zone moves with its edge. The zone loads' displacement at the
    collocation points then changes like an influence coefficient whose ends and point move
    (``σ̃0[G̃(ξ - a)(ξ̇ - ȧ) - G̃(ξ - b)(ξ̇ - ḃ)]``, ``G̃`` the kernel's slopes), which adds to
    ``ẇ - Ḃσ̃`` of ``dfields``; a zone that grows moves its tip only (:func:`intensity_jacobian`).
    The tip gap ``g̃(c) = ũ(c) - r̃(c) + 1 - Δ̃`` changes with the stresses (the influence at the
    tips), with the tip and the elements moving under the stresses, with the zones' loads seen
    from the moving tip (a zone's own end at its tip does not count: it moves with it), with
    the profile's slope and the penetration. The lengths follow from ``K̃ = 0`` at every zone:
    ``ḋ = -(∂K̃/∂d)⁻¹ ∂K̃/∂(x, Δ̃)``, or with ``tip_weights`` (per edge,
    :meth:`TipCondition.weights`) from ``K̃ - W (max(g̃, 0) - η) = 0`` (:class:`TipCondition`).

    Raises
    ------
    numpy.linalg.LinAlgError
        When ``∂K̃/∂d`` is singular (the lengths do not follow the edges).
    """
    d = zone_widths(fields)
    z = _MovingZones.of(fields, dfields.n_dirs)      # (raises for fields without zones)
    sx, sd = _zone_stress_derivatives(fields, dfields, stress, z)
    # stress-intensity factors
    W, explicit = dfields.fit_motion(BOUNDED_POWERS)
    kx, kd = W @ sx + explicit, W @ sd
    gx, gd = _tip_gap_derivatives(fields, dfields, stress, z, sx, sd)
    # the load (the zones' force σ̃0·Σd counts)
    h = fields.mesh.width
    px = -(dfields.width_vel.T @ fields.sigma + h @ sx) / (2 * np.pi)
    pd = -(h @ sd + stress) / (2 * np.pi)
    full, dd = _length_derivatives(fields.mesh.edges, d, z.act, dfields.n_dirs, kx, kd, gx, gd,
                                   tip_weights)
    n = len(fields.mesh.edges)
    lengths = np.zeros((n, dfields.n_dirs))
    lengths[z.act] = dd
    # a filled neck has no tips: its zones' rows (where the meeting tips sit on each other's
    # ends, the kernel's logarithmic slope) are not used
    gx = np.where(full[:, None], 0.0, gx)
    gd = np.where(full[:, None], 0.0, gd)
    gaps = np.zeros((n, dfields.n_dirs))
    gaps[z.act] = gx + gd @ dd
    if not np.all(np.isfinite(gaps)):
        raise np.linalg.LinAlgError("a zone tip sits on another zone's end")
    return ZoneDerivatives(lengths=lengths, intensity=kx + kd @ dd, gaps=gaps,
                           pressure=px + pd @ dd)


@attrs.frozen(kw_only=True, eq=False)
class _MovingZones:
    """The zones of a field that have a length, as :func:`zone_derivatives` moves them (``m``
    zones, ``D`` directions).

    Attributes
    ----------
    act : (m,) int array
        Their edges.
    sign : (m,)
        A tip's motion per unit length of its zone: -1 at a left edge, +1 at a right one.
    a, b : (m,)
        Their ends, left and right.
    c : (m,)
        Their tips.
    E : (m, D)
        The motion of their ends and tips in every direction: with their own edges.
    """

    act: np.ndarray
    sign: np.ndarray
    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    E: np.ndarray

    @classmethod
    def of(cls, fields: FieldSolution, n_dirs: int) -> "_MovingZones":
        """The zones of ``fields`` (with zones) for ``n_dirs`` directions."""
        mesh, loads = fields.mesh, fields.loads
        if loads is None:
            raise ValueError("zone_derivatives: fields without zones (loads is None)")
        n = len(mesh.edges)
        d = zone_widths(fields)
        act = np.flatnonzero(d > 0)
        m = act.size
        E = np.zeros((m, n_dirs))                     # zone ends and tips move with their edges
        E[np.arange(m), act] = 1.0
        return cls(act=act, sign=np.tile([-1.0, 1.0], n // 2)[act], a=loads.left[act],
                   b=loads.right[act], c=tips(mesh.edges, d)[act], E=E)


def _zone_stress_derivatives(fields: FieldSolution, dfields, stress: float,
                             z: _MovingZones) -> tuple[np.ndarray, np.ndarray]:
    """``(σ̇_x, σ̇_d)``: the contact stresses' derivatives at fixed zone lengths in every
    direction (the zones move with their edges: their loads' displacement at the collocation
    points changes like an influence coefficient whose ends and point move), (N, D), and per
    unit length of each zone (:func:`intensity_jacobian`), (N, m)."""
    slopes = functools.partial(_kernel_slopes, dfields.kernel)
    xi = fields.mesh.mid
    moved = slopes(xi[:, None] - z.a[None, :]) - slopes(xi[:, None] - z.b[None, :])
    u_dot = stress * (moved.sum(axis=1)[:, None] * dfields.colloc_vel - moved @ z.E)
    sx = lu_solve(fields.lu, dfields.rhs - u_dot, check_finite=False)
    sd = _growth_stresses(fields, dfields.kernel, stress, z.c)
    return sx, sd


def _tip_gap_derivatives(fields: FieldSolution, dfields, stress: float, z: _MovingZones,
                         sx: np.ndarray, sd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(ġ_x, ġ_d)``: the tip gaps' derivatives in every direction at fixed zone lengths,
    (m, D), and per unit length of each zone, (m, m), from the stresses' (``sx``, ``sd``,
    :func:`_zone_stress_derivatives`): the stresses, then the elements under the moving tip,
    the zones, the profile and the penetration. (A filled neck's two zones meet tip to end,
    where the kernel's slope is logarithmic; their rows are not finite, and not used.)"""
    mesh, kernel = fields.mesh, dfields.kernel
    slopes = functools.partial(_kernel_slopes, kernel)
    sign, a, b, c, E = z.sign, z.a, z.b, z.c, z.E
    with np.errstate(invalid="ignore", divide="ignore"):
        infl = mesh_influence(kernel, mesh, c)
        s = dfields.node_weights(fields.sigma)
        g_nodes = slopes(c[:, None] - dfields.nodes[None, :])
        at_tip = g_nodes @ s
        gx = (infl @ sx + E * at_tip[:, None] - g_nodes @ (s[:, None] * dfields.node_vel))
        gd = infl @ sd + np.diag(sign * at_tip)
        # the zones seen from the moving tips (each zone's end at its own tip moves with it)
        diag = np.arange(len(c))
        zone_a = slopes(c[:, None] - a[None, :])
        zone_b = slopes(c[:, None] - b[None, :])
        zone_a[diag, diag] = np.where(sign < 0, 0.0, zone_a[diag, diag])
        zone_b[diag, diag] = np.where(sign > 0, 0.0, zone_b[diag, diag])
        across = zone_a - zone_b
        gx += stress * (across.sum(axis=1)[:, None] * E - across @ E)
        # a zone that grows: another's tip sees its tip move (σ̃0 G̃(c_i - c_k)); its own tip
        # moves past all the zones, and its own load grows at the tip (σ̃0 G̃ at the zone's
        # other end)
        grow = stress * slopes(c[:, None] - c[None, :])
        grow[diag, diag] = stress * (sign * (across.sum(axis=1) - across[diag, diag])
                                     + np.where(sign < 0, zone_b[diag, diag],
                                                zone_a[diag, diag]))
        gd += grow
    r_slope = dfields.shape.slopes(c)
    gx -= r_slope[:, None] * E
    gx[:, -1] -= 1.0
    gd -= np.diag(r_slope * sign)
    return gx, gd


def _length_derivatives(edges: np.ndarray, d: np.ndarray, act: np.ndarray, n_dirs: int,
                        kx: np.ndarray, kd: np.ndarray, gx: np.ndarray, gd: np.ndarray,
                        tip_weights: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """``(full, ḋ)`` of the zones ``act``: which fill their neck, and their lengths'
    derivatives (m, D). A zone of a filled neck keeps its share ``f`` of the neck (``d =
    f·room``, the room ``X_L - X_R`` between the neck's right edge R and left edge L); every
    other zone keeps ``K̃ - W (g̃ - η) = 0`` (``W`` its ``tip_weights``, 0 without: ``K̃ = 0``;
    :class:`TipCondition`), from the intensities' ``kx``, ``kd`` and the tip gaps' ``gx``,
    ``gd`` derivatives at fixed lengths and per unit length."""
    n = len(edges)
    full = filled(edges, d)[act]
    dd = np.zeros((act.size, n_dirs))
    if np.any(full):
        space = room(edges)[act]
        right, left = neck_ends(n)
        right, left = right[act], left[act]
        dd[full] = (d[act][full] / space[full])[:, None] * (
            np.eye(n_dirs)[left[full]] - np.eye(n_dirs)[right[full]])
    free = ~full
    if np.any(free):
        rows = act[free]
        # K̃ - W (g̃ - η) = 0 at every such zone (W = 0: K̃ = 0; TipCondition)
        w = np.zeros(len(rows)) if tip_weights is None else np.asarray(tip_weights)[rows]
        phi_d = kd[rows] - w[:, None] * gd[free]
        phi_x = kx[rows] - w[:, None] * gx[free]
        dd[free] = -np.linalg.solve(phi_d[:, free], phi_x + phi_d[:, full] @ dd[full])
    return full, dd


_MEET = ("no zone lengths bound the stress at these edges: the zones of neighbouring contacts "
         "(or of one contact across the period) meet, and the gap between them exceeds the "
         "range h0, so the cohesive traction cannot fill the neck")
