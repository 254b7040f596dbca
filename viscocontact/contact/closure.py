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


#: Relative round-off of the closed contact's friction and power (sums of ``n >= 1024``
#: products of FFT coefficients): the floor of their error estimates.
ROUND_OFF = 1e-10


def measures(stress, slopes, loss, amplitude: float, mean_pressure: float):
    """Friction (eq. 4.16) and the power fed into the solid as a friction,
    ``4π Σ_m |σ̂_m|² Im K(m)`` (the spectral form of
    :func:`~viscocontact.contact.fields.dissipated_friction`), of the closed contact's
    oscillating stress ``stress`` (zero mean, on a uniform grid over the period, the profile's
    ``slopes`` there) under ``p̃∞ = mean_pressure``; ``loss`` is ``Im K(m)`` for ``m = 1, 2, …``
    (at least half the grid's points). NaN where the load vanishes to round-off."""
    n = len(stress)
    sigma = np.asarray(stress, dtype=float) - mean_pressure
    if not abs(mean_pressure) > 1e-12 * float(np.mean(np.abs(sigma))):
        return np.nan, np.nan
    mu = float(np.mean(sigma * slopes) / mean_pressure)
    coefficients = np.fft.rfft(stress)[1:] / n
    power = 4 * np.pi * float(np.sum(np.abs(coefficients) ** 2 * loss[:coefficients.size]))
    return mu, amplitude * power / (2 * np.pi * mean_pressure)


def estimates(stress, slopes, loss, amplitude: float, mean_pressure: float,
              scale) -> tuple[float, dict]:
    """The closed contact's friction, dissipated power and their error estimates: the area is
    exact (2π); μ and the power change by what every other grid point gives (nothing, for a
    profile with fewer modes than a quarter of the points, but round-off: the floor
    :data:`ROUND_OFF`), relative to ``scale(μ)`` (the methods' ``max(|μ|, floor·√m2)``).
    Returns μ and the result's ``friction_dissipation``, ``error_estimate`` and
    ``estimates``."""
    mu, power = measures(stress, slopes, loss, amplitude, mean_pressure)
    half = measures(stress[::2], slopes[::2], loss, amplitude, mean_pressure)
    size = scale(mu)
    errors = [max(abs(a - b) / size, ROUND_OFF) if np.isfinite(a - b) else np.nan
              for a, b in zip((mu, power), half)]
    return mu, {"friction_dissipation": power, "error_estimate": float(errors[0]),
                "estimates": {"area": 0.0, "friction": float(errors[0]),
                              "dissipation": float(errors[1]), "friction_scale": size}}
