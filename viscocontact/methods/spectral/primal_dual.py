r"""The primal-dual active set (a semismooth Newton method) on one grid of the spectral method,
for any operator: :func:`active_set`, its Newton systems solved by preconditioned GMRES on the
active cells (:func:`restricted_solve`), its steps controlled by :class:`_StepControl` and
damped by a line search (:func:`_line_search`)
(:mod:`~viscocontact.methods.spectral.solvers` has the overview and the references).
"""
from __future__ import annotations

import numpy as np

from ...deadline import check as check_deadline
from .grid_solution import GridSolution, circulant_diagonal, violation
from .krylov import gmres
from .operator import convolve

ACTIVE_SET = "active set"
#: Relative tolerance of the Krylov solves of the active-set method while the set still changes.
LOOSE_KRYLOV = 1e-2
#: Smallest fraction of an active-set step the line search tries, and the number of full steps
#: before the line search is switched on (three to six settle a set from a nearby start).
LINE_SEARCH_SMALLEST = 1.0 / 1024
UNDAMPED_STEPS = 10
#: Consecutive active-set steps without descent after which the solve stops ("no descent": the
#: step does not reduce |min(p, c g)| at LINE_SEARCH_SMALLEST of its length).
#: Converging solves have isolated ones, after which the set changes and the merit falls again
#: (at most two in a row on the grids that converged in the campaign's 115 adhesionless scenes
#: of its first 300 seeds; stopping at the first broke seeds 4, 101 and 212); a stagnating solve
#: has them in a row (seed 186: every step from the 24th).
STALLED_STEPS = 3


class _StepControl:
    """How the active-set steps are solved and taken: the Krylov solves loose
    (:data:`LOOSE_KRYLOV`) while the set changes and tight once a full step kept it, tighter
    when a tight solve falls short; the steps damped after :data:`UNDAMPED_STEPS` steps or on a
    cycle of sets (:func:`active_set`)."""

    def __init__(self, krylov_tolerance: float, damp: bool = True):
        self.loose = LOOSE_KRYLOV if LOOSE_KRYLOV > krylov_tolerance else None
        self.tight = krylov_tolerance
        self.damp = damp
        self.damped = False
        self.previous: np.ndarray | None = None
        self.full_step = False
        self.seen: set[bytes] = set()

    def _kept(self, active) -> bool:
        """Whether ``active`` is the set of the step before."""
        return self.previous is not None and np.array_equal(active, self.previous)

    def choose(self, active: np.ndarray, iteration: int) -> str | None:
        """The Krylov tolerance and damping of the step on ``active`` (step ``iteration``);
        without ``damp``, why the solve stops where the steps would be damped (else None)."""
        key = active.tobytes()
        if iteration > UNDAMPED_STEPS and not self.damped:     # slow to settle: damp the steps
            self.damped, self.loose = True, None
        if key in self.seen and not self._kept(active):
            if self.loose is not None:              # a cycle of inexact steps: tighten them
                self.loose = None
            else:                                   # a cycle of Newton steps: damp them
                self.damped = True
            self.seen.clear()
        self.seen.add(key)
        if self.loose is not None and self.full_step and self._kept(active):
            self.loose = None             # the last full step kept the set: it is found
        if self.damped and not self.damp:
            return (f"the set still changes after {UNDAMPED_STEPS} full steps"
                    if iteration > UNDAMPED_STEPS else "a cycle of active sets")
        return None

    def taken(self, active: np.ndarray, fraction: float, unresolved: bool) -> None:
        """Record the step on ``active`` taken by ``fraction`` (1: whole); ``unresolved``: the
        contact conditions are not met after it."""
        if (fraction == 1.0 and self.loose is None and self._kept(active) and unresolved
                and self.tight > 1e-15):
            self.tight = max(1e-3 * self.tight, 1e-15)  # the Krylov solve falls short: tighten
        self.previous, self.full_step = active, fraction == 1.0


def _merit(pressure, gap, stiffness: float) -> float:
    """``|min(p, c g)|²``, the merit of the active-set line search."""
    m = np.minimum(pressure, stiffness * gap)
    return float(m @ m)


