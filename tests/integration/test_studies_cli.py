"""``viscocontact sweep | cycle | plot | study``: files, figures, errors, and a Dask cluster."""
from __future__ import annotations

import shutil

import numpy as np
import pytest

from viscocontact.cli import main
from viscocontact.studies import COLUMNS, load_study
from viscocontact.studies.point import TIMING_COLUMNS
from viscocontact.testing.scenes import WAVY

SCENE = WAVY
SWEEP = ["--zetas", "0.1,10", "--loads", "0.05,0.15", "--elements", "32", "--quiet"]


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "wavy.toml"
    path.write_text(SCENE)
    return path


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    """The small sweep, computed serially through the command line."""
    folder = tmp_path_factory.mktemp("serial")
    (folder / "wavy.toml").write_text(SCENE)
    out = folder / "wavy_sweep.h5"
    assert main(["sweep", str(folder / "wavy.toml"), *SWEEP, "--out", str(out)]) == 0
    return out


def identical(a, b):
    oa, ob = (np.lexsort((p["step"], p["chain"])) for p in (a, b))
    for key in COLUMNS:
        if key in TIMING_COLUMNS:
            continue
        x, y = a[key][oa], b[key][ob]
        if key == "edges":
            assert all(np.array_equal(u, v) for u, v in zip(x, y))
        else:
            assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), key


@pytest.mark.parametrize("command", ["sweep", "cycle", "plot", "study"])
def test_help(capsys, command):
    assert main([command, "--help"]) == 0
    assert f"usage: viscocontact {command}" in capsys.readouterr().out


def test_sweep_plot_and_resume(tmp_path, scene, serial, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    shutil.copy(serial, tmp_path / "wavy_sweep.h5")                 # the default --out name
    data = load_study(tmp_path / "wavy_sweep.h5")
    assert data.complete and data.table("area").shape == (1, 2, 1, 2)
    assert data.axes()["variant"] == ("adhesionless",) and data.axes()["load"] == (0.05, 0.15)

    assert main(["sweep", str(scene), *SWEEP]) == 2                  # exists: no silent reuse
    assert "--resume" in capsys.readouterr().err
    assert main(["sweep", "--resume", "--out", "wavy_sweep.h5", "--quiet"]) == 0
    assert len(load_study(tmp_path / "wavy_sweep.h5")) == 4          # nothing left to compute

    assert main(["plot", "wavy_sweep.h5", "--out", str(tmp_path / "figs")]) == 0
    for name in ("wavy_sweep_area.png", "wavy_sweep_friction.png"):
        assert (tmp_path / "figs" / name).stat().st_size > 1000


def test_cycle_and_plot(tmp_path, scene, capsys):
    out = tmp_path / "c.h5"
    code = main(["cycle", str(scene), "--max-penetration", "0.4", "--step", "0.2", "--refine",
                 "1", "--zetas", "0.1,1", "--elements", "32", "--out", str(out), "--quiet",
                 "--plot"])
    text = capsys.readouterr().out
    assert code == 0, text
    assert "c_cycle.png" in text and "c_toughness.png" in text
    assert (tmp_path / "c_cycle.png").stat().st_size > 1000
    metrics = load_study(out).metrics()
    assert metrics["toughness"].shape == (2, 1, 1) and np.all(metrics["toughness"] == 0)


@pytest.mark.parametrize("content,fragment", [
    (b"not an hdf5 file at all", "not a readable HDF5 file"),
    (None, "not a viscocontact study file"),
])
def test_bad_study_file(tmp_path, capsys, content, fragment):
    path = tmp_path / "bad.h5"
    if content is None:
        import h5py

        with h5py.File(path, "w") as f:
            f["x"] = [1, 2, 3]
    else:
        path.write_bytes(content)
    assert main(["plot", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and fragment in err[0] and "Traceback" not in err[0]


def test_bad_sweep_input(tmp_path, scene, capsys):
    assert main(["sweep", str(scene), "--zetas", "0:1:3", "--out", str(tmp_path / "x.h5")]) == 2
    assert "--zetas" in capsys.readouterr().err
    assert main(["sweep", str(scene), "--zetas", "1", "--seeds", "0:2",
                 "--out", str(tmp_path / "x.h5")]) == 2
    assert "profile.seed" in capsys.readouterr().err
    for bad in ("0", "-5", "inf", "nan"):
        assert main(["sweep", str(scene), "--zetas", "1", "--time-limit", bad,
                     "--out", str(tmp_path / "x.h5")]) == 2
        assert "--time-limit" in capsys.readouterr().err
    assert main(["plot", str(tmp_path / "missing.h5")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_dask_cluster_gives_the_serial_result(tmp_path, scene, serial):
    distributed = pytest.importorskip("distributed")
    import dask

    # the nanny's default MALLOC_TRIM_THRESHOLD_ halves the solver's speed (docs/studies.md)
    environ = {"OMP_NUM_THREADS": 1, "MKL_NUM_THREADS": 1, "OPENBLAS_NUM_THREADS": 1}
    with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     host="127.0.0.1", dashboard_address=None) as cluster:
        remote = tmp_path / "dask.h5"
        assert main(["sweep", str(scene), *SWEEP, "--out", str(remote),
                     "--scheduler", cluster.scheduler_address]) == 0
    a, b = load_study(serial), load_study(remote)
    assert len(a) == len(b) == 4
    identical(a.points, b.points)


def test_bad_history_options(tmp_path, scene, capsys):
    for extra, field, allowed in ((["--ramp-tolerance", "0.01"], "--ramp-tolerance",
                                   "only with --history speed-ramp"),
                                  (["--history", "speed-ramp", "--ramp-tolerance", "0"],
                                   "history.tolerance", "(0, 0.5]")):
        assert main(["sweep", str(scene), "--zetas", "1,0.01", *extra,
                     "--out", str(tmp_path / "x.h5")]) == 2
        err = capsys.readouterr().err
        assert field in err and allowed in err and "Traceback" not in err
