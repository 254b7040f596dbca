"""A purely elastic solid: ``E(ω) = E`` at every frequency (Hooke's law, thesis equation 2.4)."""
from __future__ import annotations

import attrs
import numpy as np

from .._validation import positive
from .base import CreepSpectrum, Rheology
from .shift import TIME


def _float(value):
    """Convert to float when possible; otherwise leave it for the validator to reject by name."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return value


@attrs.frozen(kw_only=True)
class Elastic(Rheology):
    """Hookean solid, ``σ = E ε`` (equation 2.4); the limit ``β → 1`` of every viscoelastic model.

    Parameters
    ----------
    modulus : float
        Young's (or plane-strain, as the scene chooses) modulus E > 0 (Pa, or E0 units).
    reference_time : float
        τ > 0 entering ``ζ = q0·V·τ`` (s, or τ units). It has no effect on the mechanics of an
        elastic solid; it only fixes the time unit of a dimensionless scene.

    Notes
    -----
    ``E0 = E∞ = E``, ``C(ω) = 1/E`` and ``J(t) = H(t)/E``; the creep spectrum has no terms.

    Examples
    --------
    >>> from viscocontact.rheology import Elastic
    >>> Elastic(modulus=2.0).complex_modulus([0.0, 1.0, 1e6])
    array([2.+0.j, 2.+0.j, 2.+0.j])
    >>> float(Elastic(modulus=2.0).creep_function(10.0))
    0.5
    """

    modulus: float = attrs.field(default=1.0, converter=_float, validator=positive)
    reference_time: float = attrs.field(default=1.0, converter=_float, validator=positive,
                                        metadata=TIME)

    @property
    def relaxed_modulus(self) -> float:
        """E0 = E."""
        return self.modulus

    @property
    def instantaneous_modulus(self) -> float:
        """E∞ = E."""
        return self.modulus

    def complex_modulus(self, omega) -> np.ndarray:
        """``E(ω) = E`` (complex dtype, shape of ``omega``)."""
        return np.full(np.shape(omega), self.modulus, dtype=complex)

    def relaxation_function(self, t) -> np.ndarray:
        """``R(t) = E·H(t)`` (eq. 2.17 with no Maxwell arms)."""
        t = np.asarray(t, dtype=float)
        return np.where(t < 0, 0.0, self.modulus)

    def creep_spectrum(self) -> CreepSpectrum:
        """``J(t) = 1/E`` for t > 0: instantaneous ``1/E``, empty weights and times."""
        return CreepSpectrum(instantaneous=1.0 / self.modulus, weights=np.empty(0),
                             times=np.empty(0))
