"""Threads of a single solve: the rows of an influence matrix, and the columns of a multiple
right-hand-side solve, split between threads.

The rows of an influence matrix are independent and each is computed with the same arithmetic
whichever thread computes it, so the result is bit for bit the same for any thread count. The
compiled loop (:mod:`viscocontact.kernels._compiled`) releases the GIL, so the threads run at
once. The columns of a solve with one factorisation (:func:`solve_columns`, the finite-δX
borders' ``B⁻¹c``) are split into parts fixed by the column count, whatever the thread count,
each part one solve with its own copy of the pivots: scipy 1.17's ``lu_solve`` shifts the pivot
array to LAPACK's 1-based indices and back in place, so two threads solving with one 1200 × 1200
factorisation and one pivot array at once got wrong columns in five tries of five (with a copy
of the pivots each, none). BLAS itself stays single-threaded in a solve (:mod:`._blas`), because
a multi-threaded factorisation sums in another order.

The count is the number of cores this process may use, or the environment variable
``VISCOCONTACT_THREADS`` (an integer from 1 to 256), or what :func:`set_threads` set last. A
study's worker processes (process pool, Dask) run one thread each: their parallelism is over the
study's chains, one per core.
"""
from __future__ import annotations

import contextlib
import numbers
import os
import threading
from concurrent.futures import ThreadPoolExecutor
from typing import Callable, Iterator, TypeVar

import numpy as np

from .errors import ValidationError

T = TypeVar("T")
U = TypeVar("U")

#: The environment variable that sets the thread count.
ENV = "VISCOCONTACT_THREADS"
#: Most threads.
MOST = 256
#: Fewest coefficients for which a call is split between threads (a split costs tens of
#: microseconds; this many coefficients take a few milliseconds on one thread).
SPLIT_MIN = 100_000
#: Parts of a multiple right-hand-side solve (:func:`solve_columns`), fixed so that the result
#: does not depend on the thread count.
COLUMN_PARTS = 2
#: The parts' widths are multiples of this many columns.
COLUMN_UNIT = 12
#: Fewest columns that are split into parts (below it one solve costs less than the split).
SPLIT_COLUMNS = 48

