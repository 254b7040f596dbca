r"""A kernel prepared for one rheology and one speed: tables and influence coefficients.

The antiderivative of the kernel, vanishing at 0 and periodic, is assembled from exact pieces
(module :mod:`~viscocontact.kernels.base` for the notation):

.. math:: \tilde F(x) = \frac{1}{\pi}\Big[K_\infty\,(-\mathrm{Cl}_2(x))
          + \sum_i w_i\, \big(\mathcal{M}_{\zeta_i}[\Phi](x) - \mathcal{M}_{\zeta_i}[\Phi](0)\big)
          + \sum_m \frac{A_m}{m^2}\,\mathrm{Im}\big[K(m)(e^{imx} - 1)\big]\Big] ,

the first term in closed form (Clausen), the memory terms from :class:`MemoryTable` (one per
creep branch), the layer correction (``A_m = 1 - S_m``, exponentially decaying) from an FFT on a
uniform grid with a periodic cubic spline. The influence coefficient of element ``[a, b]`` at
collocation point ``ξ`` (eq. 4.32) is then ``B = F(ξ - a) - F(ξ - b) + c0 (b - a)``. Every piece
but the Clausen function's ``x log|x|`` is a piecewise cubic; :class:`~.table.KernelTable`
holds their sum as one cubic per interval of the union grid, which is what the evaluations use
(the ``*_terms`` methods sum the pieces one by one, as reference).

Branches with ``ζ_i < 1e-12`` are taken as fully relaxed (error ``O(ζ log ζ)``) and those with
``ζ_i > 1e12`` as frozen (error ``O(1/ζ)``).
"""
from __future__ import annotations

import attrs
import numpy as np
from scipy.interpolate import CubicSpline

from .clausen import TWO_PI, cl2, log_kernel, wrap
from .memory import MemoryTable
from .table import KernelTable

ZETA_RELAXED = 1e-12
ZETA_FROZEN = 1e12


