"""Rheologies: linear viscoelastic solids behind the :class:`Rheology` interface (thesis §2.1).

- :class:`Elastic`: Hooke's law, ``E(ω) = E``.
- :class:`StandardLinearSolid`: one creep time τ and ``β = E∞/E0`` (eqs. 4.4-4.5).
- :class:`PronySeries`: generalised Maxwell solid (eq. 2.17) with its exact creep form (2.20).
- :func:`fit_prony`, :func:`fit_report`: Prony fit of DMA data ``E'(ω), E''(ω)`` and its misfit.
- :class:`WLF`, :class:`Arrhenius`, :func:`shift`: time-temperature superposition (2.26-2.28).

Conventions (``exp(iωt)``, ``E'' >= 0``, ``C = 1/E``, ``reference_time``) are in :mod:`.base`.
"""
from .base import CreepSpectrum, Rheology
from .elastic import Elastic
from .fitting import FitReport, fit_prony, fit_report
from .prony import PronySeries
from .shift import TIME, WLF, Arrhenius, shift
from .sls import StandardLinearSolid

__all__ = ["Arrhenius", "CreepSpectrum", "Elastic", "FitReport", "PronySeries", "Rheology",
           "StandardLinearSolid", "TIME", "WLF", "fit_prony", "fit_report", "shift"]
