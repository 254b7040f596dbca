r"""Maugis–Dugdale adhesive wavy contact (finite-range adhesion), in the units of thesis equation
4.17.

A rigid sinusoid ``r̃ = cos x̃`` (``Λ``-scaled, ``x̃ = q0 x`` on ``[-π, π)``) pressed on an elastic
half-plane of modulus ``E = β E0``. Between the surfaces acts a Dugdale law: a uniform tensile
traction σ0 wherever the gap is in ``(0, h0)``, nothing beyond, so that ``σ0·h0 = Δγ``. The
interface is in contact on ``|x̃| < a`` (``Ã = 2a``), cohesive on ``a < |x̃| < c`` (the *outer*
length ``C̃ = 2c``, ``Ã ≤ C̃ ≤ 2π``), free beyond.

Scaling. Stresses ``σ̃ = 2σ/(E* q0 Λ)`` (``E* = E0/(1-ν²)``, tensile positive, ``p̃ = -σ̃``),
displacements and gaps ``ũ = u/Λ``, ``γ̃ = q0Δγ/(πE*)``, ``h̃0 = q0 h0``. From ``σ0 = Δγ/h0``:
``σ0/E* = (πE*γ̃/q0)/(E* h̃0/q0) = πγ̃/h̃0``, hence the cohesive stress

.. math::
    \tilde\sigma_0 = \frac{2\sigma_0}{E^* q_0\Lambda} = \frac{2\pi\tilde\gamma}{\tilde h_0\tilde\Lambda}
    = \frac{2\pi\tilde\Gamma}{\eta},\qquad \tilde\Gamma = \tilde\gamma/\tilde\Lambda^2,\quad
    \eta = h_0/\Lambda = \tilde h_0/\tilde\Lambda ,

and ``σ̃0·η = 2πΓ̃``, the right-hand side of the thesis's closure eq. 4.20. The solution depends on
``(Γ̃/β, η)`` only; stresses scale with β as in :class:`~viscocontact.reference.JohnsonWavy`.

Solution (derived here; ``α = sin(a/2)``, ``σ = σ̃0/β``). With ``S = sin(x̃/2)`` the periodic kernel
``cot((x̃-t̃)/2)`` of an even load becomes the Cauchy kernel, and ``f = σ̃/(β cos(x̃/2))`` solves the
plane problem ``(1/π)⨍ f(T)/(S-T) dT = -2S`` on ``|S| < α``, with ``f = σ/√(1-T²)`` on the zone
``α < |T| < sin(c/2)``. The solution bounded at ``S = ±α`` (no stress singularity at the contact
edge: the Maugis–Dugdale condition) gives, with the angle
``θ = arccos(cos(c/2)/cos(a/2)) ∈ [0, π/2]``,

.. math::
    \tilde p_\infty = \beta\sin^2\frac{a}{2} - \frac{2\tilde\sigma_0}{\pi}\,\theta .

The gap ``g̃`` is written with ``cos(x̃/2) = cos(a/2) cos φ`` (``φ`` runs from 0 at ``x̃ = a`` to π/2
at ``x̃ = π``, and equals θ at ``x̃ = c``):

.. math::
    \frac{d\tilde g}{d\phi} = \frac{4\cos^3\frac{a}{2}\sin^2\phi\cos\phi}{\sin(\tilde x/2)}
    + \frac{2\sigma}{\pi}\cos\frac{a}{2}\,\frac{\sin\phi}{\sin(\tilde x/2)}
      \log\frac{\sin(\theta+\phi)}{|\sin(\theta-\phi)|} > 0 ,

and the zone closes where ``g̃(c) = η``. The penetration is ``Δ̃ = 1 - (1/2π)∫g̃ dx̃`` (the mean
of ``ũ`` vanishes). The contact stress is
``σ̃ = -β cos(x̃/2)√(α² - S²)·[2 - (2σ/(π cos²(a/2))) arctan(√(1+k²) tan θ/k)/(k√(1+k²))]``,
``k² = (α² - S²)/cos²(a/2)``; it tends to σ̃0 at the contact edge (continuous stress).

Closed form: ``p̃∞(Ã, C̃)``, the contact stress, Westergaard's trough gap. Quadrature (tanh-sinh,
205 nodes, absolute error ~1e-12): the gap and ``Δ̃``, whose cohesive parts are single integrals
of elementary functions with an integrable log singularity at ``φ = θ``. An equilibrium is a root
of ``g̃(c) = η`` in θ (Brent).

Limits. ``Γ̃ → 0``: Westergaard (:mod:`~viscocontact.reference.westergaard`), error ``O(Γ̃)``, the
zone becoming where Westergaard's gap is below η. ``η → 0`` at fixed Γ̃: Johnson's JKR-type wavy
contact (:class:`~viscocontact.reference.JohnsonWavy`), errors ``O(η²)`` in ``p̃∞`` and ``Δ̃`` at
fixed Ã; the zone width tends to Dugdale's ``d = πK²/(8σ0²) = βη²/(4Γ̃)`` (Irwin's
``G = K²/(2E)`` on a rigid-elastic interface), and the error is an edge shift: Johnson's state at
``Ã + 4d/3`` is reached to ``O(η⁴)`` (the Dugdale field ahead, ``(2σ0/π) arctan√(d/x)``, is a
K-field centred ``2d/3`` inside the zone), so that the pull-off converges as ``O(η⁴)``.
Saturated zone ``c = π`` (an equilibrium whenever Westergaard's gap at the trough ``x̃ = π`` is
``≤ η``): a uniform tension deforms nothing, so ``p̃∞ = β sin²(a/2) - σ̃0`` and ``Δ̃`` and the
contact stress are Westergaard's, the latter plus σ̃0. ``Γ̃ → 0`` at fixed η < 2 (rigid,
Bradley-like): the pull-off tends to ``-(σ̃0/π) arccos(1 - η)`` at ``Ã → 0``, error ``O(Γ̃)``.

Multiple equilibria. ``g̃(c)`` rises with ``c`` and falls again near ``c = π``, where the two zones
of a period merge and the cohesive deformation vanishes. When Westergaard's trough gap is ``≤ η``
below the maximum of ``g̃(c)``, an area has up to three equilibria (smallest zone, a larger zone,
saturated): :meth:`MaugisDugdaleWavy.states` lists them; :meth:`~MaugisDugdaleWavy.state` returns
the smallest zone, the branch continuous with Johnson's JKR-type branch. Pull-off
(:meth:`~MaugisDugdaleWavy.pull_off`) is the minimum of ``p̃∞`` on that partial-contact branch
below its closure maximum, or, unloading from full contact, the end of the saturated branch.
Separated states (no contact, ``Ã = 0``) are not modelled.

Transition parameters. Johnson's ``α_J = 2√Γ̃`` (``p̃∞ = sin²(a/2) - α_J √tan(a/2)`` in the JKR
limit). The Maugis-type ``λ = 2σ0 (R/(πE²Δγ))^{1/3}`` with the crest radius ``R = 1/(q0²Λ)`` and
the solid's modulus ``E = βE*``: ``λ = 2π^{1/3}(Γ̃/β)^{2/3}/η`` (JKR-like for λ → ∞, rigid/DMT-like
for λ → 0). The Tabor parameter ``μ_T = (RΔγ²/(E²Z0³))^{1/3}`` of
:func:`viscocontact.groups.tabor_parameter`, with Maugis's matching of σ0 to the Lennard-Jones
maximum stress, ``σ0 = 16Δγ/(9√3 Z0)`` (``h0 ≈ 0.974 Z0``): ``μ_T = (πΓ̃/β)^{2/3}/(Z0/Λ)``,
``λ ≈ 1.401 μ_T``.

References
----------
Maugis, D. (1992). Adhesion of spheres: the JKR-DMT transition using a Dugdale model. J. Colloid
Interface Sci. 150, 243-269. doi:10.1016/0021-9797(92)90285-T
Johnson, K. L. (1995). The adhesion of two elastic bodies with slightly wavy surfaces. Int. J.
Solids Struct. 32, 423-430. doi:10.1016/0020-7683(94)00111-9 (the JKR-type limit).
Hui, C. Y., Lin, Y. Y., Baney, J. M., Kramer, E. J. (2001). The mechanics of contact and adhesion
of periodically rough surfaces. J. Polym. Sci. B 39, 1195-1214 (the Maugis–Dugdale wavy contact;
the formulas above were derived independently and not compared with that paper's text).
"""
from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import optimize, special

