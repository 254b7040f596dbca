"""Analytic oracles: Westergaard and Johnson's adhesive wavy contact, its Maugis–Dugdale
(finite-range) version, and the toughness of a Dugdale crack in a standard linear solid (in thesis
units)."""
from .johnson import JohnsonWavy
from .maugis_dugdale import MaugisDugdaleWavy, MDState
from .westergaard import westergaard_area, westergaard_penetration, westergaard_pressure

__all__ = ["JohnsonWavy", "MDState", "MaugisDugdaleWavy", "westergaard_area",
           "westergaard_penetration", "westergaard_pressure"]
