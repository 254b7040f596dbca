r"""Johnson's adhesive wavy contact (JKR-type, infinitely short-range adhesion), in thesis units.

Rigid sinusoid ``r̃ = cos x̃`` on an elastic half-plane of modulus ``E``; contact ``|x̃| < a``,
``s = sin(a/2)``, adhesion parameter ``Γ̃ = γ̃/Λ̃²`` (thesis eq. 4.17 with E0 as reference
modulus, ``β = E/E0``). The general solution on the arc adds to Westergaard's pressure the
homogeneous solution ``C cos(x̃/2)/√(s² - sin²(x̃/2))`` (tensile, mean 1, uniform displacement
``2 log s`` on the arc by the logarithmic capacity of a circular arc). Its stress-intensity factor
is ``K̃ = β C √(2π cot(a/2))`` (``K̃ = σ̃√(2π r̃)``), and Griffith's balance with the Irwin value
``K̃²/(4β) = 2πΓ̃`` (``δŨ/δX̃ = K̃²/(4β)``) gives ``C = 2√(Γ̃ tan(a/2)/β)``:

.. math::
    \tilde p_\infty = \beta\,\big[s^2 - C\big] = \beta s^2 - 2\sqrt{\beta\tilde\Gamma\tan(a/2)},\qquad
    \tilde\Delta = s^2(1 - 2\log s) + 2 C \log s .

In dimensional form ``p̄ = p* sin²(πa/λ) - √(2E*Δγ/λ) √tan(πa/λ)`` (Johnson 1995). The stable branch
under load control has ``dp̃∞/dÃ > 0``; pull-off is the minimum of ``p̃∞`` over it (load control) or
the extremum of ``Δ̃`` (penetration control).

References
----------
Johnson, K. L. (1995). The adhesion of two elastic bodies with slightly wavy surfaces.
Int. J. Solids Struct. 32, 423-430. doi:10.1016/0020-7683(94)00111-9
"""
from __future__ import annotations

import attrs
import numpy as np
from scipy.optimize import brentq, minimize_scalar

from .._validation import non_negative, positive


@attrs.frozen(kw_only=True)
class JohnsonWavy:
    """Adhesive wavy contact on an elastic half-plane.

    Parameters
    ----------
    Gamma : float
        ``Γ̃ = γ̃/Λ̃²`` (>= 0).
    modulus_ratio : float
        ``β = E/E0`` of the elastic solid relative to the reference modulus (1: relaxed).
    """

    Gamma: float = attrs.field(validator=non_negative)
    modulus_ratio: float = attrs.field(default=1.0, validator=positive)

    def _c(self, a):
        return 2.0 * np.sqrt(self.Gamma * np.tan(a / 2.0) / self.modulus_ratio)

    def mean_pressure(self, area):
        """``p̃∞(Ã)`` for ``Ã = 2a`` in ``(0, 2π)``."""
        a = np.asarray(area, dtype=float) / 2.0
        return self.modulus_ratio * (np.sin(a / 2) ** 2 - self._c(a))

    def penetration(self, area):
        """``Δ̃(Ã)``."""
        a = np.asarray(area, dtype=float) / 2.0
        s = np.sin(a / 2)
        return s**2 * (1 - 2 * np.log(s)) + 2 * self._c(a) * np.log(s)

    def stress_intensity(self, area):
        """``K̃ = σ̃√(2π r̃)`` at the edges on the adhesive equilibrium branch."""
        a = np.asarray(area, dtype=float) / 2.0
        return self.modulus_ratio * self._c(a) * np.sqrt(2 * np.pi / np.tan(a / 2))

    def pull_off(self, control: str = "load"):
        """``(Ã, p̃∞, Δ̃)`` at pull-off: min of p̃∞ (``"load"``) or of Δ̃ (``"penetration"``)."""
        f = self.mean_pressure if control == "load" else self.penetration
        res = minimize_scalar(lambda A: float(f(A)), bounds=(1e-9, 2 * np.pi - 1e-9),
                              method="bounded", options={"xatol": 1e-13})
        A = float(res.x)
        return A, float(self.mean_pressure(A)), float(self.penetration(A))

    def closure(self):
        """``(Ã, p̃∞)`` at the maximum of ``p̃∞`` on the stable branch: above it the contact snaps
        shut (full contact); without adhesion ``(2π, β)``."""
        if self.Gamma == 0:
            return 2 * np.pi, self.modulus_ratio
        A_min = self.pull_off("load")[0]
        res = minimize_scalar(lambda A: -float(self.mean_pressure(A)),
                              bounds=(A_min, 2 * np.pi - 1e-12), method="bounded",
                              options={"xatol": 1e-13})
        return float(res.x), float(self.mean_pressure(res.x))

    @staticmethod
    def closing_gamma(modulus_ratio: float = 1.0) -> float:
        """``Γ̃`` above which the wavy contact closes at zero load (the maximum of ``p̃∞`` on
        the stable branch, :meth:`closure`, is 0 there): about 0.0812 for ``β = 1``."""
        return float(brentq(
            lambda G: JohnsonWavy(Gamma=G, modulus_ratio=modulus_ratio).closure()[1],
            1e-4 * modulus_ratio, modulus_ratio, xtol=1e-14))

    def area_at_pressure(self, p):
        """Contact area on the stable (load-controlled) branch at mean pressure ``p``; None below
        pull-off, ``2π`` above closure (full contact)."""
        A_min, p_min, _ = self.pull_off("load")
        A_max, p_max = self.closure()
        if p < p_min:
            return None
        if p >= p_max:
            return 2 * np.pi
        return brentq(lambda A: float(self.mean_pressure(A)) - p, A_min, A_max, xtol=1e-15)

    def area_at_penetration(self, d):
        """Contact area on the stable (penetration-controlled) branch at ``Δ̃ = d``."""
        A_min, _, d_min = self.pull_off("penetration")
        hi = 2 * np.pi - 1e-12
        if d < d_min:
            return None
        if d >= float(self.penetration(hi)):
            return 2 * np.pi
        return brentq(lambda A: float(self.penetration(A)) - d, A_min, hi, xtol=1e-15)
