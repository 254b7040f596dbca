"""Reaching a Dask scheduler (address, scheduler file, Dask's configuration, connect timeout) and
points that Dask gives up on. No cluster is started here (see tests/integration)."""
import json
import math
import types

import pytest

from viscocontact.cli import main
from viscocontact.errors import ValidationError, ViscoContactError
from viscocontact.studies.parallel import DaskBackend, DaskScheduler, _DaskHandle
from viscocontact.studies.point import PointSpec, solve_point

distributed = pytest.importorskip("distributed")
dask = pytest.importorskip("dask")

SCENE = {"profile": {"kind": "sinusoid", "amplitude": 0.1},
         "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
         "load": {"mean_pressure": 0.1}, "sliding": {"zeta": 0.5}}


def test_address_sources(tmp_path):
    assert DaskScheduler(address="tcp://h:1").resolve() == ("tcp://h:1", "--scheduler")
    file = tmp_path / "scheduler.json"
    file.write_text(json.dumps({"type": "Scheduler", "address": "tcp://10.0.0.2:8786"}))
    assert DaskScheduler(scheduler_file=file).resolve()[0] == "tcp://10.0.0.2:8786"
    with dask.config.set({"scheduler-address": "tcp://10.0.0.3:8786"}):
        address, source = DaskScheduler().resolve()
    assert address == "tcp://10.0.0.3:8786" and "scheduler-address" in source


def test_address_errors(tmp_path):
    with dask.config.set({"scheduler-address": None}):
        with pytest.raises(ViscoContactError, match="DASK_SCHEDULER_ADDRESS"):
            DaskScheduler().resolve()
    with pytest.raises(ViscoContactError, match="no such scheduler file"):
        DaskScheduler(scheduler_file=tmp_path / "missing.json").resolve()
    (tmp_path / "bad.json").write_text("{not json")
    with pytest.raises(ViscoContactError, match="not a Dask scheduler file"):
        DaskScheduler(scheduler_file=tmp_path / "bad.json").resolve()


@pytest.mark.parametrize("options,field", [
    ({"address": "tcp://h:1", "scheduler_file": "s.json"}, "--scheduler-file"),
    ({"address": ""}, "--scheduler"),
    ({"connect_timeout": 0}, "connect_timeout"),
    ({"connect_timeout": float("inf")}, "connect_timeout"),
    ({"retries": -1}, "DaskScheduler.retries"),
    ({"retries": True}, "DaskScheduler.retries"),
])
def test_bad_options(options, field):
    with pytest.raises(ValidationError) as info:
        DaskScheduler(**options)
    assert info.value.field == field


def test_connect_timeout_ends_the_wait():
    spec = DaskScheduler(address="tcp://127.0.0.1:9", connect_timeout=0.5)
    with pytest.raises(ViscoContactError, match=r"cannot reach the Dask scheduler at "
                                                r"'tcp://127.0.0.1:9' \(from --scheduler\)"):
        DaskBackend(spec)


class _Future:
    def __init__(self, exc):
        self.exc = exc

    def result(self):
        raise self.exc


def test_a_point_dask_gave_up_on_is_an_error_record():
    spec = PointSpec(chain=3, step=2, phase="sweep", labels={"variant": "adhesionless",
                                                              "load": 0.1})
    worker = types.SimpleNamespace(address="tcp://127.0.0.1:4000")
    lost = distributed.KilledWorker("solve_point-1", worker, 3)
    record = _DaskHandle(_Future(lost), solve_point, (SCENE, spec, None, None)).result()
    assert record["status"] == "error" and not record["converged"]
    assert (record["chain"], record["step"], record["zeta"]) == (3, 2, 0.5)
    assert record["message"].startswith("KilledWorker: lost with its Dask worker")
    assert "tcp://127.0.0.1:4000" in record["message"]
    assert math.isnan(record["area"])


def test_other_cluster_failures_stop_the_study_with_their_reason():
    handle = _DaskHandle(_Future(OSError("scheduler gone")), solve_point, (SCENE, None))
    with pytest.raises(ViscoContactError, match="OSError: scheduler gone.*--resume continues"):
        handle.result()


def test_cli_scheduler_config_without_an_address(tmp_path, capsys, monkeypatch):
    scene = tmp_path / "s.toml"
    scene.write_text('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\n'
                     'kind = "elastic"\n[load]\nmean_pressure = 0.1\n')
    monkeypatch.delenv("DASK_SCHEDULER_ADDRESS", raising=False)
    with dask.config.set({"scheduler-address": None}):
        code = main(["sweep", str(scene), "--zetas", "1", "--out", str(tmp_path / "x.h5"),
                     "--scheduler", "config", "--quiet"])
    assert code == 2 and "scheduler-address" in capsys.readouterr().err
    assert not (tmp_path / "x.h5").exists()                 # nothing made before the failure
    code = main(["sweep", str(scene), "--zetas", "1", "--out", str(tmp_path / "x.h5"),
                 "--scheduler-file", str(tmp_path / "none.json"), "--quiet"])
    assert code == 2 and "no such scheduler file" in capsys.readouterr().err


def _stay(seconds):
    """Where a task started and ended (perf_counter, the same clock for in-process workers)."""
    import time

    start = time.perf_counter()
    time.sleep(seconds)
    return start, time.perf_counter()


def test_points_on_a_multithreaded_worker_take_turns():
    """A worker with two threads is warned about, and its points do not overlap in time."""
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        with pytest.warns(RuntimeWarning, match="one point at a time per worker process"):
            pool = DaskBackend(client)
        handles = [pool.submit(_stay, 0.2) for _ in range(3)]
        done = []
        while len(done) < 3:
            done += pool.wait(handles)
        spans = sorted(h.result() for h in done)
        pool.close()
        assert client.status == "running"                  # a client passed in stays open
    assert all(end <= nxt for (_, end), (nxt, _) in zip(spans, spans[1:]))
