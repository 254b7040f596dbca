"""The defaults of a contact problem, one definition for every way of building one.

A :class:`~viscocontact.scene.Scene` (from a file, a dict or Python) and a
:class:`~viscocontact.problem.ContactProblem` built in Python take the same components when
none is given: the half-plane, no adhesion, the ``"auto"`` method (the spectral method for an
adhesionless problem, the BEM for an adhesive one) and a solver chosen by whether the problem
is adhesive. Each is a registered name (:mod:`viscocontact._registry`), the tag a scene file
writes.

>>> from viscocontact import defaults
>>> defaults.METHOD, defaults.solver_name(adhesive=True), defaults.solver_name(adhesive=False)
('auto', 'broyden', 'bisection')
"""
from __future__ import annotations

from typing import Any

KERNEL = "half-plane"
ADHESION = "none"
METHOD = "auto"
#: The nonlinear solver of an adhesive problem (the edges' energy balances are coupled, and
#: Broyden's updates are cheaper than Newton's Jacobians) and of an adhesionless one (whose
#: edge residuals change sign once, which bisection brackets).
SOLVER = {True: "broyden", False: "bisection"}


def solver_name(adhesive: bool) -> str:
    """The registered name of the default solver."""
    return SOLVER[bool(adhesive)]


def build(kind: str, name: str) -> Any:
    """The registered component ``name`` of registry ``kind`` built with its own defaults
    (``build("solvers", "broyden")``)."""
    from ._registry import REGISTRIES

    return REGISTRIES[kind].get(name)()
