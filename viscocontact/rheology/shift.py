"""Time-temperature superposition: shift factors ``a_T`` and shifted rheologies (thesis §2.1).

Convention
----------
``a_T = τ(T)/τ(T_ref)``: every characteristic time of the material at temperature T is the one at
``T_ref`` *multiplied* by ``a_T``, and a master curve measured at ``T_ref`` gives
``E(ω; T) = E(a_T·ω; T_ref)``. With the WLF (eq. 2.27) and Arrhenius (eq. 2.28) laws as printed,
``a_T < 1`` above ``T_ref``: heating shortens the times and moves the loss peak to higher
frequencies, as in the thesis's Fig. 2.8 and in Ferry's definition of ``a_T``.

Eq. 2.26 is printed as ``τ(T) = τ(T_ref)/a_T``; combined with the signs of eqs. 2.27-2.28 it would
make a heated rubber relax *more slowly*, so this module follows the standard convention above
(``τ(T) = a_T·τ(T_ref)``) instead; use ``shift(r, 1/a)`` for a factor defined the other way.

Rheologies mark their time fields with ``metadata=TIME`` (see :data:`TIME`); :func:`shift`
rescales exactly those fields through :func:`attrs.evolve`, so plugin rheologies that follow the
same contract are shifted correctly too.
"""
from __future__ import annotations

import math

import attrs
import numpy as np

from .._validation import positive
from ..errors import ValidationError

#: attrs field metadata marking a field that holds a time (s, or τ units), scaled by :func:`shift`.
TIME = {"dimension": "time"}

#: Molar gas constant R (J/(mol·K)), exact in the 2019 SI.
GAS_CONSTANT = 8.314462618


def _temperatures(value, owner: str) -> np.ndarray:
    t = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(t)) or np.any(t <= 0):
        raise ValidationError(f"{owner}.temperature", value,
                              "finite absolute temperatures > 0 (K)")
    return t


def _finite_factor(ln_a: np.ndarray, field: str, temperature) -> np.ndarray:
    """``exp(ln_a)``, raising instead of overflowing to inf or underflowing to 0."""
    limit = np.log(np.finfo(float).max)
    if np.any(np.abs(ln_a) >= limit):
        raise ValidationError(field, temperature,
                              "temperatures whose shift factor a_T fits a float "
                              f"(|ln a_T| < {limit:.0f}); this one is too far from T_ref")
    return np.exp(ln_a)


@attrs.frozen(kw_only=True)
class WLF:
    """Williams-Landel-Ferry shift factor (eq. 2.27), for temperatures above the glass transition.

    ``log10 a_T = -C1·(T - T_ref) / (C2 + T - T_ref)``

    Parameters
    ----------
    c1 : float
        C1 > 0 (dimensionless; decimal-log convention, e.g. 17.44 for the "universal" constants).
    c2 : float
        C2 > 0 (K; e.g. 51.6).
    reference_temperature : float
        ``T_ref`` > 0 of the master curve (K).

    Notes
    -----
    The logarithm is decimal (``log10``), as is conventional for WLF constants. ``a_T`` diverges at
    the Vogel temperature ``T = T_ref - C2``; :meth:`shift_factor` raises :class:`ValidationError`
    there and below it, where the formula has no physical meaning.

    Examples
    --------
    >>> from viscocontact.rheology import WLF
    >>> wlf = WLF(c1=17.44, c2=51.6, reference_temperature=293.15)
    >>> float(wlf.shift_factor(293.15))
    1.0
    >>> bool(wlf.shift_factor(313.15) < 1.0)   # hotter: shorter times
    True
    """

    c1: float = attrs.field(converter=float, validator=positive)
    c2: float = attrs.field(converter=float, validator=positive)
    reference_temperature: float = attrs.field(converter=float, validator=positive)

    @property
    def vogel_temperature(self) -> float:
        """``T_ref - C2`` (K), where ``a_T`` diverges."""
        return self.reference_temperature - self.c2

    def log10_shift_factor(self, temperature) -> np.ndarray:
        """``log10 a_T`` at ``temperature`` (K); raises at or below :attr:`vogel_temperature`."""
        t = _temperatures(temperature, "WLF.shift_factor")
        dt = t - self.reference_temperature
        if np.any((self.c2 + dt <= 0) | (t <= self.vogel_temperature)):
            raise ValidationError(
                "WLF.shift_factor.temperature", temperature,
                f"T > T_ref - C2 = {self.vogel_temperature:g} K (WLF is singular at "
                f"T - T_ref = -C2 and meaningless below)")
        return -self.c1 * dt / (self.c2 + dt)

    def shift_factor(self, temperature) -> np.ndarray:
        """``a_T = τ(T)/τ(T_ref)`` at ``temperature`` (K), eq. 2.27 with ``log10``."""
        return _finite_factor(np.log(10.0) * self.log10_shift_factor(temperature),
                              "WLF.shift_factor.temperature", temperature)


