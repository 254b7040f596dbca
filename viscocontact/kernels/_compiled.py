r"""The influence-coefficient loop of a :class:`~.table.KernelTable`, compiled with numba.

An influence matrix needs ``F̃`` (and ``E``) at every collocation point minus every element end:
a wrap to ``[-π, π)``, an interval search in the table's grid, one or two cubics and the closed
form ``x log|x|``, then the difference of two ends per element. In numpy each of these is a pass
over a block of the matrix; this loop does them in one pass (1.2-1.5 times faster on the meshes
of a rough solve, about 30 ns per coefficient, 7 of them the logarithm). The grid is symmetric about 0,
geometric towards it and about uniform away from it, so the search starts from a bucket of a grid
uniform in ``log|x|`` (the logarithm is needed anyway for ``x log|x|``) and bisects the few nodes
of that bucket, unless ``x`` is in the interval of the previous end or the one below.

The values are those of :meth:`KernelTable.pair` up to rounding (the local coordinate is computed
with a stored inverse width, where :func:`numpy.interp` of the node indices loses the bits of the
index): the tests compare both with the kernel's pieces.

Compiled functions are cached on disk (``cache=True``): the first call in a fresh installation
compiles for a few seconds, later processes load the machine code (about half a second).
"""
from __future__ import annotations

from typing import Callable, cast

import numpy as np
from numba import njit

_PI = np.pi
_TWO_PI = 2.0 * np.pi


@njit(cache=True, nogil=True)
def _interval(x, lg, nodes, zero, first, u0, inverse_width):
    """Index ``j`` of the interval ``[nodes[j], nodes[j+1])`` that holds ``x`` (in ``[-π, π]``,
    ``lg = log|x|``; ``zero`` the index of the node 0)."""
    last = nodes.size - 2
    s = abs(x)
    if s < nodes[zero + 1]:
        k = 0
    else:
        b = int((lg - u0) * inverse_width)
        if b < 0:
            b = 0
        elif b > first.size - 2:
            b = first.size - 2
        k = first[b]
        top = first[b + 1] + 1
        while top - k > 1:
            mid = (k + top) >> 1
            if s >= nodes[zero + mid]:
                k = mid
            else:
                top = mid
    j = zero + k if x >= 0.0 else zero - k - 1
    if j < 0:
        j = 0
    elif j > last:
        j = last
    # rounding of the bucket index and the mirror image's closed end: at most a step or two
    while j > 0 and x < nodes[j]:
        j -= 1
    while j < last and x >= nodes[j + 1]:
        j += 1
    return j


@njit(cache=True, nogil=True)
def _integrals(points, ends, lo, hi, nodes, zero, first, u0, inverse_width, coef, singular,
              out_f, out_e):
    """``out[l, q] = V(ξ_l - ends[lo_q]) - V(ξ_l - ends[hi_q])`` for ``V = F̃`` into ``out_f`` and
    ``V = E`` into ``out_e`` (either may have size 0: not wanted).

    ``coef`` is ``(n, 9)``: per table interval the cubic of ``F̃`` without ``x log|x|`` (4), that
    of ``E`` (4) and the inverse width; ``singular`` the weight of ``x log|x|``.
    """
    want_f = out_f.size > 0
    want_e = out_e.size > 0
    m = ends.size
    vf = np.empty(m)
    ve = np.empty(m)
    for row in range(points.size):
        xi = points[row]
        j = 0
        for k in range(m):
            x = xi - ends[k]
            if x >= _PI:
                x -= _TWO_PI
            elif x < -_PI:
                x += _TWO_PI
            if not (-_PI <= x < _PI):
                if x != x:                          # NaN in, NaN out
                    vf[k] = x
                    ve[k] = x
                    continue
                x = np.mod(x + _PI, _TWO_PI) - _PI
            lg = np.log(abs(x)) if x != 0.0 else 0.0
            # the ends ascend, so along a row x descends: most often it stays in the previous
            # end's interval (six in ten on a rough solve's meshes) or the one below (written
            # out here: through an inlined helper this loop took 33 instead of 25 ns per
            # coefficient)
            if not (nodes[j] <= x < nodes[j + 1]):
                if j > 0 and nodes[j - 1] <= x < nodes[j]:
                    j -= 1
                else:
                    j = _interval(x, lg, nodes, zero, first, u0, inverse_width)
            t = (x - nodes[j]) * coef[j, 8]
            if want_f:
                vf[k] = (coef[j, 0] + t * (coef[j, 1] + t * (coef[j, 2] + t * coef[j, 3]))
                         + singular * x * lg)
            if want_e:
                ve[k] = coef[j, 4] + t * (coef[j, 5] + t * (coef[j, 6] + t * coef[j, 7]))
        if want_f:
            for q in range(lo.size):
                out_f[row, q] = vf[lo[q]] - vf[hi[q]]
        if want_e:
            for q in range(lo.size):
                out_e[row, q] = ve[lo[q]] - ve[hi[q]]


@njit(cache=True, nogil=True)
def _slopes(points, ends, nodes, zero, first, u0, inverse_width, dcoef, singular, out_f, out_e):
    """``out[l, k] = V'(ξ_l - ends[k])`` for ``V = F̃`` into ``out_f`` (with the slope
    ``singular·(log|x| + 1)`` of ``x log|x|``, infinite at 0) and ``V = E`` into ``out_e``
    (either may have size 0). ``dcoef`` is ``(n, 7)``: per table interval the slope's quadratic
    in the local coordinate for ``F̃`` (3) and ``E`` (3), and the inverse width."""
    want_f = out_f.size > 0
    want_e = out_e.size > 0
    m = ends.size
    for row in range(points.size):
        xi = points[row]
        j = 0
        for k in range(m):
            x = xi - ends[k]
            if x >= _PI:
                x -= _TWO_PI
            elif x < -_PI:
                x += _TWO_PI
            if not (-_PI <= x < _PI):
                if x != x:                          # NaN in, NaN out
                    if want_f:
                        out_f[row, k] = x
                    if want_e:
                        out_e[row, k] = x
                    continue
                x = np.mod(x + _PI, _TWO_PI) - _PI
            lg = np.log(abs(x))                     # -inf at 0: the slope of x log|x| there
            # the wrap above and the search written out, as in _integrals: through inlined
            # helpers this loop took 15.3 instead of 11.3 ns per pair on the slope matrix of a
            # 2044-element mesh (11.7 with a helper for the wrap alone)
            if not (nodes[j] <= x < nodes[j + 1]):
                if j > 0 and nodes[j - 1] <= x < nodes[j]:
                    j -= 1
                else:
                    j = _interval(x, lg, nodes, zero, first, u0, inverse_width)
            t = (x - nodes[j]) * dcoef[j, 6]
            if want_f:
                v = dcoef[j, 0] + t * (dcoef[j, 1] + t * dcoef[j, 2])
                if singular != 0.0:
                    v += singular * (lg + 1.0)
                out_f[row, k] = v
            if want_e:
                out_e[row, k] = dcoef[j, 3] + t * (dcoef[j, 4] + t * dcoef[j, 5])


#: :func:`_integrals` as the callers see it (numba's dispatcher types its call as argument-free)
integrals = cast(Callable[..., None], _integrals)
#: :func:`_slopes` likewise
slopes = cast(Callable[..., None], _slopes)
