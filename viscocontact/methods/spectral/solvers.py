r"""The two grid solvers of the spectral method: Polonsky-Keer and a primal-dual active set.

Both solve the discrete contact problem on one grid: pressures ``p_k >= 0``, gaps
``g_k = (A p)_k - (r̃_k - 1 + Δ̃) >= 0`` and ``p_k g_k = 0``, under load control (``mean(p) = p̃∞``
given, the penetration ``Δ̃`` a multiplier) or penetration control (``Δ̃`` given). ``A`` is the
circulant of :mod:`~viscocontact.methods.spectral.operator`.

* :func:`polonsky_keer` — the constrained conjugate gradients of Polonsky & Keer (1999) on the
  complementary energy ``½ pᵀAp - pᵀ(r̃ - 1 + Δ̃)``, in load control with the gradient projected to
  zero mean over the loaded cells and the load restored after every step, in penetration control
  without either. ``A`` must be symmetric (an elastic kernel, or ζ at a limit). The search
  directions are preconditioned by the inverse circulant on the loaded cells (Vollebregt 2014):
  from the previous grid's solution 15-25 steps instead of 100-200 (8192 cells, the thesis's
  rough profile), restarted whenever the loaded set changes.
* :func:`active_set` — primal-dual active set (a semismooth Newton method, Hintermüller, Ito &
  Kunisch 2002): on the active set ``C`` the gap vanishes, off it the pressure does. Each step
  solves ``A_CC p_C = r̃_C - 1 + Δ̃`` (with the load row ``mean(p) = p̃∞`` in load control) by
  GMRES (:mod:`~viscocontact.methods.spectral.krylov`) on FFT products, right-preconditioned by
  the inverse circulant restricted to ``C`` (Vollebregt 2014), the load row eliminated in the
  preconditioner through ``M 1``; loosely while the set changes, tightly once it does not
  (inexact Newton). After :data:`UNDAMPED_STEPS` steps, or a cycle of sets, the steps are
  damped by a line search on ``|min(p, c g)|²``: the plain update cycles on strongly
  non-symmetric operators. Any ``A``: the viscoelastic operator is not symmetric.

Both stop on the largest violation of the contact conditions, ``max(max_C |g|, max_{∉C} -g)``,
in units of the profile amplitude (the heights are normalised to 1), with ``p >= 0``.

Limits. ``A`` has a positive definite symmetric part for every rheology (``Re K > 0``), so the
discrete problem has one solution; the active-set method finds it on the thesis's scenes
(β = 10) and on every scene tried with ``tan δ`` up to 2.5 (an SLS with β <= 30), but a
standard linear solid with β = 50-100 at ζ of order one (``|Im Λ|/Re Λ`` near 5) failed in 1
of 18 and 4 of 18 rough scenes (``benchmarks/spectral.py``, the reason in the result's message).

References
----------
Polonsky, I. A. & Keer, L. M. (1999). A numerical method for solving rough contact problems
based on the multi-level multi-summation and conjugate gradient techniques. Wear 231, 206-219.
doi:10.1016/S0043-1648(99)00113-1

Hintermüller, M., Ito, K. & Kunisch, K. (2002). The primal-dual active set strategy as a
semismooth Newton method. SIAM J. Optim. 13, 865-888. doi:10.1137/S1052623401383558

Vollebregt, E. A. H. (2014). A new solver for the elastic normal contact problem using conjugate
gradients, deflation, and an FFT-based preconditioner. J. Comput. Phys. 257, 333-351.
doi:10.1016/j.jcp.2013.10.005
"""
from __future__ import annotations

import attrs
import numpy as np

from ...deadline import check as check_deadline
from .krylov import gmres
from .operator import convolve, invert

POLONSKY_KEER = "Polonsky-Keer"
#: Relative tolerance of the Krylov solves of the active-set method while the set still changes.
LOOSE_KRYLOV = 1e-2
#: Smallest fraction of an active-set step the line search tries, and the number of full steps
#: before the line search is switched on (three to six settle a set from a nearby start).
LINE_SEARCH_SMALLEST = 1.0 / 1024
UNDAMPED_STEPS = 10
#: Tolerance of the Polonsky-Keer solve for the operator's symmetric part that starts an active
#: set from far (:func:`grid_solve`).
PRESOLVE = 1e-6
#: A search direction ``t`` with ``tᵀAt <= FLAT·|t|²·max|Λ|`` has no stiffness.
FLAT = 1e-12
ACTIVE_SET = "active set"


