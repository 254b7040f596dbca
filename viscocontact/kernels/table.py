r"""One cubic table for the whole antiderivative of a prepared kernel and for its even part.

:class:`~viscocontact.kernels.prepared.PreparedKernel` assembles the antiderivative ``F̃`` from
pieces (Clausen, one :class:`~viscocontact.kernels.memory.MemoryTable` per creep branch, the layer
correction spline), each with its own search; the influence matrices need ``F̃`` (and
``E(x) = F̃(x) + F̃(-x)``) at every collocation point minus every node, in every residual. Each
piece except the Clausen term is a piecewise cubic, and a sum of piecewise cubics is a piecewise
cubic on the union of their break points. So on the union grid ``y`` (made symmetric, so that
``x ↦ -x`` maps intervals onto intervals) this table stores, per interval, the cubic

.. math:: T(x) = \frac{1}{\pi}\Big[\sum_i w_i\,\mathcal{H}_i(x) + C(x) - K\,S(x)\Big],
          \qquad \tilde F(x) = T(x) + \frac{K}{\pi}\,x\log|x| ,

with ``H_i`` the branch interpolants (:meth:`MemoryTable.antiderivative`) and ``C`` the layer
correction re-expanded exactly (to rounding), ``K`` the instantaneous compliance and
``-Cl2(x) = -S(x) + x log|x|``, ``S(x) = x + x³ P(x²)`` the smooth part of the Clausen series
(:func:`~viscocontact.kernels.clausen.cl2_smooth`). ``S`` is the only piece that is interpolated
(cubic Hermite with exact slopes on intervals of at most 2e-3, :data:`LONGEST_INTERVAL`: error
below 1e-14); the singular ``x log|x|`` stays in closed form. ``E`` (even, free of the Clausen
part) has a second set of coefficients on the same intervals, so :meth:`KernelTable.pair` finds
the interval once for both. A look-up is one :func:`numpy.interp` of the node indices (as in
:meth:`MemoryTable.antiderivative`) and a Horner evaluation per function.
"""
from __future__ import annotations

import numpy as np

from .clausen import TWO_PI, cl2_smooth, wrap

_TINY = np.finfo(float).tiny
#: Longest interval of a table's grid: the smooth part ``S`` of the Clausen function is
#: interpolated by cubic Hermite polynomials with exact slopes, whose error
#: ``h⁴·max|S⁽⁴⁾|/384`` is below 1e-14 on intervals this short. The memory tables' grids meet it
#: already (a node every 2e-3 at most away from 0, 1.5e-3 for the layer correction); an elastic
#: half-plane's grid is made of it alone.
LONGEST_INTERVAL = 2e-3


def _refined(nodes):
    """``nodes`` (symmetric about 0, with 0 a node) with every interval longer than
    :data:`LONGEST_INTERVAL` split into equal parts, built on the positive half and mirrored so
    that the grid stays exactly symmetric; a grid that meets the bound is returned as it is."""
    if np.max(np.diff(nodes)) <= LONGEST_INTERVAL:
        return nodes
    positive = nodes[nodes >= 0.0]
    parts = [positive[:1]]
    for lo, hi in zip(positive[:-1], positive[1:]):
        inner = np.linspace(lo, hi, max(1, int(np.ceil((hi - lo) / LONGEST_INTERVAL))) + 1)[1:]
        inner[-1] = hi
        parts.append(inner)
    positive = np.concatenate(parts)
    return np.concatenate([-positive[:0:-1], positive])


def _buckets(nodes, per_node: float = 4.0):
    """The start of the compiled loop's interval search: ``(first, u0, inverse_width)`` for a
    grid uniform in ``u = log|x|`` from the smallest positive node to π, with ``per_node`` buckets
    per positive node, and per bucket edge the index (among the positive nodes ``nodes[c:]``, ``c``
    the index of 0) of the interval that holds it. Logarithmic buckets suit both parts of the
    grid: geometric towards 0 and about uniform (a node every 2e-3) away from it."""
    positive = nodes[nodes >= 0.0]
    u0 = np.log(positive[1])
    count = max(1, int(per_node * len(positive)))
    width = (np.log(np.pi) - u0) / count
    edges = np.exp(u0 + width * np.arange(count + 1))
    first = np.searchsorted(positive, edges, side="right") - 1
    return np.clip(first, 0, len(positive) - 2).astype(np.intp), float(u0), 1.0 / width


