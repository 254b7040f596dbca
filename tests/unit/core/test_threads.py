"""The influence loop's thread count: where it comes from, what it accepts, and that splitting
rows between threads changes no bit."""
from __future__ import annotations

import os
import select
import signal

import numpy as np
import pytest

from viscocontact import _threads
from viscocontact._threads import ENV, set_threads, split_rows, threads
from viscocontact.errors import ValidationError


@pytest.fixture(autouse=True)
def restore():
    yield
    set_threads(None)


def test_default_is_the_cores_then_the_environment_then_the_setting(monkeypatch):
    monkeypatch.delenv(ENV, raising=False)
    assert threads() == min(_threads.available(), _threads.MOST)
    monkeypatch.setenv(ENV, " 3 ")
    assert threads() == 3
    set_threads(5)
    assert threads() == 5
    set_threads(None)
    assert threads() == 3


@pytest.mark.parametrize("value", [0, -1, 257, 2.5, True, "two", None])
def test_bad_counts_name_the_field_and_the_range(value):
    if value is None:
        return set_threads(value)           # None is the reset, not a count
    with pytest.raises(ValidationError, match=r"threads = .* expected an integer from 1 to 256"):
        set_threads(value)


@pytest.mark.parametrize("value", ["0", "x", "1.5"])
def test_a_bad_environment_value_names_the_variable(monkeypatch, value):
    monkeypatch.setenv(ENV, value)
    with pytest.raises(ValidationError, match=f"{ENV} = .* expected an integer from 1 to 256"):
        threads()


@pytest.mark.parametrize("count", [1, 2, 3, 7])
def test_split_rows_covers_every_row_once(count):
    set_threads(count)
    seen = np.zeros(50, dtype=int)

    def run(start, stop):
        seen[start:stop] += 1

    split_rows(run, 50, _threads.SPLIT_MIN)         # large enough to split
    assert np.array_equal(seen, np.ones(50, dtype=int))
    split_rows(run, 50, _threads.SPLIT_MIN - 1)     # small: one call on all rows
    assert np.array_equal(seen, np.full(50, 2))


def test_an_error_in_a_thread_reaches_the_caller():
    set_threads(2)

    def run(start, stop):
        if start == 0:
            raise RuntimeError("row block failed")

    with pytest.raises(RuntimeError, match="row block failed"):
        split_rows(run, 10, _threads.SPLIT_MIN)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
def test_a_forked_child_splits_without_the_parents_pool():
    """A child forked after the pool's threads started has none of them: its splits must start
    a pool of its own instead of waiting forever for the inherited one."""
    set_threads(2)
    seen = np.zeros(10, dtype=int)

    def run(start, stop):
        seen[start:stop] += 1

    split_rows(run, 10, _threads.SPLIT_MIN)            # the parent's pool is running
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:                                         # the child
        try:
            split_rows(run, 10, _threads.SPLIT_MIN)
            os.write(write, bytes(seen.astype(np.uint8)))
        finally:
            os._exit(0)
    os.close(write)
    try:
        ready, _, _ = select.select([read], [], [], 20.0)
        if not ready:
            os.kill(pid, signal.SIGKILL)
        assert ready, "the forked child's split did not finish in 20 s"
        got = np.frombuffer(os.read(read, 10), dtype=np.uint8)
    finally:
        os.close(read)
        os.waitpid(pid, 0)
    assert np.array_equal(got, np.full(10, 2))


@pytest.mark.parametrize("n, m", [(170, 23), (345, 48), (700, 97), (1054, 231), (1384, 484)])
def test_solve_columns_gives_the_same_bits_on_one_thread_and_on_two(n, m):
    """The parts are fixed by the column count, so the thread count changes no bit; and the
    parts (multiples of 12 columns) solve the system as one solve does."""
    from scipy.linalg import lu_factor, lu_solve

    rng = np.random.default_rng(n)
    lu = lu_factor(rng.standard_normal((n, n)) + n ** 0.5 * np.eye(n))
    c = rng.standard_normal((n, m))
    pivots = lu[1].copy()
    set_threads(1)
    one = _threads.solve_columns(lu, c)
    set_threads(2)
    two = _threads.solve_columns(lu, c)
    assert np.array_equal(one, two)
    assert one.flags.f_contiguous                 # as LAPACK returns a solve
    whole = lu_solve(lu, c)
    assert np.max(np.abs(one - whole)) <= 1e-12 * np.max(np.abs(whole))
    assert np.array_equal(lu[1], pivots)           # the caller's pivots untouched


