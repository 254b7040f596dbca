"""Threads of the compiled influence loop: the rows of one influence matrix split between threads.

The rows of an influence matrix are independent and each is computed with the same arithmetic
whichever thread computes it, so the result is bit for bit the same for any thread count. The
compiled loop (:mod:`viscocontact.kernels._compiled`) releases the GIL, so the threads run at
once. Nothing else is threaded: BLAS stays single-threaded in a solve (:mod:`._blas`), because a
multi-threaded factorisation sums in another order. Nor are a factorisation's solves split
between Python threads: scipy 1.17's ``lu_solve`` shifts the pivot array to LAPACK's 1-based
indices and back in place, so two threads solving with one 1200 × 1200 factorisation at once got
wrong columns in five tries of five (with a copy of the pivots each, none).

The count is the number of cores this process may use, or the environment variable
``VISCOCONTACT_THREADS`` (an integer from 1 to 256), or what :func:`set_threads` set last. A
study's worker processes (process pool, Dask) run one thread each: their parallelism is over the
study's chains, one per core.
"""
from __future__ import annotations

import numbers
import os
import threading
from concurrent.futures import ThreadPoolExecutor
from typing import Callable

from .errors import ValidationError

#: The environment variable that sets the thread count.
ENV = "VISCOCONTACT_THREADS"
#: Most threads.
MOST = 256
#: Fewest coefficients for which a call is split between threads (a split costs tens of
#: microseconds; this many coefficients take a few milliseconds on one thread).
SPLIT_MIN = 100_000

_lock = threading.Lock()
_count: int | None = None
_pool: ThreadPoolExecutor | None = None
_pool_size = 0


def _checked(value, source: str) -> int:
    n = None
    if isinstance(value, str):
        try:
            n = int(value)
        except ValueError:
            pass
    elif isinstance(value, numbers.Integral) and not isinstance(value, bool):
        n = int(value)
    if n is None or not 1 <= n <= MOST:
        raise ValidationError(source, value, f"an integer from 1 to {MOST}")
    return n


def available() -> int:
    """Cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:              # not on Linux
        return max(1, os.cpu_count() or 1)


def threads() -> int:
    """Threads of the influence loop: :func:`set_threads`, else ``VISCOCONTACT_THREADS``, else
    :func:`available` (at most :data:`MOST`)."""
    if _count is not None:
        return _count
    value = os.environ.get(ENV, "").strip()
    if value:
        return _checked(value, f"the environment variable {ENV}")
    return min(available(), MOST)


def set_threads(n: int | None) -> None:
    """Use ``n`` threads from now on (``None``: back to the environment or the cores)."""
    global _count
    _count = None if n is None else _checked(n, "threads")


def split_rows(run: Callable[[int, int], None], rows: int, coefficients: int) -> None:
    """Call ``run(start, stop)`` on consecutive blocks of ``rows`` that cover them, one block per
    thread (see :func:`threads`), the last one in this thread; once on all rows when the call is
    small (fewer than :data:`SPLIT_MIN` coefficients) or there is one thread."""
    n = min(threads(), rows)
    if n < 2 or coefficients < SPLIT_MIN:
        run(0, rows)
        return
    pool = _executor(n - 1)
    bounds = [rows * k // n for k in range(n + 1)]
    futures = [pool.submit(run, bounds[k], bounds[k + 1]) for k in range(n - 1)]
    try:
        run(bounds[-2], bounds[-1])
    finally:
        for f in futures:
            f.result()


def _forget_pool() -> None:
    """In a forked child: the parent's pool threads do not exist there, so start afresh (a task
    sent to the inherited pool would never run)."""
    global _pool, _pool_size, _lock
    _pool, _pool_size, _lock = None, 0, threading.Lock()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forget_pool)


def _executor(workers: int) -> ThreadPoolExecutor:
    global _pool, _pool_size
    with _lock:
        if _pool is None or _pool_size < workers:
            if _pool is not None:
                _pool.shutdown(wait=False)
            _pool = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="viscocontact")
            _pool_size = workers
        return _pool
