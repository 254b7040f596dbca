r"""Spectral moments of a profile and Nayak's summit statistics (thesis §§3.1-3.2, 3.4).

The asperity theories of Chapter 3 (Greenwood-Williamson, Fuller-Tabor, BGT/Greenwood 2006, the
height-dependent curvature model) are *3D*: they describe an isotropic, Gaussian rough surface
pressed on an elastic half-space. The package's indenters are 1D profiles. As Greenwood and
Williamson themselves did with profilometer traces, a profile is read here as a cross-section of an
isotropic surface: the profile moments ``m0 = <r²>``, ``m2 = <r'²>``, ``m4 = <r''²>`` (eq. 3.11 with
n = 1; for an isotropic surface ``m2 = π∫q³C(q)dq`` of eq. 3.44) fix the surface statistics through
Nayak's random-process theory. The thesis does not adapt these theories to 1D; neither does this
module. Their predictions are trends to compare with the 1D BEM, not its limits.

Units (the package's, thesis eq. 4.17): heights in 1/q0 (``m0 = (q0 r_rms)²``), slopes
dimensionless (``m2``), curvatures in q0 (``m4 = <(r''/q0)²>``); summit densities per unit area are in
q0², radii in 1/q0. Dimensionless summit height ``ξ = z/√m0``, curvatures ``k = K/√m4`` (negative at
a summit), Nayak's bandwidth ``α = m0 m4/m2²`` (``α >= 3/2`` for an isotropic Gaussian surface) and
``C1 = α/(2α - 3)``.

Summit statistics (isotropic Gaussian surface)
----------------------------------------------
* Density of summits per unit area ``D_s = m4/(6π√3 m2)`` (Nayak 1973).
* Joint density of summit height and principal curvatures, eq. 3.33 (:func:`summit_joint_density`).
  As printed, its integral over the whole quadrant ``K1, K2 < 0`` is ``2 D_s``: the constant
  ``√27/(4π)²`` is that of *ordered* principal curvatures (``K1 < K2``, Nayak). Eq. 3.32 integrates
  ``χ = (K1 - K2)/2`` over all reals, which would count every summit twice; here both orderings are
  never summed.
* Summit height density ``p_sum(ξ)`` (eq. 3.49, :func:`summit_height_density`), normalised to 1.
  Eq. 3.49 prints the last exponential as ``exp(-α/(2(α-1)ξ²))``; the marginal of eq. 3.33 (and the
  limit ``α → ∞``, where summit heights become the surface heights) gives ``exp(-αξ²/(2(α-1)))``.
* Mean summit height ``4√m0/√(πα)``, summit height variance ``m0[1 - (1 + 16/π - 3√3)/α]``
  (McCool's ``1 - 0.8968/α``), mean summit curvature ``(8/3)√(m4/π)`` (Nayak 1973, McCool 1986).
* Mean arithmetic curvature of the summits at height ξ, ``K̄_A*(ξ) = E[(k1 + k2)/2 | ξ]``
  (:func:`summit_mean_curvature`), computed in closed form from eq. 3.33. Eq. 3.48 as printed agrees
  with it only at ``ξ = 0`` (see ``docs/theories.md``); it is not used.

Closed forms
------------
With ``s = -(k1 + k2)/2``, ``u = |k1 - k2|/2`` the inner integral of eq. 3.33 over ``u in [0, s]`` is
``(2/3)s² - 4/9 + (4/9)e^{-3s²/2}``, and with ``b = 3/(2√α)``

.. math::
    p_{sum}(\xi) = \frac{27\sqrt{C_1}}{4\pi}\int_0^\infty e^{-C_1(\xi - bs)^2 - 3s^2/4}
        \Big[\tfrac{2}{3}s^2 - \tfrac{4}{9} + \tfrac{4}{9}e^{-3s^2/2}\Big]\,ds ,

``K̄_A* p_sum`` being the same integral with an extra factor ``-s``; the integrals
``∫_0^∞ s^n e^{-As² + Bs} ds`` follow from ``erfc`` by recursion. The result equals eq. 3.49 to
rounding.

References
----------
Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol. 93, 398-407.
Nayak, P. R. (1973). Random process model of rough surfaces in plastic contact. Wear 26, 305-333.
McCool, J. I. (1986). Comparison of models for the contact of rough surfaces. Wear 107, 37-60.
"""
from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import special

from .._validation import positive
from ..errors import ValidationError
from . import _args

__all__ = ["RoughnessMoments", "summit_height_density", "summit_joint_density",
           "summit_mean_curvature"]

