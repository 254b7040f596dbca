r"""Greenwood-Williamson (thesis equations 3.20-3.27) and Fuller-Tabor (§3.2, equation 3.28) rough
contact.

Intrinsically 3D: identical spherical summits of radius ``R``, Gaussian summit heights of standard
deviation ``σ_s`` (eq. 3.25), ``D_s`` summits per unit area, each in independent Hertzian (GW) or
JKR (Fuller-Tabor) contact with a flat elastic half-space of reduced modulus ``E*``. A summit of
height ``z`` above the summits' mean plane is compressed by ``δ = z - d``. With ``d* = d/σ_s``
(eq. 3.26) and ``F_n(h) = (1/√(2π))∫_h^∞ (x - h)^n e^{-x²/2} dx``:

.. math::
    \frac{N}{A_0} = D_s F_0(d^*),\qquad
    \frac{A}{A_0} = \pi D_s R\sigma_s F_1(d^*),\qquad
    \frac{P}{A_0 E^*} = \tfrac{4}{3} D_s \sqrt{R}\,\sigma_s^{3/2} F_{3/2}(d^*)\quad(3.26),

computed in closed form with :func:`~viscocontact.theories.asperity.gaussian_tail_moment`. For
large ``d*``, ``F_1/F_{3/2} → 4√d*/(3√π)``: GW's area is proportional to load only up to a slowly
varying factor, ``A/P → √π √(R/σ_s) √d*/E*``.

Parameters from a profile (:meth:`GreenwoodWilliamson.from_moments`): the profile is a cross-section
of an isotropic Gaussian surface (see :mod:`viscocontact.theories.summits`): ``D_s = m4/(6π√3 m2)``,
``R = 1/((8/3)√(m4/π))`` (inverse mean summit curvature), ``σ_s² = m0(1 - 0.8968/α)``. Then
``D_s R σ_s ∝ √α`` and ``D_s √R σ_s^{3/2}/√m2 ∝ α^{3/4}`` (the scalings of eqs. 3.46-3.47); Archard's
``σ_s R D_s`` (eq. 3.27) is ``√(α - 0.8968)/(16√(3π))``.

Fuller-Tabor
------------
JKR summits (:class:`~viscocontact.theories.jkr.JKRSphere`): ``A_i = πa²``, ``P_i`` and ``δ(a)`` of
eqs. 1.44-1.45. On loading a summit touches at ``δ = 0`` (where it snaps to ``a³ = 2πΔγR²/E*``); on
unloading it stays attached, on the displacement-stable branch, down to ``δ = -δ_c`` with

.. math:: \delta_c = \Big(\frac{27\pi^2\Delta\gamma^2 R}{64E^{*2}}\Big)^{1/3}\quad(3.28),

so the lower limit of eqs. 3.20-3.22 becomes ``d - δ_c``. The integrals over heights are done in the
contact radius ``a`` (``dz = δ'(a) da``) with composite Gauss-Legendre panels. Adhesion in the
package's groups: ``Δγ/E* = πγ̃/q0`` (``γ̃`` of eq. 4.17), so in q0 units ``Δγ/E* = πγ̃``.
``θ = σ_s^{3/2}/(R^{1/2} Δγ/E*)`` is Fuller and Tabor's adhesion parameter (their modulus convention
may differ by a constant factor: compare trends).

Units: the package's (lengths in 1/q0, densities in q0², ``γ̃``); outputs ``A/A0``, ``p/E*`` and
``p̃ = 2(p/E*)/Λ̃``.

References
----------
Greenwood, J. A., Williamson, J. B. P. (1966). Contact of nominally flat surfaces. Proc. R. Soc.
Lond. A 295, 300-319. doi:10.1098/rspa.1966.0242
Fuller, K. N. G., Tabor, D. (1975). The effect of surface roughness on the adhesion of elastic
solids. Proc. R. Soc. Lond. A 345, 327-342. doi:10.1098/rspa.1975.0138
McCool, J. I. (1986). Comparison of models for the contact of rough surfaces. Wear 107, 37-60.
"""
from __future__ import annotations

import math
from typing import cast

import attrs
import numpy as np
from scipy.optimize import minimize_scalar

from .._validation import non_negative, positive
from ..errors import ValidationError
from . import _args
from .asperity import AsperityModel, gaussian_tail_moment
from .jkr import JKRSphere, largest_quartic_root
from .summits import RoughnessMoments

__all__ = ["FullerTabor", "GreenwoodWilliamson"]

_SQRT_2PI = math.sqrt(2.0 * math.pi)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)


def gw_integral(n: float, separation):
    """``F_n(d*) = (1/√(2π)) ∫_{d*}^∞ (x - d*)^n e^{-x²/2} dx`` (eq. 3.26)."""
    return gaussian_tail_moment(n, separation) / _SQRT_2PI


def _gw_parameters(moments: RoughnessMoments) -> dict:
    moments.require_isotropic()
    return dict(summit_density=moments.summit_density,
                summit_radius=1.0 / moments.mean_summit_curvature,
                summit_std=moments.summit_height_std, amplitude=moments.amplitude)