@attrs.frozen(kw_only=True, eq=False)
class PreparedKernel:
    """Tables of a kernel for one rheology and one ``ζ``; build with :meth:`GreenKernel.prepare`.

    Attributes
    ----------
    instantaneous : float
        ``K∞`` plus the weights of branches treated as relaxed.
    weights, zetas : ndarray
        Weights ``w_i`` and memory lengths ``ζ_i`` of the active memory branches.
    mean : float
        ``c0`` (constant kernel, eq. 2.44).
    regimes : ndarray of str
        How each creep branch (``all_zetas``) entered: ``"relaxed"``, ``"active"`` or ``"frozen"``
        (:func:`branch_regimes` with ``tolerance``).
    tolerance : float or None
        The tolerance the regimes were decided with.
    tables, table
        The memory tables of the active branches and their sum as one cubic table
        (:mod:`~viscocontact.kernels.table`; an elastic half-plane's holds the Clausen
        function alone): built on first use, since only the
        real-space evaluations (the boundary-element method) read them; the Fourier view
        (:meth:`multiplier`, the spectral methods) does not.
    """

    kernel: object
    zeta: float
    instantaneous: float
    weights: np.ndarray
    zetas: np.ndarray
    mean: float
    correction: object  # CubicSpline of the layer correction antiderivative, or None
    correction_values: object  # CubicSpline of the layer correction kernel, or None
    all_weights: np.ndarray
    all_zetas: np.ndarray
    k_inf: float
    regimes: np.ndarray
    tolerance: float | None = None
    _built: dict = attrs.field(factory=dict, init=False, repr=False)

    @property
    def tables(self) -> tuple:
        """The :class:`MemoryTable` of each active branch (built on first use)."""
        if "tables" not in self._built:
            self._built["tables"] = tuple(MemoryTable(zi) for zi in self.zetas)
        return self._built["tables"]

    @property
    def table(self) -> KernelTable:
        """The antiderivative as one cubic table (built on first use); an elastic half-plane's
        is the Clausen function alone, tabulated on a uniform grid (its compiled influence loop
        is about three times faster than the closed form's numpy passes, equal to rounding)."""
        if "table" not in self._built:
            self._built["table"] = KernelTable.build(self.instantaneous, self.weights,
                                                     self.tables, self.correction)
        return self._built["table"]

    @classmethod
    def build(cls, kernel, rheology, zeta: float, tolerance: float | None = None) -> "PreparedKernel":
        """Tables for ``rheology`` at ``zeta``; ``tolerance`` (absolute, on the kernel's
        antiderivative per unit branch weight) widens the limits of :func:`branch_regimes`."""
        zeta = float(zeta)
        if not np.isfinite(zeta) or zeta < 0:
            raise ValueError(f"zeta = {zeta!r} is not allowed: expected a finite real >= 0")
        e0 = rheology.relaxed_modulus
        spec = rheology.creep_spectrum()
        k_inf = e0 * spec.instantaneous
        w_all = e0 * np.asarray(spec.weights, float)
        z_all = zeta * np.asarray(spec.times, float) / rheology.reference_time
        regime = branch_regimes(z_all, tolerance)
        inst = k_inf + float(np.sum(w_all[regime == RELAXED]))
        active = regime == ACTIVE
        w, z = w_all[active], z_all[active]
        corr, corr_v = None, None
        n_modes = kernel.correction_modes()
        if n_modes > 0:
            corr, corr_v = _correction_splines(kernel, k_inf, w_all, z_all, n_modes)
        return cls(kernel=kernel, zeta=zeta, instantaneous=inst, weights=w, zetas=z,
                   mean=float(kernel.mean_compliance()), correction=corr,
                   correction_values=corr_v, all_weights=w_all, all_zetas=z_all, k_inf=k_inf,
                   regimes=regime, tolerance=tolerance)

    def relaxation_lengths(self) -> np.ndarray:
        """``ζ τ_r,i/τ`` of the active branches, ascending: the memory lengths of the relaxation
        times of the creep spectrum ``K∞ + Σ w_i (1 - exp(-x/ζ_i))`` (the zeros of its Laplace
        transform, which interlace with the creep times; a standard linear solid has one,
        ``ζ/β``). Below the shortest one the solid is glassy; a stress carried by the slow
        branches reaches zero there, so a trailing edge of a stiff solid (large ``β``) has a
        boundary layer that wide. Empty without active branches."""
        return self.relaxation_spectrum()[0]

    def relaxation_spectrum(self) -> tuple[np.ndarray, np.ndarray]:
        """``(lengths, shares)``: :meth:`relaxation_lengths` and the share of the glassy
        modulus ``1/instantaneous`` that relaxes at each, ``E_i/(E0 + Σ E_j)`` of the relaxation
        function ``E0 + Σ E_i exp(-x/ℓ_i)`` of the active branches (the shares of a standard
        linear solid: ``1 - 1/β``). Empty without active branches."""
        if self.weights.size == 0 or self.instantaneous <= 0:
            return np.empty(0), np.empty(0)
        from ..rheology.prony import creep_to_relaxation

        relaxed, moduli, lengths = creep_to_relaxation(self.instantaneous, self.weights,
                                                       self.zetas)
        return lengths, moduli / (relaxed + float(np.sum(moduli)))

    # ---- Fourier view ----------------------------------------------------------------------
    def compliance(self, m):
        """``K(m) = K∞ + Σ w_i/(1 - i m ζ_i)`` (all branches, no limits applied)."""
        m = np.asarray(m, dtype=float)
        out = np.full(m.shape, self.k_inf, dtype=complex)
        for wi, zi in zip(self.all_weights, self.all_zetas):
            out = out + wi / (1.0 - 1j * m * zi)
        return out

    def multiplier(self, m):
        """Fourier multiplier: ``û_m = -(S_m K(m)/m) σ̂_m`` for ``m >= 1``."""
        m = np.asarray(m, dtype=float)
        return self.kernel.geometry_factors(m) * self.compliance(m)

    # ---- real space ------------------------------------------------------------------------
    # The evaluations below use the combined table (one interval search and one cubic per
    # function, :mod:`~viscocontact.kernels.table`); the ``*_terms`` methods assemble the same
    # functions from the pieces (Clausen, each branch's memory table, the layer correction) and
    # are the reference the table is tested against.
    def antiderivative(self, x):
        """``F̃(x) = ∫_0^x G̃(s) ds`` without the constant ``c0`` part (periodic, F̃(0) = 0)."""
        return self.table.antiderivative(x)

    def even_antiderivative(self, x):
        """``F̃(x) + F̃(-x)``: only the non-reciprocal (dissipative) part of the kernel survives.

        ``∫_e [G̃(ξ - y) - G̃(y - ξ)] dy = E(ξ - a) - E(ξ - b)`` with ``E`` this function; it vanishes
        identically for an elastic kernel (the Clausen part is odd).
        """
        return self.table.even(x)

    def antiderivative_pair(self, x):
        """``[F̃(x), F̃(x) + F̃(-x)]`` stacked (:meth:`antiderivative` and
        :meth:`even_antiderivative`, the same values) from one interval search."""
        return self.table.pair(x)

    def antiderivative_slope(self, x):
        """``F̃'(x)``: the derivative of :meth:`antiderivative` as computed (the tables'
        interpolants differentiated), i.e. the kernel without ``c0`` up to the tables' error.
        An influence coefficient ``F̃(ξ - a) - F̃(ξ - b) + c0 (b - a)`` changes with its element
        ends and collocation point by these slopes (:mod:`viscocontact.contact.sensitivity`)."""
        return self.table.slope(x)

    def slope_pair(self, x):
        """``[F̃'(x), E'(x)]`` stacked: :meth:`antiderivative_slope` and the derivative of
        :meth:`even_antiderivative` (``F̃'(x) - F̃'(-x)``, the non-reciprocal part of the kernel),
        from one interval search."""
        return self.table.slope_pair(x)

    def antiderivative_terms(self, x):
        """:meth:`antiderivative` from the pieces: ``-K Cl2`` in closed form, each branch's
        :meth:`MemoryTable.antiderivative` and the layer correction spline."""
        x = np.asarray(x, dtype=float)
        w = wrap(x)
        acc = cl2(w, wrapped=True)
        acc *= -self.instantaneous
        for wi, tab in zip(self.weights, self.tables):
            acc += wi * tab.antiderivative(w, wrapped=True)
        if self.correction is not None:
            acc += self.correction(np.mod(x, TWO_PI))
        acc /= np.pi
        return acc

    def even_antiderivative_terms(self, x):
        """:meth:`even_antiderivative` from the pieces (the Clausen part is odd and skipped)."""
        x = np.asarray(x, dtype=float)
        acc = np.zeros_like(x)
        for wi, tab in zip(self.weights, self.tables):
            acc = acc + wi * (tab.antiderivative(x) + tab.antiderivative(-x))
        if self.correction is not None:
            acc = acc + self.correction(np.mod(x, TWO_PI)) + self.correction(np.mod(-x, TWO_PI))
        return acc / np.pi

    def antiderivative_pair_terms(self, x):
        """:meth:`antiderivative_pair` from the pieces, sharing each memory table's evaluation
        at ``x``."""
        x = np.asarray(x, dtype=float)
        w = wrap(x)                      # once for every table (and -w is in [-π, π] too)
        out = np.empty((2,) + x.shape)
        acc, even = out[0], out[1]
        np.multiply(cl2(w, wrapped=True), -self.instantaneous, out=acc)
        even.fill(0.0)
        for wi, tab in zip(self.weights, self.tables):
            plus = tab.antiderivative(w, wrapped=True)
            acc += wi * plus
            plus += tab.antiderivative(-w, wrapped=True)
            even += wi * plus
        if self.correction is not None:
            plus = self.correction(np.mod(x, TWO_PI))
            acc += plus
            even += plus
            even += self.correction(np.mod(-x, TWO_PI))
        out /= np.pi
        return out

    def antiderivative_slope_terms(self, x):
        """:meth:`antiderivative_slope` from the pieces (``K g`` in closed form, each memory
        table's interpolant differentiated, the correction spline's derivative)."""
        x = np.asarray(x, dtype=float)
        acc = self.instantaneous * log_kernel(x)
        for wi, tab in zip(self.weights, self.tables):
            acc = acc + wi * tab.antiderivative_slope(x)
        if self.correction is not None:
            acc = acc + self.correction(np.mod(x, TWO_PI), 1)
        return acc / np.pi

    def slope_pair_terms(self, x):
        """:meth:`slope_pair` from the pieces."""
        x = np.asarray(x, dtype=float)
        w = wrap(x)
        acc = self.instantaneous * log_kernel(x)
        odd = np.zeros_like(x)
        for wi, tab in zip(self.weights, self.tables):
            plus = tab.antiderivative_slope(w, wrapped=True)
            acc += wi * plus
            plus -= tab.antiderivative_slope(-w, wrapped=True)
            odd += wi * plus
        if self.correction is not None:
            plus = self.correction(np.mod(x, TWO_PI), 1)
            acc = acc + plus
            odd = odd + plus - self.correction(np.mod(-x, TWO_PI), 1)
        return np.stack([acc / np.pi, odd / np.pi])

    def values(self, x):
        """The kernel ``G̃_V(x)`` of eq. 4.19 (times ``S_m`` geometry, plus ``c0``) at points ``x``."""
        x = np.asarray(x, dtype=float)
        acc = self.instantaneous * log_kernel(x)
        for wi, tab in zip(self.weights, self.tables):
            acc = acc + wi * tab.values(x)
        if self.correction_values is not None:
            acc = acc + self.correction_values(np.mod(x, TWO_PI))
        return acc / np.pi + self.mean

    def influence(self, collocation, left, right):
        """Influence matrix ``B[l, q] = ∫_{left_q}^{right_q} G̃(ξ_l - η) dη`` (eq. 4.32).

        Parameters
        ----------
        collocation : (N,) array
            Collocation points ``ξ_l``.
        left, right : (M,) arrays
            Element ends (``right > left``), on any union of intervals.
        """
        a = np.asarray(left, dtype=float)
        b = np.asarray(right, dtype=float)
        return element_integrals(self.antiderivative, collocation, a, b) + self.mean * (b - a)


