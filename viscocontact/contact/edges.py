r"""What happens at the contact edges: stress-intensity factors and the energy terms of equations
4.9-4.14.

Energies use the *stored-energy* sign (``U = (1/2)∫ p u dx >= 0``; the thesis's eqs. 4.13-4.14 as
printed, with σ tensile-positive, give minus these), in the units of eq. 4.17, so that at
equilibrium ``δŨ/δX̃ + δL̃_P/δX̃ = 2πγ̃/Λ̃²`` (eq. 4.20).

Finite edge advance ``δX`` (outward, at fixed penetration Δ̃; thesis eqs. 4.12-4.14): the field
``σ⁺`` is solved on the contact re-meshed with the edge moved, and

* ``δU = U⁺ - U⁻`` with ``U = -(1/2) Σ_q h_q σ̃_q w(ξ_q)`` (``w = r̃ - 1 + Δ̃``, exact at the
  collocation points),
* ``δL_P = -(1/2) ∫∫ σ⁻(x) [G̃(x-y) - G̃(y-x)] σ⁺(y) dy dx``: only the non-reciprocal part of the
  kernel enters, it is smooth, and the inner integral is exact (``PreparedKernel.even_antiderivative``).

Both are global quantities and converge like the load (O(N⁻²)); the crack-closure form
``(1/2)∫ σ⁺ (u⁻ - w)`` is algebraically the same sum but is dominated by near-edge collocation
errors, so it is not used. ``δX → 0`` (``edge_perturbation = 0``): the balance reduces to the
stress-intensity factor with the instantaneous compliance, ``δL̃/δX̃ = K_e K̃²/4``
(``K_e = E0 J(0+)``, or 1 when every branch is relaxed); see :func:`limit_energy_release`.

Stress-intensity factors come from the fit of :func:`~viscocontact.contact.fields.stress_intensity`
divided by a calibration factor: on an edge-graded mesh the relative error of the collocation stress
near the edge does not vanish with refinement (the mesh is self-similar there), so the fitted ``K̃``
of the exactly known single-contact field ``cos(x/2)/√(s² - sin²(x/2))`` on the same mesh type and
half-width fixes the factor (about 0.985 for n = 1 and 0.943 with geometric edge zones of ratio 1.25;
tabulated over the half-width, and h0/α with zones, once per mesh type).
"""
from __future__ import annotations

import functools

import attrs
import numpy as np

from .calibration import sif_calibration
from .fields import FieldSolution, NormalizedProfile, stress_intensity
from .mesh import (ALIGN_MAX, ZONE_CAP, Mesh, MeshSpec, build_mesh, element_counts,
                   tip_elements)
from ..kernels.prepared import element_integrals


def _antisymmetric_block(even_antiderivative, row_left, row_right, col_left, col_right):
    """``∫_{e_q} [G̃(ξ_l - y) - G̃(y - ξ_l)] dy`` at the midpoints ξ_l of the row elements.

    ``E`` is the (even) antiderivative of the odd part ``A(s) = G̃(s) - G̃(-s)``. (A 4-point
    Gauss rule in ξ instead of the midpoint changes δL_P by less than 1e-6 relative on an edge
    zone of ratio 1.25 and costs four times more.)
    """
    return element_integrals(even_antiderivative, 0.5 * (row_left + row_right), col_left,
                             col_right)


#: Fewest edge elements in an advance for the bordered enlarged mesh when the advance is not
#: aligned with an edge zone (an aligned zone is bordered with any number).
MIN_BORDER = 8

#: Most new elements whose mutual influence coefficients :meth:`EdgeContext.prepare_borders`
#: evaluates in one call (the advances' diagonal blocks are then taken from it).
GROUP_ELEMENTS = 160


def dissipative(kernel) -> bool:
    """Whether ``kernel`` has a non-reciprocal part (memory branches or a layer correction):
    without one, δL_P vanishes identically."""
    return len(kernel.weights) > 0 or kernel.correction is not None