def _line_search(p, g, step_p, step_g, stiffness: float, floor: float) -> float | None:
    """The fraction of an active-set step to take: halved from 1 until the merit falls
    (Armijo) or is below ``floor``, down to :data:`LINE_SEARCH_SMALLEST`; None when it does not
    fall at that fraction either (the step is no descent direction)."""
    s = 1.0
    before = _merit(p, g, stiffness)
    while s >= LINE_SEARCH_SMALLEST:
        after = _merit(p + s * step_p, g + s * step_g, stiffness)
        if after <= (1.0 - 1e-4 * s) * before or after <= floor:
            return s
        s *= 0.5
    return None


def _fraction(p, g, step_p, step_g, stiffness: float, floor: float, search: bool,
              stalled: int) -> tuple[float | None, int]:
    """The fraction of an active-set step to take (1 unless ``search``: the line search) and
    the count of steps in a row without descent (``stalled`` before this one); None once
    :data:`STALLED_STEPS` are (an isolated one is taken at :data:`LINE_SEARCH_SMALLEST`: a new
    set follows). A step whose Krylov solve fell short is searched too: taken whole, it can
    load most of the grid (a standard linear solid with β of 2000-5000 near ζβ ~ 3: GMRES(60)
    stagnated on 1844 active cells of 65536, and the next set had 61919)."""
    s = _line_search(p, g, step_p, step_g, stiffness, floor) if search else 1.0
    stalled = stalled + 1 if s is None else 0
    if s is None and stalled < STALLED_STEPS:
        s = LINE_SEARCH_SMALLEST
    return s, stalled


def _active_cells(p, g, heights, stiffness: float, first: bool,
                  singular_when_closed: bool) -> np.ndarray:
    """The active set of the next step: ``p - c g > 0`` (the first: the start's loaded cells,
    as a warm start gives a set, not a solution), never empty, and never every cell where the
    operator is then singular."""
    active = p > 0 if first else p - stiffness * g > 0
    if not active.any():
        active[int(np.argmax(heights))] = True
    if singular_when_closed and active.all():
        # A without its mean mode (c0 = 0) is singular on the whole grid, and under a given
        # penetration below closure some cell has a gap: keep the least loaded one out
        active[int(np.argmin(p - stiffness * g))] = False
    return active


def _update(solved, idx, p, g, delta, heights, load: bool):
    """The steps of ``(p, Δ̃, g)`` to the solution ``solved = ([p_C, (Δ̃)], info, A p)`` of the
    Newton system on the active cells ``idx`` (:func:`restricted_solve`)."""
    sol, _, product = solved
    target = np.zeros(p.size)
    target[idx] = sol[:idx.size]
    step_p = target - p
    step_d = float(sol[idx.size]) - delta if load else 0.0
    # A·target is GMRES's last product: the step of the gaps without another one
    step_g = product - (g + (heights - 1.0 + delta)) - step_d
    return step_p, step_d, step_g


def counted_products(spectrum, workers: int = 1):
    """``(apply, count)``: ``apply(v, spectrum=spectrum)`` the circulant product by FFT, and
    ``count`` the one-element list of the products taken."""
    count = [0]

    def apply(v, spectrum=spectrum):
        count[0] += 1
        return convolve(v, spectrum, workers)

    return apply, count


def active_start(apply, heights, start, mean_pressure, penetration, start_penetration):
    """The active set's starting pressure, penetration and gaps."""
    p = np.maximum(np.asarray(start, dtype=float), 0.0)
    if not p.any():
        p[int(np.argmax(heights))] = 1.0
    if mean_pressure is not None:
        p *= mean_pressure / p.mean()
    u = apply(p)
    if mean_pressure is None:
        delta = float(penetration)
    elif start_penetration is None:
        delta = 1.0 + float(np.mean((u - heights)[p > 0]))
    else:
        delta = float(start_penetration)
    return p, delta, u - (heights - 1.0 + delta)


