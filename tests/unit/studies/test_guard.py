"""One writer per study file (the lock file) and signals held during an append."""
import os
import signal

import pytest

from viscocontact.studies import StudyFileError
from viscocontact.studies.guard import exclusive, lock_path, signals_deferred


def test_a_second_writer_is_refused_and_the_lock_file_removed(tmp_path):
    path = tmp_path / "s.h5"
    with exclusive(path):
        assert lock_path(path).read_text() == str(os.getpid())
        with pytest.raises(StudyFileError, match=rf"s.h5 is being computed by process "
                                                 rf"{os.getpid()}"):
            with exclusive(path):
                pass
    assert not lock_path(path).exists()
    with exclusive(path):                                   # free again
        pass


def test_a_lock_file_left_by_a_killed_run_does_not_block(tmp_path):
    path = tmp_path / "s.h5"
    lock_path(path).write_text("999999")                    # its holder is gone: no OS lock
    with exclusive(path):
        assert lock_path(path).read_text() == str(os.getpid())
    assert not lock_path(path).exists()


def test_the_lock_is_released_when_the_block_raises(tmp_path):
    path = tmp_path / "s.h5"
    with pytest.raises(RuntimeError):
        with exclusive(path):
            raise RuntimeError("boom")
    with exclusive(path):
        pass


def test_a_lock_file_that_cannot_be_made_is_said(tmp_path):
    with pytest.raises(StudyFileError, match="cannot create the lock file"):
        with exclusive(tmp_path / "missing" / "s.h5"):
            pass


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_signals_wait_for_the_end_of_the_block(signum):
    seen = []

    def handler(s, frame):
        seen.append(("handler", s))

    previous = signal.signal(signum, handler)
    try:
        with signals_deferred():
            os.kill(os.getpid(), signum)
            for _ in range(1000):                           # Python would run a handler here
                pass
            seen.append(("block", None))
        assert seen == [("block", None), ("handler", signum)]
        assert signal.getsignal(signum) is handler          # the caller's handler is back
    finally:
        signal.signal(signum, previous)