RELAXED, ACTIVE, FROZEN = "relaxed", "active", "frozen"
_APERY = 1.2020569031595942          # ζ(3) = Σ 1/m³


def relaxed_error_bound(memory_length):
    """Bound on ``|(M_ζ[Φ](x) - M_ζ[Φ](0)) - (Φ(x) - Φ(0))|`` for ``ζ < 1``: the change of the
    antiderivative when a branch is taken as relaxed. With ``Φ = -Cl2 = -Σ sin(mx)/m²`` and
    ``|1 - 1/(1 - imζ)| <= min(mζ, 1)``: ``2[ζ Σ_{m<1/ζ} 1/m + Σ_{m>=1/ζ} 1/m²] <= 2ζ(2 + ln(1/ζ))``."""
    z = np.asarray(memory_length, dtype=float)
    with np.errstate(divide="ignore"):
        return 2.0 * z * (2.0 + np.log(1.0 / z))


def frozen_error_bound(memory_length):
    """Bound on ``|M_ζ[Φ](x) - M_ζ[Φ](0)|`` for ``ζ > 1``: what a branch taken as frozen leaves
    out (``|1/(1 - imζ)| <= 1/(mζ)``, so ``|M_ζ[Φ]| <= ζ(3)/ζ``)."""
    return 2.0 * _APERY / np.asarray(memory_length, dtype=float)


