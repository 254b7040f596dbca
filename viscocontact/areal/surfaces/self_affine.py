"""Random self-affine areal surfaces with a power-law PSD, isotropic or anisotropic.

The areal counterpart of :class:`~viscocontact.profiles.SelfAffineProfile`: a Fourier series over
the wavevectors ``q̃ = (k, l/aspect)`` of the cell (units of q0) whose effective wavenumber lies
in the band ``q_L/q0 <= q̃_e <= N_q``::

    q0·h = Σ a cos(k x̃ + l ỹ/aspect + φ),     a = A · max(q̃_e, k_r)^-(1+H),

so the 2D PSD is ``C(q) ∝ q^{-2(1+H)}`` (flat below the roll-off ``k_r``), with deterministic
amplitudes and random phases ``φ`` from ``numpy.random.default_rng(seed)``; heights are real by
construction (each mode of the half plane stands for itself and its conjugate). The constant A
makes the rms height, or the rms gradient ``√<|∇h|²>``, exactly the requested one.

Anisotropy: with ratio ``γ`` and orientation ``θ`` the surface is an isotropic one stretched by
``γ`` along the direction ``e1 = (cos θ, sin θ)``: ``q̃_e² = (γ q̃·e1)² + (q̃·e2)²``. Its features
are ``γ`` times longer along ``e1`` than across it (``γ = 1``: isotropic).
"""
from __future__ import annotations

import functools
import math

import attrs
import numpy as np

from ..._validation import in_range, int_range, positive
from ...errors import ValidationError
from ...profiles.spectral import as_float
from .spectral import SpectralSurface, SurfaceModes

__all__ = ["SelfAffineSurface"]


def _optional_float(value):
    return None if value is None else as_float(value)


def _check_rolloff(inst, attribute, value):
    if value is not None:
        in_range(1.0, float(inst.scales))(inst, attribute, value)


def _check_lowest(inst, attribute, value):
    in_range(1.0, float(inst.scales))(inst, attribute, value)


def _check_normalisation(inst, attribute, value):
    given = [v for v in (inst.rms, inst.rms_slope) if v is not None]
    if len(given) != 1:
        raise ValidationError("SelfAffineSurface.rms/rms_slope", (inst.rms, inst.rms_slope),
                              "exactly one of them given (the other None)")
    if value is not None:
        positive(inst, attribute, value)


def _optional_positive(inst, attribute, value):
    if value is not None:
        positive(inst, attribute, value)


