r"""A globally convergent semismooth Newton method on one grid of the spectral method: the
Fischer-Burmeister reformulation of the contact conditions, for the operators on which the
primal-dual active set cycles.

The contact conditions ``p >= 0``, ``g >= 0``, ``p g = 0`` (``g = A p - (r̃ - 1 + Δ̃)``) hold
exactly where ``φ(p, c g) = 0`` cell by cell, with

.. math:: φ(a, b) = \sqrt{a^2 + b^2} - a - b

and ``c = 1/A_kk`` the pressure a unit gap is worth (De Luca, Facchinei & Kanzow 1996). Unlike
the ``min(p, c g)`` of the active set, ``Ψ = ½|φ|²`` is continuously differentiable, and the
operator's symmetric part is positive semidefinite for every rheology (``Re Λ >= 0``: a
monotone problem), so every stationary point of ``Ψ`` is a solution: Newton steps on ``φ = 0``
with an Armijo line search on ``Ψ`` (and a gradient step where the Newton step is no descent)
converge from any start. Each step solves

.. math:: D_a\,δp + D_b\,c\,(A\,δp - δΔ̃) = -φ

(``D_a``, ``D_b`` the diagonal partial derivatives of ``φ``; in load control with the row
``mean(δp) = 0``, the load being met from the start) by GMRES on FFT products, preconditioned
by ``1/D_a`` on the cells where ``|D_a| > |D_b|`` (free cells) and by the inverse circulant
restricted to the others (contact cells), as the active set's Newton systems are; a free cell
without pressure (``p = 0 < g``) has a zero step and leaves the system. Once a step keeps the
contact set ``p > c g``, that set is solved exactly (the active set's Newton system on it,
:func:`~.primal_dual.restricted_solve`): the Newton iteration on ``φ`` would still have to
drive the free cells' pressures to zero and restore the load. It is slower than the active set
where that converges (about twice on the thesis's β = 10 scenes), so the grid solve uses it
where the active set's full steps do not settle the set (:func:`~.solvers.grid_solve`): a
standard linear solid with β = 1e3-1e4 at ζ of order one, where ``|Im Λ|/Re Λ`` reaches 10-40
on the grid.

References
----------
De Luca, T., Facchinei, F. & Kanzow, C. (1996). A semismooth equation approach to the solution
of nonlinear complementarity problems. Math. Program. 75, 407-439. doi:10.1007/BF02592192
"""
from __future__ import annotations

from typing import Literal

import numpy as np

from ...deadline import check as check_deadline
from .grid_solution import GridSolution, circulant_diagonal, violation
from .krylov import gmres
from .primal_dual import active_start, counted_products, restricted_solve

FISCHER_BURMEISTER = "Fischer-Burmeister Newton"
#: Armijo's sufficient decrease of ``Ψ`` (a fraction of the decrease the linear model predicts).
ARMIJO = 1e-4
#: Shortest fraction of a step the line search tries before it takes the gradient step.
SHORTEST = 2.0**-30