def branch_regimes(memory_lengths, tolerance: float | None = None) -> np.ndarray:
    """How each creep branch enters the kernel: ``"relaxed"``, ``"active"`` or ``"frozen"``.

    A branch of memory length ``ζ_i`` is relaxed below ``ZETA_RELAXED`` and frozen above
    ``ZETA_FROZEN``. With a ``tolerance`` the band narrows to where the memory integral matters:
    a branch is taken as relaxed (frozen) when that changes the antiderivative of the kernel, per
    unit branch weight, by at most ``tolerance`` (:func:`relaxed_error_bound`,
    :func:`frozen_error_bound`).
    """
    z = np.asarray(memory_lengths, dtype=float)
    relaxed = z < ZETA_RELAXED
    frozen = z > ZETA_FROZEN
    if tolerance is not None:
        with np.errstate(divide="ignore", invalid="ignore"):
            relaxed |= (z < 1.0) & (relaxed_error_bound(z) <= tolerance)
            frozen |= (z > 1.0) & (frozen_error_bound(z) <= tolerance)
    return np.where(relaxed, RELAXED, np.where(frozen, FROZEN, ACTIVE))


#: Target number of kernel evaluations per block of rows in :func:`element_integrals`: the
#: temporaries of one table look-up (a few arrays of this size) then stay in the CPU cache.
BLOCK_SIZE = 1 << 14


