"""Single-threaded BLAS for a block of code (bit-identical results whatever the thread count).

A multi-threaded BLAS sums in another order and changes the last bits of a factorisation; studies
run every point, and the solver computes its cached calibration tables, with one thread, so that
serial, process-pool and Dask runs agree bit for bit.

The BLAS thread count is a setting of the whole process, not of a thread, so blocks entered from
several threads at once (a Dask worker's threads) or nested (a study point around a solve) share
one limit: every entry limits the BLAS libraries loaded by then (a library first loaded inside a
block is limited at the next entry), and the last block out restores the counts each library had
before the first block in.
"""
from __future__ import annotations

import contextlib
import threading
from typing import Iterator


class _SharedLimit:
    """One BLAS thread while at least one block is inside (the process-wide setting, counted)."""

    def __init__(self):
        self._lock = threading.Lock()
        self._inside = 0
        self._original: dict[str, int] = {}   # library file -> its thread count before

    def enter(self) -> None:
        from threadpoolctl import threadpool_info, threadpool_limits

        with self._lock:
            for lib in threadpool_info():
                if lib["user_api"] == "blas":
                    self._original.setdefault(lib["filepath"], lib["num_threads"])
            with _control():
                threadpool_limits(limits=1, user_api="blas")
            self._inside += 1

    def exit(self) -> None:
        from threadpoolctl import threadpool_limits

        with self._lock:
            self._inside -= 1
            if self._inside == 0:
                with _control():
                    threadpool_limits(limits=dict(self._original))
                self._original.clear()


@contextlib.contextmanager
def _control() -> Iterator[None]:
    """Let this thread set a process-wide BLAS pool, then let go of it.

    threadpoolctl (from 3.8) lets only one thread, the first to set a limit, change a pool that
    all threads share (OpenBLAS on pthreads); the others are silently ignored. Here the count of
    :class:`_SharedLimit` decides between the blocks, so whichever thread enters first or leaves
    last takes the control for its one change and gives it back.
    """
    from threadpoolctl import OpenBLASController

    clear = getattr(OpenBLASController, "clear_controlling_thread", None)
    if clear is None:                      # older threadpoolctl: any thread may set the pool
        yield
        return
    clear(force=True)
    try:
        yield
    finally:
        clear()


_SHARED = _SharedLimit()


@contextlib.contextmanager
def single_blas_thread() -> Iterator[None]:
    """Run the block with single-threaded BLAS, then restore the previous thread counts.

    Uses :mod:`threadpoolctl`, which finds every BLAS loaded in the process (numpy's and scipy's
    OpenBLAS, MKL, BLIS). Thread-safe and nestable (see the module docstring).
    """
    _SHARED.enter()
    try:
        yield
    finally:
        _SHARED.exit()
