r"""Uniform-grid FFT contact solvers: the peer the BEM of viscocontact is benchmarked against.

A rigid periodic profile slides on a (visco)elastic half-plane, in the dimensionless groups of
thesis eq. 4.17 exactly as :class:`viscocontact.problem.ContactProblem` uses them: one period
``x̃ ∈ [0, 2π)``, heights ``r̃ = r/Λ`` (max 1), stresses ``σ̃`` tensile positive, displacement
positive into the solid, so the pressure ``p̃ = -σ̃`` and the mean pressure
``p̃∞ = -(1/2π)∫σ̃ dx̃``.

Discretisation
--------------
``N`` uniform cells of width ``h = 2π/N`` centred at ``x_k = x_peak + k h`` carry a constant
pressure ``p_k >= 0``; the contact condition is collocated at the cell centres. The displacement
is ``u = A p`` with ``A`` circulant, applied by FFT. Its eigenvalues follow from the Fourier
multiplier of the prepared kernel (``û_m = -(S_m K(m)/m) σ̂_m`` for ``m >= 1``, its conjugate for
``m <= -1``, ``û_0 = 2π c0 σ̂_0``) summed over all aliases of the piecewise-constant pressure:

.. math:: Λ_n = \sum_{l\in\mathbb Z} λ(n + lN)\, \mathrm{sinc}\big((n + lN) h/2\big),
          \qquad λ(m) = \frac{S_{|m|} K(m)}{|m|}\ (m>0),\quad \overline{λ(-m)}\ (m<0).

The instantaneous part ``K∞/|m|`` (with the branches relaxed at this ζ) is summed in closed form
(Clausen function: the exact influence of a cell on the log kernel); the rest decays at least as
fast and is summed over ``|l| <= 32`` aliases with the last two partial sums averaged
(alternating tail; 32 aliases differ from 256 by 2e-7 relative at most, on the highest modes as
ζ → 0), and skipped when ``S_m K(m) = K∞`` (elastic half-plane). A viscoelastic kernel makes
``A`` non-symmetric (complex ``Λ``): the pressure leans towards the leading edge.

Solvers (both in load control, ``mean(p) = p̃∞`` fixed, the penetration ``Δ̃`` a multiplier)
-----------------------------------------------------------------------------------------------
* :func:`solve_pk` — constrained conjugate gradients of Polonsky & Keer (1999, Wear 231:206) on the
  complementary energy ``½ pᵀAp - pᵀr̃``; needs ``A`` symmetric (elastic, or ζ at a limit).
* :func:`solve_pdas` — primal-dual active set (semismooth Newton, Hintermüller-Ito-Kunisch 2002):
  on the active set ``C = {p - c g > 0}`` the gap vanishes, off it the pressure does; the bordered
  system ``[A_CC, -1; 1ᵀ/N, 0][p_C; Δ̃] = [r̃_C - 1; p̃∞]`` is solved by restarted GMRES with
  a :class:`scipy.sparse.linalg.LinearOperator` made of FFTs, preconditioned by the inverse
  circulant restricted to the active set; warm-started from PK on the symmetric part of ``A``.
  Stops when ``C`` no longer changes.

:func:`solve` picks PK for a symmetric operator and PDAS otherwise (or the one asked for), and
starts a fine grid from the solution on a grid four times coarser. Outputs, in viscocontact's
conventions: contact area ``Ã`` (count of loaded cells × h, and a sub-cell estimate that places
each edge where ``p²``, linear near a square-root edge, extrapolates to zero), ``p̃∞``, ``Δ̃``
(measured from the mean plane of the deformed solid, like the BEM) and the friction coefficient
``μ = (1/(2π p̃∞)) Σ_k σ̃_k [q0 r(b_k) - q0 r(a_k)]`` (dissipated power over V·load, positive when
it opposes sliding; viscocontact.contact.fields.friction).
"""
from __future__ import annotations

import time

import attrs
import numpy as np
from scipy.sparse.linalg import LinearOperator, gmres

from viscocontact.contact.fields import NormalizedProfile
from viscocontact.kernels.clausen import cl2
from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.rheology import Elastic

