r"""Polonsky-Keer constrained conjugate gradients on one grid of the spectral method (a symmetric
operator): :func:`polonsky_keer`, its state and steps in :class:`_ConstrainedGradients`.

The complementary energy ``½ pᵀAp - pᵀ(r̃ - 1 + Δ̃)`` is minimised over ``p >= 0``, in load
control with the gradient projected to zero mean over the loaded cells and the load restored
after every step, in penetration control without either; the search directions preconditioned
by the inverse circulant on the loaded cells (Vollebregt 2014) when it is given
(:mod:`~viscocontact.methods.spectral.solvers` has the overview and the references).
"""
from __future__ import annotations

import numpy as np

from ...deadline import check as check_deadline
from .grid_solution import GridSolution, circulant_diagonal, violation
from .operator import convolve

POLONSKY_KEER = "Polonsky-Keer"
#: A search direction ``t`` with ``tᵀAt <= FLAT·|t|²·max|Λ|`` has no stiffness.
FLAT = 1e-12


class _ConstrainedGradients:
    """The state of the Polonsky-Keer iteration on one grid: the pressure, the last search
    direction and the counts (:func:`polonsky_keer` runs it).

    :meth:`measure` evaluates the gradient of the complementary energy at the pressure and the
    violation of the contact conditions, :meth:`stop` says whether the iteration ends there,
    and :meth:`step` moves the pressure along the next conjugate direction.
    """

    def __init__(self, eigenvalues, heights, *, mean_pressure, penetration, start,
                 preconditioner, tolerance: float, max_iterations: int, workers: int):
        self.lam = np.asarray(eigenvalues).real.astype(complex)
        self.pre = (None if preconditioner is None
                    else np.asarray(preconditioner).real.astype(complex))
        # with a preconditioner (steps τ ~ 1), a cell that starts to carry load takes the
        # pressure that would close its gap alone: -τ g/A_kk
        self.diagonal = 1.0 if self.pre is None else 1.0 / circulant_diagonal(self.lam)
        r = np.asarray(heights, dtype=float)
        self.mean_pressure, self.penetration = mean_pressure, penetration
        self.load = mean_pressure is not None
        self.w = r - 1.0 if self.load else r - 1.0 + float(penetration)
        if start is None:
            p = np.full(r.size, float(mean_pressure)) if self.load else np.maximum(self.w, 0.0)
        else:
            p = np.maximum(np.asarray(start, dtype=float), 0.0)
        if not p.any():
            p[int(np.argmax(self.w))] = 1.0
        if self.load:
            p *= mean_pressure / p.mean()
        self.p = p
        self.t = np.zeros_like(p)
        self.scale = float(np.max(np.abs(self.lam)))
        self.g_old, self.conjugate, self.shift, self.residual = 1.0, 0.0, 0.0, np.inf
        self.applications = 0
        self.tolerance, self.max_iterations, self.workers = tolerance, max_iterations, workers
        self.loaded: np.ndarray = np.zeros(p.size, dtype=bool)   # (set by :meth:`measure`)
        self.gradient: np.ndarray = np.zeros(p.size)

    def measure(self) -> None:
        """The loaded cells, the gradient (the gaps, shifted by the load multiplier in load
        control) and the residual at the current pressure."""
        self.loaded = s = self.p > 0
        g = convolve(self.p, self.lam, self.workers) - self.w
        self.applications += 1
        if self.load:
            self.shift = float(np.mean(g[s]))
            g -= self.shift
        self.gradient = g
        self.residual = violation(g, s)

    def stop(self, iteration: int) -> str | None:
        """Why the iteration ends after ``iteration`` steps (None: it goes on)."""
        if self.residual <= self.tolerance:
            return f"converged in {iteration} iterations"
        if iteration == self.max_iterations:
            return f"no convergence in {self.max_iterations} iterations"
        return None

    def _direction(self) -> np.ndarray:
        """The next conjugate search direction on the loaded cells (the preconditioned
        gradient when a preconditioner is given); its gradient product becomes ``g_old``."""
        s, g = self.loaded, self.gradient
        if self.pre is None:
            z = g
        else:
            z = convolve(np.where(s, g, 0.0), self.pre, self.workers)
            self.applications += 1
            if self.load:
                z -= np.mean(z[s])
        big_g = float(g[s] @ z[s])
        beta = self.conjugate * big_g / self.g_old if self.g_old > 0.0 else 0.0
        self.t = np.where(s, z + beta * self.t, 0.0)
        self.g_old = big_g
        return self.t

    def step(self) -> bool:
        """One step along the next search direction (False: no search direction is left)."""
        s, g = self.loaded, self.gradient
        gs = g[s]
        t = self._direction()
        q = convolve(t, self.lam, self.workers)
        self.applications += 1
        if self.load:
            q -= np.mean(q[s])
        denom = float(q[s] @ t[s])
        slope = float(gs @ t[s])
        if (not denom > FLAT * float(t[s] @ t[s]) * self.scale and slope > 0.0
                and np.any(t[s] > 0)):
            # a direction without stiffness (the mean mode of an incompressible solid, with
            # every cell loaded under a given penetration): the energy falls linearly along
            # it, so go to the first cell it unloads
            move = s & (t > 0)
            self.p = np.maximum(self.p - float(np.min(self.p[move] / t[move])) * t, 0.0)
            self.conjugate = 0.0
            return True
        if not denom > 0.0:
            return self._load_overlaps()
        tau = float(gs @ t[s]) / denom
        p = np.maximum(self.p - tau * t, 0.0)
        overlap = (p == 0.0) & (g < 0.0)
        if overlap.any():
            p[overlap] -= tau * self.diagonal * g[overlap]
        # a new loaded set restarts the conjugate directions: always when cells start to carry
        # load (Polonsky-Keer), and with a preconditioner also when cells stop carrying it
        changed = overlap.any() or (self.pre is not None and bool(np.any(s & (p == 0.0))))
        self.conjugate = 0.0 if changed else 1.0
        if self.load:
            p *= self.mean_pressure / p.mean()
        self.p = p
        return True

    def _load_overlaps(self) -> bool:
        """No descent within the loaded cells (none left, or a single one under load control):
        load the interpenetrating cells by their own stiffness and restart (False: there are
        none)."""
        outside = ~self.loaded & (self.gradient < 0.0)
        if not outside.any():
            return False
        self.p[outside] = -self.gradient[outside] / circulant_diagonal(self.lam)
        if self.load:
            self.p *= self.mean_pressure / self.p.mean()
        self.conjugate = 0.0
        return True

    def solution(self, iterations: int, message: str) -> GridSolution:
        """The grid solution at the current pressure."""
        delta = self.shift if self.load else float(self.penetration)
        return GridSolution(pressure=self.p, penetration=delta,
                            converged=self.residual <= self.tolerance, residual=self.residual,
                            iterations=iterations, applications=self.applications,
                            solver=POLONSKY_KEER, message=message)


