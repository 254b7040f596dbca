"""A wall-time limit for a block of code (``SIGALRM``), shared by the validation report and the
benchmark harness."""
from __future__ import annotations

import contextlib
import signal
import threading
from typing import Callable, Iterator


@contextlib.contextmanager
def time_limit(seconds: float, error: Callable[[], BaseException]) -> Iterator[None]:
    """Raise ``error()`` in the block after ``seconds`` of wall time.

    Uses ``SIGALRM``, so it only acts in the main thread of a process (a pool's workers and a
    serial runner); elsewhere, or without a limit (``seconds`` 0 or None), the block runs
    unbounded. The previous handler is restored on exit.
    """
    if (not seconds or not hasattr(signal, "setitimer")
            or threading.current_thread() is not threading.main_thread()):
        yield
        return

    def alarm(signum, frame):
        raise error()

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
