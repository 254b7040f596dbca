r"""DMT adhesive contact of a sphere (thesis §1.5; Derjaguin, Muller & Toporov 1975).

The adhesive attraction acts only outside the contact, as a long-range force; inside, the pressure
and the geometry stay Hertzian (:mod:`viscocontact.theories.hertz`). With ``R``, ``E*``, ``Δγ`` as
in :mod:`viscocontact.theories.jkr`:

.. math::
    P = \frac{4E^*a^3}{3R} - 2\pi\Delta\gamma R,\qquad \delta = \frac{a^2}{R},\qquad
    P_c = -2\pi\Delta\gamma R\ \text{at}\ a = 0,

the Bradley/Derjaguin rigid-sphere pull-off quoted in §1.5 (the thesis prints the magnitude). DMT is
the limit of small Tabor parameter (``μ_T << 1``, :mod:`viscocontact.theories.tabor`), JKR that of
large ``μ_T``; for the same R and Δγ, ``|P_c^DMT| / |P_c^JKR| = 4/3``.

Units: any consistent set (SI: m, Pa, J/m², N).

References
----------
Derjaguin, B. V., Muller, V. M., Toporov, Yu. P. (1975). Effect of contact deformations on the
adhesion of particles. J. Colloid Interface Sci. 53, 314-326. doi:10.1016/0021-9797(75)90018-1
Bradley, R. S. (1932). The cohesive force between solid surfaces and the surface energy of solids.
Phil. Mag. 13, 853-862.
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from .._validation import non_negative, positive
from . import _args
from .hertz import HertzSphere
from .jkr import PullOff

__all__ = ["DMTSphere"]


@attrs.frozen(kw_only=True)
class DMTSphere:
    """DMT contact of a sphere on a half-space.

    Parameters
    ----------
    radius : float
        Combined radius R > 0 (m).
    reduced_modulus : float
        E* > 0 (Pa).
    work_of_adhesion : float
        Δγ >= 0 (J/m²).

    Examples
    --------
    >>> import math
    >>> d = DMTSphere(radius=2.0, reduced_modulus=1.0, work_of_adhesion=0.1)
    >>> round(d.pull_off().load / (math.pi * 0.1 * 2.0), 12)
    -2.0
    """

    radius: float = attrs.field(validator=positive)
    reduced_modulus: float = attrs.field(validator=positive)
    work_of_adhesion: float = attrs.field(validator=non_negative)

    @property
    def hertz(self) -> HertzSphere:
        """The Hertzian contact that DMT keeps inside the contact."""
        return HertzSphere(radius=self.radius, reduced_modulus=self.reduced_modulus)

    def load(self, contact_radius):
        """``P = 4E*a³/(3R) - 2πΔγR``."""
        return self.hertz.load(contact_radius) - 2.0 * math.pi * self.work_of_adhesion * self.radius

    def penetration(self, contact_radius):
        """``δ = a²/R`` (Hertz, eq. 1.15)."""
        return self.hertz.penetration(contact_radius)

    def contact_radius(self, load):
        """``a = (3R(P + 2πΔγR)/(4E*))^(1/3)`` for ``P >= -2πΔγR``."""
        pc = 2.0 * math.pi * self.work_of_adhesion * self.radius
        p = _args.real("load", load, -pc)
        return np.cbrt(3.0 * self.radius * (p + pc) / (4.0 * self.reduced_modulus))

    def pull_off(self) -> PullOff:
        """``P_c = -2πΔγR`` at ``a = δ = 0``."""
        return PullOff(load=-2.0 * math.pi * self.work_of_adhesion * self.radius,
                       contact_radius=0.0, penetration=0.0)
