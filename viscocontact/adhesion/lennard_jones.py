r"""A Lennard-Jones 9-3 traction-separation law, applied cell by cell on the grids.

Two half-spaces of a Lennard-Jones solid at separation ``s`` attract with the traction (tensile
positive)

.. math:: \sigma(s) = \frac{8\Delta\gamma}{3\varepsilon}
          \left[\left(\frac{\varepsilon}{s}\right)^3 - \left(\frac{\varepsilon}{s}\right)^9\right],

zero at the equilibrium separation ``s = ε``, largest, ``σ_max = 16Δγ/(9√3 ε)``, at
``s = 3^{1/6}ε``, and its work of separation is ``∫_ε^∞ σ ds = Δγ``. Here the repulsive branch
``s < ε`` is a hard wall: the gap ``g = s - ε >= 0`` of the grids' contact problem is the
separation beyond equilibrium, the interface is in contact where ``g = 0`` (any compression), and
every other cell carries the tension ``σ(ε + g)`` (the model of Greenwood 1997 and Feng 2000
with the repulsion made rigid, which changes the pull-off by nothing in the DMT and JKR limits).

Units (thesis eq. 4.17): ``γ̃ = q0Δγ/(πE*)`` as for :class:`~viscocontact.adhesion.MaugisDugdale`,
``ε̃ = q0ε``; the traction ``σ̃Λ̃ = 2σ/(E*q0) = (16πγ̃/(3ε̃))[(ε̃/s̃)³ - (ε̃/s̃)⁹]``, whose integral
over ``q0·g`` is ``2πγ̃``. The transition from DMT (rigid, ``F = 2πRΔγ`` on a sphere) to JKR
(``1.5πRΔγ``) is governed by Tabor's parameter ``μ_T = (RΔγ²/(E*²ε³))^{1/3}``
(:meth:`LennardJones.tabor`).

The law has no edge condition for the boundary-element method (it acts on every gap, not at the
edges): :meth:`residuals` raises :class:`~viscocontact.adhesion.AdhesionLimitation`; the uniform
grids (``spectral``, ``areal-spectral``) apply it through :meth:`traction`.

References
----------
Greenwood, J. A. (1997). Adhesion of elastic spheres. Proc. R. Soc. A 453, 1277-1297.
doi:10.1098/rspa.1997.0070

Feng, J. Q. (2000). Contact behavior of spherical elastic particles: a computational study of
particle adhesion and deformations. Colloids Surf. A 172, 175-198.
doi:10.1016/S0927-7757(00)00580-X
"""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import in_range
from .base import AdhesionLimitation, AdhesionModel, EdgeTerms

#: ``σ_max ε/Δγ = 16/(9√3)``: the peak of the 9-3 law.
PEAK = 16.0 / (9.0 * np.sqrt(3.0))


@attrs.frozen(kw_only=True)
class LennardJones(AdhesionModel):
    """Lennard-Jones 9-3 adhesion with a hard-wall repulsion (module docstring).

    Parameters
    ----------
    gamma : float
        γ̃ = (1-ν²) q0 Δγ/(π E0), finite and >= 0 (eq. 4.17); 0 is no adhesion.
    range : float
        ε̃ = q0·ε, the equilibrium separation (the law's length), in ``(0, 10]``.

    Examples
    --------
    >>> lj = LennardJones(gamma=1e-3, range=0.01)
    >>> float(lj.traction(0.0)), round(float(lj.strength(1.0)), 4)
    (0.0, 0.6449)
    """

    gamma: float = attrs.field(validator=in_range(0.0))
    range: float = attrs.field(validator=in_range(0.0, 10.0, lo_open=True))

    def traction(self, gap) -> np.ndarray:
        """``σ̃Λ̃ = (16πγ̃/(3ε̃))[(ε̃/s̃)³ - (ε̃/s̃)⁹]`` at ``s̃ = ε̃ + gap`` (``gap`` the
        q0-scaled separation beyond equilibrium, clipped at 0)."""
        x = self.range / (self.range + np.maximum(np.asarray(gap, dtype=float), 0.0))
        x3 = x**3
        return 16.0 * np.pi * self.gamma / (3.0 * self.range) * (x3 - x3**3)

    def strength(self, amplitude: float) -> float:
        """The peak tension ``σ̃_max = 2πγ̃·16/(9√3 ε̃ Λ̃)`` (eq. 4.17 units)."""
        return 2.0 * np.pi * self.gamma * PEAK / (self.range * amplitude)

    def closed_strength(self, amplitude: float) -> float:
        """The peak tension: a closed interface opens where its tension exceeds it."""
        return self.strength(amplitude) if self.gamma > 0 else 0.0

    @property
    def quasi_static_zone(self) -> float:
        """``h̃²/(4γ̃)`` with ``h = Δγ/σ_max = 9√3ε/16``: the Dugdale zone of the same peak and
        work, the length a grid must resolve (``inf`` without adhesion)."""
        h = self.range / PEAK
        return h * h / (4.0 * self.gamma) if self.gamma > 0 else np.inf

    def tabor(self, radius: float) -> float:
        """Tabor's ``μ_T = (RΔγ²/(E*²ε³))^{1/3} = (R̃π²γ̃²/ε̃³)^{1/3}`` of a sphere of radius
        ``R̃ = q0R``; Maugis's ``λ ≈ 1.157 μ_T`` (his ``σ0`` the peak ``σ_max``)."""
        return (radius * np.pi**2 * self.gamma**2 / self.range**3) ** (1.0 / 3.0)

    def residuals(self, ctx) -> np.ndarray:
        if self.gamma == 0:
            return ctx.stress_intensity()
        raise AdhesionLimitation("the Lennard-Jones law acts on every gap, not at contact edges: "
                                 "the boundary-element method has no edge condition for it; "
                                 "use the spectral or areal-spectral method")

    def edge_terms(self, ctx) -> EdgeTerms:
        self.residuals(ctx)
        k = ctx.stress_intensity()
        n = len(k)
        return EdgeTerms(stored=np.zeros(n), nonconservative=np.zeros(n), target=0.0,
                         effective_work=np.full(n, np.nan), stress_intensity=k,
                         edge_perturbation=0.0)
