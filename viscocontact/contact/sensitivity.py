r"""Derivatives of the fixed-edge field solution with respect to the edges and the penetration.

For fixed edges ``x`` the stresses solve ``B(x) σ = w(x) = r̃(ξ) - 1 + Δ̃`` (eq. 4.31). Every
contact's mesh is attached to its two edges: its nodes are ``c + g(α)`` with centre ``c``,
half-width ``α`` and the node pattern ``g`` of eq. 4.22 with the solve's fixed edge zones, so each
node moves with ``∂z/∂X_{2j-1} = (1 - g'(α))/2`` and ``∂z/∂X_{2j} = (1 + g'(α))/2`` (``g'``
by a central difference of the pattern: no kernel evaluation). The influence coefficient
``B[p, q] = F(ξ_p - a_q) - F(ξ_p - b_q) + c0 (b_q - a_q)`` (eq. 4.32) then changes by

.. math:: \dot B[p, q] = G(ξ_p - a_q)(\dot ξ_p - \dot a_q) - G(ξ_p - b_q)(\dot ξ_p - \dot b_q),

``G = F' + c0`` the kernel (the slopes of the tabulated antiderivative, so that the derivative
is that of the computed ``B``). Hence ``σ̇ = B⁻¹(ẇ - Ḃσ)`` with the factorisation already at
hand, and any quantity ``ψᵀσ`` changes by ``μᵀ(ẇ - Ḃσ)`` with ``Bᵀμ = ψ`` (one adjoint solve
per quantity, whatever the number of edges). ``Ḃσ`` needs ``G`` at the collocation points
minus the nodes, the points of the influence matrix itself: a Jacobian costs about one residual.

Directions: the ``2 N_c`` edges (order ``X_1, X_2, ...``) at fixed penetration, then the
penetration ``Δ̃`` at fixed edges (last column). Load control follows from the mean pressure's
derivatives (:meth:`FieldSensitivity.pressure`).

The energy terms of the finite-δX balance (eqs. 4.12-4.14, the bordered enlarged mesh of
:meth:`~viscocontact.contact.edges.EdgeContext.border`) are differentiated the same way:
the enlarged field by an adjoint solve of the bordered system through its Schur complement, the
antisymmetric matrix of ``δL̃_P`` with the slopes of the non-reciprocal part of the kernel.
"""
from __future__ import annotations

import functools

import attrs
import numpy as np
from scipy.linalg import lu_solve

from .._threads import pair
from ..kernels.prepared import pairwise
from .edges import Border, dissipative, new_element_layout, sif_calibration
from .fields import _POWERS, N_FIT, _avg_power, edge_rows
from .mesh import contact_spec, element_counts, graded_nodes

#: Relative step of the central difference of a contact's node pattern in its half-width.
NODE_STEP = 1e-6


def contact_nodes(a: float, b: float, spec, zone) -> np.ndarray:
    """Nodes of the contact ``[a, b]`` exactly as :func:`~viscocontact.contact.mesh.build_mesh`
    places them (``zone``: its fixed edge zone, ``None``: the default one)."""
    z = 0.5 * (a + b) + graded_nodes(0.5 * (b - a), spec, zone)
    z[0], z[-1] = a, b
    return z


def node_velocities(a: float, b: float, spec, zone) -> tuple[np.ndarray, np.ndarray]:
    """``(∂z/∂a, ∂z/∂b)`` of the nodes of contact ``[a, b]`` (edge zones kept fixed)."""
    alpha = 0.5 * (b - a)
    eps = NODE_STEP * alpha
    dg = (graded_nodes(alpha + eps, spec, zone) - graded_nodes(alpha - eps, spec, zone)) / (2 * eps)
    dg[0], dg[-1] = -1.0, 1.0
    return 0.5 * (1.0 - dg), 0.5 * (1.0 + dg)


