"""Edge closing conditions: ``NoAdhesion`` (bounded stress) and ``EnergyBalance`` (eqs. 4.9-4.20)."""
from .base import AdhesionModel, EdgeTerms
from .energy_balance import DEFAULT_EDGE_PERTURBATION, EnergyBalance
from .none import NoAdhesion

__all__ = ["AdhesionModel", "EdgeTerms", "EnergyBalance", "NoAdhesion", "DEFAULT_EDGE_PERTURBATION"]
