r"""Uniform-grid spectral method for adhesionless scenes (draft docstring)."""
from .method import Spectral, SpectralPrepared

__all__ = ["Spectral", "SpectralPrepared"]