def _taylor_at(c, t0, r):
    """Coefficients in ``s`` of ``p(t0 + r s)`` for cubics ``p(t) = Σ c_k t^k`` (4 arrays ``c``)."""
    c0, c1, c2, c3 = c
    return (c0 + t0 * (c1 + t0 * (c2 + t0 * c3)),
            r * (c1 + t0 * (2.0 * c2 + 3.0 * t0 * c3)),
            r * r * (c2 + 3.0 * t0 * c3),
            r * r * r * c3)


def _reexpand(breaks, coef, lo, width, sign):
    """A piecewise cubic ``p`` (break points ``breaks``, per interval coefficients ``coef`` in
    ``t = (x - x_j)/h_j``) as cubics in ``s`` on the intervals ``[lo, lo + width]`` of a finer
    grid: ``p(sign·(lo + s·width))``, exact up to rounding."""
    start = sign * lo
    mid = sign * (lo + 0.5 * width)
    j = np.clip(np.searchsorted(breaks, mid, side="right") - 1, 0, len(breaks) - 2)
    h = breaks[j + 1] - breaks[j]
    return _taylor_at([c[j] for c in coef], (start - breaks[j]) / h, sign * width / h)


def _hermite(f, df, width):
    """Per interval coefficients in ``t`` of the cubic Hermite interpolant of node values ``f``
    and slopes ``df``."""
    f0, f1 = f[:-1], f[1:]
    d0, d1 = df[:-1] * width, df[1:] * width
    return f0, d0, 3.0 * (f1 - f0) - 2.0 * d0 - d1, 2.0 * (f0 - f1) + d0 + d1


