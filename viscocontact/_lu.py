"""The LU factorisation of a large influence matrix on the threads of one solve.

LAPACK's ``getrf`` runs on the one BLAS thread of a solve (:mod:`._blas`). Above
:data:`SMALLEST` unknowns this module factorises instead with the right-looking blocked
algorithm, panels of :data:`BLOCK` columns, calling the same LAPACK and BLAS routines on
sub-blocks in place (scipy's ``cython_blas`` and ``cython_lapack``): the factorisation of each
panel (``getrf``), then the panel's row interchanges (``laswp``), ``U₁₂ = L₁₁⁻¹A₁₂`` (``trsm``)
and ``A₂₂ -= L₂₁U₁₂`` (``gemm``) on the columns to its right. The columns to the right are cut
into two parts at places fixed by the matrix size alone: one thread updates the next panel's
columns, factorises that panel (look-ahead) and updates the first part, another updates the
second part at the same time. With one thread the same calls run one after the other, so the
factors are the same bit for bit on any thread count.

On the installed OpenBLAS (scipy 1.17's) they are also the bits of one ``scipy.linalg.lu_factor``
call, at every size measured from 700 unknowns up (``benchmarks/factorisation.py`` checks it on
influence matrices): its ``getrf`` blocks by 256 columns there and sums each update in the same
order. Another BLAS may sum in another order; the factors stay those of partial pivoting over
each full column, as in LAPACK, and the same on any thread count.

The factors are returned as :func:`scipy.linalg.lu_factor` returns them, for
:func:`scipy.linalg.lu_solve`.
"""
from __future__ import annotations

import ctypes
import warnings
from typing import Callable

import numpy as np

#: Columns of a panel (OpenBLAS's own block on x86-64 above 512 unknowns).
BLOCK = 256
#: Fewest unknowns factorised here; smaller matrices go to one ``lu_factor`` call (their
#: factorisation takes milliseconds, where the split gains little).
SMALLEST = 1024
#: The columns right of the look-ahead panel are cut where the first thread's part (after it
#: has factorised the panel) is half of them less this many panels' width: the panel's
#: factorisation takes about as long as updating two panels' columns.
LAG = 2
#: The cut falls on a multiple of this many columns.
UNIT = 16

_routines: dict | None = None


def _routine(module, name: str, n_args: int):
    """A routine of scipy's ``cython_blas`` or ``cython_lapack`` callable through ctypes
    (every argument a pointer; ctypes releases the GIL during the call)."""
    api = ctypes.pythonapi
    api.PyCapsule_GetName.restype = ctypes.c_char_p
    api.PyCapsule_GetName.argtypes = [ctypes.py_object]
    api.PyCapsule_GetPointer.restype = ctypes.c_void_p
    api.PyCapsule_GetPointer.argtypes = [ctypes.py_object, ctypes.c_char_p]
    capsule = module.__pyx_capi__[name]
    address = api.PyCapsule_GetPointer(capsule, api.PyCapsule_GetName(capsule))
    return ctypes.CFUNCTYPE(None, *[ctypes.c_void_p] * n_args)(address)


def _lapack() -> dict:
    global _routines
    if _routines is None:
        import scipy.linalg.cython_blas as blas
        import scipy.linalg.cython_lapack as lapack

        _routines = {"gemm": _routine(blas, "dgemm", 13), "trsm": _routine(blas, "dtrsm", 11),
                     "getrf": _routine(lapack, "dgetrf", 6),
                     "laswp": _routine(lapack, "dlaswp", 7)}
    return _routines


def _int(value: int):
    return ctypes.byref(ctypes.c_int(value))


_ONE, _MINUS_ONE = ctypes.c_double(1.0), ctypes.c_double(-1.0)
_L, _N, _U = ctypes.c_char_p(b"L"), ctypes.c_char_p(b"N"), ctypes.c_char_p(b"U")