@attrs.frozen(kw_only=True)
class GreenwoodWilliamson(AsperityModel):
    """Greenwood-Williamson contact (eqs. 3.20-3.26); see the module docstring.

    Parameters
    ----------
    summit_density : float
        ``D_s`` > 0, summits per unit area (q0² units).
    summit_radius : float
        ``R`` > 0 (1/q0 units).
    summit_std : float
        ``σ_s`` > 0 (1/q0 units).
    amplitude : float or None
        ``Λ̃`` for pressures in ``p̃``.

    Examples
    --------
    >>> gw = GreenwoodWilliamson(summit_density=1.0, summit_radius=1.0, summit_std=1.0)
    >>> round(float(gw.area_fraction(0.0)), 12)   # π F_1(0) = π/√(2π)
    1.253314137316
    """

    summit_density: float = attrs.field(converter=_args.as_float, validator=positive)
    summit_radius: float = attrs.field(converter=_args.as_float, validator=positive)
    summit_std: float = attrs.field(converter=_args.as_float, validator=positive)
    amplitude: float | None = attrs.field(default=None, converter=_args.as_optional_float,
                                          validator=_args.optional_positive)

    @classmethod
    def from_moments(cls, moments: RoughnessMoments) -> GreenwoodWilliamson:
        """GW parameters of an isotropic Gaussian surface with these profile moments (McCool)."""
        return cls(**_gw_parameters(moments))

    @classmethod
    def from_profile(cls, profile) -> GreenwoodWilliamson:
        """:meth:`from_moments` of the profile's statistics (and its ``Λ̃``)."""
        return cls.from_moments(RoughnessMoments.from_profile(profile))

    def contact_density(self, separation):
        """``N/A0 = D_s F_0(d*)`` (eq. 3.20), contacts per unit area (q0²)."""
        d = _args.real("separation", separation)
        return self.summit_density * gw_integral(0.0, d)

    def area_fraction(self, separation):
        """``A/A0 = π D_s R σ_s F_1(d*)`` (eqs. 3.21, 3.23, 3.26)."""
        d = _args.real("separation", separation)
        return (math.pi * self.summit_density * self.summit_radius * self.summit_std
                * gw_integral(1.0, d))

    def pressure_over_modulus(self, separation):
        """``P/(A0E*) = (4/3) D_s √R σ_s^{3/2} F_{3/2}(d*)`` (eqs. 3.22, 3.24, 3.26)."""
        d = _args.real("separation", separation)
        return (4.0 / 3.0 * self.summit_density * math.sqrt(self.summit_radius)
                * self.summit_std**1.5 * gw_integral(1.5, d))


