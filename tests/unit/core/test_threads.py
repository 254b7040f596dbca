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