#: ``1 + 16/π - 3√3`` (= 0.89681): the summit height variance is ``m0 (1 - c/α)``.
SUMMIT_VARIANCE_CONSTANT = 1.0 + 16.0 / math.pi - 3.0 * math.sqrt(3.0)
#: ``D_s = SUMMIT_DENSITY_CONSTANT · m4/m2``.
SUMMIT_DENSITY_CONSTANT = 1.0 / (6.0 * math.pi * math.sqrt(3.0))


@attrs.frozen(kw_only=True)
class RoughnessMoments:
    """Spectral moments of a profile, read as the cross-section of an isotropic surface.

    Parameters
    ----------
    m0 : float
        ``<(q0 r)²>`` > 0 (eq. 3.12).
    m2 : float
        ``<r'²>`` > 0, the mean square slope (eq. 4.54).
    m4 : float
        ``<(r''/q0)²>`` > 0, the mean square curvature.
    amplitude : float or None
        ``Λ̃ = q0·max r`` > 0, needed only to express pressures as ``p̃ = 2p/(E*Λ̃)`` (eq. 4.17).

    Examples
    --------
    >>> from viscocontact.profiles import SelfAffineProfile
    >>> m = RoughnessMoments.from_profile(SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0))
    >>> round(m.alpha, 3)
    65.88
    """

    m0: float = attrs.field(converter=_args.as_float, validator=positive)
    m2: float = attrs.field(converter=_args.as_float, validator=positive)
    m4: float = attrs.field(converter=_args.as_float, validator=positive)
    amplitude: float | None = attrs.field(default=None, converter=_args.as_optional_float,
                                          validator=_args.optional_positive)

    @classmethod
    def from_profile(cls, profile) -> RoughnessMoments:
        """The moments and the amplitude ``Λ̃`` of a :class:`~viscocontact.profiles.Profile`."""
        st = profile.statistics()
        return cls(m0=st.m0, m2=st.m2, m4=st.m4, amplitude=st.amplitude)

    @property
    def alpha(self) -> float:
        """Nayak's bandwidth parameter ``α = m0 m4/m2²``."""
        return self.m0 * self.m4 / self.m2**2

    def require_isotropic(self) -> float:
        """``α``, after checking ``α > 3/2`` (an isotropic Gaussian surface needs ``α >= 3/2``)."""
        a = self.alpha
        if not a > 1.5:
            raise ValidationError("RoughnessMoments.alpha", a,
                                  "a real number in (1.5, inf] (α = m0·m4/m2² of an isotropic "
                                  "Gaussian surface; a single sinusoid has α = 1)")
        return a

    @property
    def summit_density(self) -> float:
        """``D_s = m4/(6π√3 m2)`` summits per unit area (q0² units)."""
        return SUMMIT_DENSITY_CONSTANT * self.m4 / self.m2

    @property
    def mean_summit_height(self) -> float:
        """``4√m0/√(πα)`` above the mean plane (1/q0 units)."""
        return 4.0 * math.sqrt(self.m0 / (math.pi * self.require_isotropic()))

    @property
    def summit_height_std(self) -> float:
        """``σ_s = √(m0 (1 - (1 + 16/π - 3√3)/α))`` (1/q0 units)."""
        return math.sqrt(self.m0 * (1.0 - SUMMIT_VARIANCE_CONSTANT / self.require_isotropic()))

    @property
    def mean_summit_curvature(self) -> float:
        """Mean of ``|K1 + K2|/2`` over all summits, ``(8/3)√(m4/π)`` (q0 units)."""
        return 8.0 / 3.0 * math.sqrt(self.m4 / math.pi)


# -- Nayak's densities -----------------------------------------------------------------------------
def _c1(alpha: float) -> float:
    a = _args.real("alpha", alpha, 1.5, lo_open=True)
    return a / (2.0 * a - 3.0)


