"""Where points are computed: in this process, in a process pool or on a Dask cluster.

A backend has three methods: ``submit(fn, *args)`` returns a handle, ``wait(handles)`` returns the
handles that have finished (at least one) and ``close()``; ``handle.result()`` is the value.
The runner submits the next point of a chain only when the previous one is back, so parallelism is
over independent chains (loads, realizations, adhesive and adhesionless twins, cycles), never
along a ζ-continuation or a loading path, which are sequential by nature.

On a Dask cluster (:class:`DaskBackend`) the scheduler is found from an address, a scheduler
file or Dask's own configuration (:class:`DaskScheduler`, which also holds the connect timeout
and the retries); finished points come from one ``distributed.as_completed`` to which each chain
adds its next point, and a point Dask gives up on (its workers died, ``KilledWorker``) is stored
as an error so that the study goes on.

Every backend runs the same pure function (:func:`~viscocontact.studies.point.solve_point`) on the
same plain data, and BLAS runs single-threaded inside it (:func:`single_blas_thread`; a
multi-threaded BLAS sums in another order and changes the last bits), so serial, process-pool and
Dask runs give bit-identical results on machines with the same numpy/scipy build and CPU kind.
"""
from __future__ import annotations

import concurrent.futures
import json
import math
import threading
import uuid
import warnings
from pathlib import Path
from typing import Any, Callable, Iterable

import attrs

from ..errors import ValidationError, ViscoContactError

from .._blas import single_blas_thread  # noqa: F401  (re-exported)
from .._threads import set_threads


# ---- backends -----------------------------------------------------------------------------------
class _Deferred:
    """A call that the serial backend runs when it is waited for."""

    def __init__(self, fn, args):
        self.fn, self.args = fn, args
        self._value: Any = None
        self._done = False

    def run(self) -> None:
        self._value = self.fn(*self.args)
        self._done = True

    def result(self) -> Any:
        if not self._done:
            self.run()
        return self._value


class SerialBackend:
    """Runs each point in this process, oldest first, when the runner waits for it."""

    workers = 1

    def submit(self, fn: Callable, *args) -> _Deferred:
        return _Deferred(fn, args)

    def wait(self, handles: Iterable[_Deferred]) -> list[_Deferred]:
        first = next(iter(handles))
        first.run()
        return [first]

    def close(self) -> None:
        pass


