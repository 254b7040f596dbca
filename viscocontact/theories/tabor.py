r"""The Tabor parameter (thesis equation 1.48) and the crest radius of a rough profile (equation
4.55).

.. math::
    \mu_T = \Big(\frac{R\,\Delta\gamma^2}{E^{*2} Z_0^3}\Big)^{1/3} = \frac{l^{2/3}R^{1/3}}{Z_0},
    \qquad l = \frac{\Delta\gamma}{E^*},

with ``R`` the crest radius, ``Δγ`` the Dupré energy, ``E*`` the reduced modulus and ``Z0`` the
equilibrium distance of the traction law (the ``ε`` of :mod:`viscocontact.theories.lennard_jones`).
The thesis's eq. 1.48 prints ``E*`` to the first power in the first form, which is not
dimensionless; the second form is the standard one. :func:`tabor_parameter` is the package's
one definition of it (:mod:`viscocontact.groups` and ``viscocontact describe`` use it), so the
value is the same everywhere (``docs/thesis-notes.md`` §2).

JKR (infinitely short-range adhesion, the thesis's model) is accurate for ``μ_T >> 1`` (Greenwood:
for ``μ_T`` above about 3); DMT for ``μ_T << 1``.

Units: SI (m, J/m², Pa, m); ``μ_T`` is dimensionless.

References
----------
Tabor, D. (1977). Surface forces and surface interactions. J. Colloid Interface Sci. 58, 2-13.
Greenwood, J. A. (1997). Adhesion of elastic spheres. Proc. R. Soc. Lond. A 453, 1277-1297.
doi:10.1098/rspa.1997.0070
"""
from __future__ import annotations

import math

from . import _args

__all__ = ["equivalent_crest_radius", "tabor_parameter"]


def tabor_parameter(*, radius: float, work_of_adhesion: float, reduced_modulus: float,
                    equilibrium_distance: float = 1e-9) -> float:
    """``μ_T = (R Δγ²/(E*² Z0³))^(1/3)`` (eq. 1.48, second form).

    Parameters
    ----------
    radius : float
        Crest radius R > 0 (m).
    work_of_adhesion : float
        Δγ >= 0 (J/m²).
    reduced_modulus : float
        E* > 0 (Pa).
    equilibrium_distance : float
        Z0 > 0 (m), default 1 nm (the package's default, as in the thesis's §4.6).

    Examples
    --------
    The thesis's §4.6 case: R = 0.1 m, Δγ = 0.01 J/m², E0 = 10 MPa, ν = 0.5:

    >>> round(tabor_parameter(radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7 / 0.75), 1)
    383.2
    >>> round(tabor_parameter(radius=0.1, work_of_adhesion=0.01, reduced_modulus=1e7), 1)  # E0
    464.2
    """
    r = _args.positive("radius", radius)
    g = _args.non_negative("work_of_adhesion", work_of_adhesion)
    e = _args.positive("reduced_modulus", reduced_modulus)
    z = _args.positive("equilibrium_distance", equilibrium_distance)
    length = g / e                          # the adhesion length l = Δγ/E*
    return length ** (2.0 / 3.0) * r ** (1.0 / 3.0) / z


def equivalent_crest_radius(*, wavelength: float, rms: float) -> float:
    """``R ≈ λ0²/(4π² r_rms) = 1/(q0² r_rms)`` (eq. 4.55), m.

    The crest radius of a sinusoid of amplitude ``r_rms`` and wavelength ``λ0``; for the thesis's
    case (λ0 = 6.28 mm, r_rms = 10 µm) about 0.1 m.
    """
    lam = _args.positive("wavelength", wavelength)
    rms = _args.positive("rms", rms)
    return lam * lam / (4.0 * math.pi**2 * rms)
