"""No adhesion: bounded stress at every edge (``K̃ = 0``)."""
from __future__ import annotations

import attrs
import numpy as np

from ..contact.edges import limit_energy_release
from .base import AdhesionModel, EdgeTerms


@attrs.frozen(kw_only=True)
class NoAdhesion(AdhesionModel):
    """Adhesionless edges: the stress vanishes like a square root (``K̃ = 0``, thesis §4.5.4)."""

    def residuals(self, ctx) -> np.ndarray:
        return ctx.stress_intensity()

    def residual_derivatives(self, ctx, dfields):
        return dfields.stress_intensity()

    def edge_terms(self, ctx) -> EdgeTerms:
        k = ctx.stress_intensity()
        n = len(k)
        return EdgeTerms(stored=limit_energy_release(ctx), nonconservative=np.zeros(n),
                         target=0.0, effective_work=np.full(n, np.nan), stress_intensity=k,
                         edge_perturbation=0.0)
