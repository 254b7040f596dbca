r"""Hertz's adhesionless contact of a sphere (thesis §1.1, equations 1.4, 1.7-1.15) and of a
cylinder.

Nomenclature
------------
``R``  combined radius of curvature, ``1/R = 1/R1 + 1/R2`` (eq. 1.4);
``E*`` reduced modulus, ``1/E* = (1-ν1²)/E1 + (1-ν2²)/E2`` (eq. 1.13); for a rigid indenter on an
elastic solid ``E* = E/(1-ν²)``, which is the modulus of the package's groups (``E0/(1-ν²)``);
``a``  contact radius (sphere) or half-width (cylinder); ``δ`` penetration (approach);
``P``  load (sphere, N) or load per unit length (cylinder, N/m); ``p0`` maximum pressure.

Sphere (axisymmetric, 3D)
-------------------------
.. math::
    p(r) = p_0\sqrt{1 - r^2/a^2}\ (1.7),\quad P = \tfrac{2}{3}\pi p_0 a^2\ (1.14),\quad
    a^3 = \frac{3PR}{4E^*},\quad \delta = \frac{a^2}{R}\ (1.15),\quad p_0 = \frac{2E^*a}{\pi R},

and inside the contact the surface displacement is ``u(r) = π p0 (2a² - r²)/(4 a E*)`` (eq. 1.12).
Equivalently ``P = (4/3) E* √R δ^{3/2}`` (eq. 3.24).

Cylinder (line contact, 2D plane strain)
----------------------------------------
A parabolic cylinder ``h = x²/(2R)`` on a half-plane carries, per unit length,

.. math::
    p(x) = p_0\sqrt{1 - x^2/a^2},\qquad P' = \frac{\pi}{2}p_0 a = \frac{\pi E^* a^2}{4R},
    \qquad p_0 = \frac{E^* a}{2R}.

The penetration of a half-plane is not defined (the displacement of a line load grows like
``log|x|``); in the periodic problem it is fixed by the period, see
:func:`~viscocontact.reference.westergaard_penetration`. In the package's groups the cylinder is the
small-contact limit of Westergaard's wavy contact: with the crest radius ``R = 1/(q0 Λ̃)`` of
``Λ̃ cos x̃`` and the mean pressure ``p∞ = P'/λ0``, ``p̃∞ = 2p∞/(E* Λ̃) = (Ã/4)²``, the first term of
``sin²(Ã/4)``.

Units: any consistent set (SI: m, Pa, N for the sphere and N/m for the cylinder). The formulas are
scale-free; the thesis plots ``a/R``, ``δ/R`` and ``P/(E* R²)`` (Figs. 1.5-1.6).

References
----------
Hertz, H. (1882). Über die Berührung fester elastischer Körper. J. reine angew. Math. 92, 156-171.
doi:10.1515/crll.1882.92.156
Johnson, K. L. (1985). Contact Mechanics, §§4.2-4.3. Cambridge University Press.
doi:10.1017/CBO9781139171731
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from .._validation import positive
from ..errors import ValidationError
from . import _args

__all__ = ["HertzCylinder", "HertzSphere", "combined_radius", "reduced_modulus"]


def reduced_modulus(young1: float, poisson1: float, young2: float = math.inf,
                    poisson2: float = 0.0) -> float:
    """``E* = 1/((1-ν1²)/E1 + (1-ν2²)/E2)`` (eq. 1.13); ``young2 = inf`` is a rigid body.

    Parameters
    ----------
    young1, young2 : float
        Young's moduli (Pa), > 0 (``young2`` may be ``inf``).
    poisson1, poisson2 : float
        Poisson ratios in (-1, 0.5].

    Examples
    --------
    >>> reduced_modulus(10e6, 0.5)   # rubber on a rigid indenter: E/(1-ν²)
    13333333.333333334
    """
    e1 = _args.positive("young1", young1)
    n1 = _args.real("poisson1", poisson1, -1.0, 0.5, lo_open=True)
    n2 = _args.real("poisson2", poisson2, -1.0, 0.5, lo_open=True)
    e2 = float(young2)
    if not (e2 > 0):
        raise ValidationError("young2", young2, "a real number in (0.0, inf]")
    compliance = (1 - n1**2) / e1 + (0.0 if math.isinf(e2) else (1 - n2**2) / e2)
    return 1.0 / compliance


def combined_radius(radius1: float, radius2: float = math.inf) -> float:
    """``R = 1/(1/R1 + 1/R2)`` (eq. 1.4); ``radius2 = inf`` is a flat."""
    r1 = _args.positive("radius1", radius1)
    r2 = float(radius2)
    if not (r2 > 0):
        raise ValidationError("radius2", radius2, "a real number in (0.0, inf]")
    return 1.0 / (1.0 / r1 + (0.0 if math.isinf(r2) else 1.0 / r2))


@attrs.frozen(kw_only=True)
class HertzSphere:
    """Hertz contact of a sphere (paraboloid) on a half-space (eqs. 1.7-1.15).

    Parameters
    ----------
    radius : float
        Combined radius R > 0 (m).
    reduced_modulus : float
        E* > 0 (Pa).

    Examples
    --------
    >>> h = HertzSphere(radius=1.0, reduced_modulus=1.0)
    >>> round(float(h.contact_radius(4.0 / 3.0)), 12), float(h.penetration(1.0))
    (1.0, 1.0)
    """

    radius: float = attrs.field(validator=positive)
    reduced_modulus: float = attrs.field(validator=positive)

    def load(self, contact_radius):
        """``P = 4E*a³/(3R)`` (eqs. 1.14-1.15), N."""
        a = _args.non_negative("contact_radius", contact_radius)
        return 4.0 * self.reduced_modulus * np.power(a, 3) / (3.0 * self.radius)

    def contact_radius(self, load):
        """``a = (3PR/(4E*))^(1/3)`` (eq. 1.15) for ``P >= 0``."""
        p = _args.non_negative("load", load)
        return np.cbrt(3.0 * p * self.radius / (4.0 * self.reduced_modulus))

    def penetration(self, contact_radius):
        """``δ = a²/R`` (eq. 1.15)."""
        a = _args.non_negative("contact_radius", contact_radius)
        return np.power(a, 2) / self.radius

    def load_at_penetration(self, penetration):
        """``P = (4/3) E* √R δ^(3/2)`` (eq. 3.24) for ``δ >= 0``."""
        d = _args.non_negative("penetration", penetration)
        return 4.0 / 3.0 * self.reduced_modulus * math.sqrt(self.radius) * np.power(d, 1.5)

    def max_pressure(self, contact_radius):
        """``p0 = 2E*a/(πR) = 3P/(2πa²)``."""
        a = _args.non_negative("contact_radius", contact_radius)
        return 2.0 * self.reduced_modulus * a / (math.pi * self.radius)

    def pressure(self, r, contact_radius):
        """``p(r) = p0 √(1 - r²/a²)`` inside the contact, 0 outside (eq. 1.7)."""
        a = _args.positive("contact_radius", contact_radius)
        rr = np.abs(np.asarray(r, dtype=float))
        inside = np.clip(1.0 - (rr / a) ** 2, 0.0, None)
        return self.max_pressure(a) * np.sqrt(inside)

    def displacement(self, r, contact_radius):
        """``u(r) = π p0 (2a² - r²)/(4aE*)`` for ``r <= a`` (eq. 1.12); ``u(0) = δ``."""
        a = _args.positive("contact_radius", contact_radius)
        rr = np.asarray(r, dtype=float)
        if np.any(np.abs(rr) > a):
            raise ValidationError("r", float(np.max(np.abs(rr))),
                                        f"|r| <= contact_radius = {a}")
        return math.pi * self.max_pressure(a) * (2 * a * a - rr**2) / (4 * a * self.reduced_modulus)


@attrs.frozen(kw_only=True)
class HertzCylinder:
    """Hertz line contact of a parabolic cylinder on a half-plane (plane strain), per unit length.

    Parameters
    ----------
    radius : float
        Crest radius R > 0 (m).
    reduced_modulus : float
        Plane-strain modulus E* > 0 (Pa).

    Notes
    -----
    ``P' = πE*a²/(4R)`` (N/m), ``p0 = E*a/(2R) = 2P'/(πa)``. No penetration: see the module
    docstring. With ``R = 1/(q0 Λ̃)`` and ``p̃∞ = 2P'/(λ0 E* Λ̃)`` this is Westergaard's
    ``p̃∞ = sin²(Ã/4)`` to leading order in Ã.

    Examples
    --------
    >>> c = HertzCylinder(radius=2.0, reduced_modulus=1.0)
    >>> round(float(c.half_width(c.load(0.5))), 12)
    0.5
    """

    radius: float = attrs.field(validator=positive)
    reduced_modulus: float = attrs.field(validator=positive)

    def load(self, half_width):
        """``P' = πE*a²/(4R)`` (N/m)."""
        a = _args.non_negative("half_width", half_width)
        return math.pi * self.reduced_modulus * np.power(a, 2) / (4.0 * self.radius)

    def half_width(self, load):
        """``a = √(4P'R/(πE*))`` for ``P' >= 0``."""
        p = _args.non_negative("load", load)
        return np.sqrt(4.0 * p * self.radius / (math.pi * self.reduced_modulus))

    def max_pressure(self, half_width):
        """``p0 = E*a/(2R)``."""
        a = _args.non_negative("half_width", half_width)
        return self.reduced_modulus * a / (2.0 * self.radius)

    def pressure(self, x, half_width):
        """``p(x) = p0 √(1 - x²/a²)`` inside, 0 outside."""
        a = _args.positive("half_width", half_width)
        xx = np.abs(np.asarray(x, dtype=float))
        return self.max_pressure(a) * np.sqrt(np.clip(1.0 - (xx / a) ** 2, 0.0, None))
