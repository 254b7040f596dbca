"""Areal (2D) rough surfaces sliding in steady state over viscoelastic solids.

The areal counterpart of the 1D profiles, kernels and spectral method: a rigid periodic height
field on a rectangular cell slides at speed V over a linear viscoelastic half-space or layer.
:mod:`viscocontact.areal.surfaces` holds the surfaces (entry-point group
``viscocontact.surfaces``).
"""