@attrs.frozen(kw_only=True, eq=False)
class GridSolution:
    """The outcome of one grid solve.

    Attributes
    ----------
    pressure : ndarray
        Cell pressures ``p_k >= 0``.
    penetration : float
        ``Δ̃`` (given, or the load multiplier).
    converged : bool
    residual : float
        Largest violation of the contact conditions (units of the profile amplitude).
    iterations : int
        Conjugate-gradient steps, or active-set updates.
    applications : int
        Products with ``A`` or its inverse (one FFT pair each).
    solver : str
        :data:`POLONSKY_KEER` or :data:`ACTIVE_SET`.
    message : str
    """

    pressure: np.ndarray
    penetration: float
    converged: bool
    residual: float
    iterations: int
    applications: int
    solver: str
    message: str


def violation(gap: np.ndarray, loaded: np.ndarray) -> float:
    """``max(max_C |g|, max_{∉C} -g, 0)``: the largest violation of the contact conditions."""
    inside = np.max(np.abs(gap[loaded]), initial=0.0)
    outside = -np.min(gap[~loaded], initial=0.0)
    return float(max(inside, outside, 0.0))


def circulant_diagonal(spectrum) -> float:
    """The diagonal entry of a real symmetric circulant from its rfft (or rfft2) eigenvalues
    (their mean over all modes; the last axis holds the half spectrum)."""
    v = np.asarray(spectrum).real
    n = 2 * (v.shape[-1] - 1) * int(np.prod(v.shape[:-1]))
    return float((v[..., 0].sum() + 2.0 * v[..., 1:-1].sum() + v[..., -1].sum()) / n)


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
        self.loaded = self.gradient = None

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


class _StepControl:
    """How the active-set steps are solved and taken: the Krylov solves loose
    (:data:`LOOSE_KRYLOV`) while the set changes and tight once a full step kept it, tighter
    when a tight solve falls short; the steps damped after :data:`UNDAMPED_STEPS` steps or on a
    cycle of sets (:func:`active_set`)."""

    def __init__(self, krylov_tolerance: float):
        self.loose = LOOSE_KRYLOV if LOOSE_KRYLOV > krylov_tolerance else None
        self.tight = krylov_tolerance
        self.damped = False
        self.previous: np.ndarray | None = None
        self.full_step = False
        self.seen: set[bytes] = set()

    def _kept(self, active) -> bool:
        """Whether ``active`` is the set of the step before."""
        return self.previous is not None and np.array_equal(active, self.previous)

    def choose(self, active: np.ndarray, iteration: int) -> None:
        """The Krylov tolerance and damping of the step on ``active`` (step ``iteration``)."""
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


