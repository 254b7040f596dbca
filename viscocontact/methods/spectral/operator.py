r"""The circulant operator of a uniform grid: eigenvalues from the prepared kernel, FFT products.

``N`` cells of width ``h = 2π/N`` carry constant pressures ``p_k = -σ̃_k``; the displacement at the
cell centres is ``u = A p`` (units of the normalised heights ``r̃``, positive into the solid), with
``A`` circulant. From the Fourier multiplier of the prepared kernel (``û_m = -(S_m K(m)/m) σ̂_m``
for ``m >= 1``, the conjugate for ``m <= -1``, ``û_0 = 2π c0 σ̂_0``; eqs. 2.40-2.47, 4.19) and the
spectrum of a piecewise-constant field, the eigenvalues are the alias sums

.. math:: Λ_n = \sum_{l\in\mathbb Z} λ(n + lN)\,\mathrm{sinc}\big((n + lN)h/2\big), \qquad
          λ(m) = \frac{S_{|m|} K(m)}{|m|}\ (m > 0), \quad \overline{λ(-m)}\ (m < 0),

and ``Λ_0 = -2π c0``. The part ``K_s/|m|`` with ``K_s`` the prepared kernel's ``instantaneous``
compliance (``K∞`` plus the branches taken as relaxed) is summed in closed form: it is the exact
cell influence of the log kernel, ``A_j0 = (K_s/π)[Cl2(x_j + h/2) - Cl2(x_j - h/2)]``, whose FFT
gives its eigenvalues to round-off. The rest, ``(S K(m) - K_s)/|m|``, is summed over
``|l| <= max(ALIASES, ALIAS_TERMS/N)``; its terms alternate in sign with ``l`` (``sinc`` does),
and the partial sums are averaged twice (weights 3/4 and 1/4 on the last two pairs of terms),
which leaves a relative error below 1e-7 against 8192 aliases (measured at most 9e-8 for an SLS
with ζ from 1e-6 to 0.1 on the half-plane and a confined layer, 32 to 8192 cells; a unit test
checks 1e-7). It is skipped when the multiplier equals ``K_s`` (elastic half-plane).

The power that a pressure field feeds into the solid per unit sliding speed is
``-∫ p u' dx = 2π Σ_{m≠0} Im[S_{|m|} K(|m|)] |p̂_m|²`` (``docs/kernels.md``), for the
piecewise-constant field ``Σ_n |P_n|² D_n`` with ``P_n`` the discrete Fourier coefficients and the weights

.. math:: D_n = \sum_{l} \mathrm{Im}\big[S K\big](|n + lN|)\,\mathrm{sinc}^2\big((n + lN)h/2\big),

summed over ``|l| <= max(DISSIPATION_ALIASES, ALIAS_TERMS/N)`` plus the integral of the tail over
the creep branches (``Im K(m) = Σ_i w_i mζ_i/(1 + m²ζ_i²)``,
``∫_M^∞ Im K/m² dm = Σ_i (w_i ζ_i/2) ln(1 + 1/(Mζ_i)²)``, midpoint rule in ``l``): the power of a
solution on the thesis's rough profile moves by less than 2e-7 from 4 to 256 aliases.
"""
from __future__ import annotations

import attrs
import numpy as np
import scipy.fft

from ...kernels.clausen import TWO_PI, cl2

#: Aliases summed on each side for the non-closed-form part of the eigenvalues, at least; a
#: coarse grid takes ``ALIAS_TERMS // N`` (its terms decay more slowly in ``l``, and are cheap).
ALIASES = 8
ALIAS_TERMS = 1 << 14
#: Aliases summed on each side for the loss weights (not alternating: an integral tail is added).
DISSIPATION_ALIASES = 4
#: ``max|Im Λ| <= SYMMETRIC·max|Λ|``: the operator is taken as symmetric (elastic, or ζ at a limit).
SYMMETRIC = 1e-12


def _readonly(a):
    a = np.array(a, copy=True)
    a.setflags(write=False)
    return a


#: Alias terms evaluated at once (bounds the memory of the vectorised sums).
_BLOCK = 1 << 20


