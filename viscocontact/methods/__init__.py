"""Solution methods: how an equilibrium of a :class:`~viscocontact.problem.ContactProblem` is
computed (the boundary-element method with energy-balance edges, the uniform-grid spectral method
for adhesionless scenes, or a plugin). See :mod:`viscocontact.methods.base` for the contract."""
from .base import SolutionMethod

__all__ = ["SolutionMethod"]