@attrs.frozen(kw_only=True)
class FullerTabor:
    """Fuller-Tabor adhesive Greenwood-Williamson contact (§3.2, eq. 3.28).

    Parameters
    ----------
    summit_density, summit_radius, summit_std, amplitude
        As in :class:`GreenwoodWilliamson` (q0 units).
    gamma : float
        ``γ̃ = (1-ν²) q0 Δγ/(π E0) >= 0`` (eq. 4.17); ``Δγ/E* = πγ̃`` in 1/q0 units;
        ``γ̃ = 0`` is GW.

    Notes
    -----
    :meth:`area_fraction`, :meth:`pressure_over_modulus` and :meth:`mean_pressure` take
    ``unloading=True`` for the retraction branch (lower limit ``d - δ_c``, eq. 3.28). The loading
    curve need not be monotonic in ``d*`` (summits snap in with a tensile load), so no inversion at
    given load is offered.
    """

    summit_density: float = attrs.field(converter=_args.as_float, validator=positive)
    summit_radius: float = attrs.field(converter=_args.as_float, validator=positive)
    summit_std: float = attrs.field(converter=_args.as_float, validator=positive)
    gamma: float = attrs.field(converter=_args.as_float, validator=non_negative)
    amplitude: float | None = attrs.field(default=None, converter=_args.as_optional_float,
                                          validator=_args.optional_positive)

    @classmethod
    def from_moments(cls, moments: RoughnessMoments, *, gamma: float) -> FullerTabor:
        """Fuller-Tabor with the GW parameters of :meth:`GreenwoodWilliamson.from_moments`."""
        return cls(gamma=gamma, **_gw_parameters(moments))

    @classmethod
    def from_profile(cls, profile, *, gamma: float) -> FullerTabor:
        """:meth:`from_moments` of the profile's statistics (and its ``Λ̃``)."""
        return cls.from_moments(RoughnessMoments.from_profile(profile), gamma=gamma)

    @property
    def summit(self) -> JKRSphere:
        """One summit: JKR with ``E* = 1`` and ``Δγ = πγ̃`` (q0 units)."""
        return JKRSphere(radius=self.summit_radius, reduced_modulus=1.0,
                         work_of_adhesion=math.pi * self.gamma)

    @property
    def critical_neck(self) -> float:
        """``δ_c = (27π²Δγ²R/(64E*²))^(1/3)`` (eq. 3.28), 1/q0 units."""
        # displacement control always reports the neck's penetration
        return -cast(float, self.summit.pull_off_displacement_control().penetration)

    @property
    def adhesion_parameter(self) -> float:
        """``θ = σ_s^{3/2}/(R^{1/2}·Δγ/E*)`` (inf without adhesion)."""
        if self.gamma == 0:
            return math.inf
        return self.summit_std**1.5 / (math.sqrt(self.summit_radius) * math.pi * self.gamma)

    @property
    def greenwood_williamson(self) -> GreenwoodWilliamson:
        """The adhesionless limit ``γ̃ → 0``."""
        return GreenwoodWilliamson(summit_density=self.summit_density,
                                   summit_radius=self.summit_radius, summit_std=self.summit_std,
                                   amplitude=self.amplitude)

    def _integrals(self, d: float, unloading: bool) -> tuple[float, float]:
        """``(A/A0, P/(A0E*))`` at ``d* = d`` by composite Gauss-Legendre in the contact radius.

        Panels are ``σ_s/4`` wide in summit height ``z`` (from the lowest attached summit, or
        ``-12σ_s``, to ``12σ_s``); in each, ``a`` runs between the JKR radii of its end heights, so
        the integrand ``{πa², P_i(a)}·φ_s(z(a))·δ'(a)`` is smooth.
        """
        sph = self.summit
        sig, rad = self.summit_std, self.summit_radius
        c = math.sqrt(2.0 * math.pi * sph.work_of_adhesion)   # √(2πΔγ/E*), E* = 1
        delta_lo = -self.critical_neck if unloading else 0.0
        at_lowest = d * sig + delta_lo >= -12.0 * sig
        delta_start = delta_lo if at_lowest else -12.0 * sig - d * sig
        span = 12.0 * sig - (d * sig + delta_start)
        if span <= 0:
            return 0.0, 0.0
        n_panels = max(1, int(math.ceil(span / (0.25 * sig))))
        deltas = delta_start + np.linspace(0.0, span, n_panels + 1)
        s = largest_quartic_root(rad * c, rad * deltas)
        if at_lowest and unloading:       # the neck: a double root of the quartic
            s[0] = math.sqrt(sph.pull_off_displacement_control().contact_radius)
        a_edges = s**2
        lo, hi = a_edges[:-1, None], a_edges[1:, None]
        a = 0.5 * (hi + lo) + 0.5 * (hi - lo) * _GL_X
        w = 0.5 * (hi - lo) * _GL_W
        x = (d * sig + sph.penetration(a)) / sig
        dens = np.exp(-0.5 * x * x) / (sig * _SQRT_2PI) * sph.penetration_derivative(a) * w
        load = sph.load(a)
        area = math.pi * self.summit_density * float(np.sum(a * a * dens))
        pres = self.summit_density * float(np.sum(load * dens))
        return area, pres

    def _map(self, separation, unloading: bool, which: int):
        d = _args.real("separation", separation)
        vals = [self._integrals(float(x), bool(unloading))[which] for x in np.ravel(d)]
        return vals[0] if np.ndim(d) == 0 else np.reshape(vals, np.shape(d))

    def area_fraction(self, separation, unloading: bool = False):
        """``A/A0 = D_s ∫ π a² φ_s dz`` over the summits in contact."""
        return self._map(separation, unloading, 0)

    def pressure_over_modulus(self, separation, unloading: bool = False):
        """``P/(A0E*) = D_s ∫ P_i φ_s dz`` (negative when tensile)."""
        return self._map(separation, unloading, 1)

    def mean_pressure(self, separation, unloading: bool = False):
        """``p̃ = 2(p/E*)/Λ̃`` (needs ``amplitude``)."""
        if self.amplitude is None:
            raise ValidationError("FullerTabor.amplitude", None,
                                  "a real number in (0.0, inf] (p̃ = 2p/(E*Λ̃) needs Λ̃)")
        return 2.0 * np.asarray(self.pressure_over_modulus(separation, unloading)) / self.amplitude

    def pull_off(self) -> tuple[float, float]:
        """``(d*, P/(A0E*))`` at the most tensile point of the unloading branch (pull-off).

        The unloading load is scanned on ``d* in [-3, 8]`` and the minimum refined. When it is
        nowhere negative (weak adhesion, large θ: the tensile necks never outweigh the compressed
        summits) there is no pull-off force and ``(inf, 0.0)`` is returned.
        """
        grid = np.linspace(-3.0, 8.0, 45)
        vals = np.array([self._integrals(x, True)[1] for x in grid])
        i = int(np.argmin(vals))
        if vals[i] >= 0.0:
            return math.inf, 0.0
        lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
        res = minimize_scalar(lambda x: self._integrals(float(x), True)[1], bounds=(lo, hi),
                              method="bounded", options={"xatol": 1e-10})
        return float(res.x), float(res.fun)