class KernelTable:
    """``F̃`` and ``E`` of one prepared kernel as one piecewise cubic each (module docstring).

    Build with :meth:`build`; the evaluations take any real ``x`` (reduced to ``[-π, π)``).

    Attributes
    ----------
    nodes : ndarray
        The union grid on ``[-π, π]``, symmetric about 0, with 0 a node.
    singular : float
        ``K/π``, the weight of the closed-form ``x log|x|``.
    """

    def __init__(self, nodes, odd, even, singular: float):
        self.nodes = nodes
        self.singular = float(singular)
        self._index = np.arange(len(nodes), dtype=float)
        widths = np.diff(nodes)
        self._f = tuple(np.ascontiguousarray(c) for c in odd)
        self._e = tuple(np.ascontiguousarray(c) for c in even)
        # slopes: d/dx of the cubics in t, the powers' factors and 1/h folded in
        self._df = tuple(np.ascontiguousarray(k * c / widths) for k, c in zip((1, 2, 3), odd[1:]))
        self._de = tuple(np.ascontiguousarray(k * c / widths) for k, c in zip((1, 2, 3), even[1:]))
        # the compiled loop's layout: one row of 9 per interval (a cache line and a word)
        self._coef = np.ascontiguousarray(np.column_stack(self._f + self._e + (1.0 / widths,)))
        self._dcoef = np.ascontiguousarray(np.column_stack(self._df + self._de + (1.0 / widths,)))
        self._zero = int(np.searchsorted(nodes, 0.0))
        if not (nodes[self._zero] == 0.0 and np.array_equal(nodes[self._zero:][::-1],
                                                          -nodes[:self._zero + 1])):
            raise ValueError("a kernel table's grid must be symmetric about 0, with 0 a node")
        self._buckets = _buckets(nodes)

    @classmethod
    def build(cls, instantaneous: float, weights, tables, correction=None) -> "KernelTable":
        """The table of ``-K Cl2 + Σ w_i H_i + C`` (all over π).

        Parameters
        ----------
        instantaneous : float
            ``K``, the weight of ``-Cl2``.
        weights, tables : sequences
            Branch weights ``w_i`` and their :class:`~viscocontact.kernels.memory.MemoryTable`.
        correction : scipy.interpolate.CubicSpline, optional
            The layer correction's antiderivative on ``[0, 2π]`` (periodic).
        """
        parts = [np.array([-np.pi, 0.0, np.pi])]
        parts += [t.nodes for t in tables]
        if correction is not None:
            xc = np.asarray(correction.x, dtype=float)
            parts += [xc[xc <= np.pi], xc[xc >= np.pi] - TWO_PI]
        y = np.unique(np.concatenate(parts))
        y = np.unique(np.concatenate([y, -y]))
        y = _refined(y[(y >= -np.pi) & (y <= np.pi)])
        lo, width = y[:-1], np.diff(y)
        odd = [np.zeros(len(lo)) for _ in range(4)]
        even = [np.zeros(len(lo)) for _ in range(4)]
        for wi, tab in zip(weights, tables):
            coef = tab.coefficients
            for sign in (1.0, -1.0):
                part = _reexpand(tab.nodes, coef, lo, width, sign)
                for k in range(4):
                    even[k] += wi * part[k]
                    if sign > 0:
                        odd[k] += wi * part[k]
        if correction is not None:
            xc = np.asarray(correction.x, dtype=float)
            hc = np.diff(xc)
            c = correction.c            # c[k] multiplies (x - x_m)^(3 - k)
            coef = (c[3], c[2] * hc, c[1] * hc**2, c[0] * hc**3)
            for sign in (1.0, -1.0):
                # x in [-π, 0) is read at x + 2π, as np.mod(x, 2π) does
                shifted = np.where(sign * (lo + 0.5 * width) < 0.0, sign * TWO_PI, 0.0)
                part = _reexpand(xc, coef, lo + shifted, width, sign)
                for k in range(4):
                    even[k] += part[k]
                    if sign > 0:
                        odd[k] += part[k]
        s, ds = cl2_smooth(y)
        for k, c in enumerate(_hermite(s, ds, width)):
            odd[k] -= instantaneous * c
        odd = [c / np.pi for c in odd]
        even = [c / np.pi for c in even]
        return cls(y, odd, even, instantaneous / np.pi)

    # ---- influence coefficients --------------------------------------------------------------
    def element_integrals(self, points, left, right, parts: str = "F"):
        """``V(ξ_l - a_q) - V(ξ_l - b_q)`` for ``V`` = ``F̃`` (``parts="F"``), ``E`` (``"E"``) or
        both stacked (``"FE"``), by the compiled loop of :mod:`._compiled`: the same values as
        :func:`~viscocontact.kernels.prepared.element_integrals` with :meth:`antiderivative`,
        :meth:`even` or :meth:`pair`, up to rounding. Large calls split their rows between
        threads (:mod:`viscocontact._threads`; the same values bit for bit)."""
        from . import _compiled

        xi = np.ascontiguousarray(np.ravel(points), dtype=float)
        a = np.ravel(np.asarray(left, dtype=float))
        b = np.ravel(np.asarray(right, dtype=float))
        ends, where = np.unique(np.concatenate([a, b]), return_inverse=True)
        where = where.ravel().astype(np.intp)
        return _by_rows(_compiled.integrals, xi, a.size, ends.size, parts,
                        (ends, where[:a.size], where[a.size:], self.nodes, self._zero,
                         *self._buckets, self._coef, self.singular))

    def pairwise_slopes(self, points, ends, parts: str = "F"):
        """``V'(ξ_l - e_k)`` for every point and end, ``V`` = ``F̃`` (``parts="F"``, as
        :meth:`slope`) or both ``F̃`` and ``E`` stacked (``"FE"``, as :meth:`slope_pair`), by the
        compiled loop of :mod:`._compiled` (the same values up to rounding; large calls split
        their rows between threads, bit for bit the same)."""
        from . import _compiled

        xi = np.ascontiguousarray(np.ravel(points), dtype=float)
        e = np.ascontiguousarray(np.ravel(ends), dtype=float)
        return _by_rows(_compiled.slopes, xi, e.size, e.size, parts,
                        (e, self.nodes, self._zero, *self._buckets, self._dcoef, self.singular))

    # ---- look-ups ---------------------------------------------------------------------------
    def _locate(self, x):
        """``(w, j, t)``: ``x`` reduced to ``[-π, π)``, its interval and the position in it
        (flat arrays; the callers restore the shape). The interval and ``t`` come from one
        :func:`numpy.interp` of the node indices, as in :meth:`MemoryTable.antiderivative`
        (its search starts from the previous point's interval, and the points of one row of
        an influence matrix are ordered)."""
        w = wrap(np.ravel(x))
        s = np.interp(w, self.nodes, self._index)
        j = s.astype(np.intp)
        np.minimum(j, len(self.nodes) - 2, out=j)
        s -= j
        return w, j, s

    @staticmethod
    def _slope_horner(coef, j, t, out=None):
        d1, d2, d3 = coef
        out = d3.take(j, out=out)
        out *= t
        out += d2.take(j)
        out *= t
        out += d1.take(j)
        return out

    def _add_singular(self, out, w):
        """``out += (K/π) w log|w|`` (0 at ``w = 0``)."""
        if self.singular != 0.0:
            lg = np.abs(w)
            np.maximum(lg, _TINY, out=lg)
            np.log(lg, out=lg)
            lg *= w
            lg *= self.singular
            out += lg
        return out

    def antiderivative(self, x):
        """``F̃(x)`` (without the ``c0`` part)."""
        w, j, t = self._locate(x)
        return self._add_singular(horner(self._f, j, t), w).reshape(np.shape(x))

    def even(self, x):
        """``E(x) = F̃(x) + F̃(-x)``."""
        _, j, t = self._locate(x)
        return horner(self._e, j, t).reshape(np.shape(x))

    def pair(self, x):
        """``[F̃(x), E(x)]`` stacked, sharing the interval search."""
        w, j, t = self._locate(x)
        out = np.empty((2,) + w.shape)
        self._add_singular(horner(self._f, j, t, out[0]), w)
        horner(self._e, j, t, out[1])
        return out.reshape((2,) + np.shape(x))

    def _singular_slope(self, w):
        """``(K/π)(log|w| + 1)``."""
        lg = np.abs(w)
        with np.errstate(divide="ignore"):
            np.log(lg, out=lg)
        lg += 1.0
        lg *= self.singular
        return lg

    def slope(self, x):
        """``F̃'(x)``: the exact derivative of :meth:`antiderivative`."""
        w, j, t = self._locate(x)
        out = self._slope_horner(self._df, j, t)
        if self.singular != 0.0:
            out += self._singular_slope(w)
        return out.reshape(np.shape(x))

    def slope_pair(self, x):
        """``[F̃'(x), E'(x)]`` stacked (``E' = F̃'(x) - F̃'(-x)``), sharing the interval search."""
        w, j, t = self._locate(x)
        out = np.empty((2,) + w.shape)
        self._slope_horner(self._df, j, t, out[0])
        if self.singular != 0.0:
            out[0] += self._singular_slope(w)
        self._slope_horner(self._de, j, t, out[1])
        return out.reshape((2,) + np.shape(x))


