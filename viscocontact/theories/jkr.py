r"""JKR adhesive contact of a sphere (thesis §1.4, equations 1.39-1.47) and of a cylinder (line
contact).

Infinitely short-range adhesion of Dupré energy ``Δγ`` (eq. 1.19); ``R``, ``E*``, ``a``, ``δ``, ``P``
as in :mod:`viscocontact.theories.hertz`. Tension is negative: ``P < 0`` pulls, ``δ < 0`` is a
neck below the undeformed surface.

Sphere
------
The pressure is Hertz's plus the flat-punch term (eq. 1.11) with ``p0 = 2E*a/(πR)`` and

.. math::
    p_1 = \frac{E^*}{\pi}\Big(\frac{\delta}{a} - \frac{a}{R}\Big)\ (1.39),\qquad
    U_{el} = E^*\Big(a\delta^2 - \frac{2a^3\delta}{3R} + \frac{a^5}{5R^2}\Big)\ (1.41).

Griffith's balance ``∂U_el/∂a|_δ = 2πaΔγ`` (eqs. 1.42-1.43, i.e. ``G = Δγ`` with
``G = E*(δ - a²/R)²/(2πa)``) gives

.. math::
    \delta = \frac{a^2}{R} - \sqrt{\frac{2\pi\Delta\gamma a}{E^*}}\ (1.44),\qquad
    P = \frac{4E^*a^3}{3R} - 2\sqrt{2\pi\Delta\gamma E^*}\,a^{3/2}\ (1.45),

and ``P = ∂U_el/∂δ|_a``. The stress-intensity factor at the edge is ``K = -p1√(πa)`` and
``K²/(2E*) = Δγ``. Pull-off (eqs. 1.46-1.47, which print magnitudes):

======================  ============  ========================  =============================
control                 ``P_c``       ``a``                     ``δ``
======================  ============  ========================  =============================
load (dP/da = 0)        ``-3πΔγR/2``  ``(9πΔγR²/(8E*))^(1/3)``  ``-(3π²Δγ²R/(64E*²))^(1/3)``
displacement (dδ/da=0)  ``-5πΔγR/6``  ``(πΔγR²/(8E*))^(1/3)``   ``-(27π²Δγ²R/(64E*²))^(1/3)``
======================  ============  ========================  =============================

Both pull-off loads are independent of E*. The thesis's Figs. 1.5-1.6 use
``Δγ/(πE*R) = 0.00018``.

Cylinder (2D, per unit length)
------------------------------
``P' = πE*a²/(4R) - √(2πE*Δγ a)``; under load control the contact separates at
``a = (2R²Δγ/(πE*))^(1/3)``, ``P'_c = -(3/4)(4πE*RΔγ²)^(1/3)``. In the package's groups
(``R = 1/(q0Λ̃)``, ``Δγ/E* = πγ̃/q0``, ``p̃∞ = 2P'/(λ0E*Λ̃)``) this is the small-contact limit of
Johnson's adhesive wavy contact: ``p̃∞ ≈ (Ã/4)² - √(Γ̃Ã)`` and ``p̃_off → -(3/4)(4Γ̃²)^(1/3)`` as
``Γ̃ = γ̃/Λ̃² → 0``.

Units: any consistent set (SI: m, Pa, J/m², N or N/m).

References
----------
Johnson, K. L., Kendall, K., Roberts, A. D. (1971). Surface energy and the contact of elastic
solids. Proc. R. Soc. Lond. A 324, 301-313. doi:10.1098/rspa.1971.0141
Maugis, D. (2000). Contact, Adhesion and Rupture of Elastic Solids. Springer.
doi:10.1007/978-3-662-04125-3
Barquins, M. (1988). Adherence and rolling kinetics of a rigid cylinder in contact with a natural
rubber surface. J. Adhesion 26, 1-12.
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from .._validation import non_negative, positive
from ..errors import ValidationError
from . import _args
from .hertz import HertzCylinder, HertzSphere

__all__ = ["JKRCylinder", "JKRSphere", "PullOff"]


@attrs.frozen(kw_only=True)
class PullOff:
    """The state at which an adhesive contact separates.

    Attributes
    ----------
    load : float
        Pull-off load (negative: tensile); N, or N/m for a line contact.
    contact_radius : float
        Contact radius (or half-width) at pull-off.
    penetration : float or None
        Penetration at pull-off (negative: neck); None where it is not defined (half-plane).
    """

    load: float
    contact_radius: float
    penetration: float | None


def largest_quartic_root(b, e):
    """Largest real root ``s >= 0`` of ``s⁴ - b s - e = 0`` (``b >= 0``), vectorised.

    ``f(s) = s⁴ - bs - e`` is convex for ``s > 0`` and increasing beyond its minimum, so Newton's
    iteration from ``s0 = max((2b)^(1/3), (2|e|)^(1/4))`` (where ``f >= 0``) decreases
    monotonically to the root. Entries without a root (``e`` below the minimum of ``s⁴ - bs``) are
    NaN.
    """
    b = np.asarray(b, dtype=float)
    e = np.asarray(e, dtype=float)
    b, e = np.broadcast_arrays(b, e)
    s = np.maximum(np.cbrt(2.0 * b), np.power(2.0 * np.abs(e), 0.25))
    for _ in range(200):
        f = s**4 - b * s - e
        df = 4.0 * s**3 - b
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(df > 0, f / df, 0.0)
        s = s - step
        if np.all(np.abs(step) <= 4 * np.finfo(float).eps * np.maximum(s, 1e-300)):
            break
    smin = np.cbrt(b / 4.0)
    exists = e >= -(3.0 / 4.0) * b * smin - 1e-14 * np.maximum(np.abs(e), b * smin)
    return np.where(exists, s, np.nan)


@attrs.frozen(kw_only=True)
class JKRSphere:
    """JKR contact of a sphere on a half-space (eqs. 1.39-1.47); see the module docstring.

    Parameters
    ----------
    radius : float
        Combined radius R > 0 (m).
    reduced_modulus : float
        E* > 0 (Pa), eq. 1.13.
    work_of_adhesion : float
        Dupré energy Δγ >= 0 (J/m²), eq. 1.19. ``Δγ = 0`` is Hertz.

    Examples
    --------
    >>> import math
    >>> j = JKRSphere(radius=1.0, reduced_modulus=1.0, work_of_adhesion=1e-3)
    >>> round(j.pull_off_load_control().load / (math.pi * 1e-3), 12)
    -1.5
    """

    radius: float = attrs.field(validator=positive)
    reduced_modulus: float = attrs.field(validator=positive)
    work_of_adhesion: float = attrs.field(validator=non_negative)

    @property
    def hertz(self) -> HertzSphere:
        """The adhesionless limit ``Δγ → 0``."""
        return HertzSphere(radius=self.radius, reduced_modulus=self.reduced_modulus)

    @property
    def _c(self) -> float:
        return math.sqrt(2.0 * math.pi * self.work_of_adhesion / self.reduced_modulus)

    # -- the equilibrium curve (eqs. 1.44-1.45) -------------------------------------------------
    def penetration(self, contact_radius):
        """``δ = a²/R - √(2πΔγa/E*)`` (eq. 1.44)."""
        a = _args.non_negative("contact_radius", contact_radius)
        return np.power(a, 2) / self.radius - self._c * np.sqrt(a)

    def penetration_derivative(self, contact_radius):
        """``dδ/da = 2a/R - √(2πΔγ/E*)/(2√a)`` (> 0 on the displacement-stable branch)."""
        a = _args.positive("contact_radius", contact_radius)
        return 2.0 * a / self.radius - 0.5 * self._c / np.sqrt(a)

    def load(self, contact_radius):
        """``P = 4E*a³/(3R) - 2√(2πΔγE*) a^(3/2)`` (eq. 1.45)."""
        a = _args.non_negative("contact_radius", contact_radius)
        es = self.reduced_modulus
        return (4.0 * es * np.power(a, 3) / (3.0 * self.radius)
                - 2.0 * es * self._c * np.power(a, 1.5))

    def contact_radius(self, load):
        """Contact radius on the load-controlled stable branch, ``P >= -3πΔγR/2``.

        ``a³ = (3R/(4E*))·(P + 3πΔγR + √(6πΔγRP + (3πΔγR)²))``.
        """
        w = 3.0 * math.pi * self.work_of_adhesion * self.radius
        p = _args.real("load", load, -w / 2.0)
        root = np.sqrt(np.clip(2.0 * w * p + w * w, 0.0, None))
        return np.cbrt(3.0 * self.radius / (4.0 * self.reduced_modulus) * (p + w + root))

    def contact_radius_at_penetration(self, penetration):
        """Contact radius on the displacement-controlled stable branch (``dδ/da > 0``).

        ``δ`` must be at least the displacement-controlled pull-off penetration (eq. 1.47);
        ``s = √a`` is the largest root of ``s⁴ - R√(2πΔγ/E*) s - Rδ = 0``.
        """
        d_min = self.pull_off_displacement_control().penetration
        d = _args.real("penetration", penetration, d_min)
        s = largest_quartic_root(self.radius * self._c, self.radius * d)
        s = np.where(np.isnan(s), np.cbrt(self.radius * self._c / 4.0), s)  # at δ_min, to rounding
        return np.power(s, 2) if np.ndim(s) else float(s) ** 2

    # -- fields and energies -------------------------------------------------------------------
    def edge_coefficient(self, contact_radius):
        """``p1 = (E*/π)(δ/a - a/R) = -√(2Δγ E*/(πa))`` on the equilibrium curve (eq. 1.39)."""
        a = _args.positive("contact_radius", contact_radius)
        return -np.sqrt(2.0 * self.work_of_adhesion * self.reduced_modulus / (math.pi * a))

    def pressure(self, r, contact_radius):
        """``p(r) = p0√(1 - r²/a²) + p1/√(1 - r²/a²)`` for ``|r| < a`` (eq. 1.11), 0 outside."""
        a = _args.positive("contact_radius", contact_radius)
        rr = np.abs(np.asarray(r, dtype=float))
        inside = rr < a
        w = np.sqrt(np.where(inside, 1.0 - (rr / a) ** 2, 1.0))
        p0 = 2.0 * self.reduced_modulus * a / (math.pi * self.radius)
        return np.where(inside, p0 * w + self.edge_coefficient(a) / w, 0.0)

    def stress_intensity(self, contact_radius):
        """``K = -p1√(πa)`` (Pa·m^½); Griffith: ``K²/(2E*) = Δγ``."""
        a = _args.positive("contact_radius", contact_radius)
        return -self.edge_coefficient(a) * np.sqrt(math.pi * a)

    def elastic_energy(self, contact_radius, penetration):
        """``U_el(δ, a) = E*(aδ² - 2a³δ/(3R) + a⁵/(5R²))`` (eq. 1.41), J; any (a, δ)."""
        a = _args.non_negative("contact_radius", contact_radius)
        d = _args.real("penetration", penetration)
        r = self.radius
        return self.reduced_modulus * (a * d * d - 2 * a**3 * d / (3 * r) + a**5 / (5 * r * r))

    def energy_release_rate(self, contact_radius, penetration):
        """``G = (∂U_el/∂a)|_δ / (2πa) = E*(δ - a²/R)²/(2πa)`` (J/m²); ``G = Δγ`` at equilibrium."""
        a = _args.positive("contact_radius", contact_radius)
        d = _args.real("penetration", penetration)
        return self.reduced_modulus * (d - a * a / self.radius) ** 2 / (2.0 * math.pi * a)

    # -- pull-off (eqs. 1.46-1.47) -------------------------------------------------------------
    def pull_off_load_control(self) -> PullOff:
        """Load control (eq. 1.46, signed): ``P_c = -3πΔγR/2`` where ``dP/da = 0``."""
        g, r, e = self.work_of_adhesion, self.radius, self.reduced_modulus
        return PullOff(load=-1.5 * math.pi * g * r,
                       contact_radius=(9 * math.pi * g * r * r / (8 * e)) ** (1 / 3),
                       penetration=-((3 * math.pi**2 * g * g * r / (64 * e * e)) ** (1 / 3)))

    def pull_off_displacement_control(self) -> PullOff:
        """Displacement control (eq. 1.47, signed): ``P_c = -5πΔγR/6`` where ``dδ/da = 0``."""
        g, r, e = self.work_of_adhesion, self.radius, self.reduced_modulus
        return PullOff(load=-5.0 / 6.0 * math.pi * g * r,
                       contact_radius=(math.pi * g * r * r / (8 * e)) ** (1 / 3),
                       penetration=-((27 * math.pi**2 * g * g * r / (64 * e * e)) ** (1 / 3)))


@attrs.frozen(kw_only=True)
class JKRCylinder:
    """JKR line contact of a parabolic cylinder on a half-plane, per unit length.

    Parameters
    ----------
    radius : float
        Crest radius R > 0 (m).
    reduced_modulus : float
        Plane-strain modulus E* > 0 (Pa).
    work_of_adhesion : float
        Δγ >= 0 (J/m²).

    Notes
    -----
    ``P' = πE*a²/(4R) - √(2πE*Δγa)`` (N/m); load-controlled pull-off at
    ``a_c = (2R²Δγ/(πE*))^(1/3)``, ``P'_c = -(3/4)(4πE*RΔγ²)^(1/3)``. There is no penetration for a
    half-plane (see :mod:`viscocontact.theories.hertz`).
    """

    radius: float = attrs.field(validator=positive)
    reduced_modulus: float = attrs.field(validator=positive)
    work_of_adhesion: float = attrs.field(validator=non_negative)

    @property
    def hertz(self) -> HertzCylinder:
        """The adhesionless limit."""
        return HertzCylinder(radius=self.radius, reduced_modulus=self.reduced_modulus)

    def load(self, half_width):
        """``P' = πE*a²/(4R) - √(2πE*Δγa)`` (N/m)."""
        a = _args.non_negative("half_width", half_width)
        es = self.reduced_modulus
        return (math.pi * es * np.power(a, 2) / (4.0 * self.radius)
                - np.sqrt(2.0 * math.pi * es * self.work_of_adhesion * a))

    def half_width(self, load):
        """Half-width on the load-controlled stable branch, ``P' >= P'_c``."""
        p = _args.real("load", load, self.pull_off_load_control().load)
        scale = 4.0 * self.radius / (math.pi * self.reduced_modulus)
        b = scale * math.sqrt(2.0 * math.pi * self.reduced_modulus * self.work_of_adhesion)
        s = largest_quartic_root(b, scale * p)
        s = np.where(np.isnan(s), np.cbrt(b / 4.0), s)
        return np.power(s, 2) if np.ndim(s) else float(s) ** 2

    def pull_off_load_control(self) -> PullOff:
        """``P'_c = -(3/4)(4πE*RΔγ²)^(1/3)`` at ``a = (2R²Δγ/(πE*))^(1/3)``."""
        g, r, e = self.work_of_adhesion, self.radius, self.reduced_modulus
        return PullOff(load=-0.75 * (4 * math.pi * e * r * g * g) ** (1 / 3),
                       contact_radius=(2 * r * r * g / (math.pi * e)) ** (1 / 3), penetration=None)
