"""Cooperative wall-time limits.

>>> from viscocontact.deadline import deadline, remaining
>>> with deadline(60.0):
...     remaining() <= 60.0
True

``with deadline(seconds):`` sets a limit for the block; :func:`check` raises
:class:`~viscocontact.errors.TimeLimitExceeded` once it has passed. Every solve checks at each
residual evaluation (the step all nonlinear solvers and load paths go through), so a solve, a
study point or a validation case stops within one residual evaluation of its limit.

* The limit lives in a :mod:`contextvars` variable: it holds in the thread (or asyncio task) that
  set it, so it works in Dask worker threads, thread pools and on Windows alike, and threads
  never see each other's limits.
* Limits nest: an inner ``deadline`` can shorten the time left, never extend it (the earlier
  expiry wins, and the error names the limit that expired).
* No signal is used: an enclosing ``signal.alarm``/``setitimer`` timer and its handler are left
  untouched.

Where a limit cannot apply: the check is cooperative, so code that never calls :func:`check`
runs to its end — precomputing kernel tables (``ContactProblem.prepare``), the fields and
diagnostics after the last residual evaluation, a plugin solver or adhesion model that loops
without evaluating the residual, and anything outside viscocontact (``time.sleep``, I/O). A
thread started inside the block does not inherit the limit unless it is run in a copy of the
context (:func:`contextvars.copy_context`).
"""
from __future__ import annotations

import contextlib
import contextvars
import math
import time
from typing import Iterator, NamedTuple

from .errors import TimeLimitExceeded, ValidationError


class _Limit(NamedTuple):
    expires: float  # time.monotonic() at which the limit is reached
    seconds: float  # the limit as given (named by the error)


_ACTIVE: contextvars.ContextVar[_Limit | None] = contextvars.ContextVar(
    "viscocontact_deadline", default=None)


@contextlib.contextmanager
def deadline(seconds: float | None) -> Iterator[None]:
    """Limit the wall time of the block to ``seconds``.

    Parameters
    ----------
    seconds : float or None
        Wall time allowed to the block (s), > 0; ``None`` or ``inf`` adds no limit (an enclosing
        one still holds).

    Raises
    ------
    ValidationError
        ``seconds`` is not a number > 0 (nor None).
    TimeLimitExceeded
        From a :func:`check` in the block, once the earliest enclosing limit has passed.
    """
    if seconds is None:
        yield
        return
    if (isinstance(seconds, bool) or not isinstance(seconds, (int, float))
            or math.isnan(seconds) or seconds <= 0):
        raise ValidationError("seconds", seconds, "a number of seconds > 0, or None")
    if math.isinf(seconds):
        yield
        return
    new = _Limit(time.monotonic() + float(seconds), float(seconds))
    outer = _ACTIVE.get()
    token = _ACTIVE.set(outer if outer is not None and outer.expires <= new.expires else new)
    try:
        yield
    finally:
        _ACTIVE.reset(token)


def check() -> None:
    """Raise :class:`~viscocontact.errors.TimeLimitExceeded` if the current limit has passed.

    Costs one context-variable look-up and one clock read; a no-op outside any
    :func:`deadline`.
    """
    limit = _ACTIVE.get()
    if limit is not None and time.monotonic() >= limit.expires:
        raise TimeLimitExceeded(limit.seconds)


def remaining() -> float:
    """Seconds left before the current limit (``inf`` outside any :func:`deadline`; 0 once
    passed)."""
    limit = _ACTIVE.get()
    return math.inf if limit is None else max(0.0, limit.expires - time.monotonic())
