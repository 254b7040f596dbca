"""The :class:`Rheology` interface: a linear viscoelastic solid.

Conventions (thesis eqs. 2.17, 2.20, 2.24, 4.4-4.6)
---------------------------------------------------
* Harmonic fields go as ``exp(iωt)``; the complex modulus is ``E(ω) = E' + iE''`` with ``E'' >= 0``
  and the complex compliance ``C(ω) = 1/E(ω)`` (eq. 2.23), so ``C'' <= 0``.
* ``relaxed_modulus`` E0 = E(0), ``instantaneous_modulus`` E∞ = E(∞).
* ``reference_time`` τ is the time that enters ``ζ = q0·V·τ``. For the standard linear solid it is
  the *creep (retardation)* time of eq. 4.4, as in the thesis (its relaxation time is τ/β).
* Every rheology exposes its creep function as ``J(t) = J(0+) + Σ_i c_i (1 - exp(-t/θ_i))``
  through :meth:`creep_spectrum` (exact for Prony series); the steady-sliding Green kernel (eq. 4.2)
  is built from it for any rheology.

Contract for implementers: implement :meth:`complex_modulus`, :meth:`creep_spectrum` and the three
properties; everything else has a default.
"""
from __future__ import annotations

import abc

import attrs
import numpy as np


@attrs.frozen(kw_only=True)
class CreepSpectrum:
    """``J(t) = instantaneous + Σ_i weights[i]·(1 - exp(-t/times[i]))`` for t > 0.

    Attributes
    ----------
    instantaneous : float
        ``J(0+) = 1/E∞`` (1/Pa, or 1/E0 units in dimensionless scenes).
    weights : ndarray
        Creep weights ``c_i >= 0``; ``J(∞) = instantaneous + Σ c_i = 1/E0``.
    times : ndarray
        Retardation times ``θ_i > 0`` (s, or τ units).
    """

    instantaneous: float
    weights: np.ndarray = attrs.field(converter=lambda a: np.atleast_1d(np.asarray(a, float)))
    times: np.ndarray = attrs.field(converter=lambda a: np.atleast_1d(np.asarray(a, float)))


class Rheology(abc.ABC):
    """A linear viscoelastic solid; see the module docstring for conventions."""

    @property
    @abc.abstractmethod
    def relaxed_modulus(self) -> float:
        """E0 = E(ω → 0) (Pa, or 1 in dimensionless scenes)."""

    @property
    @abc.abstractmethod
    def instantaneous_modulus(self) -> float:
        """E∞ = E(ω → ∞)."""

    @property
    @abc.abstractmethod
    def reference_time(self) -> float:
        """τ in ``ζ = q0·V·τ`` (s, or 1 in dimensionless scenes)."""

    @abc.abstractmethod
    def complex_modulus(self, omega: np.ndarray) -> np.ndarray:
        """``E(ω)`` for angular frequency ω (rad/s, or 1/τ units); ``E'' >= 0`` for ω > 0."""

    @abc.abstractmethod
    def creep_spectrum(self) -> CreepSpectrum:
        """The creep function as a sum of exponentials (see :class:`CreepSpectrum`)."""

    # ---- defaults -------------------------------------------------------------------------
    def complex_compliance(self, omega: np.ndarray) -> np.ndarray:
        """``C(ω) = 1/E(ω)`` (eq. 2.23)."""
        return 1.0 / self.complex_modulus(omega)

    def storage_modulus(self, omega):
        """``E'(ω)``."""
        return self.complex_modulus(omega).real

    def loss_modulus(self, omega):
        """``E''(ω)``."""
        return self.complex_modulus(omega).imag

    def loss_tangent(self, omega):
        """``tan δ = E''/E'`` (eq. 2.25)."""
        e = self.complex_modulus(omega)
        return e.imag / e.real

    def creep_function(self, t):
        """``J(t)``, zero for t < 0 (eq. 4.6)."""
        t = np.asarray(t, dtype=float)
        cs = self.creep_spectrum()
        tt = np.maximum(t, 0.0)[..., None]
        j = cs.instantaneous + np.sum(cs.weights * -np.expm1(-tt / cs.times), axis=-1)
        return np.where(t < 0, 0.0, j)

    def creep_rate(self, t):
        """``dJ/dt`` for t > 0."""
        t = np.asarray(t, dtype=float)
        cs = self.creep_spectrum()
        tt = np.maximum(t, 0.0)[..., None]
        return np.where(t < 0, 0.0, np.sum(cs.weights / cs.times * np.exp(-tt / cs.times), axis=-1))

    @property
    def modulus_ratio(self) -> float:
        """``β = E∞/E0``."""
        return self.instantaneous_modulus / self.relaxed_modulus