def _edge_weights(nodes: np.ndarray, spec) -> tuple[np.ndarray, np.ndarray]:
    """Weights ``w`` with calibrated ``K̃ = w·σ`` on the first (last) fitted elements of one
    contact, its left and its right edge; ``spec`` has the contact's element count. The same
    arithmetic as :func:`~viscocontact.contact.fields.stress_intensity` with the calibration of
    :meth:`~viscocontact.contact.edges.EdgeContext.stress_intensity`, up to the least-squares
    solver."""
    left, right = nodes[:-1], nodes[1:]
    n_fit = min(N_FIT, max(3, len(left) // 2))
    xl, xr = nodes[0], nodes[-1]

    def first_row(ra, rb):
        A = np.column_stack([_avg_power(ra[:n_fit], rb[:n_fit], p) for p in _POWERS])
        return np.linalg.pinv(A)[0] * np.sqrt(2 * np.pi)

    wl = first_row(left - xl, right - xl)
    wr = first_row((xr - right)[::-1], (xr - left)[::-1])
    half = 0.5 * (xr - xl)
    first = right[0] - left[0]
    ratio = sif_calibration(spec, np.array([half, half]), np.array([first, first]) / half)
    return wl / ratio[0], wr / ratio[1]


class FieldSensitivity:
    """Derivatives of one fixed-edge field solution (see the module docstring).

    Parameters
    ----------
    fields : FieldSolution
    kernel : PreparedKernel
    shape : NormalizedProfile
    spec : MeshSpec
    zones, counts
        The fixed edge zones and element counts the mesh was built with.
    """

    def __init__(self, fields, kernel, shape, spec, zones=None, counts=None):
        self.fields = fields
        self.kernel = kernel
        self.shape = shape
        self.spec = spec
        self.zones = zones
        self.counts = counts
        mesh = fields.mesh
        nc = mesh.n_contacts
        self.n_edges = 2 * nc
        self.n_dirs = 2 * nc + 1
        n_el = len(mesh.left)
        nodes, vel, left_idx, right_idx = [], [], np.empty(n_el, np.intp), np.empty(n_el, np.intp)
        k0 = 0
        for j in range(nc):
            sl = mesh.slice(j)
            z = np.append(mesh.left[sl], mesh.right[sl][-1])
            da, db = node_velocities(mesh.edges[2 * j], mesh.edges[2 * j + 1],
                                     contact_spec(spec, counts, j),
                                     None if zones is None else zones[j])
            v = np.zeros((len(z), self.n_dirs))
            v[:, 2 * j], v[:, 2 * j + 1] = da, db
            nodes.append(z)
            vel.append(v)
            m = sl.stop - sl.start
            left_idx[sl] = k0 + np.arange(m)
            right_idx[sl] = k0 + np.arange(1, m + 1)
            k0 += m + 1
        #: node positions and velocities (K, D); element q runs from node left_idx[q] to
        #: node right_idx[q]
        self.nodes = np.concatenate(nodes)
        self.node_vel = np.concatenate(vel)
        self.left_idx, self.right_idx = left_idx, right_idx
        self.colloc_vel = 0.5 * (self.node_vel[left_idx] + self.node_vel[right_idx])
        self.width_vel = self.node_vel[right_idx] - self.node_vel[left_idx]
        w_vel = self.shape.slopes(mesh.mid)[:, None] * self.colloc_vel
        w_vel[:, -1] = 1.0
        #: ẇ: the right-hand side's change in every direction (N, D)
        self.w_vel = w_vel
        #: what an adhesion model's derivative methods share at this point (contract item 4)
        self.memo: dict = {}

    # ---- building blocks ----------------------------------------------------------------
    def node_weights(self, u: np.ndarray, left_idx=None, right_idx=None, size=None) -> np.ndarray:
        """``s_k = Σ_q u_q ([a_q = z_k] - [b_q = z_k])`` over the nodes (``u``: (N,) or (N, M))."""
        li = self.left_idx if left_idx is None else left_idx
        ri = self.right_idx if right_idx is None else right_idx
        size = len(self.nodes) if size is None else size
        u = np.asarray(u, dtype=float)
        out = np.zeros((size,) + u.shape[1:])
        np.add.at(out, li, u)
        np.subtract.at(out, ri, u)
        return out

    @functools.cached_property
    def slopes(self):
        """``(G, E')`` at the base collocation points minus the base nodes (E' None for a
        reciprocal kernel): ``G = F' + c0``, ``E'`` the non-reciprocal part."""
        return self._slopes(self.fields.mesh.mid, self.nodes)

    def _slopes(self, points, nodes):
        """``(G, E')`` at ``points`` minus ``nodes`` (every pair)."""
        k = self.kernel
        if self.dissipative:
            g, e = pairwise(k.slope_pair, points, nodes)
            g += k.mean
            return g, e
        g = pairwise(k.antiderivative_slope, points, nodes)
        g += k.mean
        return g, None

    @property
    def dissipative(self) -> bool:
        return dissipative(self.kernel)

    @functools.cached_property
    def rhs(self) -> np.ndarray:
        """``f = ẇ - Ḃσ`` (N, D): ``σ̇ = B⁻¹ f`` at fixed edges and penetration otherwise."""
        G = self.slopes[0]
        s = self.node_weights(self.fields.sigma)
        b_sigma = self.colloc_vel * (G @ s)[:, None] - G @ (self.node_vel * s[:, None])
        return self.w_vel - b_sigma

    def adjoint(self, psi: np.ndarray) -> np.ndarray:
        """``μ = B⁻ᵀ ψ`` (``ψ``: (N,) or (N, M))."""
        return lu_solve(self.fields.lu, psi, trans=1, check_finite=False)

    def linear(self, psi: np.ndarray) -> np.ndarray:
        """Derivatives ``d(ψᵀσ)/d(x, Δ̃)`` of the functionals ``ψ`` (N, M) at fixed ``ψ``:
        (M, D)."""
        return self.adjoint(psi).T @ self.rhs

    def stresses(self) -> np.ndarray:
        """``σ̇ = B⁻¹ f`` (N, D): forward mode, every direction."""
        return lu_solve(self.fields.lu, self.rhs, check_finite=False)

    def pressure(self) -> np.ndarray:
        """``dp̃∞/d(x, Δ̃)`` (D,): ``p̃∞ = -(1/2π) Σ h σ``."""
        mesh, sigma = self.fields.mesh, self.fields.sigma
        d = self.linear(mesh.width[:, None])[0] + self.width_vel.T @ sigma
        return -d / (2 * np.pi)

    # ---- stress-intensity factors -----------------------------------------------------------
    def stress_intensity(self) -> np.ndarray:
        """``dK̃/d(x, Δ̃)`` (2 N_c, D) of the calibrated stress-intensity factors."""
        counts = element_counts(self.spec, self.counts, self.fields.mesh.n_contacts)

        def calibrated(j):
            cal = attrs.evolve(self.spec, elements=int(counts[j]))
            return lambda nodes: _edge_weights(nodes, cal)

        W, explicit = self._moving_rows(calibrated)
        return self.linear(W) + explicit

    def fit_motion(self, powers) -> tuple[np.ndarray, np.ndarray]:
        """The rows ``W`` of the uncalibrated fit with ``powers``
        (:func:`~viscocontact.contact.fields.intensity_matrix`) and the change of ``Wσ`` at
        fixed ``σ`` as the rows move with the mesh, (2 N_c, D) (a central difference of the node
        pattern in each edge, as :meth:`stress_intensity`). ``dK̃ = W σ̇ + explicit``."""
        def uncalibrated(j):
            def rows(nodes):
                wl, wr = edge_rows(nodes, powers)
                return wl, wr[::-1]
            return rows

        W, explicit = self._moving_rows(uncalibrated)
        return W.T, explicit

    def _moving_rows(self, weights_of) -> tuple[np.ndarray, np.ndarray]:
        """``(W, explicit)``: the fit's rows ``W`` (N, 2 N_c) and the change of ``Wᵀσ`` at fixed
        ``σ`` as they move with the mesh (2 N_c, D), a central difference of the node pattern in
        each edge (no kernel). ``weights_of(j)`` gives contact ``j``'s function of its nodes to
        ``(w_l, w_r)``, ``w_r`` on the elements counted from the right edge."""
        mesh, sigma = self.fields.mesh, self.fields.sigma
        nc = mesh.n_contacts
        W = np.zeros((len(sigma), 2 * nc))
        explicit = np.zeros((2 * nc, self.n_dirs))
        for j in range(nc):
            sl = mesh.slice(j)
            a, b = mesh.edges[2 * j], mesh.edges[2 * j + 1]
            spec_j = contact_spec(self.spec, self.counts, j)
            zone = None if self.zones is None else self.zones[j]
            weights = weights_of(j)
            wl, wr = weights(np.append(mesh.left[sl], mesh.right[sl][-1]))
            m = len(wl)
            W[sl.start:sl.start + m, 2 * j] = wl
            W[sl.stop - m:sl.stop, 2 * j + 1] = wr[::-1]
            eps = NODE_STEP * 0.5 * (b - a)
            for e, (da, db) in enumerate(((eps, 0.0), (0.0, eps))):
                lp, rp = weights(contact_nodes(a + da, b + db, spec_j, zone))
                lm, rm = weights(contact_nodes(a - da, b - db, spec_j, zone))
                explicit[2 * j, 2 * j + e] = (lp - lm) @ sigma[sl][:m] / (2 * eps)
                explicit[2 * j + 1, 2 * j + e] = (rp - rm) @ sigma[sl][::-1][:m] / (2 * eps)
        return W, explicit

    # ---- the finite-δX energy release --------------------------------------------------------
    def energy_release(self, ctx, i: int, dx: float, ddx=None) -> np.ndarray | None:
        """``d(δŨ/δX̃ + δL̃_P/δX̃)/d(x, Δ̃)`` (D,) of edge ``i`` advanced by ``dx`` on the bordered
        mesh (``ddx``: the advance's own derivatives, (D,), when it depends on the edges).
        None when the advance is not bordered (then the caller differences)."""
        out = self.energy_releases(ctx, [(i, dx, ddx)])
        return None if out is None else out[0]

    def energy_releases(self, ctx, advances) -> np.ndarray | None:
        """:meth:`energy_release` of several edge advances ``(i, dx, ddx)`` at once: (M, D).

        The edges share the kernel evaluations (one call for all new nodes), the adjoint
        solves (one multiple right-hand-side solve on the base factorisation) and the products
        with the base mesh's slope matrices (matrix-matrix instead of one matrix-vector product
        per edge). None when any advance is not bordered."""
        edges = []
        for i, dx, ddx in advances:
            advance = _Advance.of(self, ctx, i, dx, ddx)
            if advance is None:
                return None
            edges.append(advance)
        if not edges:
            return np.empty((0, self.n_dirs))
        return _EnergyReleases(self, ctx, edges).values()


@attrs.define(kw_only=True, eq=False)
class _Advance:
    """One edge advance's bordered field with its node and collocation velocities (the
    per-edge part of :meth:`FieldSensitivity.energy_releases`)."""

    border: Border
    dx: float
    ddx: np.ndarray
    nodes: np.ndarray
    node_vel: np.ndarray
    mid: np.ndarray
    colloc_vel: np.ndarray
    width_vel: np.ndarray
    s_b: np.ndarray
    s_n: np.ndarray

    @classmethod
    def of(cls, sens: FieldSensitivity, ctx, i: int, dx: float, ddx) -> "_Advance | None":
        """Edge ``i`` of ``sens``'s field advanced by ``dx`` on the bordered mesh of ``ctx``
        (``ddx``: the advance's own derivatives, (D,), or None); None when it is not
        bordered."""
        border = ctx.border(i, dx)
        if border is None:
            return None
        mesh = sens.fields.mesh
        ddx = np.zeros(sens.n_dirs) if ddx is None else np.asarray(ddx, dtype=float)
        n = len(border.s_new)
        # new nodes: translated with edge i; with the advance, those of the new edge's
        # fixed sizes move with the new edge, the others are stretched between it and the
        # old edge (new_element_layout)
        new_nodes = np.append(border.left, border.right[-1])
        x_edge = mesh.edges[i]
        side = -1.0 if i % 2 == 0 else 1.0               # the new edge's side
        o = side * (x_edge + side * dx - new_nodes)       # distance from the new edge
        layout = new_element_layout(mesh, ctx.spec, i, dx)
        fixed = 0 if layout is None else layout[2]
        held = np.sort(o)[fixed]
        stretch = np.where(o <= held, 0.0, (o - held) / (dx - held))
        nv = np.outer(side * (1.0 - stretch), ddx)
        nv[:, i] += 1.0
        li_n, ri_n = np.arange(n), np.arange(1, n + 1)
        xi_n = 0.5 * (border.left + border.right)
        return cls(border=border, dx=float(dx), ddx=ddx, nodes=new_nodes, node_vel=nv, mid=xi_n,
                   colloc_vel=0.5 * (nv[li_n] + nv[ri_n]), width_vel=nv[ri_n] - nv[li_n],
                   s_b=sens.node_weights(border.s_old),
                   s_n=sens.node_weights(border.s_new, li_n, ri_n, n + 1))


class _EnergyReleases:
    """The derivatives of the energy releases of a batch of edge advances
    (:meth:`FieldSensitivity.energy_releases`), in the stages they share: the kernel slopes
    of every new node and collocation point (three calls), the products with the base mesh's
    matrices (on two threads), the adjoint solves (one multiple right-hand-side solve); then
    each advance's derivative (:meth:`values`), with the terms of a non-reciprocal
    (dissipative) kernel apart (:meth:`_dissipative_terms`)."""

    def __init__(self, sens: FieldSensitivity, ctx, edges: list[_Advance]):
        f = sens.fields
        self.sens, self.edges, self.mesh = sens, edges, f.mesh
        self.sig, self.h, self.w = f.sigma, f.mesh.width, f.rhs0 + f.penetration
        self.dissipative = sens.dissipative and all(e.border.cols is not None for e in edges)
        self._slopes()
        self._base_functionals(ctx)
        self._products()
        self._adjoints()

    def _slopes(self) -> None:
        """The kernel slopes for every edge's new nodes and collocation points, in three
        calls, and the node weights of the base stresses and of the old elements."""
        sens, edges = self.sens, self.edges
        self.node_bounds = np.cumsum([0] + [len(e.nodes) for e in edges])
        self.mid_bounds = np.cumsum([0] + [len(e.mid) for e in edges])
        all_nodes = np.concatenate([e.nodes for e in edges])
        all_mid = np.concatenate([e.mid for e in edges])
        self.G_bb, self.E_bb = sens.slopes
        self.G_bn, self.E_bn = sens._slopes(self.mesh.mid, all_nodes)
        self.G_nb, self.E_nb = sens._slopes(all_mid, sens.nodes)
        self.G_nn, _ = sens._slopes(all_mid, all_nodes)
        self.s_sig = sens.node_weights(self.sig)
        self.S_b = np.column_stack([e.s_b for e in edges])                  # (K, M)
        self.S_old = np.column_stack([e.border.s_old for e in edges])       # (N, M)

    def _base_functionals(self, ctx) -> None:
        """The base rows of the functionals' derivatives in ``σ``: ``ψ_b`` of the enlarged
        field and ``Ψ`` of the base field (with the antisymmetric part when dissipative)."""
        h, w, sig = self.h, self.w, self.sig
        self.psi_b = -0.5 * h * w
        # ∂/∂σ of the base field
        self.Psi = np.repeat((0.5 * h * w)[:, None], len(self.edges), axis=1)
        if self.dissipative:
            self.a_sig, hsig_a = ctx._base_products()
            self.A0 = ctx._antisymmetric_matrix()
            self.hsig = h * sig
            self.psi_b = self.psi_b - 0.25 * (hsig_a - h * self.a_sig)
            self.hS_old = h[:, None] * self.S_old

    def _products(self) -> None:
        """The products with the base mesh's (N, N) matrices, in two halves of about equal
        cost, on two threads at once (the same calls, so the same bits); the first half also
        computes ``f = ẇ - Ḃσ`` (:attr:`FieldSensitivity.rhs`, two more such products)."""
        dissipative = self.dissipative
        G_bb, E_bb, S_b, s_sig = self.G_bb, self.E_bb, self.S_b, self.s_sig

        def left():
            out = {"GS_b": G_bb @ S_b, "rhs": self.sens.rhs}                # (N, M), (N, D)
            if dissipative:
                out.update(A_old=self.A0 @ self.S_old,                      # (N, M)
                           ES_b=E_bb @ S_b,                                 # (N, M)
                           E_bb_sig=E_bb @ s_sig)                           # (N,)
            return out

        def right():
            return {"At_old": self.A0.T @ self.hS_old,                      # (N, M)
                    "hsE_old": E_bb.T @ self.hS_old,                        # (K, M)
                    "hsig_E_bb": self.hsig @ E_bb,                          # (K,)
                    "E_nb_sig": self.E_nb @ s_sig}                          # (Σn,)
        products, transposed = pair(left, right) if dissipative else (left(), {})
        self.GS_b, self.rhs = products["GS_b"], products["rhs"]
        if dissipative:
            self.A_old, self.ES_b = products["A_old"], products["ES_b"]
            self.E_bb_sig = products["E_bb_sig"]
            self.At_old, self.hsE_old = transposed["At_old"], transposed["hsE_old"]
            self.hsig_E_bb, self.E_nb_sig = transposed["hsig_E_bb"], transposed["E_nb_sig"]

    def _adjoints(self) -> None:
        """The adjoints ``λₑ = Bₑ⁻ᵀψₑ`` of every enlarged field (through the Schur complement:
        ``λ_n = S⁻ᵀ(ψ_n - Yᵀψ_b)``, ``λ_b = B⁻ᵀ(ψ_b - rᵀλ_n)``) and ``μ = B⁻ᵀΨ`` of the base
        field, in one solve on the base factorisation; ``μᵀf`` and ``G_bbᵀλ_b``."""
        sig, h, m = self.sig, self.h, len(self.edges)
        lam_n, rhs_b = [], np.empty((len(sig), m))
        for k, e in enumerate(self.edges):
            b = e.border
            h_n = b.right - b.left
            psi_n = -0.5 * h_n * b.w_new
            if self.dissipative:
                cols, rows = b.cols, b.rows
                assert cols is not None and rows is not None
                psi_n = psi_n - 0.25 * (cols.T @ self.hsig - h_n * (rows @ sig))
                a_e = self.A_old[:, k] + cols @ b.s_new
                self.Psi[:, k] -= 0.25 * (h * a_e - (self.At_old[:, k]
                                                     + rows.T @ (h_n * b.s_new)))
            ln = lu_solve(b.schur, psi_n - b.Y.T @ self.psi_b, trans=1, check_finite=False)
            lam_n.append(ln)
            rhs_b[:, k] = self.psi_b - b.r.T @ ln
        lam = self.sens.adjoint(np.column_stack([rhs_b, self.Psi]))        # (N, 2M)
        self.lam_n = lam_n
        self.lam_b, mu = lam[:, :m], lam[:, m:]
        self.base, self.LG_b = pair(lambda: mu.T @ self.rhs,               # (M, D)
                                    lambda: self.G_bb.T @ self.lam_b)       # (K, M)

    def values(self) -> np.ndarray:
        """The derivatives (M, D) of every advance's ``δŨ/δX̃ + δL̃_P/δX̃``."""
        sens, sig, w, h = self.sens, self.sig, self.w, self.h
        # the part of the explicit term that does not depend on the advance
        explicit_base = 0.5 * (sens.width_vel.T @ (sig * w) + sens.w_vel.T @ (h * sig))
        out = np.empty((len(self.edges), sens.n_dirs))
        for k, e in enumerate(self.edges):
            b = e.border
            # its columns among all new nodes and its rows among all new collocation points
            nb_ = slice(self.node_bounds[k], self.node_bounds[k + 1])
            mb_ = slice(self.mid_bounds[k], self.mid_bounds[k + 1])
            h_n = b.right - b.left
            wv_n = sens.shape.slopes(e.mid)[:, None] * e.colloc_vel
            wv_n[:, -1] = 1.0
            explicit = (-0.5 * (sens.width_vel.T @ (b.s_old * w)
                                + e.width_vel.T @ (b.s_new * b.w_new)
                                + sens.w_vel.T @ (h * b.s_old) + wv_n.T @ (h_n * b.s_new))
                        + explicit_base)
            if self.dissipative:
                explicit = explicit - 0.25 * self._dissipative_terms(k, e, nb_, mb_)
            enlarged = self._enlarged(k, e, nb_, mb_, wv_n)
            total = (b.d_u + b.d_lp) / e.dx
            out[k] = (enlarged + self.base[k] + explicit) / e.dx - total * e.ddx / e.dx
        return out

    def _dissipative_terms(self, k: int, e: _Advance, nb_: slice, mb_: slice) -> np.ndarray:
        """``T1 + T2 - T3 - T4`` (D,) of advance ``k``: the explicit derivatives of ``δL̃_P``'s
        antisymmetric products ``(h̄σ̄)ᵀAₑσₑ - (hₑσₑ)ᵀAₑσ̄`` (the non-reciprocal part of the
        kernel) at fixed stresses."""
        sens, sig, h, hsig = self.sens, self.sig, self.h, self.hsig
        b = e.border
        cols, rows = b.cols, b.rows
        assert cols is not None and rows is not None
        h_n = b.right - b.left
        s_old, s_new, s_b, s_n = b.s_old, b.s_new, e.s_b, e.s_n
        e_bn, e_nb = self.E_bn[:, nb_], self.E_nb[mb_]
        a_e = self.A_old[:, k] + cols @ s_new
        # T1: ḣ on the base rows of (h̄σ̄)ᵀAₑσₑ
        t1 = sens.width_vel.T @ (sig * a_e)
        # T2: (h̄σ̄)ᵀ Ȧₑ σₑ (base rows, all nodes)
        e_s = self.ES_b[:, k] + e_bn @ s_n
        t2 = (sens.colloc_vel.T @ (hsig * e_s) - sens.node_vel.T @ (self.hsig_E_bb * s_b)
              - e.node_vel.T @ ((hsig @ e_bn) * s_n))
        # T3: ḣₑ in (hₑσₑ)ᵀAₑσ̄
        t3 = (sens.width_vel.T @ (s_old * self.a_sig)
              + e.width_vel.T @ (s_new * (rows @ sig)))
        # T4: (hₑσₑ)ᵀ Ȧₑ σ̄ (all rows, base nodes only: σ̄ vanishes on the new elements)
        hs_old, hs_new = h * s_old, h_n * s_new
        t4 = (sens.colloc_vel.T @ (hs_old * self.E_bb_sig)
              + e.colloc_vel.T @ (hs_new * self.E_nb_sig[mb_])
              - sens.node_vel.T @ ((self.hsE_old[:, k] + hs_new @ e_nb) * self.s_sig))
        return t1 + t2 - t3 - t4

    def _enlarged(self, k: int, e: _Advance, nb_: slice, mb_: slice,
                  wv_n: np.ndarray) -> np.ndarray:
        """``λₑᵀ(ẇₑ - Ḃₑσₑ)`` (D,) of advance ``k`` (``wv_n``: ``ẇ`` on its new elements)."""
        sens = self.sens
        s_b, s_n = e.s_b, e.s_n
        g_bn, g_nb, g_nn = self.G_bn[:, nb_], self.G_nb[mb_], self.G_nn[mb_, nb_]
        lb, ln = self.lam_b[:, k], self.lam_n[k]
        g_b = self.GS_b[:, k] + g_bn @ s_n
        g_n = g_nb @ s_b + g_nn @ s_n
        lg_b = self.LG_b[:, k] + ln @ g_nb
        lg_n = lb @ g_bn + ln @ g_nn
        b_e = (sens.colloc_vel.T @ (lb * g_b) + e.colloc_vel.T @ (ln * g_n)
               - sens.node_vel.T @ (lg_b * s_b) - e.node_vel.T @ (lg_n * s_n))
        return sens.w_vel.T @ lb + wv_n.T @ ln - b_e
