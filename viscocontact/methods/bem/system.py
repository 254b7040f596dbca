"""The nonlinear system in the edge positions of a fixed contact set (thesis §4.4).

One residual evaluation is the chain of the algorithm: mesh the contacts (eqs. 4.21-4.29) →
influence matrix of the prepared kernel and the stresses for these edges (eqs. 4.31-4.32,
penetration or load control) → one residual per edge from the adhesion model (eqs. 4.9-4.20).
The system knows nothing of the solve it is part of: it sees the prepared tables, the mesh
specification, the adhesion model, the control and the element counts, and it raises
:class:`~viscocontact.contact.topology.TopologyChange` when the solver moves the edges out of
this contact set.
"""
from __future__ import annotations

import contextlib

import attrs
import numpy as np

from ...adhesion.base import AdhesionLimitation
from ...contact.edges import EdgeContext, border_geometry
from ...contact.fields import beside_factorisation
from ...contact.mesh import build_mesh, same_zones, zone_patterns
from ...contact.sensitivity import FieldSensitivity
from ...contact.topology import TopologyChange, repair
from ...deadline import check as check_deadline
from .sets import MIN_GAP, MIN_WIDTH

#: A Jacobian request after the residual fell by less than this factor since the previous one
#: gets the full difference Jacobian instead of the grouped block-diagonal one ...
SLOW_CONTRACTION = 0.25
#: ... when there are at most this many edges (its cost is one evaluation per edge; at 14 edges
#: it doubled Newton's evaluations on the rough adhesionless case, 621 -> 1732).
FULL_JACOBIAN_EDGES = 8


def residual_scale(kernel) -> float:
    """``max(1, E_eff/E0)``: the factor on the edge residual tolerance for a prepared kernel.

    ``E_eff = 1/|K(1)|`` is the modulus the solid shows at the fundamental wavelength (``E0`` in
    the relaxed limit, ``E∞`` in the glassy one). Edge residuals scale with the stresses, and so
    does their round-off: at ``ζ → ∞`` with ``β = 1e4`` an absolute tolerance of 1e-9 lies below
    what double precision can resolve.
    """
    k1 = abs(complex(kernel.compliance(1.0)))
    return max(1.0, 1.0 / k1) if k1 > 0 and np.isfinite(k1) else 1.0


class Evaluations:
    """The last few evaluations of the edge systems of one equilibrium solver, shared between
    them: a new system asked for a point that another one of the same control, element counts
    and edge zones has just evaluated takes that evaluation instead of computing it again (the
    same arithmetic, so the same numbers). The approach evaluates such points when a new
    system starts where another stopped: after contacts are born and grown (the grown edges,
    then the round-off floor's measurement there), and when a fold is crossed.

    An evaluation holds its factorisation, so only :data:`EVALUATIONS_KEPT` are kept; points the
    adhesion model rejects are not shared (their reason belongs to the system that met them).
    """

    def __init__(self, size: int | None = None):
        self.size = EVALUATIONS_KEPT if size is None else size
        self._entries: list = []     # (x bytes, control, counts, zones, (fields, ctx, r))

    def find(self, key: bytes, control, counts, zones):
        """The evaluation stored for this point, or None."""
        for n, entry in enumerate(self._entries):
            k, c, n_, z, out = entry
            if k == key and c == control and n_ == counts and same_zones(z, zones):
                self._entries.append(self._entries.pop(n))      # the latest used last
                return out
        return None

    def keep(self, key: bytes, control, counts, zones, out) -> None:
        """Store an evaluation, forgetting the oldest beyond :attr:`size`."""
        self._entries.append((key, control, counts, zones, out))
        del self._entries[:-self.size]


#: Evaluations kept by :class:`Evaluations`: the points taken again come right after the one
#: evaluated last or the one before it. Each holds its mesh's factorisation and borders (160 MB
#: at 2044 elements and 24 edges, 20 MB at 700 elements).
EVALUATIONS_KEPT = 2


@attrs.frozen(kw_only=True, eq=False)
class EdgeDerivatives:
    """Derivatives of the edge residuals of one contact set at one point.

    Attributes
    ----------
    jacobian : (n, n) array
        ``∂r/∂x`` at the system's control (penetration or load held fixed).
    control : (n,) array
        ``∂r/∂Δ̃`` or ``∂r/∂p̃∞`` at fixed edges: the control's own kind.
    pressure : (n + 1,) array
        ``∂p̃∞/∂x`` at fixed penetration and ``∂p̃∞/∂Δ̃`` at fixed edges (last).
    """

    jacobian: np.ndarray
    control: np.ndarray
    pressure: np.ndarray