def outward(edges: np.ndarray, i: int, dx: float) -> np.ndarray:
    """Edges with edge ``i`` moved outward by ``dx`` (left edges to the left, right to the right)."""
    out = np.array(edges, dtype=float)
    out[i] += dx if i % 2 else -dx
    return out


class EdgeContext:
    """Edge quantities of one field solution (built by the orchestrator, read by adhesion models)."""

    def __init__(self, fields: FieldSolution, kernel, shape: NormalizedProfile, spec: MeshSpec,
                 amplitude: float, zones=None, counts=None,
                 geometry: BorderGeometry | None = None):
        self.fields = fields
        self.kernel = kernel
        self.shape = shape
        self.spec = spec
        self.zones = zones
        self.counts = counts            # elements of each contact (None: spec.elements for all)
        self.amplitude = amplitude      # Λ̃
        self._sif: np.ndarray | None = None
        #: the borders' new rows and columns, when prepared beside the factorisation
        #: (:func:`border_geometry`; :meth:`prepare_borders` computes them otherwise)
        self._geometry = geometry

    @property
    def mesh(self) -> Mesh:
        return self.fields.mesh

    @property
    def n_edges(self) -> int:
        return len(self.mesh.edges)

    @property
    def dissipative(self) -> bool:
        """:func:`dissipative` of the kernel."""
        return dissipative(self.kernel)

    @property
    def edge_compliance(self) -> float:
        """``K_e``: coefficient of the log singularity of the kernel (E0·J(0+), or 1 if relaxed)."""
        return float(self.kernel.instantaneous)

    def stress_intensity(self) -> np.ndarray:
        """Calibrated ``K̃`` at every edge (tensile positive)."""
        if self._sif is None:
            raw = stress_intensity(self.mesh, self.fields.sigma)
            e = self.mesh.edges
            half = 0.5 * (e[1::2] - e[0::2])
            first = np.array([self.mesh.width[self.mesh.slice(j)][0]
                              for j in range(self.mesh.n_contacts)])
            counts = np.repeat(element_counts(self.spec, self.counts, len(half)), 2)
            hw, rel = np.repeat(half, 2), np.repeat(first / half, 2)
            ratio = np.empty_like(raw)
            for n in np.unique(counts):
                at = counts == n
                ratio[at] = sif_calibration(attrs.evolve(self.spec, elements=int(n)), hw[at],
                                            rel[at])
            self._sif = raw / ratio
        return self._sif

    def stored_energy(self, fields: FieldSolution | None = None) -> float:
        f = fields or self.fields
        return float(-0.5 * np.sum(f.mesh.width * f.sigma * (f.rhs0 + f.penetration)))

    def enlarged(self, i: int, dx: float) -> FieldSolution:
        """Field at the same penetration with edge ``i`` moved outward by ``dx`` (re-meshed).

        Only the moved contact's rows and columns of the influence matrix are recomputed; the
        system is solved by iterative refinement preconditioned with the base factorisation (a
        few steps, since the moved contact's mesh changes by O(dx)), falling back to a direct
        solve when that does not converge.
        """
        from scipy.linalg import lu_factor, lu_solve

        base = self.fields
        j = i // 2
        mesh = build_mesh(outward(self.mesh.edges, i, dx), self.spec, self.zones, self.counts)
        sl = self.mesh.slice(j)
        k = self.kernel
        B = base.matrix.copy()
        B[:, sl] = k.influence(mesh.mid, mesh.left[sl], mesh.right[sl])
        B[sl, :] = k.influence(mesh.mid[sl], mesh.left, mesh.right)
        rhs0 = base.rhs0.copy()
        rhs0[sl] = self.shape.heights(mesh.mid[sl]) - 1.0
        rhs = rhs0 + base.penetration
        sigma = lu_solve(base.lu, rhs, check_finite=False)
        scale = np.linalg.norm(rhs)
        lu = base.lu
        for _ in range(30):
            res = rhs - B @ sigma
            if np.linalg.norm(res) <= 1e-14 * scale:
                break
            sigma = sigma + lu_solve(base.lu, res, check_finite=False)
        else:
            lu = lu_factor(B, check_finite=False)
            sigma = lu_solve(lu, rhs, check_finite=False)
        p = float(-(mesh.width @ sigma) / (2 * np.pi))
        return FieldSolution(mesh=mesh, sigma=sigma, penetration=base.penetration,
                             mean_pressure=p, matrix=B, lu=lu, rhs0=rhs0)

    def _antisymmetric_matrix(self):
        """``A[l, q] = ∫_{e_q} [G̃(ξ_l - y) - G̃(y - ξ_l)] dy`` on the base mesh (cached)."""
        if getattr(self, "_abase", None) is None:
            m = self.mesh
            self._abase = (self.fields.antisymmetric if self.fields.antisymmetric is not None
                           else _antisymmetric_block(self.kernel.even_antiderivative, m.left,
                                                     m.right, m.left, m.right))
        return self._abase

    def nonconservative_work(self, before: FieldSolution, after: FieldSolution) -> float:
        """``δL_P`` (stored-energy sign) between the base field and an enlarged one (eq. 4.14).

        ``-(1/2)∫∫ σ⁻(x) A(x - y) σ⁺(y)`` with ``A(s) = G̃(s) - G̃(-s)`` odd, evaluated as the mean of
        the two one-sided quadratures (midpoint in one variable, exact in the other), which is
        exactly antisymmetric: it vanishes for equal fields, so ``δL_P/δX`` carries no O(N⁻²)
        offset as δX → 0. ``after`` differs from ``before`` (the base field) in one contact's
        elements only, so only that contact's rows and columns are evaluated anew.
        """
        if not self.dissipative:
            return 0.0
        E = self.kernel.even_antiderivative
        mb, ma = before.mesh, after.mesh
        changed = np.flatnonzero((mb.left != ma.left) | (mb.right != ma.right))
        A0 = self._antisymmetric_matrix()
        if changed.size == 0:
            return 0.0
        sl = slice(int(changed[0]), int(changed[-1]) + 1)
        # Q(before, after): rows on the base mesh, columns on the enlarged one
        cols = A0.copy()
        cols[:, sl] = _antisymmetric_block(E, mb.left, mb.right, ma.left[sl], ma.right[sl])
        q_ba = (mb.width * before.sigma) @ cols @ after.sigma
        # Q(after, before): rows on the enlarged mesh, columns on the base one
        rows = A0.copy()
        rows[sl, :] = _antisymmetric_block(E, ma.left[sl], ma.right[sl], mb.left, mb.right)
        q_ab = (ma.width * after.sigma) @ rows @ before.sigma
        return float(-0.25 * (q_ba - q_ab))

    def energy_release(self, i: int, dx: float) -> tuple[float, float]:
        """``(δŨ/δX̃, δL̃_P/δX̃)`` for an outward advance ``dx`` of edge ``i`` (stored sign).

        With an edge zone the enlarged contact is meshed as the base mesh bordered by new
        elements over ``dx`` (:meth:`bordered_release`); otherwise (``dx`` shorter than
        ``MIN_BORDER`` edge elements) it is re-meshed (:meth:`enlarged`).
        """
        bordered = self.bordered_release(i, dx)
        if bordered is not None:
            return bordered
        after = self.enlarged(i, dx)
        d_u = self.stored_energy(after) - self.stored_energy()
        d_lp = self.nonconservative_work(self.fields, after)
        return d_u / dx, d_lp / dx

    def _base_products(self):
        """``A σ⁻`` and ``(h σ⁻)ᵀ A`` of the base field with the antisymmetric matrix (cached)."""
        if getattr(self, "_aprod", None) is None:
            A0 = self._antisymmetric_matrix()
            f = self.fields
            self._aprod = (A0 @ f.sigma, (f.mesh.width * f.sigma) @ A0)
        return self._aprod

    def bordered_release(self, i: int, dx: float):
        """``(δŨ/δX̃, δL̃_P/δX̃)`` on the base mesh bordered by new elements over ``dx``.

        The enlarged contact keeps every base element and gains the ``n`` elements of
        :func:`new_elements` that cover ``[X - δX, X]`` (left edge) or ``[X, X + δX]`` (right
        edge); near the new edge it is then meshed as a fresh zone would be. The bordered system
        ``[[B, c], [r, d]]`` is solved through its ``n x n`` Schur complement with the base
        factorisation, and only the ``2n`` new rows and columns of the influence and
        antisymmetric matrices are evaluated. Because the two fields share all base elements, no
        re-meshing noise of the contact interior enters ``U⁺ - U⁻`` or ``δL_P``. None when ``dx``
        is shorter than ``MIN_BORDER`` edge elements (no edge zone).
        """
        border = self.border(i, dx)
        if border is None:
            return None
        return border.d_u / dx, border.d_lp / dx

    def border(self, i: int, dx: float) -> Border | None:
        """The bordered enlarged field of edge ``i`` advanced by ``dx`` (cached; None when
        ``dx`` is shorter than ``MIN_BORDER`` edge elements): what :meth:`bordered_release`
        computes, kept for its derivatives (:mod:`~viscocontact.contact.sensitivity`)."""
        key = (i, float(dx))
        if key not in self._borders:
            self.prepare_borders([key])
        return self._borders[key]

    @functools.cached_property
    def _borders(self) -> dict:
        return {}

    def prepare_borders(self, advances) -> None:
        """Compute the bordered fields of every ``(edge, δX)`` in ``advances`` at once (one
        evaluation of the new rows and columns and one multiple right-hand-side solve for all
        edges instead of one per edge) and cache them for :meth:`border`. The new rows and
        columns are the ``geometry`` given to the context when it was prepared for exactly these
        advances (while the base matrix was factorised), else computed here."""
        todo = [(int(i), float(dx)) for i, dx in advances if (int(i), float(dx)) not in
                self._borders]
        if not todo:
            return
        geometry = self._geometry
        if geometry is None or list(geometry.elements) != todo:
            geometry = border_geometry(self.mesh, self.kernel, self.shape, self.spec, todo)
        from scipy.linalg import lu_factor, lu_solve

        from .._threads import solve_columns

        for key, elements in geometry.elements.items():
            if elements is None:
                self._borders[key] = None
        new = geometry.new
        if not new:
            return
        base, mesh = self.fields, self.mesh
        c, r, cols, rows = geometry.c, geometry.r, geometry.cols, geometry.rows
        bounds = geometry.bounds
        w_new = geometry.heights + base.penetration
        Y = solve_columns(base.lu, c)                        # (N, Σn), on the cores
        w_old = base.rhs0 + base.penetration
        hsig = mesh.width * base.sigma
        r_sigma = r @ base.sigma
        if self.dissipative:
            assert cols is not None and rows is not None
            a_sig, hsig_a = self._base_products()
            cols_hsig = hsig @ cols
            rows_sigma = rows @ base.sigma
        for n, (i, dx) in enumerate(new):
            sl = slice(bounds[n], bounds[n + 1])
            ai, bi = geometry.elements[(i, dx)]
            yi = Y[:, sl]
            d = geometry.blocks[(i, dx)]                         # (n, n)
            schur = lu_factor(d - r[sl] @ yi, check_finite=False)
            s_new = lu_solve(schur, w_new[sl] - r_sigma[sl], check_finite=False)
            s_old = base.sigma - yi @ s_new
            h_new = bi - ai
            d_u = -0.5 * (np.sum(mesh.width * (s_old - base.sigma) * w_old)
                          + np.sum(h_new * s_new * w_new[sl]))
            d_lp = 0.0
            if self.dissipative:
                q_ba = hsig_a @ s_old + cols_hsig[sl] @ s_new
                q_ab = (mesh.width * s_old) @ a_sig + (h_new * s_new) @ rows_sigma[sl]
                d_lp = float(-0.25 * (q_ba - q_ab))
            self._borders[(i, dx)] = Border(
                edge=i, advance=dx, left=ai, right=bi, c=c[:, sl], r=r[sl], Y=yi, schur=schur,
                s_new=s_new, s_old=s_old, w_new=w_new[sl],
                cols=None if cols is None else cols[:, sl],
                rows=None if rows is None else rows[sl], d_u=float(d_u), d_lp=d_lp)


