r"""Persson's theory for areal (2D) surfaces: contact area against load, viscoelastic friction.

A rigid rough surface ``h(x, y)`` slides at speed V along the direction ``e_V`` over a linear
viscoelastic half-space with complex modulus ``E(ω)`` (:class:`~viscocontact.rheology.Rheology`,
``exp(iωt)``) and Poisson ratio ν. A Fourier mode of wavevector q excites the solid at
``ω = q·e_V V``; in the package's groups (eq. 4.17) ``q = q̃ q0`` and ``ωτ = q̃_V ζ`` with
``ζ = q0Vτ`` and ``q̃_V = q̃·e_V``. Pressures are given as ``p = p̄/E*`` with ``E* = E0/(1-ν²)``
(the 1D theories' ``p̃`` of eq. 4.17 is ``2p/Λ̃``).

Spectrum
--------
:class:`ArealSpectrum` lists wavevectors ``q̃_j`` with weights ``w_j`` (mean square heights,
units of m0) whose sums are the 2D integrals of Persson's theory, ``∫ d²q C(q) f(q) → Σ w_j
f(q̃_j)``, for every f even in q: ``Σ w = <(q0 h)²>``, ``Σ |q̃|² w = <|∇h|²> = ḡ²``.

Contact area (Persson 2001, eqs. 3.34-3.45 of the thesis)
---------------------------------------------------------
In full contact a mode needs the pressure ``p_q = (|q|E(q·e_V V)/(2(1-ν²))) h_q``, so the
pressure variance with the roughness resolved up to ``|q̃| <= ζ_P`` (Persson's magnification) is
``V(ζ_P) = (E*²/4) Σ_{|q̃|<=ζ_P} |q̃|² w |E/E0|²``. The pressure distribution diffuses from
``δ(σ - p̄)`` with absorption at ``σ = 0`` and leaves the area

.. math:: \frac{A}{A_0}(ζ_P) = \mathrm{erf}\Big(\frac{\bar p}{\sqrt{2V(ζ_P)}}\Big)
          = \mathrm{erf}\Big(\frac{\sqrt2\,p}{\sqrt{\sum_{|\tilde q|\le ζ_P}
          |\tilde q|^2 w\,|E(\tilde q_V ζ)/E_0|^2}}\Big),

Persson's ``erf(1/(2√G))`` with ``G = (1/8)∫d²q q²C(q)|E(q·V)/((1-ν²)σ0)|²``. Elastic
(``E = E0``, which slow sliding tends to): ``A/A0 = erf(√2 p/ḡ)``, proportional to the load at
small load, ``A/A0 ≈ κ p̄/(E*ḡ)`` with ``κ = √(8/π) ≈ 1.596``. A 1D profile extruded along y
has the same formula with ``ḡ² = m2`` (:class:`~viscocontact.theories.PerssonContact`). Fast sliding
(``ζ → ∞``) stiffens every mode to E∞ except those with ``q̃_V = 0`` (ridges along the sliding
direction, not deformed in time), which keep E0.

Friction (Persson 2001, eq. 10 there)
-------------------------------------
Each mode dissipates in the fraction ``P(q) = A/A0(|q̃|)`` of the nominal area in contact at its
magnification:

.. math:: μ = \frac{1}{2p}\sum_j |\tilde q_j|\,\tilde q_{V,j}\,w_j\,P(|\tilde q_j|)\,S_j\,
          \mathrm{Im}\frac{E(\tilde q_{V,j}ζ)}{E_0},

the discrete form of ``μ = (1/2)∫dq q³C(q)P(q)∫dφ cosφ Im E(qV cosφ)/((1-ν²)σ0)``, with
``S = 1`` (Persson 2001) or ``S = γ + (1-γ)P²`` (Persson's later correction) when
``contact_correction = γ`` is given. Every term is ``>= 0`` (``q̃_V Im E(q̃_Vζ) >= 0`` since
``E''(-ω) = -E''(ω)``), μ vanishes in both elastic limits (``ζ → 0``: E → E0; ``ζ → ∞``:
E → E∞, both real), and in full contact (``P = 1``) ``μp̄`` is exactly the power the sliding
surface feeds into the half-space divided by V. For an extruded profile it reduces to
:class:`~viscocontact.theories.PerssonFriction`.

References
----------
Persson, B. N. J. (2001). Theory of rubber friction and contact mechanics. J. Chem. Phys. 115,
3840-3861. doi:10.1063/1.1388626
Persson, B. N. J. (2001). Elastoplastic contact between randomly rough surfaces. Phys. Rev.
Lett. 87, 116101. doi:10.1103/PhysRevLett.87.116101
Persson, B. N. J., Albohr, O., Tartaglino, U., Volokitin, A. I., Tosatti, E. (2005). On the
nature of surface roughness with application to contact mechanics, sealing, rubber friction and
adhesion. J. Phys.: Condens. Matter 17, R1-R62. doi:10.1088/0953-8984/17/1/R01
"""
from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import special

