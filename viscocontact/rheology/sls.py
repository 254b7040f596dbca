"""The standard linear solid: one retardation time (thesis equations 4.4-4.5)."""
from __future__ import annotations

import math

import attrs
import numpy as np

from .._validation import _name, positive
from ..errors import ValidationError
from .base import CreepSpectrum, Rheology
from .shift import TIME


def _float(value):
    """Convert to float when possible; otherwise leave it for the validator to reject by name."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return value


def _beta_above_one(inst, attribute, value):
    if not (isinstance(value, float) and math.isfinite(value) and value > 1.0):
        raise ValidationError(_name(inst, attribute), value,
                              "a finite real number > 1 (for beta == 1 use Elastic, "
                              "registered as 'elastic')")


@attrs.frozen(kw_only=True)
class StandardLinearSolid(Rheology):
    """Standard linear solid (Zener model) with the creep function of equation 4.4.

    ``J(t) = H(t)·[1/E0 - (1/E1)·exp(-t/τ)]``, ``1/E1 = 1/E0 - 1/E∞`` (eq. 4.5).

    Parameters
    ----------
    modulus : float
        Relaxed modulus ``E0 = E(ω → 0)`` > 0 (Pa, or 1 in dimensionless scenes).
    beta : float
        ``β = E∞/E0 > 1``. (``β = 1`` is elastic: use :class:`~viscocontact.rheology.Elastic`.)
    tau : float
        Creep (retardation) time τ > 0 of eq. 4.4 (s, or τ units); it is also the
        :attr:`reference_time` of ``ζ = q0·V·τ``, as in the thesis.

    Notes
    -----
    Exact expressions::

        C(ω) = 1/E∞ + (1/E0 - 1/E∞) / (1 + iωτ)
        E(ω) = E0·(1 + iωτ) / (1 + iωτ/β)
             = E0 + (E∞ - E0)·iωτ_r / (1 + iωτ_r),   τ_r = τ/β   (eq. 2.24, one Maxwell arm)

    so the relaxation time ``τ_r = τ/β`` is shorter than the creep time: ``-C''`` peaks at
    ``ω = 1/τ``, ``E''`` at ``ω = β/τ`` and ``tan δ`` in between, at ``ω = √β/τ``, with the
    value ``(β - 1)/(2√β)``.

    Examples
    --------
    >>> from viscocontact.rheology import StandardLinearSolid
    >>> sls = StandardLinearSolid(modulus=1.0, beta=10.0, tau=1.0)
    >>> sls.instantaneous_modulus, sls.relaxation_time
    (10.0, 0.1)
    >>> complex(sls.complex_modulus(1.0))
    (1.0891089108910892+0.8910891089108911j)
    """

    modulus: float = attrs.field(default=1.0, converter=_float, validator=positive)
    beta: float = attrs.field(converter=_float, validator=_beta_above_one)
    tau: float = attrs.field(default=1.0, converter=_float, validator=positive, metadata=TIME)

    @classmethod
    def from_moduli(cls, relaxed_modulus: float, instantaneous_modulus: float,
                    tau: float = 1.0) -> "StandardLinearSolid":
        """Build from ``E0``, ``E∞`` (same units) and the creep time τ."""
        try:
            beta = float(instantaneous_modulus) / float(relaxed_modulus)
        except (TypeError, ValueError, ZeroDivisionError):
            raise ValidationError("StandardLinearSolid.from_moduli",
                                  (relaxed_modulus, instantaneous_modulus),
                                  "moduli 0 < E0 < E∞") from None
        if not float(relaxed_modulus) > 0:
            raise ValidationError("StandardLinearSolid.relaxed_modulus", relaxed_modulus,
                                  "a finite real number > 0")
        return cls(modulus=relaxed_modulus, beta=beta, tau=tau)

    # ---- Rheology interface ----------------------------------------------------------------
    @property
    def relaxed_modulus(self) -> float:
        """E0."""
        return self.modulus

    @property
    def instantaneous_modulus(self) -> float:
        """``E∞ = β·E0``."""
        return self.beta * self.modulus

    @property
    def reference_time(self) -> float:
        """The creep time τ (eq. 4.4)."""
        return self.tau

    @property
    def relaxation_time(self) -> float:
        """``τ_r = τ/β``, the time of the relaxation function."""
        return self.tau / self.beta

    def complex_modulus(self, omega) -> np.ndarray:
        """``E(ω) = E0·(1 + iωτ)/(1 + iωτ/β)``; ω in rad/s (or 1/τ units)."""
        x = 1j * np.asarray(omega, dtype=float) * self.tau
        return self.modulus * (1.0 + x) / (1.0 + x / self.beta)

    def complex_compliance(self, omega) -> np.ndarray:
        """``C(ω) = 1/E∞ + (1/E0 - 1/E∞)/(1 + iωτ)`` (exact, eq. 2.24)."""
        x = 1j * np.asarray(omega, dtype=float) * self.tau
        return (1.0 / self.instantaneous_modulus
                + self._creep_weight / (1.0 + x))

    @property
    def _creep_weight(self) -> float:
        """``1/E1 = 1/E0 - 1/E∞`` (eq. 4.5), without cancellation."""
        return (1.0 - 1.0 / self.beta) / self.modulus

    def creep_spectrum(self) -> CreepSpectrum:
        """One term: instantaneous ``1/E∞``, weight ``1/E0 - 1/E∞``, time τ."""
        return CreepSpectrum(instantaneous=1.0 / self.instantaneous_modulus,
                             weights=[self._creep_weight], times=[self.tau])

    def relaxation_function(self, t) -> np.ndarray:
        """``R(t) = H(t)·[E0 + (E∞ - E0)·exp(-t/τ_r)]`` (eq. 2.17 with one arm)."""
        t = np.asarray(t, dtype=float)
        r = self.modulus * (1.0 + (self.beta - 1.0) * np.exp(-np.maximum(t, 0.0)
                                                              / self.relaxation_time))
        return np.where(t < 0, 0.0, r)

    def to_prony(self):
        """The equivalent one-arm :class:`~viscocontact.rheology.PronySeries` (exact).

        ``E0 = modulus``, ``E1 = (β - 1)·E0``, ``τ1 = τ/β``; ``reference_time`` stays τ.
        """
        from .prony import PronySeries

        return PronySeries(relaxed_modulus=self.modulus,
                           moduli=[(self.beta - 1.0) * self.modulus],
                           times=[self.relaxation_time], reference_time=self.tau)
