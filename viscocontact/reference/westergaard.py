r"""Westergaard's adhesionless wavy contact, in the units of thesis equation 4.17.

A rigid sinusoid ``r = Λ cos(q0 x)`` pressed on an elastic half-plane of plane-strain modulus
``E* = E/(1-ν²)``; contact ``|x̃| < a`` (``Ã = 2a``), ``s = sin(a/2)``:

.. math::
    \tilde p(\tilde x) = 2\cos(\tilde x/2)\sqrt{s^2 - \sin^2(\tilde x/2)}, \qquad
    \tilde p_\infty = \sin^2(\tilde A/4), \qquad
    \tilde\Delta = s^2 (1 - 2\log s).

(``p̃ = 2p/(E* q0 Λ)``, i.e. ``p* = π E* Λ/λ0`` maps to 1.) ``Δ̃`` is measured from the mean plane
of the deformed solid; full contact (``a = π``) is reached at ``p̃∞ = 1``, ``Δ̃ = 1``.
The penetration follows from ``Δ̃ = -(1/π)∫ p̃ log|2 sin(x̃/2)| dx̃`` with the substitution
``sin(x̃/2) = s sin θ`` and ``∫_0^{π/2} cos²θ log sin θ dθ = -(π/8)(1 + 2 log 2)``.

References
----------
Westergaard, H. M. (1939). Bearing pressures and cracks. J. Appl. Mech. 6, A49-A53.
Johnson, K. L. (1985). Contact Mechanics, §13.2. Cambridge University Press. doi:10.1017/CBO9781139171731
"""
from __future__ import annotations

import numpy as np


def westergaard_pressure(area):
    """``p̃∞ = sin²(Ã/4)`` for contact area ``Ã`` in ``[0, 2π]``."""
    return np.sin(np.asarray(area, dtype=float) / 4.0) ** 2


def westergaard_area(mean_pressure):
    """Inverse of :func:`westergaard_pressure`, ``p̃∞`` in ``[0, 1]``."""
    p = np.asarray(mean_pressure, dtype=float)
    return 4.0 * np.arcsin(np.sqrt(np.clip(p, 0.0, 1.0)))


def westergaard_penetration(area):
    """``Δ̃ = s²(1 - 2 log s)``, ``s = sin(Ã/4)``."""
    s = np.sin(np.asarray(area, dtype=float) / 4.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(s > 0, s**2 * (1.0 - 2.0 * np.log(s)), 0.0)