def fischer_burmeister(circulant, heights, *, mean_pressure=None, penetration=None,
                       start=None, start_penetration: float | None = None,
                       tolerance: float = 1e-10, max_iterations: int = 200, restart: int = 60,
                       workers: int = 1) -> GridSolution:
    """Semismooth Newton on the Fischer-Burmeister function (see the module docstring).

    The arguments are those of :func:`~.primal_dual.active_set`. Converged when, with the cells
    where ``p > c g`` in contact and the others free (their pressure set to 0), the contact
    conditions hold to ``tolerance`` and the pressure is non-negative to ``tolerance·c``.
    """
    lam = np.asarray(circulant.eigenvalues)
    r = np.asarray(heights, dtype=float)
    load = mean_pressure is not None
    apply, count = counted_products(lam, workers)
    c = 1.0 / circulant_diagonal(lam.real)
    p, delta, g = active_start(apply, r, np.zeros(r.size) if start is None else np.ravel(start),
                               mean_pressure, penetration, start_penetration)
    system = _System(apply, lam, circulant.inverse, c, load, restart)
    phi = _phi(p, c * g)
    first, stuck = float(np.linalg.norm(phi)), False
    found, failed = None, None
    for it in range(1, max_iterations + 1):
        check_deadline()
        contact = p > c * g
        # a contact set kept over a step is solved exactly: there the Newton iteration on φ
        # would still have to drive the free cells' pressures to zero and restore the load;
        # a set whose exact solution failed the contact conditions is not solved again (the
        # solution does not depend on the start; a Krylov solve that fell short does)
        kept = found is not None and np.array_equal(contact, found)
        retried = failed is not None and np.array_equal(contact, failed)
        done = (_finished(apply, circulant.inverse, p, r, delta, contact, tolerance,
                          mean_pressure, c, restart) if kept and not retried else None)
        if done is False:
            failed, done = contact, None
        found = contact
        if done is not None:
            q, delta, res = done
            return GridSolution(pressure=q, penetration=delta, converged=True, residual=res,
                                iterations=it - 1, applications=count[0],
                                solver=FISCHER_BURMEISTER,
                                message=f"converged in {it - 1} Fischer-Burmeister steps")
        size = float(np.linalg.norm(phi))
        forcing = min(1e-2, np.sqrt(size / max(first, 1e-300)))
        step = system.newton(p, g, phi, forcing)
        taken = _searched(apply, p, g, phi, delta, r, c, step)
        if taken is None:
            step = system.gradient(p, g, phi)
            taken = _searched(apply, p, g, phi, delta, r, c, step, newton=False)
        if taken is None:
            stuck = True
            break
        p, g, phi, delta = taken
    # the pressure on the cells it found in contact (``p > c g``), the others freed: the start
    # from which the active set's Newton steps finish on a set it has found
    q = np.where(p > c * g, np.maximum(p, 0.0), 0.0)
    return GridSolution(pressure=q, penetration=delta, converged=False,
                        residual=violation(g, p > c * g), iterations=it,
                        applications=count[0], solver=FISCHER_BURMEISTER,
                        message=f"no descent of the Fischer-Burmeister merit after {it} steps"
                        if stuck else
                        f"no convergence in {max_iterations} Fischer-Burmeister steps")