def polonsky_keer(eigenvalues, heights, *, mean_pressure=None, penetration=None, start=None,
                  tolerance: float = 1e-10, max_iterations: int = 5000, preconditioner=None,
                  workers: int = 1) -> GridSolution:
    """Polonsky-Keer constrained conjugate gradients (symmetric operator).

    Parameters
    ----------
    eigenvalues : ndarray
        ``Λ_n`` of a symmetric circulant (imaginary parts are ignored).
    heights : ndarray
        ``r̃`` at the cell centres.
    mean_pressure, penetration : float
        Exactly one: ``p̃∞ > 0`` (load control) or ``Δ̃`` (penetration control).
    start : ndarray, optional
        Starting pressure (clipped at zero; rescaled to the load in load control). Default: the
        uniform load, or the positive part of the interference in penetration control.
    tolerance : float
        Largest violation of the contact conditions to stop at (units of the amplitude).
    preconditioner : ndarray, optional
        Eigenvalues of a symmetric positive definite circulant ``M ≈ A⁻¹`` (the inverse
        circulant): the search directions are built from ``M g`` restricted to the loaded cells
        (Vollebregt 2014) instead of the gradient ``g``.
    """
    state = _ConstrainedGradients(eigenvalues, heights, mean_pressure=mean_pressure,
                                  penetration=penetration, start=start,
                                  preconditioner=preconditioner, tolerance=tolerance,
                                  max_iterations=max_iterations, workers=workers)
    it = 0
    message = f"no convergence in {max_iterations} iterations"
    for it in range(max_iterations + 1):
        check_deadline()                  # the cooperative time limit (viscocontact.deadline)
        state.measure()
        stopped = state.stop(it)
        if stopped is not None:
            message = stopped
            break
        if not state.step():
            message = f"search direction lost after {it} iterations"
            break
    return state.solution(it, message)
