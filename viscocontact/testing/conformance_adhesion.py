"""Conformance checks for traction laws (:meth:`AdhesionModel.traction
<viscocontact.adhesion.AdhesionModel.traction>`, contract item 11).

``check_traction_law(model)`` raises :class:`AssertionError` naming the property that fails: frozen
attrs value semantics, a traction of the gaps' shape that is finite and tensile (>= 0) at every
gap beyond contact, a work of separation ``∫_0^∞ t dg = 2πγ̃`` (the work of adhesion in the law's
units, by adaptive quadrature), a peak ``strength(1)`` that the traction reaches and never
exceeds, a finite positive ``quasi_static_zone``, and a law the grids can apply
(:func:`~viscocontact.methods.spectral.traction.grid_law`).

Examples
--------
In a plugin's test suite::

    from viscocontact.testing.conformance_adhesion import check_traction_law

    def test_my_law_conforms():
        check_traction_law(MyLaw(gamma=1e-3, range=0.01))
"""
from __future__ import annotations

from typing import Any

import numpy as np

from .conformance import _check_frozen, _fail

__all__ = ["check_traction_law"]


def check_traction_law(model: Any, *, rtol: float = 1e-8) -> None:
    """Check a traction law against its contract (see the module docstring); ``rtol`` bounds
    the work of separation's relative error."""
    from scipy.integrate import quad

    from ..methods.spectral.traction import grid_law

    name = type(model).__name__
    _check_frozen(model, name)
    gamma = float(model.work_of_adhesion)
    if not gamma > 0:
        _fail(name, f"work of adhesion {gamma!r}: the checks need an adhesive law (> 0)")
    length = float(model.range)
    gaps = np.concatenate([[0.0], length * np.logspace(-4, 3, 701)])
    t = np.asarray(model.traction(gaps), dtype=float)
    if t.shape != gaps.shape:
        _fail(name, f"traction of {gaps.shape} gaps has shape {t.shape}")
    if not np.all(np.isfinite(t)) or np.any(t < 0):
        _fail(name, f"traction not finite and >= 0 at every gap (least {np.min(t):.3g})")
    if np.shape(model.traction(0.5 * length)) != ():
        _fail(name, "traction of a scalar gap is not a scalar")
    work = sum(quad(lambda g: float(model.traction(g)), lo, hi, limit=400, epsabs=0.0,
                    epsrel=0.1 * rtol)[0]
               for lo, hi in ((0.0, length), (length, 10 * length), (10 * length, np.inf)))
    if abs(work / (2 * np.pi * gamma) - 1.0) > rtol:
        _fail(name, f"work of separation {work:.10g} is not 2πγ̃ = {2 * np.pi * gamma:.10g} "
                    f"(relative error {work / (2 * np.pi * gamma) - 1.0:.2g} > {rtol:g})")
    peak = float(model.strength(1.0))
    if t.max() > peak * (1 + 1e-9) or t.max() < peak * (1 - 1e-2):
        _fail(name, f"largest sampled traction {t.max():.6g} against strength(1) = {peak:.6g} "
                    "(the peak must be reached within 1 % on a log grid of gaps, never exceeded)")
    zone = float(model.quasi_static_zone)
    if not (np.isfinite(zone) and zone > 0):
        _fail(name, f"quasi_static_zone = {zone!r}: a finite positive length is needed")
    if grid_law(model, 0.1) is None:
        _fail(name, "grid_law(model, 0.1) gives no law for the grids")
