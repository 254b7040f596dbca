"""The dimensionless groups of a scene (thesis equation 4.17) and its Tabor parameter (equation
1.48).

:func:`dimensionless_groups` is what ``viscocontact describe`` prints.

Tabor parameter
---------------
``μ_T = (R Δγ² / (E*² Z0³))^(1/3) = l^(2/3) R^(1/3) / Z0`` with the adhesion length ``l = Δγ/E*``
and the reduced (rubbery) modulus ``E* = E0/(1-ν²)``; ``tabor_glassy`` uses ``E∞/(1-ν²)``. The
thesis's eq. 1.48 prints ``E*`` to the first power in its first form, which is dimensionally
inconsistent; its second form (used here) is the standard one (Tabor 1977,
doi:10.1016/0021-9797(77)90396-4). The radius R is that of the crest of an equivalent sinusoid
(eq. 4.55): ``R = 1/(q0² Λ)`` for a sinusoid of amplitude Λ, and ``R = 1/(q0² r_rms)``
(= λ0²/(4π² r_rms)) for any other profile.

For the thesis's physical case (E0 = 10 MPa, ν = 0.5, Δγ = 0.01 J/m², λ0 = 6.28 mm,
r_rms = 10 µm, Z0 = 1 nm; R ≈ 0.1 m) this gives μ_T ≈ 383; the thesis's "μ_T ≈ 460" is obtained
with E0 in place of E* (≈ 464).
"""
from __future__ import annotations

from .scene import TABOR_SHORT_RANGE, dimensionless_groups, tabor_parameter

__all__ = ["TABOR_SHORT_RANGE", "dimensionless_groups", "tabor_parameter"]