TWO_PI = 2.0 * np.pi
ALIASES = 32
SYMMETRIC = 1e-12      # |Im Λ| / max|Λ| below this: the operator is taken as symmetric


@attrs.frozen(kw_only=True)
class PeerResult:
    """Outcome of a uniform-grid solve (same keys for both methods).

    Attributes
    ----------
    converged : bool
    method : str
        ``"pk"`` or ``"pdas"``.
    iterations : int
        Outer iterations (CG steps, or active-set updates).
    inner_iterations : int
        GMRES iterations summed over the active-set steps (0 for PK).
    area : float
        Sub-cell estimate of ``Ã`` (sum of the contact lengths per period, in [0, 2π]).
    area_count : float
        Number of loaded cells × ``2π/N``.
    mean_pressure, penetration, friction : float
        ``p̃∞``, ``Δ̃``, ``μ``.
    n_contacts : int
        Number of separate contact patches.
    residual : float
        Largest violation of the contact conditions relative to the profile amplitude.
    seconds : float
        Wall time of the solve (operator set-up included).
    message : str
    """

    converged: bool
    method: str
    iterations: int
    inner_iterations: int
    area: float
    area_count: float
    mean_pressure: float
    penetration: float
    friction: float
    n_contacts: int
    residual: float
    seconds: float
    message: str
    points: int
    pressure: np.ndarray = attrs.field(repr=False, eq=False)


@attrs.frozen(kw_only=True, eq=False)
class Grid:
    """The uniform grid and circulant operator of one profile, kernel, rheology and ζ.

    Build with :meth:`build`; ``apply(p)`` is ``u = A p``.
    """

    points: int
    x: np.ndarray             # cell centres
    heights: np.ndarray       # r̃ at the centres
    shape: NormalizedProfile
    eigenvalues: np.ndarray   # Λ_n, n = 0..N/2 (rfft layout)

    @classmethod
    def build(cls, profile, points: int, *, rheology=None, zeta: float = 0.0,
              kernel=None) -> "Grid":
        """Grid of ``points`` cells (even, >= 16) for the given components."""
        if int(points) != points or points < 16 or points % 2:
            raise ValueError(f"points = {points!r} is not allowed: expected an even integer >= 16")
        points = int(points)
        kernel = kernel or HalfPlane()
        prepared = kernel.prepare(rheology or Elastic(), zeta)
        shape = NormalizedProfile.of(profile)
        x = shape.peak_position + TWO_PI * np.arange(points) / points
        return cls(points=points, x=x, heights=shape.heights(x), shape=shape,
                   eigenvalues=eigenvalues(prepared, points))

    @property
    def cell(self) -> float:
        return TWO_PI / self.points

    @property
    def symmetric(self) -> bool:
        lam = self.eigenvalues
        return bool(np.max(np.abs(lam.imag)) <= SYMMETRIC * np.max(np.abs(lam)))

    def apply(self, p, eigenvalues=None):
        """``u = A p`` (displacement at the centres, positive into the solid)."""
        lam = self.eigenvalues if eigenvalues is None else eigenvalues
        return np.fft.irfft(lam * np.fft.rfft(p), self.points)