def _worker_start() -> None:
    """A worker process: one influence-loop thread, and Ctrl-C left to the parent (which stops
    the pool and says what is kept) instead of a traceback from every worker."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    set_threads(1)


class ProcessBackend:
    """A pool of ``workers`` processes (started with ``spawn``: no state inherited by forking)."""

    def __init__(self, workers: int):
        import multiprocessing

        self.workers = workers
        # one influence-loop thread per worker: the workers already take a core each
        self.pool = concurrent.futures.ProcessPoolExecutor(
            max_workers=workers, mp_context=multiprocessing.get_context("spawn"),
            initializer=_worker_start)

    def submit(self, fn: Callable, *args) -> concurrent.futures.Future:
        return self.pool.submit(fn, *args)

    def wait(self, handles) -> list:
        done, _ = concurrent.futures.wait(list(handles),
                                          return_when=concurrent.futures.FIRST_COMPLETED)
        return list(done)

    def close(self) -> None:
        self.pool.shutdown(wait=True, cancel_futures=True)


# ---- Dask ---------------------------------------------------------------------------------------
def _seconds(name: str):
    def check(inst, attribute, value):
        if value is not None and (isinstance(value, bool) or not isinstance(value, (int, float))
                                  or not 0 < value < math.inf):
            raise ValidationError(name, value, "a finite number of seconds > 0, or None")
    return check


def _retries(inst, attribute, value):
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise ValidationError("DaskScheduler.retries", value, "an integer >= 0")


@attrs.frozen(kw_only=True)
class DaskScheduler:
    """How to reach a Dask distributed scheduler, and how points are sent to it.

    Parameters
    ----------
    address : str, optional
        ``tcp://host:8786`` (``--scheduler ADDRESS``).
    scheduler_file : str or Path, optional
        The JSON file a scheduler writes (``dask scheduler --scheduler-file FILE``; the
        ``--scheduler-file`` option). Not together with ``address``.
    connect_timeout : float, optional
        Seconds to wait for the scheduler; default Dask's ``distributed.comm.timeouts.connect``.
    retries : int
        Times a point whose task raised is run again (Dask's ``retries``). A point whose worker
        dies is rescheduled by Dask itself, up to ``distributed.scheduler.allowed-failures``
        times (default 3); past that Dask gives up (``KilledWorker``) and the point is stored
        as an error with that reason, so that the study goes on.

    With neither ``address`` nor ``scheduler_file`` the address is Dask's own configuration
    value ``scheduler-address`` (environment variable ``DASK_SCHEDULER_ADDRESS``,
    ``--scheduler config``); a local cluster is never started implicitly.
    """

    address: str | None = attrs.field(default=None)
    scheduler_file: Any = attrs.field(default=None)
    connect_timeout: float | None = attrs.field(default=None,
                                                validator=_seconds("connect_timeout"))
    retries: int = attrs.field(default=2, validator=_retries)

    def __attrs_post_init__(self):
        if self.address is not None and self.scheduler_file is not None:
            raise ValidationError("--scheduler-file", str(self.scheduler_file),
                                  "either --scheduler ADDRESS or --scheduler-file FILE, not both")
        if self.address is not None and (not isinstance(self.address, str)
                                         or not self.address.strip()):
            raise ValidationError("--scheduler", self.address, "a scheduler address such as "
                                                               "tcp://host:8786")

    def resolve(self) -> tuple[str, str]:
        """``(address, where it came from)``; raises :class:`ViscoContactError` when unset."""
        if self.address is not None:
            return self.address, "--scheduler"
        if self.scheduler_file is not None:
            return _address_in(Path(self.scheduler_file)), f"scheduler file {self.scheduler_file}"
        import dask

        address = dask.config.get("scheduler-address", None)
        if not address:
            raise ViscoContactError(
                "no Dask scheduler address: give --scheduler ADDRESS or --scheduler-file FILE, or "
                "set Dask's configuration value scheduler-address (DASK_SCHEDULER_ADDRESS)")
        return str(address), "Dask's configuration value scheduler-address"


def _address_in(path: Path) -> str:
    """The ``address`` in a scheduler file (the JSON ``dask scheduler`` writes)."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ViscoContactError(f"no such scheduler file: {path} (a scheduler started with "
                                "--scheduler-file writes it)") from None
    except OSError as exc:
        raise ViscoContactError(f"cannot read the scheduler file {path}: "
                                f"{exc.strerror or exc}") from exc
    try:
        address = json.loads(text)["address"]
    except (ValueError, KeyError, TypeError):
        raise ViscoContactError(f"{path} is not a Dask scheduler file (a JSON object with an "
                                "'address')") from None
    return str(address)


# One point at a time per process: BLAS thread settings and the kernel-table cache are per process,
# so the points a multi-threaded Dask worker runs take turns (see DaskBackend).
_ONE_POINT = threading.Lock()


def _alone(fn: Callable, *args):
    with _ONE_POINT:
        set_threads(1)          # one influence-loop thread: the cluster's workers share its cores
        return fn(*args)


class _DaskHandle:
    """A point on the cluster; ``result()`` turns a point Dask gave up on into an error record."""

    def __init__(self, future, fn, args):
        self.future, self.fn, self.args = future, fn, args

    def result(self):
        try:
            return self.future.result()
        except Exception as exc:
            from distributed import KilledWorker

            from .point import solve_point

            if isinstance(exc, KilledWorker) and self.fn is solve_point:
                return lost_record(self.args, exc)
            raise ViscoContactError(f"a point failed on the Dask cluster ({type(exc).__name__}: "
                                    f"{exc}); the points finished so far are in the study file, "
                                    "--resume continues") from exc


def lost_record(args, exc: BaseException) -> dict:
    """The error record of a point whose task Dask gave up on (``args`` of ``solve_point``)."""
    from .point import ERROR, _skeleton

    record = _skeleton(args[0], args[1])
    record.update(status=ERROR, converged=False, seconds=math.nan,
                  message=f"{type(exc).__name__}: lost with its Dask worker too often ({exc})")
    return record


class DaskBackend:
    """Points sent to a Dask distributed scheduler (``pip install 'viscocontact[distributed]'``).

    Parameters
    ----------
    scheduler : DaskScheduler, str or distributed.Client
        Where the scheduler is (a :class:`DaskScheduler`, an address ``tcp://host:8786``), or an
        existing client (not closed by :meth:`close`).

    Notes
    -----
    Finished points are taken from one ``distributed.as_completed`` to which each chain's next
    point is added when it is submitted (Dask's idiom for work that submits more work).

    Workers should run one thread each (``dask worker --nthreads 1``,
    ``LocalCluster(threads_per_worker=1)``): BLAS thread settings and the kernel-table cache are
    per process, so the points given to one worker process take turns and its other threads
    stay idle (a warning says so).
    """

    def __init__(self, scheduler):
        try:
            import distributed
        except ImportError as exc:
            from ..errors import PluginError

            raise PluginError("--scheduler needs Dask distributed: "
                              "pip install 'viscocontact[distributed]'") from exc
        if isinstance(scheduler, distributed.Client):
            self.client, self._own, spec = scheduler, False, DaskScheduler()
        else:
            spec = scheduler if isinstance(scheduler, DaskScheduler) else DaskScheduler(
                address=scheduler)
            address, source = spec.resolve()
            options = {} if spec.connect_timeout is None else {"timeout": spec.connect_timeout}
            try:
                self.client, self._own = distributed.Client(address, **options), True
            except (OSError, TimeoutError, ValueError) as exc:
                raise ViscoContactError(f"cannot reach the Dask scheduler at {address!r} (from "
                                        f"{source}): {exc}") from exc
        self.retries = spec.retries
        threads = self.client.nthreads()
        self.workers = max(1, len(threads))
        crowded = {w: n for w, n in threads.items() if n > 1}
        if crowded:
            warnings.warn(f"{len(crowded)} Dask worker(s) run {max(crowded.values())} threads: "
                          "viscocontact runs one point at a time per worker process, so the "
                          "other threads stay idle; start workers with --nthreads 1 "
                          "(LocalCluster(threads_per_worker=1))", RuntimeWarning, stacklevel=3)
        self._completed = distributed.as_completed()
        self._handles: dict = {}

    def submit(self, fn: Callable, *args) -> _DaskHandle:
        key = f"{getattr(fn, '__name__', 'call')}-{uuid.uuid4().hex}"
        future = self.client.submit(_alone, fn, *args, key=key, retries=self.retries)
        handle = _DaskHandle(future, fn, args)
        self._handles[future.key] = handle
        self._completed.add(future)
        return handle

    def wait(self, handles) -> list:
        if not self._handles:
            return []
        done = self._completed.next_batch(block=True)
        return [self._handles.pop(f.key) for f in done if f.key in self._handles]

    def close(self) -> None:
        pending = [h.future for h in self._handles.values()]
        self._handles.clear()
        self._completed.clear()
        if pending:
            self.client.cancel(pending)
        if self._own:
            self.client.close()


def backend(workers: int = 1, scheduler=None):
    """The backend for ``--workers N`` / ``--scheduler ADDRESS`` (scheduler wins).

    ``scheduler`` is a :class:`DaskScheduler`, an address or a ``distributed.Client``.
    """
    if scheduler is not None:
        return DaskBackend(scheduler)
    if workers > 1:
        return ProcessBackend(workers)
    return SerialBackend()
