"""StudyData for the Python data stack: a short repr, pandas and xarray views of a study file.

The studies are written point by point with fake records (no solves), so every value on the grid
is known in advance: each record's area encodes where it sits (variant, load, zeta or step).
"""
import math
import sys

import numpy as np
import pytest

from viscocontact.studies import Cycle, StudyFileError, Sweep, load_study, storage
from viscocontact.studies.point import COLUMNS


def record(chain, step, *, variant="adhesionless", load=0.1, zeta=1.0, area=0.5, phase="sweep",
           target=0.1, converged=True, gamma=0.0, n_contacts=1):
    out = {k: (np.nan if kind == "float" else 0 if kind == "int" else False if kind == "bool"
               else "" if kind == "str" else np.zeros(0)) for k, kind in COLUMNS.items()}
    out.update(chain=chain, step=step, phase=phase, started_from="neighbour", variant=variant,
               seed=-1, gamma=gamma, load=load, zeta=zeta, control="mean_pressure",
               target=target, status="converged" if converged else "not_converged",
               converged=converged, message="", area=area, mean_pressure=target,
               n_contacts=n_contacts, edges=np.array([-area / 2, area / 2]), fields=None)
    return out


@pytest.fixture
def sweep_file(tmp_path, adhesive):
    """An adhesive/adhesionless sweep over 2 loads and 3 ζ, area = iv + 10 il + 100 iz, with
    the last point of the last chain missing and one point not converged."""
    sweep = Sweep(scene=adhesive, zetas=[0.1, 1.0, 10.0], loads=[0.05, 0.1],
                  history="speed-ramp")
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    for chain, (iv, il, _, _) in zip(sweep.chains(), sweep.grid()):
        for k, zeta in enumerate(chain.zetas):
            if (chain.index, k) == (3, 2):
                continue
            storage.append(path, record(chain.index, k, variant=chain.labels["variant"],
                                        load=chain.labels["load"], zeta=zeta,
                                        area=iv + 10 * il + 100 * k,
                                        gamma=chain.labels["gamma"],
                                        converged=(chain.index, k) != (1, 1)))
    return path


def test_repr_is_short_and_says_what_the_study_is(sweep_file):
    data = load_study(sweep_file)
    text = repr(data)
    assert len(text.splitlines()) == 3 and len(text) < 400
    assert "sweep" in text and "11 points, 10 converged" in text and "interrupted" in text
    assert "adhesive, adhesionless" in text and "0.05, 0.1" in text and "ζ 0.1, 1, 10" in text


def test_repr_of_a_long_grid_gives_ranges(tmp_path, adhesionless):
    sweep = Sweep(scene=adhesionless, zetas=np.logspace(-3, 2, 9), loads=[0.1])
    storage.create(tmp_path / "s.h5", sweep)
    text = repr(load_study(tmp_path / "s.h5"))
    assert "ζ 9 in [0.001, 100]" in text and "0 points, 0 converged" in text


def test_dataframe_holds_every_record(sweep_file):
    pd = pytest.importorskip("pandas")
    data = load_study(sweep_file)
    frame = data.to_dataframe()
    assert isinstance(frame, pd.DataFrame) and len(frame) == len(data) == 11
    assert list(frame.columns) == list(COLUMNS) and frame.index.name == "row"
    assert frame["area"].tolist() == data.points["area"].tolist()
    assert frame["variant"].tolist() == data.points["variant"].tolist()
    assert np.array_equal(frame["edges"].iloc[4], data.points["edges"][4])
    assert frame.attrs["kind"] == "sweep" and frame.attrs["scene"] == data.scene_toml


def test_sweep_dataset_is_the_table_on_named_axes(sweep_file):
    xr = pytest.importorskip("xarray")
    data = load_study(sweep_file)
    ds = data.to_xarray()
    assert isinstance(ds, xr.Dataset)
    assert ds.area.dims == ("variant", "load", "seed", "zeta")
    assert ds.sizes == {"variant": 2, "load": 2, "seed": 1, "zeta": 3}
    assert ds.variant.values.tolist() == ["adhesive", "adhesionless"]
    assert ds["load"].values.tolist() == [0.05, 0.1]      # ds.load is Dataset.load()
    assert ds.zeta.values.tolist() == [0.1, 1, 10]
    # every value where its record says it belongs (area = iv + 10 il + 100 iz)
    iv, il, iz = np.meshgrid(range(2), range(2), range(3), indexing="ij")
    expected = (iv + 10 * il + 100 * iz)[:, :, None, :].astype(float)
    expected[1, 1, 0, 2] = np.nan                           # never computed
    assert np.array_equal(ds.area.values, expected, equal_nan=True)
    assert np.array_equal(ds.area.where(ds.converged).values, data.table("area"),
                          equal_nan=True)
    assert np.array_equal(ds.area.values, data.table("area", converged_only=False),
                          equal_nan=True)
    assert ds.row.values[1, 1, 0, 2] == -1 and not ds.converged.values[1, 1, 0, 2]
    assert ds.status.values[1, 1, 0, 2] == "" and math.isnan(ds.n_contacts.values[1, 1, 0, 2])
    rows = ds.row.values[ds.row.values >= 0]
    assert sorted(rows.tolist()) == list(range(11))          # each record once
    assert float(ds.sel(variant="adhesive", load=0.1, zeta=1.0, seed=-1).area) == 110.0
    assert ds.gamma.sel(variant="adhesive").values.ravel()[0] == 3e-5
    assert ds.attrs["scene"] == data.scene_toml and ds.attrs["complete"] == 0
    assert ds.attrs["control"] == "mean_pressure" and ds.attrs["kind"] == "sweep"
    # CF attributes, which xarray's plots take as axis labels; Ã is a length (2π: full contact)
    assert ds.area.attrs["units"] == "1" and "2π" in ds.area.attrs["long_name"]
    assert "fraction" not in ds.area.attrs["description"]
    assert ds.zeta.attrs["long_name"] == "ζ = q0 V τ" and ds.seconds.attrs["units"] == "s"
    # every numeric result column and coordinate is labelled (the row index aside)
    numeric = [n for n in ds.variables if ds[n].dtype.kind in "fiu" and n not in ("row", "chain")]
    assert [n for n in numeric if not {"long_name", "units"} <= set(ds[n].attrs)] == []


