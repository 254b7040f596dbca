"""The study file's named dimensions (HDF5 dimension scales), files written by 0.1.0, rewrites."""
import json
import warnings

import h5py
import numpy as np
import pytest

from viscocontact.studies import Sweep, load_study, run, storage
from viscocontact.studies.point import COLUMNS, LATER_COLUMNS

from .test_data import record


@pytest.fixture
def sweep(adhesionless, mesh):
    return Sweep(scene=adhesionless, zetas=[0.3, 3.0], loads=[0.1], discretization=mesh)


def write_010(path, sweep, records):
    """A study file laid out as viscocontact 0.1.0 wrote it: no dimension scales, and none of
    the columns added since (the method and its error estimate)."""
    string = h5py.string_dtype("utf-8")
    kinds = {"int": np.int64, "float": np.float64, "bool": np.bool_, "str": string,
             "edges": h5py.vlen_dtype(np.float64)}
    with h5py.File(path, "w") as f:
        f.attrs.update(format="viscocontact.study", format_version=1, kind="sweep",
                       viscocontact_version="0.1.0", created="2026-01-01T00:00:00+00:00",
                       complete=False)
        f.create_dataset("scene", data=sweep.scene.to_toml(), dtype=string)
        f.create_dataset("study", data=json.dumps(sweep.params()), dtype=string)
        f.create_dataset("seeds", data=np.zeros(0, np.int64))
        points = f.create_group("points")
        for column, kind in COLUMNS.items():
            if column in LATER_COLUMNS:
                continue
            points.create_dataset(column, shape=(len(records),), maxshape=(None,), chunks=(256,),
                                  dtype=kinds[kind])
            for i, rec in enumerate(records):
                value = rec[column]
                points[column][i] = (str(value) if kind == "str" else
                                     np.asarray(value, float) if kind == "edges" else value)
        points.attrs["count"] = len(records)
        f.create_group("fields")


def test_columns_share_the_row_dimension(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    for k, zeta in enumerate(sweep.zetas):
        rec = record(0, k, zeta=zeta, area=0.5 + k)
        rec["fields"] = {"x": np.linspace(0, 1, 5), "pressure": np.ones(5),
                         "displacement": np.zeros(5), "gap": np.zeros(5)}
        storage.append(path, rec)
    with h5py.File(path, "r") as f:
        points = f["points"]
        assert points["row"].is_scale and points["row"][()].tolist() == [0, 1]
        for column in COLUMNS:
            assert points[column].dims[0][0].name == "/points/row", column
        assert f["seeds"].is_scale
        assert f["fields/000001/pressure"].dims[0][0].name == "/fields/000001/x"


def test_xarray_opens_the_points_without_phony_dimensions(tmp_path, sweep):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    for k, zeta in enumerate(sweep.zetas):
        storage.append(path, record(0, k, zeta=zeta, area=0.5 + k))
    with warnings.catch_warnings():
        warnings.simplefilter("error")        # xarray warns when it invents phony dimensions
        ds = xr.open_dataset(path, group="points", engine="h5netcdf")
    assert dict(ds.sizes) == {"row": 2} and ds.row.values.tolist() == [0, 1]
    assert ds.area.values.tolist() == [0.5, 1.5] and ds.status.values.tolist() == ["converged"] * 2
    assert ds.attrs["count"] == 2
    ds.close()


def test_a_file_of_010_is_read_appended_and_resumed(tmp_path, sweep, mesh, identical):
    whole = run(sweep, tmp_path / "whole.h5", progress=None)
    first = {k: v[:1] for k, v in whole.points.items()}
    old = tmp_path / "old.h5"
    write_010(old, sweep, [dict(zip(first, values)) for values in zip(*first.values())])
    with h5py.File(old, "r") as f:
        assert "row" not in f["points"]
    data = load_study(old)
    assert len(data) == 1 and data.version == "0.1.0" and data.study == sweep
    assert np.array_equal(data.points["edges"][0], whole.points["edges"][0])

    assert data.points["method"].tolist() == [""]          # not recorded by 0.1.0
    assert np.isnan(data.points["error_estimate"]).all()

    resumed = run(sweep, old, resume=True, progress=None)      # rewritten in the new layout
    assert resumed.complete and len(resumed) == 2
    later = {k: v for k, v in resumed.points.items() if k not in LATER_COLUMNS}
    identical(later, {k: v for k, v in whole.points.items() if k not in LATER_COLUMNS})
    assert resumed.points["method"][0] == "" and resumed.points["method"][1] == whole.points[
        "method"][1] != ""
    with h5py.File(old, "r") as f:
        assert f["points/row"].is_scale and f.attrs["viscocontact_version"] == "0.1.0"
        assert f.attrs["created"] == "2026-01-01T00:00:00+00:00"


def test_append_to_a_file_of_010_keeps_its_layout(tmp_path, sweep):
    old = tmp_path / "old.h5"
    write_010(old, sweep, [record(0, 0, zeta=0.3)])
    storage.append(old, dict(record(0, 1, zeta=3.0, area=2.0), method="spectral",
                             error_estimate=3e-4))
    points = load_study(old).points
    assert points["area"].tolist() == [0.5, 2.0]
    assert points["method"].tolist() == ["", "spectral"]
    assert np.isnan(points["error_estimate"][0]) and points["error_estimate"][1] == 3e-4


def test_rewrite_keeps_the_counted_points_and_drops_the_rest(tmp_path, sweep):
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    rec = record(0, 0, zeta=0.3)
    rec["fields"] = {"x": np.linspace(0, 1, 3), "pressure": np.ones(3)}
    storage.append(path, rec)
    with h5py.File(path, "r+") as f:           # a write cut short: rows, fields, no count
        for column in ("chain", "area"):
            f["points"][column].resize((2,))
        f["fields"].create_group("000001").create_dataset("x", data=np.ones(2))
    storage.rewrite(path)
    with h5py.File(path, "r") as f:
        assert f["points/area"].shape == (1,) and list(f["fields"]) == ["000000"]
    data = load_study(path)
    assert len(data) == 1 and np.array_equal(data.fields(0)["pressure"], np.ones(3))
    assert data.points["edges"][0].tolist() == [-0.25, 0.25]
    assert not path.with_name("s.h5.tmp").exists()
