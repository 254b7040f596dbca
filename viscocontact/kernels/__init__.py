"""Periodic viscoelastic Green kernels (thesis equations 2.40-2.47, 4.1-4.3, 4.19).

``GreenKernel`` describes the elastic geometry (``HalfPlane``, ``ConfinedLayer``, ``FreeLayer``);
``kernel.prepare(rheology, zeta)`` returns a :class:`PreparedKernel` whose ``influence`` gives the
coefficients ``B_lq`` of eq. 4.32 on any non-uniform mesh, for any rheology with a creep spectrum.
"""
from .base import GreenKernel
from .half_plane import HalfPlane
from .layers import ConfinedLayer, FreeLayer
from .prepared import PreparedKernel

__all__ = ["GreenKernel", "HalfPlane", "ConfinedLayer", "FreeLayer", "PreparedKernel"]