def test_approached_points_have_the_grid_of_a_ramp(tmp_path, adhesive):
    """Under the approach every adhesive point is its own chain; the grid is the same."""
    pytest.importorskip("xarray")
    sweep = Sweep(scene=adhesive, zetas=[0.1, 1.0, 10.0], history="approach", pair=False)
    path = tmp_path / "s.h5"
    storage.create(path, sweep)
    for chain in reversed(sweep.chains()):                   # finishing order does not matter
        storage.append(path, record(chain.index, 0, zeta=chain.zetas[0], variant="adhesive",
                                    area=10 * chain.zetas[0], gamma=3e-5))
    ds = load_study(path).to_xarray()
    assert ds.area.values.ravel().tolist() == [1.0, 10.0, 100.0]


def test_cycle_dataset_pads_the_steps_and_holds_the_metrics(tmp_path, adhesive):
    xr = pytest.importorskip("xarray")
    cycle = Cycle(scene=adhesive, max_penetration=0.4, step=0.2, zetas=[0.1, 1.0],
                  gammas=[0.0, 3e-5], refine=0)
    path = tmp_path / "c.h5"
    storage.create(path, cycle)
    path_of = {0: [0.0, 0.2, 0.4, 0.2, 0.0, -0.2], 1: [0.0, 0.2, 0.4, 0.2]}
    for chain in cycle.chains():
        targets = path_of[chain.index % 2]
        for k, target in enumerate(targets):
            phase = "approach" if k < 3 else "retract"
            touching = target > 0 or (phase == "approach" and target == 0.0)
            storage.append(path, record(chain.index, k, phase=phase, target=target,
                                        zeta=chain.zetas[0], gamma=chain.labels["gamma"],
                                        variant=chain.labels["variant"], area=target,
                                        n_contacts=int(touching)))
    data = load_study(path)
    ds = data.to_xarray()
    assert ds.target.dims == ("zeta", "gamma", "seed", "step")
    assert ds.sizes == {"zeta": 2, "gamma": 2, "seed": 1, "step": 6}
    assert ds.gamma.values.tolist() == [0.0, 3e-5]
    assert ds.variant.values.tolist() == ["adhesionless", "adhesive"]
    long = ds.isel(zeta=1, gamma=0, seed=0)
    short = ds.isel(zeta=1, gamma=1, seed=0)
    assert long.target.values.tolist() == path_of[0]
    assert short.phase.values.tolist() == ["approach"] * 3 + ["retract", "", ""]
    assert np.isnan(short.target.values[4:]).all() and short.row.values[4:].tolist() == [-1, -1]
    metrics = data.metrics()
    for name in ("toughness", "detachment_penetration", "cycle_work"):
        assert ds[name].dims == ("zeta", "gamma", "seed")
        assert np.array_equal(ds[name].values, metrics[name], equal_nan=True), name
    assert isinstance(ds, xr.Dataset) and ds.attrs["kind"] == "cycle"


def test_dataset_survives_netcdf(sweep_file, tmp_path):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    ds = load_study(sweep_file).to_xarray()
    ds.to_netcdf(tmp_path / "s.nc", engine="h5netcdf")
    back = xr.open_dataset(tmp_path / "s.nc", engine="h5netcdf")
    assert back.attrs["scene"] == ds.attrs["scene"]
    assert np.array_equal(back.area.values, ds.area.values, equal_nan=True)
    assert back.status.values.tolist() == ds.status.values.tolist()
    back.close()


@pytest.mark.parametrize("method,module", [("to_xarray", "xarray"), ("to_dataframe", "pandas")])
def test_missing_extra_is_named(sweep_file, monkeypatch, method, module):
    monkeypatch.setitem(sys.modules, module, None)          # import now raises ImportError
    with pytest.raises(ImportError, match=r"pip install 'viscocontact\[xarray\]'") as info:
        getattr(load_study(sweep_file), method)()
    assert module in str(info.value)


def test_points_off_the_grid_are_a_damaged_file(tmp_path, adhesionless):
    pytest.importorskip("xarray")
    path = tmp_path / "s.h5"
    storage.create(path, Sweep(scene=adhesionless, zetas=[0.1, 1.0]))
    storage.append(path, record(0, 2, zeta=10.0))           # a third ζ the study does not have
    with pytest.raises(StudyFileError, match="s.h5 is damaged"):
        load_study(path).to_xarray()