def _table_parts(antiderivative):
    """``(table, parts)`` when ``antiderivative`` is :meth:`PreparedKernel.antiderivative`,
    ``antiderivative_pair`` or ``even_antiderivative`` of a prepared kernel (a subclass that
    overrides one of them keeps its own), else None."""
    owner = getattr(antiderivative, "__self__", None)
    if not isinstance(owner, PreparedKernel):
        return None
    parts = _TABLE_PARTS.get(getattr(antiderivative, "__func__", None))
    return None if parts is None else (owner.table, parts)


_TABLE_PARTS = {PreparedKernel.antiderivative: "F", PreparedKernel.antiderivative_pair: "FE",
                PreparedKernel.even_antiderivative: "E"}
_TABLE_SLOPES: dict[object, str] = {PreparedKernel.antiderivative_slope: "F",
                                    PreparedKernel.slope_pair: "FE"}


def element_integrals(antiderivative, points, left, right, block: int = BLOCK_SIZE) -> np.ndarray:
    """``F(ξ_l - a_q) - F(ξ_l - b_q)`` for an antiderivative ``F``: integrals over elements.

    Neighbouring elements share an end (``b_q = a_{q+1}``), so ``F`` is evaluated once per
    distinct end, about half the work of evaluating both ends of every element; when the
    elements come in chains of neighbours (a mesh's contacts), the element integrals are
    differences of neighbouring columns, taken by slices. ``F`` may return
    several functions stacked along leading axes (shape ``(k,) + x.shape``, e.g.
    :meth:`PreparedKernel.antiderivative_pair`); so does the result. ``F`` is called on blocks
    of rows of about ``block`` points each (the result does not depend on it).

    The table-backed antiderivatives of a :class:`PreparedKernel` go to the compiled loop
    (:meth:`KernelTable.element_integrals`): the same values up to rounding, 1.2-1.5 times
    faster on the meshes of a rough solve (``benchmarks/influence_loop.py``).
    """
    compiled = _table_parts(antiderivative)
    if compiled is not None:
        table, parts = compiled
        return table.element_integrals(points, left, right, parts)
    xi = np.asarray(points, dtype=float)
    a = np.asarray(left, dtype=float)
    b = np.asarray(right, dtype=float)
    starts = np.flatnonzero(a[1:] != b[:-1]) + 1
    if a.size > 1 and 4 * (starts.size + 1) <= a.size:
        # chains of adjacent elements (the contacts of a mesh): F at each chain's nodes, and
        # every element the difference of two neighbouring columns, by slices (no gather)
        starts = np.concatenate([[0], starts])
        stops = np.append(starts[1:], a.size)
        nodes = np.concatenate([np.append(a[s:e], b[e - 1]) for s, e in zip(starts, stops)])

        def chains(values, out):
            k = 0
            for s, e in zip(starts, stops):
                np.subtract(values[..., k:k + e - s], values[..., k + 1:k + e - s + 1],
                            out=out[..., s:e])
                k += e - s + 1

        return _row_blocks(antiderivative, xi, nodes, a.size, chains, block)
    ends, where = np.unique(np.concatenate([a, b]), return_inverse=True)
    where = where.ravel()
    lo: slice | np.ndarray
    hi: slice | np.ndarray
    if ends.size == a.size + b.size:        # no shared ends: both ends of every element
        ends = np.concatenate([a, b])
        lo, hi = slice(0, a.size), slice(a.size, None)
    else:
        lo, hi = where[:a.size], where[a.size:]

    def gather(values, out):
        np.subtract(values[..., lo], values[..., hi], out=out)

    return _row_blocks(antiderivative, xi, ends, a.size, gather, block)


