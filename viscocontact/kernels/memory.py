r"""The steady-sliding memory integral of one creep branch, tabulated to a stated accuracy.

For a creep branch with dimensionless memory length ``ζ_i = q0·V·θ_i`` the viscoelastic Green
function (thesis eqs. 4.2, 4.19) contains

.. math:: \mathcal{M}_\zeta[f](x) = \int_0^\infty f(x + \zeta t)\, e^{-t}\, dt ,

applied to the log kernel ``g`` (for pointwise values) and to its antiderivative ``Φ = -Cl2`` (for the
influence coefficients). In Fourier space the operator multiplies ``e^{imx}`` by ``1/(1 - i m ζ)``.

Method
------
``H = M_ζ[f]`` is the 2π-periodic solution of ``ζ H' = H - f``. On a grid ``-π = x_0 < ... < x_n = π``
(the singular point ``0`` an interior node, so that both sides keep full relative resolution)

.. math:: H(x_j) = \frac{1}{\zeta}\int_0^{h_j} e^{-u/\zeta} f(x_j + u)\,du + e^{-h_j/\zeta} H(x_{j+1}),

with ``f`` replaced on each interval by its cubic Hermite interpolant (``f`` and ``f'`` are known in closed
form), whose exponential moments are exact: ``(1/ζ)∫_0^h e^{-u/ζ} u^k du = ζ^k k! P(k+1, h/ζ)``
(``P`` the regularised lower incomplete gamma function, accurate for every ``h/ζ``). Periodicity
closes the recursion: ``H(x_0) = Σ_j e^{-(x_j - x_0)/ζ} I_j / (1 - e^{-2π/ζ})``. The grid is
geometric (ratio 1.02) towards the log singularity of ``g`` at ``0``, down to ``min(1e-14, 1e-3 ζ)``,
and at most ``ζ/20`` wide within ``60 ζ`` upstream of it, so that the boundary layer of width ``ζ`` is
resolved for every ζ. Arbitrary points are evaluated exactly the same way from the next node
(:meth:`MemoryTable.values`) or, for the antiderivative table, by cubic Hermite interpolation of
``H`` with ``H' = M_ζ[g]`` (:meth:`MemoryTable.antiderivative`), which is what the influence
matrix uses.

Accuracy (measured by ``tests/unit/kernels/test_memory.py`` against adaptive quadrature of the
defining integral, for ζ from 1e-8 to 1e8): absolute error below 1e-9 in both tables.
"""
from __future__ import annotations

import functools

import numpy as np
from scipy.special import gammainc

from .clausen import TWO_PI, cl2, log_kernel, log_kernel_derivative, wrap
from .table import horner

_FACT = np.array([1.0, 1.0, 2.0, 6.0])


def _grid(zeta: float, ratio: float = 1.02, h_max: float = 2.0e-3) -> np.ndarray:
    """Nodes on ``[-π, π]`` with the singular point at the interior node 0.

    Geometric (``ratio``) away from 0 on both sides, down to ``min(1e-14, 1e-3 ζ)``; uniform
    (``h_max``) further out; spacing at most ``ζ/20`` within ``60 ζ`` upstream (``x < 0``).
    """
    x_min = min(1e-14, 1e-3 * zeta)
    reach = h_max / (ratio - 1.0)
    n_geo = int(np.ceil(np.log(reach / x_min) / np.log(ratio))) + 1
    geo = x_min * ratio ** np.arange(n_geo)
    geo = geo[geo < reach]
    n_mid = int(np.ceil((np.pi - geo[-1]) / h_max))
    mid = np.linspace(geo[-1], np.pi, n_mid + 1)[1:]
    pos = np.concatenate([geo, mid])
    x = np.concatenate([-pos[::-1], [0.0], pos])
    if zeta / 20.0 < h_max:
        a = max(-60.0 * zeta, -np.pi)
        extra = np.linspace(a, 0.0, int(np.ceil(-a * 20.0 / zeta)) + 1)[1:-1]
        x = np.union1d(x, extra[extra < -geo[0]])
    return x


def _hermite_taylor(f0, d0, f1, d1, h):
    """Taylor coefficients (about the left end) of the cubic Hermite interpolant on ``[0, h]``."""
    a0, a1 = f0, d0
    s = (f1 - f0) / h
    a2 = (3.0 * s - 2.0 * d0 - d1) / h
    a3 = (d0 + d1 - 2.0 * s) / (h * h)
    return a0, a1, a2, a3


