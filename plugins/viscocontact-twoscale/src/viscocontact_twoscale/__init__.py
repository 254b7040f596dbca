"""Example viscocontact plugin: the two-scale profile, registered as ``kind = "two-scale"``."""
from .profile import TwoScaleProfile

__all__ = ["TwoScaleProfile"]