@attrs.frozen(kw_only=True)
class Arrhenius:
    """Arrhenius shift factor (eq. 2.28), for thermally activated (e.g. sub-Tg) processes.

    ``ln a_T = (E_a/R)·(1/T - 1/T_ref)``

    Parameters
    ----------
    activation_energy : float
        ``E_a`` > 0 (J/mol).
    reference_temperature : float
        ``T_ref`` > 0 (K).

    Notes
    -----
    The logarithm is *natural*: the physics is ``τ ∝ exp(E_a/(R·T))``. Eq. 2.28 is printed with
    "log"; constants fitted with a decimal log must be converted (``E_a,ln = E_a,log10·ln 10``).
    ``R`` is :data:`GAS_CONSTANT`.

    Examples
    --------
    >>> from viscocontact.rheology import Arrhenius
    >>> arr = Arrhenius(activation_energy=100e3, reference_temperature=300.0)
    >>> round(float(arr.shift_factor(310.0)), 4)
    0.2744
    """

    activation_energy: float = attrs.field(converter=float, validator=positive)
    reference_temperature: float = attrs.field(converter=float, validator=positive)

    def shift_factor(self, temperature) -> np.ndarray:
        """``a_T = exp[(E_a/R)(1/T - 1/T_ref)]`` at ``temperature`` (K)."""
        t = _temperatures(temperature, "Arrhenius.shift_factor")
        return _finite_factor(self.activation_energy / GAS_CONSTANT
                              * (1.0 / t - 1.0 / self.reference_temperature),
                              "Arrhenius.shift_factor.temperature", temperature)


def shift(rheology, a_T: float):
    """The same rheology at another temperature: every time field multiplied by ``a_T``.

    Parameters
    ----------
    rheology : attrs-based Rheology
        Its time fields carry ``metadata=TIME`` (all built-in rheologies do, including
        ``reference_time``, so the time unit of ``ζ = q0·V·τ`` follows the material).
    a_T : float
        Shift factor ``τ(T)/τ(T_ref)`` > 0, e.g. ``WLF(...).shift_factor(T)``.

    Returns
    -------
    Rheology
        ``attrs.evolve(rheology, ...)`` with ``τ(T) = a_T·τ(T_ref)`` for every time; moduli are
        unchanged (no vertical shift).

    Notes
    -----
    See the module docstring for why this multiplies by ``a_T`` although eq. 2.26 is printed with a
    division. ``E(ω; T) = E(a_T·ω; T_ref)`` holds exactly.

    Examples
    --------
    >>> from viscocontact.rheology import StandardLinearSolid
    >>> from viscocontact.rheology.shift import shift
    >>> shift(StandardLinearSolid(beta=10.0, tau=2.0), 0.5).tau
    1.0
    """
    try:
        a = float(a_T)
    except (TypeError, ValueError):
        raise ValidationError("shift.a_T", a_T, "a finite real number > 0") from None
    if not (math.isfinite(a) and a > 0):
        raise ValidationError("shift.a_T", a_T, "a finite real number > 0")
    if not attrs.has(type(rheology)):
        raise ValidationError("shift.rheology", rheology,
                              "an attrs class whose time fields carry metadata=TIME")
    changes = {f.name: getattr(rheology, f.name) * a
               for f in attrs.fields(type(rheology))
               if f.metadata.get("dimension") == TIME["dimension"]}
    if not changes:
        raise ValidationError("shift.rheology", type(rheology).__name__,
                              "a rheology with at least one field marked metadata=TIME")
    return attrs.evolve(rheology, **changes)


__all__ = ["GAS_CONSTANT", "TIME", "WLF", "Arrhenius", "shift"]
