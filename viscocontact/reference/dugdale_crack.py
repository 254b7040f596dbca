r"""Apparent toughness of a steadily moving Dugdale crack in a standard linear solid.

A semi-infinite plane crack moves at constant speed V through a standard linear solid (thesis
eqs. 4.4-4.5) with creep function ``E0·J(t) = c(t/τ) = 1 - (1 - 1/β) e^{-t/τ}``: τ is the creep
(retardation) time of :class:`~viscocontact.rheology.StandardLinearSolid` and of ``ζ = q0Vτ``,
``β = E∞/E0``. Behind the tip a Dugdale zone of length ``a`` on the crack faces carries the
uniform closing traction σ0; the opening closes smoothly at the tip (no K left) and reaches
``δc = Δγ/σ0`` at the zone's far end, where the faces separate. Let ``κ = a/(Vτ)``: the
zone length over the distance travelled in one creep time (the time a material point spends in
the zone is ``κτ``). ``G = K²/E0'`` is the energy release rate of the far field, measured with the
*relaxed* modulus, so that ``G/Δγ`` is the apparent toughness (1 when slow).

Why it is exact. In steady state the creep integral along a material path is a convolution in the
crack-fixed coordinate and commutes with the elastic operator of the surface, so the opening is
the elastic response (compliance ``1/E0``) to the *creep-integrated* traction, and equally the
*relaxation-integrated* opening is the elastic response to the actual traction. Each integral
depends only on what the material met upstream. Where material enters the open faces from the
bonded region (opening crack), the relaxation-integrated opening vanishes in the bonded region,
so the stresses are the elastic ones. Where it enters from the open faces (closing crack), the
creep-integrated traction is known on the faces, so the opening is that of an elastic crack
under it.

Opening crack (the bonded region recedes: material leaves it through the zone). The stresses are
the elastic ones, ``K = σ0√(8a/π)``, and the opening is the creep integral of the elastic opening
along the material's path (Schapery 1975; Greenwood 2004). The elastic Dugdale opening grows as
``dD/ds = (8σ0/π) artanh√(s/a)`` with the distance ``s`` travelled into the zone, so

.. math::
    \frac{G}{\Delta\gamma} = \frac{1}{n(\kappa)},\qquad
    n = 1 - (1 - \beta^{-1})\, I(\kappa),\qquad
    I(\kappa) = \int_0^1 2w\,\operatorname{artanh}(w)\, e^{-\kappa(1-w^2)}\,dw
             = \frac{2}{\kappa}\int_0^{\sqrt\kappa} F(y)\,dy ,

with Dawson's function F. Closing crack (healing: material enters the bonded region through the
zone). The opening is that of an elastic crack of compliance ``1/E0`` loaded by the creep
integral of the traction history, ``σ0 c((a - r)/(Vτ))`` at distance r behind the tip. With
``m(κ) = ∫_0^1 c(κ(1 - w²)) dw = 1 - (1 - β^{-1}) F(√κ)/√κ``, the far field is
``K = σ0√(8a/π)·m`` and the opening at the zone's entry ``(8σ0a/(πE0'))(2m - n)``, so

.. math::
    \frac{G}{\Delta\gamma} = \frac{m(\kappa)^2}{2m(\kappa) - n(\kappa)} .

Limits: slow (κ → ∞) both → 1; fast (κ → 0) opening → β, closing → 1/β. Zone length:
``a/a0 = G/Δγ`` (opening), ``a/a0 = 1/(2m - n)`` (closing), with the quasi-static zone
``a0 = πE0'Δγ/(8σ0²)`` in a homogeneous solid (both faces deform). Since ``a`` depends on G,
the speed group is ``v = Vτ/a0`` and κ solves ``κ·n(κ) = 1/v`` (opening) or
``κ(2m - n) = 1/v`` (closing) — the self-consistent zone length; the toughness rises (opening)
or falls (closing) monotonically with v.

Rigid profile on a half-plane. Only one surface deforms: the opening is half a crack's, Irwin's
relation is ``G = K²/(2E*)`` and ``a0 = πE*Δγ/(4σ0²)``, the ratios above unchanged. In thesis
units (``γ̃``, ``h̃0 = q0h0``) ``q0a0 = h̃0²/(4γ̃)`` and ``v = 4ζγ̃/h̃0²`` (:func:`speed_group`); in
the frame of a rigid profile sliding over the solid, material enters contact at the leading edge
(closing crack) and leaves it at the trailing edge (opening crack).

Closed form: ``m`` (Dawson's function). Quadrature: ``I``, a single integral of a smooth,
bounded function (adaptive, 1e-13). The formulas were derived here; Greenwood (2004) and Persson &
Brener (2005) treat the same problem (the latter with a different cut-off of the zone), and the
equation numbers of those papers were not checked against their text.

References
----------
Schapery, R. A. (1975). A theory of crack initiation and growth in viscoelastic media I-III.
Int. J. Fract. 11, 141-159, 369-388, 549-562.
Greenwood, J. A. (2004). The theory of viscoelastic crack propagation and healing. J. Phys. D 37,
2557-2569.
Persson, B. N. J., Brener, E. A. (2005). Crack propagation in viscoelastic solids. Phys. Rev. E 71,
036123. doi:10.1103/PhysRevE.71.036123
"""
from __future__ import annotations