class EdgeSystem:
    """Residuals of the edges ``x`` of one contact set at one control value.

    Parameters
    ----------
    prep : Prepared
        Kernel tables and normalised profile.
    spec : MeshSpec
    adhesion : AdhesionModel
    control : Control
    edges : array
        The contact set (its size fixes the number of unknowns).
    counts : tuple or None
        Elements of each contact (``None``: ``spec.elements`` each); fixed, with the edge zones,
        for the whole solve so that the residual is smooth in the edges.
    on_limitation : callable, optional
        Called with the reason whenever the adhesion model rejects a point
        (:class:`~viscocontact.adhesion.base.AdhesionLimitation`).
    shared : Evaluations, optional
        Evaluations shared with the other systems of a solver (a point one of them has just
        evaluated is taken from there).
    """

    def __init__(self, prep, spec, adhesion, control, edges, counts, on_limitation=None,
                 shared: Evaluations | None = None):
        self.prep = prep
        self.spec = spec
        self.adhesion = adhesion
        self.control = control
        self.n_edges = len(edges)
        self.counts = counts
        self.zones = zone_patterns(edges, spec, counts)
        # the last point this system evaluated, valid or rejected by the model: ``(key, out)``.
        # The solvers ask for it again at once (the residual, then its derivatives); the
        # :attr:`shared` evaluations hold the valid points of this solve's other systems
        self._latest: tuple[bytes, tuple] | None = None
        self.evaluations = 0
        self.last_valid = None      # last edge vector that was a valid contact set
        self._last_size = None      # max |r| where the previous Jacobian was taken
        self._derivatives: tuple | None = None   # (x key, derivatives) of the last Jacobian
        self._previous = None       # field of the last valid evaluation (a start for the model)
        #: why the adhesion model rejected the last point it could not handle (None: none yet)
        self.limitation: str | None = None
        self._on_limitation = on_limitation
        self.shared = shared

    def evaluate(self, x):
        """``(fields, ctx, r)`` at ``x`` (the last evaluation is cached, and those of the
        :attr:`shared` ones). Every evaluation checks the cooperative deadline
        (:mod:`viscocontact.deadline`)."""
        check_deadline()
        key = x.tobytes()
        if self._latest is not None and self._latest[0] == key:
            return self._latest[1]
        if not np.all(np.isfinite(x)):
            return None, None, np.full(len(x), np.inf)
        new, changed, reason, full = repair(x, MIN_WIDTH, MIN_GAP)
        if changed:
            raise TopologyChange(reason, new, full)
        if self.shared is not None:
            out = self.shared.find(key, self.control, self.counts, self.zones)
            if out is not None:
                return self._remember(key, x, out)
        prep = self.prep
        mesh = build_mesh(x, self.spec, self.zones, self.counts)
        # the borders' new rows and columns need the mesh alone: on two cores they are
        # computed while the influence matrix is factorised (the same numbers either way)
        advances = self.adhesion.bordered_advances(mesh)
        prepared: dict = {}

        def task():
            prepared["geometry"] = border_geometry(mesh, prep.kernel, prep.shape, self.spec,
                                                   advances)
        beside = beside_factorisation(task) if advances else contextlib.nullcontext()
        # a finite edge advance: the energy balance needs the kernel's non-reciprocal part too
        try:
            with beside:
                fields = self.adhesion.field_solution(
                    mesh, prep.kernel, prep.shape, self.control.fields_kwargs(),
                    antisymmetric=self.adhesion.edge_advance() > 0, previous=self._previous)
        except AdhesionLimitation as exc:
            # a point the model cannot handle: invalid for the solver, which steps back
            self.limitation = str(exc)
            if self._on_limitation is not None:
                self._on_limitation(self.limitation)
            r = np.full(len(x), np.inf)
            self._latest = (key, (None, None, r))
            return None, None, r
        self._previous = fields
        ctx = EdgeContext(fields, prep.kernel, prep.shape, self.spec, prep.shape.amplitude,
                          self.zones, self.counts, geometry=prepared.get("geometry"))
        r = self.adhesion.residuals(ctx)
        self.evaluations += 1
        if self.shared is not None:
            self.shared.keep(key, self.control, self.counts, self.zones, (fields, ctx, r))
        return self._remember(key, x, (fields, ctx, r))

    @contextlib.contextmanager
    def probing(self):
        """Evaluations that leave the system as they found it: the cached evaluation, the
        model's start for the next one and :attr:`last_valid` are restored on exit (a probe of
        the residual off the path, :func:`~.relax._jump`'s bisection)."""
        saved = (self._latest, self._previous, self.last_valid)
        try:
            yield self
        finally:
            self._latest, self._previous, self.last_valid = saved

    def _remember(self, key: bytes, x, out: tuple) -> tuple:
        """``out``, the valid evaluation at ``x``, as the last one: cached, and its field the
        model's start for the next."""
        self._previous = out[0]
        self._latest = (key, out)
        self.last_valid = x.copy()
        return out

    def residual(self, x):
        return self.evaluate(np.asarray(x, dtype=float))[2]

    def derivatives(self, x) -> EdgeDerivatives | None:
        """The derivatives of the residuals at ``x`` from the adhesion model's analytic
        derivatives through one adjoint pass on the factorisation at hand
        (:mod:`~viscocontact.contact.sensitivity`); None when the model does not give them
        (:meth:`AdhesionModel.residual_derivatives`) or the residual is not finite. Cached for
        the last ``x``.

        Under load control the penetration follows the edges: ``dΔ̃/dx = -(∂p̃∞/∂x)/(∂p̃∞/∂Δ̃)``,
        so ``J = ∂r/∂x + (∂r/∂Δ̃) dΔ̃/dx`` and ``∂r/∂p̃∞ = (∂r/∂Δ̃)/(∂p̃∞/∂Δ̃)``.
        """
        x = np.asarray(x, dtype=float)
        key = x.tobytes()
        if self._derivatives is not None and self._derivatives[0] == key:
            return self._derivatives[1]
        fields, ctx, r = self.evaluate(x)
        out = None
        if fields is not None and np.all(np.isfinite(r)):
            sens = FieldSensitivity(fields, self.prep.kernel, self.prep.shape, self.spec,
                                    self.zones, self.counts)
            d = self.adhesion.residual_derivatives(ctx, sens)
            if d is not None and np.all(np.isfinite(d)):
                J, c = d[:, :-1], d[:, -1]
                dp = self.adhesion.pressure_derivatives(ctx, sens)
                if dp is None:
                    dp = sens.pressure()
                if self.control.is_load:
                    J = J - np.outer(c, dp[:-1] / dp[-1])
                    c = c / dp[-1]
                out = EdgeDerivatives(jacobian=J, control=c, pressure=dp)
        self._derivatives = (key, out)
        return out

    def jacobian(self, x):
        """``∂r/∂x``: analytic when the adhesion model gives derivatives (:meth:`derivatives`),
        else by forward differences (:meth:`difference_jacobian`)."""
        d = self.derivatives(x)
        if d is not None:
            return d.jacobian
        return self.difference_jacobian(x)

    def difference_jacobian(self, x):
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
                J[:, i] = self._column(x, r0, i, h[i // 2])
            return J
        J = np.zeros((n, n))
        for parity in (0, 1):
            xp = x.copy()
            xp[parity::2] += h
            dr = self.residual(xp) - r0
            if not np.all(np.isfinite(dr)):      # forward into invalid points: step back
                xp[parity::2] -= 2 * h
                dr = r0 - self.residual(xp)
            for j in range(n // 2):
                J[2 * j:2 * j + 2, 2 * j + parity] = dr[2 * j:2 * j + 2] / h[j]
        return J

    def _column(self, x, r0, i: int, h: float) -> np.ndarray:
        """Column ``i`` of the difference Jacobian: forward, or backward when the forward point
        is invalid (a model limitation there: non-finite residual)."""
        xp = x.copy()
        xp[i] += h
        col = (self.residual(xp) - r0) / h
        if not np.all(np.isfinite(col)):
            xp[i] -= 2 * h
            col = (r0 - self.residual(xp)) / h
        return col

    def orientation(self):
        """+1 for right edges, -1 for left ones (outward)."""
        return np.tile([-1.0, 1.0], self.n_edges // 2)

    def max_step(self, x):
        half = 0.5 * (x[1::2] - x[0::2])
        lim = np.maximum(0.3 * half, 1e-3)
        return np.repeat(lim, 2)
