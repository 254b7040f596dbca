"""Argument checks for the plain functions and methods of :mod:`viscocontact.theories`.

The attrs validators of :mod:`viscocontact._validation` check fields at construction; these check
call arguments (scalars or arrays) and raise the same :class:`~viscocontact.errors.ValidationError`,
naming the argument, the value and the allowed range.
"""
from __future__ import annotations

import numpy as np

from .._validation import positive as _attrs_positive
from ..errors import ValidationError


def _interval(lo, hi, lo_open, hi_open) -> str:
    left = "(" if lo_open else "["
    right = ")" if hi_open else "]"
    return f"{left}{'-inf' if lo is None else lo}, {'inf' if hi is None else hi}{right}"


def real(name: str, value, lo: float | None = None, hi: float | None = None, *,
         lo_open: bool = False, hi_open: bool = False):
    """``value`` as a float (or a float array) whose every entry is finite and in the interval.

    Raises
    ------
    ValidationError
        Naming ``name``, the value and ``"a real number in [lo, hi]"`` (ends open when asked).
    """
    desc = f"a real number in {_interval(lo, hi, lo_open, hi_open)}"
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValidationError(name, value, desc) from None
    bad = ~np.isfinite(arr)
    if lo is not None:
        bad |= (arr <= lo) if lo_open else (arr < lo)
    if hi is not None:
        bad |= (arr >= hi) if hi_open else (arr > hi)
    if np.any(bad):
        shown = value if arr.ndim == 0 else arr[bad].ravel()[0]
        raise ValidationError(name, shown if arr.ndim == 0 else float(shown),
                              desc if arr.ndim == 0 else desc + " (every entry)")
    return float(arr) if arr.ndim == 0 else arr


def positive(name: str, value):
    """A finite number (or array) > 0."""
    return real(name, value, 0.0, lo_open=True)


def non_negative(name: str, value):
    """A finite number (or array) >= 0."""
    return real(name, value, 0.0)


# -- attrs converters and validators shared by the theory classes ----------------------------------
def as_float(value):
    """attrs converter: ``float(value)`` when possible, else the raw value for the validator to
    reject with a :class:`ValidationError` naming the field."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return value


def as_optional_float(value):
    """:func:`as_float`, keeping None."""
    return None if value is None else as_float(value)


def optional_positive(inst, attribute, value):
    """attrs validator: None or a finite number > 0."""
    if value is not None:
        _attrs_positive(inst, attribute, value)
