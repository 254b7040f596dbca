r"""The grid solvers of the spectral method: Polonsky-Keer, a primal-dual active set and a
Fischer-Burmeister Newton method.

All solve the discrete contact problem on one grid: pressures ``p_k >= 0``, gaps
``g_k = (A p)_k - (r̃_k - 1 + Δ̃) >= 0`` and ``p_k g_k = 0``, under load control (``mean(p) = p̃∞``
given, the penetration ``Δ̃`` a multiplier) or penetration control (``Δ̃`` given). ``A`` is the
circulant of :mod:`~viscocontact.methods.spectral.operator`.

* :func:`polonsky_keer` (:mod:`~viscocontact.methods.spectral.conjugate_gradients`) — the
  constrained conjugate gradients of Polonsky & Keer (1999) on the complementary energy
  ``½ pᵀAp - pᵀ(r̃ - 1 + Δ̃)``, in load control with the gradient projected to zero mean over the
  loaded cells and the load restored after every step, in penetration control without either.
  ``A`` must be symmetric (an elastic kernel, or ζ at a limit). The search directions are
  preconditioned by the inverse circulant on the loaded cells (Vollebregt 2014): from the
  previous grid's solution 15-25 steps instead of 100-200 (8192 cells, the thesis's rough
  profile), restarted whenever the loaded set changes.
* :func:`active_set` (:mod:`~viscocontact.methods.spectral.primal_dual`) — primal-dual active
  set (a semismooth Newton method, Hintermüller, Ito & Kunisch 2002): on the active set ``C``
  the gap vanishes, off it the pressure does. Each step solves ``A_CC p_C = r̃_C - 1 + Δ̃`` (with
  the load row ``mean(p) = p̃∞`` in load control) by GMRES
  (:mod:`~viscocontact.methods.spectral.krylov`) on FFT products, right-preconditioned by the
  inverse circulant restricted to ``C`` (Vollebregt 2014), the load row eliminated in the
  preconditioner through ``M 1``; loosely while the set changes, tightly once it does not
  (inexact Newton). After :data:`UNDAMPED_STEPS` steps, or a cycle of sets, the steps are
  damped by a line search on ``|min(p, c g)|²`` (``damp``; without, the solve stops there):
  the plain update cycles on strongly non-symmetric operators (a step whose Krylov solve fell
  short is searched at once); after :data:`~.primal_dual.STALLED_STEPS` steps in a row that
  are no descent direction the solve stops, not converged. Any ``A``: the viscoelastic
  operator is not symmetric.
* :func:`fischer_burmeister` (:mod:`~viscocontact.methods.spectral.fischer_burmeister`) — a
  semismooth Newton method on the Fischer-Burmeister function, with a line search on its
  smooth merit: globally convergent for every rheology (the operator's symmetric part is
  positive semidefinite), each step a Newton system on the cells that are not plainly free,
  and a contact set kept over a step solved exactly (the active set's system on it).
* :func:`grid_solve` — the one a grid's operator needs: Polonsky-Keer for a symmetric
  operator; else the active set's full steps, and where they do not settle the set, the
  Fischer-Burmeister method from the same start, then the damped active set from the contact
  set that found.

All stop on the largest violation of the contact conditions, ``max(max_C |g|, max_{∉C} -g)``,
in units of the profile amplitude (the heights are normalised to 1), with ``p >= 0``.

Limits. ``A`` has a positive definite symmetric part for every rheology (``Re K > 0``), so the
discrete problem has one solution; the active-set method finds it on the thesis's scenes
(β = 10) and on every scene tried with ``tan δ`` up to 2.5 (an SLS with β <= 30). Past that
(β = 1e3-1e4 at ζ of order one, ``|Im Λ|/Re Λ`` up to 40 on the grid) its Newton steps cycle,
and its damped steps made so little descent that 7 and 12 of 24 rough scenes failed at β = 1e3
and 1e4 (``benchmarks/spectral.py --betas``), and a sinusoid's cohesive solve spent 63 of its
76 s in damped steps that did not converge. With the Fischer-Burmeister method taking over
from the full steps, all 24 converge at both β (slowest 28 s), and that sinusoid takes 7 s.

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

from .conjugate_gradients import FLAT, POLONSKY_KEER, polonsky_keer
from .fischer_burmeister import FISCHER_BURMEISTER, fischer_burmeister
from .grid_solution import GridSolution, circulant_diagonal, violation
from .operator import invert
from .primal_dual import (ACTIVE_SET, LINE_SEARCH_SMALLEST, LOOSE_KRYLOV, UNDAMPED_STEPS,
                          active_set)

__all__ = ["GridSolution", "violation", "circulant_diagonal", "polonsky_keer", "active_set",
           "fischer_burmeister", "grid_solve", "POLONSKY_KEER", "ACTIVE_SET", "FISCHER_BURMEISTER",
           "FLAT", "LOOSE_KRYLOV", "LINE_SEARCH_SMALLEST", "UNDAMPED_STEPS", "PRESOLVE"]

#: Tolerance of the Polonsky-Keer solve for the operator's symmetric part that starts an active
#: set from far (:func:`grid_solve`).
PRESOLVE = 1e-6
#: Most steps of the Fischer-Burmeister method after a failed active set (:func:`grid_solve`):
#: 8-21 (once 64) on the thesis's rough profile with β = 1e3-1e4 where it converges, about 100
#: creeping ones on a thin free layer's 8192- and 16384-cell grids (campaign seed 226, 8 and
#: 18 s), where the ladder's last converged grid is the answer instead, with its estimate.
FISCHER_BURMEISTER_STEPS = 40


def grid_solve(circulant, heights, *, mean_pressure=None, penetration=None, start=None,
               start_penetration: float | None = None, presolve: bool = False,
               tolerance: float = 1e-10, krylov_tolerance: float = 1e-10,
               max_updates: int = 100, max_iterations: int = 20000,
               workers: int = 1) -> GridSolution:
    """One grid's contact problem with the solver its operator needs: :func:`polonsky_keer` when
    it is symmetric, else :func:`active_set`, started with ``presolve`` from the solution for the
    operator's symmetric part (to :data:`PRESOLVE`, itself from ``start``): from a start far
    from the solution (none, or another problem's) its full steps rarely settle the set. Where
    they do not, :func:`fischer_burmeister` from the same start (at most
    :data:`FISCHER_BURMEISTER_STEPS` steps), then the damped active set from the contact set
    that found. The counts add up over every solve."""
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
    common.update(start_penetration=start_penetration)
    sol = active_set(circulant, heights, start=start, krylov_tolerance=krylov_tolerance,
                     max_iterations=max_updates, damp=False, **common)
    its, apps = its + sol.iterations, apps + sol.applications
    if not sol.converged:
        # full steps that do not settle the set cycle on a strongly non-symmetric operator,
        # where damped ones make little descent: the globally convergent Newton method on the
        # Fischer-Burmeister function from the same start, and where its merit stalls at the
        # round-off of a degenerate edge cell, the damped active set from the contact set it
        # found
        fb = fischer_burmeister(circulant, heights, start=start,
                                max_iterations=min(max_updates, FISCHER_BURMEISTER_STEPS),
                                **common)
        its, apps = its + fb.iterations, apps + fb.applications
        why = f"after the active set: {sol.message}"
        if fb.converged:
            return attrs.evolve(fb, message=f"{fb.message} ({why})", iterations=its,
                                applications=apps)
        last = active_set(circulant, heights, start=fb.pressure,
                          krylov_tolerance=krylov_tolerance, max_iterations=max_updates,
                          **dict(common, start_penetration=fb.penetration))
        its, apps = its + last.iterations, apps + last.applications
        found = f"from the Fischer-Burmeister method's contact set ({fb.message})"
        sol = (attrs.evolve(last, message=f"{last.message} {found}, {why}") if last.converged
               else attrs.evolve(sol, message=f"{sol.message}; {last.message} {found}"))
    return attrs.evolve(sol, iterations=its, applications=apps)
