"""Periodic viscoelastic half-plane (thesis equation 4.3; dimensionless equation 4.19)."""
from __future__ import annotations

import attrs
import numpy as np

from .base import GreenKernel


@attrs.frozen(kw_only=True)
class HalfPlane(GreenKernel):
    """Homogeneous half-plane: ``S_m = 1``, kernel ``log|2 sin(x/2)|/π`` per unit modulus E0.

    Poisson's ratio enters only through the scaling of eq. 4.17 (the factor ``1-ν²``).
    """

    def geometry_factors(self, m):
        return np.ones_like(np.asarray(m, dtype=float))
