r"""Wavy (single-wavelength) contact: Westergaard and Johnson, in the package's groups.

The closed forms live in :mod:`viscocontact.reference` (the oracles of the integration tests); this
module re-exports them next to the other theories and adds the inverse (penetration-controlled)
forms and pull-off shortcuts, without duplicating any formula.

Rigid profile ``q0·r = Λ̃ cos x̃`` on an elastic half-plane, contact ``|x̃| < Ã/2``, groups of thesis
eq. 4.17 (``p̃ = 2(1-ν²)p/(E0 q0 Λ)``, ``Δ̃ = Δ/Λ``, ``Γ̃ = γ̃/Λ̃²``, ``β = E/E0``):

* Westergaard (adhesionless): ``p̃∞ = sin²(Ã/4)``, ``Δ̃ = s²(1 - 2 log s)``, ``s = sin(Ã/4)``
  (:func:`westergaard_pressure`, :func:`westergaard_area`, :func:`westergaard_penetration`,
  :func:`westergaard_area_at_penetration`).
* Johnson (JKR-type adhesion): ``p̃∞ = β s² - 2√(βΓ̃ tan(Ã/4))``,
  ``Δ̃ = s²(1 - 2 log s) + 2C log s`` with ``C = 2√(Γ̃ tan(Ã/4)/β)`` (:class:`JohnsonWavy`, which
  also has ``area_at_pressure``, ``area_at_penetration`` and ``closure``); pull-off under load
  control (minimum of ``p̃∞`` on the stable branch) and under penetration control (minimum of
  ``Δ̃``): :func:`johnson_pull_off_load`, :func:`johnson_pull_off_penetration`.

For small contacts (``Γ̃ → 0``) Johnson's solution tends to the JKR line contact of
:class:`~viscocontact.theories.jkr.JKRCylinder` with the crest radius ``1/(q0Λ̃)``; its load-controlled
pull-off tends to ``p̃_off = -(3/4)(4βΓ̃²)^(1/3)`` (β = E/E0; γ̃ is defined with E0).

Not implemented: Carbone & Mangialardi's asymmetric wavy contact (sliding with different adhesion
energies at the advancing and receding edges). It needs the contact of a sinusoid on an arc that is
not centred on the crest, with two independent edge balances; it is not a thin wrapper and was left
out (see ``docs/theories.md``).

References
----------
Westergaard, H. M. (1939). Bearing pressures and cracks. J. Appl. Mech. 6, A49-A53.
Johnson, K. L. (1995). The adhesion of two elastic bodies with slightly wavy surfaces.
Int. J. Solids Struct. 32, 423-430. doi:10.1016/0020-7683(94)00111-9
"""
from __future__ import annotations

import math

from scipy.optimize import brentq

from ..reference import JohnsonWavy, westergaard_area, westergaard_penetration, westergaard_pressure
from . import _args

__all__ = ["JohnsonWavy", "johnson_pull_off_load", "johnson_pull_off_penetration",
           "westergaard_area", "westergaard_area_at_penetration", "westergaard_penetration",
           "westergaard_pressure"]


def westergaard_area_at_penetration(penetration: float) -> float:
    """Contact area ``Ã`` of Westergaard's contact at penetration ``Δ̃`` in ``[0, 1]``.

    Inverse of :func:`westergaard_penetration`, which increases monotonically
    (``dΔ̃/ds = -4 s log s >= 0``) from 0 at ``Ã = 0`` to 1 at full contact ``Ã = 2π``.

    Examples
    --------
    >>> round(westergaard_area_at_penetration(float(westergaard_penetration(1.0))), 12)
    1.0
    """
    d = _args.real("penetration", penetration, 0.0, 1.0)
    if d == 0.0:
        return 0.0
    if d == 1.0:
        return 2.0 * math.pi
    return brentq(lambda a: float(westergaard_penetration(a)) - d, 1e-300, 2.0 * math.pi,
                  xtol=1e-300, rtol=1e-15)


def johnson_pull_off_load(Gamma: float, modulus_ratio: float = 1.0) -> tuple[float, float, float]:
    """``(Ã, p̃∞, Δ̃)`` at Johnson's load-controlled pull-off (``JohnsonWavy.pull_off("load")``)."""
    return JohnsonWavy(Gamma=Gamma, modulus_ratio=modulus_ratio).pull_off("load")


def johnson_pull_off_penetration(Gamma: float,
                                 modulus_ratio: float = 1.0) -> tuple[float, float, float]:
    """``(Ã, p̃∞, Δ̃)`` at Johnson's penetration-controlled pull-off (minimum of ``Δ̃``)."""
    return JohnsonWavy(Gamma=Gamma, modulus_ratio=modulus_ratio).pull_off("penetration")