def test_solve_columns_parts_are_multiples_of_the_unit_and_cover_every_column(monkeypatch):
    from scipy import linalg

    seen = []
    real = linalg.lu_solve

    def spy(lu_and_piv, b, **kw):
        seen.append(b.shape[1] if b.ndim == 2 else 1)
        return real(lu_and_piv, b, **kw)

    monkeypatch.setattr(linalg, "lu_solve", spy)
    rng = np.random.default_rng(0)
    lu = linalg.lu_factor(rng.standard_normal((60, 60)) + 8 * np.eye(60))
    set_threads(2)
    _threads.solve_columns(lu, rng.standard_normal((60, 101)))
    assert sorted(seen) == [41, 60] and 60 % _threads.COLUMN_UNIT == 0
    seen.clear()
    _threads.solve_columns(lu, rng.standard_normal((60, _threads.SPLIT_COLUMNS - 1)))
    assert seen == [_threads.SPLIT_COLUMNS - 1]   # few columns: one solve


def test_alongside_runs_the_task_here_alone_while_the_work_runs_elsewhere():
    import threading

    set_threads(2)
    seen = {}

    def work():
        seen["work"] = threading.current_thread().name
        return 42

    def task():
        seen["task"] = (threading.current_thread().name, threads())

    assert _threads.alongside(work, task) == 42
    here = threading.current_thread().name
    assert seen["task"] == (here, 1)              # unsplit while beside the work
    assert seen["work"] != here
    assert threads() == 2                         # and split again afterwards
    set_threads(1)
    seen.clear()
    assert _threads.alongside(work, task) == 42   # one thread: the work alone
    assert "task" not in seen and seen["work"] == here


def test_an_error_of_the_task_is_raised_once_the_work_is_done():
    import time

    set_threads(2)
    done = []

    def work():
        time.sleep(0.05)
        done.append(True)

    def task():
        raise RuntimeError("task failed")

    with pytest.raises(RuntimeError, match="task failed"):
        _threads.alongside(work, task)
    assert done == [True]
    assert threads() == 2


def test_a_busy_side_thread_makes_the_work_run_here_without_the_task():
    """Solves in several threads of one process do not queue their factorisations behind one
    another on the side thread: a second caller meanwhile factorises in its own thread."""
    import threading

    set_threads(2)
    started, release = threading.Event(), threading.Event()
    seen = {}

    def slow_work():
        started.set()
        release.wait(10)
        return "first"

    first = threading.Thread(target=lambda: seen.setdefault(
        "first", _threads.alongside(slow_work, lambda: None)))
    first.start()
    assert started.wait(10)
    here = threading.current_thread().name
    got = _threads.alongside(lambda: (threading.current_thread().name, "second"),
                             lambda: seen.setdefault("task", True))
    release.set()
    first.join(10)
    assert got == (here, "second") and "task" not in seen
    assert seen["first"] == "first"


@pytest.mark.parametrize("count", [1, 2])
def test_pair_gives_both_results_on_any_thread_count_and_with_a_busy_side_thread(count):
    """Both halves are computed whatever the threads: on two, the first elsewhere and the
    second here alone; on one, or with the side thread claimed, one after the other here."""
    import threading

    set_threads(count)
    here = threading.current_thread().name
    first, second = _threads.pair(lambda: threading.current_thread().name,
                                  lambda: (threading.current_thread().name, threads()))
    assert second == (here, 1)
    assert (first != here) == (count == 2)
    set_threads(2)
    with _threads.second_thread() as claimed:         # another caller holds the second thread
        assert claimed
        first, second = _threads.pair(lambda: threading.current_thread().name,
                                      lambda: threading.current_thread().name)
    assert first == second == here