def new_elements(mesh: Mesh, spec: MeshSpec, i: int, dx: float):
    """``(left, right)`` of the elements that extend ``mesh`` over ``dx`` outside edge ``i``, or
    None when ``dx`` is less than ``MIN_BORDER`` edge elements (the old edge's singular field,
    now inside the contact, would be left unresolved); :func:`new_element_layout`."""
    layout = new_element_layout(mesh, spec, i, dx)
    return None if layout is None else layout[:2]


def new_element_layout(mesh: Mesh, spec: MeshSpec, i: int, dx: float):
    """``(left, right, fixed)``: the elements of :func:`new_elements` and how many of them, next
    to the new edge, keep their sizes when ``dx`` changes (the others are stretched to fill it;
    :mod:`~viscocontact.contact.sensitivity` moves the nodes so), or None.

    When the edge element ``h`` divides ``dx`` into at most ``ALIGN_MAX`` parts and the base
    mesh has equal elements of ``h`` over ``dx`` (a zone aligned with the advance), ``dx/h``
    equal elements, all stretched, however few: with fewer than ``MIN_BORDER`` the balance fell
    back to the re-meshed contact, another discretisation (edge_resolution 0.15-0.5 at
    δX = 1e-4, 7 to 2 elements per advance: Johnson's wavy area 3e-5 lower, the wavy thesis
    scene's at ζ = 1e-2 1.4e-3 lower, and no analytic Jacobian). Otherwise
    (:func:`matched_sizes`) the new edge gets the zone's own sequence of sizes (its equal edge
    elements, then the grading) up to a peak, and sizes falling by the grading from the peak
    to about ``h`` at the old edge fill the rest. The new edge is then meshed exactly as the
    base edge is, so that the discretisation error of the edge field, which is the same for the
    same pattern of elements wherever the edge lies, cancels in ``U⁺ - U⁻`` as it does for an
    aligned zone. (Sizes growing from ``h`` at both ends, the earlier border, left the new edge
    without the zone's equal elements: on Johnson's wavy contact, Γ̃ = 0.05, p̃∞ = 0.1,
    δX = 1e-4, the area then moved by 5e-4 from Johnson's when the edge element was refined
    from δX/10 to δX/25, against 1e-5 now.)
    """
    sl = mesh.slice(i // 2)
    first = sl.start if i % 2 == 0 else sl.stop - 1
    h = float(mesh.width[first])
    n = int(round(dx / h))
    inner = mesh.width[sl][:n] if i % 2 == 0 else mesh.width[sl][::-1][:n]
    if (1 <= n <= ALIGN_MAX and abs(n * h - dx) <= 1e-9 * dx and len(inner) == n
            and np.allclose(inner, h, rtol=1e-9, atol=0.0)):
        # a zone aligned with the advance (equal elements over it): the new edge gets n
        # elements of h and then the base zone's equal ones, and the old edge stays amid
        # equal elements, however few n is
        sizes, fixed = np.full(n, h), 0
    elif dx < MIN_BORDER * h * (1 - 1e-9):
        return None
    else:
        sizes, fixed = matched_layout(h, tip_elements(spec), spec.grading, dx)
    if i % 2:                       # a right edge's new elements run from the old edge out
        sizes = sizes[::-1]
    offsets = np.concatenate([[0.0], np.cumsum(sizes)])
    offsets[-1] = dx
    x = float(mesh.edges[i])
    nodes = x - dx + offsets if i % 2 == 0 else x + offsets
    nodes[-1 if i % 2 == 0 else 0] = x
    return nodes[:-1], nodes[1:], fixed


def matched_sizes(h: float, equal: int, grading: float, dx: float) -> np.ndarray:
    """Element sizes over an advance ``dx``, from the new edge (first) to the old one (last):
    an edge zone's own sequence from the new edge (``equal`` elements of ``h``, then sizes
    growing by ``grading``; :func:`~viscocontact.contact.mesh.zone_pattern`) up to a peak, then
    sizes falling by ``grading`` to about ``h`` at the old edge, stretched (by less than about
    ``grading² - 1``) to fill ``dx``; :func:`matched_layout`.

    >>> s = matched_sizes(1.0, 3, 2.0, 20.0)
    >>> s.tolist()[:5], float(s.sum())
    ([1.0, 1.0, 1.0, 2.0, 4.0], 20.0)
    """
    return matched_layout(h, equal, grading, dx)[0]


def matched_layout(h: float, equal: int, grading: float, dx: float) -> tuple[np.ndarray, int]:
    """``(sizes, fixed)`` of :func:`matched_sizes`: the first ``fixed`` sizes (the new edge's
    rising side) do not depend on ``dx``, the rest (the falling side) are stretched in
    proportion to fill it."""
    def falling(peak: float) -> list:
        out = []
        size = peak / grading
        while size >= h * (1 - 1e-9):
            out.append(size)
            size /= grading
        return out

    head: list = []
    while True:
        nxt = h if len(head) < equal else head[-1] * grading
        if head and sum(head) + nxt + sum(falling(nxt)) > dx * (1 + 1e-12):
            break
        head.append(nxt)
    tail = falling(head[-1])
    if not tail:                   # the head alone (equal elements): its last one stretches
        tail, head = head[-1:], head[:-1]
    rest = dx - sum(head)
    tail = [t * rest / sum(tail) for t in tail]
    return np.array(head + tail), len(head)


@attrs.frozen(kw_only=True, eq=False)
class BorderGeometry:
    """What the bordered fields of some edge advances need of the mesh and the kernel alone
    (:func:`border_geometry`): their new elements and the new rows and columns of the influence
    and antisymmetric matrices. It does not depend on the field, so it can be computed while the
    base matrix is factorised.

    Attributes
    ----------
    elements : dict
        ``(edge, δX) -> (left, right)`` of the new elements, or None (no border).
    new : list
        The keys with a border, in the order of the columns below.
    c, r : (N, Σn) and (Σn, N) arrays
        New columns and rows of the influence matrix.
    cols, rows : arrays or None
        The antisymmetric matrix's new columns and rows (None for a reciprocal kernel).
    blocks : dict
        ``(edge, δX) -> (n, n)`` influence of each advance's new elements on each other.
    heights : (Σn,) array
        ``r̃ - 1`` at the new collocation points.
    bounds : array
        Where each key's columns start in ``c`` (and end: the next entry), in the order of
        ``new``.
    """

    elements: dict
    new: list
    c: np.ndarray
    r: np.ndarray
    cols: np.ndarray | None
    rows: np.ndarray | None
    blocks: dict
    heights: np.ndarray
    bounds: np.ndarray


def border_geometry(mesh: Mesh, kernel, shape: NormalizedProfile, spec: MeshSpec,
                    advances) -> BorderGeometry:
    """The new elements, rows and columns of the bordered fields of ``advances`` (pairs
    ``(edge, δX)``) on ``mesh`` (:meth:`EdgeContext.prepare_borders`)."""
    elements, new = {}, []
    for i, dx in advances:
        key = (int(i), float(dx))
        elements[key] = new_elements(mesh, spec, *key)
        if elements[key] is not None and key not in new:
            new.append(key)
    bounds = np.cumsum([0] + [len(elements[key][0]) for key in new])
    if not new:
        n = len(mesh.mid)
        return BorderGeometry(elements=elements, new=new, c=np.empty((n, 0)),
                              r=np.empty((0, n)), cols=None, rows=None, blocks={},
                              heights=np.empty(0), bounds=bounds)
    k = kernel
    nonreciprocal = dissipative(k)
    a = np.concatenate([elements[key][0] for key in new])
    b = np.concatenate([elements[key][1] for key in new])
    xi = 0.5 * (a + b)
    pair = getattr(k, "antiderivative_pair", None) if nonreciprocal else None
    cols = rows = None
    if pair is not None:      # influence and antisymmetric integrals share the table look-ups
        c, cols = element_integrals(pair, mesh.mid, a, b)
        r, rows = element_integrals(pair, xi, mesh.left, mesh.right)
        c += k.mean * (b - a)
        r += k.mean * mesh.width
    else:
        c = k.influence(mesh.mid, a, b)                      # (N, n)
        r = k.influence(xi, mesh.left, mesh.right)          # (n, N)
        if nonreciprocal:
            E = k.even_antiderivative
            cols = element_integrals(E, mesh.mid, a, b)      # rows: base, columns: new
            rows = element_integrals(E, xi, mesh.left, mesh.right)   # new, base
    heights = shape.heights(xi) - 1.0
    # the new elements against each other: each advance needs its diagonal block (tens of
    # coefficients, where the call costs more than the evaluation), so groups of advances of up
    # to GROUP_ELEMENTS elements are evaluated in one call
    blocks, g0 = {}, 0
    for n in range(1, len(new) + 1):
        if n == len(new) or bounds[n + 1] - bounds[g0] > GROUP_ELEMENTS:
            gs = slice(bounds[g0], bounds[n])
            d_group = k.influence(xi[gs], a[gs], b[gs])
            for m in range(g0, n):
                rel = slice(bounds[m] - bounds[g0], bounds[m + 1] - bounds[g0])
                blocks[new[m]] = d_group[rel, rel]
            g0 = n
    return BorderGeometry(elements=elements, new=new, c=c, r=r, cols=cols, rows=rows,
                          blocks=blocks, heights=heights, bounds=bounds)


@attrs.frozen(kw_only=True, eq=False)
class Border:
    """The bordered enlarged field of one edge advance (:meth:`EdgeContext.border`).

    Attributes
    ----------
    edge : int
    advance : float
        ``δX`` (q0-scaled).
    left, right : (n,) arrays
        The new elements over the advance.
    c, r : (N, n) and (n, N) arrays
        New columns and rows of the influence matrix (base collocation points against new
        elements, and the reverse).
    Y : (N, n) array
        ``B⁻¹ c``.
    schur : tuple
        LU factors of the Schur complement ``d - r Y``.
    s_new, s_old : arrays
        Enlarged field on the new and on the base elements.
    w_new : (n,) array
        ``w = r̃ - 1 + Δ̃`` at the new collocation points.
    cols, rows : arrays or None
        The antisymmetric matrix's new columns and rows (None for a reciprocal kernel).
    d_u, d_lp : float
        ``δŨ`` and ``δL̃_P`` (not divided by δX).
    """

    edge: int
    advance: float
    left: np.ndarray
    right: np.ndarray
    c: np.ndarray
    r: np.ndarray
    Y: np.ndarray
    schur: tuple
    s_new: np.ndarray
    s_old: np.ndarray
    w_new: np.ndarray
    cols: np.ndarray | None
    rows: np.ndarray | None
    d_u: float
    d_lp: float


def limit_energy_release(ctx: EdgeContext) -> np.ndarray:
    """``δL̃/δX̃`` for ``δX → 0`` at every edge: ``K_e K̃²/4`` (Irwin with the instantaneous
    compliance; signed with K̃ so that it is monotone in the edge position)."""
    k = ctx.stress_intensity()
    return ctx.edge_compliance * k * np.abs(k) / 4.0