from .._validation import non_negative, positive
from ..errors import ValidationError

_HALF_PI = 0.5 * math.pi
_LJ_MATCH = 16.0 / (9.0 * math.sqrt(3.0))   # Z0 = _LJ_MATCH·h0 (Maugis 1992)


def _tanh_sinh(step: float = 1.0 / 32.0, reach: float = 3.2):
    """Nodes on (0, 1) as ``(x, 1 - x, w)``, both distances to the ends exact to round-off."""
    t = np.arange(-round(reach / step), round(reach / step) + 1) * step
    s = _HALF_PI * np.sinh(t)
    w = 0.5 * step * _HALF_PI * np.cosh(t) / np.cosh(s) ** 2
    out = (special.expit(2 * s), special.expit(-2 * s), w)
    for arr in out:
        arr.flags.writeable = False
    return out


_X, _XC, _W = _tanh_sinh()


@attrs.frozen(kw_only=True)
class MDState:
    """An equilibrium of the Maugis–Dugdale wavy contact.

    Parameters
    ----------
    area : float
        Contact length per period ``Ã = 2a``.
    outer : float
        Length of contact plus both cohesive zones ``C̃ = 2c`` (``Ã ≤ C̃ ≤ 2π``).
    mean_pressure : float
        ``p̃∞`` (compressive positive).
    penetration : float
        ``Δ̃`` from the mean plane of the deformed solid.
    saturated : bool
        ``C̃ = 2π``: the cohesive zones fill the whole gap region.
    zone_angle : float
        ``θ = arccos(cos(c/2)/cos(a/2))`` in ``[0, π/2]``, exact; ``C̃ - Ã`` loses digits when
        the zones are narrow (θ ∝ √(c - a)), so pass ``zone_angle=`` rather than ``outer`` to
        the field methods of :class:`MaugisDugdaleWavy` for such states.
    """

    area: float
    outer: float
    mean_pressure: float
    penetration: float
    saturated: bool
    zone_angle: float

    @property
    def zone_width(self) -> float:
        """Width ``c - a`` of each of the two cohesive zones of a period."""
        return 0.5 * (self.outer - self.area)