import math

import attrs
from scipy import integrate, optimize, special

from ..errors import ValidationError

CRACKS = ("opening", "closing")


def _check_beta(beta: float) -> float:
    try:
        b = float(beta)
    except (TypeError, ValueError):
        b = math.nan
    if not (math.isfinite(b) and b >= 1.0):
        raise ValidationError("beta", beta, "a finite real number >= 1")
    return b


def _check_crack(crack: str) -> str:
    if crack not in CRACKS:
        raise ValidationError("crack", crack, f"one of {list(CRACKS)}")
    return crack


def creep_weight_tip(kappa: float) -> float:
    """``I(κ) = ∫_0^1 2w artanh(w) e^{-κ(1-w²)} dw`` (1 at κ = 0, → 0 as κ → ∞).

    Evaluated as ``(1/κ)∫_0^1 (1 - e^{-κ(1-w²)})/(1 - w²) dw`` (by parts) with
    ``1 - w = e^{-s}``: a bounded integrand on ``s ∈ [0, ∞)`` decaying beyond ``s ≈ log 2κ``.
    """
    k = float(kappa)
    if not (math.isfinite(k) and k >= 0):
        raise ValidationError("kappa", kappa, "a finite real number >= 0")
    if k == 0.0:
        return 1.0

    def f(s):
        u = math.exp(-s)
        return -math.expm1(-k * u * (2 - u)) / (2 - u)

    knee = max(math.log(2 * k), 0.0)
    head = integrate.quad(f, 0.0, knee, epsabs=0, epsrel=1e-13, limit=200)[0] if knee else 0.0
    tail = integrate.quad(f, knee, knee + 60.0, epsabs=0, epsrel=1e-13, limit=200)[0]
    return (head + tail) / k


def creep_weight_zone(kappa: float) -> float:
    """``∫_0^1 e^{-κ(1-w²)} dw = F(√κ)/√κ`` (Dawson's F; 1 at κ = 0)."""
    k = float(kappa)
    if not (math.isfinite(k) and k >= 0):
        raise ValidationError("kappa", kappa, "a finite real number >= 0")
    return 1.0 if k == 0.0 else float(special.dawsn(math.sqrt(k))) / math.sqrt(k)


def _n_m(kappa, beta):
    soft = 1.0 - 1.0 / beta
    return 1.0 - soft * creep_weight_tip(kappa), 1.0 - soft * creep_weight_zone(kappa)