def _phi(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``√(a² + b²) - a - b`` cell by cell."""
    return np.hypot(a, b) - a - b


def _finished(apply, inverse, p, heights, delta, contact, tolerance, mean_pressure, c,
              restart) -> tuple | Literal[False] | None:
    """``(pressure, penetration, violation)`` on the contact set ``contact`` solved exactly (the
    active set's Newton system on it, :func:`~.primal_dual.restricted_solve`), when that meets
    the contact conditions to ``tolerance``; False when it does not, None when the Krylov solve
    fell short."""
    idx = np.flatnonzero(contact)
    if not idx.size:
        return None
    sol, info, _ = restricted_solve(apply, inverse, heights, idx, p, delta, mean_pressure,
                                    p.size, None, (1e-12, 0.5 * tolerance), restart)
    if info != 0:
        return None
    q = np.zeros(p.size)
    q[idx] = sol[:idx.size]
    if mean_pressure is not None:
        delta = float(sol[idx.size])
    if np.min(q) < -tolerance * c:
        return False
    q = np.maximum(q, 0.0)
    res = violation(apply(q) - (heights - 1.0 + delta), q > 0)
    return (q, delta, res) if res <= tolerance else False


def _searched(apply, p, g, phi, delta, heights, c, step, newton: bool = True):
    """Armijo's line search on ``Ψ = ½|φ|²`` along ``step = (δp, δΔ̃, A δp)``: the new
    ``(p, g, φ, Δ̃)``, or None when no fraction down to :data:`SHORTEST` decreases ``Ψ``
    enough. The decrease the linear model predicts is ``2Ψ`` per unit step for a Newton step
    and ``|∇Ψ|²`` for the gradient step."""
    dp, dd, adp = step
    merit = 0.5 * float(phi @ phi)
    slope = 2.0 * merit if newton else float(dp @ dp) + dd * dd
    s = 1.0
    while s >= SHORTEST:
        q = p + s * dp
        gq = g + s * (adp - dd)
        fq = _phi(q, c * gq)
        if 0.5 * float(fq @ fq) <= merit - ARMIJO * s * slope:
            return q, gq, fq, delta + s * dd
        s *= 0.5
    return None


class _System:
    """The Newton systems of one solve: ``D_a δp + D_b c (A δp - δΔ̃) = -φ`` by preconditioned
    GMRES, and the gradient of ``Ψ``."""

    def __init__(self, apply, eigenvalues, inverse, c: float, load: bool, restart: int):
        self.apply, self.eigenvalues, self.inverse, self.c = apply, eigenvalues, inverse, c
        self.load, self.restart = load, restart

    @staticmethod
    def derivatives(p, cg):
        """``(D_a, D_b)``: the partial derivatives of ``φ`` (at ``a = b = 0`` the element
        ``1/√2 - 1`` of the generalized Jacobian)."""
        norm = np.hypot(p, cg)
        zero = norm == 0.0
        safe = np.where(zero, 1.0, norm)
        edge = 1.0 / np.sqrt(2.0) - 1.0
        return (np.where(zero, edge, p / safe - 1.0), np.where(zero, edge, cg / safe - 1.0))

    def newton(self, p, g, phi, forcing: float):
        """The Newton step ``(δp, δΔ̃, A δp)`` to the relative residual ``forcing``.

        A free cell with no pressure (``p = 0 < g``: ``φ = 0``, ``D_a = -1``, ``D_b = 0``
        exactly) keeps it (``δp = 0``): GMRES runs on the other cells alone."""
        c, n, apply = self.c, p.size, self.apply
        da, db = self.derivatives(p, c * g)
        rows = np.flatnonzero(db != 0.0)          # the cells whose step is not zero
        m = rows.size
        da_r, scale = da[rows], c * db[rows]
        contact = np.abs(db[rows]) > np.abs(da_r)
        idx = np.flatnonzero(contact)             # within rows
        full = np.zeros(n)

        def spread(v, spectrum=None):
            full[:] = 0.0
            full[rows] = v
            return apply(full) if spectrum is None else apply(full, spectrum)

        def matvec(v):
            out = da_r * v[:m] + scale * spread(v[:m])[rows]
            if self.load:
                out -= scale * v[m]
                return np.append(out, v[:m].sum() / n)
            return out

        def restricted(v):
            full[:] = 0.0
            full[rows[idx]] = v
            return apply(full, self.inverse)[rows[idx]]

        ones = restricted(np.ones(idx.size)) if self.load and idx.size else None

        def precondition(v):
            y = np.where(contact, 0.0, v[:m] / np.where(contact, 1.0, da_r))
            if idx.size:
                y[idx] = restricted(v[idx] / scale[idx])
            if not self.load:
                return y
            if ones is None:
                return np.append(y, 0.0)
            d = (n * v[m] - y.sum()) / float(ones.sum())
            y[idx] += d * ones
            return np.append(y, d)

        rhs = np.append(-phi[rows], 0.0) if self.load else -phi[rows]
        size = float(np.linalg.norm(phi))
        atol = max(forcing * size, 1e-15 * size)
        sol, _, _ = gmres(matvec, precondition, rhs, np.zeros(rhs.size), atol,
                          restart=self.restart)
        dp = np.zeros(n)
        dp[rows] = sol[:m]
        return dp, float(sol[m]) if self.load else 0.0, apply(dp)

    def gradient(self, p, g, phi):
        """The steepest-descent step of ``Ψ``, ``(δp, δΔ̃, A δp)``: ``δp = -(D_a φ + c Aᵀ(D_b
        φ))`` and, in load control, its mean removed (the load is held) and ``δΔ̃ = c Σ D_b
        φ``."""
        da, db = self.derivatives(p, self.c * g)
        dp = -(da * phi + self.c * self.apply(db * phi, np.conj(self.eigenvalues)))
        dd = 0.0
        if self.load:
            dp -= dp.mean()
            dd = self.c * float(np.sum(db * phi))
        return dp, dd, self.apply(dp)


__all__ = ["fischer_burmeister", "FISCHER_BURMEISTER"]
