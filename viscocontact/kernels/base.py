r"""The :class:`GreenKernel` interface: the elastic geometry of the solid.

The dimensionless periodic steady-sliding Green function of the thesis (eqs. 2.40-2.47, 4.1-4.3, 4.19)
is, for a stress :math:`\tilde\sigma` over one period :math:`x̃ \in [-π, π)`,
:math:`\tilde u(x) = \int \tilde G_V(x - x_1)\, \tilde\sigma(x_1)\, dx_1` with

.. math:: \tilde G_V(x) = -\frac{1}{\pi}\sum_{m\ge1} \frac{S_m}{m}\,\mathrm{Re}\big[K(m)\,e^{imx}\big] + c_0 ,
          \qquad K(m) = E_0\, \overline{C(m q_0 V)} = K_\infty + \sum_i \frac{w_i}{1 - i m \zeta_i},

where ``S_m`` is the geometry factor (1 for the half-plane, ``1 - A_m`` for the layers of eqs. 2.42-2.43),
``c_0`` the mean-displacement compliance of eq. 2.44 (compressible layers), and ``K`` the complex
compliance normalised by E0 at the excitation frequency ``m q0 V`` (``ζ_i = q0 V θ_i`` for each creep
branch of the rheology, ``K∞ = E0/E∞``). Displacement is positive into the solid, tensile stress
positive (thesis convention), and stresses are ``σ̃ = 2(1-ν²)σ/(E0 q0 Λ)``.

Contract for implementers: implement :meth:`geometry_factors`; override :meth:`mean_compliance` and
:meth:`correction_modes` when the geometry differs from the half-plane. :meth:`prepare` builds the
tables (see :class:`~viscocontact.kernels.prepared.PreparedKernel`).
"""
from __future__ import annotations

import abc

import numpy as np


class GreenKernel(abc.ABC):
    """Elastic geometry of the solid; see the module docstring."""

    @abc.abstractmethod
    def geometry_factors(self, m: np.ndarray) -> np.ndarray:
        """``S_m`` for integer modes ``m >= 1`` (unit-modulus elastic kernel ``-S_m cos(mx)/(π m)``)."""

    def mean_compliance(self) -> float:
        """``c0``: constant part of the kernel, ``ũ_mean = 2π c0 σ̃_mean`` (0 for the half-plane)."""
        return 0.0

    def correction_modes(self) -> int:
        """Number of modes after which ``|1 - S_m|`` is below 1e-16 (0: exactly the half-plane)."""
        return 0

    def prepare(self, rheology, zeta: float, tolerance: float | None = None):
        """Tables for one rheology and dimensionless speed ``ζ = q0 V τ``.

        Parameters
        ----------
        rheology : Rheology
            The viscoelastic material (its creep spectrum defines the memory branches).
        zeta : float
            ``ζ = q0·V·τ`` with τ the rheology's ``reference_time``; 0 gives the relaxed (E0) kernel.
        tolerance : float, optional
            Treat a memory branch as relaxed or frozen when that changes the kernel's
            antiderivative by at most this much (see
            :func:`~viscocontact.kernels.prepared.branch_regimes`); default: only outside
            ``[1e-12, 1e12]``.
        """
        from .prepared import PreparedKernel

        return PreparedKernel.build(self, rheology, zeta, tolerance)
