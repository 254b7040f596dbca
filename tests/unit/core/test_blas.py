"""Single-threaded BLAS: set inside the block, restored after, shared by nested and concurrent
blocks (the process-wide setting must not be restored while another thread is still inside)."""
from __future__ import annotations

import threading

import numpy as np
import pytest
import scipy.linalg  # noqa: F401  (loads scipy's BLAS too)
from threadpoolctl import threadpool_info, threadpool_limits

from viscocontact._blas import single_blas_thread


def blas_threads() -> set[int]:
    return {lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"}


@pytest.fixture
def two_threads():
    """BLAS at two threads around the test, so that a restore is visible on any machine."""
    if not blas_threads():
        pytest.skip("no BLAS that threadpoolctl controls")
    with threadpool_limits(limits=2, user_api="blas"):
        assert blas_threads() == {2}
        yield


def test_one_thread_inside_and_restored_after(two_threads):
    a = np.random.default_rng(0).standard_normal((64, 64))
    with single_blas_thread():
        assert blas_threads() == {1}
        with single_blas_thread():
            assert blas_threads() == {1}
        assert blas_threads() == {1}              # the nested block leaves it at one
        np.linalg.solve(a, a[0])
    assert blas_threads() == {2}


def test_restored_even_when_the_block_raises(two_threads):
    with pytest.raises(RuntimeError):
        with single_blas_thread():
            raise RuntimeError("stop")
    assert blas_threads() == {2}


def test_overlapping_threads_share_the_limit(two_threads):
    """Thread A enters, B enters, A leaves: B must still run single-threaded; the counts come
    back only when B leaves too."""
    a_in, b_in, a_out = threading.Event(), threading.Event(), threading.Event()
    seen = {}

    def thread_a():
        with single_blas_thread():
            a_in.set()
            b_in.wait(10)
        a_out.set()

    def thread_b():
        a_in.wait(10)
        with single_blas_thread():
            b_in.set()
            a_out.wait(10)
            seen["b after a left"] = blas_threads()

    threads = [threading.Thread(target=thread_a), threading.Thread(target=thread_b)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert seen["b after a left"] == {1}
    assert blas_threads() == {2}
