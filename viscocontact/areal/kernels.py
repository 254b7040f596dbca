r"""Steady-sliding response of a viscoelastic half-space or layer to an areal pressure field.

A rigid surface slides at speed ``V`` along the unit vector ``e = (cos θ, sin θ)`` of the plane.
In the frame of the surface every Fourier mode ``exp(i q·x)`` of the pressure is a travelling
wave that the solid sees at the angular frequency ``ω = (q·e) V``; one plane wave is a plane-
strain problem in the frame turned to ``q``, so its displacement is that of the 1D kernels
(:mod:`viscocontact.kernels`) at the wavenumber ``|q|`` with the compliance taken at ``q·e``:

.. math:: \hat u(\mathbf q) = λ(\mathbf q)\,\hat p(\mathbf q), \qquad
          λ(\mathbf q) = \frac{S(|\mathbf q|)\,K(\mathbf q\cdot\mathbf e)}{|\mathbf q|}, \qquad
          K(m) = K_\infty + \sum_i \frac{w_i}{1 - i m ζ_i},

in the dimensionless groups of thesis eq. 4.17 (``q`` in units of ``q0 = 2π/L_x``, ``ζ_i = q0 V
θ_i``; ``p = -σ̃``, ``u`` positive into the solid). ``S`` is the geometry factor of the 1D kernel
(1 for the half-space, ``1 - A(|q| d)`` for the confined and free layers of eqs. 2.42-2.43,
functions of ``|q| d``) and the mean mode is ``û_0 = -2π c0 p̂_0`` (eq. 2.44). A mode that does
not vary along the sliding direction (``q·e = 0``) sees the relaxed modulus ``E0``. For ``q·e``
of either sign ``K(-m) = \overline{K(m)}``, so ``λ(-q) = \overline{λ(q)}`` and the operator maps
real fields to real fields.

Grid operator. On ``nx × ny`` cells of constant pressure, collocated at the centres, the operator
is a 2D circulant whose eigenvalues are the alias sums

.. math:: Λ_{nj} = \sum_{l,k} λ(n + l n_x, (j + k n_y)/a)\,
          \mathrm{sinc}\Big(\frac{n + l n_x}{n_x}\Big)\,\mathrm{sinc}\Big(\frac{j + k n_y}{n_y}\Big)

(``a`` the cell's aspect ratio, ``sinc(t) = sin(πt)/(πt)``), summed over ``|l|, |k| <= L``
(:data:`ALIASES`) with the outermost two partial sums averaged as in
:func:`~viscocontact.methods.spectral.operator.eigenvalues`. The row ``j = 0`` (fields that do
not depend on ``y``) only has the ``k = 0`` term, ``sinc(k) = 0`` otherwise: it is the 1D
operator, and with ``e = x`` it is taken from the 1D method's eigenvalues (closed form of the
instantaneous part and its alias sums) so that a surface extruded along ``y`` gives the 1D
method's solution to round-off.

The power that the pressure feeds into the solid per unit sliding speed and unit area is
``-<p ∂u/∂s> = Σ_q |P_q|² D_q`` with ``D_q = Σ_{l,k} (q·e) Im λ(q) sinc² sinc²`` over the same
aliases (non-negative for every rheology).
"""
from __future__ import annotations

from typing import cast

import attrs
import numpy as np

from .._validation import in_range, positive
from ..kernels.clausen import TWO_PI
from ..kernels.base import GreenKernel
from ..kernels.prepared import PreparedKernel
from ..methods.spectral.operator import Circulant, dissipation_weights, eigenvalues, invert

#: Aliases summed on each side in each direction (the partial sums' last two averaged): at 4
#: the eigenvalues are within 0.2 % of 40 aliases' (median 0.06 %, elastic half-space, 64²; at
#: 2, 18 % and 5 %), the row ``qy = 0`` exact (the 1D operator).
ALIASES = 4
#: ``max|Im Λ| <= SYMMETRIC·max|Λ|``: the operator is taken as symmetric.
SYMMETRIC = 1e-12


