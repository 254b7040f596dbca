r"""The Lennard-Jones traction-separation law between two half-spaces (thesis equation 1.20).

.. math::
    \sigma(g) = \frac{8\Delta\gamma}{3\varepsilon}
        \Big[\Big(\frac{\varepsilon}{g}\Big)^3 - \Big(\frac{\varepsilon}{g}\Big)^9\Big],

with ``g`` the gap, ``ε`` the equilibrium distance (``σ(ε) = 0``) and ``Δγ`` the Dupré energy; ``σ``
is positive when tensile (attraction, ``g > ε``), as in the thesis's Chapter 4. Its integral is the
work of separation, ``∫_ε^∞ σ dg = Δγ``, and the potential (work to separate from ``g`` to infinity)
is ``φ(g) = (8Δγ/3)[(ε/g)²/2 - (ε/g)⁸/8]``. The largest tension,
``σ_max = 16Δγ/(9√3 ε) ≈ 1.0264 Δγ/ε``, is reached at ``g = 3^(1/6) ε``.

The thesis uses the law only to motivate the Tabor parameter: its own model is the infinitely
short-range limit ``ε → 0`` (JKR-type, energy balance at the edges).

Units: any consistent set (SI: m, J/m², Pa).

References
----------
Greenwood, J. A. (1997). Adhesion of elastic spheres. Proc. R. Soc. Lond. A 453, 1277-1297.
doi:10.1098/rspa.1997.0070
Muller, V. M., Yushchenko, V. S., Derjaguin, B. V. (1980). On the influence of molecular forces on
the deformation of an elastic sphere and its sticking to a rigid plane. J. Colloid Interface Sci.
77, 91-101.
"""
from __future__ import annotations

import math

import attrs

from .._validation import non_negative, positive
from . import _args

__all__ = ["LennardJones"]


@attrs.frozen(kw_only=True)
class LennardJones:
    """The 3-9 traction law of eq. 1.20.

    Parameters
    ----------
    work_of_adhesion : float
        Δγ >= 0 (J/m²).
    equilibrium_distance : float
        ε > 0 (m).

    Examples
    --------
    >>> lj = LennardJones(work_of_adhesion=1.0, equilibrium_distance=1.0)
    >>> float(lj.traction(1.0)), round(float(lj.potential(1.0)), 15)
    (0.0, 1.0)
    """

    work_of_adhesion: float = attrs.field(validator=non_negative)
    equilibrium_distance: float = attrs.field(validator=positive)

    def traction(self, gap):
        """``σ(g)`` (Pa), tensile positive (eq. 1.20), for ``g > 0``."""
        g = _args.positive("gap", gap)
        e = self.equilibrium_distance
        x = e / g
        return 8.0 * self.work_of_adhesion / (3.0 * e) * (x**3 - x**9)

    def potential(self, gap):
        """``φ(g) = ∫_g^∞ σ dg' = (8Δγ/3)[(ε/g)²/2 - (ε/g)⁸/8]`` (J/m²); ``φ(ε) = Δγ``."""
        g = _args.positive("gap", gap)
        x = self.equilibrium_distance / g
        return 8.0 * self.work_of_adhesion / 3.0 * (x**2 / 2.0 - x**8 / 8.0)

    @property
    def gap_at_max_traction(self) -> float:
        """``g = 3^(1/6) ε``."""
        return 3.0 ** (1.0 / 6.0) * self.equilibrium_distance

    @property
    def max_traction(self) -> float:
        """``σ_max = 16Δγ/(9√3 ε)`` (Pa)."""
        return 16.0 * self.work_of_adhesion / (9.0 * math.sqrt(3.0) * self.equilibrium_distance)

    def tabor_parameter(self, *, radius: float, reduced_modulus: float) -> float:
        """Tabor's ``μ_T`` with ``Z0 = ε`` (eq. 1.48); see :mod:`viscocontact.theories.tabor`."""
        from .tabor import tabor_parameter

        return tabor_parameter(radius=radius, work_of_adhesion=self.work_of_adhesion,
                               reduced_modulus=reduced_modulus,
                               equilibrium_distance=self.equilibrium_distance)

