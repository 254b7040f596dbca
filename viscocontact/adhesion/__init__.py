"""Edge closing conditions: ``NoAdhesion`` (bounded stress), ``EnergyBalance`` (equations 4.9-4.20)
and ``MaugisDugdale`` (cohesive zones of finite range)."""
from .base import AdhesionLimitation, AdhesionModel, EdgeTerms
from .energy_balance import DEFAULT_EDGE_PERTURBATION, EnergyBalance
from .maugis_dugdale import MaugisDugdale
from .none import NoAdhesion

__all__ = ["AdhesionLimitation", "AdhesionModel", "EdgeTerms", "EnergyBalance", "MaugisDugdale",
           "NoAdhesion", "DEFAULT_EDGE_PERTURBATION"]