_lock = threading.Lock()
_count: int | None = None
_pool: ThreadPoolExecutor | None = None
_side: ThreadPoolExecutor | None = None     # the one thread of :func:`alongside`
_side_free = threading.Lock()               # held while a caller uses a second thread
_alone = threading.local()                  # this thread runs beside another's work
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
    :func:`available` (at most :data:`MOST`); 1 in a thread running beside another's work
    (:func:`alongside`)."""
    if getattr(_alone, "on", False):
        return 1
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
    pool = executor(n - 1)
    bounds = [rows * k // n for k in range(n + 1)]
    futures = [pool.submit(run, bounds[k], bounds[k + 1]) for k in range(n - 1)]
    try:
        run(bounds[-2], bounds[-1])
    finally:
        for f in futures:
            f.result()


def solve_columns(lu_and_piv, columns: np.ndarray) -> np.ndarray:
    """``B⁻¹ C`` from the LU factors of ``B`` (:func:`scipy.linalg.lu_factor`) for the columns
    ``C``, in :data:`COLUMN_PARTS` parts solved at once on as many threads (see :func:`threads`).

    The parts depend on the number of columns only, never on the thread count, so the result is
    the same bit for bit on one thread and on several (each part is one solve, the same call in
    either case; test). The parts' widths are multiples of :data:`COLUMN_UNIT`: on the installed
    OpenBLAS the triangular solves then give the bits of one solve of all columns (measured
    over systems of 170-2136 unknowns and 23-528 columns; splits at multiples of 4 or 8 columns
    did not). Calls with fewer than :data:`SPLIT_COLUMNS` columns are one solve. Each part gets
    its own copy of the pivots: scipy's ``lu_solve`` shifts them to 1-based indices and back in
    place, so two solves sharing one pivot array at once give wrong columns.
    """
    from scipy.linalg import lu_solve

    lu, piv = lu_and_piv
    m = columns.shape[1] if columns.ndim == 2 else 1
    if columns.ndim != 2 or m < SPLIT_COLUMNS:
        return lu_solve((lu, piv), columns, check_finite=False)
    width = COLUMN_UNIT * -(-m // (COLUMN_UNIT * COLUMN_PARTS))
    parts = [slice(j, min(j + width, m)) for j in range(0, m, width)]
    # Fortran order, as LAPACK returns one solve: products with its columns then take the same
    # BLAS path and give the same bits
    out = np.empty((lu.shape[0], m), dtype=np.result_type(lu, columns), order="F")

    def run(share) -> None:
        own = piv.copy()
        for part in share:
            out[:, part] = lu_solve((lu, own), columns[:, part], check_finite=False)

    n = min(threads(), len(parts))
    if n < 2:
        run(parts)
        return out
    pool = executor(n - 1)
    futures = [pool.submit(run, parts[k::n]) for k in range(1, n)]
    try:
        run(parts[0::n])
    finally:
        for f in futures:
            f.result()
    return out


def alongside(work: Callable[[], T], task: Callable[[], object]) -> T:
    """``work()``, computed on a thread of its own while this thread runs ``task()`` alone
    (its influence loops and solves unsplit, see :func:`threads`), so that the two share two
    cores; with one thread, ``work()`` alone and ``task`` not at all.

    For work that holds one core and releases the GIL (a LAPACK factorisation) and a task whose
    result is cached for later and would otherwise be computed after it: the task changes no
    result, only when it is computed. An exception of the task is raised once the work is done.
    When the side thread is busy (solves in several threads of one process), ``work()`` runs
    here and the task not at all, rather than wait in a queue.
    """
    global _side
    with second_thread() as two:
        if not two:
            return work()
        with _lock:
            if _side is None:
                _side = ThreadPoolExecutor(max_workers=1, thread_name_prefix="viscocontact-side")
            side = _side
        future = side.submit(work)
        _alone.on = True
        try:
            task()
        finally:
            _alone.on = False
            result = future.result()
    return result


def pair(first: Callable[[], T], second: Callable[[], U]) -> tuple[T, U]:
    """``(first(), second())``, the two computed at once on two threads when a second one is
    free (:func:`alongside`; ``second`` in this thread, alone), else one after the other. For
    independent pieces of work that release the GIL (products of dense matrices on one BLAS
    thread each): every call is the one made without threads, so the results are the same
    bits."""
    done: list = []
    out = alongside(first, lambda: done.append(second()))
    return out, (done[0] if done else second())


@contextlib.contextmanager
def second_thread() -> Iterator[bool]:
    """Whether this caller may put work on a second thread beside its own, for the block: True
    when :func:`threads` allows two and no other caller in this process holds the claim (solves
    in several threads of one process), else False, and the caller works alone rather than wait
    in a queue. One claim serves :func:`alongside` and the threaded factorisation
    (:mod:`._lu`)."""
    lock = _side_free
    if threads() < 2 or not lock.acquire(blocking=False):
        yield False
        return
    try:
        yield True
    finally:
        lock.release()


def run_alone(task: Callable[[], T]) -> T:
    """``task()`` with this thread's influence loops and solves unsplit (:func:`threads` is 1
    here while it runs): for work done beside another thread's."""
    _alone.on = True
    try:
        return task()
    finally:
        _alone.on = False


def _forget_pool() -> None:
    """In a forked child: the parent's pool threads do not exist there, so start afresh (a task
    sent to the inherited pool would never run)."""
    global _pool, _pool_size, _lock, _side, _side_free
    _pool, _pool_size, _lock, _side, _side_free = None, 0, threading.Lock(), None, threading.Lock()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forget_pool)


def executor(workers: int) -> ThreadPoolExecutor:
    """The process's pool of at least ``workers`` threads (shared by the splits above)."""
    global _pool, _pool_size
    with _lock:
        if _pool is None or _pool_size < workers:
            if _pool is not None:
                _pool.shutdown(wait=False)
            _pool = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="viscocontact")
            _pool_size = workers
        return _pool
