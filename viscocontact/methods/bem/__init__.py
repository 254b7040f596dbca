"""The boundary-element method with energy-balance edges (thesis §4.4); see
:mod:`~viscocontact.methods.bem.method`."""
from .meshing import Discretization
from .method import BEM

__all__ = ["BEM", "Discretization"]