def _clipped(apply, p, heights, delta, mean_pressure):
    """The pressure clipped at zero, with its gaps and residual; rescaled to ``mean_pressure``
    unless it is None (the load row to round-off, not to GMRES's)."""
    p = np.maximum(p, 0.0)
    if mean_pressure is not None:
        p *= mean_pressure / p.mean()
    g = apply(p) - (heights - 1.0 + delta)
    return p, g, violation(g, p > 0)


def _preconditioner(circulant):
    """The eigenvalues of the inverse circulant that precondition the Krylov solves.

    On a 2D grid the preconditioner runs in single precision (half the cost of its transforms):
    GMRES keeps the preconditioned directions (flexible GMRES), so its residual is that of the
    double-precision operator whatever the preconditioner's round-off (1e-7); the steps are
    those of the double-precision one.
    """
    inv = circulant.inverse
    return inv.astype(np.complex64) if np.ndim(inv) == 2 else inv


def active_set(circulant, heights, *, mean_pressure=None, penetration=None, start=None,
               start_penetration: float | None = None, tolerance: float = 1e-10,
               krylov_tolerance: float = 1e-10, max_iterations: int = 100, restart: int = 60,
               damp: bool = True, workers: int = 1) -> GridSolution:
    """Primal-dual active set (semismooth Newton) with preconditioned GMRES (any operator).

    Each step takes the active set ``C = {p - c g > 0}`` (``c = 1/A_kk``, the pressure a unit
    gap is worth) and solves the Newton system on it (:func:`restricted_solve`): the gap
    vanishes on ``C``, the pressure off it. The step to that solution is taken whole when it
    reduces the merit ``|min(p, c g)|²`` and halved until it does otherwise (Armijo): a full step
    is the plain primal-dual active-set update, which can cycle on a strongly non-symmetric
    operator (a large ``β`` at ``ζ`` of order one), the damped one does not. The Krylov solves
    are loose (:data:`LOOSE_KRYLOV` of their starting residual) while the set changes, tight
    on a set that a full step kept (the found set: its first solve is the tight one), to half
    the contact tolerance or ``krylov_tolerance``, whichever is looser. Converged when
    ``p >= 0`` and the contact conditions hold to ``tolerance``.

    Parameters
    ----------
    circulant : Circulant
        Its ``eigenvalues`` and ``inverse``.
    heights : ndarray
        ``r̃`` at the cell centres.
    mean_pressure, penetration : float
        Exactly one (load or penetration control).
    start : ndarray
        Starting pressure.
    start_penetration : float, optional
        Starting ``Δ̃`` in load control (default: from the gaps of ``start``).
    tolerance : float
        Largest violation of the contact conditions (units of the amplitude).
    krylov_tolerance : float
        Relative tolerance of the tight GMRES solves.
    damp : bool
        Whether steps are damped where full ones do not settle the set; without, the solve
        stops there, not converged (:func:`~.solvers.grid_solve` then takes the
        Fischer-Burmeister method, which converges globally).
    """
    lam = circulant.eigenvalues
    inv = _preconditioner(circulant)
    r = np.asarray(heights, dtype=float)
    load = mean_pressure is not None
    apply, apps = counted_products(lam, workers)
    stiffness = 1.0 / circulant_diagonal(lam.real)     # pressure that a unit gap is worth
    singular_when_closed = not load and lam.flat[0] == 0
    p, delta, g = active_start(apply, r, start, mean_pressure, penetration, start_penetration)
    control, stalled = _StepControl(krylov_tolerance, damp), 0  # (steps in a row without descent)
    floor = (0.1 * tolerance * stiffness) ** 2      # a merit the tolerance does not resolve
    for it in range(1, max_iterations + 1):
        check_deadline()                  # the cooperative time limit (viscocontact.deadline)
        active = _active_cells(p, g, r, stiffness, it == 1, singular_when_closed)
        undamped = control.choose(active, it)
        if undamped is not None:
            return _stopped(apply, p, r, delta, it - 1, apps[0], undamped)
        idx = np.flatnonzero(active)
        solved = restricted_solve(apply, inv, r, idx, p, delta, mean_pressure, r.size,
                                  control.loose, (control.tight, 0.5 * tolerance), restart)
        step_p, step_d, step_g = _update(solved, idx, p, g, delta, r, load)
        s, stalled = _fraction(p, g, step_p, step_g, stiffness, floor,
                               control.damped or solved[1] != 0, stalled)
        if s is None:
            return _stopped(apply, p, r, delta, it, apps[0],
                            f"no descent after {it} active-set steps")
        p, g = p + s * step_p, g + s * step_g
        delta += s * step_d
        res = violation(g, p > 0)
        control.taken(active, s, res > tolerance)
        if control.loose is None and solved[1] == 0 and res <= tolerance and \
                np.min(p) >= -tolerance * stiffness:
            p, g, res = _clipped(apply, p, r, delta, mean_pressure)
            if res <= 2.0 * tolerance:
                how = ", damped" if control.damped else ""
                return GridSolution(pressure=p, penetration=delta, converged=True, residual=res,
                                    iterations=it, applications=apps[0], solver=ACTIVE_SET,
                                    message=f"converged in {it} active-set steps{how}")
    return _stopped(apply, p, r, delta, max_iterations, apps[0],
                    f"no convergence in {max_iterations} active-set steps")