@attrs.frozen(kw_only=True)
class SelfAffineSurface(SpectralSurface):
    """Random self-affine surface with an exact rms height or rms gradient (module docstring).

    Parameters
    ----------
    hurst : float
        Hurst exponent ``H`` in (0, 1]: ``C(q) ∝ q^{-2(1+H)}`` (fractal dimension ``3 - H``).
    scales : int
        ``N_q = q1/q0 >= 1``, the top of the band of effective wavenumbers.
    rms : float or None
        ``q0·h_rms > 0``; ``m0 = rms²`` exactly. Give this or ``rms_slope``.
    rms_slope : float or None
        ``√<|∇h|²> > 0`` (dimensionless rms gradient); give this or ``rms``.
    seed : int
        Seed ``>= 0`` of ``numpy.random.default_rng`` for the phases.
    rolloff : float or None
        Roll-off ``k_r`` in ``[1, N_q]``: the PSD is flat below it. None: no roll-off.
    lowest : float
        ``q_L/q0`` in ``[1, N_q]``: the bottom of the band (1, the default, starts it at the
        cell's fundamental; a larger value leaves the cell several of the largest wavelengths,
        as a self-averaging sample of a surface needs).
    anisotropy : float
        ``γ > 0``: features ``γ`` times longer along ``e1`` than across (1: isotropic).
    orientation : float
        ``θ`` in ``[0, π)`` (radians): the angle of ``e1`` from the sliding direction ``x̃``.
    aspect : float
        Cell side ratio ``L_y/L_x > 0``.

    Examples
    --------
    >>> s = SelfAffineSurface(hurst=0.8, scales=16, rms=0.01, seed=1)
    >>> h = s.heights(64, 64)
    >>> h.shape, abs(float(h.std()) - 0.01) < 1e-15
    ((64, 64), True)
    """

    hurst: float = attrs.field(converter=as_float, validator=in_range(0.0, 1.0, lo_open=True))
    scales: int = attrs.field(validator=int_range(1))
    rms: float | None = attrs.field(default=None, converter=_optional_float,
                                    validator=_optional_positive)
    rms_slope: float | None = attrs.field(default=None, converter=_optional_float,
                                          validator=_check_normalisation)
    seed: int = attrs.field(default=0, validator=int_range(0))
    rolloff: float | None = attrs.field(default=None, converter=_optional_float,
                                        validator=_check_rolloff)
    lowest: float = attrs.field(default=1.0, converter=as_float, validator=_check_lowest)
    anisotropy: float = attrs.field(default=1.0, converter=as_float, validator=positive)
    orientation: float = attrs.field(default=0.0, converter=as_float,
                                     validator=in_range(0.0, math.pi, hi_open=True))
    aspect: float = attrs.field(default=1.0, converter=as_float,
                                validator=[positive, lambda inst, a, v: inst._check_band()])

    def effective_wavenumbers(self, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
        """``q̃_e = √((γ q̃·e1)² + (q̃·e2)²)`` of wavevectors ``(q̃x, q̃y)`` (units of q0)."""
        c, s = math.cos(self.orientation), math.sin(self.orientation)
        along = qx * c + qy * s
        across = -qx * s + qy * c
        return np.hypot(self.anisotropy * along, across)

    def _lattice(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(k, l, q̃_e, band)`` over the box of the half plane that holds the band."""
        reach = self.scales / min(1.0, self.anisotropy)
        kmax, lmax = int(math.floor(reach)), int(math.floor(reach * self.aspect))
        l, k = np.meshgrid(np.arange(lmax + 1), np.arange(-kmax, kmax + 1), indexing="ij")
        qe = self.effective_wavenumbers(k.astype(float), l / self.aspect)
        band = (qe >= self.lowest * (1.0 - 1e-12)) & (qe <= self.scales * (1.0 + 1e-12))
        band &= (l > 0) | (k > 0)
        if not np.any(band):
            self._refuse_band()
        return k, l, qe, band

    def _check_band(self) -> None:
        """Refuse a band without a mode of the cell, row by row of the lattice: on row l the
        band is ``lo² <= A k² + B k + C <= hi²``, an interval of k minus an inner one."""
        c, s, g2 = math.cos(self.orientation), math.sin(self.orientation), self.anisotropy**2
        lmax = int(math.floor(self.scales / min(1.0, self.anisotropy) * self.aspect))
        y = np.arange(lmax + 1) / self.aspect
        a = g2 * c * c + s * s
        b = 2.0 * y * (g2 - 1.0) * c * s
        cc = y * y * (g2 * s * s + c * c)

        def roots(radius):
            disc = b * b - 4.0 * a * (cc - radius**2)
            root = np.sqrt(np.maximum(disc, 0.0))
            return disc, (-b - root) / (2.0 * a), (-b + root) / (2.0 * a)

        eps = 1e-9
        d_hi, lo_k, hi_k = roots(self.scales * (1.0 + 1e-12))
        d_lo, in_lo, in_hi = roots(self.lowest * (1.0 - 1e-12))
        first = np.ceil(lo_k - eps)
        first[0] = max(first[0], 1.0)                              # l = 0: k > 0 only
        last = np.floor(hi_k + eps)
        hole = d_lo > 0
        below = np.where(hole, np.minimum(last, np.floor(in_lo + eps)), last) >= first
        above = hole & (np.maximum(first, np.ceil(in_hi - eps)) <= last)
        if not np.any((d_hi >= 0) & (below | above)):
            self._refuse_band()

    def _refuse_band(self):
        raise ValidationError("SelfAffineSurface.scales", self.scales,
                              f"a band [{self.lowest:g}, scales] that holds a mode of the cell "
                              f"(aspect {self.aspect:g}, anisotropy {self.anisotropy:g}, "
                              f"orientation {self.orientation:g})")

    @functools.cached_property
    def modes(self) -> SurfaceModes:
        """The modes of the band with their amplitudes and seeded phases (computed once)."""
        k, l, qe, band = self._lattice()
        phases = np.random.default_rng(self.seed).uniform(0.0, 2.0 * np.pi, k.shape)
        kr = 1.0 if self.rolloff is None else self.rolloff
        w = np.maximum(qe[band], kr) ** -(1.0 + self.hurst)
        qx, qy = k[band].astype(float), l[band] / self.aspect
        if self.rms is not None:
            norm = self.rms / math.sqrt(float(np.sum(w * w)) / 2.0)
        else:
            assert self.rms_slope is not None                  # one of the two (validated)
            norm = self.rms_slope / math.sqrt(float(np.sum((qx * qx + qy * qy) * w * w)) / 2.0)
        return SurfaceModes(kx=k[band], ky=l[band], amplitudes=norm * w, phases=phases[band])
