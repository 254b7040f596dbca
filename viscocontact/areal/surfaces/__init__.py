"""Areal surfaces: the :class:`~viscocontact.areal.surfaces.base.Surface` interface and its
implementations (entry-point group ``viscocontact.surfaces``)."""
from .base import Surface

__all__ = ["Surface"]