def summit_joint_density(xi, k1, k2, alpha: float):
    """Eq. 3.33 in dimensionless form, per ordered pair of principal curvatures.

    Returns ``Υ*`` with ``Υ dz dK1 dK2 = (m4/m2) Υ*(ξ, k1, k2) dξ dk1 dk2``:

    ``Υ* = (√27/(16π²)) √C1 exp[-C1(ξ + b(k1 + k2)/2)²] |k1 - k2| k1 k2
    exp{-(3/16)[3(k1 + k2)² - 8 k1 k2]}``, ``b = 3/(2√α)``, zero unless ``k1, k2 < 0``.
    Integrated over ``k1 < k2 < 0`` and all ξ it gives ``D_s/(m4/m2) = 1/(6π√3)``.
    """
    c1 = _c1(alpha)
    b = 1.5 / math.sqrt(float(alpha))
    xi, k1, k2 = (np.asarray(v, dtype=float) for v in (xi, k1, k2))
    summit = (k1 < 0) & (k2 < 0)
    val = (math.sqrt(27.0) / (16.0 * math.pi**2) * math.sqrt(c1)
           * np.exp(-c1 * (xi + b * (k1 + k2) / 2.0) ** 2) * np.abs(k1 - k2) * k1 * k2
           * np.exp(-3.0 / 16.0 * (3.0 * (k1 + k2) ** 2 - 8.0 * k1 * k2)))
    return np.where(summit, val, 0.0)


def _scaled_moments(nmax: int, a: float, b, log_scale):
    """``J_n = e^{-L} ∫_0^∞ s^n e^{-a s² + b s} ds`` for n = 0..nmax, with ``L = log_scale``.

    ``J_0 = ½√(π/a) e^{b²/4a} erfc(-b/(2√a))``, ``J_1 = 1/(2a) + (b/2a) J_0``,
    ``J_n = ((n-1)/(2a)) J_{n-2} + (b/2a) J_{n-1}``; ``L`` must be ``>= b²/4a`` for ``b > 0`` and
    ``>= 0`` otherwise, to avoid overflow.
    """
    y = b / (2.0 * math.sqrt(a))
    pos = b >= 0
    yy = np.where(pos, y * y, 0.0)
    head = np.where(pos, np.exp(yy - log_scale) * special.erfc(-np.abs(y)),
                    np.exp(-log_scale) * special.erfcx(np.abs(y)))
    j = [0.5 * math.sqrt(math.pi / a) * head]
    j.append(np.exp(-log_scale) / (2.0 * a) + b / (2.0 * a) * j[0])
    for n in range(2, nmax + 1):
        j.append((n - 1) / (2.0 * a) * j[n - 2] + b / (2.0 * a) * j[n - 1])
    return j


def _summit_integrals(xi, alpha: float):
    """``(p_s, n_s, E)`` with ``p_sum = p_s e^E`` and ``K̄_A* = -n_s/p_s`` (overflow-safe)."""
    c1 = _c1(alpha)
    xi = np.asarray(xi, dtype=float)
    bb = 1.5 / math.sqrt(float(alpha))
    a1 = c1 * bb * bb + 0.75
    a2 = a1 + 1.5
    lin = 2.0 * c1 * bb * xi
    # exponent of the dominant (a1) Gaussian: -C1 ξ² + lin²/(4 a1) for ξ > 0, -C1 ξ² otherwise
    log_scale = -c1 * xi**2 + np.where(lin > 0, lin * lin / (4.0 * a1), 0.0)
    j1 = _scaled_moments(3, a1, lin, log_scale + c1 * xi**2)
    j2 = _scaled_moments(1, a2, lin, log_scale + c1 * xi**2)
    const = 27.0 * math.sqrt(c1) / (4.0 * math.pi)
    p_s = const * (2.0 / 3.0 * j1[2] - 4.0 / 9.0 * j1[0] + 4.0 / 9.0 * j2[0])
    n_s = const * (2.0 / 3.0 * j1[3] - 4.0 / 9.0 * j1[1] + 4.0 / 9.0 * j2[1])
    return p_s, n_s, log_scale


def summit_height_density(xi, alpha: float):
    """Nayak's summit height density ``p_sum(ξ)``, ``ξ = z/√m0`` (eq. 3.49, corrected exponent).

    Examples
    --------
    >>> from scipy.integrate import quad
    >>> round(quad(lambda x: summit_height_density(x, 5.0), -20, 20)[0], 12)
    1.0
    """
    p_s, _, scale = _summit_integrals(xi, alpha)
    out = p_s * np.exp(scale)
    return float(out) if np.ndim(out) == 0 else out


def summit_mean_curvature(xi, alpha: float):
    """``K̄_A*(ξ) = E[(k1 + k2)/2 | summit at ξ]`` (negative), ``k = K/√m4``.

    The conditional mean of the arithmetic curvature that eq. 3.48 intends, computed from eq. 3.33.
    For high summits ``K̄_A* → -ξ/√α``, i.e. ``K̄_A → -(m2/m0) z``.
    """
    p_s, n_s, _ = _summit_integrals(xi, alpha)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = -n_s / p_s
    return float(out) if np.ndim(out) == 0 else out
