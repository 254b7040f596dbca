"""The :class:`Surface` interface: a rigid periodic 2D height field on a rectangular cell.

Contract for implementers
-------------------------
1. Coordinates are dimensionless, ``x̃ = q0·x`` and ``ỹ = q0·y`` with ``q0 = 2π/L_x``: the cell is
   ``[0, 2π) × [0, 2π·aspect)`` with ``aspect = L_y/L_x``. Sliding is along ``x̃`` unless a kernel
   says otherwise. Heights are ``q0·h(x, y)`` with zero mean over the cell, as the 1D profiles'
   heights (:mod:`viscocontact.profiles.base`).
2. Implement :meth:`heights` (the height field sampled on a uniform grid of the cell) and
   :attr:`aspect`. Everything else has a default built on them.
3. Implementations are frozen attrs classes, keyword-only, validated at construction, registered
   in the ``viscocontact.surfaces`` entry-point group.
"""
from __future__ import annotations

import abc

import numpy as np

TWO_PI = 2.0 * np.pi


class Surface(abc.ABC):
    """A rigid 2D surface, periodic over the cell ``[0, 2π) × [0, 2π·aspect)``."""

    @property
    def aspect(self) -> float:
        """``L_y / L_x``, the cell's side ratio (default 1: a square cell)."""
        return 1.0

    @abc.abstractmethod
    def heights(self, nx: int, ny: int) -> np.ndarray:
        """``q0·h`` sampled at ``x̃_i = 2π·i/nx``, ``ỹ_j = 2π·aspect·j/ny``: an array of shape
        ``(ny, nx)`` (row ``j``, column ``i``) with zero mean."""

    def grid(self, nx: int, ny: int) -> tuple[np.ndarray, np.ndarray]:
        """The sample coordinates ``(x̃, ỹ)`` of :meth:`heights`, each of shape ``(ny, nx)``."""
        x = TWO_PI * np.arange(nx) / nx
        y = TWO_PI * self.aspect * np.arange(ny) / ny
        return np.meshgrid(x, y)