def pairwise(function, points, ends, block: int = BLOCK_SIZE) -> np.ndarray:
    """``function(ξ_l - e_k)`` for every point and end (shape ``(k,) + (N, M)`` when
    ``function`` stacks ``k`` functions), evaluated on blocks of rows as in
    :func:`element_integrals`. The table-backed slopes of a :class:`PreparedKernel`
    (:meth:`~PreparedKernel.antiderivative_slope`, :meth:`~PreparedKernel.slope_pair`) go to
    the compiled loop (:meth:`KernelTable.pairwise_slopes`)."""
    owner = getattr(function, "__self__", None)
    parts = _TABLE_SLOPES.get(getattr(function, "__func__", None))
    if isinstance(owner, PreparedKernel) and parts is not None:
        return owner.table.pairwise_slopes(points, ends, parts)
    xi = np.asarray(points, dtype=float)
    ends = np.asarray(ends, dtype=float)

    def copy(values, out):
        out[...] = values

    return _row_blocks(function, xi, ends, ends.size, copy, block)


def _row_blocks(antiderivative, xi, ends, n_out, combine, block):
    """``combine(F(ξ_rows - ends), out_rows)`` over blocks of rows into one new array."""
    rows = max(1, block // max(ends.size, 1))
    out = None
    for r0 in range(0, max(xi.size, 1), rows):
        r1 = min(r0 + rows, xi.size)
        values = antiderivative(xi[r0:r1, None] - ends[None, :])
        if out is None:
            out = np.empty(values.shape[:-2] + (xi.size, n_out))
        combine(values, out[..., r0:r1, :])
    return out


def _correction_splines(kernel, k_inf, w_all, z_all, n_modes):
    """Layer correction ``Σ_m (A_m/m) Re[K e^{imx}]`` and its antiderivative on an FFT grid."""
    m = np.arange(1, n_modes + 1, dtype=float)
    a_m = 1.0 - kernel.geometry_factors(m)
    k_m = np.full(m.shape, k_inf, dtype=complex)
    for wi, zi in zip(w_all, z_all):
        k_m = k_m + wi / (1.0 - 1j * m * zi)
    n = 1 << int(np.ceil(np.log2(max(4096, 32 * n_modes))))
    spec_f = np.zeros(n, dtype=complex)
    spec_g = np.zeros(n, dtype=complex)
    spec_f[1:n_modes + 1] = a_m * k_m / m**2
    spec_g[1:n_modes + 1] = a_m * k_m / m
    sum_f = np.fft.ifft(spec_f) * n      # Σ c_m e^{i m x_k}
    sum_g = np.fft.ifft(spec_g) * n
    x = np.linspace(0.0, TWO_PI, n + 1)
    f = np.append(sum_f.imag - np.sum(spec_f).imag, 0.0)
    f[-1] = f[0]
    g = np.append(sum_g.real, sum_g.real[0])
    return CubicSpline(x, f, bc_type="periodic"), CubicSpline(x, g, bc_type="periodic")
