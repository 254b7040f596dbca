"""Single-threaded BLAS for a block of code (bit-identical results whatever the thread count).

A multi-threaded BLAS sums in another order and changes the last bits of a factorisation; studies
run every point, and the solver computes its cached calibration tables, with one thread, so that
serial, process-pool and Dask runs agree bit for bit.
"""
from __future__ import annotations

import contextlib
import ctypes
import os
from typing import Callable, Iterator


_OPENBLAS_SYMBOLS = (("openblas_get_num_threads", "openblas_set_num_threads"),
                     ("openblas_get_num_threads64_", "openblas_set_num_threads64_"),
                     ("scipy_openblas_get_num_threads64_", "scipy_openblas_set_num_threads64_"),
                     ("scipy_openblas_get_num_threads", "scipy_openblas_set_num_threads"))


def _openblas_controls() -> list[tuple[Callable[[], int], Callable[[int], None]]]:
    """(get, set) thread-count functions of every OpenBLAS loaded in this process (Linux)."""
    try:
        with open("/proc/self/maps", encoding="utf-8", errors="replace") as maps:
            paths = {line.split()[-1] for line in maps if "openblas" in line.lower()}
    except OSError:
        return []
    controls, seen = [], set()
    for path in sorted(paths):
        if not os.path.isfile(path):
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError:
            continue
        for get_name, set_name in _OPENBLAS_SYMBOLS:
            get, put = getattr(lib, get_name, None), getattr(lib, set_name, None)
            if get is None or put is None:
                continue
            address = ctypes.cast(put, ctypes.c_void_p).value
            if address not in seen:
                seen.add(address)
                get.restype, put.argtypes = ctypes.c_int, [ctypes.c_int]
                controls.append((get, put))
            break
    return controls


@contextlib.contextmanager
def single_blas_thread() -> Iterator[None]:
    """Run the block with single-threaded BLAS, then restore the previous thread counts.

    Uses :mod:`threadpoolctl` when it is installed, else the OpenBLAS libraries loaded in this
    process (numpy's and scipy's wheels bundle one each); elsewhere it does nothing, and
    bit-identical parallel runs then need ``OPENBLAS_NUM_THREADS=1`` in the environment.
    """
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:
        threadpool_limits = None
    if threadpool_limits is not None:
        with threadpool_limits(limits=1, user_api="blas"):
            yield
        return
    controls = _openblas_controls()
    before = [get() for get, _ in controls]
    for _, put in controls:
        put(1)
    try:
        yield
    finally:
        for (_, put), n in zip(controls, before):
            put(n)