def _moments(h, zeta):
    """``(1/ζ)∫_0^h e^{-u/ζ} u^k du`` for k = 0..3, shape ``h.shape + (4,)``."""
    r = np.asarray(h, dtype=float)[..., None] / zeta
    k = np.arange(4)
    return zeta ** k * _FACT * gammainc(k + 1.0, r)


class MemoryTable:
    """``M_ζ`` applied to ``g`` and to ``Φ = -Cl2``, tabulated on a graded grid.

    Parameters
    ----------
    zeta : float
        Memory length ``ζ_i = q0·V·θ_i`` (> 0).
    """

    def __init__(self, zeta: float):
        if not (np.isfinite(zeta) and zeta > 0):
            raise ValueError(f"zeta must be finite and > 0, got {zeta!r}")
        self.zeta = float(zeta)
        x = _grid(self.zeta)
        self.nodes = x
        self._j0 = int(np.searchsorted(x, 0.0))
        # f = Φ = -Cl2 with Φ' = g ; f = g with g' = cot/2
        phi, dphi = -cl2(x), log_kernel(x)
        g, dg = log_kernel(x), log_kernel_derivative(x)
        self.H = self._solve(x, phi, dphi, singular=False)      # M[Φ] at the nodes
        self.G = self._solve(x, g, dg, singular=True)           # M[g] at the nodes
        self._phi, self._dphi, self._g, self._dg = phi, dphi, g, dg
        self.H0 = self.H[self._j0]

    # ---------------------------------------------------------------------------------------
    def _local(self, x, f, df, singular):
        """Exponential moments I_j of the Hermite interpolant of f on every interval."""
        h = np.diff(x)
        f0, f1 = f[:-1].copy(), f[1:].copy()
        d0, d1 = df[:-1].copy(), df[1:].copy()
        # the two intervals touching the singular point 0: use the interval mean (exact to O(h log h))
        j0 = self._j0
        for j, (lo, hi) in ((j0 - 1, (x[j0 - 1], 0.0)), (j0, (0.0, x[j0 + 1]))):
            ht = hi - lo
            if singular:   # mean of log|2 sin(s/2)| ~ log|s| over an interval ending at 0
                mean = np.log(ht) - 1.0
            else:          # mean of -Cl2 over the interval
                mean = (-cl2(lo) - cl2(hi)) / 2.0
            f0[j], f1[j], d0[j], d1[j] = mean, mean, 0.0, 0.0
        coeffs = np.stack(_hermite_taylor(f0, d0, f1, d1, h), axis=-1)
        return np.sum(coeffs * _moments(h, self.zeta), axis=-1)

    def _solve(self, x, f, df, singular):
        zeta = self.zeta
        I = self._local(x, f, df, singular)
        E = np.exp(-np.diff(x) / zeta)
        w = np.exp(-(x[:-1] - x[0]) / zeta)
        H0 = np.sum(w * I) / -np.expm1(-TWO_PI / zeta)
        H = np.empty_like(x)
        H[-1] = H0
        for j in range(len(I) - 1, -1, -1):
            H[j] = I[j] + E[j] * H[j + 1]
        return H

    # ---------------------------------------------------------------------------------------
    def _partial(self, x, f_nodes, df_nodes, table, f, df):
        """Exact-moment evaluation at arbitrary x from the next node (see module docstring)."""
        x = wrap(x)
        j = np.clip(np.searchsorted(self.nodes, x, side="right") - 1, 0, len(self.nodes) - 2)
        x1 = self.nodes[j + 1]
        h = x1 - x
        with np.errstate(divide="ignore", invalid="ignore"):
            fx, dfx = f(x), df(x)
        bad = ~np.isfinite(fx) | ~np.isfinite(dfx) | (j == self._j0 - 1) | (j == self._j0)
        fx = np.where(bad, f_nodes[j + 1], fx)
        dfx = np.where(bad, 0.0, dfx)
        d1 = np.where(bad, 0.0, df_nodes[j + 1])
        coeffs = np.stack(_hermite_taylor(fx, dfx, f_nodes[j + 1], d1, np.where(h > 0, h, 1.0)),
                          axis=-1)
        local = np.sum(coeffs * _moments(h, self.zeta), axis=-1)
        out = local + np.exp(-h / self.zeta) * table[j + 1]
        # inside the two intervals touching the singular point: linear in the node values
        sing = (j == self._j0 - 1) | (j == self._j0)
        if np.any(sing):
            x0 = self.nodes[j]
            t = (x - x0) / (x1 - x0)
            out = np.where(sing, (1 - t) * table[j] + t * table[j + 1], out)
        return out

    def values(self, x):
        """``M_ζ[g](x)``: the memory part of the kernel at arbitrary points."""
        return self._partial(x, self._g, self._dg, self.G, log_kernel, log_kernel_derivative)

    def antiderivative_exact(self, x):
        """``M_ζ[Φ](x)`` by exact moments from the next node (slower, reference quality)."""
        return self._partial(x, self._phi, self._dphi, self.H, lambda s: -cl2(s), log_kernel)

    def antiderivative(self, x, *, wrapped: bool = False):
        """``M_ζ[Φ](x) - M_ζ[Φ](0)``, the antiderivative of ``M_ζ[g]`` vanishing at 0 (fast path).

        Cubic Hermite interpolation of the node values with the exact slopes ``H' = M_ζ[g]``
        (linear on the two intervals touching the singular point 0, error ``O(h log h)``), stored
        as one polynomial in ``t = (x - x_j)/h_j`` per interval. The interval and ``t`` come from
        a single :func:`numpy.interp` of the node indices (``t`` to about ``n·ε`` ≈ 1e-12, which
        moves the value by ``1e-12`` of one interval's increment). ``wrapped``: ``x`` is already
        in ``[-π, π]`` (:func:`~viscocontact.kernels.clausen.wrap` is skipped).
        """
        s = np.interp(x if wrapped else wrap(x), self.nodes, self._index)
        j = np.minimum(s.astype(np.intp), len(self.nodes) - 2)
        t = s - j
        return horner(self._coef, j, t)

    def antiderivative_slope(self, x, *, wrapped: bool = False):
        """``d/dx`` of :meth:`antiderivative`: the slope of the same piecewise cubic (so that a
        derivative built on it is the exact derivative of what the influence matrix uses; it
        equals ``M_ζ[g]`` at the nodes and differs from it between them by the interpolation
        error)."""
        s = np.interp(x if wrapped else wrap(x), self.nodes, self._index)
        j = np.minimum(s.astype(np.intp), len(self.nodes) - 2)
        t = s - j
        _, c1, c2, c3 = self._coef
        out = c3.take(j)
        out *= 3.0 * t
        out += 2.0 * c2.take(j)
        out *= t
        out += c1.take(j)
        out /= self._widths.take(j)
        return out

    @functools.cached_property
    def _widths(self):
        return np.diff(self.nodes)

    @functools.cached_property
    def _index(self):
        return np.arange(len(self.nodes), dtype=float)

    @property
    def coefficients(self) -> tuple:
        """The piecewise cubic of :meth:`antiderivative`: per interval ``[x_j, x_{j+1}]`` of
        :attr:`nodes`, the coefficients of ``t⁰, ..., t³`` in ``t = (x - x_j)/(x_{j+1} - x_j)``
        (four arrays; :class:`~viscocontact.kernels.table.KernelTable` sums them over the
        branches)."""
        return self._coef

    @functools.cached_property
    def _coef(self):
        """Per interval, the coefficients of ``t⁰``, ..., ``t³`` of the Hermite interpolant minus
        ``H(0)`` (four arrays)."""
        h = np.diff(self.nodes)
        H0, H1 = self.H[:-1], self.H[1:]
        G0, G1 = self.G[:-1] * h, self.G[1:] * h
        end = np.zeros(len(h), dtype=bool)
        end[[self._j0 - 1, self._j0]] = True     # G is singular at 0: linear there
        G0 = np.where(end, H1 - H0, G0)
        G1 = np.where(end, H1 - H0, G1)
        return tuple(np.ascontiguousarray(c) for c in (
            H0 - self.H0, G0, 3 * (H1 - H0) - 2 * G0 - G1, 2 * (H0 - H1) + G0 + G1))