def _stopped(apply, p, heights, delta, iterations: int, applications: int,
             message: str) -> GridSolution:
    """The active set stopped, not converged, at ``p`` (clipped at zero) with ``message``."""
    p, _, res = _clipped(apply, p, heights, delta, None)
    return GridSolution(pressure=p, penetration=delta, converged=False, residual=res,
                        iterations=iterations, applications=applications, solver=ACTIVE_SET,
                        message=message)


def restricted_solve(apply, inverse, heights, idx, p, delta, mean_pressure, n, loose, tight,
                     restart):
    """GMRES on the active set ``idx``: ``A_CC p_C - Δ̃ 1 = r̃_C - 1`` with ``mean(p) = p̃∞``
    (load control), or ``A_CC p_C = r̃_C - 1 + Δ̃``; returns ``([p_C, (Δ̃)], info, A p)`` with
    ``A p`` the product of the solution on the whole grid (GMRES's last). ``tight`` is
    ``(relative, absolute)``: the solve stops at the larger of ``loose`` times the start's
    residual and the smaller of ``relative·|rhs|`` and ``absolute`` (half the contact
    tolerance: the residual's entries are the gaps on ``C``), never below ``1e-15·|rhs|``."""
    nc = idx.size
    load = mean_pressure is not None
    full = np.zeros(n)
    last = [np.zeros(n)]

    def restrict(v, spectrum=None):
        full[:] = 0.0
        full[idx] = v
        if spectrum is not None:
            return apply(full, spectrum)[idx]
        last[0] = apply(full)
        return last[0][idx]

    if load:
        ones_pre = restrict(np.ones(nc), inverse)       # M 1, for the load row
        mean_ones = float(ones_pre.mean())
        target = mean_pressure * n / nc                 # mean over C of p_C

        def matvec(v):
            out = np.empty(nc + 1)
            out[:nc] = restrict(v[:nc]) - v[nc]
            out[nc] = v[:nc].mean()
            return out

        def precondition(v):
            y = restrict(v[:nc], inverse)
            d = (v[nc] - y.mean()) / mean_ones
            return np.append(y + d * ones_pre, d)

        rhs = np.append(heights[idx] - 1.0, target)
        x0 = np.append(p[idx], delta)
    else:
        def matvec(v):
            return restrict(v)

        def precondition(v):
            return restrict(v, inverse)

        rhs = heights[idx] - 1.0 + delta
        x0 = p[idx]
    # ``loose``: relative to the residual of the start (an inexact Newton step), never tighter
    # than the tight bound
    size = float(np.linalg.norm(rhs))
    atol = max(min(tight[0] * size, tight[1]), 1e-15 * size)
    if loose is not None:
        atol = max(atol, loose * float(np.linalg.norm(rhs - matvec(x0))))
    sol, converged, _ = gmres(matvec, precondition, rhs, x0, atol, restart=restart)
    return sol, 0 if converged else 1, last[0]
