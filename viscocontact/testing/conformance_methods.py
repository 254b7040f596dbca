"""Conformance checks for :class:`~viscocontact.methods.base.SolutionMethod` implementations.

``check_method(method)`` raises ``AssertionError`` with a clear message when a method breaks the
contract: ``unsupported`` answers a string or ``None``; a supported adhesionless elastic wavy
contact reproduces Westergaard's area within 1e-2 (or within the method's own error estimate
when it is larger), with the result schema of every method (``extras["method"]`` the registered
name of the method that ran, ``extras["error_estimate"]`` a float, fields on request, no interpenetration,
complementarity in the reported fields); a scene without contact gives the no-contact result.
"""
from __future__ import annotations

from typing import NoReturn

import numpy as np


def _fail(name: str, message: str) -> NoReturn:
    raise AssertionError(f"{name}: {message}")


def check_method(method, *, mean_pressure: float = 0.3) -> None:
    """Run the method conformance checks (see the module docstring)."""
    from ..problem import ContactProblem
    from ..profiles.sinusoid import Sinusoid
    from ..reference.westergaard import westergaard_area
    from ..result import ContactResult, SolveStatus
    from ..rheology.elastic import Elastic
    from ..solvers.bisection import Bisection

    name = type(method).__name__
    problem = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                             solver=Bisection(), mean_pressure=mean_pressure, method=method)
    why = method.unsupported(problem)
    if why is not None and not isinstance(why, str):
        _fail(name, f"unsupported() must return a string or None, not {why!r}")
    if why is not None:
        return
    result = problem.solve(fields=True)
    if not isinstance(result, ContactResult):
        _fail(name, f"solve() must return a ContactResult, not {type(result).__name__}")
    if not result.converged:
        _fail(name, f"the elastic wavy contact at p̃∞ = {mean_pressure} did not converge: "
                    f"{result.message}")
    from .._registry import methods as registered

    ran = result.extras.get("method")
    if not method.name or ran not in {method.name, *registered.names()}:
        _fail(name, f"extras['method'] must name the method that computed the result (its own "
                    f"name {method.name!r}, or a registered method it delegated to), got {ran!r}")
    estimate = result.extras.get("error_estimate")
    if not isinstance(estimate, float):
        _fail(name, "extras['error_estimate'] must be a float (NaN when there is none)")
    exact = westergaard_area(mean_pressure)
    allowed = max(1e-2, 3.0 * estimate) if np.isfinite(estimate) else 1e-2
    if abs(result.area - exact) > allowed * exact:
        _fail(name, f"Ã = {result.area:.6g} against Westergaard's {exact:.6g} "
                    f"(allowed relative {allowed:.2g})")
    if abs(result.mean_pressure - mean_pressure) > 1e-6:
        _fail(name, f"mean pressure {result.mean_pressure} instead of the load {mean_pressure}")
    if not result.min_gap >= -1e-6:
        _fail(name, f"interpenetration outside the contacts: min_gap = {result.min_gap}")
    fields = result.fields
    if fields is None or not {"x", "pressure", "displacement", "gap"} <= set(fields):
        _fail(name, "fields=True must give x, pressure, displacement and gap")
    p, g = np.asarray(fields["pressure"]), np.asarray(fields["gap"])
    scale = float(np.max(np.abs(p)))
    if np.min(p) < -1e-6 * scale:
        _fail(name, f"tension {np.min(p):.3g} in an adhesionless contact")
    if np.min(g) < -1e-6:
        _fail(name, f"negative gap {np.min(g):.3g} in the fields")
    none = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=Elastic(),
                          solver=Bisection(), penetration=-0.1, method=method).solve()
    if none.status is not SolveStatus.NO_CONTACT or none.area != 0.0:
        _fail(name, f"a penetration below first touch must give no contact, got {none.status}")
