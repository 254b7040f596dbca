"""Studies that survive faults: a process killed or terminated in the middle of a write, two
processes on one study file, a Dask worker lost, a full disk, damaged and foreign files.

Every study here is a ζ-sweep of the cheap adhesionless sinusoid (32 elements, a fraction of a
second per point). A fault is placed deterministically: the study runs in a child process whose
HDF5 ``flush`` (called once per append, after the point's rows are written and before they are
counted) or whose solve pauses on a chosen call and says so in a marker file.
"""
from __future__ import annotations

import errno
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

from viscocontact.cli import main
from viscocontact.scene import Scene
from viscocontact.studies import COLUMNS, StudyFileError, Sweep, load_study, resume, run, storage
from viscocontact.studies.guard import lock_path
from viscocontact.studies.point import TIMING_COLUMNS
from viscocontact.testing.scenes import WAVY

SCENE = WAVY
ZETAS = (0.01, 0.1, 1.0, 10.0, 100.0)
ARGS = ["--zetas", ",".join(map(str, ZETAS)), "--elements", "32", "--quiet"]

# the child: the command line, with one call of h5py.File.flush or of the solve paused
CHILD = textwrap.dedent("""
    import sys, time
    from pathlib import Path
    target, call, marker, pause = sys.argv[1], int(sys.argv[2]), Path(sys.argv[3]), float(sys.argv[4])
    if target == "flush":
        import h5py
        owner, name = h5py.File, "flush"
    else:
        import viscocontact.studies.point as owner
        name = "_solve"
    original, calls = getattr(owner, name), [0]
    def paused(*args, **kwargs):
        calls[0] += 1
        if calls[0] == call:
            marker.write_text("paused")
            time.sleep(pause)
        return original(*args, **kwargs)
    setattr(owner, name, paused)
    from viscocontact.cli import main
    sys.exit(main(sys.argv[5:]))
""")


def sweep() -> Sweep:
    return Sweep(scene=Scene.from_toml(SCENE), zetas=ZETAS, discretization={"elements": 32})


@pytest.fixture(scope="module")
def whole(tmp_path_factory):
    """The uninterrupted study."""
    return run(sweep(), tmp_path_factory.mktemp("whole") / "whole.h5", progress=None)


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "wavy.toml"
    path.write_text(SCENE)
    return path


def identical(a, b):
    oa, ob = (np.lexsort((p["step"], p["chain"])) for p in (a, b))
    assert len(oa) == len(ob)
    for key in COLUMNS:
        if key in TIMING_COLUMNS:
            continue
        x, y = a[key][oa], b[key][ob]
        if key == "edges":
            assert all(np.array_equal(u, v) for u, v in zip(x, y))
        else:
            assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), key


