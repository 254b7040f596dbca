"""Analytic oracles, in thesis units: Westergaard's and Johnson's adhesive wavy contact, its
Maugis–Dugdale (finite-range) version, and the apparent toughness of a Dugdale crack moving
through a standard linear solid."""
from .dugdale_crack import CrackState, steady_crack
from .johnson import JohnsonWavy
from .maugis_dugdale import MaugisDugdaleWavy, MDState
from .westergaard import westergaard_area, westergaard_penetration, westergaard_pressure

__all__ = ["CrackState", "JohnsonWavy", "MDState", "MaugisDugdaleWavy", "steady_crack",
           "westergaard_area", "westergaard_penetration", "westergaard_pressure"]