def _line_search(p, g, step_p, step_g, stiffness: float, floor: float) -> float:
    """The fraction of an active-set step to take: halved from 1 until the merit falls
    (Armijo), down to :data:`LINE_SEARCH_SMALLEST`, or until it is below ``floor``."""
    s = 1.0
    before = _merit(p, g, stiffness)
    while s > LINE_SEARCH_SMALLEST:
        after = _merit(p + s * step_p, g + s * step_g, stiffness)
        if after <= (1.0 - 1e-4 * s) * before or after <= floor:
            break
        s *= 0.5
    return s


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
    Newton system on the active cells ``idx`` (:func:`_restricted_solve`)."""
    sol, _, product = solved
    target = np.zeros(p.size)
    target[idx] = sol[:idx.size]
    step_p = target - p
    step_d = float(sol[idx.size]) - delta if load else 0.0
    # A·target is GMRES's last product: the step of the gaps without another one
    step_g = product - (g + (heights - 1.0 + delta)) - step_d
    return step_p, step_d, step_g


def _active_start(apply, heights, start, mean_pressure, penetration, start_penetration):
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


def active_set(circulant, heights, *, mean_pressure=None, penetration=None, start=None,
               start_penetration: float | None = None, tolerance: float = 1e-10,
               krylov_tolerance: float = 1e-10, max_iterations: int = 100, restart: int = 60,
               workers: int = 1) -> GridSolution:
    """Primal-dual active set (semismooth Newton) with preconditioned GMRES (any operator).

    Each step takes the active set ``C = {p - c g > 0}`` (``c = 1/A_kk``, the pressure a unit
    gap is worth) and solves the Newton system on it (:func:`_restricted_solve`): the gap
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
    """
    lam = circulant.eigenvalues
    inv = circulant.inverse
    if np.ndim(inv) == 2:
        # on a 2D grid the preconditioner runs in single precision (half the cost of its
        # transforms): GMRES keeps the preconditioned directions (flexible GMRES), so its
        # residual is that of the double-precision operator whatever the preconditioner's
        # round-off (1e-7); the steps are those of the double-precision one
        inv = inv.astype(np.complex64)
    r = np.asarray(heights, dtype=float)
    load = mean_pressure is not None
    apps = [0]

    def apply(v, spectrum=lam):
        apps[0] += 1
        return convolve(v, spectrum, workers)

    stiffness = 1.0 / circulant_diagonal(lam.real)     # pressure that a unit gap is worth
    singular_when_closed = not load and lam.flat[0] == 0
    p, delta, g = _active_start(apply, r, start, mean_pressure, penetration, start_penetration)
    control = _StepControl(krylov_tolerance)
    floor = (0.1 * tolerance * stiffness) ** 2      # a merit the tolerance does not resolve
    for it in range(1, max_iterations + 1):
        check_deadline()                  # the cooperative time limit (viscocontact.deadline)
        active = _active_cells(p, g, r, stiffness, it == 1, singular_when_closed)
        control.choose(active, it)
        idx = np.flatnonzero(active)
        solved = _restricted_solve(apply, inv, r, idx, p, delta, mean_pressure, r.size,
                                   control.loose, (control.tight, 0.5 * tolerance), restart)
        step_p, step_d, step_g = _update(solved, idx, p, g, delta, r, load)
        s = _line_search(p, g, step_p, step_g, stiffness, floor) if control.damped else 1.0
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
    p, g, res = _clipped(apply, p, r, delta, None)
    return GridSolution(pressure=p, penetration=delta, converged=False, residual=res,
                        iterations=max_iterations, applications=apps[0], solver=ACTIVE_SET,
                        message=f"no convergence in {max_iterations} active-set steps")


def grid_solve(circulant, heights, *, mean_pressure=None, penetration=None, start=None,
               start_penetration: float | None = None, presolve: bool = False,
               tolerance: float = 1e-10, krylov_tolerance: float = 1e-10,
               max_updates: int = 100, max_iterations: int = 20000,
               workers: int = 1) -> GridSolution:
    """One grid's contact problem with the solver its operator needs: :func:`polonsky_keer` when
    it is symmetric, else :func:`active_set`, started with ``presolve`` from the solution for the
    operator's symmetric part (to :data:`PRESOLVE`, itself from ``start``): from a start far
    from the solution (none, or another problem's) the active set needs damped steps by the
    dozen. The counts add up over both solves."""
    common = dict(mean_pressure=mean_pressure, penetration=penetration, tolerance=tolerance,
                  workers=workers)
    if circulant.symmetric:
        return polonsky_keer(circulant.eigenvalues, heights, start=start,
                             max_iterations=max_iterations, preconditioner=circulant.inverse,
                             **common)
    its = apps = 0
    if presolve:
        sym = circulant.symmetric_part()
        first = polonsky_keer(sym, heights, start=start, max_iterations=max_iterations,
                              preconditioner=invert(sym),
                              **dict(common, tolerance=PRESOLVE))
        start, start_penetration = first.pressure, first.penetration
        its, apps = first.iterations, first.applications
    sol = active_set(circulant, heights, start=start, start_penetration=start_penetration,
                     krylov_tolerance=krylov_tolerance, max_iterations=max_updates, **common)
    return attrs.evolve(sol, iterations=sol.iterations + its,
                        applications=sol.applications + apps)


def _restricted_solve(apply, inverse, heights, idx, p, delta, mean_pressure, n, loose, tight,
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
