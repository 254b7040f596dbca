r"""Newton's step of all the cohesive tips of a 1D grid together.

The tips of :mod:`~.tips` move one by one, each by the secant of its own residual ``g - η``.
Where two tips are coupled strongly - the two tips of a zone narrower than a cell, or two zones
that face each other across a neck - a move of one changes the other's residual as much as its
own, and the secants creep: an approach on a rough profile can run out of its inner solves
(:data:`~.cohesive.MAX_SETS`) before they settle.

With the contact set held, the gap is linear in the cohesive shares ``w`` of the cells, and a
tip ``x_j`` moves the share of the cell that holds it (``+1`` per cell for a zone's last tip,
``-1`` for its first). So the tips' Jacobian is

    ∂r_i/∂x_j = g'(x_i) δ_ij ± G(x_i, m_j),

``g'`` the slope of the linear interpolant the residual is read from and ``G(·, m)`` the gap's
response to a unit share of cell ``m``: ``-σ̃0 A e_m`` plus the displacement of the contact
pressures that keep the contact cells' gaps at zero (``A_CC δq = σ̃0 (A e_m)_C``; under load
control the penetration moves too and ``Σ δq = σ̃0``). The responses are computed per contact
set: by a dense factorisation of ``A_CC`` for up to :data:`DENSE` contact cells, else by GMRES
per cell (:func:`~.primal_dual.restricted_solve`).

The step is Newton's where it is meaningful, else None (the tips move by their own secants):
where the tips' motion ``ds/dt = -r`` (``s`` the outward coordinate of each tip) is stable at
the linearisation - every eigenvalue of the outward Jacobian with a positive real part: a zone
that grows under its own stress has no stable root nearby, and Newton's step would head for
the unstable one - and where no tip moves further than a cell, within which the interpolated
residual and the shares are linear (a longer step crosses kinks the Jacobian does not see).
"""
from __future__ import annotations

import numpy as np
import scipy.linalg

from .operator import convolve
from .primal_dual import restricted_solve

#: Largest contact set whose restricted operator is factorised densely (above it, GMRES per
#: cell; the two give the same responses to the Krylov tolerance).
DENSE = 400
#: Relative residual of the GMRES solves of the responses (a Jacobian for Newton's step).
RESPONSE_TOLERANCE = 1e-8


class TipResponses:
    """The gap's response to a unit cohesive share of one cell of a 1D grid, with the contact
    set held, kept while the contact set stays (module docstring).

    Parameters
    ----------
    circulant : Circulant
    strength : float
        ``σ̃0``.
    load : bool
        Load control (the penetration moves with the responses).
    workers : int
    """

    def __init__(self, circulant, strength: float, load: bool, workers: int = 1):
        self.circulant, self.strength, self.load, self.workers = (circulant, float(strength),
                                                                  bool(load), workers)
        n = circulant.points
        unit = np.zeros(n)
        unit[0] = 1.0
        self.column0 = convolve(unit, circulant.eigenvalues, workers)   # A_ij = column0[i - j]
        self.key: bytes | None = None
        self.columns: dict[int, np.ndarray | None] = {}
        self.factors = None

    def _apply(self, v, spectrum=None):
        return convolve(v, self.circulant.eigenvalues if spectrum is None else spectrum,
                        self.workers)

    def column(self, contact: np.ndarray, m: int) -> np.ndarray | None:
        """``G(·, m)`` at every cell centre for the contact set ``contact`` (None where its
        restricted system cannot be solved)."""
        key = np.asarray(contact, bool).tobytes()
        if key != self.key:
            self.key, self.columns, self.factors = key, {}, None
        if m not in self.columns:
            self.columns[m] = self._response(np.flatnonzero(contact), m)
        return self.columns[m]

    def _response(self, C: np.ndarray, m: int) -> np.ndarray | None:
        n = self.circulant.points
        load_column = np.roll(self.column0, m)                  # A e_m
        out = -self.strength * load_column
        if not C.size:
            return out
        rhs = self.strength * load_column[C]
        sol = self._dense(C, rhs) if C.size <= DENSE else self._krylov(C, rhs)
        if sol is None or not np.all(np.isfinite(sol)):
            return None
        q = np.zeros(n)
        q[C] = sol[:C.size]
        return out + self._apply(q) - (sol[C.size] if self.load else 0.0)

    def _dense(self, C, rhs):
        k = C.size
        if self.factors is None:
            matrix = self.column0[(C[:, None] - C[None, :]) % self.circulant.points]
            if self.load:          # [A_CC, -1; 1ᵀ, 0] [δq; δΔ] = [σ̃0 (A e_m)_C; σ̃0]
                matrix = np.block([[matrix, -np.ones((k, 1))], [np.ones((1, k)), np.zeros((1, 1))]])
            try:
                self.factors = scipy.linalg.lu_factor(matrix, check_finite=False)
            except (np.linalg.LinAlgError, ValueError):
                self.factors = False         # this contact set's system has no factorisation
        if self.factors is False:
            return None
        b = np.append(rhs, self.strength) if self.load else rhs
        return scipy.linalg.lu_solve(self.factors, b, check_finite=False)

    def _krylov(self, C, rhs):
        n = self.circulant.points
        heights = np.ones(n)           # the restricted solve's right side is heights_C - 1
        heights[C] += rhs
        sol, failed, _ = restricted_solve(
            self._apply, self.circulant.inverse, heights, C, np.zeros(n), 0.0,
            self.strength / n if self.load else None, n, None, (RESPONSE_TOLERANCE, np.inf),
            60)
        return None if failed else sol


def newton_tips(extents, residuals, gap, contact, responses: TipResponses):
    """The run extents after Newton's step of every tip of a 1D grid row together, or None
    where the step is not taken (module docstring). ``extents`` are the row's runs ``[L, R]``
    (cell coordinates), ``residuals`` their tips' ``g - η`` and ``gap`` the gaps at the cell
    centres, all of the same inner solve, whose contact cells are ``contact``."""
    g = np.asarray(gap, dtype=float)
    n = g.size
    x = np.array([v for run in extents for v in run], dtype=float)
    r = np.array([v for pair in residuals for v in pair], dtype=float)
    outward = np.tile([-1.0, 1.0], len(extents))
    cells = np.floor(x + 0.5).astype(int) % n
    columns = {}
    for m in np.unique(cells):
        column = responses.column(contact, int(m))
        if column is None:
            return None
        columns[int(m)] = column
    left = np.floor(x).astype(int)
    t = x - left
    J = np.diag(g[(left + 1) % n] - g[left % n])
    for j in range(x.size):
        column = columns[int(cells[j])] * outward[j]
        J[:, j] += (1.0 - t) * column[left % n] + t * column[(left + 1) % n]
    if np.any(np.linalg.eigvals(J * outward[None, :]).real <= 0.0):
        return None
    try:
        step = -np.linalg.solve(J, r)
    except np.linalg.LinAlgError:
        return None
    if not np.all(np.isfinite(step)) or np.max(np.abs(step)) > 1.0:
        return None
    y = x + step
    moved = []
    for lo, hi in zip(y[0::2], y[1::2]):
        if lo > hi:                        # the zone vanishes there (the next runs say so)
            lo = hi = 0.5 * (lo + hi)
        moved.append((float(lo), float(hi)))
    return moved