def eigenvalues(prepared, points: int, aliases: int = ALIASES) -> np.ndarray:
    """Eigenvalues ``Λ_n`` (``n = 0..N/2``) of the circulant cell-to-centre operator ``A``."""
    n_cells = points
    h = TWO_PI / n_cells
    # the part in closed form: K∞ plus the branches relaxed at this ζ (ζ_i < 1e-12)
    k_inf = float(prepared.instantaneous)
    # closed form of the K∞ part: A_j0 = (K∞/π)[Cl2(x_j + h/2) - Cl2(x_j - h/2)], x_j = j h
    xj = h * np.arange(n_cells)
    column = (k_inf / np.pi) * (cl2(xj + 0.5 * h) - cl2(xj - 0.5 * h))
    lam = np.fft.rfft(column).astype(complex)
    n = np.arange(n_cells // 2 + 1, dtype=float)

    def remainder(m):
        """(λ(m) - K∞/|m|) sinc(m h/2) for integer m != 0 (array)."""
        am = np.abs(m)
        rest = prepared.multiplier(am) - k_inf
        rest = np.where(m > 0, rest, np.conj(rest))
        arg = 0.5 * m * h
        return rest / am * np.sin(arg) / arg

    probe = np.array([1.0, 10.0, 1e3, 1e6])
    if np.all(prepared.multiplier(probe) == k_inf):
        lam[0] = -TWO_PI * float(prepared.mean)
        lam[-1] = lam[-1].real
        return lam
    total = np.zeros(n.shape, complex)
    total[1:] += remainder(n[1:])
    previous = total.copy()
    for l in range(1, aliases + 1):
        previous = total.copy()
        total += remainder(n + l * n_cells) + remainder(n - l * n_cells)
    lam += 0.5 * (total + previous)            # average of the last two partial sums
    lam[0] = -TWO_PI * float(prepared.mean)    # û_0 = 2π c0 σ̂_0 = -2π c0 p̂_0
    lam[-1] = lam[-1].real                     # Nyquist mode of a real circulant
    return lam


# ---- the two solvers ----------------------------------------------------------------------
def _check_load(mean_pressure):
    if not (np.isfinite(mean_pressure) and mean_pressure > 0):
        raise ValueError(f"mean_pressure = {mean_pressure!r} is not allowed: expected a real > 0")


def solve_pk(grid: Grid, mean_pressure: float, *, tol: float = 1e-10, max_iterations: int = 5000,
             eigenvalues=None, initial=None, started=None) -> PeerResult:
    """Polonsky-Keer constrained CG in load control (symmetric ``A`` only).

    Parameters
    ----------
    grid : Grid
    mean_pressure : float
        ``p̃∞ > 0``.
    tol : float
        Stop when ``mean|p_new - p_old| / p̃∞ <= tol``.
    eigenvalues : array, optional
        Use these (e.g. the symmetric part ``Re Λ``) instead of ``grid.eigenvalues``.
    """
    started = time.perf_counter() if started is None else started
    _check_load(mean_pressure)
    lam = grid.eigenvalues if eigenvalues is None else eigenvalues
    if np.max(np.abs(lam.imag)) > SYMMETRIC * np.max(np.abs(lam)):
        raise ValueError("solve_pk needs a symmetric operator (elastic kernel); use solve_pdas")
    lam = lam.real.astype(complex)
    r = grid.heights
    if initial is None:
        p = np.full(grid.points, float(mean_pressure))
    else:
        p = np.maximum(np.asarray(initial, float), 0.0)
        p *= mean_pressure / p.mean()
    t = np.zeros_like(p)
    g_old, delta, err, it = 1.0, 0.0, np.inf, 0
    for it in range(1, max_iterations + 1):
        s = p > 0
        g = grid.apply(p, lam) - r
        g -= g[s].mean()
        big_g = float(g[s] @ g[s])
        t = np.where(s, g + delta * (big_g / g_old) * t, 0.0)
        g_old = big_g
        q = grid.apply(t, lam)
        q -= q[s].mean()
        denom = float(q[s] @ t[s])
        if denom == 0.0:
            err = 0.0
            break
        tau = float(g[s] @ t[s]) / denom
        p_old = p
        p = np.maximum(p - tau * t, 0.0)
        overlap = (p == 0) & (g < 0)
        if overlap.any():
            delta = 0.0
            p[overlap] -= tau * g[overlap]
        else:
            delta = 1.0
        p *= mean_pressure / p.mean()
        err = float(np.mean(np.abs(p - p_old)) / mean_pressure)
        if err <= tol:
            break
    converged = err <= tol
    return _result(grid, p, "pk", converged, it, 0, started,
                   f"PK {'converged' if converged else 'stopped'} after {it} iterations "
                   f"(change {err:.2e})", lam)


def solve_pdas(grid: Grid, mean_pressure: float, *, tol: float = 1e-10,
               max_iterations: int = 200, restart: int = 60, initial=None,
               precondition: bool = True, started=None) -> PeerResult:
    """Primal-dual active set with GMRES inner solves, in load control (any ``A``).

    Parameters
    ----------
    grid : Grid
    mean_pressure : float
        ``p̃∞ > 0``.
    tol : float
        GMRES relative tolerance of each active-set system.
    max_iterations : int
        Largest number of active-set updates.
    initial : array, optional
        Starting pressure; default PK on the symmetric part ``Re Λ`` (tolerance 1e-6).
    precondition : bool
        Precondition GMRES with the inverse circulant ``A⁻¹`` (eigenvalues ``1/Λ_n``, the mean
        mode left alone) restricted to the active set, the FFT preconditioner of Vollebregt
        (2014, J. Optim. Theory Appl. 162:977) for the elastic CG.
    """
    started = time.perf_counter() if started is None else started
    _check_load(mean_pressure)
    n = grid.points
    r = grid.heights
    if initial is None:
        initial = solve_pk(grid, mean_pressure, tol=1e-6,
                           eigenvalues=grid.eigenvalues.real.astype(complex)).pressure
    p = np.asarray(initial, float).copy()
    delta = 1.0 + float(np.mean((grid.apply(p) - r)[p > 0])) if np.any(p > 0) else 0.0
    active = p > 0
    inner = 0
    lam = grid.eigenvalues
    inverse = np.where(np.abs(lam) > 0, 1.0 / np.where(lam == 0, 1.0, lam), 1.0)
    seen = set()
    for it in range(1, max_iterations + 1):
        idx = np.flatnonzero(active)
        nc = idx.size
        scale = n / nc          # balances the load row against the gap rows

        def matvec(v, idx=idx, nc=nc, scale=scale):
            full = np.zeros(n)
            full[idx] = v[:nc]
            out = np.empty(nc + 1)
            out[:nc] = grid.apply(full)[idx] - v[nc]
            out[nc] = scale * v[:nc].sum() / n
            return out

        op = LinearOperator((nc + 1, nc + 1), matvec=matvec, dtype=float)
        precond = None
        if precondition:
            def apply_inverse(v, idx=idx, nc=nc):
                full = np.zeros(n)
                full[idx] = v[:nc]
                out = v.copy()
                out[:nc] = grid.apply(full, inverse)[idx]
                return out

            precond = LinearOperator((nc + 1, nc + 1), matvec=apply_inverse, dtype=float)
        rhs = np.append(r[idx] - 1.0, scale * mean_pressure)
        x0 = np.append(p[idx], delta)
        count = [0]
        sol, info = gmres(op, rhs, x0=x0, M=precond, rtol=tol, atol=0.0, restart=restart,
                          maxiter=max(20, 4 * nc // restart + 20),
                          callback=lambda _: count.__setitem__(0, count[0] + 1),
                          callback_type="pr_norm")
        inner += count[0]
        p = np.zeros(n)
        p[idx] = sol[:nc]
        delta = float(sol[nc])
        g = grid.apply(p) - (r - 1.0 + delta)
        new = np.where(active, p > 0, g < 0)
        if np.array_equal(new, active) and info == 0:
            return _result(grid, p, "pdas", True, it, inner, started,
                           f"active set fixed after {it} updates ({inner} GMRES iterations)",
                           grid.eigenvalues, delta)
        key = new.tobytes()
        if key in seen:                       # a cycle: accept only half of the changes
            flip = np.flatnonzero(new != active)
            new = active.copy()
            new[flip[::2]] = ~active[flip[::2]]
        seen.add(key)
        if not new.any():
            new = r >= np.max(r) - 1e-12
        active = new
    p = np.maximum(p, 0.0)
    return _result(grid, p, "pdas", False, max_iterations, inner, started,
                   f"active set still changing after {max_iterations} updates",
                   grid.eigenvalues, delta)


def solve(profile, mean_pressure: float, points: int, *, rheology=None, zeta: float = 0.0,
          kernel=None, tol: float = 1e-10, nested: bool = True,
          method: str = "auto") -> PeerResult:
    """The peer for the operator: ``method="auto"`` takes PK when ``A`` is symmetric and
    PDAS + GMRES otherwise; ``"pk"`` or ``"pdas"`` force one (PDAS also solves the symmetric
    case, and with the nested start it is the faster of the two on fine grids).

    With ``nested`` a grid of more than 2048 cells starts from the solution on a grid four
    times coarser (recursively), so that the active set only has to move at the edges. The wall
    time includes building the operators and the coarse solves.
    """
    if method not in ("auto", "pk", "pdas"):
        raise ValueError(f"method = {method!r} is not allowed: expected one of "
                         "['auto', 'pk', 'pdas']")
    started = time.perf_counter()
    initial = None
    if nested and points > 2048 and points % 8 == 0:
        coarse = solve(profile, mean_pressure, points // 4, rheology=rheology, zeta=zeta,
                       kernel=kernel, tol=max(tol, 1e-8), nested=True, method=method)
        # fine cell k sits nearest coarse cell round(k/4): cells 4j-2 .. 4j+1 take coarse j
        initial = np.roll(np.repeat(coarse.pressure, 4), -2)
    grid = Grid.build(profile, points, rheology=rheology, zeta=zeta, kernel=kernel)
    if method == "pk" or (method == "auto" and grid.symmetric):
        return solve_pk(grid, mean_pressure, tol=tol, started=started, initial=initial)
    return solve_pdas(grid, mean_pressure, tol=tol, started=started, initial=initial)


# ---- derived quantities -------------------------------------------------------------------
def contact_runs(loaded: np.ndarray) -> list[tuple[int, int]]:
    """Maximal cyclic runs ``(first, length)`` of True cells."""
    n = loaded.size
    if loaded.all():
        return [(0, n)]
    if not loaded.any():
        return []
    start = int(np.flatnonzero(~loaded)[0]) + 1     # begin just after a gap: no run wraps
    rolled = np.roll(loaded, -start)
    edges = np.diff(np.concatenate([[0], rolled.astype(int), [0]]))
    firsts = np.flatnonzero(edges == 1)
    lasts = np.flatnonzero(edges == -1)
    return [((f + start) % n, int(e - f)) for f, e in zip(firsts, lasts)]


def subcell_area(p: np.ndarray, h: float) -> float:
    """Contact length with each edge where ``p²`` of the two outermost cells extrapolates to 0.

    Each edge moves by at most one cell beyond the centre of the outermost loaded cell; a run of
    one or two cells keeps its count length.
    """
    n = p.size
    total = 0.0
    for first, length in contact_runs(p > 0):
        if length == n:
            return TWO_PI
        if length < 3:
            total += length * h
            continue
        span = (length - 1) * h                   # centre of first to centre of last cell
        for end, inner in ((first, first + 1), (first + length - 1, first + length - 2)):
            a, b = p[end % n] ** 2, p[inner % n] ** 2
            reach = h * a / (b - a) if b > a else h
            span += min(max(reach, 0.0), h)
        total += span
    return min(total, TWO_PI)


def _result(grid, p, method, converged, iterations, inner, started, message, lam, delta=None):
    h = grid.cell
    r = grid.heights
    loaded = p > 0
    u = grid.apply(p, lam)
    if delta is None:
        delta = 1.0 + float(np.mean((u - r)[loaded])) if loaded.any() else 0.0
    gap = u - (r - 1.0 + delta)
    residual = max(float(np.max(np.abs(gap[loaded]), initial=0.0)),
                   float(-np.min(gap[~loaded], initial=0.0)))
    pm = float(p.mean())
    heights = grid.shape.profile.heights
    rise = heights(grid.x + 0.5 * h) - heights(grid.x - 0.5 * h)
    mu = float(-(p @ rise) / (TWO_PI * pm)) if pm > 0 else float("nan")
    return PeerResult(converged=bool(converged), method=method, iterations=int(iterations),
                      inner_iterations=int(inner), area=subcell_area(p, h),
                      area_count=float(loaded.sum() * h), mean_pressure=pm,
                      penetration=float(delta), friction=mu,
                      n_contacts=len(contact_runs(loaded)), residual=residual,
                      seconds=time.perf_counter() - started, message=message,
                      points=grid.points, pressure=p)
