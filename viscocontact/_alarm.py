"""Deprecated: the former ``SIGALRM`` time limit, now a thin wrapper over
:func:`viscocontact.deadline.deadline` (cooperative, thread-safe, no signal)."""
from __future__ import annotations

import contextlib
import time
import warnings
from typing import Callable, Iterator

from .deadline import deadline
from .errors import TimeLimitExceeded


@contextlib.contextmanager
def time_limit(seconds: float | None, error: Callable[[], BaseException]) -> Iterator[None]:
    """Raise ``error()`` once the block has run ``seconds`` of wall time.

    .. deprecated:: 0.1.0
       Use ``with viscocontact.deadline.deadline(seconds):``, which raises
       :class:`~viscocontact.errors.TimeLimitExceeded`.

    The limit is checked at every residual evaluation of a solve (see
    :mod:`viscocontact.deadline`) and, as the former signal-based limit guaranteed that a block
    never completed past its limit, once more when the block ends. A block that does not
    evaluate residuals (``time.sleep``) therefore runs to its end before ``error()`` is raised.
    No limit (``seconds`` 0 or None): the block runs unbounded.
    """
    warnings.warn("viscocontact._alarm.time_limit is deprecated: use "
                  "viscocontact.deadline.deadline", DeprecationWarning, stacklevel=3)
    if not seconds:
        yield
        return
    started = time.monotonic()
    try:
        with deadline(seconds):
            yield
    except TimeLimitExceeded as exc:
        if exc.seconds != float(seconds):   # an enclosing, shorter limit: not ours to rename
            raise
        raise error() from exc
    if time.monotonic() - started >= seconds:
        raise error()
