"""attrs validators whose errors name the field, the value and the allowed range."""
from __future__ import annotations

import math
from typing import Any, Iterable

import numpy as np

from .errors import ValidationError


def _name(inst: Any, attribute: Any) -> str:
    return f"{type(inst).__name__}.{attribute.name}"


def finite(inst, attribute, value):
    """Reject NaN and infinity."""
    try:
        ok = math.isfinite(float(value))
    except (TypeError, ValueError):
        raise ValidationError(_name(inst, attribute), value, "a finite real number") from None
    if not ok:
        raise ValidationError(_name(inst, attribute), value, "a finite real number")


def in_range(lo: float | None = None, hi: float | None = None, *, lo_open: bool = False,
             hi_open: bool = False, allow_inf: bool = False):
    """Validator for a real number in ``[lo, hi]`` (ends open when asked)."""
    left = "(" if lo_open else "["
    right = ")" if hi_open else "]"
    desc = f"a real number in {left}{'-inf' if lo is None else lo}, {'inf' if hi is None else hi}{right}"

    def check(inst, attribute, value):
        name = _name(inst, attribute)
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise ValidationError(name, value, desc) from None
        if math.isnan(v) or (math.isinf(v) and not allow_inf):
            raise ValidationError(name, value, desc)
        if lo is not None and (v < lo or (lo_open and v == lo)):
            raise ValidationError(name, value, desc)
        if hi is not None and (v > hi or (hi_open and v == hi)):
            raise ValidationError(name, value, desc)

    check.__doc__ = desc
    return check


def positive(inst, attribute, value):
    """A finite number > 0."""
    in_range(0.0, lo_open=True)(inst, attribute, value)


def non_negative(inst, attribute, value):
    """A finite number >= 0."""
    in_range(0.0)(inst, attribute, value)


def int_range(lo: int | None = None, hi: int | None = None):
    """Validator for an integer in ``[lo, hi]``."""
    desc = f"an integer in [{lo}, {'inf' if hi is None else hi}]"

    def check(inst, attribute, value):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise ValidationError(_name(inst, attribute), value, desc)
        if (lo is not None and value < lo) or (hi is not None and value > hi):
            raise ValidationError(_name(inst, attribute), value, desc)

    return check


def one_of(options: Iterable[Any]):
    """Validator for a value among ``options``."""
    opts = list(options)

    def check(inst, attribute, value):
        if value not in opts:
            raise ValidationError(_name(inst, attribute), value, f"one of {opts}")

    return check


def real_array(*, ndim: int = 1, min_size: int = 1):
    """attrs converter+validator pair helper: returns a read-only float64 copy or raises."""

    def convert(value):
        arr = np.array(value, dtype=float, copy=True)
        arr.setflags(write=False)
        return arr

    def check(inst, attribute, value):
        name = _name(inst, attribute)
        if value.ndim != ndim or value.size < min_size:
            raise ValidationError(name, value.shape, f"a {ndim}-d array with at least {min_size} entries")
        if not np.all(np.isfinite(value)):
            raise ValidationError(name, "array with NaN/inf", "finite entries")

    return convert, check


def array_eq():
    """``eq`` comparator for array fields (compare by value)."""
    import attrs

    return attrs.cmp_using(eq=lambda a, b: a.shape == b.shape and bool(np.array_equal(a, b)))


def readonly_floats(value) -> np.ndarray:
    """A read-only float copy of ``value`` (an attrs converter of array fields)."""
    arr = np.array(value, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


def readonly_ints(value, field: str, allowed: str = "integers") -> np.ndarray:
    """A read-only int64 copy of ``value``; whole floats are taken, anything else is a
    ValidationError naming ``field`` and ``allowed``."""
    arr = np.array(value, copy=True)
    if arr.dtype.kind == "f" and np.all(np.isfinite(arr)) and np.all(arr == np.round(arr)):
        arr = arr.astype(np.int64)
    if arr.dtype.kind not in "iu":
        raise ValidationError(field, value, allowed)
    arr = arr.astype(np.int64)
    arr.setflags(write=False)
    return arr
