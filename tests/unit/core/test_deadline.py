"""Cooperative time limits: expiry, nesting, threads, an enclosing SIGALRM, a solve stopped
mid-way. Expiry is forced by sleeping past a short limit or by a counting clock, never by timing
how long something takes."""
from __future__ import annotations

import contextvars
import math
import pickle
import signal
import threading
import time
import types
import warnings

import pytest

from viscocontact import deadline as deadline_module
from viscocontact.deadline import check, deadline, remaining
from viscocontact.errors import TimeLimitExceeded, ValidationError, ViscoContactError
from viscocontact.testing.scenes import WAVY

SCENE = WAVY


def expired(seconds: float) -> None:
    """Sleep well past a limit of ``seconds``."""
    time.sleep(2 * seconds + 0.01)


def test_no_limit_outside_a_block():
    check()
    assert remaining() == math.inf
    with deadline(None):
        check()
        assert remaining() == math.inf
    with deadline(math.inf):
        assert remaining() == math.inf


def test_check_raises_once_the_limit_has_passed():
    with deadline(30.0):
        check()                                   # far from its limit
        assert 0 < remaining() <= 30.0
    with pytest.raises(TimeLimitExceeded, match=r"^time limit of 0\.01 s reached$") as info:
        with deadline(0.01):
            expired(0.01)
            assert remaining() == 0.0
            check()
    assert info.value.seconds == 0.01
    assert isinstance(info.value, ViscoContactError)
    check()                                       # the limit ends with its block


def test_error_pickles_with_its_limit():
    error = pickle.loads(pickle.dumps(TimeLimitExceeded(2.5)))
    assert error.seconds == 2.5 and str(error) == "time limit of 2.5 s reached"


@pytest.mark.parametrize("seconds", [0, 0.0, -1.0, float("nan"), "10", True])
def test_bad_limit(seconds):
    with pytest.raises(ValidationError) as info:
        with deadline(seconds):
            pass
    assert info.value.field == "seconds" and "> 0" in str(info.value)


def test_inner_limit_cannot_extend_the_outer():
    with pytest.raises(TimeLimitExceeded) as info:
        with deadline(0.01):
            with deadline(3600.0):
                assert remaining() <= 0.01
                expired(0.01)
                check()
    assert info.value.seconds == 0.01             # the error names the limit that expired


def test_inner_limit_can_shorten_the_outer_and_ends_with_its_block():
    with deadline(3600.0):
        with pytest.raises(TimeLimitExceeded) as info:
            with deadline(0.01):
                expired(0.01)
                check()
        assert info.value.seconds == 0.01
        check()                                   # back under the outer limit, far from it
        assert remaining() > 0.01


def test_limit_holds_in_a_thread_and_threads_do_not_share_limits():
    """Dask runs points in worker threads: a limit set in a thread acts there, and neither
    sees the other's limit."""
    outcome = {}

    def worker():
        check()                                   # the main thread's expired limit is not ours
        try:
            with deadline(0.01):
                expired(0.01)
                check()
        except TimeLimitExceeded as exc:
            outcome["error"] = exc

    with deadline(0.01):
        expired(0.01)
        thread = threading.Thread(target=worker)
        thread.start()
        thread.join()
        with pytest.raises(TimeLimitExceeded):
            check()
    assert outcome["error"].seconds == 0.01


def test_a_thread_started_in_a_copied_context_inherits_the_limit():
    outcome = {}

    def worker():
        try:
            check()
        except TimeLimitExceeded as exc:
            outcome["error"] = exc

    with deadline(0.01):
        expired(0.01)
        context = contextvars.copy_context()
        thread = threading.Thread(target=context.run, args=(worker,))
        thread.start()
        thread.join()
    assert outcome["error"].seconds == 0.01


@pytest.mark.skipif(not hasattr(signal, "setitimer"), reason="no interval timers")
def test_an_enclosing_alarm_is_neither_cancelled_nor_replaced():
    def handler(signum, frame):  # pragma: no cover - the timer is cancelled before it fires
        raise AssertionError("the enclosing alarm fired")

    previous = signal.signal(signal.SIGALRM, handler)
    try:
        signal.setitimer(signal.ITIMER_REAL, 600.0)
        with pytest.raises(TimeLimitExceeded):
            with deadline(0.01):
                expired(0.01)
                check()
        left, _ = signal.getitimer(signal.ITIMER_REAL)
        assert 0.0 < left <= 600.0
        assert signal.getsignal(signal.SIGALRM) is handler
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)


class CountingClock:
    """``time.monotonic`` stand-in that advances one second per read: a limit of N seconds
    expires after N reads, wherever they happen."""

    def __init__(self):
        self.now = 0.0

    def monotonic(self) -> float:
        self.now += 1.0
        return self.now


def test_a_solve_stops_at_a_residual_evaluation(monkeypatch):
    """Every residual evaluation checks the limit: with a clock that advances one unit per
    check, a limit of 20 units stops a solve that needs many more evaluations, mid-way."""
    from viscocontact.methods.bem import BEM
    from viscocontact.problem import ContactProblem, Discretization
    from viscocontact.scene import Scene

    problem = ContactProblem.from_scene(Scene.from_toml(SCENE), method=BEM(),
                                        discretization=Discretization(elements=32))
    prepared = problem.prepare()
    free = problem.solve(prepared=prepared)
    assert free.converged and free.function_evaluations > 40

    clock = CountingClock()
    monkeypatch.setattr(deadline_module, "time", types.SimpleNamespace(monotonic=clock.monotonic))
    with pytest.raises(TimeLimitExceeded, match="time limit of 20 s"):
        with deadline(20.0):
            problem.solve(prepared=prepared)
    assert 19 <= clock.now <= 21                  # stopped at the check that saw the expiry


def test_deprecated_alarm_wrapper_maps_to_its_error():
    from viscocontact._alarm import time_limit

    class Stop(BaseException):
        pass

    with pytest.warns(DeprecationWarning, match="deadline"):
        with pytest.raises(Stop) as info:
            with time_limit(0.01, Stop):
                expired(0.01)
                check()
    assert isinstance(info.value.__cause__, TimeLimitExceeded)
    with pytest.warns(DeprecationWarning):        # a block that never checks: stopped at its end
        with pytest.raises(Stop):
            with time_limit(0.01, Stop):
                expired(0.01)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        with time_limit(None, Stop):
            expired(0.01)                         # no limit
        with pytest.raises(TimeLimitExceeded) as outer:   # an enclosing shorter limit is kept
            with deadline(0.01), time_limit(3600.0, Stop):
                expired(0.01)
                check()
    assert outer.value.seconds == 0.01


def test_a_spectral_solve_stops_at_an_iteration(monkeypatch):
    """The spectral method checks the limit at every iteration of its grid solvers."""
    from viscocontact.methods.spectral import Spectral
    from viscocontact.problem import ContactProblem
    from viscocontact.scene import Scene

    problem = ContactProblem.from_scene(Scene.from_toml(SCENE), method=Spectral())
    free = problem.solve()
    assert free.converged and free.iterations > 20
    clock = CountingClock()
    monkeypatch.setattr(deadline_module, "time", types.SimpleNamespace(monotonic=clock.monotonic))
    with pytest.raises(TimeLimitExceeded, match="time limit of 10 s"):
        with deadline(10.0):
            problem.solve()
    assert 9 <= clock.now <= 11