class _Factors:
    """A Fortran-ordered square array factorised in place, panel by panel."""

    def __init__(self, a: np.ndarray):
        self.a = a
        self.n = a.shape[0]
        self.address = a.ctypes.data
        self.ld = _int(self.n)
        self.f = _lapack()
        self.singular = 0           # first zero pivot (1-based), 0 if none

    def at(self, i: int, j: int):
        return ctypes.c_void_p(self.address + 8 * (i + j * self.n))

    def panel(self, k: int, e: int, ipiv: np.ndarray) -> None:
        """Factorise columns ``k:e`` from row ``k`` down (pivots 1-based, relative to ``k``)."""
        info = ctypes.c_int(0)
        self.f["getrf"](_int(self.n - k), _int(e - k), self.at(k, k), self.ld,
                        ipiv.ctypes.data_as(ctypes.c_void_p), ctypes.byref(info))
        if info.value > 0 and not self.singular:
            self.singular = k + info.value

    def update(self, k: int, e: int, ipiv: np.ndarray, c0: int, c1: int) -> None:
        """Apply the factorised panel ``k:e`` to columns ``c0:c1`` right of it."""
        if c1 <= c0:
            return
        n, f = self.n, self.f
        width = _int(c1 - c0)
        f["laswp"](width, self.at(k, c0), self.ld, _int(1), _int(e - k),
                   ipiv.ctypes.data_as(ctypes.c_void_p), _int(1))
        f["trsm"](_L, _L, _N, _U, _int(e - k), width, ctypes.byref(_ONE), self.at(k, k),
                  self.ld, self.at(k, c0), self.ld)
        if e < n:
            f["gemm"](_N, _N, _int(n - e), width, _int(e - k), ctypes.byref(_MINUS_ONE),
                      self.at(e, k), self.ld, self.at(k, c0), self.ld, ctypes.byref(_ONE),
                      self.at(e, c0), self.ld)

    def left(self, k: int, ipiv: np.ndarray) -> None:
        """The row interchanges of panel ``k`` on the columns left of it."""
        self.f["laswp"](_int(k), self.at(k, 0), self.ld, _int(1), _int(len(ipiv)),
                        ipiv.ctypes.data_as(ctypes.c_void_p), _int(1))


def cut(n: int, k: int) -> int:
    """Where the columns right of the look-ahead panel after panel ``k`` are split (an index
    into the matrix): fixed by ``n`` and ``k`` alone, so that the factors do not depend on the
    thread count."""
    start = min(k + 2 * BLOCK, n)
    first = max(0, (n - start - LAG * BLOCK) // 2) // UNIT * UNIT
    return start + first


def lu_factor(matrix: np.ndarray, task: Callable[[], object] | None = None):
    """``(lu, piv)`` of ``matrix`` as :func:`scipy.linalg.lu_factor` gives them (no finiteness
    check), on two threads of this process when :func:`~viscocontact._threads.threads` allows.

    ``task``: work to run beside the factorisation on the second thread, in its own thread
    alone (:func:`~viscocontact._threads.alongside`); the factorisation takes that thread's share
    once the task is done. With one thread the task does not run (what it prepares is computed
    when it is needed), as with :func:`~viscocontact._threads.alongside`.
    """
    from ._threads import alongside, executor, pair, run_alone, second_thread

    n = matrix.shape[0]
    if n < SMALLEST:
        from scipy.linalg import lu_factor as scipy_lu_factor

        factorise = lambda: scipy_lu_factor(matrix, check_finite=False)   # noqa: E731
        return factorise() if task is None else alongside(factorise, task)
    # the copy into Fortran order reads the rows with a stride: two halves of the columns on
    # two threads take half as long (16 instead of 29 ms at 2136 unknowns)
    a = np.empty(matrix.shape, dtype=float, order="F")
    half = n // 2
    pair(lambda: np.copyto(a[:, half:], matrix[:, half:]),
         lambda: np.copyto(a[:, :half], matrix[:, :half]))
    with second_thread() as two:
        pool = executor(1) if two else None
        beside = pool.submit(run_alone, task) if pool is not None and task is not None else None
        piv = _blocked(_Factors(a), pool, beside)
        if beside is not None:
            beside.result()
    return a, piv


def _blocked(f: _Factors, pool, beside) -> np.ndarray:
    n = f.n
    starts = range(0, n, BLOCK)
    ipivs = [np.zeros(min(BLOCK, n - k), dtype=np.intc) for k in starts]
    f.panel(0, min(BLOCK, n), ipivs[0])
    for j, k in enumerate(starts[:-1]):
        e, e2 = k + BLOCK, min(k + 2 * BLOCK, n)
        split = cut(n, k)
        ipiv = ipivs[j]
        second = None
        if pool is not None and split < n and (beside is None or beside.done()):
            second = pool.submit(f.update, k, e, ipiv, split, n)
        f.update(k, e, ipiv, e, e2)              # the next panel's columns, then the panel
        f.panel(e, e2, ipivs[j + 1])
        f.update(k, e, ipiv, e2, split)
        if second is None:
            f.update(k, e, ipiv, split, n)
        else:
            second.result()
    piv = np.empty(n, dtype=np.int32)
    for j, k in enumerate(starts):
        if k > 0:
            f.left(k, ipivs[j])
        piv[k:k + len(ipivs[j])] = ipivs[j] + (k - 1)
    if f.singular:
        from scipy.linalg import LinAlgWarning

        warnings.warn(f"Diagonal number {f.singular} is exactly zero. Singular matrix.",
                      LinAlgWarning, stacklevel=3)
    return piv