def _theta_of(a: float, c: float) -> float:
    """``θ = arccos(cos(c/2)/cos(a/2))`` without the cancellation of arccos near 1."""
    one_minus = 2 * math.sin((c + a) / 4) * math.sin((c - a) / 4) / math.cos(a / 2)
    return min(2 * math.asin(math.sqrt(min(max(0.5 * one_minus, 0.0), 1.0))), _HALF_PI)


def _area_and_angle(area, outer=None, zone_angle=None, required=True):
    """``(a, θ)`` from ``Ã`` and either ``C̃`` or θ, checked (θ None when neither is given and
    not ``required``).

    Raises
    ------
    ValidationError
        ``area`` outside ``(0, 2π)``, ``outer`` outside ``[area, 2π]`` or given with
        ``zone_angle``, ``zone_angle`` outside ``[0, π/2]``, or neither given when ``required``.
    """
    a = 0.5 * float(area)
    if not 0.0 < a < math.pi:
        raise ValidationError("area", area, "a number in (0, 2π)")
    if zone_angle is not None:
        if outer is not None:
            raise ValidationError("outer", outer, "None when zone_angle is given")
        th = float(zone_angle)
        if not 0.0 <= th <= _HALF_PI:
            raise ValidationError("zone_angle", zone_angle, "a number in [0, π/2]")
        return a, th
    if outer is None:
        if required:
            raise ValidationError("outer", outer, "a number in [area, 2π] (or zone_angle)")
        return a, None
    c = 0.5 * float(outer)
    if not a <= c <= math.pi:
        raise ValidationError("outer", outer, f"a number in [area, 2π] = [{area}, 2π]")
    return a, _theta_of(a, c)


