"""Checks of the numbers a scene is made of: finite reals in a range, named by their key."""
from __future__ import annotations

import math
import types
from typing import Any, Mapping

import numpy as np

from .errors import ValidationError

#: Relative agreement asked of two values of one quantity (a physical value and its
#: dimensionless key, two Poisson ratios).
REL_TOL = 1e-9


# small helpers
def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(
        value, (bool, np.bool_))


def _as_float(value: Any) -> Any:
    try:
        return float(value) if _is_number(value) else value
    except OverflowError:  # an integer beyond the float range: the validator rejects it
        return value


def _overflows(value: Any) -> bool:
    """Whether ``value`` (or an item of it) is an integer too large for a float."""
    if isinstance(value, (list, tuple)):
        return any(_overflows(v) for v in value)
    try:
        float(value) if _is_number(value) else None
    except OverflowError:
        return True
    return False


def _check_number(field: str, value: Any, lo=None, hi=None, lo_open=False) -> None:
    interval = (f"{'(' if lo_open else '['}{'-inf' if lo is None else lo}, "
                f"{'inf' if hi is None else hi}]")
    desc = f"a finite real number in {interval}"
    if not _is_number(value) or _overflows(value) or not math.isfinite(float(value)):
        raise ValidationError(field, value, desc)
    v = float(value)
    if lo is not None and (v < lo or (lo_open and v == lo)):
        raise ValidationError(field, value, desc)
    if hi is not None and v > hi:
        raise ValidationError(field, value, desc)


def _freeze(mapping: Mapping | None) -> Mapping | None:
    if mapping is None:
        return None
    if not isinstance(mapping, Mapping):
        raise ValidationError("physical", mapping, "a table of SI values")
    return types.MappingProxyType({k: _as_float(v) for k, v in mapping.items()})


def _agree(a: float, b: float) -> bool:
    return math.isclose(float(a), float(b), rel_tol=REL_TOL, abs_tol=0.0)


def check_one_poisson(kernel, poisson: float) -> None:
    """A kernel's own Poisson ratio (a layer's) must be the scene's: one material, one ratio."""
    knu = getattr(kernel, "poisson", None)
    if knu is not None and not _agree(knu, poisson):
        from .errors import ValidationError

        raise ValidationError("kernel.poisson", knu, f"the scene's poisson = {poisson!r} "
                                                     "(one material, one Poisson ratio)")
