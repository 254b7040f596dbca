r"""Restarted GMRES with right preconditioning, for the active-set systems of the spectral method.

``A M y = b - A x0``, ``x = x0 + M y``: with the preconditioner on the right the Arnoldi residual
is the true residual ``|b - A x|``, which is what the tolerance is on. Orthogonalisation is
classical Gram-Schmidt, repeated when the first pass cancels most of the vector (Daniel et al.
1976; twice is as accurate as modified Gram-Schmidt, Giraud et al. 2005); the least-squares
problem is updated with Givens rotations. The operator and the preconditioner are plain
callables: each call is one product by FFT, the work that matters. The preconditioned
directions ``M v_j`` are kept and the solution is built from them (flexible GMRES, Saad 1993):
the preconditioner may vary from step to step (a single-precision one) without spoiling the
residual, which is that of ``A``.

References
----------
Saad, Y. & Schultz, M. H. (1986). GMRES: a generalized minimal residual algorithm for solving
nonsymmetric linear systems. SIAM J. Sci. Stat. Comput. 7, 856-869. doi:10.1137/0907058

Daniel, J. W., Gragg, W. B., Kaufman, L. & Stewart, G. W. (1976). Reorthogonalization and stable
algorithms for updating the Gram-Schmidt QR factorization. Math. Comp. 30, 772-795.
doi:10.1090/S0025-5718-1976-0431641-8

Saad, Y. (1993). A flexible inner-outer preconditioned GMRES algorithm. SIAM J. Sci. Comput.
14, 461-469. doi:10.1137/0914028

Giraud, L., Langou, J. & Rozložník, M. (2005). The loss of orthogonality in the Gram-Schmidt
orthogonalization process. Comput. Math. Appl. 50, 1069-1075. doi:10.1016/j.camwa.2005.08.009
"""
from __future__ import annotations

import math

import numpy as np

#: A Gram-Schmidt pass that leaves less than this share of the vector's norm lost orthogonality
#: to cancellation and is repeated (Daniel, Gragg, Kaufman & Stewart 1976: 1/√2).
REORTHOGONALISE = 1.0 / math.sqrt(2.0)


def gmres(matvec, precondition, rhs, x0, atol: float, max_iterations: int = 400,
          restart: int = 60):
    """Solve ``A x = rhs`` to ``|rhs - A x| <= atol``.

    Parameters
    ----------
    matvec, precondition : callable
        ``v -> A v`` and ``v -> M v`` (``M ≈ A⁻¹``).
    rhs, x0 : ndarray
        Right-hand side and start.
    atol : float
        Absolute tolerance on the residual norm.
    max_iterations, restart : int
        Largest number of Arnoldi steps in all, and per cycle.

    Returns
    -------
    x : ndarray
    converged : bool
    iterations : int
        Arnoldi steps taken (each one product with ``A`` and one with ``M``).
    """
    x = np.array(x0, dtype=float, copy=True)
    r = rhs - matvec(x)
    beta = float(np.linalg.norm(r))
    steps = 0
    size = rhs.size
    while beta > atol and steps < max_iterations:
        m = min(restart, max_iterations - steps, size)
        basis = np.empty((m + 1, size))
        directions = np.empty((m, size))
        hess = np.zeros((m + 1, m))
        cs = np.zeros(m)
        sn = np.zeros(m)
        g = np.zeros(m + 1)
        g[0] = beta
        basis[0] = r / beta
        k = 0
        for j in range(m):
            directions[j] = precondition(basis[j])
            w = matvec(directions[j])
            steps += 1
            before = float(np.linalg.norm(w))
            h = basis[:j + 1] @ w
            w -= h @ basis[:j + 1]
            norm_w = float(np.linalg.norm(w))
            if norm_w < REORTHOGONALISE * before:    # cancellation: a second pass
                h2 = basis[:j + 1] @ w
                w -= h2 @ basis[:j + 1]
                h += h2
                norm_w = float(np.linalg.norm(w))
            col = np.append(h, norm_w)
            for i in range(j):                       # the previous rotations on the new column
                a, b = col[i], col[i + 1]
                col[i], col[i + 1] = cs[i] * a + sn[i] * b, -sn[i] * a + cs[i] * b
            denom = math.hypot(col[j], col[j + 1])
            cs[j], sn[j] = (1.0, 0.0) if denom == 0.0 else (col[j] / denom, col[j + 1] / denom)
            col[j], col[j + 1] = denom, 0.0
            g[j + 1] = -sn[j] * g[j]
            g[j] = cs[j] * g[j]
            hess[:j + 2, j] = col
            k = j + 1
            if abs(g[j + 1]) <= atol or norm_w == 0.0:
                break
            basis[j + 1] = w / norm_w
        y = _back_substitute(hess[:k, :k], g[:k])
        x += y @ directions[:k]
        r = rhs - matvec(x)
        beta = float(np.linalg.norm(r))
        if k == 0:
            break
    return x, beta <= atol, steps


def _back_substitute(upper: np.ndarray, g: np.ndarray) -> np.ndarray:
    """Solve the upper triangular ``upper y = g`` (zero pivots give zero components)."""
    n = g.size
    y = np.zeros(n)
    for i in range(n - 1, -1, -1):
        piv = upper[i, i]
        y[i] = 0.0 if piv == 0.0 else (g[i] - upper[i, i + 1:] @ y[i + 1:]) / piv
    return y
