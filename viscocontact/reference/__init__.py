"""Analytic oracles: Westergaard and Johnson's adhesive wavy contact, Hertz/JKR (in thesis units)."""
from .johnson import JohnsonWavy
from .westergaard import westergaard_area, westergaard_penetration, westergaard_pressure

__all__ = ["JohnsonWavy", "westergaard_area", "westergaard_penetration", "westergaard_pressure"]