def toughness(kappa: float, beta: float, crack: str = "opening") -> float:
    """``G/Δγ`` at a given ``κ = a/(Vτ)`` (zone length over creep distance).

    Parameters
    ----------
    kappa : float
        ``a/(Vτ)`` >= 0 (0: infinitely fast).
    beta : float
        ``E∞/E0`` >= 1.
    crack : {"opening", "closing"}
        Opening (bonded region receding) or closing (healing) crack.
    """
    beta, crack = _check_beta(beta), _check_crack(crack)
    n, m = _n_m(kappa, beta)
    return 1.0 / n if crack == "opening" else m * m / (2 * m - n)


def zone_length(kappa: float, beta: float, crack: str = "opening") -> float:
    """``a/a0`` at a given κ: ``G/Δγ`` (opening), ``1/(2m - n)`` (closing)."""
    beta, crack = _check_beta(beta), _check_crack(crack)
    n, m = _n_m(kappa, beta)
    return 1.0 / n if crack == "opening" else 1.0 / (2 * m - n)


@attrs.frozen(kw_only=True)
class CrackState:
    """A steadily moving Dugdale crack at the speed group ``v = Vτ/a0``.

    Parameters
    ----------
    speed : float
        ``v = Vτ/a0``.
    kappa : float
        ``κ = a/(Vτ)`` of the self-consistent zone.
    toughness : float
        ``G/Δγ``.
    zone_length : float
        ``a/a0``.
    """

    speed: float
    kappa: float
    toughness: float
    zone_length: float


def steady_crack(speed: float, beta: float, crack: str = "opening") -> CrackState:
    """The self-consistent zone and toughness at ``v = Vτ/a0``: κ solves ``κ·(a0/a) = 1/v``.

    Examples
    --------
    >>> from viscocontact.reference.dugdale_crack import steady_crack
    >>> s = steady_crack(1.0, beta=10.0)
    >>> round(s.toughness, 4) == round(s.zone_length, 4), 1 < s.toughness < 10
    (True, True)
    """
    beta, crack = _check_beta(beta), _check_crack(crack)
    v = float(speed)
    if not (math.isfinite(v) and v > 0):
        raise ValidationError("speed", speed, "a finite real number > 0")
    # κ·(a0/a) rises from 0 to ∞ with κ; a/a0 lies within [1/2, β], so κ within [1/(2v), β/v]
    g = lambda lk: math.exp(lk) / zone_length(math.exp(lk), beta, crack) - 1.0 / v
    lo, hi = math.log(1.0 / (beta * v)) - 1.0, math.log(beta / v) + 1.0
    kappa = math.exp(optimize.brentq(g, lo, hi, xtol=1e-14, rtol=1e-14))
    return CrackState(speed=v, kappa=kappa, toughness=toughness(kappa, beta, crack),
                      zone_length=zone_length(kappa, beta, crack))


def speed_group(zeta: float, gamma: float, h0: float) -> float:
    """``v = Vτ/a0 = 4ζγ̃/h̃0²`` for a rigid profile on a half-plane, in thesis units.

    ``a0 = πE*Δγ/(4σ0²)`` with the relaxed ``E* = E0/(1-ν²)`` and ``σ0 = Δγ/h0`` gives
    ``q0a0 = h̃0²/(4γ̃)``; with ``ζ = q0Vτ`` the ratio follows.

    Parameters
    ----------
    zeta : float
        ``ζ = q0Vτ`` (thesis eq. 4.17).
    gamma : float
        ``γ̃ = (1-ν²)q0Δγ/(πE0)``.
    h0 : float
        ``h̃0 = q0h0``, the range of the Dugdale law.
    """
    return 4.0 * float(zeta) * float(gamma) / float(h0) ** 2


__all__ = ["CRACKS", "CrackState", "creep_weight_tip", "creep_weight_zone", "speed_group",
           "steady_crack", "toughness", "zone_length"]