@attrs.frozen(kw_only=True)
class MaugisDugdaleWavy:
    """Maugis–Dugdale adhesive contact of a rigid sinusoid on an elastic half-plane.

    Parameters
    ----------
    Gamma : float
        ``Γ̃ = γ̃/Λ̃²`` (>= 0), as in :class:`~viscocontact.reference.JohnsonWavy`.
    h0 : float
        Range of the Dugdale law relative to the amplitude, ``η = h0/Λ = h̃0/Λ̃`` (> 0).
    modulus_ratio : float
        ``β = E/E0`` of the elastic solid relative to the reference modulus (1: relaxed).

    Examples
    --------
    >>> from viscocontact.reference import JohnsonWavy, MaugisDugdaleWavy
    >>> md = MaugisDugdaleWavy(Gamma=0.05, h0=1e-3)
    >>> round(md.cohesive_stress, 4)
    314.1593
    >>> s = md.state(2.0)
    >>> round(s.mean_pressure, 4), round(float(JohnsonWavy(Gamma=0.05).mean_pressure(2.0)), 4)
    (-0.1007, -0.1007)
    """

    Gamma: float = attrs.field(validator=non_negative)
    h0: float = attrs.field(validator=positive)
    modulus_ratio: float = attrs.field(default=1.0, validator=positive)

    @classmethod
    def from_groups(cls, *, gamma: float, h0: float, amplitude: float,
                    modulus_ratio: float = 1.0) -> MaugisDugdaleWavy:
        """From thesis groups: ``γ̃``, ``h̃0 = q0 h0`` and ``Λ̃ = q0 Λ`` (all dimensionless)."""
        return cls(Gamma=gamma / amplitude**2, h0=h0 / amplitude, modulus_ratio=modulus_ratio)

    @classmethod
    def from_transition(cls, *, Gamma: float, transition: float,
                        modulus_ratio: float = 1.0) -> MaugisDugdaleWavy:
        """The range η that gives the transition parameter ``λ`` at this ``Γ̃`` and β."""
        if not (math.isfinite(transition) and transition > 0):
            raise ValidationError("transition", transition, "a finite real number > 0")
        h0 = 2 * math.pi ** (1 / 3) * (Gamma / modulus_ratio) ** (2 / 3) / transition
        return cls(Gamma=Gamma, h0=h0, modulus_ratio=modulus_ratio)

    # ----------------------------------------------------------------- groups
    @property
    def cohesive_stress(self) -> float:
        """``σ̃0 = 2σ0/(E* q0 Λ) = 2πΓ̃/η``."""
        return 2 * math.pi * self.Gamma / self.h0

    @property
    def johnson_parameter(self) -> float:
        """Johnson's (1995) ``α_J = 2√Γ̃``."""
        return 2 * math.sqrt(self.Gamma)

    @property
    def transition_parameter(self) -> float:
        """``λ = 2σ0 (R/(πE²Δγ))^{1/3} = 2π^{1/3}(Γ̃/β)^{2/3}/η``, crest radius ``R = 1/(q0²Λ)``."""
        return 2 * math.pi ** (1 / 3) * (self.Gamma / self.modulus_ratio) ** (2 / 3) / self.h0

    @property
    def tabor(self) -> float:
        """``μ_T = (RΔγ²/(E²Z0³))^{1/3} = (πΓ̃/β)^{2/3}/(Z0/Λ)`` with ``Z0 = 16h0/(9√3)``."""
        return (math.pi * self.Gamma / self.modulus_ratio) ** (2 / 3) / (_LJ_MATCH * self.h0)

    # ------------------------------------------------------ state at (a, c)
    @property
    def _sigma(self) -> float:
        return self.cohesive_stress / self.modulus_ratio

    def _slope(self, a, th, phi, to_theta):
        """``dg̃/dφ``; ``to_theta = θ - φ`` passed separately to keep it exact near φ = θ."""
        k = math.cos(a / 2)
        S = np.sqrt(math.sin(a / 2) ** 2 + (k * np.sin(phi)) ** 2)     # sin(x̃/2)
        out = 4 * k**3 * np.sin(phi) ** 2 * np.cos(phi) / S
        if self._sigma > 0:
            log = np.log(np.sin(th + phi) / np.abs(np.sin(to_theta)))
            out = out + (2 * self._sigma / math.pi) * k * np.sin(phi) * log / S
        return out

    def _gap_at(self, a, th, phi_end):
        """``g̃`` at ``φ = phi_end``: the integral of the slope with the log point at an end."""
        def piece(lo, hi):      # ∫_lo^hi, one of lo, hi being θ or 0
            if hi <= lo:
                return 0.0
            phi = lo + (hi - lo) * _X
            to_theta = (hi - lo) * _XC if hi == th else th - phi
            if lo == th:
                to_theta = -(hi - lo) * _X
            return (hi - lo) * float(np.sum(_W * self._slope(a, th, phi, to_theta)))

        if phi_end <= 0.5 * th:
            return piece(0.0, phi_end)
        at_c = piece(0.0, th)
        return at_c - piece(phi_end, th) if phi_end <= th else at_c + piece(th, phi_end)

    def mean_pressure(self, area: float, outer: float | None = None, *,
                      zone_angle: float | None = None) -> float:
        """``p̃∞ = β sin²(Ã/4) - (2σ̃0/π)θ`` for any contact ``Ã`` and outer length ``C̃`` (or
        zone angle θ), in equilibrium or not."""
        a, th = _area_and_angle(area, outer, zone_angle)
        return self._pressure(a, th)

    def zone_gap(self, area: float, outer: float | None = None, *,
                 zone_angle: float | None = None) -> float:
        """The gap ``g̃(c)`` at the end of the zone; equilibrium when it equals η (or, saturated,
        when ``C̃ = 2π`` and it is ``≤ η``)."""
        a, th = _area_and_angle(area, outer, zone_angle)
        return self._gap_at(a, th, th)

    def penetration(self, area: float, outer: float | None = None, *,
                    zone_angle: float | None = None) -> float:
        """``Δ̃ = 1 - (1/π)∫_a^π g̃ dx̃``."""
        a, th = _area_and_angle(area, outer, zone_angle)
        return self._penetration(a, th)

    def _penetration(self, a, th):
        k = math.cos(a / 2)
        total = 0.0
        for lo, hi in ((0.0, th), (th, _HALF_PI)):
            if hi > lo:
                phi = lo + (hi - lo) * _X
                to_theta = (hi - lo) * _XC if lo == 0.0 else -(hi - lo) * _X
                lever = 2 * np.arcsin(k * np.cos(phi))          # π - x̃
                total += (hi - lo) * float(np.sum(_W * lever * self._slope(a, th, phi, to_theta)))
        return 1.0 - total / math.pi

    def stress(self, x, area: float, outer: float | None = None, *,
               zone_angle: float | None = None):
        """``σ̃(x̃)`` (tensile positive) on the period, for contact ``Ã`` and outer length ``C̃``."""
        a, th = _area_and_angle(area, outer, zone_angle)
        x = np.abs(np.asarray(x, dtype=float))
        al2, k2a = math.sin(a / 2) ** 2, math.cos(a / 2) ** 2
        zone = np.cos(x / 2) >= math.cos(a / 2) * math.cos(th)         # φ(x̃) <= θ
        out = np.where((x >= a) & zone, self.cohesive_stress, 0.0)
        inside = x < a
        rest = al2 - np.sin(x[inside] / 2) ** 2
        k = np.sqrt(rest / k2a)
        r = np.sqrt(1 + k**2)
        with np.errstate(divide="ignore", invalid="ignore"):
            z = np.where(k > 0, 2 * self._sigma / (math.pi * k2a)
                         * np.arctan(r * math.tan(th) / k) / (k * r), 0.0)
        out[inside] = -self.modulus_ratio * np.cos(x[inside] / 2) * np.sqrt(rest) * (2 - z)
        return out

    def gap(self, x, area: float, outer: float | None = None, *,
            zone_angle: float | None = None):
        """Gap ``g̃(x̃)`` (``Λ`` units), zero in contact."""
        a, th = _area_and_angle(area, outer, zone_angle)
        x = np.abs(np.asarray(x, dtype=float))
        out = np.zeros_like(x)
        for i, xi in np.ndenumerate(x):
            if xi > a:
                cos_phi = min(math.cos(xi / 2) / math.cos(a / 2), 1.0)
                out[i] = self._gap_at(a, th, math.acos(cos_phi))
        return out

    # ------------------------------------------------------------ equilibria
    def _zone_gaps(self, a, thetas):
        """``g̃(c)`` for an array of zone angles θ (vectorised :meth:`zone_gap`)."""
        th = np.asarray(thetas, dtype=float)[:, None]
        slope = self._slope(a, th, th * _X, th * _XC)
        return th[:, 0] * np.sum(_W * slope, axis=1)

    def _thetas(self, a, smallest_only=False):
        """Zone angles θ of the equilibria at half-width a, smallest first (θ = π/2: saturated).

        ``g̃(c)`` is Westergaard's rising gap for σ = 0; for σ > 0 it rises to a maximum and falls
        to Westergaard's trough gap at θ = π/2 (the cohesive part vanishes there)."""
        eta = self.h0
        grid = np.linspace(0.0, _HALF_PI, 33)
        g = np.r_[0.0, self._zone_gaps(a, grid[1:])]
        f = lambda t: self._gap_at(a, t, t) - eta
        root = lambda lo, hi: optimize.brentq(f, lo, hi, xtol=1e-15, rtol=1e-15)
        above = np.flatnonzero(g > eta)
        if not above.size and self._sigma > 0:        # the maximum may fall between nodes
            i = int(np.argmax(g))
            lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
            top = optimize.minimize_scalar(lambda t: -self._gap_at(a, t, t), bounds=(lo, hi),
                                           method="bounded", options={"xatol": 1e-14})
            if -top.fun <= eta:
                return [_HALF_PI]
            return [root(0.0, top.x)] if smallest_only else [
                root(0.0, top.x), root(top.x, _HALF_PI), _HALF_PI]
        if not above.size:
            return [_HALF_PI]
        out = [root(grid[above[0] - 1], grid[above[0]])]
        if not smallest_only and g[-1] <= eta:
            if g[-1] < eta:
                out.append(root(grid[above[-1]], grid[above[-1] + 1]))
            out.append(_HALF_PI)
        return out

    def _state(self, a, th) -> MDState:
        c = 2 * math.acos(math.cos(a / 2) * math.cos(th))
        return MDState(area=2 * a, outer=2 * c, mean_pressure=self._pressure(a, th),
                       penetration=self._penetration(a, th), saturated=th == _HALF_PI,
                       zone_angle=th)

    def _pressure(self, a, th):
        return self.modulus_ratio * math.sin(a / 2) ** 2 - 2 * self.cohesive_stress * th / math.pi

    def states(self, area: float) -> tuple[MDState, ...]:
        """Every equilibrium with contact length ``Ã``, by increasing zone (1 to 3 of them)."""
        a, _ = _area_and_angle(area, required=False)
        return tuple(self._state(a, th) for th in self._thetas(a))

    def state(self, area: float) -> MDState:
        """The equilibrium of smallest zone at ``Ã`` (continuous with Johnson's JKR branch)."""
        a, _ = _area_and_angle(area, required=False)
        return self._state(a, self._thetas(a, smallest_only=True)[0])

    def _partial_pressure(self, area):
        """``p̃∞`` on the partial-contact branch (smallest unsaturated zone); above any ``p̃∞``
        (``β + 1``) where that branch does not exist."""
        a = 0.5 * area
        th = self._thetas(a, smallest_only=True)[0]
        if th == _HALF_PI and self._sigma > 0:
            return self.modulus_ratio + 1.0
        return self._pressure(a, th)

    def _partial_extrema(self):
        """``(Ã at pull-off, Ã at the closure maximum)`` of the partial branch, or None."""
        areas = 2 * math.pi * (0.5 - 0.5 * np.cos(np.linspace(0, math.pi, 49)[1:-1]))
        p = np.array([self._partial_pressure(A) for A in areas])
        on = p < self.modulus_ratio + 1.0
        if not on.any():
            return None
        i_top = int(np.argmax(np.where(on, p, -math.inf)))
        i = int(np.argmin(np.where(on, p, math.inf)[:i_top + 1]))
        lo, hi = (areas[i - 1] if i else 1e-6), areas[min(i + 1, areas.size - 1)]
        res = optimize.minimize_scalar(self._partial_pressure, bounds=(lo, hi), method="bounded",
                                       options={"xatol": 1e-10})
        a_off = float(res.x) if res.fun < p[i] else float(areas[i])
        lo, hi = areas[max(i_top - 1, 0)], areas[min(i_top + 1, areas.size - 1)]
        top = lambda A: -min(self._partial_pressure(A), -p[i])
        res = optimize.minimize_scalar(top, bounds=(lo, hi), method="bounded",
                                       options={"xatol": 1e-10})
        a_top = float(res.x) if -res.fun > p[i_top] else float(areas[i_top])
        return a_off, a_top

    def pull_off(self, branch: str = "partial") -> MDState:
        """Pull-off under load control: the most tensile ``p̃∞`` of a stable branch.

        ``"partial"``: the minimum of the partial-contact branch (smallest unsaturated zone)
        below its closure maximum: Johnson's pull-off in the JKR limit, the rigid Bradley-like
        value ``-(σ̃0/π) arccos(1 - η)`` in the other; when that branch does not exist, the
        saturated minimum. ``"full"``: unloading from full contact, the gap opens at the trough
        onto the saturated branch ``p̃∞ = β sin²(a/2) - σ̃0``, stable down to the area where
        Westergaard's trough gap ``2[cos(a/2) - sin²(a/2) log cot(a/4)]`` equals η (``Ã → 0``
        and ``p̃∞ = -σ̃0`` for η ≥ 2); there the contact jumps, onto the partial branch if that
        holds the load, else off.
        """
        if branch not in ("partial", "full"):
            raise ValidationError("branch", branch, "one of ['partial', 'full']")
        ext = self._partial_extrema() if branch == "partial" else None
        if ext is not None:
            return self.state(ext[0])
        if self.h0 >= 2.0:
            return MDState(area=0.0, outer=2 * math.pi, mean_pressure=-self.cohesive_stress,
                           penetration=0.0, saturated=True, zone_angle=_HALF_PI)
        trough = lambda a: (2 * (math.cos(a / 2) - math.sin(a / 2) ** 2
                                 * math.log(1 / math.tan(a / 4))) - self.h0)
        return self._state(optimize.brentq(trough, 1e-300, math.pi, xtol=1e-15, rtol=1e-15),
                           _HALF_PI)

    def area_at_pressure(self, p: float):
        """``Ã`` on the stable (rising) part of the partial-contact branch at mean pressure ``p``,
        between pull-off and the closure maximum; None outside that range."""
        ext = self._partial_extrema()
        if ext is None:
            return None
        lo, hi = ext
        if not self._partial_pressure(lo) <= p <= self._partial_pressure(hi):
            return None
        return optimize.brentq(lambda A: self._partial_pressure(A) - p, lo, hi, xtol=1e-13)

    def state_at_pressure(self, p: float):
        """The stable partial-contact :class:`MDState` at mean pressure ``p`` (None outside the
        range of :meth:`area_at_pressure`)."""
        area = self.area_at_pressure(p)
        return None if area is None else self.state(area)