def start_paused(tmp_path, target: str, call: int, pause: float, argv) -> tuple:
    """The child process and its marker file, once the marker says it is paused."""
    script, marker = tmp_path / "child.py", tmp_path / "paused"
    script.write_text(CHILD)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    proc = subprocess.Popen([sys.executable, str(script), target, str(call), str(marker),
                             str(pause), *map(str, argv)], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    while not marker.exists():
        if proc.poll() is not None:
            raise AssertionError(f"child ended before the pause: {proc.stderr.read()}")
        time.sleep(0.02)
    return proc, marker


def finish(proc) -> int:
    try:
        proc.wait(timeout=120)
    finally:
        proc.stderr.close()
    return proc.returncode


def test_sigkill_in_the_middle_of_a_write(tmp_path, scene, whole):
    path = tmp_path / "s.h5"
    proc, _ = start_paused(tmp_path, "flush", 3, 60.0,
                           ["sweep", scene, *ARGS, "--out", path])
    proc.kill()                                  # the third point's rows written, not counted
    assert finish(proc) == -signal.SIGKILL
    partial = load_study(path)
    assert not partial.complete and len(partial) == 2
    assert partial.points["step"].tolist() == [0, 1]
    done = resume(path, progress=None)
    assert done.complete and len(done) == len(ZETAS)
    assert done.points["step"].tolist() == list(range(len(ZETAS)))    # none lost, none twice
    identical(done.points, whole.points)


def test_sigterm_in_the_middle_of_a_write_lets_it_finish(tmp_path, scene, whole):
    path = tmp_path / "s.h5"
    proc, _ = start_paused(tmp_path, "flush", 3, 1.0,
                           ["sweep", scene, *ARGS, "--out", path])
    proc.send_signal(signal.SIGTERM)             # held until the append is done
    assert finish(proc) == -signal.SIGTERM
    partial = load_study(path)
    assert len(partial) == 3 and partial.points["step"].tolist() == [0, 1, 2]
    assert main(["sweep", str(scene), *ARGS, "--out", str(path), "--resume"]) == 0
    done = load_study(path)
    assert done.complete and done.points["step"].tolist() == list(range(len(ZETAS)))
    identical(done.points, whole.points)


def test_a_second_process_cannot_write_the_study(tmp_path, scene, capsys):
    path = tmp_path / "s.h5"
    proc, _ = start_paused(tmp_path, "solve", 2, 60.0, ["sweep", scene, *ARGS, "--out", path])
    try:
        for extra in (["--resume"], ["--force"]):
            code = main(["sweep", str(scene), *ARGS, "--out", str(path), *extra])
            err = capsys.readouterr().err.strip()
            assert code == 2 and len(err.splitlines()) == 1
            assert f"s.h5 is being computed by process {proc.pid}" in err
        data = load_study(path)                  # readers are welcome, the file is intact
        assert len(data) == 1 and data.points["converged"].all()
        assert main(["plot", str(path), "--out", str(tmp_path / "figs")]) == 0
    finally:
        proc.kill()
        finish(proc)
    assert len(resume(path, progress=None)) == len(ZETAS)


def test_a_file_held_open_elsewhere_delays_a_write_and_then_says_why(tmp_path, monkeypatch):
    path = tmp_path / "s.h5"
    storage.create(path, sweep())
    points = run(sweep(), tmp_path / "one.h5", progress=None).points
    first = {k: v[0] for k, v in points.items()} | {"fields": None}   # a record to append
    holder = subprocess.Popen(
        [sys.executable, "-c", "import sys, time, h5py\nf = h5py.File(sys.argv[1], 'r')\n"
         "print('open', flush=True)\ntime.sleep(float(sys.argv[2]))", str(path), "60"],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "open"
        monkeypatch.setattr(storage, "WRITE_WAIT", 0.3)
        with pytest.raises(StudyFileError, match="held open by another process"):
            storage.append(path, first)
    finally:
        holder.kill()
        holder.wait()
        holder.stdout.close()
    assert len(load_study(path)) == 0            # nothing half written
    holder = subprocess.Popen(                   # a short hold: the write waits for it
        [sys.executable, "-c", "import sys, time, h5py\nf = h5py.File(sys.argv[1], 'r')\n"
         "print('open', flush=True)\ntime.sleep(0.5)", str(path)], stdout=subprocess.PIPE,
        text=True)
    try:
        assert holder.stdout.readline().strip() == "open"
        monkeypatch.setattr(storage, "WRITE_WAIT", 60.0)
        assert storage.append(path, first) == 0
    finally:
        holder.wait()
        holder.stdout.close()
    assert load_study(path).points["area"].tolist() == [first["area"]]


def test_a_full_disk_during_an_append_keeps_the_earlier_points(tmp_path, monkeypatch, whole):
    path = tmp_path / "s.h5"
    real, writes = h5py.Dataset.__setitem__, []

    def setitem(self, key, value):
        if self.name == "/points/area":
            writes.append(key)
            if len(writes) == 3:
                raise OSError(errno.ENOSPC, "No space left on device")
        return real(self, key, value)

    monkeypatch.setattr(h5py.Dataset, "__setitem__", setitem)
    with pytest.raises(StudyFileError, match=r"cannot write a point to .*s.h5: No space left on "
                                             r"device; the file keeps the 2 points before it"):
        run(sweep(), path, progress=None)
    monkeypatch.setattr(h5py.Dataset, "__setitem__", real)
    partial = load_study(path)
    assert len(partial) == 2 and not partial.complete
    assert partial.points["area"].tolist() == whole.points["area"][:2].tolist()
    assert not lock_path(path).exists()
    done = resume(path, progress=None)
    assert done.points["step"].tolist() == list(range(len(ZETAS)))
    identical(done.points, whole.points)


@pytest.mark.parametrize("kind", ["truncated", "foreign", "not-hdf5"])
def test_damaged_and_foreign_files(tmp_path, scene, capsys, kind):
    path = tmp_path / "s.h5"
    if kind == "truncated":
        storage.create(path, sweep())
        data = path.read_bytes()
        path.write_bytes(data[: len(data) * 2 // 3])
        fragment = "s.h5 is truncated"
    elif kind == "foreign":
        with h5py.File(path, "w") as f:
            f["temperature"] = np.arange(4.0)
        fragment = "s.h5 is an HDF5 file but not a viscocontact study file"
    else:
        path.write_text("time,force\n0,1\n")
        fragment = "s.h5 is not a readable HDF5 file"
    before = path.read_bytes()
    for argv in (["plot", str(path)], ["sweep", str(scene), *ARGS, "--out", str(path),
                                       "--resume"], ["sweep", "--resume", "--out", str(path)]):
        assert main(argv) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and fragment in err[0], err
    assert path.read_bytes() == before           # left as it was
    assert not lock_path(path).exists()


@pytest.mark.slow
def test_a_dask_worker_lost_mid_study(tmp_path, whole):
    """A worker killed while it solves a point: Dask reschedules the point on another worker
    (up to distributed.scheduler.allowed-failures times) and the study completes."""
    distributed = pytest.importorskip("distributed")
    import dask

    environ = {"OMP_NUM_THREADS": 1, "MKL_NUM_THREADS": 1, "OPENBLAS_NUM_THREADS": 1}
    study = Sweep(scene=Scene.from_toml(SCENE), zetas=ZETAS, loads=[0.1, 0.12],
                  discretization={"elements": 32})
    with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     host="127.0.0.1", dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        # every point takes half a second more, so that a worker is caught in the middle of one
        client.run(exec, "import time, viscocontact.studies.point as p\n"
                         "_solve = p._solve\n"
                         "def slow(*args):\n"
                         "    time.sleep(0.5)\n"
                         "    return _solve(*args)\n"
                         "p._solve = slow\n", {})
        killed = []

        def kill_a_busy_worker():
            while not killed:
                busy = [w for w, keys in client.processing().items() if keys]
                if busy:
                    pid = client.run(os.getpid, workers=busy[:1])[busy[0]]
                    os.kill(pid, signal.SIGKILL)
                    killed.append(pid)
                time.sleep(0.05)

        killer = threading.Thread(target=kill_a_busy_worker, daemon=True)
        killer.start()
        data = run(study, tmp_path / "dask.h5", scheduler=cluster.scheduler_address,
                   progress=None)
        killer.join(timeout=60)
    assert killed and data.complete and len(data) == 2 * len(ZETAS)
    assert data.points["converged"].all()                  # the lost point was computed again
    chain0 = {k: v[data.points["chain"] == 0] for k, v in data.points.items()}
    identical(chain0, whole.points)                          # same bits as the serial run
