r"""The closed (full) contact's load and when it is the adhesionless answer: the rules that the
spectral method's and the BEM's closed contacts share.

A closed contact ties penetration and load through the mean displacement,
``Δ̃ = 1 - r̂_0 - 2π c0 p̃∞`` (``r̂_0`` the mean height of the normalised profile, ``c0`` the kernel's
mean compliance). An incompressible solid (``c0 = 0``, a half-plane) closes at the one
penetration ``1 - r̂_0``, where it carries any load from the closing load ``max σ̃_osc`` up; the
penetration-controlled answer there is that least load, the limit of the partial contacts
(Westergaard's p̃∞ = 1 at Δ̃ = 1).
"""
from __future__ import annotations

import numpy as np

#: Penetrations within this of an incompressible solid's closing penetration are that penetration.
CLOSING_TOLERANCE = 1e-9
#: What a result at an incompressible solid's closing penetration adds to its message.
AT_CLOSING_PENETRATION = ("; at the closing penetration of an incompressible solid, with the "
                          "least load that keeps it closed (the limit of partial contact)")


def load_at(penetration: float, mean_height: float, mean_compliance: float) -> float:
    """``p̃∞`` of the closed contact at ``Δ̃`` (NaN on an incompressible solid, whose penetration
    does not fix it)."""
    if mean_compliance == 0.0:
        return np.nan
    return -(penetration - 1.0 + mean_height) / (2.0 * np.pi * mean_compliance)


def at_closing_penetration(penetration: float, mean_height: float) -> bool:
    """Whether ``Δ̃`` is an incompressible solid's closing penetration ``1 - r̂_0``."""
    return abs(penetration - (1.0 - mean_height)) <= CLOSING_TOLERANCE


def closes(closing_load: float, mean_height: float, mean_compliance: float,
           mean_pressure=None, penetration=None) -> bool:
    """Whether the adhesionless equilibrium at this load or penetration is the closed contact: it
    carries the load without tension (``p̃∞ >= max σ̃_osc``); on an incompressible solid, at its
    closing penetration or beyond (beyond, the closed contact cannot be imposed)."""
    if mean_pressure is not None:
        return mean_pressure >= closing_load
    if mean_compliance == 0.0:
        return penetration >= 1.0 - mean_height - CLOSING_TOLERANCE
    return load_at(penetration, mean_height, mean_compliance) >= closing_load
