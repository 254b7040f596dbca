"""Edge closing conditions: ``NoAdhesion`` (bounded stress), ``EnergyBalance`` (equations 4.9-4.20)
``MaugisDugdale`` (cohesive zones of finite range) and ``LennardJones`` (a 9-3 traction law on the
grids)."""
from .base import AdhesionLimitation, AdhesionModel, EdgeTerms
from .energy_balance import DEFAULT_EDGE_PERTURBATION, EnergyBalance
from .lennard_jones import LennardJones
from .maugis_dugdale import MaugisDugdale
from .none import NoAdhesion

__all__ = ["AdhesionLimitation", "AdhesionModel", "EdgeTerms", "EnergyBalance", "LennardJones",
           "MaugisDugdale",
           "NoAdhesion", "DEFAULT_EDGE_PERTURBATION"]
