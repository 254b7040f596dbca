"""The blocked LU factorisation of large influence matrices (:mod:`viscocontact._lu`): the same
bits on one thread and on two, the factors of partial pivoting, and the task beside it."""
from __future__ import annotations

import threading
import warnings

import numpy as np
import pytest
from scipy.linalg import LinAlgWarning, lu_factor, lu_solve

from viscocontact import _lu, _threads
from viscocontact._threads import set_threads, threads


@pytest.fixture(autouse=True)
def restore():
    yield
    set_threads(None)


def influence_like(n: int, seed: int = 0) -> np.ndarray:
    """A matrix of the influence matrices' kind: a logarithmic kernel on uneven points, so that
    partial pivoting has rows to choose between."""
    rng = np.random.default_rng(seed)
    x = np.sort(rng.uniform(0.0, 2 * np.pi, n))
    d = np.abs(x[:, None] - x[None, :]) + 1e-3
    return -np.log(d) + 0.1 * rng.standard_normal((n, n))


@pytest.mark.parametrize("n", [_lu.SMALLEST, 1100, 1337, 2 * _lu.BLOCK * 3 + 5])
def test_the_same_bits_on_one_thread_and_on_two(n):
    a = influence_like(n, n)
    set_threads(1)
    one = _lu.lu_factor(a)
    set_threads(2)
    two = _lu.lu_factor(a)
    assert np.array_equal(one[0], two[0]) and np.array_equal(one[1], two[1])


@pytest.mark.parametrize("n", [_lu.SMALLEST, 1337])
def test_the_factors_are_those_of_partial_pivoting(n):
    """``P A = L U`` to round-off, with LAPACK's pivots (the same rows chosen as one
    ``lu_factor`` call chooses), in ``lu_factor``'s layout for ``lu_solve``."""
    a = influence_like(n, 7)
    lu, piv = _lu.lu_factor(a)
    ref_lu, ref_piv = lu_factor(a, check_finite=False)
    assert piv.dtype == ref_piv.dtype and np.array_equal(piv, ref_piv)
    lower = np.tril(lu, -1) + np.eye(n)
    upper = np.triu(lu)
    pa = a.copy()
    for i, p in enumerate(piv):                   # LAPACK's interchanges, in order
        pa[[i, p]] = pa[[p, i]]
    assert np.max(np.abs(lower @ upper - pa)) <= 1e-12 * np.max(np.abs(a))
    b = np.random.default_rng(1).standard_normal(n)
    x = lu_solve((lu, piv), b)
    assert np.max(np.abs(a @ x - b)) <= 1e-10 * np.max(np.abs(b)) * np.linalg.norm(a, np.inf)
    assert np.max(np.abs(lu - ref_lu)) <= 1e-10 * np.max(np.abs(ref_lu))


def test_the_input_is_left_as_it_was():
    a = influence_like(_lu.SMALLEST, 3)
    before = a.copy()
    _lu.lu_factor(a)
    assert np.array_equal(a, before)


def test_small_matrices_go_to_one_lapack_call():
    a = influence_like(_lu.SMALLEST - 1, 2)
    lu, piv = _lu.lu_factor(a)
    ref = lu_factor(a, check_finite=False)
    assert np.array_equal(lu, ref[0]) and np.array_equal(piv, ref[1])


def test_the_cut_depends_on_the_size_and_the_panel_only():
    n = 2000
    for k in range(0, n - _lu.BLOCK, _lu.BLOCK):
        c = _lu.cut(n, k)
        assert min(k + 2 * _lu.BLOCK, n) <= c <= n
        assert (c - min(k + 2 * _lu.BLOCK, n)) % _lu.UNIT == 0


def test_a_singular_matrix_warns_as_lu_factor_does():
    a = influence_like(_lu.SMALLEST, 4)
    a[:, 700] = 0.0
    with pytest.warns(LinAlgWarning, match="exactly zero"):
        _lu.lu_factor(a)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _lu.lu_factor(influence_like(_lu.SMALLEST, 5))      # and a regular one does not


@pytest.mark.parametrize("n", [_lu.SMALLEST - 1, _lu.SMALLEST])
def test_the_task_runs_alone_on_two_threads_and_not_on_one(n):
    a = influence_like(n, 6)
    seen = {}

    def task():
        seen["task"] = (threading.current_thread().name, threads())

    set_threads(2)
    out = _lu.lu_factor(a, task)
    assert np.array_equal(out[0], _lu.lu_factor(a)[0])
    assert seen["task"][1] == 1       # beside the factorisation, its own loops unsplit
    assert threads() == 2
    set_threads(1)
    seen.clear()
    _lu.lu_factor(a, task)
    assert "task" not in seen       # one thread: what the task prepares is computed when needed


def test_an_error_of_the_task_is_raised_once_the_factors_are_done():
    set_threads(2)

    def task():
        raise RuntimeError("task failed")

    with pytest.raises(RuntimeError, match="task failed"):
        _lu.lu_factor(influence_like(_lu.SMALLEST, 8), task)
    assert not _threads._side_free.locked()


def test_factorisations_in_two_threads_at_once_give_the_same_bits():
    """Solves in several threads of one process: one takes the second thread, the other
    factorises alone, both with the same bits."""
    set_threads(2)
    a = influence_like(1200, 9)
    ref = _lu.lu_factor(a)
    results = []
    workers = [threading.Thread(target=lambda: results.append(_lu.lu_factor(a)))
               for _ in range(3)]
    for w in workers:
        w.start()
    for w in workers:
        w.join(60)
    assert len(results) == 3
    assert all(np.array_equal(r[0], ref[0]) and np.array_equal(r[1], ref[1]) for r in results)
