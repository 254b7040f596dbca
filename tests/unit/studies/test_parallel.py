"""Serial and process-pool runs give bit-identical files; BLAS threads are restored."""
import pytest

from viscocontact.errors import ValidationError
from viscocontact.studies import Sweep, run
from viscocontact._threads import threads
from viscocontact.studies.parallel import (ProcessBackend, SerialBackend,
                                           backend, single_blas_thread)


def test_workers_give_the_serial_result(tmp_path, adhesionless, mesh, identical):
    sweep = Sweep(scene=adhesionless, zetas=[0.3, 3.0], loads=[0.05, 0.15], discretization=mesh)
    serial = run(sweep, tmp_path / "serial.h5", progress=None)
    pooled = run(sweep, tmp_path / "pool.h5", workers=2, progress=None)
    assert len(serial) == len(pooled) == 4
    identical(serial.points, pooled.points)


def test_single_blas_thread_restores_the_thread_counts():
    """(Nesting and threads: tests/unit/core/test_blas.py.)"""
    from threadpoolctl import threadpool_info

    def counts():
        return [lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"]

    before = counts()
    with single_blas_thread():
        assert all(n == 1 for n in counts())
    assert counts() == before


def test_backend_choice():
    assert isinstance(backend(1), SerialBackend)
    pool = backend(2)
    try:
        assert isinstance(pool, ProcessBackend) and pool.workers == 2
        assert pool.wait([pool.submit(max, 1, 2)])[0].result() == 2
        # each worker takes a core: its influence loop runs on one thread
        assert pool.wait([pool.submit(threads)])[0].result() == 1
    finally:
        pool.close()


def test_bad_workers(tmp_path, adhesionless):
    with pytest.raises(ValidationError, match="workers"):
        run(Sweep(scene=adhesionless, zetas=[1.0]), tmp_path / "s.h5", workers=0)