from .._validation import array_eq, in_range
from ..errors import ValidationError
from ..rheology.base import Rheology
from . import _args

__all__ = ["ArealSpectrum", "PerssonArealContact", "PerssonArealFriction"]


def _ro(value):
    arr = np.array(value, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


def _check_vectors(inst, attribute, value):
    name = f"ArealSpectrum.{attribute.name}"
    if value.ndim != 1 or value.size == 0:
        raise ValidationError(name, value.shape, "a non-empty 1-d array")
    if value.shape != inst.qx.shape:
        raise ValidationError(name, value.shape, f"the shape of qx {inst.qx.shape}")
    if not np.all(np.isfinite(value)):
        raise ValidationError(name, "array with NaN/inf", "finite entries")


def _check_weights(inst, attribute, value):
    _check_vectors(inst, attribute, value)
    if np.any(value < 0) or not np.any(value > 0):
        raise ValidationError("ArealSpectrum.weights", value, "numbers >= 0, not all zero")
    if np.any((inst.qx == 0) & (inst.qy == 0) & (value > 0)):
        raise ValidationError("ArealSpectrum.qx/qy", (0.0, 0.0),
                              "non-zero wavevectors (the mean plane carries no roughness)")


@attrs.frozen(kw_only=True)
class ArealSpectrum:
    """Discrete 2D roughness spectrum (see the module docstring).

    Parameters
    ----------
    qx, qy : array_like, shape (K,)
        Wavevectors ``q̃ = q/q0``, non-zero.
    weights : array_like, shape (K,)
        ``w >= 0`` in units of m0: each mode's share of ``<(q0 h)²>``.
    """

    qx: np.ndarray = attrs.field(converter=_ro, validator=_check_vectors, eq=array_eq(),
                                 hash=False)
    qy: np.ndarray = attrs.field(converter=_ro, validator=_check_vectors, eq=array_eq(),
                                 hash=False)
    weights: np.ndarray = attrs.field(converter=_ro, validator=_check_weights, eq=array_eq(),
                                      hash=False)

    @classmethod
    def from_surface(cls, surface, nx: int | None = None, ny: int | None = None) -> ArealSpectrum:
        """Exact weights ``a²/2`` of a :class:`~viscocontact.areal.surfaces.SpectralSurface`
        (or of the profile of an :class:`~viscocontact.areal.surfaces.ExtrudedProfile`); else the
        periodogram of the surface sampled on ``(nx, ny)`` (default 256²)."""
        from ..areal.surfaces.extruded import ExtrudedProfile
        from ..areal.surfaces.spectral import SpectralSurface

        if isinstance(surface, ExtrudedProfile):
            return cls.from_profile(surface.profile)
        if isinstance(surface, SpectralSurface):
            m = surface.modes
            qx, qy = m.wavevectors(surface.aspect)
            return cls(qx=qx, qy=qy, weights=m.amplitudes**2 / 2.0)
        h = surface.heights(nx or 256, ny or 256)
        ny_, nx_ = h.shape
        X = np.fft.fft2(h - h.mean()) / h.size
        qx = np.broadcast_to(np.fft.fftfreq(nx_, 1.0 / nx_)[None, :], h.shape)
        qy = np.broadcast_to((np.fft.fftfreq(ny_, 1.0 / ny_) / surface.aspect)[:, None], h.shape)
        P = np.abs(X) ** 2
        keep = (P > 0) & ((qx != 0) | (qy != 0))
        return cls(qx=qx[keep], qy=qy[keep], weights=P[keep])

    @classmethod
    def from_profile(cls, profile) -> ArealSpectrum:
        """A 1D profile extruded along y: its one-sided weights at ``q̃ = (k, 0)``."""
        from .spectrum import LineSpectrum

        line = LineSpectrum.from_profile(profile)
        return cls(qx=line.wavenumbers, qy=np.zeros_like(line.wavenumbers), weights=line.weights)

    @classmethod
    def isotropic_power_law(cls, *, hurst: float, scales: float, rms: float,
                            lowest: float = 1.0, rolloff: float | None = None, nodes: int = 48,
                            angles: int = 64) -> ArealSpectrum:
        """The continuous isotropic ``C̃(q̃) ∝ max(q̃, k_r)^{-2(1+H)}`` on ``[lowest, scales]``,
        normalised to ``m0 = rms²``, as a quadrature: ``nodes`` Gauss-Legendre points in
        ``log q̃`` on each side of the roll-off times ``angles`` equally spaced directions
        (the power-law moments to rounding: e^{s·log q} is entire; trigonometric moments of the
        angle up to order ``angles - 1`` exactly)."""
        hurst = _args.real("hurst", hurst, 0.0, 1.0, lo_open=True)
        scales = _args.real("scales", scales, 1.0, lo_open=True)
        lowest = _args.real("lowest", lowest, 1.0, scales, hi_open=True)
        rms = _args.positive("rms", rms)
        kr = lowest if rolloff is None else _args.real("rolloff", rolloff, lowest, scales)
        for name, n in (("nodes", nodes), ("angles", angles)):
            if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
                raise ValidationError(f"ArealSpectrum.isotropic_power_law.{name}", n,
                                      "an integer >= 2")
        x, w = np.polynomial.legendre.leggauss(int(nodes))
        ks, ws = [], []
        for lo, hi in ((lowest, kr), (kr, scales)):
            if hi <= lo:
                continue
            a, b = math.log(lo), math.log(hi)
            k = np.exp(0.5 * (a + b) + 0.5 * (b - a) * x)
            ks.append(k)
            # C̃ q̃ dq̃ dφ with dq̃ = q̃ d(log q̃)
            ws.append(0.5 * (b - a) * w * k * k * np.maximum(k, kr) ** (-2.0 * (1.0 + hurst)))
        k, wk = np.concatenate(ks), np.concatenate(ws)
        phi = 2.0 * np.pi * (np.arange(angles) + 0.5) / angles
        weights = np.outer(wk, np.full(angles, 2.0 * np.pi / angles))
        weights *= rms**2 / weights.sum()
        return cls(qx=np.outer(k, np.cos(phi)).ravel(), qy=np.outer(k, np.sin(phi)).ravel(),
                   weights=weights.ravel())

    @property
    def magnitudes(self) -> np.ndarray:
        """``|q̃|`` of every mode."""
        return np.hypot(self.qx, self.qy)

    @property
    def m0(self) -> float:
        """``<(q0 h)²> = Σ w``."""
        return float(np.sum(self.weights))

    @property
    def gradient_variance(self) -> float:
        """``ḡ² = <|∇h|²> = Σ |q̃|² w``."""
        return float(np.sum((self.qx**2 + self.qy**2) * self.weights))

    def cumulative(self, values: np.ndarray) -> np.ndarray:
        """``Σ_{|q̃_i| <= |q̃_j|} values_i`` for every mode j (the last axis runs over the modes;
        modes of equal ``|q̃|`` share one value, as Persson's P(q) of a ring)."""
        q = np.round(self.magnitudes, 12)
        order = np.argsort(q, kind="stable")
        qs = q[order]
        ends = np.searchsorted(qs, qs, side="right") - 1     # last mode of each one's ring
        vals = np.asarray(values, dtype=float)
        out = np.empty_like(vals)
        out[..., order] = np.cumsum(vals[..., order], axis=-1)[..., ends]
        return out


@attrs.frozen(kw_only=True)
class PerssonArealContact:
    """Persson's elastic contact area of an areal surface (module docstring).

    Parameters
    ----------
    spectrum : ArealSpectrum
        The surface's spectrum (``ArealSpectrum.from_surface(surface)``).

    Examples
    --------
    >>> from viscocontact.areal.surfaces import SelfAffineSurface
    >>> c = PerssonArealContact(spectrum=ArealSpectrum.from_surface(
    ...     SelfAffineSurface(hurst=0.8, scales=32, rms_slope=0.1)))
    >>> round(float(c.area_fraction(0.001)) / 0.01, 4)         # κ p/ḡ at small load
    1.5957
    """

    spectrum: ArealSpectrum = attrs.field(validator=attrs.validators.instance_of(ArealSpectrum))

    @classmethod
    def from_surface(cls, surface) -> PerssonArealContact:
        """The theory for a :class:`~viscocontact.areal.surfaces.Surface` (its spectrum)."""
        return cls(spectrum=ArealSpectrum.from_surface(surface))

    def gradient_variance(self, magnification: float | None = None) -> float:
        """``ḡ²(ζ_P) = Σ_{|q̃| <= ζ_P} |q̃|² w`` (all modes when ``magnification`` is None)."""
        s = self.spectrum
        g = (s.qx**2 + s.qy**2) * s.weights
        if magnification is None:
            return float(np.sum(g))
        z = _args.real("magnification", magnification, 0.0, lo_open=True)
        return float(np.sum(g[s.magnitudes <= z * (1 + 1e-12)]))

    def area_fraction(self, pressure, magnification: float | None = None):
        """``A/A0 = erf(√2 p/ḡ(ζ_P))`` for ``p = p̄/E* >= 0`` (full below the first mode)."""
        p = _args.non_negative("pressure", pressure)
        g2 = self.gradient_variance(magnification)
        if g2 == 0.0:
            return np.ones_like(p) if np.ndim(p) else 1.0
        return special.erf(math.sqrt(2.0) * p / math.sqrt(g2))

    def pressure_at_area(self, area_fraction):
        """Inverse of :meth:`area_fraction`: ``p = ḡ erfinv(A/A0)/√2`` for ``A/A0 in [0, 1)``."""
        f = _args.real("area_fraction", area_fraction, 0.0, 1.0, hi_open=True)
        return math.sqrt(self.gradient_variance() / 2.0) * special.erfinv(f)

    @property
    def small_load_slope(self) -> float:
        """``d(A/A0)/dp`` at ``p = 0``: ``κ/ḡ`` with ``κ = √(8/π)``."""
        return math.sqrt(8.0 / math.pi) / math.sqrt(self.gradient_variance())


@attrs.frozen(kw_only=True)
class PerssonArealFriction:
    """Persson's viscoelastic friction and contact area of an areal surface (module docstring).

    Parameters
    ----------
    spectrum : ArealSpectrum
        The surface's spectrum.
    rheology : Rheology
        The viscoelastic solid (E0 = ``relaxed_modulus``, τ = ``reference_time``).
    direction : float
        Angle of the sliding direction ``e_V`` from ``x̃``, radians in ``[0, 2π)`` (default 0:
        along x, as the areal method slides).
    contact_correction : float or None
        ``γ`` in ``S = γ + (1-γ)P²`` (in [0, 1]), or None for ``S = 1``.

    Examples
    --------
    >>> from viscocontact.areal.surfaces import SelfAffineSurface
    >>> from viscocontact.rheology import StandardLinearSolid
    >>> f = PerssonArealFriction(
    ...     spectrum=ArealSpectrum.from_surface(SelfAffineSurface(hurst=0.8, scales=16, rms=0.01)),
    ...     rheology=StandardLinearSolid(beta=10.0))
    >>> float(f.coefficient(1e-9, 0.01)) < 1e-9 < float(f.coefficient(1.0, 0.01))
    True
    """

    spectrum: ArealSpectrum = attrs.field(validator=attrs.validators.instance_of(ArealSpectrum))
    # attrs' instance_of stub takes a concrete type[T]; an abstract class is valid at run time
    rheology: Rheology = attrs.field(
        validator=attrs.validators.instance_of(Rheology))  # type: ignore[type-abstract]
    direction: float = attrs.field(default=0.0, converter=_args.as_float,
                                   validator=in_range(0.0, 2.0 * math.pi, hi_open=True))
    contact_correction: float | None = attrs.field(
        default=None, validator=attrs.validators.optional(in_range(0.0, 1.0)))

    @classmethod
    def from_surface(cls, surface, rheology: Rheology, *, direction: float = 0.0,
                     contact_correction: float | None = None) -> PerssonArealFriction:
        """The theory for a :class:`~viscocontact.areal.surfaces.Surface` on ``rheology``."""
        return cls(spectrum=ArealSpectrum.from_surface(surface), rheology=rheology,
                   direction=direction, contact_correction=contact_correction)

    @property
    def sliding_wavenumbers(self) -> np.ndarray:
        """``q̃_V = q̃·e_V`` of every mode."""
        s = self.spectrum
        return s.qx * math.cos(self.direction) + s.qy * math.sin(self.direction)

    def moduli(self, zeta):
        """``E(q̃_V ζ/τ)/E0`` for every mode; shape ``(*shape(ζ), K)``."""
        z = _args.non_negative("zeta", zeta)
        qv = self.sliding_wavenumbers
        omega = np.multiply.outer(z, np.abs(qv)) / self.rheology.reference_time
        e = self.rheology.complex_modulus(omega) / self.rheology.relaxed_modulus
        return np.where(qv < 0, np.conj(e), e)           # E(-ω) = conj E(ω)

    def contact_fractions(self, zeta, pressure):
        """``P(|q̃|)``: contact fraction with the roughness resolved up to each mode's ring."""
        p = _args.positive("pressure", pressure)
        s = self.spectrum
        e = self.moduli(zeta)
        var = s.cumulative((s.qx**2 + s.qy**2) * s.weights * np.abs(e) ** 2)
        return special.erf(math.sqrt(2.0) * p / np.sqrt(var))

    def area_fraction(self, zeta, pressure):
        """``A/A0`` with all the roughness resolved."""
        frac = self.contact_fractions(zeta, pressure)
        return frac[..., int(np.argmax(self.spectrum.magnitudes))]

    def coefficient(self, zeta, pressure):
        """Friction coefficient ``μ >= 0`` at speed ``ζ`` and pressure ``p = p̄/E* > 0``."""
        p = _args.positive("pressure", pressure)
        s = self.spectrum
        e = self.moduli(zeta)
        frac = self.contact_fractions(zeta, p)
        if self.contact_correction is not None:
            g = float(self.contact_correction)
            frac = frac * (g + (1.0 - g) * frac**2)
        work = s.magnitudes * self.sliding_wavenumbers * s.weights * e.imag
        return np.sum(work * frac, axis=-1) / (2.0 * p)

    def full_contact_stress(self, zeta):
        """``μp̄/E*`` with every mode in contact (``P = 1``): the power per unit area fed into the
        half-space by the sliding surface, over ``E*V``."""
        s = self.spectrum
        e = self.moduli(zeta)
        return np.sum(s.magnitudes * self.sliding_wavenumbers * s.weights * e.imag, axis=-1) / 2.0
