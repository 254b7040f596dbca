"""Conformance checks for :class:`~viscocontact.areal.surfaces.base.Surface` implementations.

``check_surface(surface)`` raises :class:`AssertionError` naming the property that fails: frozen
attrs value semantics, a positive aspect, heights of shape ``(ny, nx)`` that are real, finite,
zero-mean, reproducible on odd and even grids and returned as new writable arrays, point sampling
(the even samples of a grid twice as fine are the coarse samples, up to the constant of the
mean), the grid of :meth:`~viscocontact.areal.surfaces.base.Surface.grid`, finite statistics,
pickling (studies send surfaces to worker processes), and a round trip through the scene table
(:mod:`viscocontact.areal.surfaces.tables`).

Examples
--------
In a plugin's test suite::

    from viscocontact.testing.conformance_surfaces import check_surface

    def test_my_surface_conforms():
        check_surface(MySurface(amplitude=0.1))
"""
from __future__ import annotations

import math
import pickle
import tomllib
from typing import Any

import attrs
import numpy as np

from .conformance import _check_frozen, _check_hashable, _fail

__all__ = ["check_surface"]

#: Grids the heights are checked on: even, odd and mixed sides.
GRIDS = ((16, 12), (15, 17), (32, 32))


def check_surface(surface: Any, *, registered: bool = True, rtol: float = 1e-9) -> None:
    """Check a surface against its contract (see the module docstring).

    Parameters
    ----------
    surface : Surface
        The instance to check.
    registered : bool
        Whether the class is registered in ``viscocontact.surfaces`` (the round trip then goes
        through :func:`~viscocontact.areal.surfaces.tables.surface_table`; otherwise through the
        constructor's parameters).
    rtol : float
        Relative tolerance of the sampling checks, against the largest height.

    Raises
    ------
    AssertionError
        Naming the failed property.
    """
    from ..areal.surfaces.analysis import sample_statistics
    from ..areal.surfaces.base import Surface

    name = f"check_surface({type(surface).__qualname__})"
    if not isinstance(surface, Surface):
        _fail(name, "not a subclass of viscocontact.areal.surfaces.base.Surface")
    _check_frozen(surface, name)
    _check_hashable(surface, name)
    aspect = surface.aspect
    if not (isinstance(aspect, (float, int)) and math.isfinite(aspect) and aspect > 0):
        _fail(name, f"aspect = {aspect!r} must be a finite number > 0 (L_y/L_x)")

    for nx, ny in GRIDS:
        h = surface.heights(nx, ny)
        if not isinstance(h, np.ndarray) or h.shape != (ny, nx):
            _fail(name, f"heights({nx}, {ny}) must be an array of shape ({ny}, {nx}) (rows are "
                        f"y), got {getattr(h, 'shape', type(h))}")
        if h.dtype.kind != "f" or not np.all(np.isfinite(h)):
            _fail(name, f"heights({nx}, {ny}) must be finite real floats (dtype {h.dtype})")
        scale = max(float(np.max(np.abs(h))), 1e-300)
        if abs(float(h.mean())) > rtol * scale:
            _fail(name, f"heights({nx}, {ny}) must have zero mean: mean = {float(h.mean()):.3g} "
                        f"against max |h| = {scale:.3g}")
        if not np.array_equal(h, surface.heights(nx, ny)):
            _fail(name, f"heights({nx}, {ny}) differ between two calls (seeded, no global state)")
        if not h.flags.writeable:
            _fail(name, f"heights({nx}, {ny}) must be a new writable array (callers modify it)")
        h[...] += 1.0
        if np.array_equal(h, surface.heights(nx, ny)):
            _fail(name, f"heights({nx}, {ny}) returned an array the surface keeps: changing it "
                        "changed the next call's heights (return a copy)")
        h -= 1.0
        fine = surface.heights(2 * nx, 2 * ny)[::2, ::2]
        err = float(np.max(np.abs((fine - fine.mean()) - (h - h.mean())))) / scale
        if err > rtol:
            _fail(name, f"heights are not point samples: the even samples of heights({2 * nx}, "
                        f"{2 * ny}) differ from heights({nx}, {ny}) by {err:.3g} of max |h| "
                        f"(> {rtol:g}) beyond a constant")
        x, y = surface.grid(nx, ny)
        if x.shape != (ny, nx) or y.shape != (ny, nx):
            _fail(name, f"grid({nx}, {ny}) must return two arrays of shape ({ny}, {nx})")
        if not (np.allclose(x[0], 2 * np.pi * np.arange(nx) / nx, rtol=0, atol=1e-12)
                and np.allclose(y[:, 0], 2 * np.pi * aspect * np.arange(ny) / ny, rtol=0,
                                atol=1e-12 * max(1.0, aspect))):
            _fail(name, "grid() must be x̃_i = 2πi/nx along rows and ỹ_j = 2π·aspect·j/ny "
                        "along columns")

    stats = sample_statistics(surface, 64, 64)
    values = attrs.asdict(stats)
    bad = {k: v for k, v in values.items() if not np.isfinite(v)}
    if bad:
        _fail(name, f"statistics have non-finite values {bad}")
    if stats.rms <= 0:
        _fail(name, "the surface is flat (rms height 0): a surface needs roughness")
    try:
        copy = pickle.loads(pickle.dumps(surface))
    except Exception as exc:
        _fail(name, f"cannot be pickled ({exc}): studies send surfaces to worker processes")
    if copy != surface or not np.array_equal(copy.heights(16, 12), surface.heights(16, 12)):
        _fail(name, "a pickled and unpickled copy differs from the surface")
    _check_round_trip(surface, name, registered)


def _check_round_trip(surface: Any, name: str, registered: bool) -> None:
    from .._toml import dumps

    if registered:
        from ..areal.surfaces.tables import build_surface, surface_table

        try:
            table = surface_table(surface)
        except Exception as exc:  # PluginError: not registered
            _fail(name, f"cannot serialise as a scene table: {exc} (register the class under "
                        "the entry-point group viscocontact.surfaces and install the distribution)")
        parsed = tomllib.loads(dumps({"surface": table}))["surface"]
        try:
            rebuilt = build_surface(parsed)
        except Exception as exc:
            _fail(name, f"rebuilding from the scene table {parsed!r} failed: {exc}")
    else:
        from ..areal.surfaces.tables import surface_parameters

        params = surface_parameters(surface)
        parsed = tomllib.loads(dumps({"surface": params}))["surface"]
        try:
            rebuilt = type(surface)(**parsed)
        except Exception as exc:
            _fail(name, f"rebuilding from the TOML parameters {parsed!r} failed: {exc}")
    if rebuilt != surface:
        _fail(name, f"round trip through the scene table changed the surface: {surface!r} -> "
                    f"{rebuilt!r}")