def _alias_sum(n_cells: int, aliases: int, term, weights=None) -> np.ndarray:
    """``Σ_{|l| <= aliases} weight_l · term(m, sign_l)`` over ``m = n + l N`` for ``n = 0..N/2``
    (the term at ``m = 0`` skipped), in blocks of aliases; ``term(m, l)`` gets float arrays."""
    n = np.arange(n_cells // 2 + 1, dtype=float)
    ls = np.arange(-aliases, aliases + 1)
    w = np.ones(ls.shape) if weights is None else weights
    total = None
    rows = max(1, _BLOCK // n.size)
    for i in range(0, ls.size, rows):
        block = ls[i:i + rows].astype(float)
        m = n[None, :] + n_cells * block[:, None]
        zero = m == 0.0
        m = np.where(zero, 1.0, m)
        value = term(m, block[:, None])
        value = np.where(zero, 0.0, value) * w[i:i + rows, None]
        part = value.sum(axis=0)
        total = part if total is None else total + part
    assert total is not None, "aliases >= 0: at least one block"
    return total


def eigenvalues(kernel, points: int, aliases: int | None = None) -> np.ndarray:
    """Eigenvalues ``Λ_n`` (``n = 0..N/2``, rfft layout) of the cell-to-centre operator ``A``.

    Parameters
    ----------
    kernel : PreparedKernel
        The prepared kernel (:meth:`~viscocontact.kernels.base.GreenKernel.prepare`): its
        ``multiplier``, ``instantaneous`` and ``mean``.
    points : int
        Number of cells ``N`` (even).
    aliases : int, optional
        Aliases summed on each side for the part without closed form (default
        ``max(ALIASES, ALIAS_TERMS // points)``).
    """
    n_cells = int(points)
    if aliases is None:
        aliases = max(ALIASES, ALIAS_TERMS // n_cells)
    h = TWO_PI / n_cells
    k_split = float(kernel.instantaneous)
    ends = cl2(h * (np.arange(n_cells) + 0.5))          # Cl2 at the cell ends (j + 1/2) h
    column = (k_split / np.pi) * (ends - np.roll(ends, 1))
    lam = scipy.fft.rfft(column).astype(complex)
    probe = np.array([1.0, 2.0, 10.0, 1e3, 1e6])
    if np.any(np.asarray(kernel.multiplier(probe)) != k_split):
        # sinc((n + lN)h/2) = (-1)^l sin(nπ/N) / ((n + lN)π/N)
        sine = np.sin(np.pi * np.arange(n_cells // 2 + 1) / n_cells)

        def rest(m, l):
            am = np.abs(m)
            value = np.asarray(kernel.multiplier(am), dtype=complex) - k_split
            value = np.where(m > 0, value, np.conj(value))
            sign = 1.0 - 2.0 * (np.abs(l) % 2)
            return value / am * sign * sine * (n_cells / (np.pi * m))

        weights = np.ones(2 * aliases + 1)
        weights[[0, -1]] = 0.25                # the mean of the last three partial sums, each
        weights[[1, -2]] = 0.75                # the mean of two consecutive ones
        lam += _alias_sum(n_cells, aliases, rest, weights)
    lam[0] = -TWO_PI * float(kernel.mean)         # û_0 = 2π c0 σ̂_0 = -2π c0 p̂_0
    lam[-1] = lam[-1].real                        # Nyquist mode of a real circulant
    return lam


def dissipation_weights(kernel, points: int, aliases: int | None = None) -> np.ndarray:
    """Weights ``D_n`` (``n = 0..N/2``) of the power fed into the solid (module docstring)."""
    n_cells = int(points)
    if aliases is None:
        aliases = max(DISSIPATION_ALIASES, ALIAS_TERMS // n_cells)
    n = np.arange(n_cells // 2 + 1, dtype=float)
    weights = np.asarray(kernel.all_weights, float)
    zetas = np.asarray(kernel.all_zetas, float)
    if not np.any((weights != 0.0) & (zetas > 0.0) & np.isfinite(zetas)):
        return np.zeros(n.shape)                 # no dissipative branch: no loss
    # sinc²((n + lN)h/2) = sin²(nπ/N) (N/((n + lN)π))²
    scale = (n_cells * np.sin(np.pi * n / n_cells) / np.pi) ** 2

    def loss(m, l):
        return np.asarray(kernel.multiplier(np.abs(m))).imag / (m * m)

    out = _alias_sum(n_cells, aliases, loss)
    # tail |l| > aliases by the midpoint rule: Σ_{l>L} g(n + lN) ≈ (1/N) ∫_{n+(L+1/2)N}^∞ g
    upper = n + (aliases + 0.5) * n_cells
    lower = (aliases + 0.5) * n_cells - n
    tail = np.zeros(n.shape)
    for w, z in zip(weights, zetas):
        if w == 0.0 or z == 0.0 or not np.isfinite(z):
            continue
        for start in (upper, lower):
            tail += 0.5 * w * z * np.log1p(1.0 / (start * z) ** 2)
    out = scale * (out + tail / n_cells)
    out[0] = 0.0
    return out


@attrs.frozen(kw_only=True, eq=False)
class Circulant:
    """The circulant operator of one prepared kernel on ``points`` cells (read-only tables).

    Attributes
    ----------
    points : int
    eigenvalues : ndarray, complex, shape (points // 2 + 1,)
        ``Λ_n`` (module docstring).
    inverse : ndarray, complex
        ``1/Λ_n``; the mean mode, where ``Λ_0`` vanishes on an incompressible solid, takes
        ``1/|Λ_1|`` (a preconditioner only ever sees it restricted to a contact set).
    symmetric : bool
        ``max|Im Λ| <= SYMMETRIC·max|Λ|``: the operator is symmetric to round-off.
    """

    points: int
    eigenvalues: np.ndarray = attrs.field(converter=_readonly)
    inverse: np.ndarray = attrs.field(converter=_readonly)
    symmetric: bool

    @classmethod
    def build(cls, kernel, points: int) -> "Circulant":
        """The operator of ``kernel`` (a PreparedKernel) on ``points`` cells."""
        lam = eigenvalues(kernel, points)
        inverse = invert(lam)
        symmetric = bool(np.max(np.abs(lam.imag)) <= SYMMETRIC * np.max(np.abs(lam)))
        return cls(points=int(points), eigenvalues=lam, inverse=inverse, symmetric=symmetric)

    def symmetric_part(self) -> np.ndarray:
        """Eigenvalues of ``(A + Aᵀ)/2`` (``Re Λ``)."""
        return self.eigenvalues.real.astype(complex)


def invert(spectrum: np.ndarray) -> np.ndarray:
    """``1/Λ_n``, with ``1/|Λ_1|`` for a vanishing mean mode (an incompressible solid); any
    number of dimensions (the mean mode first, ``Λ_1`` the next entry of the flat layout)."""
    lam = np.asarray(spectrum, dtype=complex)
    flat = lam.ravel()
    out = np.empty_like(flat)
    out[1:] = 1.0 / flat[1:]
    out[0] = 1.0 / flat[0] if flat[0] != 0 else 1.0 / abs(flat[1])
    return out.reshape(lam.shape)


def power(pressure: np.ndarray, weights: np.ndarray, workers: int = 1) -> float:
    """``-(1/2π)∫ p u' dx`` of a piecewise-constant pressure with the loss weights ``D_n``
    (:func:`dissipation_weights`): the power fed into the solid per unit sliding speed and period
    length, in the units of ``p`` times ``r̃``."""
    n = len(pressure)
    spec = np.abs(scipy.fft.rfft(pressure, workers=workers)) ** 2 / n**2
    spec[1:-1] *= 2.0                   # the modes n and N - n together
    return float(spec @ weights)


def convolve(values: np.ndarray, spectrum: np.ndarray, workers: int = 1) -> np.ndarray:
    """``irfft(spectrum · rfft(values))``: a circulant product by FFT.

    A 2D ``spectrum`` of shape ``(ny, nx//2 + 1)`` (the rfft2 layout, ``nx`` even) is the
    operator of an ``(ny, nx)`` periodic grid, and ``values`` its cells flattened row by row:
    the solvers see flat vectors in every dimension. A single-precision 2D ``spectrum``
    (``complex64``) gives the product in single precision."""
    if np.ndim(spectrum) == 1:
        n = len(values)
        return scipy.fft.irfft(spectrum * scipy.fft.rfft(values, workers=workers), n,
                               workers=workers)
    # the 2D transform one axis at a time, the complex passes in place: the same arithmetic as
    # rfft2/irfft2 (the same bits), 1.5-1.7 times faster on 1024² and 2048² grids (rfft2's
    # complex pass copies the half spectrum, and the product with the spectrum another)
    ny, nx = spectrum.shape[0], 2 * (spectrum.shape[1] - 1)
    grid = np.reshape(values, (ny, nx))
    if spectrum.dtype == np.complex64:
        grid = grid.astype(np.float32)
    half = scipy.fft.rfft(grid, axis=1, workers=workers)
    half = scipy.fft.fft(half, axis=0, workers=workers, overwrite_x=True)
    half *= spectrum
    half = scipy.fft.ifft(half, axis=0, workers=workers, overwrite_x=True)
    return scipy.fft.irfft(half, nx, axis=1, workers=workers, overwrite_x=True).ravel()


class OperatorCache:
    """Circulant operators per (prepared kernel, number of cells), built on first use.

    An explicit cache that a caller keeps along a sweep at fixed ζ (it is held by
    :class:`~viscocontact.methods.spectral.SpectralPrepared`); it holds a reference to each
    prepared kernel it has seen, so that a key is never reused by another kernel object.
    """

    def __init__(self):
        self._tables: dict[tuple[str, int, int], tuple[object, object]] = {}

    def _get(self, what: str, kernel, points: int, build):
        key = (what, id(kernel), int(points))
        hit = self._tables.get(key)
        if hit is None or hit[0] is not kernel:
            hit = (kernel, build(kernel, int(points)))
            self._tables[key] = hit
        return hit[1]

    def circulant(self, kernel, points: int) -> Circulant:
        """The :class:`Circulant` of ``kernel`` on ``points`` cells."""
        return self._get("circulant", kernel, points, Circulant.build)

    def dissipation(self, kernel, points: int) -> np.ndarray:
        """The loss weights ``D_n`` of ``kernel`` on ``points`` cells (read-only)."""
        return self._get("dissipation", kernel, points,
                         lambda k, n: _readonly(dissipation_weights(k, n)))

    def __len__(self) -> int:
        return len(self._tables)
