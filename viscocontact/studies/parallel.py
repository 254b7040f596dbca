"""Where points are computed: in this process, in a process pool or on a Dask cluster.

A backend has three methods: ``submit(fn, *args)`` returns a handle, ``wait(handles)`` returns the
handles that have finished (at least one) and ``close()``; ``handle.result()`` is the value.
The runner submits the next point of a chain only when the previous one is back, so parallelism is
over independent chains (loads, realizations, adhesive and adhesionless twins, cycles), never
along a ζ-continuation or a loading path, which are sequential by nature.

Every backend runs the same pure function (:func:`~viscocontact.studies.point.solve_point`) on the
same plain data, and BLAS runs single-threaded inside it (:func:`single_blas_thread`; a
multi-threaded BLAS sums in another order and changes the last bits), so serial, process-pool and
Dask runs give bit-identical results on machines with the same numpy/scipy build and CPU kind.
"""
from __future__ import annotations

import concurrent.futures
from typing import Any, Callable, Iterable


from .._blas import single_blas_thread  # noqa: F401  (re-exported)


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


class ProcessBackend:
    """A pool of ``workers`` processes (started with ``spawn``: no state inherited by forking)."""

    def __init__(self, workers: int):
        import multiprocessing

        self.workers = workers
        self.pool = concurrent.futures.ProcessPoolExecutor(
            max_workers=workers, mp_context=multiprocessing.get_context("spawn"))

    def submit(self, fn: Callable, *args) -> concurrent.futures.Future:
        return self.pool.submit(fn, *args)

    def wait(self, handles) -> list:
        done, _ = concurrent.futures.wait(list(handles),
                                          return_when=concurrent.futures.FIRST_COMPLETED)
        return list(done)

    def close(self) -> None:
        self.pool.shutdown(wait=True, cancel_futures=True)


class DaskBackend:
    """Points sent to a Dask distributed scheduler (``pip install 'viscocontact[distributed]'``).

    Parameters
    ----------
    scheduler : str or distributed.Client
        Scheduler address (``tcp://host:8786``) or an existing client (not closed by
        :meth:`close`).
    """

    def __init__(self, scheduler):
        try:
            import distributed
        except ImportError as exc:
            from ..errors import PluginError

            raise PluginError("--scheduler needs Dask distributed: "
                              "pip install 'viscocontact[distributed]'") from exc
        self._distributed = distributed
        if isinstance(scheduler, distributed.Client):
            self.client, self._own = scheduler, False
        else:
            try:
                self.client, self._own = distributed.Client(scheduler), True
            except (OSError, TimeoutError, ValueError) as exc:
                from ..errors import ViscoContactError

                raise ViscoContactError(f"cannot reach the Dask scheduler at {scheduler!r}: "
                                        f"{exc}") from exc
        self.workers = max(1, sum(self.client.nthreads().values()))

    def submit(self, fn: Callable, *args):
        return self.client.submit(fn, *args, pure=False)

    def wait(self, handles) -> list:
        done, _ = self._distributed.wait(list(handles), return_when="FIRST_COMPLETED")
        return list(done)

    def close(self) -> None:
        if self._own:
            self.client.close()


def backend(workers: int = 1, scheduler=None):
    """The backend for ``--workers N`` / ``--scheduler ADDRESS`` (scheduler wins)."""
    if scheduler is not None:
        return DaskBackend(scheduler)
    if workers > 1:
        return ProcessBackend(workers)
    return SerialBackend()