def wavenumbers(nx: int, ny: int, aspect: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """``(qx, qy)`` of the rfft2 layout of an ``(ny, nx)`` grid of the cell
    ``[0, 2π) × [0, 2π·aspect)``, in units of ``q0``: arrays of shape ``(ny, nx//2 + 1)``."""
    qx = np.arange(nx // 2 + 1, dtype=float)
    qy = np.fft.fftfreq(ny, 1.0 / ny) / aspect
    return np.meshgrid(qx, qy)


def _alias_weights(aliases: int) -> np.ndarray:
    w = np.ones(2 * aliases + 1)
    if aliases >= 1:
        w[[0, -1]] = 0.25          # the mean of the last three partial sums, each
        w[[1, -2]] = 0.75          # the mean of two consecutive ones
    return w


@attrs.frozen(kw_only=True, eq=False)
class ArealKernel:
    """A 1D prepared kernel (rheology, ``ζ``, geometry) seen by an areal surface.

    Build with :meth:`prepare`. The Fourier multiplier, the grid eigenvalues and the loss weights
    follow from the 1D kernel's ``compliance`` (every registered rheology) and
    ``geometry_factors`` (half-plane, confined and free layers) as the module docstring says.

    Attributes
    ----------
    prepared : PreparedKernel
        The 1D kernel (:meth:`GreenKernel.prepare`).
    direction : float
        Angle ``θ`` (radians) of the sliding direction from the ``x̃`` axis, in ``[-π, π]``.
    aspect : float
        ``L_y/L_x`` of the cell.

    Examples
    --------
    Across the sliding direction the solid is relaxed (``K = 1``); along it, at ``ζ → ∞``, a
    standard linear solid is ``β`` times stiffer:

    >>> from viscocontact.kernels.half_plane import HalfPlane
    >>> from viscocontact.rheology import StandardLinearSolid
    >>> k = ArealKernel.prepare(HalfPlane(), StandardLinearSolid(beta=10.0), 1e12)
    >>> complex(k.multiplier(0.0, 2.0)), round(complex(k.multiplier(2.0, 0.0)).real, 6)
    ((0.5+0j), 0.05)
    """

    prepared: PreparedKernel
    direction: float = attrs.field(default=0.0, validator=in_range(-np.pi, np.pi))
    aspect: float = attrs.field(default=1.0, validator=positive)

    @classmethod
    def prepare(cls, kernel, rheology, zeta: float, *, direction: float = 0.0,
                aspect: float = 1.0) -> "ArealKernel":
        """The kernel of ``kernel`` (a :class:`~viscocontact.kernels.base.GreenKernel`) for
        ``rheology`` at ``ζ = q0 V τ``, sliding at ``direction`` on a cell of ``aspect``."""
        return cls(prepared=kernel.prepare(rheology, zeta), direction=float(direction),
                   aspect=float(aspect))

    @property
    def geometry(self) -> GreenKernel:
        """The 1D kernel's geometry (half-plane, layers)."""
        return cast(GreenKernel, self.prepared.kernel)

    @property
    def along_x(self) -> bool:
        """Sliding along ``x̃``: the row ``qy = 0`` is the 1D operator."""
        return self.direction == 0.0

    def frequency(self, qx, qy) -> np.ndarray:
        """``q·e``, the wavenumber along the sliding direction."""
        return (np.cos(self.direction) * np.asarray(qx, float)
                + np.sin(self.direction) * np.asarray(qy, float))

    def multiplier(self, qx, qy) -> np.ndarray:
        """``λ(q) = S(|q|) K(q·e)/|q|`` (0 at ``q = 0``; the mean mode is ``-2π c0``);
        ``qx`` and ``qy`` broadcast against each other."""
        qx, qy = np.asarray(qx, float), np.asarray(qy, float)
        q = np.hypot(qx, qy)
        zero = q == 0.0
        qs = np.where(zero, 1.0, q)
        # sliding along x̃: the compliance depends on qx alone (evaluated once per column)
        k = self.prepared.compliance(qx if self.along_x else self.frequency(qx, qy))
        geometry = (1.0 if self.geometry.correction_modes() == 0
                    else self.geometry.geometry_factors(qs))
        value = geometry * k / qs
        return np.where(zero, 0.0, value)

    def loss(self, qx, qy) -> np.ndarray:
        """``(q·e) Im λ(q)``: the power density weight of a mode (>= 0)."""
        return self.frequency(qx, qy) * np.imag(self.multiplier(qx, qy))

    # ---- the grid operator -------------------------------------------------------------------
    def _radial(self, q: np.ndarray) -> np.ndarray:
        """``S(|q|)/|q|`` with 0 at ``q = 0``."""
        zero = q == 0.0
        if zero.any():
            q = np.where(zero, 1.0, q)
        inv = 1.0 / q
        if self.geometry.correction_modes() != 0:
            inv = self.geometry.geometry_factors(q) * inv
        if zero.any():
            inv[np.broadcast_to(zero, inv.shape)] = 0.0
        return inv

    def _alias_sum(self, nx: int, ny: int, aliases: int, power: int, row, weights) -> np.ndarray:
        """``Σ_{l,k} w_l w_k row(q·e) S(|q|)/|q| (sinc_x sinc_y)^power`` over ``q = (n + l nx,
        (j + k ny)/a)``; with ``e = x`` the row factor is taken out of the inner sum over ``k``
        (it depends on ``qx`` alone), which leaves real arrays there, even in ``qy``: the rows
        ``qy <= 0`` are those of ``-qy``, summed once (half the work)."""
        n = np.arange(nx // 2 + 1, dtype=float)[None, :]      # integer indices, broadcast
        j = np.fft.fftfreq(ny, 1.0 / ny)[:, None]
        if self.along_x:
            j = j[:ny // 2 + 1]                               # 0, 1, ..., ny/2 - 1, -ny/2
        total = np.zeros((j.size, nx // 2 + 1), dtype=complex)
        for l, wl in zip(range(-aliases, aliases + 1), weights):
            mx = n + l * nx
            sx = wl * np.sinc(mx / nx) ** power
            inner = np.zeros(total.shape, dtype=complex if not self.along_x else float)
            for k, wk in zip(range(-aliases, aliases + 1), weights):
                my = (j + k * ny) / self.aspect
                part = self._radial(np.hypot(mx, my)) * (wk * np.sinc((j + k * ny) / ny) ** power)
                inner += part if self.along_x else part * row(self.frequency(mx, my))
            total += (sx * row(mx)) * inner if self.along_x else sx * inner
        if self.along_x:
            total = np.concatenate([total, total[ny // 2 - 1:0:-1]])
        return total

    def eigenvalues(self, nx: int, ny: int, aliases: int = ALIASES) -> np.ndarray:
        """``Λ_{nj}`` of the ``(ny, nx)`` grid in the rfft2 layout, shape ``(ny, nx//2 + 1)``."""
        _check_grid(nx, ny)
        lam = self._alias_sum(nx, ny, aliases, 1, self.prepared.compliance,
                              _alias_weights(aliases))
        if self.along_x:
            lam[0] = eigenvalues(self.prepared, nx)
        lam[0, 0] = -TWO_PI * float(self.prepared.mean)
        return _hermitian(lam)

    def dissipation_weights(self, nx: int, ny: int, aliases: int = ALIASES) -> np.ndarray:
        """``D_{nj}`` (module docstring), shape ``(ny, nx//2 + 1)``; the row ``qy = 0`` from the
        1D method's weights when sliding along ``x̃``."""
        _check_grid(nx, ny)
        d = self._alias_sum(nx, ny, aliases, 2,
                            lambda m: m * np.imag(self.prepared.compliance(m)),
                            np.ones(2 * aliases + 1)).real
        if self.along_x:
            d[0] = dissipation_weights(self.prepared, nx)
        d[0, 0] = 0.0
        return d

    def circulant(self, nx: int, ny: int) -> Circulant:
        """The grid operator as the spectral method's :class:`Circulant` (flat cells, row by
        row; :func:`~viscocontact.methods.spectral.operator.convolve` reads the 2D layout)."""
        lam = self.eigenvalues(nx, ny)
        symmetric = bool(np.max(np.abs(lam.imag)) <= SYMMETRIC * np.max(np.abs(lam)))
        return Circulant(points=nx * ny, eigenvalues=lam, inverse=invert(lam),
                         symmetric=symmetric)


def _check_grid(nx: int, ny: int) -> None:
    from ..errors import ValidationError

    for name, n in (("nx", nx), ("ny", ny)):
        if isinstance(n, bool) or int(n) != n or n < 2 or n % 2:
            raise ValidationError(f"grid.{name}", n, "an even integer >= 2")


def _hermitian(lam: np.ndarray) -> np.ndarray:
    """The columns ``n = 0`` and ``n = nx/2`` of a real operator obey ``Λ(-q) = conj Λ(q)``
    within the column: the alias sums, truncated, nearly do; make them exact."""
    out = lam.copy()
    ny = lam.shape[0]
    flip = (-np.arange(ny)) % ny
    for c in (0, -1):
        out[:, c] = 0.5 * (lam[:, c] + np.conj(lam[flip, c]))
    return out