def _by_rows(loop, xi, columns: int, evaluations: int, parts: str, args: tuple):
    """``loop(xi, *args, out_f, out_e)`` into a new ``(len(parts), xi.size, columns)`` array
    (``out_f``/``out_e`` the ``"F"``/``"E"`` planes, empty when not asked for), its rows split
    between threads by :func:`viscocontact._threads.split_rows` (``evaluations`` per row)."""
    from .._threads import split_rows

    out = np.empty((len(parts), xi.size, columns))
    empty = np.empty((0, 0))
    out_f = out[parts.index("F")] if "F" in parts else empty
    out_e = out[parts.index("E")] if "E" in parts else empty

    def rows(start, stop):
        loop(xi[start:stop], *args, out_f[start:stop] if out_f.size else empty,
             out_e[start:stop] if out_e.size else empty)

    split_rows(rows, xi.size, xi.size * evaluations)
    return out if len(parts) > 1 else out[0]


def horner(coef, j, t, out=None):
    """``c0[j] + t (c1[j] + t (c2[j] + t c3[j]))`` for the cubic coefficients ``coef = (c0, c1,
    c2, c3)`` of the intervals ``j`` at local coordinates ``t``, in place on contiguous gathers
    (about twice the speed of gathering rows of an ``(n, 4)`` table); into ``out`` if given."""
    c0, c1, c2, c3 = coef
    out = c3.take(j, out=out)
    out *= t
    out += c2.take(j)
    out *= t
    out += c1.take(j)
    out *= t
    out += c0.take(j)
    return out
