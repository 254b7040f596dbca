"""The unit of work of a study: its time limit, in any thread, next to a caller's alarm."""
from __future__ import annotations

import signal
import threading
import time

import pytest

from viscocontact.deadline import deadline
from viscocontact.studies.point import PointSpec, solve_point

MESSAGE = "TimeLimitExceeded: time limit of 0.001 s reached"


def test_time_limit_holds_in_a_worker_thread(adhesive, mesh):
    """A Dask worker runs points in threads: the limit acts there too (1 ms is far below an
    adhesive first touch) and the point is an error with the reason; without a limit the same
    point converges in a thread."""
    scene = adhesive.to_dict()
    spec = PointSpec(chain=0, step=0, phase="sweep", discretization=mesh)
    records = []

    def worker(limit):
        records.append(solve_point(scene, spec, None, limit))

    for limit in (1e-3, None):
        thread = threading.Thread(target=worker, args=(limit,))
        thread.start()
        thread.join()
    limited, free = records
    assert limited["status"] == "error" and not limited["converged"]
    assert limited["message"] == MESSAGE
    assert free["converged"] and free["n_contacts"] >= 1


def test_an_enclosing_deadline_still_holds(adhesionless, mesh):
    """A point's own limit cannot extend the caller's shorter one."""
    scene = adhesionless.to_dict()
    spec = PointSpec(chain=0, step=0, phase="sweep", discretization=mesh)
    with deadline(1e-3):
        time.sleep(0.01)                          # the caller's limit has passed
        record = solve_point(scene, spec, None, 3600.0)
    assert record["status"] == "error" and record["message"] == MESSAGE


@pytest.mark.skipif(not hasattr(signal, "setitimer"), reason="no interval timers")
def test_time_limit_leaves_the_callers_alarm_running(adhesive, mesh):
    def handler(signum, frame):  # pragma: no cover - cancelled before it fires
        raise AssertionError("the caller's alarm fired")

    previous = signal.signal(signal.SIGALRM, handler)
    try:
        signal.setitimer(signal.ITIMER_REAL, 600.0)
        record = solve_point(adhesive.to_dict(), PointSpec(chain=0, step=0, phase="sweep",
                                                           discretization=mesh), None, 1e-3)
        left, _ = signal.getitimer(signal.ITIMER_REAL)
        assert record["message"] == MESSAGE
        assert 0.0 < left <= 600.0 and signal.getsignal(signal.SIGALRM) is handler
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)
